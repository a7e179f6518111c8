#!/bin/bash
# usage: run.sh FILE TAG METHOD [extra args...]   -> logs/TAG_METHOD.json/.err
cd /tmp/s88h1/main
F=$1; T=$2; M=$3; shift 3
timeout 900 .venv/bin/stiefelsym verify --claims $F --method $M --jobs 1 --no-report --format json --timeout 120 "$@" \
  > /tmp/s88h1/out/logs/${T}_${M}.json 2> /tmp/s88h1/out/logs/${T}_${M}.err
echo "$T $M rc=$?"
