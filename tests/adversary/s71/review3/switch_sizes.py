# ruff: noqa
"""Claims that are counts of plain integers at their smallest stated size (so the cost model exempts them from the
time and memory refusal, judged there) and something else at a large size.  Truth: arithmetic / numpy (truth.py).
Run: stiefelsym verify --claims switch_sizes.py --size 100000,2 --method auto --jobs 1 --no-report"""
from stiefelsym import Count, Rank, admissible, claim

SIZES = admissible(n_max=4)


@claim("r3-switch-gram", kind="id", sizes=SIZES)
def switch_gram(s):
    """A count at n <= 4; beyond, X Xᵀ X − X = 0 (true on V): an n x n product at n = 100000."""
    if int(s.n) <= 4:
        return {"c": Count(int(s.n), int(s.n))}
    return {"m": s.X @ s.X.T @ s.X - s.X}


@claim("r3-switch-false", kind="id", sizes=SIZES)
def switch_false(s):
    """A count at n <= 4; beyond, X Xᵀ = I_n (false for r < n)."""
    if int(s.n) <= 4:
        return {"c": Count(int(s.n), int(s.n))}
    return {"m": s.X @ s.X.T - s.In}


@claim("r3-switch-rank", kind="dim", sizes=SIZES)
def switch_rank(s):
    """A count at n <= 4; beyond, rank A = n (true: a generic diagonal A)."""
    if int(s.n) <= 4:
        return {"c": Count(int(s.n), int(s.n))}
    return {"rk": Rank(s.A, int(s.n))}


@claim("r3-bigcount-false", kind="dim", sizes=SIZES)
def bigcount_false(s):
    """10^5000 = 10^5000 + 1 (false), as a count."""
    return {"c": Count(10 ** 5000, 10 ** 5000 + 1)}


@claim("r3-bigcount-true", kind="dim", sizes=SIZES)
def bigcount_true(s):
    """n^(n·1000) = n^(n·1000) (true), as a count: a number of about 5·10^8 digits at n = 100000."""
    k = int(s.n) ** (int(s.n) * 1000)
    return {"c": Count(k, k)}
