"""Free method: stop 82's H1 (a Lagrangian scaled by a size coefficient that vanishes at some size) through the
stop-84 door's blind spot: c = 1 - 2r/(n + r) = (n - r)/(n + r), 0 at r = n, accepted by free.algebra.divisor
(its constant group has one sign).  The double Neumann Lagrangian L = c (tr(X'^T Y') - tr(X^T A Y)).

el-k-nr      c = (n - r)/(n + r): at r = n the Lagrangian is 0 and the accelerations do not exist (the statement
             has no meaning there, like s82's b3-el-n-minus-r, which free now leaves undecided)  -- not true at r = n
el-k-r1      c = 1 - 2/(r + 1) = (r - 1)/(r + 1): 0 at r = 1
el-k-n4      c = 1 - 8/(n + 4): 0 at n = 4 only
el-c1        c = 1: TRUE control
el-k-nr-f    c = (n - r)/(n + r) with Lam's sign flipped: FALSE at r < n (control)
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SZ = admissible(n_max=4)


def _flow(t, z, sign=1):
    Lam = z["X"].T @ t.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]
    Lam = Lam * sign
    return {"X": -(t.A @ z["X"]) + z["X"] @ Lam.T, "Y": -(t.A @ z["Y"]) + z["Y"] @ Lam}


def _D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _run(s, c_of, sign=1):
    z = double_point(s)
    T = lambda t, v: t.tr(v["X"].T @ v["Y"]) * c_of(t)       # noqa: E731
    U = lambda t, q: t.tr(q["X"].T @ t.A @ q["Y"]) * c_of(t)  # noqa: E731
    acc, _ = euler_lagrange(s, T, U, _D0, {"X": z["X"], "Y": z["Y"]}, {"X": z["Xdot"], "Y": z["Ydot"]},
                            real_coordinates(s, ["X", "Y"]))
    want = _flow(s, z, sign)
    return {"X''": acc["X"] - want["X"], "Y''": acc["Y"] - want["Y"]}


def _knr(t):
    return 1 - 2 * t.tr(t.Ir) / (t.tr(t.In) + t.tr(t.Ir))


@claim("el-k-nr", kind="id", sizes=SZ)
def el_k_nr(s):
    return _run(s, _knr)


@claim("el-k-r1", kind="id", sizes=SZ)
def el_k_r1(s):
    return _run(s, lambda t: 1 - 2 / (t.tr(t.Ir) + 1))


@claim("el-k-n4", kind="id", sizes=SZ)
def el_k_n4(s):
    return _run(s, lambda t: 1 - 8 / (t.tr(t.In) + 4))


@claim("el-c1", kind="id", sizes=SZ)
def el_c1(s):
    return _run(s, lambda t: t.q(1))


@claim("el-k-nr-f", kind="id", sizes=SZ)
def el_k_nr_f(s):
    return _run(s, _knr, sign=-1)
