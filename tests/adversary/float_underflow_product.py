"""A false claim the float method passes: every constant is inside the float range the pass checks
(2^-1000 .. 2^1000), but their product is not; c·c·tr(XᵀX) underflows to 0 in float64."""
from fractions import Fraction

from stiefelsym import admissible, claim


@claim("adv-underflow-product", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def tiny_times_tiny(s):
    """c²·tr(XᵀX) = 0 for c = 2^-600 (false: it is r·2^-1200)."""
    c = s.const(Fraction(1, 2 ** 600))
    return {"c^2 tr(XtX)": c * c * s.tr(s.X.T @ s.X)}
