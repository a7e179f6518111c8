"""D1 probe: systems.euler_lagrange at fixed sizes with a kinetic energy that is not quadratic,
T = tr(ẊᵀẎ) + Ẋ₁₁Ẋ₂₁Ẏ₁₁ (cubic; each coordinate basis vector has at most one of the three factors nonzero,
so the polarization at basis vectors sees the quadratic part only).  The cubic term is no null Lagrangian:
its Euler–Lagrange equations differ from (D-eq) at a generic point (d/dt ∂T/∂Ẋ₁₁ = d/dt(Ẋ₂₁Ẏ₁₁) ≠ 0).
The claim that the accelerations are (D-eq)'s is false."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


@claim("s78-el-cubic-false", paper="prep", kind="id", sizes=[(2, 1), (3, 1), (3, 2)])
def el_cubic_false(s):
    """False: with T = tr(ẊᵀẎ) + Ẋ₁₁Ẋ₂₁Ẏ₁₁, Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ."""
    z = double_point(s)

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) + v["X"][0, 0] * v["X"][1, 0] * v["Y"][0, 0]

    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}
