"""Statements true only at a hard case's special point (lambda = a_1 + 10^-12, eigenvalue gaps 10^-9)."""
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3)


@claim("h2h-near-pole", kind="id", sizes=SZ)
def near_pole(s):
    """False: lambda - a_1 - 10^-12 = 0."""
    return {"r": s.lam - s.A[0, 0] - Fraction(1, 10 ** 12)}


@claim("h2h-near-pole-res", kind="id", sizes=SZ)
def near_pole_res(s):
    """False: 1/(lambda - a_1) = 10^12, written with the resolvent: R(lambda)_{11} - 10^12 = 0."""
    return {"r": s.resolvent(s.lam)[0, 0] - 10 ** 12}


@claim("h2h-near-pole-tr", kind="id", sizes=SZ)
def near_pole_tr(s):
    """False: (lambda - a_1)(lambda - a_2) ... written without an entry: det-free, tr R(lambda) (lambda - a_1)..."""
    return {"r": (s.lam - s.A[0, 0]) * 10 ** 12 - 1}


@claim("h2h-gap", kind="id", sizes=SZ)
def gap(s):
    """False: a_2 - a_1 = 10^-9."""
    return {"r": s.A[1, 1] - s.A[0, 0] - Fraction(1, 10 ** 9)}


@claim("h2h-large", kind="id", sizes=SZ)
def large(s):
    """False: tr P^T P = 10^12 tr P^T P (true at P = 0 only)."""
    return {"r": s.tr(s.P.T @ s.P) * (10 ** 12 - 1)}
