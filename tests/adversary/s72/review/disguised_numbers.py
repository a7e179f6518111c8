"""s72 review: numbers in disguise as scalars of the algebra (attempts Y1-Y7).  Each claim is FALSE unless said."""
from fractions import Fraction

import numpy as np

from stiefelsym import Count, admissible, claim

SIZES = admissible(n_max=3)


class LyingFraction(Fraction):
    """A Fraction whose arithmetic says 1/2 is 1."""
    def __mul__(self, o):
        return o

    __rmul__ = __mul__


@claim("s72-y-np-int64", paper="No", kind="id", section="t", sizes=SIZES)
def np_int64(s):
    """X·int64(2) − X = 0 (false)."""
    return {"x": s.X * np.int64(2) - s.X}


@claim("s72-y-np-float-half", paper="No", kind="id", section="t", sizes=SIZES)
def np_float(s):
    """X·float64(0.5)·2 − X = 0 (true as a real identity; a float in a claim is refused)."""
    return {"x": s.X * np.float64(0.5) * 2 - s.X}


@claim("s72-y-fraction-subclass", paper="No", kind="id", section="t", sizes=SIZES)
def fraction_subclass(s):
    """X·F − X with F a Fraction subclass of value 1/2 that multiplies like 1 (false: X/2 − X)."""
    return {"x": s.X * LyingFraction(1, 2) - s.X}


@claim("s72-y-np-bool", paper="No", kind="id", section="t", sizes=SIZES)
def np_bool(s):
    """X·True − X = 0 (a bool as a number; true if read as 1)."""
    return {"x": s.X * True - s.X}


@claim("s72-y-count-np", paper="No", kind="dim", section="t", sizes=SIZES)
def count_np(s):
    """Count(int64(n), n + 1) (false)."""
    return {"c": Count(np.int64(int(s.n)), int(s.n) + 1)}


@claim("s72-y-mat-np-float", paper="No", kind="id", section="t", sizes=SIZES)
def mat_np(s):
    """tr(X·[[0.1]]...) via s.mat of a numpy float (refused)."""
    n = int(s.n)
    return {"x": s.mat([[np.float64(0.1) if i == j else 0 for j in range(n)] for i in range(n)], ("n", "n")) @ s.X - s.X}


@claim("s72-y-q-huge-den", paper="No", kind="id", section="t", sizes=SIZES)
def q_huge(s):
    """(1 + 1/10^5000)X − X = 0 (false)."""
    return {"x": s.q(10 ** 5000 + 1, 10 ** 5000) * s.X - s.X}
