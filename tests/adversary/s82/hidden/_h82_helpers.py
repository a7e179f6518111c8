"""Helpers (no claims) for the s82 hidden statements: Hamiltonians and flows written from the paper's
formulas with the public API only."""
from stiefelsym import twisted
from stiefelsym.systems import ctranspose, re_trace, realify_real


def H_kappa(t):
    """(neumann): H = ½tr PᵀP − (½ + κ) tr (XᵀP)² + ½ tr XᵀAX (κ generic)."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_kappa_at(t, z):
    K = z["X"].T @ z["P"]
    return t.tr(z["P"].T @ z["P"]) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(z["X"].T @ t.A @ z["X"]) / 2


def H_euclid_neumann(t):
    """(neumann) at κ = −½: ½ tr PᵀP + ½ tr XᵀAX."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_normal(t):
    """(normal_metric): H₀ = ½⟨Φ, Φ⟩."""
    return t.killing(t.Phi, t.Phi) / 2


def H_manakov(t):
    """Submersion metric with 𝔸(ξ) = Aξ + ξA (Manakov, B = A²): ½⟨Φ, AΦ + ΦA⟩ = −½ tr(Φ²A)."""
    return -t.tr(t.Phi @ t.Phi @ t.A) / 2


def psi12(t):
    """Ψ₁₂ = (e₁, p₂) − (e₂, p₁) = ⟨Ψ, J⟩, J = E₁∧E₂ (r = 2)."""
    return t.killing(t.Psi, twisted.magnetic_matrix(t))


def flow_double(t, z):
    """(D-eq), (D-L): Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ, Λ = XᵀAY − ẊᵀẎ."""
    Lam = z["X"].T @ t.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]
    return {"X": z["Xdot"], "Y": z["Ydot"],
            "Xdot": -(t.A @ z["X"]) + z["X"] @ Lam.T, "Ydot": -(t.A @ z["Y"]) + z["Y"] @ Lam}


def H_coupled(t, z):
    """(C-neumann): T_κ + tr XᵀAY."""
    XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    c = t.q(1, 2) + t.kappa
    return (t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(XP @ XP) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(YQ @ YQ)
            + t.tr(z["X"].T @ t.A @ z["Y"]))


def flow_complex(t, z):
    """(W-eq), (W-L): Z̈ = −AZ + ZΛ, Λ = Z̄ᵀAZ − Ż̄ᵀŻ (realified)."""
    Z, Zd, A = z["Z"], z["Zdot"], realify_real(t, t.A)
    Lam = ctranspose(t, t.conj(Z)) @ A @ Z - ctranspose(t, t.conj(Zd)) @ Zd
    return {"Z": Zd, "Zdot": -(A @ Z) + Z @ Lam}


def psi_sum(t, w):
    """Σ_j ψ_j = tr(ŻZ̄ᵀ − ZŻ̄ᵀ) (complex), as [Re, Re(i·)]."""
    M = w["Zdot"] @ ctranspose(t, t.conj(w["Z"])) - w["Z"] @ ctranspose(t, t.conj(w["Zdot"]))
    i = t.realify(t.In - t.In, t.In)
    return [re_trace(t, M), re_trace(t, i @ M)]


def psi0_trace(t, w):
    """tr ψ₀, ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ (r × r), as [Re, Re(i·)]."""
    M = ctranspose(t, w["Z"]) @ t.conj(w["Zdot"]) - ctranspose(t, w["Zdot"]) @ t.conj(w["Z"])
    i = t.realify(t.Ir - t.Ir, t.Ir)
    return [re_trace(t, M), re_trace(t, i @ M)]
