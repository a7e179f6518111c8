# ruff: noqa
"""s74: the slow exact runs of h74-coupled-trace-energy reduced (finding c1)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3)


@claim("q74-xay-symmetric", kind="id", sizes=S)
def xay_symmetric(s):
    """tr(XᵀAY) = tr(YᵀAX): A symmetric (a degree-2 identity in the two points)."""
    return {"tr X^T A Y - tr Y^T A X": s.tr(s.X.T @ s.A @ s.Y) - s.tr(s.Y.T @ s.A @ s.X)}


@claim("q74-xyyx-trace", kind="id", sizes=S)
def xyyx_trace(s):
    """tr(XYᵀYXᵀ) = r: XᵀX = YᵀY = I_r."""
    return {"tr X Y^T Y X^T - r": s.tr(s.X @ s.Y.T @ s.Y @ s.X.T) - s.tr(s.Ir)}
