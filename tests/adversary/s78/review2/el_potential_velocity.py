"""A potential that reads the velocity (closed over): U(t, q) = tr(XᵀAY) + tr(Ẋ₀ᵀX), with Ẋ₀ the point's velocity.
The Lagrangian meant is L = tr(ẊᵀẎ) − tr(XᵀAY) − tr(ẊᵀX); −tr(ẊᵀX) = −d/dt ½tr(XᵀX) is a null Lagrangian, so the
true accelerations are (D-eq)'s: Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ, Λ = XᵀAY − ẊᵀẎ.  The engine takes Ẋ₀ as a constant
coefficient of U (a force −Ẋ₀ in the Y... X-equation): ∂L/∂X = −AY − Ẋ₀, so Ÿ = −AY − Ẋ₀ + YM, XᵀŸ = −2ẊᵀẎ...
The toolkit refuses a kinetic energy that closes over the position (o78-el-closure); a potential that closes over
the velocity is the same door from the other side."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SZ = [(2, 1), (3, 1), (3, 2)]


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _acc(s):
    z = double_point(s)
    Xd0 = z["Xdot"]

    def U(t, q):
        return t.tr(q["X"].T @ t.A @ q["Y"]) + t.tr(Xd0.T @ q["X"])

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"])
    acc, _ = euler_lagrange(s, T, U, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return z, acc


@claim("r2-el-Uvel-true", paper="prep", kind="id", sizes=SZ)
def uvel_true(s):
    """TRUE (null Lagrangian): the accelerations are (D-eq)'s."""
    z, acc = _acc(s)
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}


@claim("r2-el-Uvel-false", paper="prep", kind="id", sizes=SZ)
def uvel_false(s):
    """FALSE: the engine's constant-coefficient reading: the X-equation gets the extra force −Ẋ₀
    (T = tr(ẊᵀẎ): ∂T/∂Ẏ = Ẋ, d/dt → Ẍ = −∂U/∂Y + Xμᵀ...; ∂T/∂Ẋ = Ẏ → Ÿ = −AY − Ẋ₀ + Yμ).
    With XᵀŸ + 2ẊᵀẎ + ẌᵀY = 0 ... μ = Λ + XᵀẊ₀/2 (by symmetry of the split, as in the review's G case with G = Ẋ₀)."""
    z, acc = _acc(s)
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    G = Xd
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ (Lam.T + G.T @ X / 2)),
            "Ydd": acc["Y"] - (-(A @ Y) + Y @ (Lam + X.T @ G / 2) - G)}
