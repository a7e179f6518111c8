#!/bin/sh
# Every method at the sizes (5,1) (5,2) (6,2) (6,3) (5,5) (6,1); each process under `timeout 300`.
D=tests/adversary/s74/hidden
S="--size 5,1 --size 5,2 --size 6,2 --size 6,3 --size 5,5 --size 6,1"
for f in claims negatives; do
  for m in exact rational modular float ball free auto; do
    start=$(date +%s)
    timeout 300 .venv/bin/stiefelsym verify --claims $D/$f.py $S --method $m --jobs 1 --no-report --timeout 120 > $D/logbig_${f}_$m.txt 2>&1
    echo "rc=$? seconds=$(( $(date +%s) - start ))" >> $D/logbig_${f}_$m.txt
  done
done
