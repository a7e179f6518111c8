# ruff: noqa
"""Driver (not a claims file): python dask_driver2.py METHOD SCHEDULER FILE:ID [FILE:ID ...]
One stiefelsym.verify call on the dask cluster with claims of several files (the run server of the single-
threaded worker loads each file in its own process, one after the other)."""
import sys

import stiefelsym

method, sched = sys.argv[1:3]
if sched != "local":
    from distributed import Client
    _default = Client(sched)
claims = []
for spec in sys.argv[3:]:
    path, cid = spec.split(":")
    claims.append(stiefelsym.load_claims_file(path).get(cid))
res = stiefelsym.verify(claims, sizes=[(3, 2)], methods=[method], scheduler=None if sched == "local" else sched)
for r in res:
    print(r.line(limit=200))
print("ok:", res.ok)
