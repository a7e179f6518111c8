# ruff: noqa: F841, E702, F401, E731, E741
"""Review2 s63: a second claims file with the same claim ids as recs.py, different statements
(rc-true here is FALSE: tr(X^T P) + 1 = 0)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


@claim("rc-true", paper="t", kind="id", section="2", sizes=S)
def rc_true(s):
    """TRUE: d/dt tr(X^T X) = 0 along X' = P."""
    return {"r": s.tr(s.X.T @ s.P) + 1}
