"""Numbers in disguise and constants outside the float range that no literal shows: subclasses of int and
Fraction whose conversions lie, Decimal, numpy's bool, and powers of traced numbers (n^-700, (n + 1)^600,
(tr PᵀP + 5)^40) that underflow, overflow or absorb in float64 although every literal is small."""
from decimal import Decimal
from fractions import Fraction

import numpy as np

from stiefelsym import admissible, claim


class _LyingInt(int):
    """5 as an int, 0 through int() and index()."""

    def __int__(self):
        return 0

    def __index__(self):
        return 0


class _LyingFraction(Fraction):
    """1/3 as a Fraction, 0 as its numerator and as a float."""

    @property
    def numerator(self):
        return 0

    def __float__(self):
        return 0.0


@claim("adv-num-int-subclass", kind="id", sizes=admissible(n_max=3), statement="5 X = 0")
def int_subclass(s):
    """False: 5 X is not 0 (an int subclass whose int() is 0)."""
    return {"r": s.X * _LyingInt(5)}


@claim("adv-num-fraction-subclass", kind="id", sizes=admissible(n_max=3), statement="X / 3 = 0")
def fraction_subclass(s):
    """False (a Fraction subclass whose numerator and float are 0)."""
    return {"r": s.const(_LyingFraction(1, 3)) * s.X}


@claim("adv-num-resolvent-subclass", kind="id", sizes=admissible(n_max=3), statement="R(5) = R(0)")
def resolvent_subclass(s):
    """False: the spectral parameter an int subclass whose int() is 0."""
    return {"r": s.resolvent(_LyingInt(5)) - s.resolvent(0)}


@claim("adv-num-decimal", kind="id", sizes=admissible(n_max=3), statement="(c X + X) - c X = 0, c = 1e20")
def decimal_constant(s):
    """False: it is X (c a Decimal)."""
    c = Decimal("1e20")
    return {"r": (s.X * c + s.X) - s.X * c}


@claim("adv-num-numpy-bool", kind="id", sizes=admissible(n_max=3), statement="X - X b = 0, b = numpy True")
def numpy_bool(s):
    """True as numbers (b = 1) but b is a numpy bool: refused, never proved through it."""
    return {"r": s.X - s.X * np.bool_(True)}


@claim("adv-num-pow-underflow", kind="id", sizes=admissible(n_max=3), statement="n^-700 tr(X^T X) = 0")
def pow_underflow(s):
    """False: r n^-700 is about 10^-334, 0 in float64 (no literal is outside the float range)."""
    return {"r": s.tr(s.In) ** -700 * s.tr(s.X.T @ s.X)}


@claim("adv-num-pow-overflow", kind="id", sizes=admissible(n_max=3), statement="(c X + X) - c X = 0, c = (n + 1)^600")
def pow_overflow(s):
    """False: it is X; c is infinite in float64."""
    c = (s.tr(s.In) + 1) ** 600
    return {"r": (s.X * c + s.X) - s.X * c}


@claim("adv-num-pow-absorb-trace", kind="id", sizes=admissible(n_max=3),
       statement="(c + t) - c = 0, c = (tr P^T P + 5)^40, t = tr(X^T A X)")
def pow_absorb_trace(s):
    """False: it is t; c (above 10^28 at every point) absorbs t in double precision."""
    c = (s.tr(s.P.T @ s.P) + 5) ** 40
    t = s.tr(s.X.T @ s.A @ s.X)
    return {"r": (c + t) - c}
