# ruff: noqa
"""A report's headline against its records: a rejected correction, a `not` claim refuted without a witness."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("hl-false-corr", paper="r65", kind="id", sizes=SZ, statement=r"X^T X = 2 I_r")
def false_with_false_correction(s):
    """XᵀX = 2I_r (false), with a registered correction that is false too."""
    return {"r": s.X.T @ s.X - 2 * s.Ir}


@false_with_false_correction.claim.correction("XᵀX = 3I_r")
def _corr(s):
    return {"r": s.X.T @ s.X - 3 * s.Ir}


@claim("hl-not-vanishes", paper="r65", kind="not", expect="nonzero", sizes=SZ, statement=r"X^T P + P^T X \ne 0")
def not_that_vanishes(s):
    """A 'does not hold' whose residual vanishes on T*V: fails without a witness point."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}
