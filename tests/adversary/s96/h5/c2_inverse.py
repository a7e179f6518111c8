"""Symbolic inverses beyond 3x3 by their work: singular matrices (on the chart, or of the entries' polynomials)."""
from stiefelsym import admissible, claim

SZ5 = admissible(n_min=4, n_max=5, r_max=2)


@claim("h5i-singular-xxt", kind="id", sizes=SZ5)
def singular_xxt(s):
    """Not a statement: (X X^T + P P^T)^{-1} of a matrix of rank <= 2r < n (singular): (.)^{-1} (.) - I = 0 has no
    meaning; no method may say proved or checked."""
    m = s.X @ s.X.T + s.P @ s.P.T
    return {"r": m.inv() @ m - s.identity(s.n, "n")}


@claim("h5i-projector-inv", kind="id", sizes=SZ5)
def projector_inv(s):
    """Not a statement: I - X X^T is a projector (singular on V(n, r)); its inverse does not exist."""
    m = s.identity(s.n, "n") - s.X @ s.X.T
    return {"r": m.inv() @ m - s.identity(s.n, "n")}


@claim("h5i-worked-true", kind="id", sizes=SZ5)
def worked_true(s):
    """True: (I + X X^T + P P^T)^{-1} (I + X X^T + P P^T) = I (positive definite)."""
    m = s.identity(s.n, "n") + s.X @ s.X.T + s.P @ s.P.T
    return {"r": m.inv() @ m - s.identity(s.n, "n")}


@claim("h5i-worked-false", kind="id", sizes=SZ5)
def worked_false(s):
    """False: (I + X X^T + P P^T)^{-1} = I - X X^T - P P^T."""
    m = s.identity(s.n, "n") + s.X @ s.X.T + s.P @ s.P.T
    return {"r": m.inv() - s.identity(s.n, "n") + s.X @ s.X.T + s.P @ s.P.T}


@claim("h5i-pivot-zero-false", kind="id", sizes=SZ5)
def pivot_zero_false(s):
    """False: a matrix whose (0,0) entry is X^T X - I = 0 on the chart (zero only symbolically in the chart) and
    whose inverse exists: [[x^T x - 1 + 0, 1], ...] = J + (X^T X - I)_{00} E_00, J invertible; claims its inverse is
    the identity."""
    n = s.n
    J = s.identity(n, "n") * 0 + s.mat([[1 if (i + 1) % n == j else 0 for j in range(n)] for i in range(n)],
                                      ("n", "n"))
    g = (s.X.T @ s.X)[0, 0] - 1
    m = J + s.identity(n, "n") * g
    return {"r": m.inv() - s.identity(n, "n")}
