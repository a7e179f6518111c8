# ruff: noqa
"""True identities with huge intermediate terms, and a false twin of relative size 2^-120 (r64)."""
from stiefelsym import claim

C = 2 ** 60


@claim("r64-cancel-true", kind="id", sizes=[(3, 2)])
def cancel_true(s):
    """(X + cP)ᵀ(X + cP) = I + c²PᵀP on T*V, c = 2^60 (XᵀP + PᵀX = 0)."""
    c = s.q(C, 1)
    V = s.X + c * s.P
    return {"gram": V.T @ V - s.Ir - c * c * (s.P.T @ s.P)}


@claim("r64-cancel-false", kind="id", sizes=[(3, 2)])
def cancel_false(s):
    """(X + cP)ᵀ(X + cP) = I + (c² + 1)PᵀP: false (off by PᵀP against terms of size c²)."""
    c = s.q(C, 1)
    V = s.X + c * s.P
    return {"gram": V.T @ V - s.Ir - (c * c + 1) * (s.P.T @ s.P)}
