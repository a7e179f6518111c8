"""s89h1: entries that vanish at every point of the exact method's equivariant chart (X₀ = (E₁ … E_r)) but not on T*V.

 s89h1-p00 (FALSE for n >= 2; TRUE at (1,1) where P = 0): P[0,0] = 0.  At X₀, P = (K; Z) with K skew: P[0,0] = 0 there.
 s89h1-x10 (FALSE for n >= 2): X[1,0] = 0 (0 at X₀).
 s89h1-xtax00 (FALSE for n >= 2): (XᵀAX)[0,0] = A[0,0]·... stated as (XᵀAX)[0,0] − (XᵀX)[0,0]·A[0,0] = 0 (true at X₀, A diagonal).
 s89h1-a01 (TRUE): A[0,1] = 0 (A diagonal).
 s89h1-xxt-entry (FALSE for r < n): (XXᵀ)[0,0] = 1 (true at X₀).
 s89h1-phi-entry (FALSE for n >= 3, r = 1): Φ[1,2] = 0 (true at X₀ with r = 1: Φ = p e₁ᵀ − e₁ pᵀ has Φ[1,2] = 0).
"""
from stiefelsym import claim

Z = [(2, 1), (3, 1), (3, 2), (5, 1), (5, 2), (6, 1)]


@claim("s89h1-p00", kind="id", sizes=Z)
def p00(s):
    """P[0,0] = 0 (false)."""
    return {"r": s.P[0, 0]}


@claim("s89h1-x10", kind="id", sizes=Z)
def x10(s):
    """X[1,0] = 0 (false)."""
    return {"r": s.X[1, 0]}


@claim("s89h1-xtax00", kind="id", sizes=Z)
def xtax00(s):
    """(XᵀAX)[0,0] = A[0,0] (false for n >= 2)."""
    return {"r": (s.X.T @ s.A @ s.X)[0, 0] - s.A[0, 0]}


@claim("s89h1-a01", kind="id", sizes=Z)
def a01(s):
    """A[0,1] = 0 (true)."""
    return {"r": s.A[0, 1]}


@claim("s89h1-xxt-entry", kind="id", sizes=Z)
def xxt_entry(s):
    """(XXᵀ)[0,0] = 1 (false for r < n)."""
    return {"r": (s.X @ s.X.T)[0, 0] - 1}


@claim("s89h1-phi-entry", kind="id", sizes=Z)
def phi_entry(s):
    """Φ[1,2] = 0 (false for n >= 3)."""
    return {"r": s.Phi[1, 2] if int(s.n) >= 3 else s.Phi[0, 1] * 0}
