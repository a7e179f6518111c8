"""Metric realization (X^T X = I, X^T A^-1 P skew) claims that read coordinates (Cayley chart, pre-check)."""
from stiefelsym import admissible, claim

S = admissible(n_max=4, n_min=2)


@claim("m-true-coord", kind="id", realization="metric", sizes=S)
def m_true_coord(s):
    """TRUE in the metric realization: the (0,0) entry of X^T A^{-1} P + P^T A^{-1} X vanishes, and
    sum_i X_{i0}^2 = 1."""
    n = int(s.n)
    M = s.X.T @ s.Ainv @ s.P
    tot = s.X[0, 0] * s.X[0, 0]
    for i in range(1, n):
        tot = tot + s.X[i, 0] * s.X[i, 0]
    return {"skew00": M[0, 0], "norm": tot - s.q(1)}


@claim("m-false-standard", kind="id", realization="metric", sizes=S)
def m_false_standard(s):
    """FALSE in the metric realization: X^T P is skew (entry (0,0) of X^T P vanishes)."""
    M = s.X.T @ s.P
    return {"xp00": M[0, 0]}
