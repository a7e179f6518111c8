"""Class 1: entries read through a block with the n−r coordinate space (the chart choice).

M = block([[I_r], [B]]) with B = s.generic("B", "n-r", "r"): an n×r matrix whose first r rows are I_r.
c1-nr-false: Xᵀ M = I_r.  At X₀ = (E₁…E_r) it holds (X₀ᵀM = I_r), but for a general X ∈ V(n, r) XᵀM = X₁ᵀ + X₂ᵀB
   ≠ I_r: FALSE (e.g. X = (E₂, E₃) at (3,2): XᵀM = (0 1; 0 0)+… ).
c1-nr-true: Mᵀ M − I_r − BᵀB = 0: TRUE (MᵀM = I_r + BᵀB).
c1-nr-xxt-false: (I_n − X Xᵀ) M = 0: at X₀ it is (0; B) ≠ 0 anyway: FALSE, must fail.
c1-nr-sym-false: Xᵀ S X with S = block([[I_r, 0],[0, 0_{n-r}]]) (a projector on the first r coordinates):
   XᵀSX = I_r holds at X₀ only: FALSE.
"""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=3, n_min=3, r_max=2, where=lambda n, r: r < n)


def _M(s):
    B = s.generic("B", "n-r", "r")
    return block([[s.Ir], [B]]), B


@claim("c1-nr-false", kind="id", sizes=SZ)
def c1_nr_false(s):
    M, _ = _M(s)
    return {"r": s.X.T @ M - s.Ir}


@claim("c1-nr-true", kind="id", sizes=SZ)
def c1_nr_true(s):
    M, B = _M(s)
    return {"r": M.T @ M - s.Ir - B.T @ B}


@claim("c1-nr-xxt-false", kind="id", sizes=SZ)
def c1_nr_xxt_false(s):
    M, _ = _M(s)
    return {"r": (s.In - s.X @ s.X.T) @ M}


@claim("c1-nr-sym-false", kind="id", sizes=SZ)
def c1_nr_sym_false(s):
    Z1 = s.zeros(s.r, s.n - s.r, ("r", "n-r"))
    Z2 = s.zeros(s.n - s.r, s.n - s.r, ("n-r", "n-r"))
    S = block([[s.Ir, Z1], [Z1.T, Z2]])
    return {"r": s.X.T @ S @ s.X - s.Ir}
