"""A true and a false statement, and a correction, for forged results files."""
from stiefelsym import admissible, claim


@claim("h2c-true", kind="id", sizes=admissible(n_max=3))
def c_true(s):
    """True: X^T P + P^T X = 0."""
    return {"r": s.X.T @ s.P + s.P.T @ s.X}


@claim("h2c-false", kind="id", sizes=admissible(n_max=3))
def c_false(s):
    """False: X^T P = 0."""
    return {"r": s.X.T @ s.P}


@c_false.claim.correction("the symmetric part: X^T P + P^T X = 0")
def c_false_fix(s):
    return {"r": s.X.T @ s.P + s.P.T @ s.X}
