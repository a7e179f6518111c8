# ruff: noqa
"""Class 2: strings where numbers go (Trace.arg lets str through).
Each residual is FALSE unless the string is read as a number that makes it vanish.
c2s-mat: s.mat([['0']],('?','?')) * tr(PᵀP) ... FALSE unless '0' is 0 -> then TRUE(0). We state residual tr(PᵀP)*I1 - tr(PᵀP)*M where M=s.mat([['1']]): TRUE iff '1'->1.
c2s-mat0: tr(PᵀP) * s.mat([['0']])  : the residual is 0 iff '0' read as 0 (then vacuous TRUE); under a consistent reading it is a string: must be error.
c2s-res: s.resolvent('0') @ A + I  : TRUE iff '0' read as 0 ((0I - A)^{-1}A = -I).
c2s-rank: Rank(X, '2')  (rank X = 2 at r=2 TRUE if read as 2); Rank(X, '3') FALSE.
c2s-count: Count(3, '3') ; Count(3, '4') FALSE.
c2s-zeros: zeros('1','1') * tr(PᵀP).
"""
from stiefelsym import admissible, claim, Rank, Count, block

SZ = admissible(n_max=3, n_min=3, r_min=2, r_max=2)

@claim("c2s-mat1", kind="id", sizes=SZ)
def a(s):
    """TRUE iff '1' is 1: t·[1] − t·['1']."""
    t = s.tr(s.P.T @ s.P)
    return {"r": s.mat([[1]]) * t - s.mat([["1"]]) * t}

@claim("c2s-mat2", kind="id", sizes=SZ)
def a2(s):
    """FALSE: t·['2'] − t·[1] (if '2' -> 2 then t ≠ 0)."""
    t = s.tr(s.P.T @ s.P)
    return {"r": s.mat([["2"]]) * t - s.mat([[1]]) * t}

@claim("c2s-mat0", kind="id", sizes=SZ)
def b(s):
    """FALSE as a string; t·['0']."""
    return {"r": s.tr(s.P.T @ s.P) * s.mat([["0"]])}

@claim("c2s-matx", kind="id", sizes=SZ)
def b2(s):
    """FALSE: ['x'] − ['y'] (sympify would give symbols x − y ≠ 0)."""
    return {"r": s.mat([["x"]]) - s.mat([["x-0"]])}

@claim("c2s-res", kind="id", sizes=SZ)
def c(s):
    """TRUE iff '0' is 0: R(0)A + I."""
    return {"r": s.resolvent("0") @ s.A + s.In}

@claim("c2s-rank-false", kind="dim", sizes=SZ)
def d(s):
    """FALSE: rank X = '3' at r = 2."""
    return {"rank": Rank(s.X, "3")}

@claim("c2s-count-false", kind="dim", sizes=SZ)
def e(s):
    """FALSE: Count(3, '4')."""
    return {"c": Count(3, "4")}

@claim("c2s-tangent", kind="id", sizes=SZ)
def f(s):
    """FALSE: d/dε tr(XᵀX) along X ↦ '1' ."""
    return {"r": s.d(lambda t: t.tr(t.P.T @ t.P), {"X": s.X, "P": "0"})}

@claim("c2s-block", kind="id", sizes=SZ)
def g(s):
    """FALSE: block([[X, '0']])."""
    return {"r": block([[s.X.T @ s.X - s.Ir, "0"]])}
