from stiefelsym import admissible, claim


@claim("h2-fa", kind="id", sizes=admissible(n_max=3), statement="X^T P = 0 (an erratum at r >= 2)",
       fails_at=lambda n, r: r >= 2, erratum="X^T P is skew, zero at r = 1 only")
def fa(s):
    """XᵀP = 0: true at r = 1 only"""
    return {"r": s.X.T @ s.P}
