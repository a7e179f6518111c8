"""In-process Python API, route c: a claim of one's own given reviewed=True and a reason by dataclasses.replace.
FALSE: the last row of X vanishes at (3,2)."""
import dataclasses
import stiefelsym
from stiefelsym import admissible, claim


@claim("mine-bottom-c", kind="id", sizes=admissible(n_max=3))
def bottom_row(s):
    """FALSE: the last row of X vanishes."""
    return {"x": s.X[2:3, :]}


c = dataclasses.replace(bottom_row.claim, reviewed=True, equivariance="the rows of X rotate with g (not true)")
for m in ("exact", "auto", "modular"):
    for r in stiefelsym.verify([c], sizes=[(3, 2)], methods=[m], jobs=1):
        print(f"{r.claim} ({r.n},{r.r}) {r.method}: {r.verdict} -- {(r.message or r.residual or '')[:100]} | {str(r.reductions)[:90]}")
