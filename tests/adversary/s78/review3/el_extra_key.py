"""Item 2: a value passed in through the function's own variable dict.  euler_lagrange(s, T, U, g, position,
velocity, coords) with an extra variable "C" of the position (and the velocity) that has no coordinate: U reads
q["C"], which the claim set to the point's velocity Ẋ₀.  The step check (_kinetic_reads_point) sees U read its
own variable only.  U(q) = tr(XᵀAY) + tr(CᵀX) with C = Ẋ₀: the Lagrangian meant is T − U = (D-Lag) − tr(ẊᵀX),
and −tr(ẊᵀX) = −½ d/dt tr(XᵀX) is a null Lagrangian, so (D-eq)'s accelerations are TRUE (as review2's W4,
whose closure road is now refused); the engine adds the force −Ẋ₀ (Ÿ gets −Ẋ), FALSE.
Control: the same U closing over Ẋ₀ (review2 W4) — refused now."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def T(t, v):
    return t.tr(v["X"].T @ v["Y"])


def U(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"]) + t.tr(q["C"].T @ q["X"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _acc(s):
    z = double_point(s)
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    acc, _ = euler_lagrange(s, T, U, D0, {"X": X, "Y": Y, "C": Xd}, {"X": Xd, "Y": Yd, "C": Xd - Xd},
                            real_coordinates(s, ["X", "Y"]))
    A = s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return acc, X, Y, Xd, Yd, A, Lam


@claim("r3-el-extra-true", kind="id", sizes=[(2, 1), (3, 1), (3, 2)])
def extra_true(s):
    acc, X, Y, Xd, Yd, A, Lam = _acc(s)
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}


@claim("r3-el-extra-false", kind="id", sizes=[(2, 1), (3, 1), (3, 2)])
def extra_false(s):
    """the engine's: the equations of T − tr(XᵀAY) − tr(CᵀX) with C a constant: Ÿ = −AY − C + Yμᵀ,
    Ẍ = −AX + Xμ, and d²/dt²(XᵀY) = 0 gives μᵀ = Λ + ½XᵀC; with C = Ẋ₀."""
    acc, X, Y, Xd, Yd, A, Lam = _acc(s)
    M = Lam + X.T @ Xd / 2
    return {"Xdd": acc["X"] - (-(A @ X) + X @ M.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ M - Xd)}


@claim("r3-el-closure-control", kind="id", sizes=[(2, 1)])
def closure_control(s):
    """the same with U closing over Ẋ₀ (review2 W4's road): refused expected (error)."""
    z = double_point(s)
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]

    def U2(t, q):
        return t.tr(q["X"].T @ t.A @ q["Y"]) + t.tr(Xd.T @ q["X"])
    acc, _ = euler_lagrange(s, T, U2, D0, {"X": X, "Y": Y}, {"X": Xd, "Y": Yd}, real_coordinates(s, ["X", "Y"]))
    A = s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T)}
