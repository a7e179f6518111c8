"""h4 hidden trial: the false twins (one change each), stated where they are false."""
from __future__ import annotations

from stiefelsym import claim, comm, twisted
from stiefelsym.systems import complex_point, coupled_point, ctranspose, derivative, double_point, realify_real

from _h4common import (ANY, N_GE2, R2, R_GE2, R_GE3, R_LT_N, H_E, H_N, H_kappa, U_pot, Phi_eta, L_mag,
                       el_double_tangent, Lam_dbl, deq_tangent, L_dual_dbl, coupled_flow, W_eq_tangent)


@claim("h4t-mag-multipliers", kind="id", sizes=R_GE2)
def mag_multipliers(s):
    """Twin: factor ½ dropped in front of ε(KF + FK).  False for r ≥ 2 (r = 1: K = 0)."""
    f = twisted.multiplier_flow(s, H_E, F=s.eta)
    K = s.X.T @ s.P
    F = s.eta
    return {"Pi": f["Pi"],
            "Lambda": f["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P + s.eps * (K @ F + F @ K)),
            "Xdot": f.Xdot - s.P}


@claim("h4t-mag-spectral", kind="pb", sizes=R2)
def mag_spectral(s):
    """Twin: sign of λ²A flipped in 𝓛: tr 𝓛'² gains 4λ² tr(𝓛A), whose derivative 4λ² tr(Φ_ε[XXᵀ, A]) ≠ 0."""
    out = {}
    for name, H in (("euk", H_E), ("nor", H_N)):
        fl = twisted.flow(s, H)
        out[f"tr L^2 {name}"] = s.d(lambda t: t.tr(L_mag(t, +1) @ L_mag(t, +1)), fl)
    return out


@claim("h4t-mag-bracket-momentum", kind="pb", sizes=R_LT_N)
def mag_bracket_momentum(s):
    """Twin: sign of the right-hand side (= +⟨[XXᵀ, A], ξ⟩): residual 2t ≠ 0 for r < n (t = tr(Aξ) = 0 at r = n)."""
    f = lambda t: t.killing(Phi_eta(t), t.xi)
    return {"{H, <Phi_F, xi>}_F - <[XX^T, A], xi>": twisted.bracket(s, H_kappa, f, F=s.eta)
            - s.killing(comm(s.X @ s.X.T, s.A), s.xi)}


@claim("h4t-mag-potential-flow", kind="id", sizes=R_LT_N)
def mag_potential_flow(s):
    """Twin: the projector dropped (Ṗ = −AX): false for r < n."""
    fl = twisted.flow(s, U_pot, F=s.eta)
    return {"Xdot": fl.Xdot, "Pdot": fl.Pdot + s.A @ s.X}


@claim("h4t-mag-right-momentum", kind="pb", sizes=R_GE3)
def mag_right_momentum(s):
    """Twin: a component of Ψ along θ ∉ centralizer of F: d tr(Ψθ)/dt = ε tr(S[θ, F]) ≠ 0 for r ≥ 3."""
    fl = twisted.flow(s, H_kappa, F=s.eta)
    return {"dH/dt": s.d(H_kappa, fl),
            "d tr(Psi theta)/dt": s.d(lambda t: t.tr(t.Psi @ t.theta), fl)}


@claim("h4t-mag-rank-one", kind="id", sizes=R_GE2)
def mag_rank_one(s):
    """Twin: the same equality at r ≥ 2, where F = η ≠ 0 (the Lorentz force changes Ṗ)."""
    fl = twisted.flow(s, H_kappa, F=s.eta)
    d = s.dirac_flow(H_kappa)
    return {"X": fl.Xdot - d.Xdot, "P": fl.Pdot - d.Pdot}


@claim("h4t-double-energy", kind="pb", sizes=R_LT_N)
def double_energy(s):
    """Twin: the Lagrangian T − U in place of the energy T + U (sign of the potential).  True at r = n (YXᵀ = I, tr XᵀAY = tr A), so stated for r < n."""
    z, tan = el_double_tangent(s)
    E = lambda t, w: t.tr(w["Xdot"].T @ w["Ydot"]) - t.tr(w["X"].T @ t.A @ w["Y"])
    return {"dE/dt": derivative(s, E, z, tan)}


@claim("h4t-double-trace-L2", kind="pb", sizes=ANY)
def double_trace_L2(s):
    """Twin: the printed (I − λA)⁻¹ off the diagonal (the erratum of Theorem 10.1): tr 𝓛² not conserved."""
    z = double_point(s)
    return {"d tr L^2/dt": derivative(s, lambda t, w: (L_dual_dbl(t, w, True) @ L_dual_dbl(t, w, True)).trace(), z,
                                      deq_tangent(s, z))}


@claim("h4t-double-lax-block21", kind="lax", sizes=R_GE2)
def double_lax_block21(s):
    """Twin: the orders of the products with Λ − λ swapped; equal at r = 1 only."""
    z = double_point(s)
    R = s.resolvent(s.lam)
    M = Lam_dbl(s, z) - s.lam * s.Ir
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    lhs = derivative(s, lambda t, w: w["Xdot"].T @ t.resolvent(t.lam) @ w["Ydot"], z, deq_tangent(s, z))
    return {"block21": lhs - (X.T @ R @ Yd @ M + M @ Xd.T @ R @ Y)}


@claim("h4t-coupled-prep", kind="id", sizes=N_GE2)
def coupled_prep(s):
    """Twin: index swap AYXᵀ → AXYᵀ in the first rate (differs by A(XYᵀ − YXᵀ) ≠ 0, n ≥ 2)."""
    z = coupled_point(s)
    fl = coupled_flow(s)
    X, Y, A = s.X, s.Y, s.A
    return {"dPhiX": derivative(s, lambda t, w: w["P"] @ w["X"].T - w["X"] @ w["P"].T, z, fl) - (X @ Y.T @ A - A @ X @ Y.T)}


@claim("h4t-complex-prep", kind="id", sizes=R_GE2)
def complex_prep(s):
    """Twin: conjugation dropped (plain transposes Zᵀ): residual Z(Λ − Λᵀ)Zᵀ ≠ 0 for r ≥ 2 (Λ real at r = 1)."""
    z = complex_point(s)
    A = realify_real(s, s.A)
    tan = W_eq_tangent(s, z)
    T = lambda t, M: ctranspose(t, M)
    G = z["Z"] @ T(s, z["Z"])
    return {"dM/dt": derivative(s, lambda t, w: w["Zdot"] @ T(t, w["Z"]) - w["Z"] @ T(t, w["Zdot"]), z, tan) - comm(G, A)}
