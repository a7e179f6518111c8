# ruff: noqa
"""s76 hidden round: one FALSE twin of each statement of claims.py (one change each), with fails_at where numpy
(indep.py.in) finds them false."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, claim, comm, elementary
from stiefelsym.systems import coupled_point, derivative, stiefel_pairs_flow

from _h76_helpers import (H_man_a2, H_neum, H_neum_k, H_not_manakov, L_big, coupled_H_kappa, e_rphi, killing)

SMALL = admissible(n_max=4)
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2 (so(1) = 0)")
R_IS_1 = admissible(n_max=4, r_max=1, condition="r = 1")
TWO_R_LE_N = admissible(n_max=5, n_min=2, where=lambda n, r: 2 * r <= n, condition="2r <= n (Chasles-Manakov)")


@claim("n76-phi-normal-block-no-psi", paper=("LEMA1",), kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 2, erratum="false twin (s76 hidden round)")
def phi_normal_block_no_psi(s):
    """Twin of h76-phi-normal-block: Φ = πΦ + Φπ on all of T*V (the XΨXᵀ term dropped)."""
    pi = s.X @ s.X.T
    return {"pi Phi + Phi pi - Phi": pi @ s.Phi + s.Phi @ pi - s.Phi}


@claim("n76-j2r-along-neumann", paper=("Chasles-Manakov", "N0_XP2"), kind="pb", sizes=TWO_R_LE_N,
       fails_at=lambda n, r: True, erratum="false twin (s76 hidden round)")
def j2r_along_neumann(s):
    """Twin of h76-manakov-j2r-resolvent: e_2r(RΦ) conserved along the Neumann flow (N0_XP2) instead."""
    r = int(s.r)
    fl = s.dirac_flow(H_neum(s.q(0)))
    return {"d e_2r(R Phi)/dt": s.d(lambda t: e_rphi(t, 2 * r), fl)}


@claim("n76-so-n-noninvariant-bracket", paper=("SO(n)-inv",), kind="pb", sizes=SMALL,
       fails_at=lambda n, r: n >= 2, erratum="false twin (s76 hidden round)")
def so_n_noninvariant_bracket(s):
    """Twin of h76-so-n-invariants-closed: G = tr(C₂XᵀAP) (A inserted: not SO(n)-invariant)."""
    C1, C2 = s.generic("C1", "r", "r"), s.generic("C2", "r", "r")
    F = lambda t: t.tr(C1 @ t.P.T @ t.P)
    G = lambda t: t.tr(C2 @ t.X.T @ t.A @ t.P)
    phi_xi = lambda t: killing(t, t.Phi, s.xi)
    return {"{Phi_xi, {F, G}}": s.bracket(phi_xi, lambda t: t.bracket(F, G))}


@claim("n76-so-r-noninvariant-bracket", paper=("REDUCED_BRACKET",), kind="pb", sizes=SMALL,
       fails_at=lambda n, r: r >= 2, erratum="false twin (s76 hidden round)")
def so_r_noninvariant_bracket(s):
    """Twin of h76-so-r-invariants-closed: G = tr(C XᵀAP), C a constant r×r matrix (not SO(r)-invariant)."""
    C = s.generic("C", "r", "r")
    F = lambda t: t.tr(t.P.T @ t.A @ t.A @ t.P)
    G = lambda t: t.tr(C @ t.X.T @ t.A @ t.P)
    psi_eta = lambda t: killing(t, t.Psi, s.eta)
    return {"{Psi_eta, {F, G}}": s.bracket(psi_eta, lambda t: t.bracket(F, G))}


@claim("n76-torus-xcx", paper=("torus", "perelomov"), kind="pb", sizes=SMALL,
       fails_at=lambda n, r: r >= 2, erratum="false twin (s76 hidden round)")
def torus_xcx(s):
    """Twin of h76-torus-functions-commute: XXᵀ replaced by XCXᵀ (C constant symmetric r×r)."""
    C = s.generic("C", "r", "r", "sym")
    L = lambda t: t.Phi * t.lam + t.X @ C @ t.X.T - t.A * (t.lam * t.lam)
    L3 = lambda t: t.tr(L(t) @ L(t) @ L(t))
    psi_eta = lambda t: killing(t, t.Psi, s.eta)
    return {"{Psi_eta, tr L^3}": s.bracket(psi_eta, L3)}


@claim("n76-coupled-antidiagonal-momentum", paper=("C-neumann", "C-eq"), kind="pb", sizes=admissible(n_max=3),
       fails_at=lambda n, r: r >= 2, erratum="false twin (s76 hidden round)")
def coupled_antidiagonal(s):
    """Twin of h76-coupled-perturbed-momentum: XᵀP − PᵀX − (YᵀQ − QᵀY) conserved."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, coupled_H_kappa, z, [("X", "P"), ("Y", "Q")])
    mom = lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"] - w["Y"].T @ w["Q"] + w["Q"].T @ w["Y"]
    return {"d(antidiagonal momentum)/dt": derivative(s, mom, z, fl)}


