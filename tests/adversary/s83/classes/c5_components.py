"""Classes 1/5 (chart choice; a rank's undecided paths): ranks and residuals that differ between the components
of T*V at r = n (O(n) = SO(n) ∪ O⁻(n)), and ranks "at every point" that drop at special points.

Truths (by hand; numpy check in c5_truth.py.in):
At r = n, X ∈ O(n), det X = ±1, both signs occur (two components).  Y ∈ O(n) a second point, independent.
  d = det(XᵀY) = ±1, all four sign combinations of (det X, det Y) occur, d = −1 on half of T*V × T*V.
comp-det2: (det(XᵀY))² − 1 = 0                                        TRUE  (d = ±1)
comp-det1: det(XᵀY) − 1 = 0                                           FALSE (d = −1 on two of four components)
comp-rank-n:  Rank((d − 1)·I_r, r) generic                          FALSE (rank 0 wherever d = 1: a whole component)
comp-rank-0:  Rank((d − 1)·I_r, 0) generic                          FALSE (rank r wherever d = −1)
comp-rank-sq0: Rank((d² − 1)·I_r, 0) generic                        TRUE  (the zero matrix)
comp-rank-sqr: Rank((d² − 1)·I_r + I_r, r, generic=False)           TRUE  (= I_r at every point)
every-xtp:   Rank(XᵀP, r, generic=False)  (r < n)                    FALSE (P = 0 is a point of T*V: rank 0 there)
every-xtp-g: Rank(XᵀP + PᵀX + Ψ, r, generic=True) (= 2XᵀP on T*V... no: XᵀP + PᵀX = 0 on T*V, so the matrix is
             Ψ = XᵀP − PᵀX = 2XᵀP, a generic r×r matrix of rank r when r is even; r = 2 here) TRUE at (3,2)
every-ipsi:  Rank(I_r + ΨᵀΨ, r, generic=False)                       TRUE  (positive definite) -- undecided is honest
every-ipsi-f: Rank(I_r + ΨᵀΨ, r − 1, generic=False)                  FALSE
"""
from stiefelsym import Rank, admissible, claim, det

SQ = admissible(n_max=3, n_min=2, where=lambda n, r: r == n)
RC = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


def _d(s):
    return det(s, s.X.T @ s.Y)


@claim("comp-det2", kind="id", sizes=SQ)
def comp_det2(s):
    d = _d(s)
    return {"d2": d * d - 1}


@claim("comp-det1", kind="id", sizes=SQ)
def comp_det1(s):
    return {"d": _d(s) - 1}


@claim("comp-rank-n", kind="dim", sizes=SQ)
def comp_rank_n(s):
    return {"rank": Rank((_d(s) - 1) * s.Ir, s.r)}


@claim("comp-rank-0", kind="dim", sizes=SQ)
def comp_rank_0(s):
    return {"rank": Rank((_d(s) - 1) * s.Ir, 0)}


@claim("comp-rank-sq0", kind="dim", sizes=SQ)
def comp_rank_sq0(s):
    d = _d(s)
    return {"rank": Rank((d * d - 1) * s.Ir, 0)}


@claim("comp-rank-sqr", kind="dim", sizes=SQ)
def comp_rank_sqr(s):
    d = _d(s)
    return {"rank": Rank((d * d - 1) * s.Ir + s.Ir, s.r, generic=False)}


@claim("every-xtp", kind="dim", sizes=RC)
def every_xtp(s):
    return {"rank": Rank(s.X.T @ s.P, s.r, generic=False)}


@claim("every-xtp-g", kind="dim", sizes=RC)
def every_xtp_g(s):
    return {"rank": Rank(s.X.T @ s.P + s.P.T @ s.X + s.Psi, 2)}


@claim("every-ipsi", kind="dim", sizes=RC)
def every_ipsi(s):
    return {"rank": Rank(s.Ir + s.Psi.T @ s.Psi, s.r, generic=False)}


@claim("every-ipsi-f", kind="dim", sizes=RC)
def every_ipsi_f(s):
    return {"rank": Rank(s.Ir + s.Psi.T @ s.Psi, s.r - 1, generic=False)}


@claim("comp-detx", kind="id", sizes=SQ)
def comp_detx(s):
    """det X − 1 = 0 at r = n: FALSE (det X = −1 on O⁻(n)); det(s, X) may be refused (X maps R^r to R^n)."""
    return {"d": det(s, s.X) - 1}


@claim("comp-detx2", kind="id", sizes=SQ)
def comp_detx2(s):
    """(det X)² − 1 = 0 at r = n: TRUE."""
    d = det(s, s.X)
    return {"d": d * d - 1}


@claim("comp-rank-plus", kind="dim", sizes=SQ)
def comp_rank_plus(s):
    """Rank((1 + det XᵀY)·I_r, r) generic: FALSE (rank 0 where det XᵀY = −1, half of the components)."""
    return {"rank": Rank((1 + _d(s)) * s.Ir, s.r)}


@claim("comp-xinv", kind="id", sizes=SQ)
def comp_xinv(s):
    """X⁻¹ − Xᵀ = 0 at r = n: TRUE (X orthogonal); X.inv() of an n×n point."""
    return {"x": s.X.inv() - s.X.T}
