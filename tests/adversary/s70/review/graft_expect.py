# ruff: noqa
"""Two claims with one graph (XᵀX − I_r): s70-ge-holds (true, expected to hold) and s70-ge-not
(kind "not", expect="nonzero": 'XᵀX − I_r does not vanish', false).  The free record of the first, a
`proved (all n, r)` with its certificate, is grafted onto the second (results edited by graft_expect_forge.py).
Honest: s70-ge-not is never `proved`; free answers undecided, the fixed-size methods `fails`.
`report` must refuse the grafted record (a certificate of vanishing is not one of non-vanishing)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3)


@claim("s70-ge-holds", kind="id", sizes=S)
def holds(s):
    """XᵀX = I_r."""
    return {"gram": s.X.T @ s.X - s.Ir}


@claim("s70-ge-not", kind="not", expect="nonzero", sizes=S)
def not_(s):
    """XᵀX − I_r does not vanish (false)."""
    return {"gram": s.X.T @ s.X - s.Ir}
