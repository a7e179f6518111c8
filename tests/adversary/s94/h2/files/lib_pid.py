"""Library path: claims whose graph depends on the process (first pid seen in this process lineage, a counter of
calls), verified in-process with jobs=1 and jobs=2 (auto, sizes n = 5, 6)."""
import os
import sys
import stiefelsym
from stiefelsym import admissible, claim

FIRST = []
CALLS = [0]


@claim("lib-firstpid", kind="id", sizes=admissible(n_max=6), statement="X^T P + P^T X = 0 (or X^T P in a child)")
def firstpid(s):
    """true in the process that traced first, false (XᵀP) in any other"""
    if not FIRST:
        FIRST.append(os.getpid())
    if os.getpid() == FIRST[0]:
        return {"r": s.X.T @ s.P + s.P.T @ s.X}
    return {"r": s.X.T @ s.P}


@claim("lib-firstpid-rev", kind="id", sizes=admissible(n_max=6), statement="X^T P = 0 (or the constraint in a child)")
def firstpid_rev(s):
    """false in the process that traced first, true in any other"""
    if not FIRST:
        FIRST.append(os.getpid())
    if os.getpid() == FIRST[0]:
        return {"r": s.X.T @ s.P}
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("lib-parity", kind="id", sizes=admissible(n_max=6), statement="pid parity")
def parity(s):
    """true in processes of even pid, false in odd"""
    if os.getpid() % 2 == 0:
        return {"r": s.X.T @ s.P + s.P.T @ s.X}
    return {"r": s.X.T @ s.P}


if __name__ == "__main__":
    jobs = int(sys.argv[1])
    ids = sys.argv[2].split(",") if len(sys.argv) > 2 else None
    cs = [c for c in [firstpid.claim, firstpid_rev.claim, parity.claim] if ids is None or c.id in ids]
    res = stiefelsym.verify(cs, sizes=[(4, 2), (5, 1), (5, 2), (6, 2), (6, 3)], methods=["free", "auto"], jobs=jobs)
    for r in res:
        print(r.claim, r.method, r.n, r.r, r.verdict, (r.digest or "")[:10], (r.message or "")[:120])
