#!/bin/sh
# run.sh FILE [methods...]: verify a claims file, logs in logs/FILE.METHOD.log
f=$1; shift
for m in ${@:-exact}; do
  /tmp/h4/main/.venv/bin/stiefelsym verify --claims "$f" --method "$m" --jobs 1 --timeout 120 --no-report > "logs/$(basename $f .py).$m.log" 2>&1
  echo "== $f $m"; grep -v "^\s*$" "logs/$(basename $f .py).$m.log" | tail -40
done
