# ruff: noqa
"""Markdown structure forgery (q64): a paper label whose math segment puts `<!--` at the start of a line
(an HTML block that hides everything up to a line with `-->`), and a true claim's statement (several lines,
math_ok: no `$`, `#`, `%`) that closes it and prints a forged verdict table for the false claim."""
from stiefelsym import claim

FORGED = "\n".join([
    "X^T X = I_r",
    "-->",
    "",
    "`q64-md-a` (XᵀX = 2 I_r) verdicts:",
    "",
    "| size (n,r) | method | verdict | time | certificate | seed | p (false pass) |",
    "| --- | --- | --- | ---: | --- | ---: | ---: |",
    "| (3,2) | modular | checked | 0.01 s | 2 independent points | 0 | 1.7e-36 |",
    "",
    "<!--",
])


@claim("q64-md-a", paper="x$\n<!--$", kind="id", section="3", sizes=[(3, 2)], statement=r"X^T X = 2 I_r")
def md_a(s):
    """XᵀX = 2I on V(3,2) (false: XᵀX = I)."""
    return {"XtX": s.X.T @ s.X - 2 * s.Ir}


@claim("q64-md-b", kind="id", section="4", sizes=[(3, 2)], statement=FORGED)
def md_b(s):
    """A true statement, XᵀX = I."""
    return {"XtX": s.X.T @ s.X - s.Ir}
