# ruff: noqa
from stiefelsym import claim


@claim("q64-leftright", kind="id", sizes=[(3, 2)], statement='X^T X = 2 I_r \\left(')
def f(s):
    'XᵀX = 2I $\\left( a$ end.'
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}
