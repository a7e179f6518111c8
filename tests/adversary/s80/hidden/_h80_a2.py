# ruff: noqa
"""s80 (h2): the (A2) helpers shared by claims2.py and negatives2.py (no claims)."""
from stiefelsym import Rank, comm
from stiefelsym.bases import matrix_units

from _h80_helpers import lam1, lam2


def kernel_spanning_set(s, X, h):
    """A spanning set of ker Λ1(h + v), v = XXᵀ, when vhv = 0 = (I − v)h(I − v) (a point of Θ(Ψ⁻¹(0))):
    ξ + η_off with ξ = vαv or (I − v)β(I − v) (α, β = E_i∧E_j), η_off = (I − v)wv − vw(I − v), w = −[ξ, h];
    and vSv, (I − v)S(I − v) (S = E_ij + E_ji) (proof of Lemma LEMA1 with h₁ = 0)."""
    n = int(s.n)
    v = X @ X.T
    N = s.In - v
    U = matrix_units(s, "n", "n")
    out = []
    for i in range(n):
        for j in range(n):
            E = U[i * n + j]
            if i < j:
                for xi in (v @ (E - E.T) @ v, N @ (E - E.T) @ N):
                    w = -comm(xi, h)
                    out.append(xi + N @ w @ v - v @ w @ N)
            if i <= j:
                S = E + E.T
                out += [v @ S @ v, N @ S @ N]
    return out


def a2_checks(s, drop):
    n, r = int(s.n), int(s.r)
    Pt = s.P - s.X @ (s.X.T @ s.P)
    h = Pt @ s.X.T - s.X @ Pt.T
    x = h + s.X @ s.X.T
    ks = kernel_spanning_set(s, s.X, h)
    z = s.fresh("n", "n")
    m = len(ks)
    G = s.mat([[lam1(x, ks[a], ks[b]) - lam2(x, s.A, ks[a], ks[b]) for b in range(m)] for a in range(m)], ("?", "?"))
    checks = {f"Lambda_1(k_{a}, z)": lam1(x, ks[a], z) for a in range(m)}
    checks["rank of Lambda_(1,-1) on ker Lambda_1"] = Rank(G, r * r + (n - r) ** 2 - drop)
    return checks


