"""Benign: a user's file re-declares a catalog function as a claim of its own (new id, other sizes), plus a claim
of its own.  The re-declared claim is dropped silently (its function's __module__ is the catalog's)."""
from stiefelsym import admissible, claim
from stiefelsym.proofs.sec7_grassmannians import reduced_equation_on_the_grassmannian as f

claim("my-neum-gras-n3", kind="id", sizes=[(3, 1), (3, 2)])(f)


@claim("mine-tangent", kind="id", sizes=admissible(n_max=3))
def honest(s):
    """X^T P + P^T X = 0."""
    return {"c": s.X.T @ s.P + s.P.T @ s.X}
