"""s89h2: the dimension-free method's letters at a declared r = 1 (E₁, every r×r matrix a scalar); the
fixed-size methods decide the same statements.  Truth: by hand (r = 1: x, p ∈ ℝⁿ, |x| = 1, xᵀp = 0) and numpy.
 r1-ppt-false (FALSE, n ≥ 2): P Pᵀ = tr(PᵀP)·X Xᵀ  (p pᵀ vs |p|² x xᵀ: different rank-1 matrices).
 r1-ppt-true (TRUE): (P Pᵀ)(P Pᵀ) = tr(PᵀP)·P Pᵀ.
 r1-phi-false (FALSE, n ≥ 2): P Xᵀ = X Pᵀ.
 r1-swap-false (FALSE, n ≥ 2): X Pᵀ A P Xᵀ = P Xᵀ A X Pᵀ  (xᵀ… : (pᵀAp) x xᵀ vs (xᵀAx) p pᵀ).
 r1-swap-true (TRUE): Xᵀ A P Pᵀ A X = (Xᵀ A P)(Pᵀ A X)  (a 1×1 product: the same words; trivially true).
 r1-scalar-true (TRUE): (XᵀAX)(PᵀP) X = X (PᵀP)(XᵀAX).
 r1-scalar-false (FALSE, n ≥ 2): (XᵀAX) P = P (XᵀAP)?? : (xᵀAx) p vs (xᵀAp) p — different scalars.
"""
from stiefelsym import admissible, claim
R1 = admissible(n_max=3, n_min=2, r_max=1, condition="r = 1, n >= 2")
X = lambda s: s.X
@claim("r1-ppt-false", kind="id", sizes=R1)
def a(s):
    """FALSE: PPᵀ = tr(PᵀP) XXᵀ."""
    return {"r": s.P @ s.P.T - s.tr(s.P.T @ s.P) * (s.X @ s.X.T)}
@claim("r1-ppt-true", kind="id", sizes=R1)
def b(s):
    """TRUE: (PPᵀ)² = tr(PᵀP) PPᵀ."""
    M = s.P @ s.P.T
    return {"r": M @ M - s.tr(s.P.T @ s.P) * M}
@claim("r1-phi-false", kind="id", sizes=R1)
def c(s):
    """FALSE: PXᵀ = XPᵀ."""
    return {"r": s.P @ s.X.T - s.X @ s.P.T}
@claim("r1-swap-false", kind="id", sizes=R1)
def d(s):
    """FALSE: XPᵀAPXᵀ = PXᵀAXPᵀ."""
    return {"r": s.X @ s.P.T @ s.A @ s.P @ s.X.T - s.P @ s.X.T @ s.A @ s.X @ s.P.T}
@claim("r1-scalar-true", kind="id", sizes=R1)
def e(s):
    """TRUE: (XᵀAX)(PᵀP)X = X(PᵀP)(XᵀAX)... as X·(PᵀP)·(XᵀAX) reordered."""
    a_, p_ = s.X.T @ s.A @ s.X, s.P.T @ s.P
    return {"r": s.X @ a_ @ p_ - s.X @ p_ @ a_}
@claim("r1-scalar-false", kind="id", sizes=R1)
def f(s):
    """FALSE: P (XᵀAX) = P (XᵀAP)."""
    return {"r": s.P @ (s.X.T @ s.A @ s.X) - s.P @ (s.X.T @ s.A @ s.P)}
