#!/bin/sh
# Runs every method, one --method per process, on claims.py and negatives.py at the default sizes;
# each process under `timeout 300`.  Logs: log_<file>_<method>.txt
D=tests/adversary/s74/hidden
for f in claims negatives; do
  for m in exact rational modular float ball free auto; do
    start=$(date +%s)
    timeout 300 .venv/bin/stiefelsym verify --claims $D/$f.py --method $m --jobs 1 --no-report --timeout 60 > $D/log_${f}_$m.txt 2>&1
    echo "rc=$? seconds=$(( $(date +%s) - start ))" >> $D/log_${f}_$m.txt
  done
done
