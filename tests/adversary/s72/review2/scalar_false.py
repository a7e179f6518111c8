"""s72 review2: a false scalar claim, tr(X^T X) - r + 1 = 0 (it is 1 on V), the base of forged certificates."""
from stiefelsym import admissible, claim


@claim("rw2-scalar-false", kind="id", paper="No", section="t", sizes=admissible(n_max=4))
def scalar_false(s):
    """tr(X^T X) - r + 1 = 0: false (the left side is 1 on V)."""
    return {"s": s.tr(s.X.T @ s.X) - s.tr(s.identity(s.r)) + s.q(1)}
