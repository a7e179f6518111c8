"""s60 review probes: powers with exponent 0 or negative of undefined or vanishing numbers."""
from stiefelsym import admissible, claim

R1 = admissible(n_max=3, r_max=1)


@claim("s60r-pow0-undefined", paper="adv", kind="id", sizes=R1)
def pow0_undefined(s):
    """Undefined at r = 1: ((tr I_r - 1)^-1)^0 - 1 (the base is 1/0)."""
    c = s.tr(s.Ir) - 1
    return {"r": (c ** -1) ** 0 - 1}


@claim("s60r-negpow-undefined", paper="adv", kind="id", sizes=R1)
def negpow_undefined(s):
    """Undefined at r = 1: c^-1 * c - 1 with c = tr I_r - 1."""
    c = s.tr(s.Ir) - 1
    return {"r": (c ** -1) * c - 1}


@claim("s60r-negpow-nonzero", paper="adv", kind="not", expect="nonzero", sizes=R1)
def negpow_nonzero(s):
    """Undefined at r = 1: 1/(c^-1) + tr(P^T P) said nonzero, c = tr I_r - 1 (1/(1/0) = 0 in symengine)."""
    c = s.tr(s.Ir) - 1
    return {"r": (c ** -1) ** -1 + s.tr(s.P.T @ s.P)}


@claim("s60r-pow0-zero", paper="adv", kind="id", sizes=R1)
def pow0_zero(s):
    """0^0 - 1 with 0 = tr(X^T P) (0 on T*V): Python's 0**0 = 1, so true as a rational function? state 0**0 = 1."""
    c = s.tr(s.X.T @ s.P)
    return {"r": c ** 0 - 1}
