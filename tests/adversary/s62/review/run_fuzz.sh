#!/bin/sh
# usage: run_fuzz.sh SEED  (from tests/adversary/s62/review); every method at (3,2), (3,3), (4,2); free once
S=$1
cd /work/main
mkdir -p tests/adversary/s62/review/out
for m in exact modular rational float ball; do
  for sz in 3,2 3,3 4,2; do
    timeout 300 .venv/bin/stiefelsym verify --claims tests/adversary/s62/review/fuzz_claims_$S.py --size $sz --method $m --jobs 1 --no-report --format json > tests/adversary/s62/review/out/f${S}_${m}_$sz.json 2>/dev/null
    echo "$m $sz rc=$?"
    (cd tests/adversary/s62/review && ../../../../.venv/bin/python compare.py $S ${sz%,*} ${sz#*,} out/f${S}_${m}_$sz.json)
  done
done
timeout 300 .venv/bin/stiefelsym verify --claims tests/adversary/s62/review/fuzz_claims_$S.py --method free --jobs 1 --no-report --format json > tests/adversary/s62/review/out/f${S}_free.json 2>/dev/null
echo "free rc=$?"
