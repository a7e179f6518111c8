"""A kinetic energy whose coefficient moves with the position, read through the point of a derivative
(systems.derivative's z, a function's variable: the trace check of euler_lagrange's T follows attrs, calls and
steps, and lets a function's variable through).  G(t, z) = acc(z)·tr(e) with e a 1×1 variable of the point, 0
there, moved by the flow {"e": 1}: derivative(...) = acc at the point (the ε-part of acc·ε).

T(v) = c(X)·tr(ẊᵀẎ), c(X) = 1 + tr(XᵀX), X the position (z["X"]): the engine reads c at the point as a constant,
K = c·K₀, and solves  c·Ÿ = −AY + Yμ,  c·Ẍ = −AX + Xμᵀ  with XᵀY = I: the "naive" accelerations
Ẍ = (−AX + XMᵀ)/c, Ÿ = (−AY + YM)/c, M = XᵀAY − c·ẊᵀẎ  (from ẌᵀY + 2ẊᵀẎ + XᵀŸ = 0 with ẌᵀY = ... symmetric split).
The real Euler–Lagrange equations of L = c(X)tr(ẊᵀẎ) − tr(XᵀAY) have the extra terms ċẎ, ċẊ and −2X tr(ẊᵀẎ):
    d/dt(cẎ) = ∂L/∂X  ⇒ cŸ + ċẎ = 2X tr(ẊᵀẎ) − AY + Yμ
    d/dt(cẊ) = ∂L/∂Y  ⇒ cẌ + ċẊ = −AX + Xμᵀ            (ċ = 2tr(XᵀẊ))
The toolkit refuses this kinetic energy when it closes over the double point (o78-el-closure); the false claim
states the naive accelerations.  The true twin states the real ones (μ solved by hand below)."""
from stiefelsym import claim
from stiefelsym.systems import derivative, double_point, euler_lagrange, real_coordinates

SZ = [(2, 1), (3, 1), (3, 2)]


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _acc(s):
    z0 = double_point(s)
    e0 = s.zeros(1, 1, ("?", "?"))
    one = s.identity(1, ("?", "?")) if False else s.mat([[s.q(1)]])
    point = {"X": z0["X"], "Y": z0["Y"], "Xd": z0["Xdot"], "Yd": z0["Ydot"], "e": e0}

    def G(t, z):
        def T(u, v):
            return u.tr(v["X"].T @ v["Y"]) * (u.tr(z["X"].T @ z["X"]) + 1)
        acc, _ = euler_lagrange(t, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xd"], "Y": z["Yd"]},
                                real_coordinates(t, ["X", "Y"]))
        return {"X": acc["X"] * t.tr(z["e"]), "Y": acc["Y"] * t.tr(z["e"])}
    return z0, derivative(s, G, point, {"e": one})


def _naive(s, z):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    c = s.tr(X.T @ X) + 1
    M = X.T @ A @ Y - Xd.T @ Yd * c
    return (-(A @ X) + X @ M.T) / c, (-(A @ Y) + Y @ M) / c


def _real(s, z):
    """cẌ = −AX − ċẊ + XMᵀ, cŸ = −AY − ċẎ + 2τX + YM, τ = tr(ẊᵀẎ), ċ = 2tr(XᵀẊ);
    XᵀŸ + 2ẊᵀẎ + ẌᵀY = 0 ⇒ (−XᵀAY − ċXᵀẎ + 2τXᵀX + M) + 2cẊᵀẎ + (−XᵀAY − ċẊᵀY + M) = 0 (Mᵀ on the Ẍ side
    transposed: (XMᵀ)ᵀY = M XᵀY = M); with XᵀẎ + ẊᵀY = 0 the ċ terms cancel:
    2M = 2XᵀAY − 2τXᵀX − 2cẊᵀẎ."""
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    c = s.tr(X.T @ X) + 1
    cd = s.tr(X.T @ Xd) * 2
    tau = s.tr(Xd.T @ Yd)
    M = X.T @ A @ Y - X.T @ X * tau - Xd.T @ Yd * c
    return (-(A @ X) - Xd * cd + X @ M.T) / c, (-(A @ Y) - Yd * cd + X * (tau * 2) + Y @ M) / c


@claim("r2-el-kpoint-true", paper="prep", kind="id", sizes=SZ)
def kpoint_true(s):
    """TRUE: the Euler–Lagrange accelerations of c(X)tr(ẊᵀẎ) − tr(XᵀAY) with XᵀY = I."""
    z, acc = _acc(s)
    Xdd, Ydd = _real(s, z)
    return {"Xdd": acc["X"] - Xdd, "Ydd": acc["Y"] - Ydd}


@claim("r2-el-kpoint-false", paper="prep", kind="id", sizes=SZ)
def kpoint_false(s):
    """FALSE: the constant-coefficient reading's accelerations."""
    z, acc = _acc(s)
    Xdd, Ydd = _naive(s, z)
    return {"Xdd": acc["X"] - Xdd, "Ydd": acc["Y"] - Ydd}
