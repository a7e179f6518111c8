"""s73: compare every decided verdict of `stiefelsym verify` logs with the numpy truth of indep.py outputs.

Usage: compare.py INDEP_OUTPUT[,INDEP_OUTPUT...] LOG [LOG ...]
proved / checked / numeric = the statement holds (for a `not` claim: its residual is nonzero);
fails = it does not.  A dimension-free verdict ("all n, r") is compared with every size numpy ran for the
claim.  Undecided, inconclusive and error are listed apart (no decision)."""
import re
import sys
from collections import Counter

truth = {}
for f in sys.argv[1].split(","):
    for line in open(f):
        if line.startswith("#") or not line.strip():
            continue
        cid, n, r, tf = line.split()[:4]
        key = (cid, int(n), int(r))
        val = tf == "TRUE"
        if key in truth and truth[key] != val:
            print(f"numpy disagrees with itself at {key}")
        truth[key] = val

LINE = re.compile(r"^(\S+) \((\d+),(\d+)\) (\w+): (\w+)")
FREE = re.compile(r"^(\S+) all n, r (\w+): (\w+)")
PASS = {"proved", "checked", "numeric"}
right = wrong = 0
nodec = Counter()
wrongs = []
seen_missing = set()
for log in sys.argv[2:]:
    for line in open(log):
        m = LINE.match(line)
        if m:
            cid, n, r, meth, verdict = m.group(1), int(m.group(2)), int(m.group(3)), m.group(4), m.group(5)
            keys = [(cid, n, r)]
        else:
            m = FREE.match(line)
            if not m:
                continue
            cid, meth, verdict = m.groups()
            keys = [k for k in truth if k[0] == cid]
        if verdict not in PASS and verdict != "fails":
            nodec[(cid, meth, verdict)] += 1
            continue
        holds = verdict in PASS
        for k in keys:
            if k not in truth:
                seen_missing.add(k)
                continue
            if truth[k] == holds:
                right += 1
            else:
                wrong += 1
                wrongs.append(f"WRONG {log}: {line.strip()[:160]}  numpy: {'true' if truth[k] else 'false'} at {k}")
print("\n".join(wrongs))
print(f"right {right}, wrong {wrong}, without a decision {sum(nodec.values())}")
for (cid, meth, v), c in sorted(nodec.items()):
    print(f"  no decision: {cid} {meth} {v} x{c}")
if seen_missing:
    print("no numpy value for:", sorted(seen_missing)[:20], "..." if len(seen_missing) > 20 else "")
