"""Helpers shared by claims.py and twins.py (no claims here)."""
from __future__ import annotations

from stiefelsym import block, comm, elementary
from stiefelsym.bases import matrix_of, matrix_units, so_basis


def H_kappa(t):
    """(neumann): ½tr PᵀP − (½ + κ)tr((XᵀP)²) + ½tr XᵀAX, κ the scene's generic parameter."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_kappa0(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.q(1, 2) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def L_star(t, lam):
    R = t.resolvent(lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def J_r(t):
    z = t.zeros(t.r, t.r, ("r", "r"))
    return block([[z, t.Ir], [-t.Ir, z]])


def e2_explicit(t, lam, sign=-1):
    """tr(R XXᵀ) + sign·½ tr(RΦRΦ) (sign = −1 the true one)."""
    R = t.resolvent(lam)
    return t.tr(R @ t.X @ t.X.T) + sign * t.q(1, 2) * t.tr(R @ t.Phi @ R @ t.Phi)


def constraints(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def theta(t):
    return t.Phi + t.X @ t.X.T


def theta_jacobian(s):
    rows = s.jacobian(lambda t: [theta(t)], symmetric=False) + s.jacobian(constraints, symmetric=True)
    return s.mat(rows)


def so_r_fields(s):
    """Columns: (Xη, Pη) for η = E_a∧E_b ∈ so(r), in the Jacobian's coordinates (X row by row, then P)."""
    n, r = int(s.n), int(s.r)
    cols = []
    for eta in so_basis(s, "r"):
        V, W = s.X @ eta, s.P @ eta
        cols.append([V[i, j] for i in range(n) for j in range(r)] + [W[i, j] for i in range(n) for j in range(r)])
    return s.mat([list(row) for row in zip(*cols)]) if cols else None


def l1_matrix(s):
    v = s.X @ s.X.T
    return matrix_of(s, lambda xi: comm(xi, v), so_basis(s, "n"), "sym")


def l1_kernel(s):
    """Coordinates (ξ_ij, i < j) of XηXᵀ (η ∈ so(r)) and of (I − XXᵀ)E(I − XXᵀ) (E ∈ so(n))."""
    n = int(s.n)
    Q = s.In - s.X @ s.X.T
    els = [s.X @ eta @ s.X.T for eta in so_basis(s, "r")] + [Q @ E @ Q for E in so_basis(s, "n")]
    cols = [[xi[i, j] for i in range(n) for j in range(i + 1, n)] for xi in els]
    return s.mat([list(row) for row in zip(*cols)])


def centralizer_kernel(s, x):
    """Coordinates (entries, row by row) of x^k (k = 0..n−1) and, when 2r < n, of E0 E_ab E0 with
    E0 = c'(x) = Σ_{j ≤ 2r} (−1)^j e_j(x) x^{2r−j} (x = diag(x', 0) on span(X, P) ⊕ its complement, c' the
    characteristic polynomial of x'; x E0 = E0 x = 0)."""
    n, r = int(s.n), int(s.r)
    els, p = [], s.In
    for k in range(n):
        els.append(p)
        p = p @ x
    if 2 * r < n:
        e = elementary(s, x, 2 * r)
        E0 = s.zeros(s.n, s.n, ("n", "n"))
        pw = s.In
        for j in range(2 * r, -1, -1):
            term = pw * e[j]
            E0 = E0 + (term if j % 2 == 0 else -term)
            pw = pw @ x
        els += [E0 @ E @ E0 for E in matrix_units(s, "n", "n")]
    cols = [[M[i, j] for i in range(n) for j in range(n)] for M in els]
    return s.mat([list(row) for row in zip(*cols)])


def gl_orbit_rank(n, r):
    m = min(2 * r, n)
    return n * n - m - (n - m) ** 2
