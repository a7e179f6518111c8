# ruff: noqa
"""Today's change 1 (latex.math_idioms): a claim's own words (docstring, check names, erratum, correction
description) full of the ASCII idioms the reports now rewrite.  One false claim (X^T P = 0), its false
correction, and one true claim.  Looked for: a check name or witness line that says something else than the
record; a verification.tex that pdflatex cannot compile."""
from stiefelsym import admissible, claim

S = admissible(n_min=3, n_max=3, r_in=(2,))


@claim("tx-idioms-false", kind="id", sizes=S, paper="VV",
       erratum="L*_neum != L*_man as printed; 1<=i<=r -> X0 x P0; a^{b_{L*_neum}} Theta_{X0}; x_{L*_neum; "
               "A*_man(lambda)^{-1} is r x r; 2 x 0 -> 0; k x m x n; (X0) x (P0); a<=b<=c<=d",
       statement=r"X^T P = 0")
def tx_false(s):
    """L*_neum(lambda) is 2r x 2r; i != j; 1<=i<=r; Theta(X0, P0); x_{a_{L*_neum}}; (n + r) x 2r; 3 x 0 -> 0; L*_neum_x; A*_man}"""
    return {"X0 x P0 != 0 -> L*_neum": s.X.T @ s.P, "Q0^{L*_man} x_{1<=i<=r}": s.X.T @ s.X - s.Ir}


@tx_false.claim.correction("L*_neum x L*_man != X0 -> Theta_{1<=i<=r}^{L*_neum}")
def tx_false_corr(s):
    return {"X0 != P0": s.P.T @ s.X}


@claim("tx-idioms-true", kind="id", sizes=S, paper="VV", statement=r"X^T X = I_r")
def tx_true(s):
    """Theta x Theta != 0 -> X0 x P0; L*_neum 1<=i<=r r x r"""
    return {"r x r != 0 -> 1<=i<=r X0": s.X.T @ s.X - s.Ir}
