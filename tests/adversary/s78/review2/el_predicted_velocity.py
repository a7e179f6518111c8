"""The generic velocity w of euler_lagrange's third-difference test is drawn from the scene's random source
with its state saved and restored, and its parameters are kept under a fixed name: the claim's next draw of the
same shape (s.general_params("g", N, 1)) repeats w's coefficients c under the randomized methods, and a second
euler_lagrange call reuses c.  A cubic term that vanishes at c's direction (and has zero gradient at every
coordinate basis vector, as the review's Ẋ₁₁Ẋ₂₁Ẏ₁₁) then passes the test and is dropped from K.

T₂ = tr(ẊᵀẎ) + Ẋ₁₁Ẋ₂₁(g₄Ẏ₁₁ − g₃Ẏ₂₁) at n = 2, r = 1 (coordinates X₁₁, X₂₁, Y₁₁, Y₂₁ = indices 0..3).
The cubic term is no null Lagrangian (its Hessian in q̇ enters d/dt ∂T/∂q̇): the claim that T₂'s accelerations
are (D-eq)'s is FALSE (for T₁ = tr(ẊᵀẎ) it is TRUE)."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _el(s, z, T):
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return acc


def _deq(s, z):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return -(A @ X) + X @ Lam.T, -(A @ Y) + Y @ Lam


def T1(t, v):
    return t.tr(v["X"].T @ v["Y"])


@claim("r2-el-predict-false", paper="prep", kind="id", sizes=[(2, 1)])
def predict_false(s):
    """FALSE: T₂'s accelerations are (D-eq)'s."""
    z = double_point(s)
    acc1 = _el(s, z, T1)
    g = s.general_params("g", 4, 1, ("?", "?"))

    def T2(t, v):
        X, Y = v["X"], v["Y"]
        return t.tr(X.T @ Y) + X[0, 0] * X[1, 0] * (g[3, 0] * Y[0, 0] - g[2, 0] * Y[1, 0])
    acc2 = _el(s, z, T2)
    Xdd, Ydd = _deq(s, z)
    return {"Xdd": acc2["X"] - Xdd, "Ydd": acc2["Y"] - Ydd, "first": acc1["X"] - Xdd}


@claim("r2-el-predict-true", paper="prep", kind="id", sizes=[(2, 1)])
def predict_true(s):
    """TRUE control: T₁'s accelerations twice are (D-eq)'s."""
    z = double_point(s)
    acc1 = _el(s, z, T1)
    g = s.general_params("g", 4, 1, ("?", "?"))

    def T2(t, v):
        return t.tr(v["X"].T @ v["Y"]) + g[0, 0] - g[0, 0]
    acc2 = _el(s, z, T2)
    Xdd, Ydd = _deq(s, z)
    return {"Xdd": acc2["X"] - Xdd, "Ydd": acc2["Y"] - Ydd, "first": acc1["X"] - Xdd}


@claim("r2-el-predict-control", paper="prep", kind="id", sizes=[(2, 1)])
def predict_control(s):
    """The same false claim with g drawn before the first call (so not w's coefficients): refused (error) expected."""
    z = double_point(s)
    g = s.general_params("g", 4, 1, ("?", "?"))
    acc1 = _el(s, z, T1)

    def T2(t, v):
        X, Y = v["X"], v["Y"]
        return t.tr(X.T @ Y) + X[0, 0] * X[1, 0] * (g[3, 0] * Y[0, 0] - g[2, 0] * Y[1, 0])
    acc2 = _el(s, z, T2)
    Xdd, Ydd = _deq(s, z)
    return {"Xdd": acc2["X"] - Xdd, "Ydd": acc2["Y"] - Ydd, "first": acc1["X"] - Xdd}
