# ruff: noqa
"""In-process: the catalog's checks run first (unsealed: slices interned), then a claims file loaded into the
process (sealed) whose claims share slices with each other; then stiefelsym.verify(files=...) (isolated).
Every verdict must be the claim's own, and the table must take no entry after the seal."""
import stiefelsym
from stiefelsym.methods import fixed_size as fs
from stiefelsym.claims import load_claims_file

base = stiefelsym.verify("euclidean-flow", sizes=[(3, 2)], methods="exact")
print("catalog:", [(r.claim, r.verdict) for r in base], "slices:", len(fs._SLICES))
reg = load_claims_file("intern_pair.py")
before = dict(fs._SLICES)
claims = [c for c in reg] if not hasattr(reg, "claims") else list(reg.claims.values())
res = stiefelsym.verify(claims, sizes=[(3, 2), (3, 3)], methods="exact")
for r in res:
    print(r.claim, r.variant, r.n, r.r, r.verdict, r.expected)
print("table unchanged after the seal:", dict(fs._SLICES) == before)
iso = stiefelsym.verify(files="intern_pair.py", sizes=[(3, 2)], methods="exact")
print("isolated:", [(r.claim, r.verdict, r.expected) for r in iso])
