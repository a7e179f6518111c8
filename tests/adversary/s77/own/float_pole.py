"""Divisions the float method meets at a pole, and one it meets only for want of precision.  Docstrings state the
truth; each residual is 0 wherever it is defined."""
from fractions import Fraction

from stiefelsym import admissible, claim


@claim("s77-pole-at-n-100", kind="id", sizes=admissible(n_max=4))
def pole_at_n_100(s):
    """(c·tr PᵀP)/c = tr PᵀP, c = n − 100: undefined at n = 100, true elsewhere."""
    c = s.tr(s.In) - 100
    K = s.tr(s.P.T @ s.P)
    return {"w": (c * K) / c - K}


@claim("s77-pole-on-v", kind="id", sizes=admissible(n_max=4))
def pole_on_v(s):
    """(c·X)/c = X, c = tr(XᵀX) − r: c vanishes on all of V (no point is defined), float64 sees it only up to
    rounding."""
    c = s.tr(s.X.T @ s.X) - s.r
    return {"w": (s.X * c) / c - s.X}


@claim("s77-tiny-divisor", kind="id", sizes=admissible(n_max=4))
def tiny_divisor(s):
    """(c·tr PᵀP)/c = tr PᵀP, c = (1 + 10⁻³⁰ tr PᵀP) − 1, nonzero at every point with P ≠ 0: TRUE.  float64 rounds
    c to 0; more precision resolves it."""
    K = s.tr(s.P.T @ s.P)
    c = (1 + K * Fraction(1, 10**30)) - 1
    return {"w": (c * K) / c - K}
