# ruff: noqa
"""Attempts on the new field `place` of an erratum (class 8: report ingestion)."""
from stiefelsym import admissible, claim


@claim("pl-false", kind="id", sizes=admissible(n_max=3, r_min=2),
       erratum="X^T P is skew, not zero", place="the proof of Theorem 7.1",
       expect="fails")
def pl_false(s):
    """X^T P = 0 (false at r >= 2)."""
    return {"XtP": s.X.T @ s.P}


@pl_false.claim.correction("X^T P + P^T X")
def pl_false_fixed(s):
    return {"XtP": s.X.T @ s.P + s.P.T @ s.X}


@claim("pl-noplace", kind="id", sizes=admissible(n_max=3, r_min=2),
       erratum="X^T P is skew, not zero", expect="fails")
def pl_noplace(s):
    """X^T P = 0 (false at r >= 2), erratum with no place."""
    return {"XtP": s.X.T @ s.P}
