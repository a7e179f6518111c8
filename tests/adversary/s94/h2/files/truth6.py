import json
import re
import sys
import numpy as np
rng = np.random.default_rng(3)
src = open("/tmp/s94h2/files/c6/f6_many.py").read()
exprs = dict(re.findall(r'@claim\("(h2-m\d\d)".*?return \{"r": (.*?)\}\n', src, re.S))
class S: pass
def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    W = rng.standard_normal((r, r)); Om = W - W.T
    P = X @ Om + (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r))
    s = S(); s.X, s.P, s.Ir, s.In = X, P, np.eye(r), np.eye(n)
    d = rng.standard_normal(n); s.A = np.diag(d)
    return s
def holds(cid, n, r):
    return all(np.abs(eval(exprs[cid], {"s": point(n, r)})).max() < 1e-8 for _ in range(3))
bad = tot = 0
for path in sys.argv[1:]:
    for rec in json.load(open(path))["results"]:
        if rec.get("n") is None:
            t = all(holds(rec["claim"], n, r) for n in range(1, 7) for r in range(1, n + 1))
        else:
            t = holds(rec["claim"], rec["n"], rec["r"])
        v = rec["verdict"]; tot += 1
        ok = (v in ("proved", "checked", "numeric") and t) or (v == "fails" and not t) or v in ("undecided", "inconclusive")
        if not ok:
            bad += 1; print("WRONG", path, rec["claim"], rec.get("n"), rec.get("r"), rec["method"], v, "truth", t)
print(f"{tot} records compared, {bad} wrong")
