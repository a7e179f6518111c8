"""Batch 7: batch 3's degenerate Lagrangian with a small symbolic budget (exact_max_n=1), so that the exact method
at (n, r) may take the dimension-free proof specialised to the size (stiefelsym.methods.specialise).

  b7-el-n-minus-r    L = (n - r)(tr(X'^T Y') - tr(X^T A Y)), X^T Y = I_r: accelerations (D-eq)   degenerate at r = n
  b7-el-n-minus-2r   L = (n - 2r)(...)                                                           degenerate at n = 2r
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SZ = admissible(n_max=4)


def _D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _run(s, c_of):
    z = double_point(s)
    T = lambda t, v: t.tr(v["X"].T @ v["Y"]) * c_of(t)       # noqa: E731
    U = lambda t, q: t.tr(q["X"].T @ t.A @ q["Y"]) * c_of(t)  # noqa: E731
    acc, _ = euler_lagrange(s, T, U, _D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    Lam = z["X"].T @ s.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]
    return {"X''": acc["X"] - (-(s.A @ z["X"]) + z["X"] @ Lam.T),
            "Y''": acc["Y"] - (-(s.A @ z["Y"]) + z["Y"] @ Lam)}


@claim("b7-el-n-minus-r", kind="id", sizes=SZ, exact_max_n=1)
def el_n_minus_r(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir))


@claim("b7-el-n-minus-2r", kind="id", sizes=SZ, exact_max_n=1)
def el_n_minus_2r(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir) * 2)
