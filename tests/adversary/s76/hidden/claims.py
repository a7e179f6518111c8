# ruff: noqa
"""s76 hidden round: further statements of Fedorov & Jovanović written with the public API only.
Every claim here is true as stated (checked independently in indep.py.in); the false twins are in negatives.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm, elementary
from stiefelsym.systems import coupled_point, derivative, stiefel_pairs_flow

from _h76_helpers import (H_man_a2, H_man_ainv, H_neum, H_neum_k, L_big, L_dual, coupled_H_kappa, e_rphi, killing)

SMALL = admissible(n_max=4)
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2 (so(1) = 0)")
TWO_R_LE_N = admissible(n_max=5, n_min=2, where=lambda n, r: 2 * r <= n, condition="2r <= n (Chasles-Manakov)")


# 1 ----------------------------------------------------------------------------------------------
@claim("h76-phi-normal-block", paper=("LEMA1", "momentum_map", "grassmannian"), kind="id", sizes=SMALL)
def phi_normal_block(s):
    """§6, proof of Lemma LEMA1: at X0 = (E_1..E_r), h = Φ(X0, P0) = [[h1, h2], [-h2ᵀ, 0]]: the
    (n-r)×(n-r) block of Φ vanishes; coordinate-free, with π = XXᵀ: (I - π)Φ(I - π) = 0 and
    πΦ + Φπ - Φ = XΨXᵀ (h1 = Ψ; on Ψ⁻¹(0), §7, Φ = πΦ + Φπ)."""
    pi = s.X @ s.X.T
    Q = s.In - pi
    return {"(I-pi) Phi (I-pi)": Q @ s.Phi @ Q,
            "pi Phi + Phi pi - Phi - X Psi X^T": pi @ s.Phi + s.Phi @ pi - s.Phi - s.X @ s.Psi @ s.X.T}


# 2 ----------------------------------------------------------------------------------------------
@claim("h76-manakov-j2r-resolvent", paper=("Chasles-Manakov", "Manakov*", "dot_XP2"), kind="pb", sizes=TWO_R_LE_N)
def manakov_j2r_resolvent(s):
    """§8, Theorem Chasles-Manakov: J_2r(λ)/a(λ) = Σ_{I_2r} |Φ|^I_I / Π(λ - a_i) = e_2r(RΦ), R = (λ - A)⁻¹, is
    an integral of the Manakov flow with B = A² (𝔸ξ = Aξ + ξA, H = ½<Φ, 𝔸Φ> = −½tr(AΦ²)); the odd
    coefficients e_1(RΦ), e_3(RΦ) vanish (RΦ is similar to the skew R^{1/2}ΦR^{1/2})."""
    r = int(s.r)
    fl = s.dirac_flow(H_man_a2)
    es = elementary(s, s.resolvent(s.lam) @ s.Phi, max(2 * r, 3))
    return {"d e_2r(R Phi)/dt": s.d(lambda t: e_rphi(t, 2 * r), fl),
            "H_AA - (-1/2 tr A Phi^2)": killing(s, s.Phi, s.A @ s.Phi + s.Phi @ s.A) / 2 - H_man_a2(s),
            "e_1(R Phi)": es[1], "e_3(R Phi)": es[3]}


# 3 ----------------------------------------------------------------------------------------------
@claim("h76-so-n-invariants-closed", paper=("SO(n)-inv", "momentum_map", "LEMA"), kind="pb", sizes=SMALL)
def so_n_invariants_closed(s):
    """§2, 'The algebra of SO(n)-invariant functions': since SO(n) acts in a Hamiltonian way,
    C^∞(T*V)^{SO(n)} is closed under the Poisson bracket: for F = tr(C₁PᵀP), G = tr(C₂XᵀP) (C₁, C₂
    constant r×r), {Φ_ξ, F} = {Φ_ξ, G} = 0 and {Φ_ξ, {F, G}} = 0."""
    C1, C2 = s.generic("C1", "r", "r"), s.generic("C2", "r", "r")
    F = lambda t: t.tr(C1 @ t.P.T @ t.P)
    G = lambda t: t.tr(C2 @ t.X.T @ t.P)
    phi_xi = lambda t: killing(t, t.Phi, s.xi)
    return {"{Phi_xi, F}": s.bracket(phi_xi, F), "{Phi_xi, G}": s.bracket(phi_xi, G),
            "{Phi_xi, {F, G}}": s.bracket(phi_xi, lambda t: t.bracket(F, G))}


# 4 ----------------------------------------------------------------------------------------------
@claim("h76-so-r-invariants-closed", paper=("REDUCED_BRACKET", "momentum_right_map", "right_action"), kind="pb",
       sizes=SMALL)
def so_r_invariants_closed(s):
    """§6, (REDUCED_BRACKET): the induced bracket {f, g}' on (T*V)/SO(r) is well defined: the bracket of two
    right SO(r)-invariant functions is again invariant.  F = tr(XᵀAP), G = tr(PᵀA²P):
    {Ψ_η, F} = {Ψ_η, G} = {Ψ_η, {F, G}} = 0."""
    F = lambda t: t.tr(t.X.T @ t.A @ t.P)
    G = lambda t: t.tr(t.P.T @ t.A @ t.A @ t.P)
    psi_eta = lambda t: killing(t, t.Psi, s.eta)
    return {"{Psi_eta, F}": s.bracket(psi_eta, F), "{Psi_eta, G}": s.bracket(psi_eta, G),
            "{Psi_eta, {F, G}}": s.bracket(psi_eta, lambda t: t.bracket(F, G))}


# 5 ----------------------------------------------------------------------------------------------
@claim("h76-torus-functions-commute", paper=("torus", "perelomov", "NEUMANN", "REDUCED_BRACKET"), kind="pb",
       sizes=SMALL)
def torus_functions_commute(s):
    """§6, proof of Theorem NEUMANN: the functions (torus) commute with all the integrals Θ*𝓕 + Ψ*(C^∞(so(r))):
    J_1 = tr Ψ² and J_2 = tr Ψ⁴ commute with Ψ_η and with tr 𝓛(λ)³, and the Perelomov integrals
    tr 𝓛(λ)^k (𝓛 = λΦ + XXᵀ − λ²A) are right SO(r)-invariant: {Ψ_η, tr 𝓛(λ)³} = 0."""
    J1 = lambda t: t.tr(t.Psi @ t.Psi)
    J2 = lambda t: t.tr(t.Psi @ t.Psi @ t.Psi @ t.Psi)
    L3 = lambda t: t.tr(L_big(t) @ L_big(t) @ L_big(t))
    psi_eta = lambda t: killing(t, t.Psi, s.eta)
    return {"{J1, Psi_eta}": s.bracket(J1, psi_eta), "{J2, Psi_eta}": s.bracket(J2, psi_eta),
            "{J1, tr L^3}": s.bracket(J1, L3), "{Psi_eta, tr L^3}": s.bracket(psi_eta, L3)}


# 6 ----------------------------------------------------------------------------------------------
@claim("h76-coupled-perturbed-momentum", paper=("C-neumann", "C-eq", "so(n,n)"), kind="pb",
       sizes=admissible(n_max=3))
def coupled_perturbed_momentum(s):
    """App. 2: the perturbed coupled Hamiltonian H_κ = T_κ + tr(XᵀAY) − 2κ tr(XᵀP YᵀQ) is invariant under the
    right diagonal SO(r)-action, so the diagonal momentum XᵀP − PᵀX + YᵀQ − QᵀY is conserved by its flow for
    every κ, as is H_κ."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, coupled_H_kappa, z, [("X", "P"), ("Y", "Q")])
    mom = lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"] + w["Y"].T @ w["Q"] - w["Q"].T @ w["Y"]
    return {"d(diag momentum)/dt": derivative(s, mom, z, fl),
            "dH_kappa/dt": derivative(s, coupled_H_kappa, z, fl)}


