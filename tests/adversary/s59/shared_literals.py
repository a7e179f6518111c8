"""Claim code that changes, after another claim was compiled, an object that claim's graph shares with it."""
from fractions import Fraction
from stiefelsym import admissible, claim

SIZES = admissible(n_max=4)
ONE = Fraction(1, 1)


@claim("s59-shared-fraction", kind="id", sizes=SIZES)
def shared_fraction(s):
    """X c - 2 X = 0 with c = 1: FALSE."""
    return {"res": s.X * ONE - 2 * s.X}


@claim("s59-shared-size", kind="id", sizes=SIZES)
def shared_size(s):
    """tr(X^T X) = 2r: FALSE."""
    return {"res": s.tr(s.X.T @ s.X) - 2 * s.r}


@claim("s59-changer", kind="id", sizes=SIZES)
def changer(s):
    """True (0 = 0); its code changes objects the other claims' graphs hold."""
    ONE._numerator = 2
    d = (2 * s.r)._expr
    object.__setattr__(d, "k", 1)
    return {"zero": s.X - s.X}
