"""Rank kernel certificates that hold only at the equivariant chart's point, or only in part."""
from stiefelsym import Rank, admissible, block, claim

SZ = admissible(n_min=2, r_max=2, where=lambda n, r: r < n, n_max=4)


def _en(s):
    n = int(s.n)
    return s.mat([[0]] * (n - 1) + [[1]], ("n", "?"))


@claim("h2k-const-en", kind="dim", sizes=SZ)
def const_en(s):
    """True: rank XX^T = r, with a forged kernel [I - XX^T, e_n]."""
    K = block([[s.In - s.X @ s.X.T, _en(s)]])
    return {"rank": Rank(s.X @ s.X.T, int(s.r), kernel=K)}


@claim("h2k-entry-col", kind="dim", sizes=SZ)
def entry_col(s):
    """True: rank X^T = r, forged kernel column: the last column of I - e_1 e_1^T read through a block."""
    n = int(s.n)
    K = block([[s.In - s.X @ s.X.T, (s.In - s.X @ s.X.T)[0:n, 0:1] * 0 + s.In[0:n, n - 1:n]]])
    return {"rank": Rank(s.X.T, int(s.r), kernel=K)}


@claim("h2k-xxt-true", kind="dim", sizes=SZ)
def xxt_true(s):
    """True: rank X^T = r, honest kernel I - XX^T."""
    return {"rank": Rank(s.X.T, int(s.r), kernel=s.In - s.X @ s.X.T)}


@claim("h2k-p-kernel", kind="dim", sizes=SZ)
def p_kernel(s):
    """True: rank X^T = r; forged kernel [I - XX^T, P_{last row}-ish]: (I - XX^T) + column e_n e_n^T X ... """
    n = int(s.n)
    v = s.In[0:n, n - 1:n] - s.X @ s.X.T[0:int(s.r), n - 1:n]
    return {"rank": Rank(s.X.T, int(s.r), kernel=block([[s.In - s.X @ s.X.T, v]]))}


@claim("h2k-generic-r", kind="dim", sizes=admissible(n_min=2, r_max=2, n_max=3))
def generic_r(s):
    """True: rank X^T X = r (= I_r); forged kernel X^T P (zero at ... no: skew, nonzero)."""
    return {"rank": Rank(s.X.T @ s.X, int(s.r), kernel=s.X.T @ s.P + s.P.T @ s.X)}
