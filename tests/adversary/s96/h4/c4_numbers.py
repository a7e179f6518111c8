"""Stop 96, h4: subclasses of the admitted number types (int, Fraction) that lie to float(), hash, ==, or the
arithmetic of one backend; bool and numpy integers as constants."""
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3, r_max=1)


class LyingInt(int):
    def __float__(self):
        return 3.0

    def __mul__(self, o):
        return int(self) * o

    __rmul__ = __mul__


class LyingFraction(Fraction):
    def __float__(self):
        return 0.0

    @property
    def numerator(self):
        return 0


@claim("h4t-int-subclass-true", kind="id", sizes=SZ)
def int_subclass_true(s):
    """True: X * c - X * 2 = 0 with c = LyingInt(2) (an int 2 whose float() says 3)."""
    return {"r": s.X * LyingInt(2) - s.X * 2}


@claim("h4t-int-subclass-false", kind="id", sizes=SZ)
def int_subclass_false(s):
    """False: X * c - X * 3 = 0 with c = LyingInt(2) (float() says 3)."""
    return {"r": s.X * LyingInt(2) - s.X * 3}


@claim("h4t-fraction-subclass-false", kind="id", sizes=SZ)
def fraction_subclass_false(s):
    """False: X * c = 0 with c = LyingFraction(1, 2) (float() says 0, numerator says 0)."""
    return {"r": s.X * LyingFraction(1, 2)}


@claim("h4t-bool-true", kind="id", sizes=SZ)
def bool_true(s):
    """True: X * True - X = 0."""
    return {"r": s.X * True - s.X}


@claim("h4t-bool-false", kind="id", sizes=SZ)
def bool_false(s):
    """False: X * True = 0."""
    return {"r": s.X * True}


@claim("h4t-huge-int-false", kind="id", sizes=SZ)
def huge_int_false(s):
    """False: (X * (2^2000 + 1)) - X * 2^2000 = 0 (it is X)."""
    return {"r": s.X * (2 ** 2000 + 1) - s.X * 2 ** 2000}
