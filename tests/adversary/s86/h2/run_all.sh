#!/bin/bash
# usage: run_all.sh METHOD...   runs every claim at the default sizes and at (5,2), (5,5), (6,3), seed 1
cd /tmp/s86h2/main
C=/tmp/s86h2/out/claims.py
ALL=$(grep -o '@claim("s86h2[^"]*' $C | cut -d'"' -f2)
RN="s86h2-rigid-body-velocities s86h2-rigid-body-velocities-twin s86h2-hcp-right-invariant s86h2-hcp-right-invariant-twin"
R2="s86h2-magnetic-nor-minus-euk s86h2-magnetic-nor-minus-euk-twin"
GEN=$(for c in $ALL; do case " $RN $R2 " in *" $c "*) ;; *) echo $c;; esac; done)
T=${TMO:-900}
for M in "$@"; do
  timeout $T .venv/bin/stiefelsym verify --claims $C $ALL --method $M --jobs 1 --no-report --seed 1 --format json > /tmp/s86h2/out/logs/${M}_default.json 2> /tmp/s86h2/out/logs/${M}_default.err; echo "$M default rc=$?"
  timeout $T .venv/bin/stiefelsym verify --claims $C $GEN $R2 --size 5,2 --method $M --jobs 1 --no-report --seed 1 --format json > /tmp/s86h2/out/logs/${M}_5_2.json 2> /tmp/s86h2/out/logs/${M}_5_2.err; echo "$M 5,2 rc=$?"
  timeout $T .venv/bin/stiefelsym verify --claims $C $GEN $RN --size 5,5 --method $M --jobs 1 --no-report --seed 1 --format json > /tmp/s86h2/out/logs/${M}_5_5.json 2> /tmp/s86h2/out/logs/${M}_5_5.err; echo "$M 5,5 rc=$?"
  timeout $T .venv/bin/stiefelsym verify --claims $C $GEN --size 6,3 --method $M --jobs 1 --no-report --seed 1 --format json > /tmp/s86h2/out/logs/${M}_6_3.json 2> /tmp/s86h2/out/logs/${M}_6_3.err; echo "$M 6,3 rc=$?"
done
