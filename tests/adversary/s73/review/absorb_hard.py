"""Float/ball numeric of a false claim hidden by absorption, under a hard case that changes no parameter."""
from stiefelsym import admissible, claim


@claim("s73-absorb-x", kind="id", sizes=admissible(n_max=3))
def absorb_x(s):
    """(cX + X) - cX = 0 with c = 10^20: FALSE (the residual is X)."""
    c = s.q(10**20)
    return {"absorb": (c * s.X + s.X) - c * s.X}


@claim("s73-absorb-tiny", kind="id", sizes=admissible(n_max=3))
def absorb_tiny(s):
    """X^T X - I_r + 10^-30 I_r = 0: FALSE (residual 10^-30 I_r)."""
    return {"tiny": s.X.T @ s.X - s.Ir + s.q(1, 10**30) * s.Ir}
