"""Class 8 base file (results files forged from its runs).
  b8-false: X X^T - I_n = 0        FALSE at r < n (rank-r projector; truth.py)
  b8-true:  X^T X - I_r = 0        TRUE (orthonormal columns)
  b8-skew:  X^T P + P^T X = 0      TRUE (the tangent condition)
  b8-skewf: X^T P - P^T X = 0      FALSE at r >= 2 (X^T P is skew: X^T P - P^T X = 2 X^T P != 0); TRUE at r = 1
            (a 1 x 1 matrix is its own transpose); the runs are at (3,1), where exact proved it: right
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, where=lambda n, r: r < n)


@claim("b8-false", kind="id", sizes=SZ)
def _f(s):
    return {"x": s.X @ s.X.T - s.In}


@claim("b8-true", kind="id", sizes=SZ)
def _t(s):
    return {"x": s.X.T @ s.X - s.Ir}


@claim("b8-skew", kind="id", sizes=SZ)
def _k(s):
    return {"x": s.X.T @ s.P + s.P.T @ s.X}


@claim("b8-skewf", kind="id", sizes=SZ)
def _kf(s):
    return {"x": s.X.T @ s.P - s.P.T @ s.X}
