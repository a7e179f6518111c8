"""systems.euler_lagrange on the double system with a kinetic energy that has a term linear in the
velocities with constant coefficients, T = tr(ẊᵀẎ) + tr(GᵀẊ) (G a generic constant n×r matrix).
tr(GᵀẊ) = d/dt tr(GᵀX) is a null Lagrangian: the Euler–Lagrange equations, hence the accelerations,
are those of T = tr(ẊᵀẎ), (D-eq): Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ, Λ = XᵀAY − ẊᵀẎ.

The free scene's solve takes d/dt ∂T/∂q̇ as ∂T/∂q̇ with q̇ replaced by q̈, which keeps the constant G
of ∂T/∂Ẋ = Ẏ + G: its accelerations are Ẍ = −AX + X(Λᵀ + GᵀX/2), Ÿ = −AY + Y(Λ + XᵀG/2) − G."""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SIZES = admissible(n_max=3)


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _acc(s, G):
    z = double_point(s)

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) + t.tr(G.T @ v["X"])

    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return z, acc


@claim("s78-el-linear-true", paper="prep", kind="id", sizes=SIZES)
def el_true(s):
    """With T = tr(ẊᵀẎ) + tr(GᵀẊ) (a null Lagrangian added), Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ."""
    G = s.generic("G", "n", "r")
    z, acc = _acc(s, G)
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}


@claim("s78-el-linear-false", paper="prep", kind="id", sizes=SIZES)
def el_false(s):
    """False: with T = tr(ẊᵀẎ) + tr(GᵀẊ), Ẍ = −AX + X(Λᵀ + GᵀX/2), Ÿ = −AY + Y(Λ + XᵀG/2) − G."""
    G = s.generic("G", "n", "r")
    z, acc = _acc(s, G)
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ (Lam.T + G.T @ X / 2)),
            "Ydd": acc["Y"] - (-(A @ Y) + Y @ (Lam + X.T @ G / 2) - G)}
