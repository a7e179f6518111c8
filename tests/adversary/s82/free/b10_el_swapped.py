"""Batch 10: Euler-Lagrange equations of the double system at a point other than the scene's own, with a potential
that closes over a constant matrix C of the scene.

L = tr(X'^T Y') - U,  U = tr(X^T A Y) + tr(X^T C),  X^T Y = I_r (multiplier M, force d tr(M^T g)/dq).  By hand:
    Y'' = -AY - C + Y M^T,   X'' = -AX + X M,   g'' = 0  =>  M = Y^T A X - Y'^T X' + (1/2) C^T X,
so  X'' = -AX + X (Y^T A X - Y'^T X' + (1/2) C^T X),  Y'' = -AY - C + Y (X^T A Y - X'^T Y' + (1/2) X^T C).

The point: (X, Y, X', Y') = (DY, DX, DY', DX') (the scene's double point with X and Y exchanged: it satisfies
X^T Y = I_r and its derivative).  C is a value of the scene the potential closes over (a constant of U).

  b10-own-c-true      at the scene's own point, C = DX' (captured velocity): the hand formula       TRUE (control)
  b10-swap-c-true     at the swapped point, C = DX': the hand formula with C = DX'                 TRUE
  b10-swap-c-moved    at the swapped point: the hand formula with C replaced by DY' (what a substitution
                      DX' -> DY' of the point's letters would give)                                FALSE (C != DY')
  b10-swap-g-true     at the swapped point, C = a generic constant G (s.generic): hand formula      TRUE (control)
  b10-swap-pos-true   at the swapped point, C = DY (captured position letter): hand formula with C = DY   TRUE
  b10-swap-pos-moved  the same with C replaced by DX                                               FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import double_point, euler_lagrange, real_coordinates

SZ = admissible(n_max=4)


def _D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _T(t, v):
    return t.tr(v["X"].T @ v["Y"])


def _run(s, C, swap, C_claim):
    z = double_point(s)
    U = lambda t, q: t.tr(q["X"].T @ t.A @ q["Y"]) + t.tr(q["X"].T @ C)   # noqa: E731
    if swap:
        X, Y, Xd, Yd = z["Y"], z["X"], z["Ydot"], z["Xdot"]
    else:
        X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    acc, _ = euler_lagrange(s, _T, U, _D0, {"X": X, "Y": Y}, {"X": Xd, "Y": Yd}, real_coordinates(s, ["X", "Y"]))
    A = s.A
    M = Y.T @ A @ X - Yd.T @ Xd + C_claim.T @ X / 2
    want_X = -(A @ X) + X @ M
    want_Y = -(A @ Y) - C_claim + Y @ M.T
    return {"X''": acc["X"] - want_X, "Y''": acc["Y"] - want_Y}


@claim("b10-own-c-true", kind="id", sizes=SZ)
def own_c_true(s):
    z = double_point(s)
    return _run(s, z["Xdot"], False, z["Xdot"])


@claim("b10-swap-c-true", kind="id", sizes=SZ)
def swap_c_true(s):
    z = double_point(s)
    return _run(s, z["Xdot"], True, z["Xdot"])


@claim("b10-swap-c-moved", kind="id", sizes=SZ)
def swap_c_moved(s):
    z = double_point(s)
    return _run(s, z["Xdot"], True, z["Ydot"])


@claim("b10-swap-g-true", kind="id", sizes=SZ)
def swap_g_true(s):
    G = s.generic("G", "n", "r")
    return _run(s, G, True, G)


@claim("b10-swap-pos-true", kind="id", sizes=SZ)
def swap_pos_true(s):
    z = double_point(s)
    return _run(s, z["Y"], True, z["Y"])


@claim("b10-swap-pos-moved", kind="id", sizes=SZ)
def swap_pos_moved(s):
    z = double_point(s)
    return _run(s, z["Y"], True, z["X"])
