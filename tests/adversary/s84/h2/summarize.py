# ruff: noqa: E702
"""Summarize logs/<method>.seed<k>.<file>.json: per claim x method verdict counts; flag wrong verdicts.
Truth: an id without '-twin' is TRUE at every size it is stated for; an id with '-twin' is FALSE at every size it
is stated for (sizes restricted so, checked by truth_numpy*.py).  For kind=not claims, 'proved' means the
statement (nonzero) holds.  Wrong: TRUE + fails, FALSE + proved/checked/numeric."""
import json
import glob
import os
import re
from collections import Counter, defaultdict
PASS = {"proved", "checked", "numeric"}
os.chdir(os.path.dirname(os.path.abspath(__file__)))
table = defaultdict(lambda: defaultdict(Counter))
wrong, notes = [], []
nruns = 0
for fn in sorted(glob.glob("logs/*.json")):
    m = re.match(r"logs/(\w+)\.seed(\d+)\.(\w+)\.json", fn)
    if not m:
        continue
    meth, seed, f = m.groups()
    try:
        d = json.load(open(fn))
    except Exception as e:
        notes.append(f"{fn}: unreadable ({e})"); continue
    for rec in d.get("results", []):
        nruns += 1
        c, v = rec["claim"], rec["verdict"]
        key = f"{meth}" + (f"/s{seed}" if meth != "free" else "")
        table[c][key][v] += 1
        twin = "-twin" in c
        size = (rec.get("n"), rec.get("r"))
        msg = (rec.get("detail") or rec.get("message") or rec.get("reason") or "")
        if (twin and v in PASS) or (not twin and v == "fails"):
            wrong.append((c, meth, seed, size, v, str(msg)[:300]))
        if v in ("error",):
            notes.append(f"ERROR {c} {meth} s{seed} {size}: {str(msg)[:300]}")
methods = sorted({k for c in table for k in table[c]})
print(f"runs: {nruns}")
print("| claim | " + " | ".join(methods) + " |")
print("|---|" + "---|" * len(methods))
for c in sorted(table):
    print(f"| {c} | " + " | ".join(", ".join(f"{v} {k}" for v, k in sorted(table[c][m].items())) or "-" for m in methods) + " |")
print("\nWRONG VERDICTS:", len(wrong))
for w in wrong:
    print(w)
print("\nNOTES:")
for n in notes[:80]:
    print(n)
