"""Nonvanishing claims (expect="nonzero") under float and ball: the float method's `numeric` of a nonvanishing
claim rests on its first-order error bound alone (no exact confirmation when |value| > bound).  Each claim's
residual is written so that its TRUE value is known; the docstring says whether the claim ("the residual is
not identically zero") is TRUE or FALSE."""
from stiefelsym import admissible, claim

C = 2**60


def absorbed(s, M):
    """(C M + M) − C M: exactly M, computed as 0 in float64 where |M| < C u."""
    return (M * C + M) - M * C


@claim("s74-nz-square-absorbed", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def square_absorbed(s):
    """z z − tr(PᵀP)² with z = (C t + t) − C t, t = tr(PᵀP): identically 0, so the claim is FALSE."""
    t = s.tr(s.P.T @ s.P)
    z = absorbed(s, t)
    return {"w": z * z - t * t}


@claim("s74-nz-matrix-absorbed", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def matrix_absorbed(s):
    """Zᵀ Z − PᵀP with Z = (C P + P) − C P: identically 0, FALSE."""
    Z = absorbed(s, s.P)
    return {"w": Z.T @ Z - s.P.T @ s.P}


@claim("s74-nz-inverse-absorbed", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def inverse_absorbed(s):
    """(I + Z)⁻¹(I + PᵀP) − I with Z = (C PᵀP + PᵀP) − C PᵀP: identically 0, FALSE."""
    Z = absorbed(s, s.P.T @ s.P)
    return {"w": (s.Ir + Z).inv() @ (s.Ir + s.P.T @ s.P) - s.Ir}


@claim("s74-nz-division-absorbed", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def division_absorbed(s):
    """t / (1 + z) − t/(1 + t) with z = (C t + t) − C t, t = tr(PᵀP): identically 0, FALSE."""
    t = s.tr(s.P.T @ s.P)
    z = absorbed(s, t)
    return {"w": t / (1 + z) - t / (1 + t)}


@claim("s74-nz-tiny-true", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def tiny_true(s):
    """2⁻¹¹⁰⁰ tr(PᵀP) + 2⁻¹¹⁰⁰: nonzero (TRUE); underflows in float64."""
    return {"w": s.tr(s.P.T @ s.P) * s.q(1, 2**1100) + s.q(1, 2**1100)}


@claim("s74-nz-absorbed-true", kind="not", expect="nonzero", sizes=admissible(n_max=3))
def absorbed_true(s):
    """(C t + 1) − C t with t = tr(PᵀP) + 1: exactly 1, nonzero (TRUE); computed 0 in float64."""
    t = s.tr(s.P.T @ s.P) + 1
    return {"w": (t * C + 1) - t * C}
