"""Classes 5/7: the exact method beyond its symbolic budget on purpose (a generic 4×4 inverse: symbolic solves
larger than 3×3 with non-numeric pivots are not attempted), and what `exact` (its rational-point decisions,
`_decided_at_points`) and `auto` (the modular fallback, the dimension-free proof specialised) record then.

G = a generic 4×4 matrix of the claim's own (s.generic, on R^n at n = 4), H = U·V with U 4×3, V 3×4 generic: rank 3.
At (4,2):
ab-inv-t:       G⁻¹G − I_n = 0                           TRUE
ab-rank-full:   Rank(G⁻¹, 4)                              TRUE  (full)
ab-rank-full-f: Rank(G⁻¹H, 4)                             FALSE (rank 3)
ab-rank-lo-t:   Rank(G⁻¹H, 3)                             TRUE
ab-rank-lo-f:   Rank(G⁻¹H, 2)                             FALSE (3 > 2)
ab-nz-t:        tr(G⁻¹G) does not vanish (expect nonzero) TRUE (= 4)
ab-nz-f:        G⁻¹G − I_n does not vanish                FALSE (it vanishes)
ab-every-f:     Rank(G⁻¹H + H, 3, generic=False)          FALSE (H = 0 is not a point of this claim: U, V generic
                parameters; but G⁻¹H + H = (G⁻¹ + I)H has rank < 3 where U = 0: a point of the parameters)
ab-cnt-t:       {Rank(G⁻¹, 4), Count(4, 4)}               TRUE
ab-cnt-f:       {Rank(G⁻¹, 4), Count(4, 5)}               FALSE
ab-budget-t:    XᵀX − I_r with exact_max_n=1 (auto: beyond the budget at n = 4)   TRUE
ab-budget-f:    tr(XXᵀ) − tr(I_n) with exact_max_n=1                                FALSE (r ≠ n)
ab-budget-rk:   Rank(XᵀX, 2) with exact_max_n=1 (auto: modular's full-rank proof)  TRUE
ab-budget-rkf:  Rank(XXᵀ, 3) with exact_max_n=1                                      FALSE (rank 2)
"""
from stiefelsym import Count, Rank, admissible, claim

SZ = admissible(n_max=4, n_min=4, where=lambda n, r: r == 2)


def _g(s):
    return s.generic("G", "n", "n")


def _h(s):
    return s.generic("U", "n", "?3") @ s.generic("V", "?3", "n") if False else \
        s.general_params("U", 4, 3, ("n", "?")) @ s.general_params("V", 3, 4, ("?", "n"))


@claim("ab-inv-t", kind="id", sizes=SZ)
def ab_inv_t(s):
    G = _g(s)
    return {"x": G.inv() @ G - s.In}


@claim("ab-rank-full", kind="dim", sizes=SZ)
def ab_rank_full(s):
    return {"rank": Rank(_g(s).inv(), 4)}


@claim("ab-rank-full-f", kind="dim", sizes=SZ)
def ab_rank_full_f(s):
    return {"rank": Rank(_g(s).inv() @ _h(s), 4)}


@claim("ab-rank-lo-t", kind="dim", sizes=SZ)
def ab_rank_lo_t(s):
    return {"rank": Rank(_g(s).inv() @ _h(s), 3)}


@claim("ab-rank-lo-f", kind="dim", sizes=SZ)
def ab_rank_lo_f(s):
    return {"rank": Rank(_g(s).inv() @ _h(s), 2)}


@claim("ab-nz-t", kind="not", sizes=SZ, expect="nonzero")
def ab_nz_t(s):
    G = _g(s)
    return {"x": s.tr(G.inv() @ G)}


@claim("ab-nz-f", kind="not", sizes=SZ, expect="nonzero")
def ab_nz_f(s):
    G = _g(s)
    return {"x": G.inv() @ G - s.In}


@claim("ab-every-f", kind="dim", sizes=SZ)
def ab_every_f(s):
    H = _h(s)
    return {"rank": Rank(_g(s).inv() @ H + H, 3, generic=False)}


@claim("ab-cnt-t", kind="dim", sizes=SZ)
def ab_cnt_t(s):
    return {"rank": Rank(_g(s).inv(), 4), "k": Count(4, 4)}


@claim("ab-cnt-f", kind="dim", sizes=SZ)
def ab_cnt_f(s):
    return {"rank": Rank(_g(s).inv(), 4), "k": Count(4, 5)}


@claim("ab-budget-t", kind="id", sizes=SZ, exact_max_n=1)
def ab_budget_t(s):
    return {"x": s.X.T @ s.X - s.Ir}


@claim("ab-budget-f", kind="id", sizes=SZ, exact_max_n=1)
def ab_budget_f(s):
    return {"x": s.tr(s.X @ s.X.T) - s.tr(s.In)}


@claim("ab-budget-rk", kind="dim", sizes=SZ, exact_max_n=1)
def ab_budget_rk(s):
    return {"rank": Rank(s.X.T @ s.X, 2)}


@claim("ab-budget-rkf", kind="dim", sizes=SZ, exact_max_n=1)
def ab_budget_rkf(s):
    return {"rank": Rank(s.X @ s.X.T, 3)}


@claim("ab-die-t", kind="id", sizes=SZ)
def ab_die_t(s):
    """(tr XᵀX − tr I_r)·t^(2²⁰) + (XᵀP + PᵀX), t = tr(PᵀP): TRUE (0 on T*V).  The exact attempt writes t^(2²⁰) out
    (or dies); auto's record must say which method decided (modular: checked), never exact's proved."""
    t = s.tr(s.P.T @ s.P)
    return {"x": (s.tr(s.X.T @ s.X) - s.tr(s.Ir)) * t ** (2**20) * s.Ir + s.X.T @ s.P + s.P.T @ s.X}


@claim("ab-die-f", kind="id", sizes=SZ)
def ab_die_f(s):
    """the same with XᵀP − PᵀX: FALSE."""
    t = s.tr(s.P.T @ s.P)
    return {"x": (s.tr(s.X.T @ s.X) - s.tr(s.Ir)) * t ** (2**20) * s.Ir + s.X.T @ s.P - s.P.T @ s.X}
