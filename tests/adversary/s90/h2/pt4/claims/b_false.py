"""x-dup FALSE here: XᵀX = 2 I_r (same id, same residual name)."""
from stiefelsym import admissible, claim

@claim("x-dup", kind="id", sizes=admissible(n_max=3))
def x_dup(s):
    """FALSE: XᵀX − 2 I_r."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}
