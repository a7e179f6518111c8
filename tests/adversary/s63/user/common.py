"""Helpers shared by claims.py and negatives.py (no claims here)."""


def killing(t, a, b):
    return -t.tr(a @ b) / 2


def H_E(t):
    """(Euclidean): H_E = 1/2 tr P^T P."""
    return t.tr(t.P.T @ t.P) / 2


def H_0(t):
    """(normal_metric) written as 1/2 <Phi, Phi>."""
    return killing(t, t.Phi, t.Phi) / 2


def manakov_cubic(t, xi):
    """The Manakov operator for B = A^3: ad_A^{-1} ad_{A^3} xi = A^2 xi + A xi A + xi A^2."""
    A = t.A
    return A @ A @ xi + A @ xi @ A + xi @ A @ A


def H_cubic(t):
    """Submersion Hamiltonian 1/2 <AA(Phi), Phi> with the B = A^3 Manakov operator."""
    return killing(t, manakov_cubic(t, t.Phi), t.Phi) / 2


def H_neum0_theta(t):
    """H o Theta with H(h + v) = 1/2 <h,h> - <A, v>, h = Phi, v = X X^T."""
    return killing(t, t.Phi, t.Phi) / 2 - killing(t, t.A, t.X @ t.X.T)


def H_neum0(t):
    return t.tr(t.P.T @ t.P) / 2 - t.tr(t.X.T @ t.P @ t.X.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def L_dual(t):
    from stiefelsym import block
    R = t.resolvent(t.lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])
