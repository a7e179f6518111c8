# ruff: noqa
from stiefelsym import admissible, claim


@claim("r2-pfs-true", kind="id", sizes=admissible(n_max=2))
def inner(s):
    """XᵀX = I_r (true)."""
    return {"x": s.X.T @ s.X - s.Ir}
