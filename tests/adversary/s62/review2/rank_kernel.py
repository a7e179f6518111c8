"""Rank claims with kernel= certificates: wrong, partly right, wrong shape, and ranks true on one component of O(n)
only (r = n).  X + I and X - I: on SO(n) X has eigenvalue 1 for odd n; on O(n)^- it has eigenvalue -1 (and for
odd n, -X is a rotation).  ax(X) = (X32 - X23, X13 - X31, X21 - X12) is the axis of X (n = 3), a kernel vector of
X - I on SO(3) and of X + I on O(3)^- (not of the other)."""
from stiefelsym import Rank, admissible, block, claim

N3 = admissible(n_min=3, n_max=3, r_min=3, where=lambda n, r: r == n, condition="n = r = 3")
N2 = admissible(n_min=2, n_max=2, r_min=2, where=lambda n, r: r == n, condition="n = r = 2")


def J(s):
    n = int(s.n)
    return s.mat([[1 if i == j else 0 for j in range(n)] for i in range(n)], ("n", "r"))


def ax(s):
    X = s.X
    return s.mat([[X[2, 1] - X[1, 2]], [X[0, 2] - X[2, 0]], [X[1, 0] - X[0, 1]]], ("r", "?"))


@claim("rk-xmi-2-kernel", kind="dim", sizes=N3)
def xmi2k(s):
    """FALSE (rank 3 on O(3)^-): generic rank of X - I is 2, kernel ax(X) (right on SO(3) only)."""
    return {"rank": Rank(s.X - J(s), 2, kernel=ax(s))}


@claim("rk-xpi-2-kernel", kind="dim", sizes=N3)
def xpi2k(s):
    """FALSE (rank 3 on SO(3)): generic rank of X + I is 2, kernel ax(X) (right on O(3)^- only)."""
    return {"rank": Rank(s.X + J(s), 2, kernel=ax(s))}


@claim("rk-xmi-2", kind="dim", sizes=N3)
def xmi2(s):
    """FALSE (rank 3 on O(3)^-): generic rank of X - I is 2."""
    return {"rank": Rank(s.X - J(s), 2)}


@claim("rk-xpi-2", kind="dim", sizes=N3)
def xpi2(s):
    """FALSE (rank 3 on SO(3)): generic rank of X + I is 2."""
    return {"rank": Rank(s.X + J(s), 2)}


@claim("rk-xmi-3", kind="dim", sizes=N3)
def xmi3(s):
    """FALSE (rank 2 on SO(3)): generic rank of X - I is 3."""
    return {"rank": Rank(s.X - J(s), 3)}


@claim("rk-xpi-3", kind="dim", sizes=N3)
def xpi3(s):
    """FALSE (rank 2 on O(3)^-): generic rank of X + I is 3."""
    return {"rank": Rank(s.X + J(s), 3)}


@claim("rk2-xpi-1", kind="dim", sizes=N2)
def xpi1_2(s):
    """FALSE (rank 2 on SO(2)): generic rank of X + I is 1 (true on reflections)."""
    X = s.X
    K = s.mat([[X[0, 1]], [-1 - X[0, 0]]], ("r", "?"))
    return {"rank": Rank(X + J(s), 1, kernel=K)}


@claim("rk2-xpi-2", kind="dim", sizes=N2)
def xpi2_2(s):
    """FALSE (rank 1 on reflections): generic rank of X + I is 2."""
    return {"rank": Rank(s.X + J(s), 2)}


@claim("rk-pt-wrong-kernel", kind="dim", sizes=admissible(n_max=4, r_min=2, where=lambda n, r: r < n))
def pt_wrong(s):
    """FALSE: rank of P^T (r x n) is r - 1 with kernel X (wrong: P^T X = -X^T P != 0)."""
    return {"rank": Rank(s.P.T, int(s.r) - 1, kernel=s.X[:, 0:1])}


