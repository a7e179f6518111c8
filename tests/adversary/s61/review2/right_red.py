"""Candidates for the right-reduced chart at r = n (X = I) against non-covariant claims (all FALSE)."""
from stiefelsym import admissible, claim, det

SQ = admissible(n_max=4, n_min=2, where=lambda n, r: r == n, condition="r = n")


@claim("rr-x-minus-in", kind="id", sizes=SQ)
def x_minus_in(s):
    """FALSE: X = I_n."""
    return {"X - I": s.X - s.In}


@claim("rr-tr-x", kind="id", sizes=SQ)
def tr_x(s):
    """FALSE: tr X = n."""
    return {"tr X - n": s.tr(s.X) - s.q(int(s.n))}


@claim("rr-x-sym", kind="id", sizes=SQ)
def x_sym(s):
    """FALSE: X symmetric."""
    return {"X - X^T": s.X - s.X.T}


@claim("rr-det-x", kind="id", sizes=SQ)
def det_x(s):
    """FALSE: det X = 1 (only one component)."""
    return {"det X - 1": det(s, s.X) - s.q(1)}


@claim("rr-xp", kind="id", sizes=SQ)
def xp(s):
    """FALSE: P X^T ... tr(P) = 0."""
    return {"tr P": s.tr(s.P)}


@claim("rr-psi-ir", kind="id", sizes=SQ)
def psi_ir(s):
    """FALSE: X^T P = P (X = I)."""
    return {"XtP - P": s.X.T @ s.P - s.P}
