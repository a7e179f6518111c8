"""Point 3, the other way: a claims file whose second claim's function claims to come from a catalog module
(its __module__ set to stiefelsym.proofs.sec7_grassmannians before @claim reads it): claims._in_catalog then keeps
it out of the file's registry, silently.  The hidden claim is false (the last row of X vanishes)."""
from stiefelsym import admissible, claim


@claim("visible-true", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}


def bottom_row(s):
    """The last row of X vanishes."""
    return {"x": s.X[s.X.shape[0] - 1:, :]}


bottom_row.__module__ = "stiefelsym.proofs.sec7_grassmannians"
claim("hidden-false", kind="id", sizes=admissible(n_max=3))(bottom_row)
