# ruff: noqa
"""Probe: does the dimension-free method use the r = 1 hypotheses (X^T P = 0 on T*V(n, 1))?"""
from stiefelsym import admissible, claim


@claim("s65p-r1-rmax", kind="id", sizes=admissible(n_max=4, r_max=1, condition="r = 1"))
def r1_rmax(s):
    """r = 1: P X^T P = 0 (X^T P = 0), declared with r_max=1."""
    return {"P X^T P": s.P @ s.X.T @ s.P}


@claim("s65p-r1-rin", kind="id", sizes=admissible(n_max=4, r_in=(1,), condition="r = 1"))
def r1_rin(s):
    """r = 1: P X^T P = 0, declared with r_in=(1,)."""
    return {"P X^T P": s.P @ s.X.T @ s.P}


@claim("s65p-r1-xtp", kind="id", sizes=admissible(n_max=4, r_max=1, condition="r = 1"))
def r1_xtp(s):
    """r = 1: X^T P = 0."""
    return {"X^T P": s.X.T @ s.P}


@claim("s65p-r1-false", kind="id", sizes=admissible(n_max=4, n_min=2, r_max=1, condition="r = 1"),
       fails_at=lambda n, r: True, erratum="probe: X P^T P is not 0 at r = 1")
def r1_false(s):
    return {"X P^T P": s.X @ s.P.T @ s.P}
