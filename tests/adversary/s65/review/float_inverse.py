# ruff: noqa
"""True identities through a matrix inverse: float and ball never resolve them (friction, not a wrong verdict)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("fi-gram-inv", paper="r65", kind="id", sizes=SZ)
def gram_inv(s):
    """(XᵀX)⁻¹ = I_r on T*V."""
    return {"r": (s.X.T @ s.X).inv() - s.Ir}


@claim("fi-inv-times", paper="r65", kind="id", sizes=SZ)
def inv_times(s):
    """(I + PᵀP)⁻¹(I + PᵀP) = I_r."""
    M = s.Ir + s.P.T @ s.P
    return {"r": M.inv() @ M - s.Ir}


@claim("fi-scaled-inv", paper="r65", kind="id", sizes=SZ)
def scaled_inv(s):
    """(3I + XᵀX)⁻¹ · 4 = I_r on T*V."""
    return {"r": (s.Ir * 3 + s.X.T @ s.X).inv() * 4 - s.Ir}
