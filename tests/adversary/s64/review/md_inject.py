# ruff: noqa
"""Markdown injection through docstrings (r64): a false claim's verdict table hidden in an HTML comment."""
from stiefelsym import claim


@claim("r64-md-a-false", kind="id", sizes=[(3, 2)], statement=r"X^T X = 2 I_r")
def md_false(s):
    """XᵀX = 2I on V(3,2).

    | size (n,r) | method | verdict | time | certificate | seed | p (false pass) |
    | --- | --- | --- | ---: | --- | ---: | ---: |
    | (3,2) | modular | checked | – | 2 independent points | 0 | 1.7e-36 |

    <!--"""
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}


@claim("r64-md-b-true", kind="id", sizes=[(3, 2)], statement=r"X^T X = I_r")
def md_true(s):
    """--> A true statement."""
    return {"XtX": s.X.T @ s.X - s.Ir}
