# ruff: noqa
"""A plain claims file with a false claim (it runs nothing in the pytest process)."""
from stiefelsym import admissible, claim


@claim("r2-dtxt-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀX = 2 I_r (false at every size)."""
    return {"xtx": s.X.T @ s.X - 2 * s.Ir}
