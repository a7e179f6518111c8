# ruff: noqa
"""Probe: float64 error model on resolvent products (term scale 0 with a nonzero bound)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3, n_min=2)


@claim("s65p-resolvent-offdiag", kind="id", sizes=S)
def resolvent_offdiag(s):
    """R = (lam - A)^-1; A R - R A = 0 (commute)."""
    R = s.resolvent(s.lam)
    return {"[A, R]": s.A @ R - R @ s.A}


@claim("s65p-resolvent-inv", kind="id", sizes=S)
def resolvent_inv(s):
    """(lam I - A) R = I."""
    R = s.resolvent(s.lam)
    return {"(lam - A) R - I": (s.lam * s.In - s.A) @ R - s.In}


@claim("s65p-resolvent-explicit-inv", kind="id", sizes=S)
def resolvent_explicit_inv(s):
    """(lam I - A).inv() equals s.resolvent(lam)."""
    return {"inv - R": (s.lam * s.In - s.A).inv() - s.resolvent(s.lam)}
