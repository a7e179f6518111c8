"""Round 4b: residuals that vanish on one component of O(n) only (r = n), hidden from float64 by an
absorption (cu + R) − cu with c = 10^20, so that only the exact confirmation mod p can see them: it
must evaluate a point on each component.  Each claim is false (det X = 1 on SO(n) only)."""
from stiefelsym import admissible, claim

def _det2(X):
    return X[0, 0] * X[1, 1] - X[0, 1] * X[1, 0]


@claim("adv-s34b-comp-det2", kind="id", sizes=admissible(n_max=2, r_is_n=True))
def det_is_one_2(s):
    """det X = 1 at r = n = 2, absorbed: false on the component det X = −1."""
    c = 10 ** 20
    u = s.tr(s.P.T @ s.P)
    return {"det": (c * u + (_det2(s.X) - 1)) - c * u}


@claim("adv-s34b-comp-cofactor", kind="id", sizes=admissible(n_min=3, n_max=3, r_is_n=True))
def cofactor(s):
    """X_11 = its cofactor X_22 X_33 − X_23 X_32 at r = n = 3, absorbed: X = cof(X)/det X holds with
    det X = 1 only, false on the other component."""
    c = 10 ** 20
    u = s.tr(s.P.T @ s.P)
    X = s.X
    cof = X[1, 1] * X[2, 2] - X[1, 2] * X[2, 1]
    return {"X11": (c * u + (X[0, 0] - cof)) - c * u}
