# ruff: noqa
from stiefelsym import claim


@claim("q64-uncounted-env", kind="id", sizes=[(3, 2)], statement='X^T X = 2 I_r')
def f(s):
    'XᵀX = 2I $\\begin {matrix} a$ and more.'
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}
