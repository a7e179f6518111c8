"""A size times a positive int (a Dim) as the printed rank or count."""
from stiefelsym import Count, Rank, admissible, claim

S = admissible(n_max=5, n_min=2)


def big_inv(s):
    return (s.Ir + s.P.T @ s.P).inv()


@claim("dr-rank-dim-true", kind="dim", sizes=S)
def dr_rank_dim_true(s):
    """TRUE: (I + P^T P)^{-1} has rank r (printed as s.r * 1)."""
    return {"rank": Rank(big_inv(s), s.r * 1)}


@claim("dr-rank-dim-false", kind="dim", sizes=S)
def dr_rank_dim_false(s):
    """FALSE: (I + P^T P)^{-1} has rank 2r (printed as s.r * 2)."""
    return {"rank": Rank(big_inv(s), s.r * 2)}


@claim("dr-rank-dim-false-psi", kind="dim", sizes=S)
def dr_rank_dim_false_psi(s):
    """FALSE at odd r: Psi R has rank r (printed as s.r * 1)."""
    return {"rank": Rank(s.Psi @ big_inv(s), s.r * 1)}


@claim("dr-count-dim", kind="dim", sizes=S)
def dr_count_dim(s):
    """FALSE: 2n = 2n + 1 as a count of sizes."""
    return {"c": Count(s.n * 2, 2 * int(s.n) + 1)}
