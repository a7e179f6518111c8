#!/bin/bash
# usage: run.sh FILE TAG SIZEARGS METHOD...   e.g. run.sh c7_graph_edit.py c7e "--size 3,1" exact auto
cd /tmp/s89h2/main
F=$1; TAG=$2; SZ=$3; shift 3
for M in "$@"; do
  timeout 300 .venv/bin/stiefelsym verify --claims /tmp/s89h2/out/$F --method $M --jobs 1 --no-report $SZ --format json \
    > /tmp/s89h2/out/logs/${TAG}_${M}.json 2> /tmp/s89h2/out/logs/${TAG}_${M}.err
  echo "== $TAG $M rc=$?"
  python3 -c "
import json,sys
d=json.load(open('/tmp/s89h2/out/logs/${TAG}_${M}.json'))
recs=d['results']
for r in recs: print('  ',r.get('claim'),r.get('n'),r.get('r'),r.get('method'),r.get('verdict'),(r.get('message') or r.get('certificate') or '')[:110])
" 2>&1 | head -300
done
