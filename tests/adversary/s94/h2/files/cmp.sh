#!/bin/bash
# usage: cmp.sh FILE TAG [extra args]  -> runs jobs 1 and jobs 2, writes out/TAG.j1.json out/TAG.j2.json, prints diff
F=$1; T=$2; shift 2
PY="env PYTHONPATH=/tmp/s94h2/repo /work/main/.venv/bin/python"
cd /tmp/s94h2/files
for j in 1 2; do
  /usr/bin/time -f "j$j %e s" timeout 300 $PY -m stiefelsym verify --claims $F --jobs $j --format json --no-report "$@" > /tmp/s94h2/out/$T.j$j.json 2> /tmp/s94h2/out/$T.j$j.err
  echo "rc j$j: $?"; tail -1 /tmp/s94h2/out/$T.j$j.err
done
$PY /tmp/s94h2/files/cmpjson.py /tmp/s94h2/out/$T.j1.json /tmp/s94h2/out/$T.j2.json
