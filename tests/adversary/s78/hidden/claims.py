# ruff: noqa
"""s78 hidden round: 12 statements of Fedorov & Jovanović that neither the catalog nor the earlier rounds state
(true as printed; numpy check in indep.py.in).  Run with
    stiefelsym verify --claims tests/adversary/s78/hidden/claims.py --method M --jobs 1 --timeout 120
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, admissible, claim, comm, det
from stiefelsym.bases import so_basis

from _h78_helpers import (H_man_a2, H_neum_k, L_dual, dim_V, dim_so, ddim_printed, eta_hat, fibre_lift, killing,
                          normal_gram, phi0, phi_of, thimm_gradient, two_l_printed)

SMALL = admissible(n_max=4)
N_GE_2 = admissible(n_max=5, n_min=2, r_max=1, condition="n >= 2 (so(1) = 0); the statement does not involve r")
CORANK_1 = admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")
N_IS_2R = admissible(n_max=4, n_min=2, where=lambda n, r: n == 2 * r, condition="n = 2r")
TWO_R_LE_N = admissible(n_max=6, n_min=2, where=lambda n, r: 2 * r <= n, condition="n >= 2r")


# 1 ------------------------------------------------------------------------------------------------------------
@claim("h78-thimm-invariant-bracket", paper=("iso", "SO(n)-inv", "LEMA"), kind="pb", sizes=SMALL,
       statement=r"\{F,G\}=-\langle\Phi,[\nabla\tilde f,\nabla\tilde g]\rangle,\ "
                 r"\tilde f(\xi)=F(X,\xi X-\tfrac12XX^T\xi X)")
def thimm_invariant_bracket(s):
    """§2, after Lemma LEMA (Thimm): under (iso) T*_X V ≅ 𝔳 the Poisson bracket of SO(n)-invariant functions
    is {f̃₁, f̃₂}_𝔳 = −⟨ξ, [∇f̃₁, ∇f̃₂]⟩ (the MINUS Lie–Poisson sign), ξ = Φ(X, P), f̃(ξ) = F(X, ξX − ½XXᵀξX).
    Checked for F = tr(S PᵀP), G = tr(C XᵀP), H = tr(T (PᵀP)²) (S, T symmetric, C general, all generic)."""
    S = s.generic("S", "r", "r", "sym")
    T = s.generic("T", "r", "r", "sym")
    C = s.generic("C", "r", "r")
    F = lambda t: t.tr(S @ t.P.T @ t.P)
    G = lambda t: t.tr(C @ t.X.T @ t.P)
    H = lambda t: t.tr(T @ t.P.T @ t.P @ t.P.T @ t.P)
    gF, gG, gH = thimm_gradient(s, F), thimm_gradient(s, G), thimm_gradient(s, H)
    return {"{F,G} + <Phi,[dF,dG]>": s.bracket(F, G) + killing(s, s.Phi, comm(gF, gG)),
            "{F,H} + <Phi,[dF,dH]>": s.bracket(F, H) + killing(s, s.Phi, comm(gF, gH))}


# 2 ------------------------------------------------------------------------------------------------------------
@claim("h78-edelman-lagrangian", paper=("normal_metric_lagrangian", "Phi_0", "P(dot_X)", "cond_X"), kind="id",
       sizes=SMALL, statement=r"\tfrac12\langle\Phi_0,\Phi_0\rangle=\tfrac12\tr(\dot X^T\dot X)"
                              r"-\tfrac14\tr(\dot X^TXX^T\dot X),\ X^TP+P^TX=0\ \text{for}\ P=\dot X-\tfrac12XX^T\dot X")
def edelman_lagrangian(s):
    """§3, (normal_metric_lagrangian), (Phi_0), (P(dot_X)): on TV (Ẋ = V, a tangent vector: XᵀV skew; here V = s.P,
    which satisfies the same constraint), L₀ = ½⟨Φ₀, Φ₀⟩ is the metric ½tr(Ẋᵀ(I − ½XXᵀ)Ẋ), and the Legendre image
    P = Ẋ − ½XXᵀẊ satisfies (cond_XP) ("from the constraints (cond_X) we get the conditions (cond_XP)")."""
    V, X = s.P, s.X
    L0 = killing(s, phi0(s, V), phi0(s, V)) / 2
    P = V - X @ X.T @ V / 2
    return {"L0 - Edelman form": L0 - (s.tr(V.T @ V) / 2 - s.tr(V.T @ X @ X.T @ V) / 4),
            "X^T P + P^T X": X.T @ P + P.T @ X}


# 3 ------------------------------------------------------------------------------------------------------------
@claim("h78-gras-wedge-corank-one", paper=("neum-gras", "gras-velocities", "iden2", "neum-gras**"), kind="id",
       sizes=CORANK_1, statement=r"r=n-1,\ \tilde P=(I-XX^T)P:\ \tilde P\eta\tilde P^T=\sum\eta_{ij}\,\dot e_i\wedge\dot e_j=0")
def gras_wedge_corank_one(s):
    """§7 before (neum-gras**): for r = n − 1 the second term 2Σ e₁∧…∧ė_i∧…∧ė_j∧…∧e_r of (neum-gras) vanishes
    by (gras-velocities): the velocities ė_i = p̃_i of P̃ = (I − XXᵀ)P (XᵀP̃ = 0, a point of Ψ⁻¹(0)) lie on the
    line e_n, so ė_i ∧ ė_j = 0 for all i, j, i.e. P̃ηP̃ᵀ = 0 for every η ∈ so(r)."""
    Pt = (s.In - s.X @ s.X.T) @ s.P
    return {"Pt eta Pt^T": Pt @ s.eta @ Pt.T, "X^T Pt": s.X.T @ Pt}


# 4 ------------------------------------------------------------------------------------------------------------
@claim("h78-lax-does-not-fix-flow", paper=("prep", "Neumann_LA", "LA1", "No", "right_action"), kind="id",
       sizes=SMALL, statement=r"V=\text{(No)}+(X\eta,P\eta):\ \tfrac{d}{dt}\Phi=[XX^T,A],\ "
                              r"\tfrac{d}{dt}XX^T=[\Phi,XX^T],\ V\in T(T^*V)")
def lax_does_not_fix_flow(s):
    """Introduction and §5 ("the Lax pair does not define the system itself"): adding the right SO(r) vector field
    (Xη, Pη) to the Neumann flow (No) (generic κ) gives a vector field tangent to T*V that still satisfies (prep),
    hence (LA1): dΦ/dt = [XXᵀ, A], d(XXᵀ)/dt = [Φ, XXᵀ]."""
    fl = s.dirac_flow(H_neum_k)
    V = {"X": fl.Xdot + s.X @ s.eta, "P": fl.Pdot + s.P @ s.eta}
    pi = s.X @ s.X.T
    return {"dPhi - [XX^T, A]": s.d(lambda t: t.Phi, V) - comm(pi, s.A),
            "d(XX^T) - [Phi, XX^T]": s.d(lambda t: t.X @ t.X.T, V) - comm(s.Phi, pi),
            "d(X^T X)": s.d(lambda t: t.X.T @ t.X, V),
            "d(X^T P + P^T X)": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, V)}


# 5 ------------------------------------------------------------------------------------------------------------
@claim("h78-gl-killing-signature", paper=("symmetric-pair", "killing", "LAMBDA12"), kind="id", sizes=SMALL,
       statement=r"\langle K,K\rangle=\tfrac12\tr K^TK,\ \langle S,S\rangle=-\tfrac12\tr S^TS,\ \langle K,S\rangle=0,"
                 r"\ \langle XX^T,XX^T\rangle=-\tfrac r2")
def gl_killing_signature(s):
    """§6 after (symmetric-pair): gl(n) = so(n) + Sym(n) is ⟨·,·⟩-orthogonal, ⟨·,·⟩ = −½tr(ab) is positive definite
    on so(n) (⟨K, K⟩ = ½‖K‖²) and negative definite on Sym(n) (⟨S, S⟩ = −½‖S‖²); on Θ(T*V): ⟨Φ, XXᵀ⟩ = 0 and
    ⟨XXᵀ, XXᵀ⟩ = −r/2."""
    K = s.generic("K", "n", "n", "skew")
    S = s.generic("S", "n", "n", "sym")
    v = s.X @ s.X.T
    return {"<K,K> - |K|^2/2": killing(s, K, K) - s.tr(K.T @ K) / 2,
            "<S,S> + |S|^2/2": killing(s, S, S) + s.tr(S.T @ S) / 2,
            "<K,S>": killing(s, K, S),
            "<Phi, XX^T>": killing(s, s.Phi, v),
            "<XX^T, XX^T> + r/2": killing(s, v, v) + s.tr(s.Ir) / 2}


# 6 ------------------------------------------------------------------------------------------------------------
@claim("h78-delta0-grassmannian", paper=("bols-jov", "ddim", "2l"), kind="dim", sizes=TWO_R_LE_N,
       statement=r"n\ge2r:\ \delta_0=2\dim V_{n,r}-\ddim-2l=r=\operatorname{rank}G_{n,r}=\min(r,n-r)")
def delta0_grassmannian(s):
    """§4 after Theorem bols-jov: for n ≥ 2r, δ₀ = 2dim V − ddim C∞(T*V)^{SO(n)} − 2l (with (ddim) and Lemma 2l as
    printed) equals r, which is the rank min(r, n − r) of the symmetric space G_{n,r} — the dimension of the invariant
    tori of the normal geodesic flow on G_{n,r}."""
    n, r = int(s.n), int(s.r)
    d0 = 2 * dim_V(n, r) - ddim_printed(n, r) - two_l_printed(n, r)
    return {"delta_0 = r": Count(d0, r), "r = rank G(n,r)": Count(r, min(r, n - r))}


# 7 ------------------------------------------------------------------------------------------------------------
@claim("h78-n2r-det-phi", paper=("Chasles-Manakov", "man-dual", "dot_XP3*", "2r-integrals"), kind="pb",
       sizes=N_IS_2R, statement=r"n=2r:\ \mathcal J_{2r}=\det\Phi=\det\big(P^T(I-XX^T)P\big)\ (=\det[X\,P]^2),\ "
                                r"\tfrac{d}{dt}\det\big(P^T(I-XX^T)P\big)=0\ \text{along (dot\_XP3*)}")
def n2r_det_phi(s):
    """§8, Theorem Chasles-Manakov at n = 2r: 𝒥₂ᵣ(λ) = Σ a(λ)/Π(λ − a_i)|Φ|^{I}_{I} has degree n − 2r = 0 and is the
    single minor det Φ = (e₁∧…∧e_r∧p₁∧…∧p_r)² = det[X P]² = det(Pᵀ(I − XXᵀ)P) (Gram/Schur complement), a constant of
    the Manakov flow (dot_XP3*) (0 tangent cones)."""
    G = normal_gram(s)
    fl = s.dirac_flow(H_man_a2)
    return {"det Phi - det G": det(s, s.Phi) - det(s, G),
            "d det G / dt": s.d(lambda t: det(t, t.P.T @ (t.In - t.X @ t.X.T) @ t.P), fl)}


# 8 ------------------------------------------------------------------------------------------------------------
@claim("h78-dual-lax-covariance", paper=("2r-integrals", "LA3", "DUAL", "right_action"), kind="id", sizes=SMALL,
       statement=r"\tfrac{d}{ds}\mathcal L^*(Xe^{s\eta},Pe^{s\eta})\big|_0=[\mathcal L^*,\hat\eta],\ "
                 r"\hat\eta=\mathrm{diag}(\eta,\eta)")
def dual_lax_covariance(s):
    """§8 after (2r-integrals): "although the Lax matrix 𝓛* is not invariant under the right SO(r)-action, the
    spectral curve and therefore all 𝓘₂ₗ are": 𝓛* is covariant, 𝓛*(Xh, Ph) = diag(h, h)ᵀ𝓛*(X, P)diag(h, h),
    infinitesimally d/ds 𝓛*(Xe^{sη}, Pe^{sη}) = [𝓛*, diag(η, η)]."""
    lam = s.lam
    D = s.d(lambda t: L_dual(t, t.X, t.P, lam), {"X": s.X @ s.eta, "P": s.P @ s.eta})
    L = L_dual(s, s.X, s.P, lam)
    return {"dL* - [L*, eta_hat]": D - comm(L, eta_hat(s, s.eta))}


# 9 ------------------------------------------------------------------------------------------------------------
@claim("h78-so-n-killing-form", paper=("normal_metric", "killing"), kind="id", sizes=N_GE_2,
       statement=r"\tr(\operatorname{ad}_\xi\operatorname{ad}_\zeta)=(n-2)\tr(\xi\zeta)=-2(n-2)\langle\xi,\zeta\rangle")
def so_n_killing_form(s):
    """§3, the normal metric: ⟨·,·⟩ = −½tr(ab) is proportional to the negative Killing form of so(n), whose normal
    metric is the standard metric of SO(n)/SO(n−r): B(ξ, ζ) = tr(ad_ξ ad_ζ) = (n − 2)tr(ξζ) = −2(n − 2)⟨ξ, ζ⟩
    (trace over the ⟨·,·⟩-orthonormal basis E_i∧E_j)."""
    xi, zeta = s.xi, s.zeta
    basis = so_basis(s, "n")
    B = killing(s, basis[0], comm(xi, comm(zeta, basis[0])))
    for E in basis[1:]:
        B = B + killing(s, E, comm(xi, comm(zeta, E)))
    return {"B(xi,zeta) - (n-2) tr(xi zeta)": B - (int(s.n) - 2) * s.tr(xi @ zeta)}


# 10 -----------------------------------------------------------------------------------------------------------
@claim("h78-iso-projection", paper=("iso", "P-neutral", "momentum_map"), kind="id", sizes=SMALL,
       statement=r"L(\xi)=\xi X-\tfrac12XX^T\xi X\in T^*_XV,\ \Phi(X,L(\xi))=\xi-(I-XX^T)\xi(I-XX^T)")
def iso_projection(s):
    """§2 (iso): the restriction of Φ to T*_X V is an isomorphism onto 𝔳 = so(n−r)^⊥; its inverse on 𝔳 is
    ξ ↦ L(ξ) = ξX − ½XXᵀξX, and on all of so(n) Φ(X, L(ξ)) is the orthogonal projection of ξ onto 𝔳,
    ξ − (I − XXᵀ)ξ(I − XXᵀ)."""
    L = fibre_lift(s, s.xi)
    Q = s.In - s.X @ s.X.T
    return {"X^T L + L^T X": s.X.T @ L + L.T @ s.X,
            "Phi(X, L(xi)) - pr(xi)": phi_of(s, s.X, L) - (s.xi - Q @ s.xi @ Q)}


# 11 -----------------------------------------------------------------------------------------------------------
@claim("h78-gras-reduced-dimension", paper=("grassmannian", "NEUMANN2", "momentum_right_map"), kind="dim",
       sizes=admissible(n_max=6), statement=r"\dim\Psi^{-1}(0)/SO(r)=2\dim V_{n,r}-2\dim so(r)=2r(n-r)"
                                           r"=\dim T^*G_{n,r}")
def gras_reduced_dimension(s):
    """§7: Ψ⁻¹(0)/SO(r) ≅ T*G_{n,r}: dim T*V − dim so(r) (the level Ψ = 0) − dim so(r) (the quotient) =
    2r(n − r) = 2(dim so(n) − dim so(r) − dim so(n − r)) = 2 dim G_{n,r}."""
    n, r = int(s.n), int(s.r)
    red = 2 * dim_V(n, r) - 2 * dim_so(r)
    return {"dim = 2r(n-r)": Count(red, 2 * r * (n - r)),
            "= 2 dim G": Count(red, 2 * (dim_so(n) - dim_so(r) - dim_so(n - r)))}


# 12 -----------------------------------------------------------------------------------------------------------
@claim("h78-dual-lax-conjugation-sp", paper=("LA3", "LA4", "DUAL", "2r-integrals"), kind="id", sizes=SMALL,
       statement=r"J\mathcal A^*_{neum}(\lambda)\ \text{symmetric for both (LA4)},\ J=\begin{pmatrix}0&I\\-I&0\end{pmatrix}")
def dual_lax_a_symplectic(s):
    """§8 (LA4) with (2r-integrals) ("due to the symplectic block structure ... odd powers vanish"): not only 𝓛* but
    both printed 𝓐*_neum(λ) (κ = 0: [[XᵀP, I], [Λ − λI, −PᵀX]]; κ = −½: [[0, I], [Λ − λI, 0]], Λ = XᵀAX − PᵀP) lie in
    sp(2r): J𝓐* is symmetric, so the flow 𝓛̇* = [𝓛*, 𝓐*] stays in sp(2r)."""
    from stiefelsym import block
    I, Z = s.Ir, s.zeros(s.r, s.r, ("r", "r"))
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    K = s.X.T @ s.P
    J = block([[Z, I], [-I, Z]])
    A0 = block([[K, I], [Lam - s.lam * I, -K.T]])
    AE = block([[Z, I], [Lam - s.lam * I, Z]])
    return {"J A0 sym": J @ A0 - (J @ A0).T, "J AE sym": J @ AE - (J @ AE).T}


# 13 -----------------------------------------------------------------------------------------------------------
from stiefelsym import Rank
from stiefelsym.systems import complex_point, ctranspose, re_trace, real_complex_point, realify_real


def _psi0(t, z):
    """ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ (realified)."""
    return ctranspose(t, z["Z"]) @ t.conj(z["Zdot"]) - ctranspose(t, z["Zdot"]) @ t.conj(z["Z"])


def _u1_sum(t, z):
    """M = ŻZ̄ᵀ − ZŻ̄ᵀ (n × n), whose diagonal entries are the ψ_j of (u(1)): Σ_j ψ_j = tr M."""
    return z["Zdot"] @ ctranspose(t, t.conj(z["Z"])) - z["Z"] @ ctranspose(t, t.conj(z["Zdot"]))


@claim("h78-complex-u1-center", paper=("u(1)", "W-eq", "dual-complex"), kind="id", sizes=SMALL,
       statement=r"\sum_{j=1}^n\psi_j=-\tr\psi_0,\quad \psi_0|_{Z=\bar Z=X,\ \dot Z=P}=X^TP-P^TX=\Psi")
def complex_u1_center(s):
    """App. 2, after (u(1)): for ρ₁ = … = ρₙ the left U(1)-action Z ↦ ρZ is the action of the centre of the right
    U(r) (Z ↦ Zρ), so its momentum Σⱼ ψⱼ (ψⱼ = Σᵢ ż_i^j z̄_i^j − z_i^j ż̄_i^j) is −tr ψ₀ (ψ₀ = ZᵀŻ̄ − ŻᵀZ̄, the u(r)
    momentum); at real data (V(n, r) ⊂ W(n, r)) ψ₀ is the right momentum Ψ = XᵀP − PᵀX of (momentum_right_map)."""
    z = complex_point(s)
    In_i = s.realify(s.In - s.In, s.In)
    Ir_i = s.realify(s.Ir - s.Ir, s.Ir)
    M, p0 = _u1_sum(s, z), _psi0(s, z)
    zr = real_complex_point(s)
    return {"Re(tr M + tr psi_0)": re_trace(s, M) + re_trace(s, p0),
            "Im(tr M + tr psi_0)": re_trace(s, In_i @ M) + re_trace(s, Ir_i @ p0),
            "psi_0 at real data - Psi": _psi0(s, zr) - realify_real(s, s.Psi)}


# 14 -----------------------------------------------------------------------------------------------------------
@claim("h78-psi-generic-rank", paper=("NEUMANN", "dim_fol", "torus", "momentum_right_map"), kind="dim",
       sizes=admissible(n_max=5), statement=r"\operatorname{rank}\Psi(X,P)=2\left[\tfrac r2\right]\ \text{(generic)}")
def psi_generic_rank(s):
    """§6, Theorem NEUMANN and its proof: the generic trajectories are those where the momentum Ψ has maximal rank,
    which is 2[r/2] (an element of so(r)); (dim_fol) counts [r/2] Casimirs J_k for this rank."""
    r = int(s.r)
    return {"rank Psi": Rank(s.Psi, 2 * (r // 2))}
