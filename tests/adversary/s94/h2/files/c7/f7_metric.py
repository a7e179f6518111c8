"""Metric realization, an erratum whose correction expects holds, a correction expecting nonzero."""
from stiefelsym import admissible, claim


@claim("h2-f7-metric", kind="id", sizes=admissible(n_max=6), realization="metric", statement="X^T X = I (metric)",
       exact_max_n=3)
def met(s):
    """the first constraint in the metric realization"""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("h2-f7-metric-f", kind="id", sizes=admissible(n_max=6), realization="metric", statement="X^T P = 0 (metric)",
       exact_max_n=3)
def met_f(s):
    """XᵀP = 0 in the metric realization"""
    return {"r": s.X.T @ s.P}


@claim("h2-f7-err", kind="id", sizes=admissible(n_max=6), statement="X^T P = 0", expect="fails",
       erratum="XᵀP is skew, not zero", exact_max_n=3)
def err(s):
    """printed XᵀP = 0 (false at r >= 2)"""
    return {"r": s.X.T @ s.P}


@err.claim.correction("XᵀP + PᵀX = 0", expect="holds")
def err_fix(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@err.claim.correction("XᵀP does not vanish", expect="nonzero")
def err_nz(s):
    return {"r": s.X.T @ s.P}


@claim("h2-f7-same", kind="id", sizes=admissible(n_max=6), statement="X X^T X = X", exact_max_n=3)
def same(s):
    """true"""
    return {"r": s.X @ s.X.T @ s.X - s.X}


@claim("h2-f7-same-metric", kind="id", sizes=admissible(n_max=6), realization="metric", statement="X X^T X = X",
       exact_max_n=3)
def same_metric(s):
    """true in the metric realization too?"""
    return {"r": s.X @ s.X.T @ s.X - s.X}
