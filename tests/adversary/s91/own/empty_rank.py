"""The empty-matrix rank branch: a 0 × 3 matrix has rank 0 at every point, so a claimed rank 1 is false."""
from stiefelsym import Rank, admissible, claim


@claim("empty-rank-false", kind="dim", sizes=admissible(3))
def empty_false(s):
    return {"rank": Rank(s.X[0:0, :], 1, generic=True, meaning="a rank the empty matrix cannot have")}


@claim("empty-rank-true", kind="dim", sizes=admissible(3))
def empty_true(s):
    return {"rank": Rank(s.X[0:0, :], 0, generic=True, meaning="0")}
