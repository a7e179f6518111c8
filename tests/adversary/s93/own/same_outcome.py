# ruff: noqa
"""One outcome whatever the method, for two ill-formed claims (h2 M1, M2 of stop 92):
- a nonvanishing statement whose trace is refused (X − I_r: an n×r matrix minus an r×r one);
- a check with no entries (a 0×0 block of XᵀX − I_r), and its false twin with a 0×0 check beside a false one.
"""
from stiefelsym import admissible, claim

SZ = admissible(n_min=3, n_max=3, r_min=2, r_max=2)


@claim("own-refused-nonzero", kind="id", sizes=SZ, expect="nonzero")
def refused_nonzero(s):
    """X − I_r ≠ 0: refused (the spaces differ)."""
    return {"r": s.X - s.Ir}


@claim("own-refused-zero", kind="id", sizes=SZ)
def refused_zero(s):
    """X − I_r = 0: refused (the spaces differ)."""
    return {"r": s.X - s.Ir}


@claim("own-empty-check", kind="id", sizes=SZ)
def empty_check(s):
    """A 0×0 block of XᵀX − I_r: a vacuous check."""
    return {"r": (s.X.T @ s.X - s.Ir)[0:0, 0:0]}


@claim("own-empty-beside-false", kind="id", sizes=SZ)
def empty_beside_false(s):
    """A vacuous check beside a false one (PᵀP = 0)."""
    return {"r": (s.X.T @ s.X - s.Ir)[0:0, 0:0], "f": s.P.T @ s.P}
