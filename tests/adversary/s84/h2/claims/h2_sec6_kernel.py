"""h2: (A1) with a kernel certificate (the same statement as h2-a1-rank of h2_sec6.py, TRUE).
Kernel of y ↦ Λ_{1,−1}(y,·) at h + v = Θ(X,P): y_k = E_kk + ξ_k, (ξ_k)_ij = [h, E_kk]_ij/(a_i − a_j) (i ≠ j), k = 1..n.
-twin (FALSE, n >= 2): the same kernel certificate with rank claimed n² − n + 1."""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units


def skew(M):
    return (M - M.T) / 2


def sym(M):
    return (M + M.T) / 2


def kernel(s):
    n, a, h = s.n, s.a, s.Phi
    cols = []
    for k in range(n):
        col = []
        for i in range(n):
            for j in range(n):
                if i == j:
                    col.append(s.q(1) if i == k else s.q(0))
                else:
                    hk = (h[i, k] if j == k else s.q(0)) - (h[k, j] if i == k else s.q(0))
                    col.append(hk / (a[i] - a[j]))
        cols.append(col)
    return s.mat([[cols[k][m] for k in range(n)] for m in range(n * n)])


def M_of(s):
    h = s.Phi

    def f(y):
        return comm(s.A, sym(y)) + comm(s.A, skew(y)) - comm(h, sym(y))
    return matrix_of(s, f, matrix_units(s, "n", "n"))


@claim("h2-a1-rank-kernel", kind="dim", section="6", sizes=admissible(n_max=4, n_min=2, condition="n >= 2"))
def a1_rank_kernel(s):
    """TRUE: rank n² − n with an explicit n-dimensional kernel certificate."""
    return {"rank": Rank(M_of(s), s.n * s.n - s.n, kernel=kernel(s))}


@claim("h2-a1-rank-kernel-twin", kind="dim", section="6", sizes=admissible(n_max=4, n_min=2, condition="n >= 2"))
def a1_rank_kernel_twin(s):
    """FALSE: rank n² − n + 1 (the certificate proves rank <= n² − n)."""
    return {"rank": Rank(M_of(s), s.n * s.n - s.n + 1, kernel=kernel(s))}
