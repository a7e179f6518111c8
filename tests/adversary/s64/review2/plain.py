# ruff: noqa
"""A false and a true claim (q64), the base of the hand-edited results files."""
from stiefelsym import claim


@claim("q64-plain-false", kind="id", sizes=[(3, 2)], statement=r"X^T X = 2 I_r")
def plain_false(s):
    """XᵀX = 2I (false)."""
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}


@claim("q64-plain-true", kind="id", sizes=[(3, 2)], statement=r"X^T X = I_r")
def plain_true(s):
    """XᵀX = I (true)."""
    return {"XtX": s.X.T @ s.X - s.Ir}
