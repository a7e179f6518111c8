# ruff: noqa
"""Shared helpers of claims.py and negatives.py (no claims here)."""
from stiefelsym import twisted, systems


def H_kappa(t):
    """H_{neum,kappa} of (neumann): ½tr PᵀP − (½+κ) tr (XᵀP)² + ½ tr XᵀAX."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_normal(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_eucl(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def no_flow(t):
    """The printed flow (No) with a generic κ."""
    X, P, A = t.X, t.P, t.A
    c = 1 + 2 * t.kappa
    return {"X": P - c * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + c * (P @ X.T @ P) + X @ X.T @ A @ X}


def wedge(a, b):
    return a @ b.T - b @ a.T


def L_hat(t):
    """μ²·L(1/μ): the Lax matrix of (LA2) in the reciprocal parameter."""
    lam = t.lam
    return lam * lam * (t.X @ t.X.T) + lam * t.Phi - t.A


def L_eps(t, eps_sign=1):
    E1, E2 = twisted.basis_vector(t, 0), twisted.basis_vector(t, 1)
    e1, e2 = t.X @ E1, t.X @ E2
    Phi_eps = t.Phi + eps_sign * t.eps * wedge(e1, e2)
    return t.lam * Phi_eps + t.X @ t.X.T - t.lam * t.lam * t.A, Phi_eps


def cross_col(t, u, v):
    """u × v for 3×1 columns, as a 3×1 matrix (n = 3 only)."""
    return t.mat([[u[1, 0] * v[2, 0] - u[2, 0] * v[1, 0]],
                  [u[2, 0] * v[0, 0] - u[0, 0] * v[2, 0]],
                  [u[0, 0] * v[1, 0] - u[1, 0] * v[0, 0]]], ("n", "?"))


def coupled_H(kappa_sym):
    def H(t, z):
        X, P, Y, Q = z["X"], z["P"], z["Y"], z["Q"]
        K, M = X.T @ P, Y.T @ Q
        c = t.q(1, 2) + kappa_sym(t)
        return (t.tr(P.T @ P) / 2 - c * t.tr(K @ K) + t.tr(Q.T @ Q) / 2 - c * t.tr(M @ M)
                + t.tr(X.T @ t.A @ Y))
    return H


def double_tangent(t, z):
    """The printed (D-eq), (D-L): Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ, Λ = XᵀAY − ẊᵀẎ."""
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    Lam = X.T @ t.A @ Y - Xd.T @ Yd
    return {"X": Xd, "Y": Yd, "Xdot": -(t.A @ X) + X @ Lam.T, "Ydot": -(t.A @ Y) + Y @ Lam}
