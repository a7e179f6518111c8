# ruff: noqa
"""Base claims for report ingestion: one true identity, one false identity."""
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))


@claim("c8-true", kind="id", sizes=S)
def t(s):
    """X^T X = I (true on T*V)."""
    return {"x": s.X.T @ s.X - s.Ir}


@claim("c8-false", kind="id", sizes=S)
def f(s):
    """X^T P = 0 (false on T*V)."""
    return {"x": s.X.T @ s.P}
