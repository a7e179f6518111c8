"""Counts of traced values (not ints), alone and with a full rank over budget."""
from stiefelsym import Count, Rank, admissible, claim

S = admissible(n_max=5, n_min=2)


def big_inv(s):
    return (s.Ir + s.P.T @ s.P).inv()


@claim("c-traced-true", kind="dim", sizes=S)
def c_traced_true(s):
    """TRUE: tr X^T X = r, as a Count."""
    return {"c": Count(s.tr(s.X.T @ s.X), int(s.r))}


@claim("c-traced-false", kind="dim", sizes=S)
def c_traced_false(s):
    """FALSE: tr P^T P = 0, as a Count."""
    return {"c": Count(s.tr(s.P.T @ s.P), 0)}


@claim("c-traced-false-rank", kind="dim", sizes=S)
def c_traced_false_rank(s):
    """FALSE: tr P^T P = 0 as a Count, with a full rank (over budget at r = 5)."""
    return {"c": Count(s.tr(s.P.T @ s.P), 0), "rank": Rank(s.mat([[s.X[0, 0] * s.tr(big_inv(s))]]), 1)}
