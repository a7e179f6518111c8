"""Class 3 (exceptions and what a trace shows as a side channel): branches on a size's door caught by the claim,
on the identity and hash of the size objects, on repr/str of a size, on refusals of Rank.

Truths: XᵀX = I_r TRUE at every (n, r); XXᵀ = I_n TRUE iff r = n; tr(XXᵀ) = r.
br-door-catch:   try int(s.n) (the door); if it raised: XᵀX − I_r (TRUE), else at n = 3: XXᵀ − I_n (FALSE at (3,2)),
                 else XᵀX − I_r.  The claim's code at (3,2) states XXᵀ = I_n: fails (or error), never proved.
br-door-catch-t: the same with the TRUE statement at n = 3 (tr(XXᵀ) − tr(I_r)): proved/checked/numeric.
br-is:           `s.n is s.r` (no door can see `is`): True -> XXᵀ − I_n, else XᵀX − I_r; stated on r = n only
                 (XXᵀ = I_n TRUE there): TRUE either way at r = n.  br-is-f: the branch picks XXᵀ − I_n when
                 `s.n is not s.r`, stated at r < n: FALSE if that branch is taken at (3,2).
br-hash:         hash(s.n) == hash(s.r) picks XXᵀ − I_n (FALSE at (3,2)) else XᵀX − I_r
br-repr:         repr(s.n) == "3" picks XXᵀ − I_n (FALSE at (3,2)) else XᵀX − I_r
br-rank-exc:     Rank(s.X, -1) refused? on refusal: XXᵀ − I_n (FALSE at (3,2)); else its own statement
br-bool-dim:     bool(s.r) (a size's truth value) picks XXᵀ − I_n (FALSE) when false
"""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3, n_min=3, where=lambda n, r: r == 2)
SQ = admissible(n_max=3, n_min=2, where=lambda n, r: r == n)


def _t(s):
    return {"x": s.X.T @ s.X - s.Ir}


def _f(s):
    return {"x": s.X @ s.X.T - s.In}


@claim("br-door-catch", kind="id", sizes=SZ)
def br_door_catch(s):
    try:
        k = int(s.n)
    except Exception:
        return _t(s)
    return _f(s) if k == 3 else _t(s)


@claim("br-door-catch-t", kind="id", sizes=SZ)
def br_door_catch_t(s):
    try:
        k = int(s.n)
    except Exception:
        return _t(s)
    return {"x": s.tr(s.X @ s.X.T) - s.tr(s.Ir)} if k == 3 else _t(s)


@claim("br-is", kind="id", sizes=SQ)
def br_is(s):
    return _f(s) if s.n is s.r else _t(s)


@claim("br-is-f", kind="id", sizes=SZ)
def br_is_f(s):
    return _t(s) if s.n is s.r else _f(s)


@claim("br-hash", kind="id", sizes=SZ)
def br_hash(s):
    try:
        same = hash(s.n) == hash(s.r)
    except Exception:
        same = False
    return _f(s) if same else _t(s)


@claim("br-repr", kind="id", sizes=SZ)
def br_repr(s):
    try:
        three = repr(s.n) == "3" or str(s.n) == "3"
    except Exception:
        three = False
    return _f(s) if three else _t(s)


@claim("br-rank-exc", kind="dim", sizes=SZ)
def br_rank_exc(s):
    try:
        R = Rank(s.X, -1)
    except Exception:
        return _f(s)
    return {"rank": R}


@claim("br-bool-dim", kind="id", sizes=SZ)
def br_bool_dim(s):
    try:
        b = bool(s.r)
    except Exception:
        b = True
    return _t(s) if b else _f(s)


@claim("br-is-sq", kind="id", sizes=SQ)
def br_is_sq(s):
    """At r = n: `s.n is s.r` picks XXᵀ − 2·I_n (FALSE: XXᵀ = I_n), else XᵀX − I_r (TRUE).  Whichever object the
    trace hands for the sizes, the verdict must be the one of the branch the code takes at that size."""
    return {"x": s.X @ s.X.T - 2 * s.In} if s.n is s.r else _t(s)


@claim("br-eq-sq", kind="id", sizes=SQ)
def br_eq_sq(s):
    """At r = n: `s.n == s.r` (a size's comparison) picks XXᵀ − 2·I_n (FALSE), else XᵀX − I_r."""
    try:
        same = bool(s.n == s.r)
    except Exception:
        same = False
    return {"x": s.X @ s.X.T - 2 * s.In} if same else _t(s)
