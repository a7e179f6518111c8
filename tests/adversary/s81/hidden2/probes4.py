"""s81 hidden2 (h81b): h81b-metric-leaf-casimirs's statement in the standard realization (for the comparison in FINDINGS)."""
from __future__ import annotations

from stiefelsym import admissible, claim

from claims import generic_function


@claim("p81b-standard-leaf-casimirs", kind="pb", sizes=admissible(n_max=4))
def standard_leaf_casimirs(s):
    """The constraints XᵀX, XᵀP + PᵀX are Casimirs of the Dirac bracket (the same generic f as #1)."""
    C1, C2 = s.fresh("r", "r"), s.fresh("r", "r")
    f = generic_function(s)
    return {"{tr C1 X^T X, f}": s.bracket(lambda t: t.tr(C1 @ t.X.T @ t.X), f),
            "{tr C2 (X^T P + P^T X), f}": s.bracket(lambda t: t.tr(C2 @ (t.X.T @ t.P + t.P.T @ t.X)), f)}
