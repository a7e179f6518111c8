# ruff: noqa
"""Records shared across r (a graph in A alone is run once per n, at the least r) whose claims declare an
erratum at some r only.  Honest: s70-sf-false (tr(A)² = tr(A²), false for n >= 2) fails at every (n, r),
expected only at r = 2; s70-sf-true (tr(A²) = tr(A·A), true) is proved at every size, UNEXPECTED at r = 2
where it declares an erratum; the report must list the erratum sizes right and never call r = 1 expected."""
from stiefelsym import admissible, claim

S = admissible(n_min=2, n_max=3)


@claim("s70-sf-false", kind="id", sizes=S, fails_at=lambda n, r: r == 2, erratum="false at r = 2 (declared)")
def false_(s):
    """tr(A)² = tr(A²)."""
    return {"t": s.tr(s.A) * s.tr(s.A) - s.tr(s.A @ s.A)}


@claim("s70-sf-true", kind="id", sizes=S, fails_at=lambda n, r: r == 2, erratum="declared false at r = 2 (wrongly)")
def true_(s):
    """tr(A²) = tr(A·A)."""
    return {"t": s.tr(s.A @ s.A) - s.tr(s.A.T @ s.A)}
