"""Sizes multiplied by 0 (Dim(0·n)) used as numbers: a divisor the trace takes for a nonzero size."""
from stiefelsym import admissible, claim, Inverse

SZ = admissible(n_max=3, n_min=2)


@claim("dz-x0-over-0", paper="t", kind="id", section="2", sizes=SZ)
def dz1(s):
    """(X·0)/0: undefined everywhere (correct: error; never proved)."""
    z = s.n * 0
    return {"r": (s.X * z) / z}


@claim("dz-xx-over-0", paper="t", kind="id", section="2", sizes=SZ)
def dz2(s):
    """X·(0/0) − X: undefined."""
    z = s.n * 0
    return {"r": s.X * (s.q(1) * z / z) - s.X}


@claim("dz-false", paper="t", kind="id", section="2", sizes=SZ)
def dz3(s):
    """FALSE where defined? P + (X·0)/0 (P ≠ 0): undefined (error)."""
    z = s.n * 0
    return {"r": s.P + (s.X * z) / z}


@claim("dz-inverse", paper="t", kind="id", section="2", sizes=SZ)
def dz4(s):
    """Inverse(x ↦ x·0, y ↦ y/0 ... ) on so(r): not invertible (0 map); must not pass."""
    z = s.n * 0
    return {"inv": Inverse(lambda t, x: x * z, lambda t, y: (y * z) / (z * z) + y * 0, on=("so(r)",))}


@claim("dz-neg-size", paper="t", kind="id", section="2", sizes=SZ)
def dz5(s):
    """A size times −1 as a number: −n X + n X = 0 (TRUE)."""
    return {"r": s.X * (s.n * -1) + s.X * s.n}
