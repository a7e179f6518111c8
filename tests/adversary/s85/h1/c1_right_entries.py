"""Class 1: entries on R^r (not R^n) read through blocks of r-typed spaces: the reading is no door to R^n, but a
chart reduced by O(r) on the right (X -> X h) would make some of them 0.

Truth (numpy in truth.py): at r = 2, (XᵀAX)[0,1], (PᵀP)[0,1], (XᵀP)[0,1] are generic nonzero numbers.
re-xax-f     (XᵀAX)[0,1] = 0                                 FALSE
re-blk-f     block([[XᵀAX, Ψ], [Ψ, PᵀP]])[0, 1] = 0          FALSE ((XᵀAX)[0,1])
re-blk2-f    the same block's entry [0, 3] = Ψ[0,1]          FALSE
re-blk3-f    block([[XᵀP], [PᵀX]])[1, 0] = 0 (the 2r×r block's (1,0) entry = (XᵀP)[1,0])   FALSE
re-sym-t     (XᵀAX)[0,1] − (XᵀAX)[1,0] = 0                   TRUE (control)
re-trc-t     Σ_i (PᵀP)[i,i] − tr(PᵀP) = 0                     TRUE (control)
"""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=4, r_min=2)


@claim("re-xax-f", kind="id", sizes=SZ)
def xax_f(s):
    return {"x": (s.X.T @ s.A @ s.X)[0, 1]}


@claim("re-blk-f", kind="id", sizes=SZ)
def blk_f(s):
    B = block([[s.X.T @ s.A @ s.X, s.Psi], [s.Psi, s.P.T @ s.P]])
    return {"x": B[0, 1]}


@claim("re-blk2-f", kind="id", sizes=SZ)
def blk2_f(s):
    B = block([[s.X.T @ s.A @ s.X, s.Psi], [s.Psi, s.P.T @ s.P]])
    return {"x": B[0, int(s.r) + 1]}


@claim("re-blk3-f", kind="id", sizes=SZ)
def blk3_f(s):
    B = block([[s.X.T @ s.P], [s.P.T @ s.X]])
    return {"x": B[1, 0]}


@claim("re-sym-t", kind="id", sizes=SZ)
def sym_t(s):
    M = s.X.T @ s.A @ s.X
    return {"x": M[0, 1] - M[1, 0]}


@claim("re-trc-t", kind="id", sizes=SZ)
def trc_t(s):
    M = s.P.T @ s.P
    tot = M[0, 0]
    for i in range(1, int(s.r)):
        tot = tot + M[i, i]
    return {"x": tot - s.tr(M)}
