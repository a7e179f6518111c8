# ruff: noqa
"""s75 probes of the slow exact run of h75-dimfol-r-n at (4,4): the rank of ad_Φ on so(n) at r = n, alone, with a
kernel certificate (Φ, Φ³, …: they commute with Φ), and the same rank for ad_Ψ (proved in 0.02 s in claims.py)."""
from stiefelsym import Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

R_IS_N = admissible(n_max=5, n_min=2, where=lambda n, r: r == n, condition="r = n >= 2")


def _coords(s, M, n):
    return [M[i, j] for i in range(n) for j in range(i + 1, n)]


@claim("p75-ad-phi-rank-r-n", kind="dim", sizes=R_IS_N)
def ad_phi_rank(s):
    """rank ad_Φ on so(n) = n(n − 1)/2 − [n/2] at r = n (no kernel)."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: comm(s.Phi, xi), so_basis(s, "n"), "skew")
    return {"rank ad_Phi": Rank(M, n * (n - 1) // 2 - n // 2)}


@claim("p75-ad-phi-rank-r-n-kernel", kind="dim", sizes=R_IS_N)
def ad_phi_rank_kernel(s):
    """The same with the kernel certificate Φ, Φ³, …, Φ^{2[n/2]−1} (in the coordinates of so_basis)."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: comm(s.Phi, xi), so_basis(s, "n"), "skew")
    cols, F, F2 = [], s.Phi, s.Phi @ s.Phi
    for _ in range(n // 2):
        cols.append(_coords(s, F, n))
        F = F @ F2
    K = s.mat([list(row) for row in zip(*cols)])
    return {"rank ad_Phi": Rank(M, n * (n - 1) // 2 - n // 2, kernel=K)}


@claim("p75-ad-psi-rank-r-n", kind="dim", sizes=R_IS_N)
def ad_psi_rank(s):
    """rank ad_Ψ on so(r) at r = n (as h75-ad-psi-rank)."""
    r = int(s.r)
    M = matrix_of(s, lambda eta: comm(s.Psi, eta), so_basis(s, "r"), "skew")
    return {"rank ad_Psi": Rank(M, r * (r - 1) // 2 - r // 2)}
