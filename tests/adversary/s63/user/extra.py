"""r = n statement declared with r_is_n=True (so that free may use X X^T = I)."""
from stiefelsym import admissible, claim

from common import H_0, H_neum0


@claim("u63-r-is-n", paper=("N0_XP2", "dot_X3"), kind="id", section="8",
       sizes=admissible(n_max=5, r_is_n=True, where=lambda n, r: r == n, condition="r = n"))
def neumann_is_geodesic_r_is_n(s):
    """r = n: tr X^TAX = tr A and the Neumann flow (N0_XP2) is the normal geodesic flow."""
    fN = s.dirac_flow(H_neum0)
    f0 = s.dirac_flow(H_0)
    return {"V": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A), "X": fN["X"] - f0["X"], "P": fN["P"] - f0["P"]}


from stiefelsym import Rank  # noqa: E402
from stiefelsym.bases import matrix_of, so_basis  # noqa: E402


def _so_coords(xi, m):
    return [xi[i, j] for i in range(m) for j in range(i + 1, m)]


@claim("u63-l1-rank-kernel", paper=("L1", "LEMA1"), kind="dim", section="6", sizes=admissible(n_max=5, n_min=2))
def l1_rank_kernel(s):
    """(L1) with a kernel certificate: the kernel of xi -> [xi, XX^T] contains X so(r) X^T and
    Q so(n) Q (Q = I - XX^T), of dimension dim so(r) + dim so(n-r); rank r(n-r)."""
    n, r = int(s.n), int(s.r)
    v = s.X @ s.X.T
    Q = s.In - v
    M = matrix_of(s, lambda xi: xi @ v - v @ xi, so_basis(s, "n"), "sym")
    gens = [s.X @ E @ s.X.T for E in so_basis(s, "r")] + [Q @ F @ Q for F in so_basis(s, "n")]
    cols = [_so_coords(g, n) for g in gens]
    K = s.mat([[c[i] for c in cols] for i in range(n * (n - 1) // 2)], ("so", "?"))
    return {"rank": Rank(M, r * (n - r), kernel=K)}
