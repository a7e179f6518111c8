# ruff: noqa
"""The stop's own attempt on the exact method's reuse of a product of transposes (a b = (bᵀ aᵀ)ᵀ): false statements
that compare a product with the product of the transposes, which the memo now takes as a transpose."""
from stiefelsym import admissible, claim


@claim("o64-xp-symmetric", kind="id", sizes=admissible(n_max=4))
def xp_symmetric(s):
    """XᵀP = PᵀX (false for r >= 2: XᵀP is skew on T*V, nonzero)."""
    return {"d": s.X.T @ s.P - s.P.T @ s.X}


@claim("o64-xp-skew", kind="id", sizes=admissible(n_max=4))
def xp_skew(s):
    """XᵀP = −PᵀX (true: the tangency of P)."""
    return {"d": s.X.T @ s.P + s.P.T @ s.X}


@claim("o64-yq-symmetric", kind="id", sizes=admissible(n_max=4))
def yq_symmetric(s):
    """YᵀQ = QᵀY at the second point (false for r >= 2)."""
    return {"d": s.Y.T @ s.Q - s.Q.T @ s.Y}


@claim("o64-xap-transpose", kind="id", sizes=admissible(n_max=4))
def xap_transpose(s):
    """(XᵀAP)ᵀ = PᵀAX (true: A symmetric)."""
    return {"d": (s.X.T @ s.A @ s.P).T - s.P.T @ s.A @ s.X}


@claim("o64-xap-swapped", kind="id", sizes=admissible(n_max=4))
def xap_swapped(s):
    """XᵀAP = PᵀAX (false for r >= 2)."""
    return {"d": s.X.T @ s.A @ s.P - s.P.T @ s.A @ s.X}
