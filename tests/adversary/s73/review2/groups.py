# ruff: noqa
"""Stop 73, second review: a claims file's claim proved in two groups of checks (one reads coordinates of R^n, the
other none).  The early rational point of run_exact is taken only for a whole claim (`whole`), so a group's run
goes to the symbolic chart without it."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "hidden"))

from stiefelsym import admissible, claim
from stiefelsym.systems import complex_point

from _h73_helpers import Lambda_complex, cstar, unitary_r


def lambda_order_residual(s):
    z = complex_point(s)
    Z, Zd = z["Z"], z["Zdot"]
    U = unitary_r(s, s.eta, s.generic("S", "r", "r", "sym"))
    return Lambda_complex(s, Z @ U, Zd @ U) - U @ Lambda_complex(s, Z, Zd) @ cstar(U)


def x_column_norm(s):
    """Σᵢ X_i1² − 1 = 0, read entry by entry (a true check that reads coordinates of ℝⁿ)."""
    total = s.X[0, 0] * s.X[0, 0]
    for i in range(1, int(s.n)):
        total = total + s.X[i, 0] * s.X[i, 0]
    return total - s.q(1)


@claim("rv2-complex-lambda-order-whole", paper=("W-L",), kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2),
       fails_at=lambda n, r: True, erratum="twin: Λ(ZU) = UΛU* (false at r = 2)")
def whole(s):
    """False (hidden round's twin n73-complex-lambda-order): Λ(ZU, ŻU) = UΛU*; one check."""
    return {"Lambda(ZU) - U Lambda U*": lambda_order_residual(s)}


@claim("rv2-complex-lambda-order-grouped", paper=("W-L",), kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2),
       fails_at=lambda n, r: True, erratum="twin: Λ(ZU) = UΛU* (false at r = 2), beside a true check in coordinates")
def grouped(s):
    """False: the same false check beside a true check that reads coordinates of ℝⁿ (Σ X_i1² = 1)."""
    return {"Lambda(ZU) - U Lambda U*": lambda_order_residual(s), "|X e1|^2 - 1": x_column_norm(s)}
