"""Huge and tiny constants in one sum, under ball and float (2^±1000, 2^-1100 below float64's normal range)."""
from stiefelsym import claim

SZ = [(3, 2)]
BIG, TINY, SUB = 2**1000, 2**1000, 2**1100


@claim("s76-big-tiny-false", kind="id", sizes=SZ)
def big_tiny_false(s):
    """FALSE: c t + d t − c t = d t with c = 2^1000, d = 2^-1000, t = tr PᵀP."""
    t = s.tr(s.P.T @ s.P)
    return {"r": s.q(BIG, 1) * t + s.q(1, TINY) * t - s.q(BIG, 1) * t}


@claim("s76-big-tiny-true", kind="id", sizes=SZ)
def big_tiny_true(s):
    """TRUE: (c t + t) − c t − t = 0."""
    t = s.tr(s.P.T @ s.P)
    return {"r": (s.q(BIG, 1) * t + t) - s.q(BIG, 1) * t - t}


@claim("s76-big-constraint-tiny", kind="id", sizes=SZ)
def big_constraint_tiny(s):
    """FALSE: 2^1000 tr(XᵀX − I) + 2^-1000 tr PᵀP = 0 (the first term is 0 on T*V, the second is not)."""
    return {"r": s.q(BIG, 1) * s.tr(s.X.T @ s.X - s.Ir) + s.q(1, TINY) * s.tr(s.P.T @ s.P)}


@claim("s76-sub-nonzero", kind="not", expect="nonzero", sizes=SZ)
def sub_nonzero(s):
    """TRUE: 2^-1100 tr PᵀP does not vanish identically (below float64's normal range)."""
    return {"r": s.q(1, SUB) * s.tr(s.P.T @ s.P)}


@claim("s76-sub-nonzero-big", kind="not", expect="nonzero", sizes=SZ)
def sub_nonzero_big(s):
    """TRUE: 2^1000 tr(XᵀX − I) + 2^-1100 tr PᵀP does not vanish identically."""
    return {"r": s.q(BIG, 1) * s.tr(s.X.T @ s.X - s.Ir) + s.q(1, SUB) * s.tr(s.P.T @ s.P)}


@claim("s76-big-nonzero-false", kind="not", expect="nonzero", sizes=SZ)
def big_nonzero_false(s):
    """FALSE: 2^1000 tr(XᵀX − I) − 2^-1100 (tr PᵀP − tr PᵀP) does not vanish (it does, on T*V)."""
    t = s.tr(s.P.T @ s.P)
    return {"r": s.q(BIG, 1) * s.tr(s.X.T @ s.X - s.Ir) - s.q(1, SUB) * (t - t)}


@claim("s76-ratio-true", kind="id", sizes=SZ)
def ratio_true(s):
    """TRUE: (2^1000 t + 2^-1100) / (2^1000 t + 2^-1100) − 1 = 0."""
    t = s.tr(s.P.T @ s.P)
    u = s.q(BIG, 1) * t + s.q(1, SUB)
    return {"r": u / u - 1}


@claim("s76-ratio-false", kind="id", sizes=SZ)
def ratio_false(s):
    """FALSE: (2^1000 t + 2^-1100) / (2^1000 t) − 1 = 0 (off by 2^-2100 / t)."""
    t = s.tr(s.P.T @ s.P)
    return {"r": (s.q(BIG, 1) * t + s.q(1, SUB)) / (s.q(BIG, 1) * t) - 1}
