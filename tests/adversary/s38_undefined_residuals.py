"""Round 8: residuals undefined at a stated size (a division by a constant that is 0 there: tr C of the second
block projector of ℝʳ, tr(E<rᵀE<r) = r − 1 at r = 1).  The exact method's symbolic arithmetic turns 1/0 into an
infinity (1/0 · 0 = nan) and called nan "a nonzero function on the chart": `fails` with no witness, where every
sampled method is inconclusive and a division probe answers error; a matrix [[nan]] "has rank 1" over the function
field, [[1/(1/0)]] rank 0."""
from stiefelsym import Rank, admissible, claim
from stiefelsym import twisted

R1 = admissible(n_min=3, n_max=3, r_min=1, r_max=1)


@claim("adv-s38-nan-times-zero", kind="id", sizes=R1)
def nan_times_zero(s):
    """(1/c)·(tr XᵀX − 1) = 0 with c = tr C = 0 at r = 1: undefined (1/0 · 0)."""
    c = s.tr(twisted.block_projector(s, 1))
    return {"d": (1 / c) * (s.tr(s.X.T @ s.X) - 1)}


@claim("adv-s38-nan-quotient", kind="id", sizes=R1)
def nan_quotient(s):
    """c·(1/c) = 1 with c = tr C = 0 at r = 1: undefined."""
    c = s.tr(twisted.block_projector(s, 1))
    return {"d": c * (1 / c) - 1}


@claim("adv-s38-nan-nonzero", kind="id", sizes=R1, expect="nonzero")
def nan_nonzero(s):
    """c·(1/c) − 1 is not identically zero (c = tr C = 0 at r = 1: undefined, never nonzero)."""
    c = s.tr(twisted.block_projector(s, 1))
    return {"d": c * (1 / c) - 1}


@claim("adv-s38-zero-of-infinity", kind="id", sizes=R1, expect="nonzero")
def zero_of_infinity(s):
    """1/(1/c) + tr(XᵀX) − 1 is nonzero (c = tr C = 0 at r = 1: 1/(1/0) is no 0)."""
    c = s.tr(twisted.block_projector(s, 1))
    return {"d": 1 / (1 / c) + (s.tr(s.X.T @ s.X) - 1)}


@claim("adv-s38-rank-of-nan", kind="dim", sizes=R1)
def rank_of_nan(s):
    """[[(1/c)·(tr XᵀX − 1)]] has rank 0 (c = tr C = 0 at r = 1: undefined, not rank 1)."""
    c = s.tr(twisted.block_projector(s, 1))
    return {"r": Rank(s.mat([[(1 / c) * (s.tr(s.X.T @ s.X) - 1)]]), 0)}


@claim("adv-s38-rank-of-infinity", kind="dim", sizes=R1)
def rank_of_infinity(s):
    """[[1/(1/c)]] has rank 1 (c = tr C = 0 at r = 1: undefined, not rank 0)."""
    c = s.tr(twisted.block_projector(s, 1))
    return {"r": Rank(s.mat([[1 / (1 / c)]]), 1)}


@claim("adv-s38-defined-false", kind="id", sizes=R1)
def defined_false(s):
    """c'·(1/c') = 2 with c' = tr D = 1 at r = 1 (false and defined: a control that must still fail)."""
    c = s.tr(twisted.block_projector(s, 0))
    return {"d": c * (1 / c) - 2}
