# ruff: noqa
"""A claim whose erratum sizes (fails_at) raise at (3,2): `report` skips its binding of the erratum there."""
from stiefelsym import admissible, claim


def _fails_at(n, r):
    if (n, r) == (3, 2):
        raise RuntimeError("no answer here")
    return r >= 2


@claim("pl-raise", kind="id", sizes=admissible(n_max=3, r_min=2),
       erratum="X^T P is skew, not zero", fails_at=_fails_at)
def pl_raise(s):
    """X^T P = 0 (false at r >= 2)."""
    return {"XtP": s.X.T @ s.P}
