"""s72 review: auto's late exact beyond the symbolic budget, and check of its records (attempts L1-L3)."""
from stiefelsym import Rank, admissible, claim

SIZES = admissible(n_max=4)


@claim("s72-late-rank-low", kind="dim", paper="No", section="t", sizes=SIZES, exact_max_n=1)
def rank_low(s):
    """rank X Xᵀ = r + 1 (false: it is r): modular inconclusive, exact late refutes."""
    return {"rk": Rank(s.X @ s.X.T, int(s.r) + 1)}


@claim("s72-late-every-point", kind="dim", paper="No", section="t", sizes=SIZES, exact_max_n=1)
def every_point(s):
    """rank X = r at every point (true): modular undecided, exact late proves."""
    return {"rk": Rank(s.X, int(s.r), generic=False)}


@claim("s72-late-every-point-p", kind="dim", paper="No", section="t", sizes=SIZES, exact_max_n=1)
def every_point_p(s):
    """rank P = r at every point (false: P = 0 is a point)."""
    return {"rk": Rank(s.P, int(s.r), generic=False)}
