"""One true and one false claim, for the hand-edited results files (edit_results.py)."""
from stiefelsym import admissible, claim

ONE = admissible(n_max=3, n_min=3, r_min=2, r_max=2)


@claim("ed-true", kind="id", sizes=ONE)
def ed_true(s):
    """XᵀX = I."""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("ed-false", kind="id", sizes=ONE)
def ed_false(s):
    """XᵀP = 0 (false)."""
    return {"r": s.X.T @ s.P}