# 7 ----------------------------------------------------------------------------------------------
@claim("h76-manakov-ainv-shares-j", paper=("Chasles-Manakov", "sp1", "man-dual"), kind="pb", sizes=TWO_R_LE_N)
def manakov_ainv_shares_j(s):
    """§8, before Theorem Chasles-Manakov: Manakov flows with different B move over the same foliation, so
    J_2r(λ)/a(λ) = e_2r(RΦ) is also an integral of the Manakov flow with B = −A⁻¹ (𝔸ξ = A⁻¹ξA⁻¹, the Poisson
    sphere case at r = 1), as is e_2(RΦ)."""
    r = int(s.r)
    fl = s.dirac_flow(H_man_ainv)
    return {"d e_2r(R Phi)/dt": s.d(lambda t: e_rphi(t, 2 * r), fl),
            "d e_2(R Phi)/dt": s.d(lambda t: e_rphi(t, 2), fl)}


# 8 ----------------------------------------------------------------------------------------------
@claim("h76-neumann-flows-differ", paper=("No", "N0_XP2", "NE_XP"), kind="not", expect="nonzero",
       sizes=R_GE_2)
def neumann_flows_differ(s):
    """§5, 'for different κ the flows (No) do not coincide' (r >= 2): the Ẋ of (N0_XP2) and (NE_XP) differ."""
    f0 = s.dirac_flow(H_neum(s.q(0)))
    fe = s.dirac_flow(H_neum(s.q(-1, 2)))
    return {"Xdot(kappa=0) - Xdot(kappa=-1/2)": f0["X"] - fe["X"]}


