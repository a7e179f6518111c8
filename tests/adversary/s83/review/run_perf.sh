#!/bin/sh
# usage: run_perf.sh FILE...   exact at (4,2) before (96621a3a~1, /tmp/h2/before) and after (/tmp/h2/main);
# prints file, clone, verdict, the claim's seconds and the route ("no randomness": the symbolic chart decided;
# "seed 0": the dimension-free proof specialised after the chart ended beyond the symbolic budget)
for f in "$@"; do
  for c in before main; do
    line=$(cd /tmp/h2/$c && timeout 600 .venv/bin/stiefelsym verify --claims "$f" --method exact --size 4,2 --jobs 1 --timeout 300 --no-report 2>&1 | grep -E "^adv.*exact:" | head -1)
    echo "$(basename $f) $c $(echo "$line" | sed -E 's/.*exact: ([a-z]+) \(([0-9.]+)s, ([^)]*)\).*/\1 \2 \3/')"
  done
done
