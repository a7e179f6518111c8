"""Class 8 base claims (for forging results.json and certificates by hand).

c8-true:  XᵀX − I_r = 0 on T*V (TRUE: the constraint).  Also its free certificate is the one transplanted.
c8-false: XXᵀ − I_n = 0 (FALSE for r < n: rank XXᵀ = r < n; numpy: tr = r − n).
c8-true2: XᵀP + PᵀX = 0 (TRUE: the second constraint).
c8-false2: XᵀP = 0 (FALSE for r >= 2; TRUE at r = 1, where XᵀP is a skew 1×1 matrix: numpy).
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


@claim("c8-true", kind="id", sizes=SZ)
def c8_true(s):
    """TRUE: XᵀX = I_r."""
    return {"r": s.X.T @ s.X - s.Ir}


@claim("c8-false", kind="id", sizes=SZ)
def c8_false(s):
    """FALSE: XXᵀ = I_n (r < n)."""
    return {"r": s.X @ s.X.T - s.In}


@claim("c8-true2", kind="id", sizes=SZ)
def c8_true2(s):
    """TRUE: XᵀP + PᵀX = 0."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("c8-false2", kind="id", sizes=SZ)
def c8_false2(s):
    """FALSE: XᵀP = 0."""
    return {"r": s.X.T @ s.P}
