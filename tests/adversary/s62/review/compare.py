"""Compare a verify --format json output with numpy truth.  usage: compare.py SEED N R results.json"""
import json
import subprocess
import sys
seed, n, r, path = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
truth = json.loads(subprocess.run([sys.executable, "numpy_truth.py", seed, n, r], capture_output=True, text=True,
                                  check=True).stdout)
res = json.load(open(path))["results"]
bad, tally = [], {}
for rec in res:
    if f"{rec['n']},{rec['r']}" != f"{n},{r}":
        continue
    t = truth[rec["claim"]]
    v = rec["verdict"]
    tally[(t, v)] = tally.get((t, v), 0) + 1
    wrong = (t and v == "fails") or (not t and v in ("proved", "checked", "numeric"))
    if wrong:
        bad.append((rec["claim"], rec["method"], v, t))
print(sorted(tally.items()), "WRONG:", bad)
