"""Sizes used as numbers: n, 2n, -n, 0·n (each claim TRUE)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("dm-n", paper="t", kind="id", section="2", sizes=SZ)
def dm1(s):
    """n X − tr(I_n) X = 0."""
    return {"r": s.X * s.n - s.X * s.tr(s.In)}


@claim("dm-2n", paper="t", kind="id", section="2", sizes=SZ)
def dm2(s):
    """(2n) X − 2 tr(I_n) X = 0."""
    return {"r": s.X * (s.n * 2) - s.X * s.tr(s.In) * 2}


@claim("dm-minus-n", paper="t", kind="id", section="2", sizes=SZ)
def dm3(s):
    """(−n) X + tr(I_n) X = 0."""
    return {"r": s.X * (s.n * -1) + s.X * s.tr(s.In)}


@claim("dm-zero-n", paper="t", kind="id", section="2", sizes=SZ)
def dm4(s):
    """(0·n) X = 0."""
    return {"r": s.X * (s.n * 0)}
