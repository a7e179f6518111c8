# ruff: noqa
"""Helpers shared by claims.py and negatives.py of s74 (no claims here)."""
from stiefelsym import block


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


def mpow(s, M, k, I):
    out = I
    for _ in range(k):
        out = out @ M
    return out


def tr_pow(s, M, k):
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


def block_M(s, X, P, sign=-1):
    """The 2r x 2r matrix VU of Φ = UV, U = (P X), V = (Xᵀ; −Pᵀ): [[XᵀP, I_r], [−PᵀP, −PᵀX]]
    (``sign`` = +1: +PᵀP, the twin)."""
    return block([[X.T @ P, s.Ir], [(P.T @ P) * sign, -(P.T @ X)]])


def H_neum_kappa(t):
    """(neumann) with the scene's κ."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neum_0(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_normal(t):
    """(normal_metric): ½tr(PᵀP) − ½tr((XᵀP)²)."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2


def manakov_inv(t, xi):
    """The Manakov operator (Manakov) for B = −A⁻¹: 𝔸ξ = ad_A⁻¹ad_B ξ = A⁻¹ξA⁻¹."""
    return t.Ainv @ xi @ t.Ainv


def H_manakov_inv(t):
    """(submersion_metric) with 𝔸ξ = A⁻¹ξA⁻¹: −¼tr(A⁻¹ΦA⁻¹Φ)."""
    F = t.Phi
    return -t.tr(manakov_inv(t, F) @ F) / 4


def H_manakov_sq(t):
    """(submersion_metric) with (Manakov*), B = A²: 𝔸ξ = Aξ + ξA."""
    F = t.Phi
    return -t.tr((t.A @ F + F @ t.A) @ F) / 4


def H_not_manakov(t):
    """−¼tr(AΦAΦ): ξ ↦ AξA is not ad_A⁻¹ad_B for any B."""
    F = t.Phi
    return -t.tr(t.A @ F @ t.A @ F) / 4


def H_sphere(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def coupled_T(t, z):
    """T_0 of (C-neumann) (κ = 0)."""
    K, M = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    return t.tr(z["P"].T @ z["P"]) / 2 - t.tr(K @ K) / 2 + t.tr(z["Q"].T @ z["Q"]) / 2 - t.tr(M @ M) / 2


def coupled_V(t, z):
    return t.tr(z["X"].T @ t.A @ z["Y"])


def H_coupled0(t, z):
    return coupled_T(t, z) + coupled_V(t, z)


def L_so_nn(t, z, nu, sign):
    """(so(n,n)) L(ν) = ν[[0, A], [A, 0]] + diag(PXᵀ − XPᵀ, QYᵀ − YQᵀ) + sign·ν⁻¹[[0, XYᵀ], [YXᵀ, 0]]."""
    X, P, Y, Q, A = z["X"], z["P"], z["Y"], z["Q"], t.A
    Z = A - A
    return (block([[Z, A], [A, Z]]) * nu + block([[P @ X.T - X @ P.T, Z], [Z, Q @ Y.T - Y @ Q.T]])
            + block([[Z, X @ Y.T], [Y @ X.T, Z]]) * (t.q(sign) / nu))
