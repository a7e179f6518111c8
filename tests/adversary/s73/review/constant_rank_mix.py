"""Ranks of matrices of constants (decided at one exact point by the rational method), mixed with entries of the
point that are constant on T*V only, and with lambda entries that cancel."""
from stiefelsym import Rank, admissible, claim


@claim("s73-const-rank-sized", kind="dim", sizes=admissible(n_max=4, n_min=2))
def const_rank_sized(s):
    """[[n - 3, 0], [0, 1]] (n read as a number) has rank 2: FALSE at n = 3, TRUE at n = 2 and n = 4."""
    n = int(s.n)
    return {"rank": Rank(s.mat([[n - 3, 0], [0, 1]], ("?", "?")), 2)}


@claim("s73-const-rank-lam-cancel", kind="dim", sizes=admissible(n_max=3))
def const_rank_lam_cancel(s):
    """[[1 + lam - lam, 2], [2, 4]] has rank 2: FALSE (it is [[1, 2], [2, 4]], rank 1)."""
    return {"rank": Rank(s.mat([[1 + s.lam - s.lam, 2], [2, 4]], ("?", "?")), 2)}


@claim("s73-const-rank-on-v", kind="dim", sizes=admissible(n_max=3))
def const_rank_on_v(s):
    """[[tr(X^T X) - r, 1], [0, 1]] has rank 2: FALSE on T*V (it is [[0, 1], [0, 1]], rank 1)."""
    M = s.mat([[s.tr(s.X.T @ s.X) - s.tr(s.Ir), 1], [0, 1]], ("?", "?"))
    return {"rank": Rank(M, 2)}


@claim("s73-const-rank-on-v-true", kind="dim", sizes=admissible(n_max=3))
def const_rank_on_v_true(s):
    """[[tr(X^T X) - r, 1], [0, 1]] has rank 1: TRUE on T*V."""
    M = s.mat([[s.tr(s.X.T @ s.X) - s.tr(s.Ir), 1], [0, 1]], ("?", "?"))
    return {"rank": Rank(M, 1)}


@claim("s73-const-rank-inverse", kind="dim", sizes=admissible(n_max=3))
def const_rank_inverse(s):
    """The inverse of [[1, 2], [3, 4]] times [[1, 2], [2, 4]] has rank 1: TRUE (a constant matrix of rank 1)."""
    B = s.mat([[1, 2], [3, 4]], ("?", "?"))
    C = s.mat([[1, 2], [2, 4]], ("?", "?"))
    return {"rank": Rank(B.inv() @ C, 1)}


@claim("s73-const-rank-every-point", kind="dim", sizes=admissible(n_max=3))
def const_rank_every_point(s):
    """[[1, 2], [3, 4]] has rank 2 at every point: TRUE (constant, invertible)."""
    return {"rank": Rank(s.mat([[1, 2], [3, 4]], ("?", "?")), 2, generic=False)}
