"""Second point and complex point read by coordinates (Cayley chart, rational pre-check)."""
from stiefelsym import admissible, claim

S = admissible(n_max=4, n_min=2)


def colnorm(M, rows, j):
    tot = M[0, j] * M[0, j]
    for i in range(1, rows):
        tot = tot + M[i, j] * M[i, j]
    return tot


@claim("p2-y-true", kind="id", sizes=S)
def y_true(s):
    """TRUE: column 0 of Y has norm 1, and (Y^T Q)_{00} = 0."""
    n = int(s.n)
    return {"norm": colnorm(s.Y, n, 0) - s.q(1), "yq00": (s.Y.T @ s.Q)[0, 0]}


@claim("p2-zc-true", kind="id", sizes=S)
def zc_true(s):
    """TRUE: the realified complex point has orthonormal columns: column 0 of Zc has norm 1."""
    m = int(s.Zc.shape[0])
    return {"norm": colnorm(s.Zc, m, 0) - s.q(1)}


@claim("p2-zc-false", kind="id", sizes=S)
def zc_false(s):
    """FALSE: column 0 of Zc has norm 2."""
    m = int(s.Zc.shape[0])
    return {"norm": colnorm(s.Zc, m, 0) - s.q(2)}
