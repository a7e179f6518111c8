"""Class 5 under hard cases (--hard): residuals that are tiny exactly where the hard case puts its point.

 h-spread-false:  n·tr(A²) − (tr A)² = 0: FALSE (= Σ_{i<j} (a_i − a_j)², 0 only if all a_i are equal; near-equal-a
                  makes it ≈ 1e-24 at the 1e-12 case).
 h-spread-true:   n·tr(A²) − (tr A)² − Σ_{i<j}(a_i − a_j)² written as ½·tr of the commutator square... TRUE twin:
                  tr(A²) − tr(A·A) = 0.
 h-comm-false:    [A, XXᵀ] = 0: FALSE (≈ (a_i − a_j)·… small under near-equal-a).
 h-pp-false:      tr(PᵀP)·ε-free: tr(PᵀP) − tr(PᵀP)(1 + 2^-60)... written 2^60·tr(PᵀP) − (2^60 + 1)·tr(PᵀP) = 0: FALSE
                  (= −tr PᵀP; absorbed in float when tr PᵀP is small? huge-momenta makes it large).
 h-pp-true:       2^60·tr(PᵀP) − (2^60 + 1)·tr(PᵀP) + tr(PᵀP) = 0: TRUE.
"""
from stiefelsym import admissible, claim, comm

SZ = admissible(n_max=3, n_min=2)


@claim("h-spread-false", kind="id", sizes=SZ)
def spread_false(s):
    return {"spread": s.tr(s.In) * s.tr(s.A @ s.A) - s.tr(s.A) * s.tr(s.A)}


@claim("h-spread-true", kind="id", sizes=SZ)
def spread_true(s):
    return {"0": s.tr(s.A @ s.A) - s.tr(s.A.T @ s.A)}


@claim("h-comm-false", kind="id", sizes=SZ)
def comm_false(s):
    return {"[A, XXt]": comm(s.A, s.X @ s.X.T)}


@claim("h-pp-false", kind="id", sizes=SZ)
def pp_false(s):
    t = s.tr(s.P.T @ s.P)
    return {"pp": t * 2 ** 60 - t * (2 ** 60 + 1)}


@claim("h-pp-true", kind="id", sizes=SZ)
def pp_true(s):
    t = s.tr(s.P.T @ s.P)
    return {"pp": t * 2 ** 60 - t * (2 ** 60 + 1) + t}
