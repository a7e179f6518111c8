# ruff: noqa
"""The stop's own attempt on the hand witness: a claim's own matrix and scalar named X beside the engine's X."""
from stiefelsym import claim


@claim("fool-own-x", kind="id", sizes=[(2, 1)], fails_at=lambda n, r: True, erratum="probe")
def own_x(s):
    """A claim's own matrix named X beside the engine's X: X_own - X = 0 (false)."""
    G = s.generic("X", "n", "r")
    return {"r": G - s.X}


@claim("fool-own-scalar-x", kind="id", sizes=[(2, 1)], fails_at=lambda n, r: True, erratum="probe")
def own_scalar_x(s):
    """A claim's own scalar named X beside the engine's X."""
    c = s.scalar("X")
    return {"r": s.X * c - s.X}
