"""Item 2 controls: whitelisted calls fed a value computed from the point outside T (expected: refused at trace):
resolvent of c(X), mat of closed-over entries, scalar_matrix of c(X), generic's product with the position,
realify of X.  Each is the naive (false) claim of the kinetic energy c(X)tr(ẊᵀẎ) on the double point."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _run(s, coef):
    z = double_point(s)
    X = z["X"]
    c = s.tr(X.T @ X) + 1

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * coef(t, c, X)
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    return {"Xdd": acc["X"]}


@claim("r3-wl-resolvent-false", kind="id", sizes=[(2, 1)])
def wl_resolvent(s):
    return _run(s, lambda t, c, X: t.tr(t.resolvent(c)))


@claim("r3-wl-mat-false", kind="id", sizes=[(2, 1)])
def wl_mat(s):
    return _run(s, lambda t, c, X: t.tr(t.mat([[c]])))


@claim("r3-wl-scalar-matrix-false", kind="id", sizes=[(2, 1)])
def wl_scalar_matrix(s):
    return _run(s, lambda t, c, X: t.tr(t.scalar_matrix(c, 1, "?")))


@claim("r3-wl-realify-false", kind="id", sizes=[(2, 1)])
def wl_realify(s):
    return _run(s, lambda t, c, X: t.tr(t.realify(X, X).T @ t.realify(X, X)))
