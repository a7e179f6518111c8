# ruff: noqa
"""Stop 73, second review: a true claim whose exact evaluation is one long native product (flint), which the
symbolic deadline cannot interrupt: the forked attempt is stopped from outside (HardTimeout) and the point is
tried after it; and the same claim made false by a small extra term."""
from stiefelsym import admissible, claim


def big(s, k):
    t = s.tr(s.P.T @ s.P) + s.tr(s.X.T @ s.A @ s.X)
    a = t ** k
    return t, a


@claim("rv2-native-power-true", paper=("cond_XP",), kind="id", sizes=admissible(n_max=6))
def native_true(s):
    """True: (t^k)(t^k) = t^(2k), t = tr PᵀP + tr XᵀAX (k = 12)."""
    t, a = big(s, 12)
    return {"t^k t^k - t^2k": a * a - t ** 24}


@claim("rv2-native-power-false", paper=("cond_XP",), kind="id", sizes=admissible(n_max=6),
       fails_at=lambda n, r: True, erratum="an extra term tr XᵀX / 1000 (= r/1000 on V)")
def native_false(s):
    """False: (t^k)(t^k) = t^(2k) + tr(XᵀX)/1000 (tr XᵀX = r on V)."""
    t, a = big(s, 12)
    return {"t^k t^k - t^2k - trXtX/1000": a * a - t ** 24 - s.tr(s.X.T @ s.X) / 1000}


def x_column_norm(s):
    total = s.X[0, 0] * s.X[0, 0]
    for i in range(1, int(s.n)):
        total = total + s.X[i, 0] * s.X[i, 0]
    return total - s.q(1)


@claim("rv2-native-grouped-false", paper=("cond_XP",), kind="id", sizes=admissible(n_max=6),
       fails_at=lambda n, r: True, erratum="Σ X_i1² = 1 + 1/1000 (false)")
def native_grouped_false(s):
    """False: a true heavy check that reads no coordinate (proved first, in a group of its own) beside a false check
    in coordinates, Σᵢ X_i1² = 1 + 1/1000."""
    t, a = big(s, 12)
    return {"t^k t^k - t^2k": a * a - t ** 24, "|X e1|^2 - 1 - 1/1000": x_column_norm(s) - s.q(1, 1000)}
