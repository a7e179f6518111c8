# ruff: noqa
"""A claims file's erratum (a formula of its own, false) citing the catalog's label LA3*D and registering a
correction with the very words of the catalog's correction of double-neumann-dual-lax: run together with
the catalog's claim, is the user's failure counted as the same misprint of the paper?"""
from stiefelsym import admissible, claim

WORDS = "(LA3*D): (λI_n − A)⁻¹ in place of (I_n − λA)⁻¹ in the off-diagonal blocks"


@claim("mine-la3d", paper=("LA3*D",), kind="id", sizes=admissible(n_max=2), fails_at=lambda n, r: True,
       erratum="my own formula, unrelated to the paper's Lax pair")
def mine(s):
    """tr(XᵀX) = r + 1 (false)."""
    return {"tr": (s.X.T @ s.X).trace() - s.r - 1}


@mine.claim.correction(WORDS)
def mine_corrected(s):
    return {"tr": (s.X.T @ s.X).trace() - s.r}
