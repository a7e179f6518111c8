# ruff: noqa: E701, E702, E731, E741
"""Compare verdicts in logs/*.json with the truth (by hand + truth_numpy.py)."""
import glob
import json
import os
import collections
import sys
HERE = os.path.dirname(os.path.abspath(__file__))

def truth(c, n, r):
    """True / False / None (no truth of its own)."""
    if c in ("s88h2a-state", "s88h2a-generic-same-name"):
        return None
    if c == "s88h2a-float-const":
        return False
    if c == "s88h2a-swallow":
        return False
    if c.endswith("-twin"):
        if c == "s88h2-lambda-expansion-twin" and r == 1:
            return True
        return False
    return True

PASS = {"proved", "checked", "numeric"}
wrong, other, table = [], collections.Counter(), collections.defaultdict(dict)
nrec = 0
files = sys.argv[1:] or sorted(glob.glob(os.path.join(HERE, "logs", "*.json")))
for f in files:
    try:
        d = json.load(open(f))
    except Exception as e:
        print("unreadable", f, e); continue
    tag = os.path.basename(f)[:-5]
    for rec in d["results"]:
        nrec += 1
        c, n, r, v = rec["claim"], rec["n"], rec["r"], rec["verdict"]
        t = truth(c, n, r)
        table[(c, tag)][(n, r)] = v
        if t is None:
            continue
        if (t and v == "fails") or (not t and v in PASS):
            wrong.append((tag, c, n, r, v, t))
        elif v not in PASS and v != "fails":
            other[(tag, c, v)] += 1
print(nrec, "records;", "WRONG:", len(wrong))
for w in wrong: print("  WRONG", w)
for k, v in sorted(other.items()): print("  other", k, v)
if "-t" in os.environ.get("SHOW", ""):
    for (c, tag), row in sorted(table.items()):
        print(f"{tag:22s} {c:34s}", " ".join(f"{n},{r}:{v[:2]}" for (n, r), v in sorted(row.items(), key=lambda x: (x[0][0] or 0, x[0][1] or 0))))
