# ruff: noqa
"""Stop 73, second review: a claim proved in two groups whose first group (no coordinate of R^n read) is one long
native product, and whose second group (coordinates read) is false and slow to evaluate at a rational point (nested
inverses: the heights double at each level).  The exact attempt is stopped from outside at 1.1 x 0.8 x timeout + 1 s
and the point after it has what is left of the run's budget."""
from stiefelsym import admissible, claim


def x_column_norm(s):
    total = s.X[0, 0] * s.X[0, 0]
    for i in range(1, int(s.n)):
        total = total + s.X[i, 0] * s.X[i, 0]
    return total - s.q(1)


def nested(s, k):
    M = s.In + s.X @ s.X.T + s.A
    for _ in range(k):
        M = (s.In + M @ M.T).inv() + s.A
    return M


@claim("rv2-slowpoint-grouped-false", paper="cond_XP", kind="id", sizes=admissible(n_max=12),
       fails_at=lambda n, r: True, erratum="Σ X_i1² = 1 + 1/1000 (false)")
def slowpoint(s):
    """False (its third check): a heavy true check that reads no coordinate, a true check slow at a rational point,
    and Σᵢ X_i1² = 1 + 1/1000."""
    t = s.tr(s.P.T @ s.P) + s.tr(s.X.T @ s.A @ s.X)
    a = t ** 12
    M = nested(s, 6)
    return {"t^k t^k - t^2k": a * a - t ** 24,
            "slow": (M - M.T) * x_column_norm(s),
            "|X e1|^2 - 1 - 1/1000": x_column_norm(s) - s.q(1, 1000)}
