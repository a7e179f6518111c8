# ruff: noqa
"""Marks every verdict of a verify log right or wrong against indep.py's output (numpy truth)."""
import re, sys
truth = {}
for line in open(sys.argv[1]):
    m = re.match(r"(\S+): (.*)", line)
    if not m or line.startswith("h71-counts"):
        continue
    cid, rest = m.groups()
    for t in re.finditer(r"\((\d+),(\d+)\) ([TF])", rest):
        truth[(cid, (int(t[1]), int(t[2])))] = t[3] == "T"
    for t in re.finditer(r"\((\d+),(\d+)\) \((\d+), (\d+)\) vs \((\d+), (\d+)\)", rest):
        truth[(cid, (int(t[1]), int(t[2])))] = (t[3], t[4]) == (t[5], t[6])
    for t in re.finditer(r"\((\d+),(\d+)\) (\d+) vs (\d+)(?!\))", rest):
        truth[(cid, (int(t[1]), int(t[2])))] = t[3] == t[4]
for n in range(1, 7):
    for r in range(1, n + 1):
        so = lambda m: m * (m - 1) // 2
        N = r * (n - r) + r * (r - 1) // 2
        two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
        truth[("h71-counts", (n, r))] = True
        truth[("h71-n-bigger-than-half", (n, r))] = 2 * N > two_l
        truth[("h71-n-bigger-than-half-corrected", (n, r))] = True
        truth[("n71-counts-n-off-by-one", (n, r))] = False
PASS = {"proved", "checked", "numeric"}
wrong, undecided, n_ok, missing = [], [], 0, []
for path in sys.argv[2:]:
    for line in open(path):
        m = re.match(r"(\S+) \((\d+),(\d+)\) (\w+): (\w+)", line)
        if not m:
            continue
        cid, n, r, meth, verdict = m[1], int(m[2]), int(m[3]), m[4], m[5]
        key = (cid, (n, r))
        if key not in truth:
            missing.append(key); continue
        t = truth[key]
        if verdict in PASS:
            (n_ok := n_ok + 1) if t else wrong.append(line.strip())
            if not t: pass
        elif verdict == "fails":
            (n_ok := n_ok + 1) if not t else wrong.append(line.strip())
        else:
            undecided.append(line.strip()[:160])
print(f"decided and right: {n_ok}; WRONG: {len(wrong)}; no decision: {len(undecided)}; without numpy truth: {len(set(missing))}")
for w in wrong: print("WRONG:", w)
for u in undecided: print("no decision:", u)
for k in sorted(set(missing)): print("no truth:", k)
