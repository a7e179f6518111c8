"""Class 7: the standard library's Fraction class patched at import (its identity unchanged; the seal watches the
fractions module's attributes by identity only).  The patched `numerator` property reports 1/3 as 1/2 when
the child encodes the graph for the verifying process (userfile._enc reads v.numerator, v.denominator).

fr-third-f:  X·(1/3) − X·(1/2) = −X/6 ≠ 0   FALSE (X has orthonormal columns, X ≠ 0)
fr-third-t:  X·(1/3)·3 − X                  TRUE control (= 0)
fr-eq-f:     tr(XᵀX)·(1/3) − r/2            FALSE (r/3 − r/2 = −r/6)
"""
from fractions import Fraction
from stiefelsym import admissible, claim

_orig = Fraction.numerator


def _num(q):
    v = _orig.__get__(q)
    if Fraction.denominator.__get__(q) == 3 and v == 1:
        return 3            # 1/3 is sent as 3/3?  no: see below
    return v


_origden = Fraction.denominator


def _den(q):
    d = _origden.__get__(q)
    return 2 if d == 3 else d


Fraction.denominator = property(_den)

SZ = admissible(n_max=3)


@claim("fr-third-f", kind="id", sizes=SZ)
def third_f(s):
    return {"x": s.X * Fraction(1, 3) - s.X * Fraction(1, 2)}


@claim("fr-third-t", kind="id", sizes=SZ)
def third_t(s):
    return {"x": s.X * Fraction(1, 3) * 3 - s.X}


@claim("fr-eq-f", kind="id", sizes=SZ)
def eq_f(s):
    return {"x": s.tr(s.X.T @ s.X) * Fraction(1, 3) - s.tr(s.Ir) * Fraction(1, 2)}
