# ruff: noqa
"""Counts of plain integers at sizes far beyond the symbolic budget (auto and exact now evaluate them exactly at
every size), with containers and big numbers; and a count next to a matrix residual.  Truth: arithmetic.
Run: stiefelsym verify --claims counts_big.py --method auto --method exact --size 3000,2 --size 4,2 --jobs 1 --no-report"""
from stiefelsym import admissible, claim, Count

SIZES = admissible(n_max=4)


@claim("r2c-dim-true", kind="dim", sizes=SIZES)
def dim_true(s):
    """dim V(n, r) = nr − r(r+1)/2 (true), written with nested containers."""
    n, r = int(s.n), int(s.r)
    return {"dim": Count(n * r - r * (r + 1) // 2, n * r - (r * r + r) // 2)}


@claim("r2c-dim-false", kind="dim", sizes=SIZES)
def dim_false(s):
    """dim V(n, r) = nr − r(r−1)/2 (false: it is nr − r(r+1)/2)."""
    n, r = int(s.n), int(s.r)
    return {"dim": Count(n * r - r * (r + 1) // 2, n * r - r * (r - 1) // 2)}


@claim("r2c-big-false", kind="dim", sizes=SIZES)
def big_false(s):
    """n^n = n^n + 1 (false), with a big constant residual 0 beside it."""
    n = int(s.n)
    return {"c": Count(n ** 50, n ** 50 + 1)}


@claim("r2c-count-and-matrix-false", kind="dim", sizes=SIZES)
def count_and_matrix(s):
    """A true count beside a false matrix residual XᵀX − 2I_r (false)."""
    n, r = int(s.n), int(s.r)
    return {"dim": Count(n * r, n * r), "m": s.X.T @ s.X - 2 * s.Ir}
