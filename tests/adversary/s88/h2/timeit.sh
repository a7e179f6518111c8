#!/bin/bash
# usage: timeit.sh CLAIM SIZE REPS  -- exact method, main vs base (7d2b52f5) alternately; prints verdict and seconds
F=${F:-/tmp/s88h2/out/adv_content.py}
for i in $(seq $3); do
  for tree in main base; do
    cd /tmp/s88h2/$tree
    timeout 900 .venv/bin/stiefelsym verify --claims $F $1 --size $2 --method exact --jobs 1 --no-report --seed 1 --format json 2>/dev/null \
      | python3 -c "import json,sys; d=json.load(sys.stdin); [print('$tree', r['claim'], r['n'], r['r'], r['verdict'], round(r['seconds'],2)) for r in d['results']]"
  done
done
