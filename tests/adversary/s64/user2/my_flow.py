# ruff: noqa
"""A flow of my own for `stiefelsym discover`: the Manakov geodesic flow (dot_XP3*),
Xdot = (A Phi + Phi A) X, Pdot = (A Phi + Phi A) P."""


def manakov(s):
    M = s.A @ s.Phi + s.Phi @ s.A
    return {"X": M @ s.X, "P": M @ s.P}


def manakov_wrong(s):
    """The operator A^2 xi + xi A^2 (not a Manakov operator of the form ad_A^{-1} ad_B)."""
    M = s.A @ s.A @ s.Phi + s.Phi @ s.A @ s.A
    return {"X": M @ s.X, "P": M @ s.P}
