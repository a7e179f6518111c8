#!/bin/bash
# usage: run_adv.sh FILE TAG METHOD...  runs every claim of FILE at its default sizes
cd /tmp/s88h2/main
for M in "${@:3}"; do
  timeout ${TMO:-1200} .venv/bin/stiefelsym verify --claims $1 --method $M --jobs 1 --no-report --seed 1 --format json \
    > /tmp/s88h2/out/logs/$2_${M}.json 2> /tmp/s88h2/out/logs/$2_${M}.err; echo "$2 $M rc=$?"
done
