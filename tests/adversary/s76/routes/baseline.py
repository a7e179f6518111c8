"""Baseline: a true and a false claim."""
from stiefelsym import admissible, claim


@claim("rt-true", paper="t", kind="id", section="0", sizes=admissible(n_max=3))
def true_one(s):
    """XᵀX = I (TRUE)."""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("rt-false", paper="t", kind="id", section="0", sizes=admissible(n_max=3))
def false_one(s):
    """XXᵀ = I (FALSE for r < n)."""
    return {"r": s.X @ s.X.T - s.In}
