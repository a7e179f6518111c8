"""The stop's last own attempt: a kinetic energy that is not a polynomial in the velocities, written with a call a
step's function may make (the resolvent, at a parameter that moves with the velocity): T = tr(ẊᵀẎ) + tr R(μ),
μ = tr(ẊᵀẊ), R(μ) = (μI − A)⁻¹.  Its third difference does not vanish; the claim that its accelerations are
(D-eq)'s is false, and every method must refuse the step rather than pass it."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


@claim("o78-el-rational-false", paper="prep", kind="id", sizes=[(2, 1), (3, 2)])
def el_rational_false(s):
    z = double_point(s)

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) + t.tr(t.resolvent(t.tr(v["X"].T @ v["X"])))
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}
