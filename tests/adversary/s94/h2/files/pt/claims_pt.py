"""Claims for the library's loaded sizes: one traced with symbolic sizes, one that reads n (size door), one with a
where condition, one that always raises, one that reads n only in a correction."""
from stiefelsym import admissible, claim


@claim("h2-sym", kind="id", sizes=admissible(n_max=3), statement="X^T P + P^T X = 0")
def sym(s):
    """true"""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("h2-door", kind="id", sizes=admissible(n_max=3), statement="(n - n) X = 0")
def door(s):
    """true: reads n"""
    k = int(s.n)
    return {"r": (k - k) * s.X}


@claim("h2-where", kind="id", sizes=admissible(n_max=3, where=lambda n, r: n >= 2 * r, condition="n >= 2r"),
       statement="X^T X = I")
def where(s):
    """true"""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("h2-raise", kind="id", sizes=admissible(n_max=3), statement="raises")
def boom(s):
    """raises"""
    raise RuntimeError("boom")


@claim("h2-corrdoor", kind="id", sizes=admissible(n_max=3), statement="X^T P = 0")
def corrdoor(s):
    """false; its correction reads n"""
    return {"r": s.X.T @ s.P}


@corrdoor.claim.correction("symmetrised, with (n - n) added")
def corrdoor_fix(s):
    k = int(s.n)
    return {"r": s.X.T @ s.P + s.P.T @ s.X + (k - k) * s.X.T @ s.X}
