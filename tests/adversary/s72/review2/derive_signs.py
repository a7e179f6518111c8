"""s72 review2 (attempt D1): a true scalar claim whose residual has a constant term with a sum as coefficient:
(n + 1)(tr(X^T X) - r) = 0.  `derive` prints R with the constant's parentheses dropped."""
from stiefelsym import admissible, claim


@claim("rw2-derive-sign", kind="id", paper="No", section="t", sizes=admissible(n_max=4))
def derive_sign(s):
    """(n + 1)(tr(X^T X) - r) = 0 (true on V)."""
    c = s.tr(s.identity(s.n)) + s.q(1)
    return {"s": c * (s.tr(s.X.T @ s.X) - s.tr(s.identity(s.r)))}
