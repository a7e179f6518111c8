"""False at every size: XᵀX = 2 I_r (its free run and its runs at sizes in one plan, where the free result is kept)."""
from stiefelsym import admissible, claim


@claim("fool-remembered-false", kind="id", sizes=admissible(n_max=5))
def false_one(s):
    return {"r": s.X.T @ s.X - 2 * s.Ir}


@claim("fool-remembered-true", kind="id", sizes=admissible(n_max=5))
def true_one(s):
    return {"r": s.X.T @ s.X - s.Ir}
