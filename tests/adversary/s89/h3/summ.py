# ruff: noqa: E401
import json, sys, collections
rows = collections.defaultdict(dict)
for f in sys.argv[1:]:
    d = json.load(open(f))
    for r in d["results"]:
        rows[r["claim"]][(r["n"], r["r"], r["method"])] = r.get("verdict") + ("" if r.get("expected", True) in (True, None) else "!")
for c, v in rows.items():
    print(c, " ".join(f"{k[0]}{k[1]}{k[2][:3]}={x}" for k, x in sorted(v.items())))
