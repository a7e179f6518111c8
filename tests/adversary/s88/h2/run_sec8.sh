#!/bin/bash
# usage: run_sec8.sh METHOD...  runs every claim of sec8_claims.py at its default sizes (n <= 4; Cauchy–Binet n <= 5)
cd /tmp/s88h2/main
C=/tmp/s88h2/out/sec8_claims.py
for M in "$@"; do
  timeout ${TMO:-1200} .venv/bin/stiefelsym verify --claims $C --method $M --jobs 1 --no-report --seed 1 --format json \
    > /tmp/s88h2/out/logs/sec8_${M}.json 2> /tmp/s88h2/out/logs/sec8_${M}.err; echo "$M rc=$?"
done
