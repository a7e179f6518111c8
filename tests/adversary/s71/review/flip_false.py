# ruff: noqa
"""A false identity (XᵀP = 0 at r >= 2) whose `fails` record is edited into `checked` (report_flip.py)."""
from stiefelsym import admissible, claim


@claim("s71-flip-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2)."""
    return {"xtp": s.X.T @ s.P}
