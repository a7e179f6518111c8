# ruff: noqa
"""Claims beyond their symbolic budget (exact_max_n=1) that the modular method cannot decide on purpose, so that
auto tries exact after all.  Truth: truth.py (numpy / sympy).
Run: stiefelsym verify --claims late_exact.py --size 4,2 --size 3,3 --method auto --jobs 1 --no-report"""
from stiefelsym import Count, Rank, admissible, claim

SIZES = admissible(n_max=4)


@claim("r3-late-rank-low", kind="dim", sizes=SIZES, exact_max_n=1)
def rank_low(s):
    """rank X Xᵀ = r + 1 (false: it is r): modular finds r at every point (inconclusive)."""
    return {"rk": Rank(s.X @ s.X.T, int(s.r) + 1)}


@claim("r3-late-every-point", kind="dim", sizes=SIZES, exact_max_n=1)
def every_point(s):
    """rank X = r at every point (true: XᵀX = I_r): modular leaves it undecided."""
    return {"rk": Rank(s.X, int(s.r), generic=False)}


@claim("r3-late-every-point-false", kind="dim", sizes=SIZES, exact_max_n=1)
def every_point_false(s):
    """rank (X + P) = r at every point (false for r >= 1 somewhere? X + P has XᵀX = I, generic rank r; at a point
    with P = -X... not tangent unless X = 0: P tangent means XᵀP skew; P = -X gives XᵀP = -I, not skew: so rank r
    everywhere? (X+P)ᵀX = I + PᵀX, with PᵀX skew: I + skew is invertible, so rank r at every point: TRUE)."""
    return {"rk": Rank(s.X + s.P, int(s.r), generic=False)}


@claim("r3-late-every-point-false2", kind="dim", sizes=SIZES, exact_max_n=1)
def every_point_false2(s):
    """rank P = r at every point (false: P = 0 is a point of T*V)."""
    return {"rk": Rank(s.P, int(s.r), generic=False)}


@claim("r3-late-nonzero-false", kind="id", sizes=SIZES, exact_max_n=1, expect="nonzero")
def nonzero_false(s):
    """tr(XᵀX) − r is nonzero (false: it vanishes on V)."""
    return {"x": s.tr(s.X.T @ s.X) - int(s.r)}
