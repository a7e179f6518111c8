"""Item 2: the position rebuilt inside T through a whitelisted call.  The claim makes the point of the double
system from its own generic parameters: X = G = s.generic("G", "n", "r"), Y = X(XᵀX)⁻¹ (XᵀY = I),
Ẋ = s.generic("V", "n", "r"), Ẏ = −Y(ẊᵀY) (ẊᵀY + XᵀẎ = 0).  T reads t.generic("G", "n", "r") — the same
matrix, i.e. the position — through KINETIC_CONSTANT_CALLS' `generic`: T = c(X)tr(ẊᵀẎ), c = 1 + tr(XᵀX), the
kinetic energy stop 78 refuses when it closes over the position (o78-el-closure) and review2 W3 read through a
function's variable.  TRUE: the real Euler–Lagrange accelerations (review2's `_real`, checked there with sympy);
FALSE: the constant-coefficient ("naive") ones."""
from stiefelsym import claim
from stiefelsym.systems import euler_lagrange, real_coordinates

SZ = [(2, 1), (3, 1), (3, 2)]


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def T(t, v):
    G = t.generic("G", "n", "r")
    return t.tr(v["X"].T @ v["Y"]) * (t.tr(G.T @ G) + 1)


def _point(s):
    X = s.generic("G", "n", "r")
    Y = X @ (X.T @ X).inv()
    Xd = s.generic("V", "n", "r")
    Yd = -(Y @ (Xd.T @ Y))
    return {"X": X, "Y": Y, "Xdot": Xd, "Ydot": Yd}


def _acc(s):
    z = _point(s)
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return z, acc


def _naive(s, z):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    c = s.tr(X.T @ X) + 1
    M = X.T @ A @ Y - Xd.T @ Yd * c
    return (-(A @ X) + X @ M.T) / c, (-(A @ Y) + Y @ M) / c


def _real(s, z):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    c = s.tr(X.T @ X) + 1
    cd = s.tr(X.T @ Xd) * 2
    tau = s.tr(Xd.T @ Yd)
    M = X.T @ A @ Y - X.T @ X * tau - Xd.T @ Yd * c
    return (-(A @ X) - Xd * cd + X @ M.T) / c, (-(A @ Y) - Yd * cd + X * (tau * 2) + Y @ M) / c


@claim("r3-el-generic-true", kind="id", sizes=SZ)
def generic_true(s):
    z, acc = _acc(s)
    Xdd, Ydd = _real(s, z)
    return {"Xdd": acc["X"] - Xdd, "Ydd": acc["Y"] - Ydd}


@claim("r3-el-generic-false", kind="id", sizes=SZ)
def generic_false(s):
    z, acc = _acc(s)
    Xdd, Ydd = _naive(s, z)
    return {"Xdd": acc["X"] - Xdd, "Ydd": acc["Y"] - Ydd}


@claim("r3-el-generic-constraints-ok", kind="id", sizes=SZ)
def constraints_ok(s):
    """TRUE: the point satisfies XᵀY = I, ẊᵀY + XᵀẎ = 0."""
    z = _point(s)
    return {"D0": z["X"].T @ z["Y"] - s.Ir, "D0dot": z["Xdot"].T @ z["Y"] + z["X"].T @ z["Ydot"]}
