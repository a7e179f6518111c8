"""Absorbed false residuals that read A, P and X (every parameter family a hard case rewrites)."""
from stiefelsym import admissible, claim


@claim("s73-absorb-axp", kind="id", sizes=admissible(n_max=3))
def absorb_axp(s):
    """(c M + M) - c M = 0 with M = X^T A X + P^T P and c = 10^20: FALSE (the residual is M)."""
    c = s.q(10**20)
    M = s.X.T @ s.A @ s.X + s.P.T @ s.P
    return {"absorb": (c * M + M) - c * M}
