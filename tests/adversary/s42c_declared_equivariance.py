"""A user's claim that declares an equivariance it does not have: D = E11 is a fixed projector, so the statements
hold at X = (I; 0), the point of the equivariant chart, and fail at a generic X (r < n).  At r = n, XXᵀ = I and
both hold."""
from stiefelsym import Rank, admissible, claim


def _projector(s):
    n = s.n
    return s.mat([[s.q(1) if (i, j) == (0, 0) else s.q(0) for j in range(n)] for i in range(n)], ("n", "n"))


@claim("adv-s42c-declared-equivariance", paper=("prep",), kind="id", sizes=admissible(4),
       equivariance="the statement is invariant under O(n) (it is not: D is a fixed projector)")
def declared_equivariance(s):
    """(I − D)XXᵀD = 0 for D = E11."""
    D = _projector(s)
    return {"(I - D) X X^T D": (s.In - D) @ s.X @ s.X.T @ D}


@claim("adv-s42c-declared-equivariance-rank", paper=("prep",), kind="dim", sizes=admissible(4),
       equivariance="the rank is O(n)-invariant (it is not: D is a fixed projector)")
def declared_equivariance_rank(s):
    """rank (I − D)XXᵀD = 0 at a generic point for D = E11."""
    D = _projector(s)
    return {"rank": Rank((s.In - D) @ s.X @ s.X.T @ D, 0, generic=True)}
