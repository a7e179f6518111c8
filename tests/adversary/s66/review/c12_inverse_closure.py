# ruff: noqa
"""Inverse statements whose op and inv read a closure that divides by a non-constant (computed outside
them): x -> c x with c = tr(X^T R(lam) X) (or c = tr(P^T P)), inverse y -> y / c with 1/c computed outside.
FALSE as "invertible at every point of T*V": c vanishes (or is undefined) at some points."""
from stiefelsym import Inverse, RightInverse, admissible, claim

S = admissible(n_min=2, n_max=3, r_in=(1,))


@claim("c12-closure-resolvent", kind="id", sizes=S)
def clo_res(s):
    """x -> c x on Sym(r), c = tr(X^T (lam I - A)^-1 X): claimed invertible at every point, inverse y -> y/c."""
    c = s.tr(s.X.T @ s.resolvent(s.lam) @ s.X)
    d = 1 / c
    return {"inv": Inverse(lambda t, x: (x * c,), lambda t, y: (y * d,), on=("Sym(r)",))}


@claim("c12-closure-PtP", kind="id", sizes=S)
def clo_ptp(s):
    """x -> tr(P^T P) x on Sym(r): claimed invertible at every point (false at P = 0)."""
    c = s.tr(s.P.T @ s.P)
    d = 1 / c
    return {"inv": Inverse(lambda t, x: (x * c,), lambda t, y: (y * d,), on=("Sym(r)",))}


@claim("c12-closure-matrix-inv", kind="id", sizes=S)
def clo_minv(s):
    """x -> M x M^T on Sym(r) with M = I + X^T... M = P^T P + lam I_r (singular at lam = -|P|^2)."""
    M = s.P.T @ s.P + s.Ir * s.lam
    Mi = M.inv()
    return {"inv": Inverse(lambda t, x: (M @ x @ M.T,), lambda t, y: (Mi @ y @ Mi.T,), on=("Sym(r)",))}


@claim("c12-right-closure", kind="id", sizes=S)
def right_clo(s):
    """x -> tr(P^T P) x from Sym(r) onto Sym(r): claimed onto at every point (false at P = 0)."""
    c = s.tr(s.P.T @ s.P)
    d = 1 / c
    return {"onto": RightInverse(lambda t, x: (x * c,), lambda t, y: (y * d,), on=("Sym(r)",), to=("Sym(r)",))}
