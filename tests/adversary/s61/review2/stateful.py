"""Claims whose graph depends on how many times the claim function was called (module state)."""
from stiefelsym import Rank, admissible, claim

S = admissible(n_max=5, n_min=2)
CALLS = {"a": 0, "b": 0, "c": 0, "d": 0}


@claim("st-true-first", kind="id", sizes=S)
def true_first(s):
    """TRUE on the first call (X^T X - I), FALSE afterwards (X^T X)."""
    CALLS["a"] += 1
    if CALLS["a"] == 1:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X.T @ s.X}


@claim("st-false-first", kind="id", sizes=S)
def false_first(s):
    """FALSE on the first call, TRUE afterwards."""
    CALLS["b"] += 1
    if CALLS["b"] == 1:
        return {"r": s.X.T @ s.X}
    return {"r": s.X.T @ s.X - s.Ir}


def big_inv(s):
    return (s.Ir + s.P.T @ s.P).inv()


@claim("st-rank-false-first", kind="dim", sizes=S)
def rank_false_first(s):
    """Rank of Psi (I+P^TP)^{-1}: claims r (false for odd r) on the first call, then a full-rank matrix."""
    CALLS["c"] += 1
    if CALLS["c"] == 1:
        return {"rank": Rank(s.Psi @ big_inv(s), int(s.r))}
    return {"rank": Rank(big_inv(s), int(s.r))}
