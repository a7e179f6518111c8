"""W3's class through systems.euler_lagrange: the kinetic energy T is a step's function traced at each call and
held to nothing across calls.  T(t, v) = c·tr(ẊᵀẎ) with c = 1 at its first euler_lagrange, 2 after (a mode the
claim flips); U = tr(XᵀAY), D0 = XᵀY − I (the double system of s78/review/el_linear_kinetic.py).
Truth (by hand): for L = c·tr(ẊᵀẎ) − tr(XᵀAY) with XᵀY = I: c·Ẍ = −AX + XΛ̃ᵀ, i.e. Ẍ = −AX/c + XΛ_cᵀ,
Λ_c = XᵀAY/c − ẊᵀẎ (differentiate XᵀY = I twice: ẌᵀY + 2ẊᵀẎ + XᵀŸ = 0 fixes the multiplier).
For ONE function T (whatever c) the two calls give the same accelerations:
  s79r2-el-state-contradiction: acc1 = acc(c=1) and acc2 = acc(c=2), with acc(1) ≠ acc(2)      FALSE
  s79r2-el-state-control:       the same with two different T objects, c = 1 and c = 2          TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SIZES = admissible(n_min=3, n_max=3)


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _el(s, T):
    z = double_point(s)
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return z, acc


def _expected(s, z, c):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y / c - Xd.T @ Yd
    return -(A @ X) / c + X @ Lam.T, -(A @ Y) / c + Y @ Lam


@claim("s79r2-el-state-contradiction", kind="id", sizes=SIZES)
def contra(s):
    mode = [1]

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * mode[0]
    z, acc1 = _el(s, T)
    mode[0] = 2
    _, acc2 = _el(s, T)
    e1, e2 = _expected(s, z, 1), _expected(s, z, 2)
    return {"Xdd (1)": acc1["X"] - e1[0], "Ydd (1)": acc1["Y"] - e1[1],
            "Xdd (2)": acc2["X"] - e2[0], "Ydd (2)": acc2["Y"] - e2[1]}


@claim("s79r2-el-state-control", kind="id", sizes=SIZES)
def control(s):
    z, acc1 = _el(s, lambda t, v: t.tr(v["X"].T @ v["Y"]))
    _, acc2 = _el(s, lambda t, v: t.tr(v["X"].T @ v["Y"]) * 2)
    e1, e2 = _expected(s, z, 1), _expected(s, z, 2)
    return {"Xdd (1)": acc1["X"] - e1[0], "Ydd (1)": acc1["Y"] - e1[1],
            "Xdd (2)": acc2["X"] - e2[0], "Ydd (2)": acc2["Y"] - e2[1]}
