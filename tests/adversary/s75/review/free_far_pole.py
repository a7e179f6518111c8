"""Divisions by a size-dependent constant that vanishes only at a size beyond the default run, in claims
stated for every n, r.  Each residual is 0 where defined and undefined (0/0) at the vanishing size, so a
proof "for every n, r" is wrong there.  Docstrings state the truth."""
from stiefelsym import admissible, claim, Inverse


def c_far(s):
    return s.tr(s.In) - 100


def c_line(s):
    return s.tr(s.In) - s.tr(s.Ir) * 2 - 5


@claim("s75-far-pole-scalar", kind="id", sizes=admissible(n_max=4))
def far_pole_scalar(s):
    """(c·tr PᵀP)/c = tr PᵀP with c = n − 100: undefined at n = 100 (stated there), true elsewhere."""
    c = c_far(s)
    K = s.tr(s.P.T @ s.P)
    return {"w": (c * K) / c - K}


@claim("s75-line-pole-scalar", kind="id", sizes=admissible(n_max=4))
def line_pole_scalar(s):
    """(c X)/c = X with c = n − 2r − 5: undefined on the line n = 2r + 5 ((7,1), (9,2), ...), stated there."""
    c = c_line(s)
    return {"w": (s.X * c) / c - s.X}


def op_far(s, x):
    return (x * c_far(s),)


def inv_far(s, y):
    return (y / c_far(s),)


@claim("s75-far-pole-inverse", kind="id", sizes=admissible(n_max=4))
def far_pole_inverse(s):
    """x ↦ (n − 100) x is a bijection of Sym(r) at every point: FALSE at n = 100 (it is 0 there)."""
    return {"inv": Inverse(op_far, inv_far, on=("Sym(r)",))}


def op_line(s, x):
    return (x * c_line(s),)


def inv_line(s, y):
    return (y / c_line(s),)


@claim("s75-line-pole-inverse", kind="id", sizes=admissible(n_max=4))
def line_pole_inverse(s):
    """x ↦ (n − 2r − 5) x is a bijection of Sym(r): FALSE at (7,1), (9,2), ..."""
    return {"inv": Inverse(op_line, inv_line, on=("Sym(r)",))}
