# ruff: noqa
"""Witness naming: false claims whose own parameters are named like the scene's letters (X, P, A, lam, λ,
kappa, E1).  The report's witness must let a reader tell them apart and rebuild the nonzero residual."""
from stiefelsym import admissible, claim

S = admissible(n_min=2, n_max=2, r_in=(1,))


@claim("c9-own-X", kind="id", sizes=S)
def own_x(s):
    """false: Xg^T Xg = X^T X for a generic matrix of the claim's own named "X"."""
    G = s.generic("X", "n", "r")
    return {"x": G.T @ G - s.X.T @ s.X}


@claim("c9-own-A", kind="id", sizes=S)
def own_a(s):
    """false: the claim's own symmetric "A" equals the scene's A."""
    B = s.generic("A", "n", "n", "sym")
    return {"x": s.X.T @ (B - s.A) @ s.X}


@claim("c9-own-lam", kind="id", sizes=S)
def own_lam(s):
    """false: the claim's own scalar "λ" equals the scene's λ."""
    return {"x": s.scalar("λ") - s.lam}


@claim("c9-own-lambda", kind="id", sizes=S)
def own_lambda(s):
    """false: own "lambda" = lam."""
    return {"x": s.scalar("lambda") - s.lam}


@claim("c9-own-a1", kind="id", sizes=S)
def own_a1(s):
    """false: own "a_1" equals the first eigenvalue a_1 of A: X^T A X = own a_1 ... (via the scalar a_1)."""
    return {"x": s.scalar("a_1") * s.X.T @ s.X - s.X.T @ s.A @ s.X}
