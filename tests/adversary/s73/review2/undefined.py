# ruff: noqa
"""Stop 73, second review: statements that are undefined on T*V (a division by a function that vanishes
identically there), which the early rational point must not refute with a witness: each should be an `error`
(the division probe) or at worst inconclusive, never `fails` with a witness nor a pass."""
from stiefelsym import admissible, claim

SIZES = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")


@claim("rv2-undefined-scalar", paper="cond_XP", kind="id", sizes=SIZES)
def undefined_scalar(s):
    """Undefined: (tr XᵀX − r)/(tr XᵀX − r) − 1 (0/0 on V)."""
    d = s.tr(s.X.T @ s.X) - s.r
    return {"0/0 - 1": d / d - 1}


@claim("rv2-undefined-matrix", paper="cond_XP", kind="id", sizes=SIZES)
def undefined_matrix(s):
    """Undefined: (Iₙ − XXᵀ)⁻¹(Iₙ − XXᵀ) − Iₙ (Iₙ − XXᵀ is a projector of rank n − r ≥ 1... singular at r < n? no:
    it is singular for r ≥ 1)."""
    M = s.In - s.X @ s.X.T
    return {"M^-1 M - I": M.inv() @ M - s.In}


@claim("rv2-undefined-resolvent", paper="cond_XP", kind="id", sizes=SIZES)
def undefined_resolvent(s):
    """Undefined: the resolvent at the eigenvalue a₁ (reads a coordinate), times (a₁I − A), minus I."""
    mu = s.a[0]
    return {"R(a1)(a1 - A) - I": s.resolvent(mu) @ (s.In * mu - s.A) - s.In}


@claim("rv2-undefined-xtp", paper="cond_XP", kind="id", sizes=SIZES)
def undefined_xtp(s):
    """Undefined: 1/tr(XᵀP) (tr XᵀP = 0 on T*V: XᵀP is skew), times tr(XᵀP), minus 1."""
    d = s.tr(s.X.T @ s.P)
    return {"d/d - 1": d / d - 1}
