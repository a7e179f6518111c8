# ruff: noqa
"""Helpers shared by claims.py and negatives.py of s73 (no claims here)."""
from stiefelsym import block, comm, det, elementary, twisted
from stiefelsym.systems import ctranspose, re_trace, realify_real


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


def tr_pow(s, M, k):
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


def uhlenbeck_F(t):
    """(Mum_geod), r = 1: F_i = e_i² + Σ_{j≠i} (e_ip_j − e_jp_i)²/(a_i − a_j), i = 1..n."""
    n, a, e, Phi = int(t.n), t.a, t.X, Phi_of(t.X, t.P)
    out = []
    for i in range(n):
        acc = e[i, 0] * e[i, 0]
        for j in range(n):
            if j != i:
                acc = acc + Phi[i, j] * Phi[i, j] / (a[i] - a[j])
        out.append(acc)
    return out


def H_sphere(t):
    """(sphere_neum): ½(p, p) + ½(Ae, e)."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def sphere_flow(s):
    """ė = p, ṗ = −Ae + ((Ae, e) − (p, p))e."""
    e, p, A = s.X, s.P, s.A
    return {"X": p, "P": -(A @ e) + e @ (e.T @ A @ e - p.T @ p)}


def H_quartic(t):
    """(quartic): ½tr(PᵀP) + tr(XᵀA²X) − tr(XᵀAXXᵀAX)."""
    X, P, A = t.X, t.P, t.A
    M = X.T @ A @ X
    return t.tr(P.T @ P) / 2 + t.tr(X.T @ A @ A @ X) - t.tr(M @ M)


def L_dual(t, lam):
    """(LA3) 𝓛*(λ) = [[−XᵀRP, −XᵀRX], [I + PᵀRP, PᵀRX]], R = (λI − A)⁻¹."""
    R, X, P = t.resolvent(lam), t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def L_big(t, lam):
    """(LA2) 𝓛(λ) = λΦ + XXᵀ − λ²A."""
    return Phi_of(t.X, t.P) * lam + t.X @ t.X.T - t.A * (lam * lam)


def wedge2(s, X):
    """e_1 ∧ e_2 = e_1e_2ᵀ − e_2e_1ᵀ = XFXᵀ, F = E_1∧E_2 (r = 2)."""
    F = twisted.magnetic_matrix(s)
    return X @ F @ X.T


def cayley(s, M, I):
    return (I - M) @ (I + M).inv()


def H_coupled(t, z):
    """(C-neumann) with a free κ: T_κ + tr(XᵀAY)."""
    X, P, Y, Q = z["X"], z["P"], z["Y"], z["Q"]
    c = t.q(1, 2) + t.kappa
    K, L = X.T @ P, Y.T @ Q
    return (t.tr(P.T @ P) / 2 - c * t.tr(K @ K) + t.tr(Q.T @ Q) / 2 - c * t.tr(L @ L)
            + t.tr(X.T @ t.A @ Y))


# -- complex Stiefel variety W(n, r), realified -----------------------------------------------------

def cstar(M):
    """M* (conjugate transpose) of a realified complex matrix is its real transpose."""
    return M.T


def lagrangian_complex(t, Z, Zd):
    """(W-Lag) ½tr(ŻᵀŻ̄) − ½tr(ZᵀAZ̄) = ½tr(Ż*Ż) − ½tr(Z*AZ) (real)."""
    A = realify_real(t, t.A)
    return re_trace(t, cstar(Zd) @ Zd) / 2 - re_trace(t, cstar(Z) @ A @ Z) / 2


def Lambda_complex(t, Z, Zd):
    """(W-L) Λ = Z̄ᵀAZ − Ż̄ᵀŻ = Z*AZ − Ż*Ż."""
    A = realify_real(t, t.A)
    return cstar(Z) @ A @ Z - cstar(Zd) @ Zd


def psi0_complex(t, Z, Zd):
    """ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ (plain transposes)."""
    T = lambda M: ctranspose(t, M)
    return T(Z) @ t.conj(Zd) - T(Zd) @ t.conj(Z)


def unitary_r(t, eta, S):
    """U = (I − K)(I + K)⁻¹, K = η + iS skew-Hermitian (η skew, S symmetric r × r), realified."""
    K = t.realify(eta, S)
    I = realify_real(t, t.Ir)
    return (I - K) @ (I + K).inv()
