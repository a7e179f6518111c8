"""Batch 3: Euler-Lagrange equations of a Lagrangian scaled by a number that depends on the size.

The double Neumann system (D-Lag): L = c (tr(X'^T Y') - tr(X^T A Y)), X^T Y = I_r.  For c != 0 the accelerations
are those of c = 1, (D-eq): X'' = -AX + X Lam^T, Y'' = -AY + Y Lam, Lam = X^T A Y - X'^T Y'.  For c = 0 the
Lagrangian is 0 and the equations say nothing about X'', Y'' (every acceleration that keeps the constraint is a
solution): the statement "the accelerations of L are (D-eq)" has no meaning there (the kinetic matrix is 0).

  b3-el-c1          c = 1                                        TRUE at every size (control: the catalog's double-neumann-flow)
  b3-el-n           c = n = tr I_n                               TRUE at every size (c != 0)
  b3-el-n-minus-r   c = n - r                                    c = 0 at r = n: the accelerations do not exist there
  b3-el-r-minus-1   c = r - 1                                    c = 0 at r = 1
  b3-el-n-minus-2r  c = n - 2r                                   c = 0 at (2,1), (4,2), ...; NEGATIVE at n < 2r
  b3-el-n-minus-r-false   c = n - r with the sign of Lam flipped FALSE at r < n (control that free does not prove a false one)
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


@claim("b3-el-c1", kind="id", sizes=SZ)
def el_c1(s):
    return _run(s, lambda t: t.q(1))


@claim("b3-el-n", kind="id", sizes=SZ)
def el_n(s):
    return _run(s, lambda t: t.tr(t.In))


@claim("b3-el-n-minus-r", kind="id", sizes=SZ)
def el_n_minus_r(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir))


@claim("b3-el-r-minus-1", kind="id", sizes=SZ)
def el_r_minus_1(s):
    return _run(s, lambda t: t.tr(t.Ir) - 1)


@claim("b3-el-n-minus-2r", kind="id", sizes=SZ)
def el_n_minus_2r(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir) * 2)


@claim("b3-el-n-minus-r-false", kind="id", sizes=SZ)
def el_n_minus_r_false(s):
    return _run(s, lambda t: t.tr(t.In) - t.tr(t.Ir), sign=-1)
