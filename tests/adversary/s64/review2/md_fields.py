# ruff: noqa
"""Which claim fields reach verification.md with a line of their own (q64): each field carries a `$...$`
segment (or plain text, for section) that begins a line with a marker ZZ<field>.  False claim, erratum declared."""
from stiefelsym import claim


@claim("q64-fields", paper="lab$\nZZlabel$", kind="id", section="3\nZZsection | x",
       sizes=[(3, 2)], statement="X^T X = 2 I_r\nZZstatement", fails_at=lambda n, r: True,
       erratum="wrong $\nZZerratum$ factor")
def fields(s):
    """XᵀX = 2I $\nZZtitle$ (false)."""
    return {"XtX $\nZZcheck$": s.X.T @ s.X - 2 * s.Ir}


@fields.claim.correction("factor 1 $\nZZcorrection$")
def fields_fixed(s):
    return {"XtX $\nZZcheck$": s.X.T @ s.X - s.Ir}
