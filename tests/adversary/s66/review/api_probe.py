# ruff: noqa
"""Verdicts of a claims file through the Python API, with or without the catalog imported first."""
import sys, json
mode = sys.argv[1]
path = sys.argv[2]
methods = sys.argv[3].split(",")
if mode == "catalog":
    import stiefelsym.proofs  # noqa
import stiefelsym
before = sorted(m for m in ("stiefelsym.twisted", "stiefelsym.systems", "stiefelsym.brackets") if m in sys.modules)
res = stiefelsym.verify(files=[path], methods=methods, sizes=[(3, 2)], timeout=120)
after = sorted(m for m in ("stiefelsym.twisted", "stiefelsym.systems", "stiefelsym.brackets") if m in sys.modules)
print("before", before, "after", after)
for r in res:
    print(r.claim_id if hasattr(r, "claim_id") else getattr(r, "id", "?"), r.method, r.verdict, (getattr(r, "note", "") or "")[:150])
