#!/bin/sh
# run.sh FILE [methods...]: verify FILE with each method into logs/FILE.METHOD.log
f=$1; shift
ms=${*:-"free exact modular float ball"}
for m in $ms; do
  timeout 900 /tmp/r81b/main/.venv/bin/stiefelsym verify --claims "$f" --method $m --jobs 1 --timeout 120 --no-report > "logs/$(basename $f .py).$m.log" 2>&1
  echo "== $f $m"; grep -E "^r81|^h4|^s81|Traceback" "logs/$(basename $f .py).$m.log" | sed 's/\(.\{230\}\).*/\1/' | head -60
done
