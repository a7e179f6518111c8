# ruff: noqa
"""A plain claims file in a folder that is a Python package (it has an __init__.py): one false identity.
Honest outcome: s71-pkg-false (XᵀP = 0, false for r >= 2) FAILS its items at (2,2), (3,2), (3,3)."""
from stiefelsym import admissible, claim


@claim("s71-pkg-false", kind="id", sizes=admissible(n_max=3))
def false_claim(s):
    """XᵀP = 0 (false for r >= 2: only XᵀP + PᵀX = 0 on T*V)."""
    return {"xtp": s.X.T @ s.P}
