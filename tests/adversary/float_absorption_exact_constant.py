"""A false claim the float method passes (routes 2 and 5, a new entrance): route 2's own example,
(cX + X) − cX = 0 with c absorbing X in double precision, written with an exact int c = 10^20, which
is inside the float range the constant pass checks.  In float64 cX + X rounds to cX, the residual is
exactly 0, its error bound is far below 1e-8 of the terms' scale, and the verdict is `numeric`."""
from stiefelsym import admissible, claim


@claim("adv-absorbed-int", paper="prep", kind="id", section="t", sizes=admissible(n_max=4))
def absorbed(s):
    """(cX + X) − cX = 0 for c = 10^20 (false: it is X)."""
    c = 10 ** 20
    return {"(Xc + X) - Xc": (s.X * c + s.X) - s.X * c}
