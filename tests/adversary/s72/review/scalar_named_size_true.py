"""s72 review: a true claim with a user scalar named n, to read its certificate (attempt S5)."""
from stiefelsym import admissible, claim


@claim("s72-scalar-n-true", paper="No", kind="id", section="t", sizes=admissible(n_max=3))
def scalar_n_true(s):
    """c·(tr(XᵀX) − tr(I_r)) / (tr(I_n) ... ) = 0 with c = s.scalar("n") (true on V)."""
    c = s.scalar("n")
    return {"x": c * s.tr(s.X.T @ s.X) - c * s.tr(s.Ir) + 0 * s.tr(s.In)}
