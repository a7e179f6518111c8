# ruff: noqa
"""Class 2 (floats in disguise): number-like objects that are not int/Fraction as constants.
Each residual is FALSE (nonzero on T*V) unless its disguised constant is read as its displayed value."""
from fractions import Fraction
from decimal import Decimal
import numpy as np
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))


class Lying(int):
    """an int whose value is 1 but whose arithmetic says 0"""
    def __mul__(self, o): return 0
    __rmul__ = __mul__
    def __add__(self, o): return o
    __radd__ = __add__
    def __index__(self): return 0
    def __int__(self): return 0


class LyingF(Fraction):
    def __new__(cls): return super().__new__(cls, 1, 1)
    @property
    def numerator(self): return 0


@claim("c2-lying-int", kind="id", sizes=S)
def lying_int(s):
    """X * Lying(1): false (X != 0)."""
    return {"x": s.X * Lying(1)}


@claim("c2-lying-int-radd", kind="id", sizes=S)
def lying_int2(s):
    """tr(X^T X) - r + Lying(1): = 1, false."""
    return {"x": s.tr(s.X.T @ s.X) - s.r + Lying(1)}


@claim("c2-lying-frac", kind="id", sizes=S)
def lying_frac(s):
    """X * LyingF(): false."""
    return {"x": s.X * LyingF()}


@claim("c2-bool", kind="id", sizes=S)
def bool_const(s):
    """X * True - X: true (True == 1)."""
    return {"x": s.X * True - s.X}


@claim("c2-bool-false", kind="id", sizes=S)
def bool_false(s):
    """X * True: false."""
    return {"x": s.X * True}


@claim("c2-np-int64-overflow", kind="id", sizes=S)
def np_overflow(s):
    """c = int64(2**62)*4 wraps to 0 in numpy; the true product 2**64 != 0: X * c is false."""
    with np.errstate(over="ignore"):
        c = np.int64(2 ** 62) * np.int64(4)
    return {"x": s.X * c}


@claim("c2-decimal", kind="id", sizes=S)
def dec(s):
    """X * Decimal('1e-400') (nonzero): false."""
    return {"x": s.X * Decimal("1e-400")}


@claim("c2-np-bool", kind="id", sizes=S)
def npbool(s):
    """X * np.True_: false."""
    return {"x": s.X * np.True_}


@claim("c2-pow-npint", kind="id", sizes=S)
def powint(s):
    """(X^T X)^np.int8(3) - I: true on T*V."""
    return {"x": (s.X.T @ s.X) ** np.int8(3) - s.Ir}


@claim("c2-q-lying", kind="id", sizes=S)
def q_lying(s):
    """X * s.q(Lying(1), 1): false."""
    return {"x": s.X * s.q(Lying(1), 1)}


@claim("c2-frac-of-float", kind="id", sizes=S)
def frac_float(s):
    """X * (Fraction(0.1) - Fraction(1, 10)): Fraction(0.1) is the binary double, != 1/10, so this is FALSE."""
    return {"x": s.X * (Fraction(0.1) - Fraction(1, 10))}
