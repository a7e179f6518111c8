"""Class 1 (the chart chosen from the graph): the second point Y (and Q) of T*V beside X, in ranks "at every
point" and in residuals that a chart fixing both points would decide wrongly.

Truths: X, Y independent points of V(n, r).  XᵀY is an r×r matrix that is invertible for generic X, Y and
singular for some (r < n: Y's columns orthogonal to X's, e.g. n = 3, r = 1); at r = n XᵀY ∈ O(n), invertible.
sp-every-f:   Rank(XᵀY, r, generic=False) at r < n     FALSE
sp-gen-t:     Rank(XᵀY, r) generic                      TRUE
sp-eq-f:      XᵀY − I_r = 0                             FALSE
sp-sq-every:  Rank(XᵀY, n, generic=False) at r = n     TRUE  (undecided is honest)
sp-yty:       YᵀY − I_r = 0                             TRUE
sp-yq:        YᵀQ + QᵀY = 0                             TRUE ; sp-yq-f: YᵀQ − QᵀY = 0 FALSE
sp-xq-f:      XᵀQ + QᵀX = 0                             FALSE (Q is tangent at Y, not at X)
sp-proj-f:    Rank(XXᵀ − YYᵀ, 0) generic                FALSE (XXᵀ ≠ YYᵀ generically)
sp-proj-t:    Rank(XXᵀYYᵀ, r) generic (r < n)           TRUE
"""
from stiefelsym import Rank, admissible, claim

RC = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)
SQ = admissible(n_max=3, n_min=2, where=lambda n, r: r == n)


@claim("sp-every-f", kind="dim", sizes=RC)
def sp_every_f(s):
    return {"rank": Rank(s.X.T @ s.Y, s.r, generic=False)}


@claim("sp-gen-t", kind="dim", sizes=RC)
def sp_gen_t(s):
    return {"rank": Rank(s.X.T @ s.Y, s.r)}


@claim("sp-eq-f", kind="id", sizes=RC)
def sp_eq_f(s):
    return {"x": s.X.T @ s.Y - s.Ir}


@claim("sp-sq-every", kind="dim", sizes=SQ)
def sp_sq_every(s):
    return {"rank": Rank(s.X.T @ s.Y, s.n, generic=False)}


@claim("sp-yty", kind="id", sizes=RC)
def sp_yty(s):
    return {"x": s.Y.T @ s.Y - s.Ir}


@claim("sp-yq", kind="id", sizes=RC)
def sp_yq(s):
    return {"x": s.Y.T @ s.Q + s.Q.T @ s.Y}


@claim("sp-yq-f", kind="id", sizes=RC)
def sp_yq_f(s):
    return {"x": s.Y.T @ s.Q - s.Q.T @ s.Y}


@claim("sp-xq-f", kind="id", sizes=RC)
def sp_xq_f(s):
    return {"x": s.X.T @ s.Q + s.Q.T @ s.X}


@claim("sp-proj-f", kind="dim", sizes=RC)
def sp_proj_f(s):
    return {"rank": Rank(s.X @ s.X.T - s.Y @ s.Y.T, 0)}


@claim("sp-proj-t", kind="dim", sizes=RC)
def sp_proj_t(s):
    return {"rank": Rank(s.X @ s.X.T @ s.Y @ s.Y.T, s.r)}
