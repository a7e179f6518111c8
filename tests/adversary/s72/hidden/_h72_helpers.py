# ruff: noqa
"""Helpers shared by claims.py and negatives.py of s72 (no claims here)."""
from stiefelsym import block, comm, elementary, twisted
from stiefelsym.brackets import MatrixFunction, skew, sym
from stiefelsym.systems import complex_point, ctranspose, derivative, re_trace, realify_real


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


def tr_pow(s, M, k):
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


def H_neum_kappa(t):
    """(neumann): ½tr PᵀP − (½ + κ)tr (XᵀP)² + ½tr XᵀAX."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neum_c(c):
    """H_neum,κ at a fixed rational κ = c (c a function of the scene)."""
    def H(t):
        K = t.X.T @ t.P
        return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + c(t)) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2
    return H


def L_neum(t, lam, signA=-1):
    """(LA2) 𝓛(λ) = λΦ + XXᵀ − λ²A (signA = −1 as printed)."""
    return Phi_of(t.X, t.P) * lam + t.X @ t.X.T + t.A * (lam * lam * signA)


def manakov_a3(s, xi, middle=1):
    """The Manakov operator for B = A³: ad_A⁻¹ad_{A³} ξ = A²ξ + AξA + ξA² (middle = the sign of AξA)."""
    A = s.A
    return A @ A @ xi + (A @ xi @ A) * middle + xi @ A @ A


def H_manakov_a3(t):
    """(submersion_metric) H_𝔸 = ½<𝔸Φ, Φ> for 𝔸 = ad_A⁻¹ad_{A³}."""
    Phi = Phi_of(t.X, t.P)
    return t.killing(manakov_a3(t, Phi), Phi) / 2


def Phi_eps(t):
    """(mag-mom-stief) Φ_ε = Φ + ε e₁∧e₂ = Φ + ε X F Xᵀ, F = E₁∧E₂ ∈ so(2)."""
    F = twisted.magnetic_matrix(t)
    return Phi_of(t.X, t.P) + (t.X @ F @ t.X.T) * t.eps


# -- complex Stiefel variety W(n, r) (Appendix 2), realified ---------------------------------------

def zero_r(t):
    return t.zeros(t.r, t.r, ("r", "r"))


def Lambda_complex(t, z):
    """(W-L): Λ = Z̄ᵀAZ − Ż̄ᵀŻ."""
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(t, t.A)
    return ctranspose(t, t.conj(Z)) @ A @ Z - ctranspose(t, t.conj(Zd)) @ Zd


def flow_complex(t, z):
    """(W-eq) as printed, first order: Ż = Zdot, Z̈ = −AZ + ZΛ."""
    A = realify_real(t, t.A)
    return {"Z": z["Zdot"], "Zdot": -(A @ z["Z"]) + z["Z"] @ Lambda_complex(t, z)}


def L_complex(t, z, off):
    """(LA3*) 𝓛(λ) with R = (λI − A)⁻¹ on the diagonal blocks and ``off`` in the off-diagonal ones."""
    R, F = realify_real(t, t.resolvent(t.lam)), realify_real(t, off)
    Z, Zd, T, bar = z["Z"], z["Zdot"], (lambda M: ctranspose(t, M)), t.conj
    I = realify_real(t, t.Ir)
    return block([[-(T(Z) @ R @ bar(Zd)), -(T(Z) @ F @ bar(Z))],
                  [I + T(Zd) @ F @ bar(Zd), T(Zd) @ R @ bar(Z)]])


def i_2r(t):
    """i·I_{2r} (complex), realified blockwise like L_complex."""
    J = t.realify(zero_r(t), t.Ir)
    O = realify_real(t, zero_r(t))
    return block([[J, O], [O, J]])
