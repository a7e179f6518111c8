# ruff: noqa: F841, E702, F401, E731, E741
"""Review2 s63: a small claims file whose results are edited by hand (results_edits.py)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


@claim("rc-true", paper="t", kind="id", section="2", sizes=S)
def rc_true(s):
    """TRUE: d/dt tr(X^T X) = 0 along X' = P."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.X), {"X": s.P})}


@claim("rc-false", paper="t", kind="id", section="2", sizes=S)
def rc_false(s):
    """FALSE: tr(P^T P) = 0."""
    return {"r": s.tr(s.P.T @ s.P)}


@claim("rc-big", paper="t", kind="id", section="2", sizes=S)
def rc_big(s):
    """TRUE: a huge constant that cancels."""
    C = 2 ** 15000
    return {"r": (s.X * C + s.P) - s.X * C - s.P}
