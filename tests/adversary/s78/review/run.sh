#!/bin/bash
# usage: run.sh FILE [extra args]; runs every method, logs to logs/FILE.METHOD.log, prints verdict lines
S=/tmp/h2/main/.venv/bin/stiefelsym
f=$1; shift
b=$(basename $f .py)
for m in auto exact modular rational float ball free; do
  timeout 300 $S verify --claims $f --method $m --jobs 1 --timeout 60 "$@" > logs/$b.$m.log 2>&1
  grep -E "^[a-z0-9][a-z0-9._+-]* .*(proved|checked|numeric|fails|inconclusive|undecided|error)" logs/$b.$m.log | sed "s/^/[$m] /" | cut -c1-230
done
