# ruff: noqa
"""A true identity (XᵀP + PᵀX = 0) run the same way, whose `checked` record gives report_flip.py its evidence."""
from stiefelsym import admissible, claim


@claim("s71-flip-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2)."""
    return {"xtp": s.X.T @ s.P + s.P.T @ s.X}
