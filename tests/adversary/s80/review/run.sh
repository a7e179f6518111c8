#!/bin/bash
# usage: run.sh FILE [methods...] ; logs to logs/FILE.METHOD.log, prints verdict lines
S=/tmp/h1/main/.venv/bin/stiefelsym
f=$1; shift
ms=${*:-"exact modular float free"}
b=$(basename $f .py)
for m in $ms; do
  timeout 600 $S verify --claims $f --method $m --jobs 1 --timeout 120 --no-report $EXTRA > logs/$b.$m.log 2>&1
  grep -E "(proved|checked|numeric|fails|inconclusive|undecided|error)" logs/$b.$m.log | grep -v "^ " | sed "s/^/[$m] /" | cut -c1-300
done
