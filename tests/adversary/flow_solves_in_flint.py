"""False and ill-posed claims through the Euler–Lagrange solve, which the exact method makes in flint and keeps
there (stiefelsym.systems._Algebra.solve, _Layout.assemble); el-true-control is the positive control."""
from stiefelsym import claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates


def T(t, v):
    return t.tr(v["X"].T @ v["Y"])


def T_zero(t, v):
    return t.tr(v["X"].T @ v["Y"]) * 0          # a degenerate kinetic form: K = 0


def U(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def D0_twice(t, q):
    return [q["X"].T @ q["Y"] - t.Ir, q["X"].T @ q["Y"] - t.Ir]   # every constraint twice: singular


def lam(z, A):
    return z["X"].T @ A @ z["Y"] - z["Xdot"].T @ z["Ydot"]


def acc(s, z, kinetic=T, cons=D0):
    a, _ = euler_lagrange(s, kinetic, U, cons, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                          real_coordinates(s, ["X", "Y"]))
    return a


@claim("el-transposed-lambda", kind="id")
def el_transposed_lambda(s):
    """False: Ẍ = −AX + XΛ (Λ in place of Λᵀ)."""
    z = double_point(s)
    L = lam(z, s.A)
    return {"X": acc(s, z)["X"] - (-(s.A @ z["X"]) + z["X"] @ L)}


@claim("el-sign", kind="id")
def el_sign(s):
    """False: Ÿ = AY + YΛ (the sign of AY)."""
    z = double_point(s)
    L = lam(z, s.A)
    return {"Y": acc(s, z)["Y"] - ((s.A @ z["Y"]) + z["Y"] @ L)}


@claim("el-degenerate-kinetic", kind="id")
def el_degenerate_kinetic(s):
    """Ill-posed: T = 0, so K is singular; whatever it says must not be proved."""
    z = double_point(s)
    return {"X": acc(s, z, kinetic=T_zero)["X"] - z["X"]}


@claim("el-repeated-constraints", kind="id")
def el_repeated_constraints(s):
    """Ill-posed: every constraint twice, so the multipliers' matrix is singular."""
    z = double_point(s)
    L = lam(z, s.A)
    return {"X": acc(s, z, cons=D0_twice)["X"] - (-(s.A @ z["X"]) + z["X"] @ L.T)}


@claim("el-true-control", kind="id")
def el_true_control(s):
    """True (positive control): Ẍ = −AX + XΛᵀ."""
    z = double_point(s)
    L = lam(z, s.A)
    return {"X": acc(s, z)["X"] - (-(s.A @ z["X"]) + z["X"] @ L.T)}
