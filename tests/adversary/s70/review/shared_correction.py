# ruff: noqa
"""A claim in A alone (shared across r) that fails as printed, with two corrections: one true, one false,
and one with expect="nonzero" whose statement is true (tr(A²) − tr(A)² is not identically 0 for n >= 2).
Honest: printed fails everywhere (expected); "true" correction proved/checked at every size; "false"
correction fails; the nonzero correction proved (exact/modular), `undecided` under free."""
from stiefelsym import admissible, claim

S = admissible(n_min=2, n_max=4)


@claim("s70-sc", kind="id", sizes=S, fails_at=lambda n, r: True, erratum="printed with the square outside")
def printed(s):
    """tr(A)² = tr(A²)."""
    return {"t": s.tr(s.A) * s.tr(s.A) - s.tr(s.A @ s.A)}


@printed.claim.correction("tr(A²) = tr(AᵀA)")
def corr_true(s):
    return {"t": s.tr(s.A @ s.A) - s.tr(s.A.T @ s.A)}


@printed.claim.correction("tr(A)² = 2 tr(A²) (false)")
def corr_false(s):
    return {"t": s.tr(s.A) * s.tr(s.A) - 2 * s.tr(s.A @ s.A)}


@printed.claim.correction("tr(A)² − tr(A²) does not vanish", expect="nonzero")
def corr_nonzero(s):
    return {"t": s.tr(s.A) * s.tr(s.A) - s.tr(s.A @ s.A)}
