# ruff: noqa
"""Driver (not a claims file): python dask_driver.py FILE CLAIM_ID METHOD [SCHEDULER]
Loads FILE with the public door stiefelsym.load_claims_file and verifies CLAIM_ID at (3,2), locally or on
the dask scheduler given (the only way a user's claim reaches the workers: `verify --scheduler --claims`
refuses every claim of a file, 'its source file cannot be read')."""
import sys

import stiefelsym

path, cid, method = sys.argv[1:4]
sched = sys.argv[4] if len(sys.argv) > 4 else None
if sched:     # the engine's own client is not the default one, and distributed.wait needs one (a crash otherwise)
    from distributed import Client
    _default = Client(sched)
reg = stiefelsym.load_claims_file(path)
c = reg.get(cid)
res = stiefelsym.verify([c], sizes=[(3, 2)], methods=[method], scheduler=sched)
for r in res:
    print(r.line(limit=200))
print("ok:", res.ok)
