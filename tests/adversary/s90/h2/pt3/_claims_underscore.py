"""A claims file whose name starts with "_": FALSE claim XᵀX = 2 I_r."""
from stiefelsym import admissible, claim


@claim("u-false", kind="id", sizes=admissible(n_max=3))
def u(s):
    """FALSE: XᵀX = 2 I_r."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}
