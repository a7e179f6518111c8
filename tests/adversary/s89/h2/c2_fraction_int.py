"""Class 2/3: a Fraction constant whose denominator is 1 (Fraction(2), Fraction(0), Fraction(6, 3)).
 c2-frac-int (TRUE): Fraction(2)·t − 2·t = 0, t = tr PᵀP.
 c2-frac-int-false (FALSE for n ≥ 2): Fraction(3)·t − t = 0 (residual 2t ≠ 0: numpy, t > 0 at a generic point).
 c2-frac-zero (TRUE): Fraction(0)·t = 0.
 c2-frac-third (TRUE, control): Fraction(1, 3)·3·t − t = 0.
 c2-frac-int-matrix (TRUE): Fraction(2)·X − X − X = 0.
 c2-frac-int-sum (TRUE): (t + Fraction(1)) − 1 − t = 0 (an integer Fraction added, not multiplied).
"""
from fractions import Fraction
from stiefelsym import admissible, claim
ANY = admissible(n_max=3)
def _t(s): return s.tr(s.P.T @ s.P)

@claim("c2-frac-int", kind="id", sizes=ANY)
def a(s):
    """TRUE: Fraction(2)·t = 2t."""
    return {"r": Fraction(2) * _t(s) - 2 * _t(s)}

@claim("c2-frac-int-false", kind="id", sizes=ANY)
def b(s):
    """FALSE: Fraction(3)·t = t."""
    return {"r": Fraction(3) * _t(s) - _t(s)}

@claim("c2-frac-zero", kind="id", sizes=ANY)
def c(s):
    """TRUE: Fraction(0)·t = 0."""
    return {"r": Fraction(0) * _t(s)}

@claim("c2-frac-third", kind="id", sizes=ANY)
def d(s):
    """TRUE: Fraction(1, 3)·3·t = t."""
    return {"r": Fraction(1, 3) * 3 * _t(s) - _t(s)}

@claim("c2-frac-int-matrix", kind="id", sizes=ANY)
def e(s):
    """TRUE: Fraction(2)·X = X + X."""
    return {"r": Fraction(2) * s.X - s.X - s.X}

@claim("c2-frac-int-sum", kind="id", sizes=ANY)
def f(s):
    """TRUE: (t + Fraction(1)) − 1 − t = 0."""
    return {"r": (_t(s) + Fraction(1)) - 1 - _t(s)}
