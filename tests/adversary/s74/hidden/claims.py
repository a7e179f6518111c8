# ruff: noqa
"""s74 hidden round: fifteen further statements of Fedorov & Jovanović, written with the public API only.

Every claim here is true as stated (checked independently in indep.py.in); the false twins are in negatives.py.
Helpers (no claims) are in _h74_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, block, claim, comm, elementary
from stiefelsym.systems import coupled_point, derivative, stiefel_pairs_flow

from _h74_helpers import (H_coupled0, H_manakov_inv, H_manakov_sq, H_neum_0, H_neum_kappa, H_normal, H_sphere,
                          L_so_nn, Phi_of, Psi_of, block_M, coupled_T, coupled_V, manakov_inv, mpow, tr_pow)

SMALL = admissible(n_max=4)
R_IS_1 = admissible(n_max=4, r_max=1, condition="r = 1")
R_IS_2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2")
R_IS_N = admissible(n_max=4, where=lambda n, r: r == n, condition="r = n")
COUPLED = admissible(n_max=3)
COUPLED_N2 = admissible(n_max=3, n_min=2, condition="n >= 2 (at n = 1, P = Q = 0 and nothing moves)")


# 1 ---------------------------------------------------------------------------------------------------
@claim("h74-phi-block-traces", paper=("SO(n)-inv", "LEMA", "momentum_map"), kind="id", sizes=SMALL)
def phi_block_traces(s):
    """§2, (SO(n)-inv) and Lemma LEMA: the SO(n)-invariant functions tr Φᵏ of the momentum are functions of
    Ψ and PᵀP only: Φ = UV with U = (P X), V = (Xᵀ; −Pᵀ), so tr Φᵏ = tr Mᵏ with the 2r × 2r matrix
    M = VU = [[XᵀP, I_r], [−PᵀP, −PᵀX]] (k = 2, …, 6)."""
    X, P = s.X, s.P
    M = block_M(s, X, P)
    F = s.Phi
    return {f"tr Phi^{k} - tr M^{k}": tr_pow(s, F, k) - tr_pow(s, M, k) for k in (2, 3, 4, 5, 6)}


# 2 ---------------------------------------------------------------------------------------------------
@claim("h74-phi-annihilated", paper=("SO(n)-inv", "2l", "momentum_map"), kind="id", sizes=SMALL)
def phi_annihilated(s):
    """§2 (Lemma 2l: the orbits of Φ(T*V)): Φ has at most 2r nonzero eigenvalues, those of
    M = [[XᵀP, I_r], [−PᵀP, −PᵀX]]: with p_M(w) = det(wI − M) = Σ (−1)ʲe_j(M)w^{2r−j}, Φ·p_M(Φ) = 0."""
    X, P = s.X, s.P
    M = block_M(s, X, P)
    F = s.Phi
    m = 2 * int(s.r)
    e = elementary(s, M, m)
    pM = F - F
    for j in range(m + 1):
        term = mpow(s, F, m - j, s.In) * e[j]
        pM = pM + term if j % 2 == 0 else pM - term
    return {"Phi p_M(Phi)": F @ pM}


# 3 ---------------------------------------------------------------------------------------------------
@claim("h74-phi-cubic-r1", paper=("momentum_map", "sphere_neum", "2l"), kind="id", sizes=R_IS_1)
def phi_cubic_r1(s):
    """§1/§2 at r = 1 (T*S^{n−1}): Φ = p ∧ e is (p, p)^{1/2} times the generator of the rotation in the
    plane (e, p), so Φ³ + (p, p)Φ = 0 (the generic orbit of Φ(T*S^{n−1}) has 2l = 2(n − 2))."""
    F = s.Phi
    return {"Phi^3 + (p,p) Phi": F @ F @ F + F * s.tr(s.P.T @ s.P)}


# 4 ---------------------------------------------------------------------------------------------------
@claim("h74-psi-body", paper=("momentum_map", "momentum_right_map", "Phi"), kind="id", sizes=SMALL)
def psi_body(s):
    """§2: the right momentum is the left one seen from the frame X: XᵀΦX = Ψ (so Ψ is SO(n)-invariant,
    and Φ, Ψ have the same invariants tr Ψᵏ = tr (XXᵀΦ)ᵏ)."""
    X = s.X
    return {"X^T Phi X - Psi": X.T @ s.Phi @ X - s.Psi}


# 5 ---------------------------------------------------------------------------------------------------
@claim("h74-space-body-r-n", paper=("normal_metric", "dot_X3", "mag*", "YM"), kind="id", sizes=R_IS_N)
def space_body_r_n(s):
    """§3 remark (r = n: T*V_{n,n} = T*SO(n)) and the proof of Proposition YM: Φ is the angular momentum
    in space and Ψ the one in the body frame, Φ = XΨXᵀ; along the normal geodesic flow (dot_X3) the space
    angular velocity ẊXᵀ is Φ and the body angular velocity XᵀẊ is Ψ (the inertia operator is the
    identity)."""
    X = s.X
    fl = s.dirac_flow(H_normal)
    return {"Phi - X Psi X^T": s.Phi - X @ s.Psi @ X.T,
            "Xdot X^T - Phi": fl["X"] @ X.T - s.Phi,
            "X^T Xdot - Psi": X.T @ fl["X"] - s.Psi}


# 6 ---------------------------------------------------------------------------------------------------
@claim("h74-manakov-inv-a-flow", paper=("Manakov", "sp1", "dot_XP2", "submersion_metric"), kind="id",
       sizes=SMALL)
def manakov_inv_a_flow(s):
    """§4 (Manakov) with B = −A⁻¹ (the Poisson-sphere operator of §8, here at every r): 𝔸ξ = A⁻¹ξA⁻¹ solves
    ad_A(𝔸ξ) = ad_B ξ, and the flow of H = ½⟨𝔸Φ, Φ⟩ = −¼tr(A⁻¹ΦA⁻¹Φ) is (dot_XP2): ∂H/∂P = 𝔸(Φ)X,
    −∂H/∂X = 𝔸(Φ)P (Λ = Π = 0), Ẋ = 𝔸(Φ)X, Ṗ = 𝔸(Φ)P."""
    A, Ai, xi = s.A, s.Ainv, s.xi
    B = -Ai
    W = manakov_inv(s, s.Phi)
    HX, HP = s.gradient(H_manakov_inv)
    fl = s.dirac_flow(H_manakov_inv)
    return {"ad_A A(xi) - ad_B xi": comm(A, manakov_inv(s, xi)) - comm(B, xi),
            "H_P - A(Phi)X": HP - W @ s.X, "-H_X - A(Phi)P": -HX - W @ s.P,
            "Xdot": fl["X"] - W @ s.X, "Pdot": fl["P"] - W @ s.P}


# 7 ---------------------------------------------------------------------------------------------------
@claim("h74-manakov-inv-a-lax", paper=("Manakov", "man", "sp1"), kind="lax", sizes=SMALL)
def manakov_inv_a_lax(s):
    """§4, the Manakov Lax pair for B = −A⁻¹: along the flow of H = −¼tr(A⁻¹ΦA⁻¹Φ),
    d/dt(Φ + λA) = [A⁻¹ΦA⁻¹ − λA⁻¹, Φ + λA]."""
    lam, A, Ai = s.lam, s.A, s.Ainv
    fl = s.dirac_flow(H_manakov_inv)
    L = s.Phi + A * lam
    M = manakov_inv(s, s.Phi) - Ai * lam
    return {"dL/dt - [M, L]": s.d(lambda t: t.Phi + t.A * lam, fl) - comm(M, L)}


# 8 ---------------------------------------------------------------------------------------------------
@claim("h74-manakov-inv-a-commutes", paper=("Chasles-Manakov", "man", "sp1", "Manakov*"), kind="pb", sizes=SMALL)
def manakov_inv_a_commutes(s):
    """§8 (proof of Theorem Chasles-Manakov: the Manakov flows for different B share the isotropic foliation):
    the Hamiltonians of B = −A⁻¹ and B = A² Poisson-commute, and H_{−A⁻¹} conserves the integrals
    tr(Φ + λA)³ of (man)."""
    lam = s.lam
    return {"{H_-A^-1, H_A^2}": s.bracket(H_manakov_inv, H_manakov_sq),
            "{H_-A^-1, tr(Phi + lam A)^3}": s.bracket(H_manakov_inv, lambda t: tr_pow(t, t.Phi + t.A * lam, 3))}


# 9 ---------------------------------------------------------------------------------------------------
@claim("h74-kappa-right-action", paper=("No", "neumann", "EM", "right_action", "grassmannian"), kind="id",
       sizes=SMALL)
def kappa_right_action(s):
    """§5 and §7: the Neumann flows (No) for κ and for κ = 0 differ by the infinitesimal right SO(r)-action
    with η = 2κXᵀP: (Ẋ, Ṗ)_κ − (Ẋ, Ṗ)_0 = 2κ(XXᵀP, PXᵀP), which is the flow of κ/2⟨Ψ, Ψ⟩ = −κ tr((XᵀP)²)
    (so all of them reduce to the same flow on T*G_{n,r})."""
    X, P, kap = s.X, s.P, s.kappa
    K = X.T @ P
    fk = s.dirac_flow(H_neum_kappa)
    f0 = s.dirac_flow(H_neum_0)
    fr = s.dirac_flow(lambda t: -t.kappa * t.tr((t.X.T @ t.P) @ (t.X.T @ t.P)))
    return {"Xdot_k - Xdot_0 - 2k X K": fk["X"] - f0["X"] - X @ K * (2 * kap),
            "Pdot_k - Pdot_0 - 2k P K": fk["P"] - f0["P"] - P @ K * (2 * kap),
            "flow of -k tr K^2, X": fr["X"] - X @ K * (2 * kap),
            "flow of -k tr K^2, P": fr["P"] - P @ K * (2 * kap)}


# 10 --------------------------------------------------------------------------------------------------
@claim("h74-chasles-r1-discriminant", paper=("Mum_geod", "Gen_Chasles", "sphere_neum"), kind="id", sizes=R_IS_1)
def chasles_r1_discriminant(s):
    """§8, Proposition Mum_geod (Chasles–Moser), r = 1: the line l = p + span{e} meets the quadric
    Q(λ) = {((A − λ)⁻¹x, x) = 1} where (Re, e)t² + 2(Re, p)t + (Rp, p) − 1 = 0, R = (A − λ)⁻¹; its
    discriminant D(λ) = (Re, p)² − (Re, e)((Rp, p) − 1) equals (Re, e) + ½tr(RΦRΦ) (= Σ F_i/(a_i − λ)), so
    l is tangent to Q(λ) exactly at the roots, and D(λ) is conserved by the Neumann flow (sphere_neum)."""
    lam = s.lam

    def D(t):
        R = -t.resolvent(lam)
        e, p = t.X, t.P
        return t.tr(e.T @ R @ p) ** 2 - t.tr(e.T @ R @ e) * (t.tr(p.T @ R @ p) - 1)

    R = -s.resolvent(lam)
    F = s.Phi
    return {"D - (Re,e) - tr(R Phi R Phi)/2": D(s) - s.tr(s.X.T @ R @ s.X) - s.tr(R @ F @ R @ F) / 2,
            "dD/dt": s.d(D, s.dirac_flow(H_sphere))}


# 11 --------------------------------------------------------------------------------------------------
@claim("h74-cpb-lax-generic", paper=("CPB", "central", "LAMBDA12"), kind="lax", sizes=SMALL)
def cpb_lax_generic(s):
    """§6, remark after Theorem NEUMANN: the Clebsch–Perelomov–Bogoyavlenski system (CPB) ḣ = [v, A],
    v̇ = [h, v] on so(n) ⊕ Sym(n) (at a generic point, not only on Θ(T*V)) has the Lax pair
    L = λh + v − λ²A, M = h − λA: L̇ = [M, L], so tr L² and tr L³ of (central) are conserved."""
    h, v, lam, A = s.xi, s.generic("v", "n", "n", "sym"), s.lam, s.A
    hd, vd = comm(v, A), comm(h, v)
    L = h * lam + v - A * (lam * lam)
    Ld = hd * lam + vd
    M = h - A * lam
    return {"Ldot - [M, L]": Ld - comm(M, L), "d tr L^2/dt": s.tr(L @ Ld), "d tr L^3/dt": s.tr(L @ L @ Ld)}


# 12 --------------------------------------------------------------------------------------------------
@claim("h74-coupled-trace-energy", paper=("so(n,n)", "C-neumann"), kind="id", sizes=COUPLED)
def coupled_trace_energy(s):
    """Appendix 2, (so(n,n)) and (C-neumann), κ = 0: with −ν⁻¹ in front of the last term of L(ν) (the
    catalog's correction) tr L(ν)² = 2ν²tr A² − 4H + 2rν⁻², H = T₀ + tr(XᵀAY) the energy; with the printed +ν⁻¹
    it is 2ν²tr A² − 4(T₀ − tr(XᵀAY)) + 2rν⁻², which is not the energy."""
    z = coupled_point(s)
    nu = s.scalar("nu")
    T, V = coupled_T(s, z), coupled_V(s, z)
    rr = s.tr(s.Ir)
    base = s.tr(s.A @ s.A) * (2 * nu * nu) + rr * (s.q(2) / (nu * nu))
    Lp, Lc = L_so_nn(s, z, nu, 1), L_so_nn(s, z, nu, -1)
    return {"tr L_printed^2": s.tr(Lp @ Lp) - (base - (T - V) * 4),
            "tr L_corrected^2": s.tr(Lc @ Lc) - (base - (T + V) * 4)}


# 13 --------------------------------------------------------------------------------------------------
@claim("h74-coupled-printed-invariant-moves", paper=("so(n,n)", "C-neumann", "C-eq"), kind="not",
       expect="nonzero", sizes=COUPLED_N2)
def coupled_printed_invariant_moves(s):
    """Appendix 2: T₀ − tr(XᵀAY), the ν⁰ coefficient of tr L(ν)² for the printed (so(n,n)), is not conserved
    by the κ = 0 coupled flow (C-neumann): so the printed L(ν) cannot be a Lax matrix of it."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled0, z, [("X", "P"), ("Y", "Q")])
    return {"d(T - V)/dt": derivative(s, lambda t, w: coupled_T(t, w) - coupled_V(t, w), z, fl)}


# 14 --------------------------------------------------------------------------------------------------
@claim("h74-perelomov-energy", paper=("perelomov", "LA2", "N0_XP2", "neumann"), kind="id", sizes=SMALL)
def perelomov_energy(s):
    """§5, (perelomov): the Hamiltonian is among the integrals: tr 𝓛_neum(λ)² = r − 4λ²H_neum,0 + λ⁴tr A²
    (the λ and λ³ terms vanish: tr(ΦXXᵀ) = tr(ΦA) = 0)."""
    lam = s.lam
    L = s.Phi * lam + s.X @ s.X.T - s.A * (lam * lam)
    return {"tr L^2 - (r - 4 lam^2 H0 + lam^4 tr A^2)":
            s.tr(L @ L) - (s.tr(s.Ir) - H_neum_0(s) * (4 * lam * lam) + s.tr(s.A @ s.A) * (lam * lam * lam * lam))}


# 15 --------------------------------------------------------------------------------------------------
@claim("h74-grassmann-plucker-r2", paper=("grassmannian", "neum-gras", "mag-mom-grass"), kind="id", sizes=R_IS_2)
def grassmann_plucker_r2(s):
    """§7, r = 2: the quotient map V_{n,2} → G_{n,2}, X ↦ W = e₁∧e₂ = XFXᵀ (F = E₁∧E₂), lands in the unit
    decomposable bivectors: W³ + W = 0, tr W² = −2, −W² = XXᵀ (the plane's projector) and WX = XF."""
    X = s.X
    F = s.mat([[0, 1], [-1, 0]], ("r", "r"))
    W = X @ F @ X.T
    return {"W^3 + W": W @ W @ W + W, "tr W^2 + 2": s.tr(W @ W) + 2, "W^2 + X X^T": W @ W + X @ X.T,
            "W X - X F": W @ X - X @ F}
