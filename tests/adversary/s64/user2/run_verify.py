# ruff: noqa
"""Verify a claims file from Python; print one line per result and save a pickle-free summary.

usage: python run_verify.py FILE METHOD [n,r ...]   (env CLAIMS=id1,id2 to restrict)
"""
import json, os, sys, time
import stiefelsym

f, method, *sizes = sys.argv[1:]
t0 = time.time()
ids = os.environ.get("CLAIMS")
res = stiefelsym.verify(ids.split(",") if ids else None, files=f, methods=[method], sizes=sizes or None, jobs=1, timeout=300)
dt = time.time() - t0
rows = []
for r in res:
    rows.append(dict(claim=r.claim, n=r.n, r=r.r, method=r.method, verdict=r.verdict,
                     expected=r.expected, seconds=round(r.seconds, 3)))
    print(f"{r.claim:28s} ({r.n},{r.r}) {r.method:8s} {r.verdict:12s} expected={r.expected} {r.seconds:.2f}s")
print("ok:", res.ok, f"total {dt:.1f}s")
print(res.summary())
tag = os.environ.get("TAG", "")
out = f"/tmp/s64u2/{f.split('/')[-1].split('.')[0]}-{method}{tag}.json"
json.dump(rows, open(out, "w"), indent=1)
