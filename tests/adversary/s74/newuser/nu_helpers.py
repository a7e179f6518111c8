"""Helpers shared by the new user's claims files (no claims here, as docs/guide.md advises)."""


def neumann_kappa(t):
    """H_{neum,kappa} of (neumann): 1/2 tr P^T P - (1/2 + kappa) tr (X^T P)^2 + 1/2 tr X^T A X."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def printed_No(s):
    """The printed right-hand side of (No) at the scene's kappa."""
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * s.kappa
    return {"X": P - c * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + c * (P @ X.T @ P) + X @ X.T @ A @ X}
