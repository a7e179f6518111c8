"""Two euler_lagrange calls in one claim, at the same point, with different kinetic energies.
T₁ = tr(ẊᵀẎ); T₂ = 2tr(ẊᵀẎ) (quadratic, constant coefficients): with L₂ = T₂ − U, K doubles:
Ẍ = (−AX + XMᵀ)/2, Ÿ = (−AY + YM)/2, M = XᵀAY − 2ẊᵀẎ (from XᵀŸ + 2ẊᵀẎ + ẌᵀY = 0).
TRUE: T₂'s accelerations are these; FALSE twin: T₂'s accelerations are T₁'s ((D-eq))."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SZ = [(2, 1), (3, 1), (3, 2)]


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _el(s, z, T):
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return acc


def T1(t, v):
    return t.tr(v["X"].T @ v["Y"])


def T2(t, v):
    return t.tr(v["X"].T @ v["Y"]) * 2


def T3(t, v):
    return t.tr(v["X"].T @ v["Y"]) + v["X"][0, 0] * v["X"][1, 0] * v["Y"][0, 0]


def _true2(s, z):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    M = X.T @ A @ Y - Xd.T @ Yd * 2
    return (-(A @ X) + X @ M.T) / 2, (-(A @ Y) + Y @ M) / 2


def _deq(s, z):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return -(A @ X) + X @ Lam.T, -(A @ Y) + Y @ Lam


@claim("r2-two-calls-true", paper="prep", kind="id", sizes=SZ)
def two_true(s):
    z = double_point(s)
    a1 = _el(s, z, T1)
    a2 = _el(s, z, T2)
    Xdd, Ydd = _true2(s, z)
    X1, Y1 = _deq(s, z)
    return {"X2": a2["X"] - Xdd, "Y2": a2["Y"] - Ydd, "X1": a1["X"] - X1}


@claim("r2-two-calls-false", paper="prep", kind="id", sizes=SZ)
def two_false(s):
    z = double_point(s)
    _el(s, z, T1)          # the first call: its own engine draws
    a2 = _el(s, z, T2)
    X1, Y1 = _deq(s, z)
    return {"X2": a2["X"] - X1, "Y2": a2["Y"] - Y1}


@claim("r2-two-calls-cubic-false", paper="prep", kind="id", sizes=[(2, 1), (3, 1)])
def two_cubic_false(s):
    """FALSE: the second call, with the review's cubic T₃, gives (D-eq)."""
    z = double_point(s)
    a1 = _el(s, z, T1)
    a3 = _el(s, z, T3)
    X1, Y1 = _deq(s, z)
    return {"X3": a3["X"] - X1, "Y3": a3["Y"] - Y1, "X1": a1["X"] - X1}


@claim("r2-cubic-first-false", paper="prep", kind="id", sizes=[(2, 1), (3, 1)])
def cubic_first_false(s):
    """FALSE: the cubic call first, then T₁: (D-eq) for the cubic."""
    z = double_point(s)
    a3 = _el(s, z, T3)
    a1 = _el(s, z, T1)
    X1, Y1 = _deq(s, z)
    return {"X3": a3["X"] - X1, "Y3": a3["Y"] - Y1, "X1": a1["X"] - X1}
