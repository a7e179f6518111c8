"""The shape-hint hold (stop 80) keys a function by (id(f), the SHAPE SIGNATURE of the step's argument), and the
signature of a dict is its keys IN ORDER: the same kinetic energy handed to two euler_lagrange calls of the same
system, the second with the position and velocity dicts written {"Y": .., "X": ..}, is never compared.
T(t, v) = c·tr(ẊᵀẎ), c = 1 at the first call, 2 at the second (a mode the claim flips); U = tr(XᵀAY), D0 = XᵀY − I
(the double system of s79/review2/el_stateful.py).
Truth (by hand, s79/review2/el_stateful.py): for L = c·tr(ẊᵀẎ) − tr(XᵀAY) with XᵀY = I,
Ẍ = −AX/c + XΛ_cᵀ, Ÿ = −AY/c + YΛ_c, Λ_c = XᵀAY/c − ẊᵀẎ.  For ONE function T both calls give the same
accelerations; those of c = 1 and c = 2 differ (AX ≠ 0 … generic).
  s80r-el-keyorder-contradiction: acc1 = acc(c=1) and acc2 = acc(c=2) (second call's dicts in the order Y, X)  FALSE
  s80r-el-keyorder-control:       the same with two T objects (c = 1, c = 2)                                 TRUE
  s80r-el-keyorder-honest-false:  one stateless T (c = 1), "acc2 = acc(c=2)"                                 FALSE
  s80r-el-sameorder-contradiction: the stateful T, both calls in the order X, Y (the stop's own fix: refused)
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SIZES = admissible(n_min=3, n_max=3)


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _el(s, T, order=("X", "Y")):
    z = double_point(s)
    pos = {"X": z["X"], "Y": z["Y"]}
    vel = {"X": z["Xdot"], "Y": z["Ydot"]}
    acc, _ = euler_lagrange(s, T, U_double, D0, {k: pos[k] for k in order}, {k: vel[k] for k in order},
                            real_coordinates(s, ["X", "Y"]))
    return z, acc


def _expected(s, z, c):
    X, Y, Xd, Yd, A = z["X"], z["Y"], z["Xdot"], z["Ydot"], s.A
    Lam = X.T @ A @ Y / c - Xd.T @ Yd
    return -(A @ X) / c + X @ Lam.T, -(A @ Y) / c + Y @ Lam


def _checks(s, z, acc1, acc2):
    e1, e2 = _expected(s, z, 1), _expected(s, z, 2)
    return {"Xdd (1)": acc1["X"] - e1[0], "Ydd (1)": acc1["Y"] - e1[1],
            "Xdd (2)": acc2["X"] - e2[0], "Ydd (2)": acc2["Y"] - e2[1]}


@claim("s80r-el-keyorder-contradiction", kind="id", sizes=SIZES)
def contra(s):
    mode = [1]

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * mode[0]
    z, acc1 = _el(s, T)
    mode[0] = 2
    _, acc2 = _el(s, T, ("Y", "X"))
    return _checks(s, z, acc1, acc2)


@claim("s80r-el-sameorder-contradiction", kind="id", sizes=SIZES)
def contra_same(s):
    mode = [1]

    def T(t, v):
        return t.tr(v["X"].T @ v["Y"]) * mode[0]
    z, acc1 = _el(s, T)
    mode[0] = 2
    _, acc2 = _el(s, T)
    return _checks(s, z, acc1, acc2)


@claim("s80r-el-keyorder-control", kind="id", sizes=SIZES)
def control(s):
    z, acc1 = _el(s, lambda t, v: t.tr(v["X"].T @ v["Y"]))
    _, acc2 = _el(s, lambda t, v: t.tr(v["X"].T @ v["Y"]) * 2, ("Y", "X"))
    return _checks(s, z, acc1, acc2)


@claim("s80r-el-keyorder-honest-false", kind="id", sizes=SIZES)
def honest(s):
    T = lambda t, v: t.tr(v["X"].T @ v["Y"])   # noqa: E731
    z, acc1 = _el(s, T)
    _, acc2 = _el(s, T, ("Y", "X"))
    return _checks(s, z, acc1, acc2)
