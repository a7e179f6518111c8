"""Stop 63, own attempt: exact constants far outside float64 (2^15000 + 1, 3^-9000, (c + 1)/c) in false
statements; every fixed-size method must refute them or leave them open, never pass them."""
from fractions import Fraction
from stiefelsym import admissible, claim

C = 2 ** 15000
T = Fraction(1, 3 ** 9000)
S = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


@claim("hf-plus-one", paper="t", kind="id", section="2", sizes=S)
def plus_one(s):
    return {"r": s.X * (C + 1) - s.X * C}


@claim("hf-tiny", paper="t", kind="id", section="2", sizes=S)
def tiny(s):
    return {"r": s.X * T}


@claim("hf-tiny-trace", paper="t", kind="id", section="2", sizes=S)
def tiny_trace(s):
    return {"r": s.tr(s.X.T @ s.X) * T - s.tr(s.Ir) * T + T * T}


@claim("hf-ratio", paper="t", kind="id", section="2", sizes=S)
def ratio(s):
    return {"r": s.X * Fraction(C + 1, C) - s.X}
