# ruff: noqa
"""Hand witnesses at small points where a divisor of the residual could vanish (resolvents, inverses).
Every claim is FALSE; the question is whether the witness printed is a point where the residual is defined
and has the printed value."""
from stiefelsym import admissible, claim

S = admissible(n_min=2, n_max=3, r_in=(1,))


@claim("c10-resolvent", kind="id", sizes=S)
def res(s):
    """false: tr(X^T R(lam) X) = 1/lam (R(lam) = (lam I - A)^-1)."""
    return {"x": s.tr(s.X.T @ s.resolvent(s.lam) @ s.X) * s.lam - 1}


@claim("c10-inverse-PtP", kind="id", sizes=S)
def inv(s):
    """false: (I + P^T P)^-1 = I - P^T P."""
    M = s.Ir + s.P.T @ s.P
    return {"x": M.inv() - (s.Ir - s.P.T @ s.P)}


@claim("c10-div-trace", kind="id", sizes=S)
def div(s):
    """false: tr(X^T A X) / tr(X^T A A X) = 1."""
    return {"x": s.tr(s.X.T @ s.A @ s.X) / s.tr(s.X.T @ s.A @ s.A @ s.X) - 1}


@claim("c10-two-resolvents", kind="id", sizes=S)
def two(s):
    """false: R(lam) R(kappa) = R(lam) + R(kappa)."""
    return {"x": s.X.T @ (s.resolvent(s.lam) @ s.resolvent(s.kappa) - s.resolvent(s.lam) - s.resolvent(s.kappa)) @ s.X}
