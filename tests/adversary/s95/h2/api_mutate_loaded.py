"""A claim object of `stiefelsym.load` changed after loading (frozen fields set with object.__setattr__)."""
import dataclasses
import sys

import stiefelsym

F = sys.argv[1] if len(sys.argv) > 1 else "tests/adversary/s95/h2/c8_small.py"
reg = stiefelsym.load(files=F)
for cid in ("h2c-true", "h2c-false"):
    c = reg.get(cid) if hasattr(reg, "get") else reg[cid]
    for field, value in (("expect", "nonzero"), ("kind", "not")):
        try:
            c2 = dataclasses.replace(c, **{field: value})
        except Exception as e:      # noqa: BLE001
            print(cid, field, "replace refused:", type(e).__name__, str(e)[:150])
            continue
        try:
            res = stiefelsym.verify([c2], sizes=[(3, 2)], methods=["modular", "exact"], jobs=1)
            print(cid, field, value, [(r.method, r.verdict, r.expect if hasattr(r, "expect") else None) for r in res])
        except Exception as e:      # noqa: BLE001
            print(cid, field, "verify refused:", type(e).__name__, str(e)[:200])
    try:
        object.__setattr__(c, "expect", "nonzero")
        res = stiefelsym.verify([c], sizes=[(3, 2)], methods=["modular"], jobs=1)
        print(cid, "setattr expect", [(r.method, r.verdict) for r in res])
    except Exception as e:          # noqa: BLE001
        print(cid, "setattr refused:", type(e).__name__, str(e)[:200])
