"""Counts whose value is a scalar of the scene (not a plain int)."""
from stiefelsym import Count, claim


@claim("s76-count-trxtx", kind="dim", sizes=[(3, 2)])
def count_trxtx(s):
    """tr XᵀX = r on T*V (true)."""
    return {"c": Count(s.tr(s.X.T @ s.X), 2)}


@claim("s76-count-tiny", kind="id", sizes=[(3, 2)])
def count_tiny(s):
    """1 + 2^-200 tr PᵀP = 1 (false)."""
    return {"c": Count(1 + s.q(1, 2**200) * s.tr(s.P.T @ s.P), 1)}


@claim("s76-count-const", kind="id", sizes=[(3, 2)])
def count_const(s):
    """tr PᵀP − tr PᵀP + 3 = 3 (true)."""
    return {"c": Count(s.tr(s.P.T @ s.P) - s.tr(s.P.T @ s.P) + 3, 3)}
