# ruff: noqa
"""An `error` verdict (a claim that divides by an identically zero expression): its record's `expected`,
`erratum` and `place` hand-edited, against `check` and `report`."""
from stiefelsym import admissible, claim


@claim("ee-div0", kind="id", sizes=admissible(n_max=3, r_min=2))
def ee_div0(s):
    """(X^T X - I)/tr(X^T P + P^T X): undefined on T*V."""
    return {"q": (s.X.T @ s.X - s.Ir) / s.tr(s.X.T @ s.P + s.P.T @ s.X)}
