from stiefelsym import Rank, admissible, claim


@claim("t72-const-rank", kind="dim", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="rank 1, not 2")
def const_rank(s):
    """A constant 2 x 2 matrix of rank 1 stated of rank 2, beside a true identity of the point."""
    M = s.mat([[1, 2], [2, 4]], ("?", "?"))
    return {"rank": Rank(M, 2), "id": s.X.T @ s.X - s.Ir}


@claim("t72-const-rank-true", kind="dim", sizes=admissible(n_max=3))
def const_rank_true(s):
    """The positive control: a constant 2 x 2 matrix of rank 1 stated of rank 1, beside a true identity."""
    M = s.mat([[1, 2], [2, 4]], ("?", "?"))
    return {"rank": Rank(M, 1), "id": s.X.T @ s.X - s.Ir}
