"""Kinetic energies of the double system whose coefficients move with the position, given to
systems.euler_lagrange (which solves for constant coefficients): through a value of the claim the function closes
over (the position z["X"]), through its own scene's point (t.DX), and through a flow.  The engine would solve
the equations of another Lagrangian (no d/dt of the coefficients, no ∂T/∂q): every method refuses them.  The
claims state the accelerations of that naive solve, false for the Lagrangian written."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _run(s, T):
    z = double_point(s)
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return z, acc


@claim("o78-el-closure", paper="prep", kind="id", sizes=[(2, 1), (3, 1)])
def el_closure(s):
    """T = tr(ẊᵀẎ)(1 + tr(XᵀX)) with X the position closed over."""
    z = double_point(s)
    X = z["X"]

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * (t.tr(X.T @ X) + 1)
    _, acc = _run(s, T)
    return {"Xdd": acc["X"]}


@claim("o78-el-own-point", paper="prep", kind="id", sizes=[(2, 1), (3, 1)])
def el_own_point(s):
    """T = tr(ẊᵀẎ)(1 + tr(XᵀX)) with X read from T's own scene (t.DX, the double point's X)."""
    def T(t, v):
        X = double_point(t)["X"]
        return t.tr(v["X"].T @ v["Y"]) * (t.tr(X.T @ X) + 1)
    _, acc = _run(s, T)
    return {"Xdd": acc["X"]}


@claim("o78-el-constant-ok", paper="prep", kind="id", sizes=[(2, 1), (3, 1)])
def el_constant_ok(s):
    """T = tr(ẊᵀẎ)(1 + tr(A)) with a constant coefficient: the Euler-Lagrange equations of (D-Lag) scaled,
    Ẍ = −AX/c + XΛᵀ... stated here only as: the step accepts it (the residual is the acceleration minus itself)."""
    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * (t.tr(t.A) + 1)
    _, acc = _run(s, T)
    return {"Xdd": acc["X"] - acc["X"]}


@claim("o78-el-cubic-trace", paper="prep", kind="id", sizes=[(2, 1), (3, 2)])
def el_cubic_trace(s):
    """False: T = tr(ẊᵀẎ) + tr(ẊᵀẊẎᵀG) (a cubic trace form, G constant) has (D-eq)'s accelerations.  Refused
    by every method, the dimension-free one included (it took ∂T/∂q̇ at q̇ ↦ q̈, quadratic in q̈)."""
    G = s.generic("G", "n", "r")
    z = double_point(s)

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) + t.tr(v["X"].T @ v["X"] @ v["Y"].T @ G)
    _, acc = _run(s, T)
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}
