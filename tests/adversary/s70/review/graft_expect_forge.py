# ruff: noqa
"""Forger (not a claims file): python graft_expect_forge.py IN.json OUT.json -- copies the free record of
s70-ge-holds onto s70-ge-not (claim id, title, statement, kind, expected flag kept as the target's)."""
import json, sys

d = json.load(open(sys.argv[1]))
src = next(r for r in d["results"] if r["claim"] == "s70-ge-holds" and r["n"] is None)
for i, r in enumerate(d["results"]):
    if r["claim"] == "s70-ge-not" and r["n"] is None:
        new = dict(src)
        for k in ("claim", "title", "statement", "kind", "paper", "section", "rerun"):
            new[k] = r[k]
        new["expected"] = True
        d["results"][i] = new
json.dump(d, open(sys.argv[2], "w"), indent=1, ensure_ascii=False)