@claim("n76-j-along-non-manakov", paper=("Chasles-Manakov",), kind="pb", sizes=TWO_R_LE_N,
       fails_at=lambda n, r: n >= 3 and n != 2 * r, erratum="false twin (s76 hidden round)")
def j_along_non_manakov(s):
    """Twin of h76-manakov-ainv-shares-j: the operator ξ ↦ AξA (A in place of A⁻¹, not a Manakov operator)."""
    r = int(s.r)
    fl = s.dirac_flow(H_not_manakov)
    return {"d e_2r(R Phi)/dt": s.d(lambda t: e_rphi(t, 2 * r), fl)}


@claim("n76-neumann-flows-differ-r1", paper=("No",), kind="not", expect="nonzero", sizes=R_IS_1,
       fails_at=lambda n, r: True, erratum="false twin (s76 hidden round)")
def neumann_flows_differ_r1(s):
    """Twin of h76-neumann-flows-differ stated at r = 1, where XᵀP = 0 and all the flows (No) coincide."""
    f0 = s.dirac_flow(H_neum(s.q(0)))
    fe = s.dirac_flow(H_neum(s.q(-1, 2)))
    return {"Xdot(kappa=0) - Xdot(kappa=-1/2)": f0["X"] - fe["X"]}


@claim("n76-psi-equals-xtp", paper=("grassmannian",), kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 2, erratum="false twin (s76 hidden round)")
def psi_equals_xtp(s):
    """Twin of h76-psi-twice-xtp: Ψ = XᵀP (factor 2 dropped)."""
    return {"Psi - X^T P": s.Psi - s.X.T @ s.P}


@claim("n76-xtrx-conserved", paper=("2r-integrals", "No"), kind="pb", sizes=R_GE_2,
       fails_at=lambda n, r: r < n, erratum="false twin (s76 hidden round)")
def xtrx_conserved(s):
    """Twin of h76-dual-e4-every-kappa: the single term tr(XᵀRX) of 𝓘₂/a conserved along (No)."""
    fl = s.dirac_flow(H_neum_k)
    return {"d tr(X^T R X)/dt": s.d(lambda t: t.tr(t.X.T @ t.resolvent(t.lam) @ t.X), fl)}


@claim("n76-j-commutes-manakov-a2", paper=("Chasles-Manakov", "man"), kind="pb", sizes=SMALL,
       fails_at=lambda n, r: n >= 3, erratum="false twin (s76 hidden round)")
def j_commutes_manakov_a2(s):
    """Twin of h76-j-commutes-manakov: tr(Φ + μA²)³ (A² in place of A)."""
    mu = s.scalar("mu")
    E2l = lambda t: e_rphi(t, 2)
    M3 = lambda t: t.tr((t.Phi + t.A @ t.A * mu) @ (t.Phi + t.A @ t.A * mu) @ (t.Phi + t.A @ t.A * mu))
    return {"{e2(R(l)Phi), tr(Phi + mu A^2)^3}": s.bracket(E2l, M3)}
