"""Class 5 (the error model / rounding of a value) and class 3: Count statements whose value is a scalar of the
scene (it depends on the point), compared "exactly" by each method, including float and ball, where the value is
computed in floating point or as a ball.

Truths at (3,2), on T*V (X ∈ V(3,2), XᵀP + PᵀX = 0):
cnt-z:      Count(tr(XᵀX) − tr(I_r), 0)                       TRUE  (tr XᵀX = r on V)
cnt-z-f:    Count(tr(XᵀX) − tr(I_r), 1)                       FALSE
cnt-tr:     Count(tr(XᵀX), 2)                                  TRUE
cnt-tr-f:   Count(tr(XᵀX), 3)                                  FALSE
cnt-ratio:  Count(tr(PᵀP)·tr(PᵀP)⁻¹ ... written (tr PᵀP)/(tr PᵀP), 1)   TRUE where P ≠ 0 (the count is a value at
            almost every point; 0/0 at P = 0): proved/checked/numeric or error, never fails
cnt-ratio-f: the same against 2                                 FALSE
cnt-xx:     Count(tr((XXᵀ)²) − tr(XXᵀ), 0)                     TRUE  (XXᵀ is a projector of rank r)
cnt-xx-f:   Count(tr((XXᵀ)²), 3)                               FALSE (= 2)
cnt-pt:     Count(tr(XᵀP), 0)                                  TRUE  (XᵀP skew on T*V)
cnt-pp:     Count(tr(PᵀP), 0)                                  FALSE (P ≠ 0 generically)
cnt-big:    Count(2⁶⁰·(tr(XᵀX) − tr(I_r)) + 1, 1)             TRUE  (float: 2⁶⁰ times the rounding of tr XᵀX − 2)
cnt-big-f:  Count(2⁶⁰·(tr(XᵀX) − tr(I_r)) + 1, 2)             FALSE
"""
from stiefelsym import Count, admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)


def _z(s):
    return s.tr(s.X.T @ s.X) - s.tr(s.Ir)


@claim("cnt-z", kind="dim", sizes=SZ)
def cnt_z(s):
    return {"k": Count(_z(s), 0)}


@claim("cnt-z-f", kind="dim", sizes=SZ)
def cnt_z_f(s):
    return {"k": Count(_z(s), 1)}


@claim("cnt-tr", kind="dim", sizes=SZ)
def cnt_tr(s):
    return {"k": Count(s.tr(s.X.T @ s.X), 2)}


@claim("cnt-tr-f", kind="dim", sizes=SZ)
def cnt_tr_f(s):
    return {"k": Count(s.tr(s.X.T @ s.X), 3)}


@claim("cnt-ratio", kind="dim", sizes=SZ)
def cnt_ratio(s):
    t = s.tr(s.P.T @ s.P)
    return {"k": Count(t / t, 1)}


@claim("cnt-ratio-f", kind="dim", sizes=SZ)
def cnt_ratio_f(s):
    t = s.tr(s.P.T @ s.P)
    return {"k": Count(t / t, 2)}


@claim("cnt-xx", kind="dim", sizes=SZ)
def cnt_xx(s):
    Q = s.X @ s.X.T
    return {"k": Count(s.tr(Q @ Q) - s.tr(Q), 0)}


@claim("cnt-xx-f", kind="dim", sizes=SZ)
def cnt_xx_f(s):
    Q = s.X @ s.X.T
    return {"k": Count(s.tr(Q @ Q), 3)}


@claim("cnt-pt", kind="dim", sizes=SZ)
def cnt_pt(s):
    return {"k": Count(s.tr(s.X.T @ s.P), 0)}


@claim("cnt-pp", kind="dim", sizes=SZ)
def cnt_pp(s):
    return {"k": Count(s.tr(s.P.T @ s.P), 0)}


@claim("cnt-big", kind="dim", sizes=SZ)
def cnt_big(s):
    return {"k": Count(2**60 * _z(s) + 1, 1)}


@claim("cnt-big-f", kind="dim", sizes=SZ)
def cnt_big_f(s):
    return {"k": Count(2**60 * _z(s) + 1, 2)}
