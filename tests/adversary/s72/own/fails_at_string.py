from stiefelsym import Rank, admissible, claim


@claim("t72-const-rank", kind="dim", sizes=admissible(n_max=3), fails_at="all", erratum="rank 1, not 2")
def const_rank(s):
    """A constant 2 x 2 matrix of rank 1 stated of rank 2, beside a true identity of the point."""
    M = s.mat([[1, 2], [2, 4]], ("?", "?"))
    return {"rank": Rank(M, 2), "id": s.X.T @ s.X - s.Ir}
