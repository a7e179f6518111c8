# ruff: noqa
"""Class 5 (float underflow / overflow of constants).  'true'/'false' in each docstring is the truth on T*V."""
from fractions import Fraction
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))
T = Fraction(1, 2 ** 600)


@claim("c5-split-underflow", kind="id", sizes=S)
def split(s):
    """false: (X * 2^-600) * 2^-600 = 0 (two representable constants, an underflowing product)."""
    return {"x": (s.X * T) * T}


@claim("c5-split-underflow-trace", kind="id", sizes=S)
def split_tr(s):
    """false: tr((X 2^-600)^T (X 2^-600)) * 2^-600 = 0 (it is r 2^-1800)."""
    Y = s.X * T
    return {"x": s.tr(Y.T @ Y) * T}


@claim("c5-sub-underflow", kind="id", sizes=S)
def sub_under(s):
    """false: (X^T X * 2^-537) * 2^-537 - (I * 2^-537) * 2^-537 + I * 2^-1074 * 3 = 0 (it is 3*2^-1074 I)"""
    a = Fraction(1, 2 ** 537)
    return {"x": ((s.X.T @ s.X) * a) * a - (s.Ir * a) * a + s.Ir * Fraction(3, 2 ** 1074)}


@claim("c5-overflow-true", kind="id", sizes=S)
def over_true(s):
    """true: ((2^800 X)^T (2^800 X)) 2^-1600 - I = 0 (intermediate 2^1600 overflows float64)."""
    B = s.X * 2 ** 800
    return {"x": (B.T @ B) * Fraction(1, 2 ** 1600) - s.Ir}


@claim("c5-overflow-false", kind="id", sizes=S)
def over_false(s):
    """false: ((2^800 X)^T (2^800 X)) 2^-1600 - 2 I = 0 (it is -I)."""
    B = s.X * 2 ** 800
    return {"x": (B.T @ B) * Fraction(1, 2 ** 1600) - 2 * s.Ir}


@claim("c5-cancel-huge", kind="id", sizes=S)
def cancel(s):
    """false: (X + 2^-1100 X) - X = 0 (it is 2^-1100 X; float64 absorbs 2^-1100 X into X)."""
    return {"x": (s.X + s.X * Fraction(1, 2 ** 1100)) - s.X}


@claim("c5-cancel-huge-P", kind="id", sizes=S)
def cancel2(s):
    """false: (2^1000 X + P) - 2^1000 X = 0 (it is P)."""
    return {"x": (s.X * 2 ** 1000 + s.P) - s.X * 2 ** 1000}


@claim("c5-lam-scaled", kind="id", sizes=S)
def lam_scaled(s):
    """false: lam * 2^-1074 * 2^-2 * X = 0 (a parameter times a constant below the smallest subnormal)."""
    return {"x": (s.lam * Fraction(1, 2 ** 1074)) * Fraction(1, 4) * s.X}
