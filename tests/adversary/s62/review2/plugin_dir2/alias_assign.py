import stiefelsym

declare = stiefelsym.claim


@declare("pd2-alias-assign", kind="id", sizes=stiefelsym.admissible(n_max=3))
def f(s):
    """FALSE: P = 0 (claim bound by an assignment)."""
    return {"P": s.P}
