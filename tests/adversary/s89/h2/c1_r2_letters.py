# ruff: noqa: E702
"""s89h2: the dimension-free method's letters at a declared r = 2 (E₁, E₂ with E₁E₁ᵀ + E₂E₂ᵀ = I_r).
 r2-comm-false (FALSE): PᵀP·XᵀAX = XᵀAX·PᵀP (two symmetric 2×2 matrices need not commute; numpy).
 r2-psi-sq-true (TRUE): Ψ² = −½tr(ΨᵀΨ)·I_r (Ψ skew 2×2).
 r2-ch-true (TRUE): Cayley–Hamilton at r = 2: M² − tr(M)M + ½(tr(M)² − tr(M²))I = 0, M = PᵀAX + XᵀP.
 r2-ch-false (FALSE): M² − tr(M)M + ½(tr(M)² + tr(M²))I = 0 (sign slip).
 r2-sym-false (FALSE): PᵀAX is symmetric (PᵀAX − XᵀAP = 0).
"""
from stiefelsym import admissible, claim
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
@claim("r2-comm-false", kind="id", sizes=R2)
def a(s):
    """FALSE: [PᵀP, XᵀAX] = 0."""
    U, V = s.P.T @ s.P, s.X.T @ s.A @ s.X
    return {"r": U @ V - V @ U}
@claim("r2-psi-sq-true", kind="id", sizes=R2)
def b(s):
    """TRUE: Ψ² = −½tr(ΨᵀΨ)I."""
    return {"r": s.Psi @ s.Psi + s.tr(s.Psi.T @ s.Psi) / 2 * s.Ir}
def _M(s): return s.P.T @ s.A @ s.X + s.X.T @ s.P
@claim("r2-ch-true", kind="id", sizes=R2)
def c(s):
    """TRUE: Cayley–Hamilton at r = 2."""
    M = _M(s); t = s.tr(M)
    return {"r": M @ M - t * M + (t * t - s.tr(M @ M)) / 2 * s.Ir}
@claim("r2-ch-false", kind="id", sizes=R2)
def d(s):
    """FALSE: the sign slip."""
    M = _M(s); t = s.tr(M)
    return {"r": M @ M - t * M + (t * t + s.tr(M @ M)) / 2 * s.Ir}
@claim("r2-sym-false", kind="id", sizes=R2)
def e(s):
    """FALSE: PᵀAX symmetric."""
    return {"r": s.P.T @ s.A @ s.X - s.X.T @ s.A @ s.P}
