"""Batch 5: the square family's two trace symbols, the complex Euler-Lagrange equations scaled by a size, r = 1.

  b5-sq-trace-xxt     at r = n: tr(X X^T) - tr(X^T X) = 0                           TRUE (cyclicity, every size)
  b5-sq-trace-n-r     at r = n: tr(I_n) - tr(I_r) = 0                                TRUE at r = n (n = r)
  b5-sq-trace-false   at r = n: tr(X X^T) - tr(I_n) + 1 = 0                          FALSE (= 1)
  b5-cx-el-c1         complex Neumann (catalog form) c = 1: Z'' = -AZ + Z(Z*AZ - Z'*Z')... via W0 multipliers
                      (we only check that free and the fixed-size methods agree on the scaled twin below)
  b5-cx-el-nr         the same Lagrangian times c = n - r                           degenerate at r = n
  b5-r1-scalar        at r = 1: X^T A X X^T P = X^T P X^T A X                        TRUE at r = 1 (1 x 1 matrices commute)
  b5-r1-scalar-every  the same at every r                                            FALSE at r >= 2 (X^T P = 0 at r = 1 anyway)
"""
from stiefelsym import admissible, claim


@claim("b5-sq-trace-xxt", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def sq_trace_xxt(s):
    return {"tr XXt - tr XtX": s.tr(s.X @ s.X.T) - s.tr(s.X.T @ s.X)}


@claim("b5-sq-trace-n-r", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def sq_trace_n_r(s):
    return {"n - r": s.tr(s.In) - s.tr(s.Ir)}


@claim("b5-sq-trace-false", kind="id", sizes=admissible(n_max=5, r_is_n=True))
def sq_trace_false(s):
    return {"tr XXt - n + 1": s.tr(s.X @ s.X.T) - s.tr(s.In) + 1}


@claim("b5-r1-scalar", kind="id", sizes=admissible(n_max=5, r_min=1, r_max=1))
def r1_scalar(s):
    M, K = s.X.T @ s.A @ s.X, s.X.T @ s.A @ s.P
    return {"[M, K]": M @ K - K @ M}


@claim("b5-r1-scalar-every", kind="id", sizes=admissible(n_max=4))
def r1_scalar_every(s):
    M, K = s.X.T @ s.A @ s.X, s.X.T @ s.A @ s.P
    return {"[M, K]": M @ K - K @ M}
