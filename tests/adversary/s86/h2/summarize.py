# ruff: noqa: E702, M
"""Compare the engine's verdicts (logs/*.json) with the truth derived by hand and by truth_numpy.py."""
import glob
import json
import os
import collections

def truth(c, n, r):
    if not c.endswith("-twin"):
        return True
    base = c[:-5]
    if base in ("s86h2-jensen-pdot", "s86h2-jensen-accel", "s86h2-metric-lambda-equivariant",
                "s86h2-double-swap", "s86h2-coupled-torque", "s86h2-perturbed-euclid-dual-lax"):
        return r == 1
    if base == "s86h2-jensen-ptp":
        return r == 1 or r == n
    if base == "s86h2-double-diagonal-momenta":
        return r == n
    return False

PASS = {"proved", "checked", "numeric"}
rows = collections.defaultdict(dict)
wrong, other = [], collections.Counter()
nrec = 0
for f in sorted(glob.glob(os.path.join(os.path.dirname(__file__) or ".", "logs", "*.json"))):
    try:
        d = json.load(open(f))
    except Exception as e:
        print("unreadable", f, e); continue
    for rec in d["results"]:
        nrec += 1
        c, n, r, v = rec["claim"], rec["n"], rec["r"], rec["verdict"]
        m = os.path.basename(f).split("_")[0] + ("" if rec["method"] == os.path.basename(f).split("_")[0] else "->" + str(rec["method"]))
        t = truth(c, n, r)
        rows[(c, m)][(n, r)] = v
        if (t and v == "fails") or (not t and v in PASS):
            wrong.append((c, m, n, r, v, t, rec.get("rerun")))
        elif v not in PASS and v != "fails":
            other[(c, m, v)] += 1
print(f"{nrec} records")
print("WRONG VERDICTS:", len(wrong))
for w in wrong:
    print("  ", w)
print("refusals / other verdicts (claim, method, verdict): count")
for k, v in sorted(other.items()):
    print("  ", k, v)
sizes = sorted({s for v in rows.values() for s in v}, key=lambda s: (s[0] or 0, s[1] or 0))
ab = {"proved": "P", "checked": "C", "numeric": "N", "fails": "F", "undecided": "u", "inconclusive": "i", "error": "E"}
print("\nverdict table (P proved, C checked, N numeric, F fails, u undecided, i inconclusive, E error); truth T/F per size")
print("claim/method".ljust(48) + " ".join(f"{n},{r}".rjust(4) for n, r in sizes))
for (c, m) in sorted(rows):
    line = f"{c[6:]}/{m}".ljust(48)
    for s in sizes:
        v = rows[(c, m)].get(s)
        line += (ab.get(v, v[:1]) + ("T" if truth(c, *(s if s[0] else (9, 5))) else "F")).rjust(5) if v else "    ."
    print(line)