@claim("rk-xt-kernel-right", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_right(s):
    """TRUE: rank of X^T (r x n) is r, kernel I - X X^T (rank n - r)."""
    return {"rank": Rank(s.X.T, int(s.r), kernel=s.In - s.X @ s.X.T)}


@claim("rk-xt-kernel-too-big", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_big(s):
    """FALSE: rank of X^T is r - 1, 'kernel' [I - XX^T, P] (P is not in the kernel)."""
    return {"rank": Rank(s.X.T, int(s.r) - 1, kernel=block([[s.In - s.X @ s.X.T, s.P]]))}


@claim("rk-xt-kernel-partly", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_partly(s):
    """FALSE: rank of X^T is r - 1, 'kernel' [I - XX^T, X (I - X^T X) + X e1] partly right."""
    e = s.mat([[1]] + [[0]] * (int(s.r) - 1), ("r", "?"))
    return {"rank": Rank(s.X.T, int(s.r) - 1, kernel=block([[s.In - s.X @ s.X.T, s.X @ e]]))}


@claim("rk-xt-kernel-shape", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_shape(s):
    """ERROR expected: a kernel with r rows for a matrix of n columns."""
    return {"rank": Rank(s.X.T, int(s.r), kernel=s.Ir)}


@claim("rk-xt-kernel-transposed", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_tr(s):
    """FALSE: rank of X^T is r - 1 with kernel X (X^T X = I: not a kernel)."""
    return {"rank": Rank(s.X.T, int(s.r) - 1, kernel=s.X)}


@claim("rk-xt-kernel-lam", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_lam(s):
    """TRUE: rank of X^T is r, kernel lam (I - X X^T) (a scalar parameter in the kernel)."""
    return {"rank": Rank(s.X.T, int(s.r), kernel=s.lam * (s.In - s.X @ s.X.T))}


@claim("rk-xt-kernel-lam-false", kind="dim", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def xt_lam_f(s):
    """FALSE: rank of X^T is r - 1, kernel [(I - XX^T), (lam - lam) P + X e1 * 0 + ... ] where the extra column
    is (tr(P^T P) - tr(P^T P)) X e1 = 0 (an identically zero column: adds no rank)."""
    e = s.mat([[1]] + [[0]] * (int(s.r) - 1), ("r", "?"))
    z = s.tr(s.P.T @ s.P) - s.tr(s.P.T @ s.P)
    return {"rank": Rank(s.X.T, int(s.r) - 1, kernel=block([[s.In - s.X @ s.X.T, z * (s.X @ e)]]))}


def _bd(s):
    n = int(s.n)
    Z = s.zeros(n, n, ("n", "r"))
    return block([[s.X - J(s), Z], [Z, s.X + J(s)]])


@claim("rk-bd-5-kernel-one-comp", kind="dim", sizes=N3)
def bd5(s):
    """TRUE: diag(X - I, X + I) has rank 5 on both components; kernel (ax; 0) is right on SO(3) only."""
    z = s.zeros(3, 1, ("r", "?"))
    return {"rank": Rank(_bd(s), 5, kernel=block([[ax(s)], [z]]))}


@claim("rk-bd-4-kernel", kind="dim", sizes=N3)
def bd4(s):
    """FALSE: rank 4 with 'kernel' [(ax; 0), (0; ax)] (each right on one component only)."""
    z = s.zeros(3, 1, ("r", "?"))
    return {"rank": Rank(_bd(s), 4, kernel=block([[ax(s), z], [z, ax(s)]]))}


@claim("rk-bd-5", kind="dim", sizes=N3)
def bd5n(s):
    """TRUE: diag(X - I, X + I) has rank 5."""
    return {"rank": Rank(_bd(s), 5)}


@claim("rk-bd-6", kind="dim", sizes=N3)
def bd6(s):
    """FALSE: diag(X - I, X + I) has rank 6."""
    return {"rank": Rank(_bd(s), 6)}
