"""s89h2 class 1: entries of r×r matrices (for charts that also reduce by O(r)) and of A (moved by the chart).
 c1r-xax01 (FALSE, r = 2): (XᵀAX)₁₂ = 0.  An O(r)-reduced chart diagonalizing XᵀAX would make it 0; numpy: ≠ 0.
 c1r-ptp01 (FALSE, r = 2): (PᵀP)₁₂ = 0.  numpy: ≠ 0 for n ≥ 3 (at (2,2) P = XW, PᵀP = WᵀW = w²I: TRUE there).
 c1r-xtp-diag (TRUE): (XᵀP)₁₁ = 0 (XᵀP is skew on T*V).
 c1r-psi12 (TRUE, r = 2): Ψ₁₂² = tr(ΨᵀΨ)/2.
 c1r-psi12-false (FALSE, r = 2): Ψ₁₂ = tr(ΨᵀΨ)/2 (degree 1 vs 2).
 c1r-a01 (TRUE, n ≥ 2): A₁₂ = 0 (A = diag(a)).  c1r-a00 (TRUE): A₁₁ = a₁.  c1r-ainv00 (TRUE): (A⁻¹)₁₁·a₁ = 1.
 c1r-a00-false (FALSE, n ≥ 2): A₁₁ = a₂.
 c1r-phi-entry (FALSE, n ≥ 2, r = 1): Φ₁₂ = 0 (Φ = PXᵀ − XPᵀ; numpy ≠ 0).
"""
from stiefelsym import admissible, claim
R2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2")
N2 = admissible(n_max=3, n_min=2, condition="n >= 2")
R1 = admissible(n_max=3, n_min=2, r_max=1, condition="r = 1, n >= 2")
ANY = admissible(n_max=3)

@claim("c1r-xax01", kind="id", sizes=R2)
def a(s):
    """FALSE: (XᵀAX)₁₂ = 0."""
    return {"r": (s.X.T @ s.A @ s.X)[0, 1]}

@claim("c1r-ptp01", kind="id", sizes=R2)
def b(s):
    """FALSE for n ≥ 3: (PᵀP)₁₂ = 0."""
    return {"r": (s.P.T @ s.P)[0, 1]}

@claim("c1r-xtp-diag", kind="id", sizes=ANY)
def c(s):
    """TRUE: (XᵀP)₁₁ = 0."""
    return {"r": (s.X.T @ s.P)[0, 0]}

@claim("c1r-psi12", kind="id", sizes=R2)
def d(s):
    """TRUE: Ψ₁₂² = tr(ΨᵀΨ)/2."""
    p = s.Psi[0, 1]
    return {"r": p * p - s.tr(s.Psi.T @ s.Psi) / 2}

@claim("c1r-psi12-false", kind="id", sizes=R2)
def e(s):
    """FALSE: Ψ₁₂ = tr(ΨᵀΨ)/2."""
    return {"r": s.Psi[0, 1] - s.tr(s.Psi.T @ s.Psi) / 2}

@claim("c1r-a01", kind="id", sizes=N2)
def f(s):
    """TRUE: A₁₂ = 0."""
    return {"r": s.A[0, 1]}

@claim("c1r-a00", kind="id", sizes=ANY)
def g(s):
    """TRUE: A₁₁ = a₁."""
    return {"r": s.A[0, 0] - s.a[0]}

@claim("c1r-ainv00", kind="id", sizes=ANY)
def h(s):
    """TRUE: (A⁻¹)₁₁·a₁ = 1."""
    return {"r": s.Ainv[0, 0] * s.a[0] - 1}

@claim("c1r-a00-false", kind="id", sizes=N2)
def i(s):
    """FALSE: A₁₁ = a₂."""
    return {"r": s.A[0, 0] - s.a[1]}

@claim("c1r-phi-entry", kind="id", sizes=R1)
def j(s):
    """FALSE: Φ₁₂ = 0."""
    return {"r": s.Phi[0, 1]}
