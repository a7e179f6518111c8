#!/bin/sh
# summarize.sh FILE: per claim and method, the verdicts (from logs/FILE.METHOD.log)
b=$(basename $1 .py)
for l in logs/$b.*.log; do m=${l#logs/$b.}; m=${m%.log}
  grep -oE "^h4-[A-Za-z0-9-]+ (\([0-9],[0-9]\)|all n, r) [a-z]+: [a-z]+" $l | awk -v m=$m '{v=$NF; c=$1; k=c" "m; a[k]=(k in a)? a[k]","v : v} END{for(k in a) print k": "a[k]}'
done | sort
