# ruff: noqa
"""Helpers shared by claims.py and negatives.py (no claims here)."""
from stiefelsym import block

r_lt_n = dict(where=lambda n, r: r < n, condition="r < n (the block n − r is not empty)")


def X0_of(s):
    return block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])


def Zrr(s):
    return s.zeros(s.r, s.r, ("r", "r"))


def Znr(s, k):
    return s.zeros(s.n - s.r, k, ("n-r", k))


def I_nr(s):
    m = s.n - s.r
    return s.mat([[1 if i == j else 0 for j in range(m)] for i in range(m)], ("n-r", "n-r"))


def skew_nr(s, name):
    G = s.generic(name, "n-r", "n-r")
    return G - G.T


def sym_nr(s, name):
    G = s.generic(name, "n-r", "n-r")
    return G + G.T


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


def diag_blocks(s, a, b):
    """diag(a, b) on ℝⁿ = ℝʳ ⊕ ℝⁿ⁻ʳ."""
    return block([[a, s.zeros(s.r, s.n - s.r, ("r", "n-r"))], [s.zeros(s.n - s.r, s.r, ("n-r", "r")), b]])


def so_nr_basis(s):
    m = s.n - s.r
    out = []
    for i in range(m):
        for j in range(i + 1, m):
            out.append(s.mat([[(1 if (a, b) == (i, j) else -1 if (a, b) == (j, i) else 0) for b in range(m)]
                              for a in range(m)], ("n-r", "n-r")))
    return out


def action_matrix(s, P2):
    """columns: the entries of βP2 for β in the basis of so(n − r)."""
    r, m = s.r, s.n - s.r
    cols = []
    for beta in so_nr_basis(s):
        M = beta @ P2
        cols.append([M[i, j] for i in range(m) for j in range(r)])
    return s.mat([list(row) for row in zip(*cols)])


def dso(m):
    return m * (m - 1) // 2 if m > 1 else 0


