# ruff: noqa
"""Summarize `stiefelsym verify --format json` from stdin: claim, method, verdicts by size (q64 review)."""
import json, sys
from collections import defaultdict
d = json.load(sys.stdin)
rows = defaultdict(list)
for r in d["results"]:
    size = "all" if r["n"] is None else f"{r['n']},{r['r']}"
    tag = r["verdict"] + ("" if r.get("variant") is None else f"[corr]")
    rows[(r["claim"], r["method"])].append(f"{size}:{tag}")
for (c, m), v in rows.items():
    print(f"{c:28s} {m:8s} {' '.join(v)}")
