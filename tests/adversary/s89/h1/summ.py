# ruff: noqa: E702
import json
import sys
for f in sys.argv[1:]:
    try:
        d = json.load(open(f))
    except Exception as e:
        print(f, "unreadable", e); continue
    for r in d["results"]:
        print(f"{r['claim']:34s} ({r.get('n')},{r.get('r')}) {r.get('method'):8s} {r.get('verdict'):12s} exp={r.get('expected')} | {(r.get('message') or '')[:160]} | {(r.get('certificate') or '')[:120]}")
