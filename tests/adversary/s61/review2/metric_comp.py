"""Metric realization at r = n = 5: a rank full on one component of O(5) only (over budget)."""
from stiefelsym import Rank, admissible, claim
from budget_ranks import det_entries

SQ = admissible(n_max=5, n_min=5, where=lambda n, r: r == n)


@claim("mc-one-component", kind="dim", realization="metric", sizes=SQ)
def mc_one_component(s):
    """FALSE on det X = 1: diag(det X - 1, tr (I + P^T P)^{-1}) has generic rank 2."""
    d = det_entries(s.X, 5)
    t = s.tr((s.Ir + s.P.T @ s.P).inv())
    z = s.q(0)
    return {"rank": Rank(s.mat([[d - s.q(1), z], [z, t]]), 2)}


@claim("mc-true", kind="dim", realization="metric", sizes=SQ)
def mc_true(s):
    """TRUE: diag((det X)^2, tr (I + P^T P)^{-1}) has generic rank 2."""
    d = det_entries(s.X, 5)
    t = s.tr((s.Ir + s.P.T @ s.P).inv())
    z = s.q(0)
    return {"rank": Rank(s.mat([[d * d, z], [z, t]]), 2)}
