import stiefelsym.claims
from stiefelsym import admissible


@stiefelsym.claim("pd2-sub-import", kind="id", sizes=admissible(n_max=3))
def f(s):
    """FALSE: X^T P = 0 (import stiefelsym.claims binds stiefelsym)."""
    return {"XtP": s.X.T @ s.P}
