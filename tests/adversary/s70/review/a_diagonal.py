# ruff: noqa
"""Statements true only for a diagonal A, read through an entry of A, a constant matrix on ℝⁿ, an entry of X
beside A, a sum of entries, and a Rank.  The Cayley and unconstrained charts take A = diag(a) also for graphs
that read coordinates, while the equivariant chart takes A generic symmetric.
Verdict of this review: NOT a hole.  The project's convention is A = diag(a_1..a_n) (CLAIMS.md l.13, the
paper l.115, 852), so every claim here is true and `proved`/`checked`/`numeric` is right; a graph that reads no
coordinate of ℝⁿ is O(n)-covariant, so the two charts agree on it.  (Doc nit: the guide's table calls s.A "the
symmetric matrix A (diagonal at sampled points)", which reads as if A were a general symmetric matrix.)"""
from stiefelsym import Rank, admissible, claim, comm

S = admissible(n_min=2, n_max=3)
F = dict(fails_at=lambda n, r: True, erratum="false for a general symmetric A (true for the convention A = diag(a))")


@claim("s70-ad-entry", kind="id", sizes=S, **F)
def entry(s):
    """A₁₂ = 0 (false)."""
    return {"a12": s.A[0, 1]}


@claim("s70-ad-comm", kind="id", sizes=S, **F)
def comm_e11(s):
    """[A, E₁₁] = 0 with E₁₁ a constant matrix of ℝⁿ (false)."""
    n = int(s.n)
    E = s.mat([[1 if (i, j) == (0, 0) else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    return {"[A,E11]": comm(s.A, E)}


@claim("s70-ad-xentry", kind="id", sizes=S, **F)
def with_x_entry(s):
    """tr(A) X₁₁ − X₁₁ tr(A) + (AXXᵀ − XXᵀA) = 0 at r = n reads an entry (false: AXXᵀ = XXᵀA at r = n is true!)"""
    return {"a": s.X[0, 0] * s.tr(s.A) - s.tr(s.A) * s.X[0, 0] + s.tr(s.A @ s.X @ s.P.T - s.P @ s.X.T @ s.A) * 0 + s.A[0, 1] * s.X[0, 0]}


@claim("s70-ad-offdiag-sum", kind="id", sizes=S, **F)
def offdiag(s):
    """Σ_{i≠j} A_ij² = 0, i.e. tr(A²) = Σ A_ii² (false)."""
    n = int(s.n)
    return {"off": s.tr(s.A @ s.A) - sum(s.A[i, i] * s.A[i, i] for i in range(n))}


@claim("s70-ad-rank", kind="dim", sizes=S, **F)
def rank_comm(s):
    """The 1×1 matrix (A₁₂) has generic rank 0 (false: 1)."""
    return {"rk": Rank(s.mat([[s.A[0, 1]]]), 0)}
