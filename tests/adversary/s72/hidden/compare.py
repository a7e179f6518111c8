"""Compare every decided verdict of stiefelsym logs with indep.py's numpy answer.

usage: python compare.py INDEP_OUTPUT LOG [LOG ...]
A verdict proved/checked/numeric says "true", fails says "false"; undecided/inconclusive/error decide nothing.
A free-method "all n, r" verdict is compared with every size numpy ran for the claim."""
import re
import sys
from collections import Counter

truth = {}
for line in open(sys.argv[1]):
    if line.startswith("#") or not line.strip():
        continue
    cid, n, r, ans = line.split()[:4]
    truth[(cid, int(n), int(r))] = ans == "true"

pat = re.compile(r"^(\S+) \((\d+),(\d+)\) (\w+): (\w+)")
pat_free = re.compile(r"^(\S+) all n, r (\w+): (\w+)")
count = Counter()
for log in sys.argv[2:]:
    for line in open(log):
        m = pat.match(line)
        if m:
            cid, n, r, method, verdict = m.group(1), int(m.group(2)), int(m.group(3)), m.group(4), m.group(5)
            keys = [(cid, n, r)]
        else:
            m = pat_free.match(line)
            if not m:
                continue
            cid, method, verdict = m.groups()
            keys = [k for k in truth if k[0] == cid]
        if verdict in ("proved", "checked", "numeric"):
            said = True
        elif verdict == "fails":
            said = False
        else:
            count["no decision"] += 1
            print(f"NO DECISION {cid} {keys[0][1:] if len(keys) == 1 else 'all'} {method}: {verdict}")
            continue
        for k in keys:
            if k not in truth:
                count["no numpy"] += 1
                print(f"NO NUMPY {k} {method} {verdict}")
                continue
            if truth[k] == said:
                count["right"] += 1
            else:
                count["WRONG"] += 1
                print(f"WRONG {k} {method}: {verdict}, numpy says {'true' if truth[k] else 'false'}")
print(dict(count))
