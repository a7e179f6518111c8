"""Variants of the review's cubic kinetic term (each a FALSE claim that the accelerations are (D-eq)'s):
which pass the third-difference test under the randomized methods?"""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _run(s, T):
    z = double_point(s)
    acc, _ = euler_lagrange(s, T, U_double, D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y - Xd.T @ Yd
    return {"Xdd": acc["X"] - (-(A @ X) + X @ Lam.T), "Ydd": acc["Y"] - (-(A @ Y) + Y @ Lam)}


@claim("r2-cubic-one-false", paper="prep", kind="id", sizes=[(2, 1)])
def one(s):
    """Ẋ₁₁Ẋ₂₁Ẏ₁₁ (the review's)"""
    return _run(s, lambda t, v: t.tr(v["X"].T @ v["Y"]) + v["X"][0, 0] * v["X"][1, 0] * v["Y"][0, 0])


@claim("r2-cubic-diff-false", paper="prep", kind="id", sizes=[(2, 1)])
def diff(s):
    """Ẋ₁₁Ẋ₂₁(Ẏ₁₁ − Ẏ₂₁)"""
    return _run(s, lambda t, v: t.tr(v["X"].T @ v["Y"])
                + v["X"][0, 0] * v["X"][1, 0] * (v["Y"][0, 0] - v["Y"][1, 0]))


@claim("r2-cubic-gen-false", paper="prep", kind="id", sizes=[(2, 1)])
def gen(s):
    """Ẋ₁₁Ẋ₂₁Ẏ₁₁·g (g a claim's generic constant)"""
    g = s.general_params("g", 4, 1, ("?", "?"))
    return _run(s, lambda t, v: t.tr(v["X"].T @ v["Y"]) + v["X"][0, 0] * v["X"][1, 0] * v["Y"][0, 0] * g[0, 0])


@claim("r2-cubic-scalar-false", paper="prep", kind="id", sizes=[(2, 1)])
def scal(s):
    """Ẋ₁₁Ẋ₂₁Ẏ₁₁·c (c = s.scalar)"""
    c = s.scalar("c")
    return _run(s, lambda t, v: t.tr(v["X"].T @ v["Y"]) + v["X"][0, 0] * v["X"][1, 0] * v["Y"][0, 0] * c)
