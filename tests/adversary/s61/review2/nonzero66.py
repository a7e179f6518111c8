"""expect="nonzero" and rank claims at r = n = 6, reading coordinates (the symbolic chart beyond budget)."""
from stiefelsym import Rank, admissible, claim

S = admissible(n_max=6, n_min=6, where=lambda n, r: r == n)


@claim("nz-true", kind="not", expect="nonzero", sizes=S)
def nz_true(s):
    """TRUE: X_00 is not identically 0."""
    return {"x00": s.X[0, 0]}


@claim("nz-false", kind="not", expect="nonzero", sizes=S)
def nz_false(s):
    """FALSE: sum_i X_i0^2 - 1 is not identically 0."""
    tot = s.X[0, 0] * s.X[0, 0]
    for i in range(1, 6):
        tot = tot + s.X[i, 0] * s.X[i, 0]
    return {"norm-1": tot - s.q(1)}


@claim("nz-rank-mixed", kind="not", expect="nonzero", sizes=S)
def nz_rank_mixed(s):
    """A nonzero claim with a full rank of coordinates."""
    return {"x00": s.X[0, 0], "rank": Rank(s.mat([[s.X[0, 0]]]), 1)}


@claim("rk66-true", kind="dim", sizes=S)
def rk66_true(s):
    """TRUE: the 2x2 block X[0:2, 0:2] has generic rank 2."""
    return {"rank": Rank(s.X[0:2, 0:2], 2)}


@claim("rk66-false-every", kind="dim", sizes=S)
def rk66_false_every(s):
    """FALSE: the 2x2 block X[0:2, 0:2] has rank 2 at every point (it can vanish)."""
    return {"rank": Rank(s.X[0:2, 0:2], 2, generic=False)}
