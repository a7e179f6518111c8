# ruff: noqa
"""Marks the declared truth (fails_at of negatives.py, 'true' for claims.py) against indep_output.txt, then every
decided verdict of verify logs against that truth: `python compare.py indep_output.txt LOG...`."""
import re, sys, ast

truth = {}
for line in open(sys.argv[1]):
    m = re.match(r"(\S+): (.*)", line)
    if not m or "counts (" in line:
        continue
    for n, r, tf in re.findall(r"\((\d+),(\d+)\) ([TF])", m.group(2)):
        truth[(m.group(1), int(n), int(r))] = tf == "T"
for line in open(sys.argv[1]):
    m = re.match(r"h71b-neumann2-counts \((\d+),(\d+)\): ([TF]);  n71b-neumann2-rank-so-r: ([TF])", line)
    if m:
        n, r = int(m.group(1)), int(m.group(2))
        truth[("h71b-neumann2-counts", n, r)] = m.group(3) == "T"
        truth[("n71b-neumann2-rank-so-r", n, r)] = m.group(4) == "T"
right = wrong = undecided = 0
for log in sys.argv[2:]:
    for line in open(log):
        m = re.match(r"(\S+) \((\d+),(\d+)\) (\w+): (\w+)", line)
        if not m:
            continue
        cid, n, r, meth, v = m.group(1), int(m.group(2)), int(m.group(3)), m.group(4), m.group(5)
        t = truth.get((cid, n, r))
        if t is None or v not in ("proved", "checked", "numeric", "fails"):
            undecided += v not in ("proved", "checked", "numeric", "fails")
            continue
        ok = (v != "fails") == t
        right += ok
        if not ok:
            wrong += 1
            print("WRONG:", line.strip()[:200])
print(f"right {right}, wrong {wrong}, no decision or no numpy truth at that size {undecided}")
