from stiefelsym import Rank, admissible, claim


@claim("t72-lam-rank-true", kind="dim", sizes=admissible(n_max=3))
def lam_rank_true(s):
    """lam * I_r has rank r (lam generic): true."""
    return {"rank": Rank(s.lam * s.Ir, s.r)}


@claim("t72-lam-const-mix-true", kind="dim", sizes=admissible(n_max=3))
def lam_const_mix_true(s):
    """[[1, lam], [lam, 1]] (2x2 on an opaque space) has rank 2 for generic lam: true."""
    M = s.mat([[1, s.lam], [s.lam, 1]], ("?", "?"))
    return {"rank": Rank(M, 2)}


@claim("t72-trace-const-true", kind="dim", sizes=admissible(n_max=3))
def trace_const_true(s):
    """[[tr(X^T X), 1], [1, 1]] is [[r, 1], [1, 1]] on V: rank 2 for r >= 2, rank 1 at r = 1: stated as rank 2 for
    r >= 2 (the entry tr(X^T X) is a constant on V but built from the point)."""
    M = s.mat([[s.tr(s.X.T @ s.X), 1], [1, 1]], ("?", "?"))
    return {"rank": Rank(M, 2 if int(s.r) >= 2 else 1)}