# 9 ----------------------------------------------------------------------------------------------
@claim("h76-psi-twice-xtp", paper=("grassmannian", "momentum_right_map", "cond_XP"), kind="id", sizes=SMALL)
def psi_twice_xtp(s):
    """§7: '(X, P) belongs to Ψ⁻¹(0) if and only if XᵀP = 0': on T*V, XᵀP is skew, so Ψ = 2XᵀP = −2PᵀX."""
    return {"Psi - 2 X^T P": s.Psi - 2 * (s.X.T @ s.P), "Psi + 2 P^T X": s.Psi + 2 * (s.P.T @ s.X)}


# 10 ---------------------------------------------------------------------------------------------
@claim("h76-dual-e4-every-kappa", paper=("2r-integrals", "LA3", "No", "neumann"), kind="pb", sizes=R_GE_2)
def dual_e4_every_kappa(s):
    """§8 with §5: the coefficients e_2, e_4 of the spectral curve of 𝓛*_neum(λ) (𝓘_{2l}(λ)/a(λ)) are right
    SO(r)-invariant, and the flows (No) differ by the flow of a function of Ψ, so they are integrals of (No) for
    every κ (Theorem DUAL states κ = 0, −½)."""
    fl = s.dirac_flow(H_neum_k)
    return {"d e_2(L*)/dt": s.d(lambda t: elementary(t, L_dual(t), 4)[2], fl),
            "d e_4(L*)/dt": s.d(lambda t: elementary(t, L_dual(t), 4)[4], fl)}


# 11 ---------------------------------------------------------------------------------------------
@claim("h76-j-commutes-manakov", paper=("Chasles-Manakov", "man", "man-dual"), kind="pb", sizes=SMALL)
def j_commutes_manakov(s):
    """§8, Chasles-Manakov: the dual integrals of the Manakov flows commute with the big Manakov integrals
    tr(Φ + μA)^k of (man) and among themselves: {e_2(R(λ)Φ), tr(Φ + μA)³} = 0, {e_2(R(λ)Φ), e_2(R(μ)Φ)} = 0."""
    mu = s.scalar("mu")
    E2l = lambda t: e_rphi(t, 2)
    E2m = lambda t: e_rphi(t, 2, mu)
    M3 = lambda t: t.tr((t.Phi + t.A * mu) @ (t.Phi + t.A * mu) @ (t.Phi + t.A * mu))
    return {"{e2(R(l)Phi), tr(Phi + mu A)^3}": s.bracket(E2l, M3), "{e2(R(l)Phi), e2(R(mu)Phi)}": s.bracket(E2l, E2m)}
