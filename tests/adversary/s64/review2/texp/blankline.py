# ruff: noqa
from stiefelsym import claim


@claim("q64-blankline", kind="id", sizes=[(3, 2)], statement='X^T X\n\n= 2 I_r')
def f(s):
    'XᵀX = 2I.'
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}
