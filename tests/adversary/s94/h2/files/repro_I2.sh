#!/bin/bash
# I2: a bad --stiefelsym-timeout / --stiefelsym-memory reaches the runner per item: every claim FAILED, exit 1
cd /tmp/s94h2/files/pt && PYTHONPATH=/tmp/s94h2/repo timeout 250 /work/main/.venv/bin/python -m pytest --stiefelsym \
  --stiefelsym-timeout=nan --stiefelsym-method modular --stiefelsym-size 3,2 claims_pt.py -q -p no:cacheprovider 2>&1 | tail -6
