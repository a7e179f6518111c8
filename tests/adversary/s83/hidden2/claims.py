"""h4 hidden trial: statements of Appendices 1 and 2 in my own formulation (true versions).

Derivations by hand are in each docstring; indep.py.in checks each numerically with plain numpy."""
from __future__ import annotations

from stiefelsym import claim, comm, twisted
from stiefelsym.systems import complex_point, coupled_point, derivative, realify_real

from _h4common import (ANY, R1, R2, H_E, H_N, H_kappa, U_pot, Phi_eta, L_mag,
                       el_double_tangent, Lam_dbl, deq_tangent, L_dual_dbl, coupled_flow,
                       star, W_eq_tangent)
from stiefelsym.systems import double_point


@claim("h4-mag-multipliers", kind="id", sizes=ANY)
def mag_multipliers(s):
    """Lagrange form of the twisted Euclidean Neumann flow, any rank, F = η ∈ so(r):
    Ẋ = P − XΠ, Ṗ = −AX − εẊF + XΛ + PΠ.  XᵀẊ + ẊᵀX = 0 gives Π = 0 (XᵀP skew).  Then
    d/dt(XᵀP + PᵀX) = 2PᵀP − 2XᵀAX + 2Λ − ε(KF + FK) with K = XᵀP (XᵀPF + FᵀPᵀX = KF + FK since PᵀX = −K).
    So Λ = XᵀAX − PᵀP + (ε/2)(KF + FK).  At r = 2, F = J: KF + FK = −2(e₁,p₂)I, which is the printed (mag-euk)."""
    f = twisted.multiplier_flow(s, H_E, F=s.eta)
    K = s.X.T @ s.P
    F = s.eta
    return {"Pi": f["Pi"],
            "Lambda": f["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P + s.eps * (K @ F + F @ K) / 2),
            "Xdot": f.Xdot - s.P}


@claim("h4-mag-spectral", kind="pb", sizes=R2)
def mag_spectral(s):
    """Spectral invariants: with 𝓛(λ) = λΦ_ε + XXᵀ − λ²A and d𝓛/dt = [𝓐, 𝓛] along (mag-euk), (mag-nor),
    tr 𝓛ᵏ is conserved for every λ; checked for k = 2, 3 as polynomials in λ, with the flows derived from ω_ε."""
    out = {}
    for name, H in (("euk", H_E), ("nor", H_N)):
        fl = twisted.flow(s, H)
        out[f"tr L^2 {name}"] = s.d(lambda t: t.tr(L_mag(t) @ L_mag(t)), fl)
        out[f"tr L^3 {name}"] = s.d(lambda t: t.tr(L_mag(t) @ L_mag(t) @ L_mag(t)), fl)
    return out


@claim("h4-mag-bracket-momentum", kind="pb", sizes=ANY)
def mag_bracket_momentum(s):
    """{H, ⟨Φ_F, ξ⟩}_F = −⟨[XXᵀ, A], ξ⟩ for H = H_neum,κ, F = η, any rank.  {H, f} is the derivative of H along
    the flow of f; the flow of ⟨Φ_F, ξ⟩ is (ξX, ξP) (momentum map); the kinetic part is O(n)-invariant and
    d(½tr XᵀAX) along ξX = tr(XᵀAξX) =: t.  ⟨[XXᵀ, A], ξ⟩ = −½tr((XXᵀA − AXXᵀ)ξ) = −½(t + t) = −t
    (tr(XXᵀξA) = −tr(AξXXᵀ)).  So the sum vanishes."""
    f = lambda t: t.killing(Phi_eta(t), t.xi)
    return {"{H, <Phi_F, xi>}_F + <[XX^T, A], xi>": twisted.bracket(s, H_kappa, f, F=s.eta)
            + s.killing(comm(s.X @ s.X.T, s.A), s.xi)}


@claim("h4-mag-potential-flow", kind="id", sizes=ANY)
def mag_potential_flow(s):
    """The twisted flow (F = η, any rank) of the potential U = ½tr XᵀAX alone: U_P = 0, so Ẋ = −XΠ and tangency
    gives Π = 0, Ẋ = 0; the Lorentz force −εẊF vanishes; Ṗ = −AX + XΛ, d/dt(XᵀP + PᵀX) = 2Λ − 2XᵀAX = 0,
    so Ṗ = −(I − XXᵀ)AX: the magnetic term does not see a function of X."""
    fl = twisted.flow(s, U_pot, F=s.eta)
    return {"Xdot": fl.Xdot, "Pdot": fl.Pdot + (s.In - s.X @ s.X.T) @ s.A @ s.X}


@claim("h4-mag-right-momentum", kind="pb", sizes=ANY)
def mag_right_momentum(s):
    """Along the twisted flow of H_neum,κ with F = η (any rank): dH/dt = 0, dΨ/dt = ε[F, XᵀẊ]
    (the untwisted part conserves Ψ; the Lorentz term −εẊF adds −εXᵀẊF + εFXᵀẊ, the multipliers drop out
    of the skew part), hence d/dt tr(Ψη) = ε tr([η, S]η) = 0: the component of Ψ along F is conserved."""
    fl = twisted.flow(s, H_kappa, F=s.eta)
    S = s.X.T @ fl.Xdot
    return {"dH/dt": s.d(H_kappa, fl),
            "dPsi/dt - eps[F, X^T Xdot]": s.d(lambda t: t.Psi, fl) - s.eps * comm(s.eta, S),
            "d tr(Psi eta)/dt": s.d(lambda t: t.tr(t.Psi @ t.eta), fl)}


@claim("h4-mag-rank-one", kind="id", sizes=R1)
def mag_rank_one(s):
    """At r = 1, so(1) = 0: F = η = 0 and the twisted flow is the Dirac flow of the canonical form."""
    fl = twisted.flow(s, H_kappa, F=s.eta)
    d = s.dirac_flow(H_kappa)
    return {"X": fl.Xdot - d.Xdot, "P": fl.Pdot - d.Pdot}


# ---------------------------------------------------------------------------------- Appendix 2

@claim("h4-double-energy", kind="pb", sizes=ANY)
def double_energy(s):
    """The energy E = tr(ẊᵀẎ) + tr(XᵀAY) of (D-Lag) is conserved along the Euler–Lagrange flow with (D0):
    with (D-eq) dE/dt = tr(ΛXᵀẎ) + tr(ẊᵀYΛ) = tr(Λ(XᵀẎ + ẊᵀY)) = 0 (derivative of (D0))."""
    z, tan = el_double_tangent(s)
    E = lambda t, w: t.tr(w["Xdot"].T @ w["Ydot"]) + t.tr(w["X"].T @ t.A @ w["Y"])
    return {"dE/dt": derivative(s, E, z, tan)}


@claim("h4-double-trace-L2", kind="pb", sizes=ANY)
def double_trace_L2(s):
    """tr 𝓛(λ)² is conserved along (D-eq) for the Lax matrix (LA3*D) with (λI − A)⁻¹ in all four blocks
    (d𝓛/dt = [𝓛, 𝓐] ⇒ d tr 𝓛² /dt = 2tr(𝓛[𝓛, 𝓐]) = 0)."""
    z = double_point(s)
    return {"d tr L^2/dt": derivative(s, lambda t, w: (L_dual_dbl(t, w) @ L_dual_dbl(t, w)).trace(), z,
                                      deq_tangent(s, z))}


@claim("h4-double-lax-block21", kind="lax", sizes=ANY)
def double_lax_block21(s):
    """Block (2,1) of (LA3*D) written out: along (D-eq), R = (λI − A)⁻¹, Λ = XᵀAY − ẊᵀẎ,
    d/dt(ẊᵀRẎ) = ẌᵀRẎ + ẊᵀRŸ = (ΛXᵀ − XᵀA)RẎ + ẊᵀR(YΛ − AY); AR = RA = λR − I gives
    (Λ − λ)XᵀRẎ + ẊᵀRY(Λ − λ) + XᵀẎ + ẊᵀY, and the last two cancel (derivative of (D0))."""
    z = double_point(s)
    R = s.resolvent(s.lam)
    M = Lam_dbl(s, z) - s.lam * s.Ir
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    lhs = derivative(s, lambda t, w: w["Xdot"].T @ t.resolvent(t.lam) @ w["Ydot"], z, deq_tangent(s, z))
    return {"block21": lhs - (M @ X.T @ R @ Yd + Xd.T @ R @ Y @ M)}


@claim("h4-coupled-prep", kind="id", sizes=ANY)
def coupled_prep(s):
    """Along the Hamiltonian flow of (C-neumann) on T*V × T*V, every κ: Ẋ = P − cXPᵀX, Ṗ = −AY + cPXᵀP + XΛ
    (c = 1 + 2κ, Λ symmetric), so d/dt(PXᵀ) = −AYXᵀ + XΛXᵀ + PPᵀ (the c terms cancel) and
    d/dt(PXᵀ − XPᵀ) = XYᵀA − AYXᵀ; symmetrically d/dt(QYᵀ − YQᵀ) = YXᵀA − AXYᵀ."""
    z = coupled_point(s)
    fl = coupled_flow(s)
    X, Y, A = s.X, s.Y, s.A
    return {"dPhiX": derivative(s, lambda t, w: w["P"] @ w["X"].T - w["X"] @ w["P"].T, z, fl) - (X @ Y.T @ A - A @ Y @ X.T),
            "dPhiY": derivative(s, lambda t, w: w["Q"] @ w["Y"].T - w["Y"] @ w["Q"].T, z, fl) - (Y @ X.T @ A - A @ X @ Y.T)}


@claim("h4-complex-prep", kind="id", sizes=ANY)
def complex_prep(s):
    """(prep) on W(n, r): along (W-eq), Z̈ = −AZ + ZΛ with Λ = Z*AZ − Ż*Ż Hermitian,
    d/dt(ŻZ* − ZŻ*) = −AZZ* + ZΛZ* + ZZ*A − ZΛ*Z* = [ZZ*, A], and d/dt(ZZ*) = ŻZ* + ZŻ* = [ŻZ* − ZŻ*, ZZ*]
    by Z*Z = I, Ż*Z + Z*Ż = 0."""
    z = complex_point(s)
    Z, Zd = z["Z"], z["Zdot"]
    A = realify_real(s, s.A)
    tan = W_eq_tangent(s, z)
    M = Zd @ star(Z) - Z @ star(Zd)
    G = Z @ star(Z)
    return {"dM/dt": derivative(s, lambda t, w: w["Zdot"] @ w["Z"].T - w["Z"] @ w["Zdot"].T, z, tan) - comm(G, A),
            "dG/dt": derivative(s, lambda t, w: w["Z"] @ w["Z"].T, z, tan) - comm(M, G)}
