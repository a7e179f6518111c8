"""Summarize logs/<method>.json into a table: claim x method -> verdict counts; flag wrong verdicts.
A twin (id ending in -twin*) is false at every size it is stated for (derive_numpy.log); an honest claim is true."""
import json
import os
from collections import Counter, defaultdict
methods = ["exact", "modular", "rational", "float", "ball", "free", "auto"]
pass_verdicts = {"proved", "checked", "numeric"}
table = defaultdict(dict)
wrong = []
for m in methods:
    seen = {}
    for fn in sorted(os.listdir("logs")):
        if not (fn.startswith(m + ".") or fn.startswith(m + "_")) or not fn.endswith(".json"):
            continue
        try:
            d = json.load(open(os.path.join("logs", fn)))
        except Exception:
            continue
        for rec in d["results"]:
            key = (rec["claim"], rec.get("n"), rec.get("r"), rec.get("size"))
            seen[key] = rec
    per = defaultdict(Counter)
    for (c, n, r, _), rec in seen.items():
        v = rec["verdict"]
        per[c][v] += 1
        twin = "-twin" in c
        if (twin and v in pass_verdicts) or (not twin and v == "fails"):
            wrong.append((c, m, n, r, v, (rec.get("detail") or rec.get("message") or "")[:200]))
    for c, cnt in per.items():
        table[c][m] = ", ".join(f"{v} {k}" for v, k in sorted(cnt.items()))
print("| statement | " + " | ".join(methods) + " |")
print("|---|" + "---|" * len(methods))
for c in sorted(table):
    print(f"| {c} | " + " | ".join(table[c].get(m, "-") for m in methods) + " |")
print()
print("WRONG VERDICTS:", len(wrong))
for w in wrong:
    print(w)
