"""Round 16: the runs of a registered correction taken out of a results file.  The claim fails at every size;
its correction ("constant dropped") holds at r = 1 and fails at r = 2, 3.  With the correction's failing records
taken out the file read as if the correction had been run at (3,1) only."""
from stiefelsym import admissible, claim


@claim("adv-s42-corrected", paper="adv", kind="id", sizes=admissible(n_max=3, n_min=3))
def corrected(s):
    """tr((XᵀP − PᵀX)²) + tr(XᵀX) = r + 1 (false everywhere)."""
    M = s.X.T @ s.P - s.P.T @ s.X
    return {"c": s.tr(M @ M) + s.tr(s.X.T @ s.X) - s.tr(s.Ir) - 1}


@corrected.claim.correction("constant dropped")
def corrected_fix(s):
    M = s.X.T @ s.P - s.P.T @ s.X
    return {"c": s.tr(M @ M) + s.tr(s.X.T @ s.X) - s.tr(s.Ir)}
