"""Adversary of the unconstrained chart (f340a62): a true claim that the Cayley chart proves at once (there
tr(XᵀX) = r exactly, so its powers are constants) and whose evaluation on the unconstrained chart (tr(XᵀX) a sum
of n r squares, its K-th power a polynomial of C(K + nr − 1, nr − 1) terms) takes the whole time budget: tried
first, the unconstrained chart turns a proof into `inconclusive`."""
from stiefelsym import Rank, claim

K = 40


def _residual(s):
    t = s.tr(s.X.T @ s.X)
    a = t ** K
    b = (t ** (K // 2)) * (t ** (K // 2 - 1)) * t
    return s.X[0, 0] * (a - b)


@claim("u-cost-power", kind="id", sizes=[(3, 2)], statement="X11 (t^K - t^(K/2) t^(K/2-1) t) = 0, t = tr(X^T X)")
def cost_power(s):
    """True everywhere; cheap on the Cayley chart, costly on the unconstrained chart."""
    return {"r": _residual(s)}


@claim("u-cost-power-cayley", kind="id", sizes=[(3, 2)], statement="the same, with a trivial rank (Cayley chart)")
def cost_power_cayley(s):
    """The same residual; the trivial rank statement keeps the graph off the unconstrained chart."""
    return {"r": _residual(s), "rank": Rank(s.Ir, s.r)}
