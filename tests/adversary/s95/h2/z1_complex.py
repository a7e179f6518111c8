"""The complex W(n, r), realified: true statements and false twins, some true at a reduced chart's point."""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=3)


def J(s, m, tag):
    I, Z = s.identity(m, tag), s.zeros(m, m, (tag, tag))
    return block([[Z, -I], [I, Z]])


def _r(s):
    return int(s.r)


@claim("h2z-unitary", kind="id", sizes=SZ)
def unitary(s):
    """True: Z^T Z = I_{2r} (Z^* Z = I realified)."""
    return {"r": s.Zc.T @ s.Zc - s.identity(2 * _r(s), "r+r")}


@claim("h2z-tangent", kind="id", sizes=SZ)
def tangent(s):
    """True: Z^T V + V^T Z = 0."""
    return {"r": s.Zc.T @ s.Zc_dot + s.Zc_dot.T @ s.Zc}


@claim("h2z-tangent-false", kind="id", sizes=SZ)
def tangent_false(s):
    """False: Z^T V = 0."""
    return {"r": s.Zc.T @ s.Zc_dot}


@claim("h2z-imag-false", kind="id", sizes=SZ)
def imag_false(s):
    """False: Im(Z^* V) = 0 (the lower-left r x r block of the realified Z^T V)."""
    r = _r(s)
    return {"r": (s.Zc.T @ s.Zc_dot)[r:2 * r, 0:r]}


@claim("h2z-real-false", kind="id", sizes=admissible(n_min=2, n_max=3))
def real_false(s):
    """False: Im Z = 0 (the lower-left n x r block of the realified Z)."""
    n, r = int(s.n), _r(s)
    return {"r": s.Zc[n:2 * n, 0:r]}


@claim("h2z-first-entry-false", kind="id", sizes=SZ)
def first_entry_false(s):
    """False: Im Z_{11} = 0."""
    n = int(s.n)
    return {"r": s.Zc[n, 0]}


@claim("h2z-complex-structure", kind="id", sizes=SZ)
def complex_structure(s):
    """True: J Z = Z J (Z is complex-linear)."""
    return {"r": J(s, int(s.n), "?") @ s.Zc - s.Zc @ J(s, _r(s), "?")}


@claim("h2z-projector-false", kind="id", sizes=SZ)
def projector_false(s):
    """False unless r = n: Z Z^T = I_{2n}."""
    return {"r": s.Zc @ s.Zc.T - s.identity(2 * int(s.n), "n+n")}


@claim("h2z-conj-false", kind="id", sizes=SZ)
def conj_false(s):
    """False: conj(Z)^T Z = I (Z^T Z = I in the complex bilinear form)."""
    return {"r": s.conj(s.Zc).T @ s.Zc - s.identity(2 * _r(s), "r+r")}
