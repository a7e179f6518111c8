"""Round 16: a claim that expects its checks NOT to vanish (expect="nonzero") with a rank or a count beside its
residual.  The methods decided such a claim by its residuals alone (one nonzero entry: `proved`), so the rank or
count beside it was never looked at: "XᵀAP does not vanish, and 2 = 3" was proved by exact, modular, rational and
auto, and with a rank above the matrix's full size by ball too.  A rank or a count holds or not; it does not
vanish: such a claim is refused (error).  Controls: residuals only, one nonvanishing (proved), one vanishing on
T*V (fails)."""
from stiefelsym import Count, Rank, admissible, claim

SIZES = admissible(n_max=3, n_min=2, r_min=2)


@claim("adv-s42-nonzero-wrong-count", paper="adv", kind="id", sizes=SIZES, expect="nonzero")
def nonzero_wrong_count(s):
    """XᵀAP does not vanish, and 2 = 3 (false)."""
    return {"XtAP": s.X.T @ s.A @ s.P, "count": Count(2, 3)}


@claim("adv-s42-nonzero-rank-above-full", paper="adv", kind="id", sizes=SIZES, expect="nonzero")
def nonzero_rank_above_full(s):
    """XᵀAP does not vanish, and XᵀX (r x r) has rank r + 1 at every point (false: no r x r matrix does)."""
    return {"XtAP": s.X.T @ s.A @ s.P, "rank": Rank(s.X.T @ s.X, s.r + 1, generic=False)}


@claim("adv-s42-nonzero-wrong-generic-rank", paper="adv", kind="id", sizes=SIZES, expect="nonzero")
def nonzero_wrong_generic_rank(s):
    """XᵀAP does not vanish, and XᵀP + PᵀX has generic rank r (false: it is 0 on T*V)."""
    return {"XtAP": s.X.T @ s.A @ s.P, "rank": Rank(s.X.T @ s.P + s.P.T @ s.X, s.r, generic=True)}


@claim("adv-s42-nonzero-only-residuals", paper="adv", kind="id", sizes=SIZES, expect="nonzero")
def nonzero_only_residuals(s):
    """Control: XᵀAP does not vanish (true)."""
    return {"XtAP": s.X.T @ s.A @ s.P}


@claim("adv-s42-nonzero-vanishing", paper="adv", kind="id", sizes=SIZES, expect="nonzero")
def nonzero_vanishing(s):
    """Control: XᵀP + PᵀX does not vanish (false: it is a constraint of T*V)."""
    return {"XtP": s.X.T @ s.P + s.P.T @ s.X}


@claim("adv-s42-nonzero-rank-alone", paper="adv", kind="dim", sizes=SIZES, expect="nonzero")
def nonzero_rank_alone(s):
    """A rank alone, expected not to vanish: XᵀP + PᵀX has generic rank r (false).  Before: `fails` under every
    fixed-size method whatever the rank (no residual: "vanished ... probability <= 0")."""
    return {"rank": Rank(s.X.T @ s.P + s.P.T @ s.X, s.r, generic=True)}
