"""Batch 12: a resolvent at a moving parameter mu = l + (n - r) tr(P^T P) beside R(l): at r = n the two are one
matrix at every point, elsewhere they differ; the rewriting divides by m - l (m the symbol standing for mu).

  b12-move-commute    [R(l), R(mu)] = 0                        TRUE at every size
  b12-move-sq         the same, declared at r = n              TRUE (one matrix)
  b12-move-equal-sq   R(l) = R(mu) at r = n                    TRUE at r = n (free: a miss expected)
"""
from stiefelsym import admissible, claim


def _two(s):
    mu = s.lam + (s.tr(s.In) - s.tr(s.Ir)) * s.tr(s.P.T @ s.P)
    return s.resolvent(s.lam), s.resolvent(mu)


@claim("b12-move-commute", kind="id", sizes=admissible(n_max=4))
def move_commute(s):
    R1, R2 = _two(s)
    return {"[R1, R2]": R1 @ R2 - R2 @ R1}


@claim("b12-move-sq", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def move_sq(s):
    R1, R2 = _two(s)
    return {"[R1, R2]": R1 @ R2 - R2 @ R1}


@claim("b12-move-equal-sq", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def move_equal_sq(s):
    R1, R2 = _two(s)
    return {"R1 - R2": R1 - R2}
