"""s89h2 classes 2/5 on statements of non-vanishing (expect="nonzero"): a pass means "the residual is not
identically 0 on T*V"; a `fails` of a TRUE one or a pass of a FALSE one is a wrong verdict.  u = tr PᵀP + 1 (≥ 1).
 nz-underflow-true (TRUE): 2^-1100·u ≠ 0 (float64 underflows to 0).
 nz-overflow-true (TRUE): 2^1100·u ≠ 0 (float64 overflows).
 nz-tiny-true (TRUE): (u + 2^-60·u) − u ≠ 0 (float64 absorbs 2^-60·u into u: 0).
 nz-absorb-false (FALSE: identically 0): (2^60·u + u) − 2^60·u − u ≠ 0 (float64 may leave rounding garbage).
 nz-constraint-false (FALSE): tr(XᵀX) − tr(I_r) ≠ 0 (0 on T*V; float64 leaves ~1e-16).
 nz-constraint2-false (FALSE): tr((XᵀP + PᵀX)ᵀ(XᵀP + PᵀX)) ≠ 0 (0 on T*V).
 nz-big-const-false (FALSE: identically 0): (c·u − c·u) with c = 3^700 (an exact constant beyond float range).
"""
from fractions import Fraction
from stiefelsym import admissible, claim
ANY = admissible(n_max=3)
def u(s): return s.tr(s.P.T @ s.P) + 1

@claim("nz-underflow-true", kind="not", expect="nonzero", sizes=ANY)
def a(s):
    """TRUE: 2^-1100·u ≠ 0."""
    return {"r": Fraction(1, 2 ** 1100) * u(s)}

@claim("nz-overflow-true", kind="not", expect="nonzero", sizes=ANY)
def b(s):
    """TRUE: 2^1100·u ≠ 0."""
    return {"r": 2 ** 1100 * u(s)}

@claim("nz-tiny-true", kind="not", expect="nonzero", sizes=ANY)
def c(s):
    """TRUE: (u + 2^-60·u) − u ≠ 0."""
    return {"r": (u(s) + Fraction(1, 2 ** 60) * u(s)) - u(s)}

@claim("nz-absorb-false", kind="not", expect="nonzero", sizes=ANY)
def d(s):
    """FALSE: (2^60·u + u) − 2^60·u − u ≠ 0."""
    return {"r": (2 ** 60 * u(s) + u(s)) - 2 ** 60 * u(s) - u(s)}

@claim("nz-constraint-false", kind="not", expect="nonzero", sizes=ANY)
def e(s):
    """FALSE: tr(XᵀX) − tr(I_r) ≠ 0."""
    return {"r": s.tr(s.X.T @ s.X) - s.tr(s.Ir)}

@claim("nz-constraint2-false", kind="not", expect="nonzero", sizes=ANY)
def f(s):
    """FALSE: |XᵀP + PᵀX|² ≠ 0."""
    C = s.X.T @ s.P + s.P.T @ s.X
    return {"r": s.tr(C.T @ C)}

@claim("nz-big-const-false", kind="not", expect="nonzero", sizes=ANY)
def g(s):
    """FALSE: c·u − c·u ≠ 0 with c = 3^700."""
    c = 3 ** 700
    return {"r": c * u(s) - c * u(s)}
