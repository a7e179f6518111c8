"""Claims whose graph depends on how many fixed-size traces happened (module state, per size)."""
import sys
from stiefelsym import Rank, admissible, claim

S = admissible(n_max=5, n_min=2)
CALLS = {}


def _count(key, s):
    k = (key, int(s.n), int(s.r))
    CALLS[k] = CALLS.get(k, 0) + 1
    print(f"TRACE {k} #{CALLS[k]}", file=sys.stderr)
    return CALLS[k]


@claim("st3-true-first", kind="id", sizes=S)
def true_first(s):
    """TRUE on the first fixed-size call, FALSE afterwards."""
    if _count("a", s) <= 2:
        return {"r": s.X.T @ s.X - s.Ir}
    return {"r": s.X.T @ s.X}


@claim("st3-false-first", kind="id", sizes=S)
def false_first(s):
    """FALSE on the first fixed-size call, TRUE afterwards."""
    if _count("b", s) <= 2:
        return {"r": s.X.T @ s.X}
    return {"r": s.X.T @ s.X - s.Ir}


def big_inv(s):
    return (s.Ir + s.P.T @ s.P).inv()


@claim("st3-rank-false-first", kind="dim", sizes=S)
def rank_false_first(s):
    """FALSE first (rank r of Psi at odd r), then a full-rank matrix."""
    if _count("c", s) <= 2:
        return {"rank": Rank(s.Psi @ big_inv(s), int(s.r))}
    return {"rank": Rank(big_inv(s), int(s.r))}
