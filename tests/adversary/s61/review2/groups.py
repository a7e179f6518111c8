"""Claims split into check groups (equivariant chart for checks reading no coordinates, Cayley for the rest),
with an over-budget rank in the Cayley group."""
from stiefelsym import Rank, admissible, claim

S = admissible(n_max=5, n_min=4, where=lambda n, r: r >= 4)


def big_inv(s):
    return (s.Ir + s.P.T @ s.P).inv()


@claim("g-true", kind="dim", sizes=S)
def g_true(s):
    """TRUE: X^T X = I and [X00 tr (I+P^TP)^{-1}] has generic rank 1."""
    return {"res": s.X.T @ s.X - s.Ir, "rank": Rank(s.mat([[s.X[0, 0] * s.tr(big_inv(s))]]), 1)}


@claim("g-false-res", kind="dim", sizes=S)
def g_false_res(s):
    """FALSE: tr P^T P = 0 (no coordinates) and the rank as above."""
    return {"res": s.tr(s.P.T @ s.P), "rank": Rank(s.mat([[s.X[0, 0] * s.tr(big_inv(s))]]), 1)}


@claim("g-false-rank", kind="dim", sizes=S)
def g_false_rank(s):
    """FALSE: [[X00 t, X00 t],[X01 t, X01 t]] has rank 2 (it has rank 1)."""
    t = s.tr(big_inv(s))
    a, b = s.X[0, 0] * t, s.X[0, 1] * t
    return {"res": s.X.T @ s.X - s.Ir, "rank": Rank(s.mat([[a, a], [b, b]]), 2)}


@claim("g-rank-true-res-coord", kind="dim", sizes=S)
def g_rank_true_res_coord(s):
    """TRUE: sum_i X_i0^2 = 1 (reads coordinates) and the rank as above."""
    n = int(s.n)
    tot = s.X[0, 0] * s.X[0, 0]
    for i in range(1, n):
        tot = tot + s.X[i, 0] * s.X[i, 0]
    return {"res": tot - s.q(1), "rank": Rank(s.mat([[s.X[0, 0] * s.tr(big_inv(s))]]), 1)}
