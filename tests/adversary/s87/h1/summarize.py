# ruff: noqa: E701, E702
"""Compare verdicts in logs/*.json with the truth (hand + truth_numpy.py). No stiefelsym import."""
import collections
import glob
import json
import os
import sys

def _delta2(n, r):
    dso = lambda m: m * (m - 1) // 2
    dimV = n * r - r * (r + 1) // 2
    ddim = dimV - dso(n - r) + (dso(n - 2 * r) if n > 2 * r else 0)
    tl = (n * (n - 1) // 2 - n // 2) if n <= 2 * r + 1 else 2 * r * (n - r - 1)
    return 2 * (2 * dimV - ddim) - tl

TW = {  # twin / trick -> truth(n, r); None = unknown (not judged)
    "s87h1-manakov-euler-twin": lambda n, r: n <= 2,
    "s87h1-manakov-quartic-twin": lambda n, r: n <= 2,
    "s87h1-gram-psi-bracket-twin": lambda n, r: r in (1, n),
    "s87h1-manakov-delta-twin": lambda n, r: _delta2(n, r) == 2 * r * (n - r),
    "s87h1-lambda-1-minus-2-twin": lambda n, r: n == 1,
    "s87h1-kernel-l3-l4-twin": lambda n, r: n == 1,
    "s87h1-hb-euler-twin": lambda n, r: r <= 2,
    "s87h1-neum-b-euler-twin": lambda n, r: r == 1,
    "s87h1-lema1-rank-twin": lambda n, r: r <= 1,
    "s87h1-lema1-count-twin": lambda n, r: False,
    "s87h1-neumann2-rank-twin": lambda n, r: r <= 2,
    "s87h1-velocity-psi-twin": lambda n, r: r == 1,
    "s87h1-ne-multiplier-twin": lambda n, r: r == 1,
    "s87h1k-gram-psi-square": lambda n, r: r == n,
    "s87h1k-xptx-zero": lambda n, r: r == 1,
    "s87h1k-xxt-identity": lambda n, r: r == n,
    "s87h1k-rank-every-point": lambda n, r: None if r <= 2 else False,
    "s87h1k-xtax-offdiag": lambda n, r: False,
    "s87h1k-not-constraint": lambda n, r: False,
    "s87h1k-inverse-r1": lambda n, r: r == 1,
    "s87h1k-phi-conserved-neumann": lambda n, r: n == 1 or r == n,
    "s87h1k-ad-a-rank-everywhere": lambda n, r: None,
    "s87h1k-not-xxt": lambda n, r: r < n,
    "s87h1k-not-psi": lambda n, r: r >= 2,
    "s87h1k-inverse-kappa": lambda n, r: False,
    "s87h1k-inverse-trA": lambda n, r: False,
    "s87h1k-inverse-c": lambda n, r: False,
    "s87h1k-not-mixed": lambda n, r: None,   # FALSE read as 'both nonzero', TRUE read as 'some residual nonzero'
    "s87h1k-count-scalar-true": lambda n, r: True,
    "s87h1k-count-scalar-false": lambda n, r: False,
    "s87h1k-det-plus": lambda n, r: False,
    "s87h1k-det-minus": lambda n, r: False,
    "s87h1k-det-square": lambda n, r: True,
    "s87h1k-n0-ne-coincide": lambda n, r: r == 1,
}

def truth(c, n, r):
    if n is None:   # dimension-free: the statement for every n, r
        if c in TW:
            return all(TW[c](nn, rr) is not False for nn in range(1, 8) for rr in range(1, nn + 1))
        return True
    return TW[c](n, r) if c in TW else True

PASS = {"proved", "checked", "numeric"}
files = sys.argv[1:] or sorted(glob.glob(os.path.join(os.path.dirname(os.path.abspath(__file__)), "logs", "*.json")))
rows = collections.defaultdict(dict); wrong = []; other = collections.Counter(); nrec = 0
for f in files:
    try:
        d = json.load(open(f))
    except Exception as e:
        print("unreadable", f, e); continue
    tag = os.path.basename(f)[:-5]
    for rec in d["results"]:
        nrec += 1
        c, n, r, v = rec["claim"], rec.get("n"), rec.get("r"), rec["verdict"]
        m = tag + ("" if tag.endswith(rec["method"]) else "->" + rec["method"])
        t = truth(c, n, r)
        rows[(c, m)][(n, r)] = v
        if (t is True and v == "fails") or (t is False and v in PASS):
            wrong.append((c, m, n, r, v, t))
        elif v not in PASS and v != "fails":
            other[(c, m, v, (rec.get("reason") or rec.get("detail") or rec.get("message") or "")[:150])] += 1
print(f"{nrec} records")
print("WRONG VERDICTS:", len(wrong))
for w in wrong: print("  ", w)
print("other verdicts:")
for k, v in sorted(other.items()): print("  ", v, k)
sizes = sorted({s for v in rows.values() for s in v}, key=lambda s: (s[0] or 0, s[1] or 0))
ab = {"proved": "P", "checked": "C", "numeric": "N", "fails": "F", "undecided": "u", "inconclusive": "i", "error": "E"}
print("claim/method".ljust(44) + " ".join(f"{n},{r}".rjust(5) for n, r in sizes))
for (c, m) in sorted(rows):
    line = f"{c[5:]}/{m}"[:43].ljust(44)
    for s in sizes:
        v = rows[(c, m)].get(s)
        t = truth(c, *s)
        line += (ab.get(v, v[:1]) + {True: "T", False: "F", None: "?"}[t]).rjust(6) if v else "     ."
    print(line)
