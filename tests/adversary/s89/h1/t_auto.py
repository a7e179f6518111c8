"""s89h1: auto at n >= 5 takes the dimension-free proof first.  Claims whose graph with symbolic sizes is
special at one size.

 s89h1-cancel-n5 (UNDEFINED at n = 5 / TRUE elsewhere): M (trI_n - 5)/(trI_n - 5) - M = 0, M = XᵀP.
    At n = 5 the claim divides by 0: must not be 'proved' at n = 5.  Stated at n = 5 only.
 s89h1-cancel-square (UNDEFINED at r = n): K (tr(XXᵀA) - trA)/(tr(XXᵀA) - trA) - K, K = XᵀP: at r = n
    XXᵀ = I so the divisor is identically 0.  Stated at (5,5) only.
    At (5,4) it is TRUE (the divisor is not identically 0 there).
 s89h1-n-minus-5 (TRUE at n = 5, FALSE elsewhere): (trI_n - 5) XᵀX = 0.
 s89h1-n-minus-5-twin (FALSE at n = 5): (trI_n - 6) XᵀX = 0 at n = 5.
 s89h1-square-only (TRUE only at r = n): XXᵀ - I_n = 0, at (5,5) (true) and (5,4) (false).
 s89h1-square-phi (TRUE at r = n): Φ = X Ψ Xᵀ at r = n (P = XK: PXᵀ - XPᵀ = X(K - Kᵀ)Xᵀ = XΨXᵀ ... with Ψ = XᵀP - PᵀX);
    FALSE for r < n.
 s89h1-r1-skew (TRUE at r = 1): Ψ = 0 (so(1) = 0); FALSE for r >= 2.
 s89h1-e6 (TRUE at n = 5): e_6(XXᵀ + A) = 0 for a 5x5 matrix (degree 5 char. poly); FALSE at n = 6.
 s89h1-n-minus-6 (TRUE at n = 6, FALSE at n = 5): (trI_n - 6) XᵀX = 0.
 s89h1-e6-r (TRUE for r <= 5, FALSE at (6,6)): e_6(XᵀX + PᵀP) = 0 (an r×r matrix; at (6,6) it is det(I + PᵀP) > 0).
 s89h1-e2-xxt (TRUE at every size, the free method proves it): e_2(XXᵀ) = r(r-1)/2 (XXᵀ a rank-r projector).
 s89h1-e2-xxt-twin (FALSE at every size): e_2(XXᵀ) = r(r+1)/2.
"""
from stiefelsym import claim, elementary


@claim("s89h1-cancel-n5", kind="id", sizes=[(5, 1), (5, 2), (6, 1)])
def cancel_n5(s):
    """M (n-5)/(n-5) = M: divides by 0 at n = 5."""
    d = s.tr(s.In) - 5
    M = s.X.T @ s.P
    return {"r": M * d / d - M}


@claim("s89h1-cancel-square", kind="id", sizes=[(5, 5), (5, 4)])
def cancel_square(s):
    """K d/d = K, d = tr(XXᵀA) - tr A: divides by 0 at r = n."""
    d = s.tr(s.X @ s.X.T @ s.A) - s.tr(s.A)
    K = s.X.T @ s.P
    return {"r": K * d / d - K}


@claim("s89h1-n-minus-5", kind="id", sizes=[(5, 1), (5, 2), (6, 1)])
def n_minus_5(s):
    """(n - 5) XᵀX = 0: true at n = 5 only."""
    return {"r": (s.tr(s.In) - 5) * (s.X.T @ s.X)}


@claim("s89h1-n-minus-6", kind="id", sizes=[(5, 1), (5, 2), (6, 1)])
def n_minus_6(s):
    """(n - 6) XᵀX = 0: true at n = 6 only."""
    return {"r": (s.tr(s.In) - 6) * (s.X.T @ s.X)}


@claim("s89h1-square-only", kind="id", sizes=[(5, 5), (5, 4), (6, 6)])
def square_only(s):
    """XXᵀ = I_n: true at r = n only."""
    return {"r": s.X @ s.X.T - s.In}


@claim("s89h1-square-phi", kind="id", sizes=[(5, 5), (5, 4), (6, 6), (6, 2)])
def square_phi(s):
    """Φ = XΨXᵀ: true at r = n only."""
    return {"r": s.Phi - s.X @ s.Psi @ s.X.T}


@claim("s89h1-r1-skew", kind="id", sizes=[(5, 1), (6, 1), (5, 2)])
def r1_skew(s):
    """Ψ = 0: true at r = 1 only."""
    return {"r": s.Psi}


@claim("s89h1-e6", kind="id", sizes=[(5, 1), (5, 2), (6, 1), (6, 2)])
def e6(s):
    """e_6(XXᵀ + A) = 0: true at n = 5 (a 5x5 matrix), false at n = 6."""
    return {"r": elementary(s, s.X @ s.X.T + s.A, 6)[6]}


@claim("s89h1-e6-r", kind="id", sizes=[(5, 1), (5, 2), (6, 1), (6, 2), (6, 6)])
def e6_r(s):
    """e_6(XᵀX + P^TP)... : e_6 of an r×r matrix is 0 for r < 6 (true at r <= 5, false at (6,6))."""
    return {"r": elementary(s, s.X.T @ s.X + s.P.T @ s.P, 6)[6]}


@claim("s89h1-e2-xxt", kind="id", sizes=[(5, 1), (5, 2), (6, 1), (6, 6), (5, 5)])
def e2_xxt(s):
    """e_2(XXᵀ) = r(r-1)/2 (true at every size: XXᵀ is a projector of rank r)."""
    r = s.tr(s.Ir)
    return {"r": elementary(s, s.X @ s.X.T, 2)[2] - r * (r - 1) / 2}


@claim("s89h1-e2-xxt-twin", kind="id", sizes=[(5, 1), (5, 2), (6, 1), (6, 6), (5, 5)])
def e2_xxt_twin(s):
    """e_2(XXᵀ) = r(r+1)/2 (false unless r = 0)."""
    r = s.tr(s.Ir)
    return {"r": elementary(s, s.X @ s.X.T, 2)[2] - r * (r + 1) / 2}
