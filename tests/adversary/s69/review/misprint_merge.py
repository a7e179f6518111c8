# ruff: noqa
"""Two unrelated errata of one's own (two different formulas, each wrong in its own way) that happen to cite one
label and whose corrections carry the same words: does the headline count them as one misprint?  And a Count
whose own words quote "(paper: 5)"."""
from stiefelsym import Count, admissible, claim


@claim("mm-trace", paper=("thm-x",), kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True,
       erratum="tr XᵀX printed as r + 1.")
def trace_printed(s):
    """tr(XᵀX) = r + 1 (false: it is r)."""
    return {"tr": (s.X.T @ s.X).trace() - s.r - 1}


@trace_printed.claim.correction("the sign of the last term")
def trace_corrected(s):
    return {"tr": (s.X.T @ s.X).trace() - s.r}


@claim("mm-momentum", paper=("thm-x",), kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: r > 1,
       erratum="XᵀP printed as PᵀX (another formula, another misprint).")
def momentum_printed(s):
    """XᵀP − PᵀX = 0 (false: XᵀP + PᵀX = 0)."""
    return {"sym": s.X.T @ s.P - s.P.T @ s.X}


@momentum_printed.claim.correction("the sign of the last term")
def momentum_corrected(s):
    return {"sym": s.X.T @ s.P + s.P.T @ s.X}


@claim("mm-count", paper=("thm-y",), kind="dim", sizes=admissible(n_max=3), fails_at=lambda n, r: True,
       erratum="a count of my own, not the paper's")
def my_count(s):
    """The rows of X counted as r + 1 (false)."""
    return {"rows": Count(s.X.shape[0], s.n + 1, "rows of X (paper: 5)")}
