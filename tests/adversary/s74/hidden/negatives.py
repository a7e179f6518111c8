# ruff: noqa
"""s74 hidden round: false twins of claims.py, one change each, with `fails_at` where numpy (indep.py.in)
finds the twin false.  Helpers in _h74_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import admissible, block, claim, comm, elementary
from stiefelsym.systems import coupled_point, derivative, stiefel_pairs_flow

from _h74_helpers import (H_coupled0, H_manakov_inv, H_manakov_sq, H_neum_0, H_neum_kappa, H_not_manakov,
                          H_sphere, L_so_nn, block_M, coupled_T, coupled_V, manakov_inv, mpow, tr_pow)

SMALL = admissible(n_max=4)
R_IS_1 = admissible(n_max=4, r_max=1, condition="r = 1")
R_IS_2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2")
R_IS_N = admissible(n_max=4, where=lambda n, r: r == n, condition="r = n")
COUPLED = admissible(n_max=3)
COUPLED_N2 = admissible(n_max=3, n_min=2, condition="n >= 2")
ALWAYS = lambda n, r: True
N2 = lambda n, r: n >= 2


@claim("n74-phi-block-traces-plus", kind="id", sizes=SMALL, fails_at=N2,
       erratum="twin: M = [[XᵀP, I], [+PᵀP, −PᵀX]]")
def phi_block_traces_plus(s):
    """False twin of h74-phi-block-traces: +PᵀP in M (true only where P = 0, n = 1)."""
    M = block_M(s, s.X, s.P, sign=1)
    return {f"tr Phi^{k} - tr M^{k}": tr_pow(s, s.Phi, k) - tr_pow(s, M, k) for k in (2, 3, 4, 5, 6)}


@claim("n74-phi-charpoly-no-factor", kind="id", sizes=SMALL, fails_at=lambda n, r: n > 2 * r,
       erratum="twin: p_M(Φ) = 0 without the factor Φ (true when n <= 2r, where p_M = w^{2r−n} det(w − Φ))")
def phi_charpoly_no_factor(s):
    """False twin of h74-phi-annihilated: p_M(Φ) = 0 (Cayley–Hamilton holds for it only when n <= 2r)."""
    M = block_M(s, s.X, s.P)
    F = s.Phi
    m = 2 * int(s.r)
    e = elementary(s, M, m)
    pM = F - F
    for j in range(m + 1):
        term = mpow(s, F, m - j, s.In) * e[j]
        pM = pM + term if j % 2 == 0 else pM - term
    return {"p_M(Phi)": pM}


@claim("n74-phi-cubic-r1-minus", kind="id", sizes=R_IS_1, fails_at=N2, erratum="twin: Φ³ − (p, p)Φ = 0")
def phi_cubic_r1_minus(s):
    """False twin of h74-phi-cubic-r1: Φ³ = (p, p)Φ."""
    F = s.Phi
    return {"Phi^3 - (p,p) Phi": F @ F @ F - F * s.tr(s.P.T @ s.P)}


@claim("n74-psi-body-minus", kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 2, erratum="twin: XᵀΦX = −Ψ")
def psi_body_minus(s):
    """False twin of h74-psi-body: XᵀΦX = −Ψ (true at r = 1, where Ψ = 0)."""
    return {"X^T Phi X + Psi": s.X.T @ s.Phi @ s.X + s.Psi}


@claim("n74-space-body-transposed", kind="id", sizes=R_IS_N, fails_at=lambda n, r: n >= 2,
       erratum="twin: Φ = XΨᵀXᵀ (a transpose of Ψ; XᵀΨX, the other transpose, is refused: its spaces do not match)")
def space_body_transposed(s):
    """False twin of h74-space-body-r-n: Φ = XΨᵀXᵀ."""
    return {"Phi - X Psi^T X^T": s.Phi - s.X @ s.Psi.T @ s.X.T}


@claim("n74-manakov-inv-a-pdot-sign", kind="id", sizes=SMALL, fails_at=N2, erratum="twin: Ṗ = −A⁻¹ΦA⁻¹P")
def manakov_inv_a_pdot_sign(s):
    """False twin of h74-manakov-inv-a-flow: Ṗ = −𝔸(Φ)P."""
    fl = s.dirac_flow(H_manakov_inv)
    return {"Pdot": fl["P"] + manakov_inv(s, s.Phi) @ s.P}


@claim("n74-manakov-inv-a-lax-sign", kind="lax", sizes=SMALL, fails_at=N2, erratum="twin: M = A⁻¹ΦA⁻¹ + λA⁻¹")
def manakov_inv_a_lax_sign(s):
    """False twin of h74-manakov-inv-a-lax: M = 𝔸(Φ) + λA⁻¹ (B = +A⁻¹ in M)."""
    lam = s.lam
    fl = s.dirac_flow(H_manakov_inv)
    L = s.Phi + s.A * lam
    M = manakov_inv(s, s.Phi) + s.Ainv * lam
    return {"dL/dt - [M, L]": s.d(lambda t: t.Phi + t.A * lam, fl) - comm(M, L)}


@claim("n74-manakov-a-a-commutes", kind="pb", sizes=SMALL, fails_at=lambda n, r: n >= 3,
       erratum="twin: −¼tr(AΦAΦ) (ξ ↦ AξA, not a Manakov operator) commutes with H_{A²}")
def manakov_a_a_commutes(s):
    """False twin of h74-manakov-inv-a-commutes: A in place of A⁻¹ (true at n <= 2, so(2) abelian)."""
    return {"{H_AA, H_A^2}": s.bracket(H_not_manakov, H_manakov_sq)}


@claim("n74-kappa-right-action-xptx", kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 2,
       erratum="twin: Ẋ_κ − Ẋ_0 = 2κXPᵀX (a transpose: XPᵀX = −XXᵀP)")
def kappa_right_action_xptx(s):
    """False twin of h74-kappa-right-action: 2κXPᵀX."""
    X, P, kap = s.X, s.P, s.kappa
    fk = s.dirac_flow(H_neum_kappa)
    f0 = s.dirac_flow(H_neum_0)
    return {"Xdot_k - Xdot_0 - 2k X P^T X": fk["X"] - f0["X"] - X @ P.T @ X * (2 * kap)}


@claim("n74-chasles-r1-plus-one", kind="id", sizes=R_IS_1, fails_at=ALWAYS,
       erratum="twin: D = (Re, p)² − (Re, e)((Rp, p) + 1)")
def chasles_r1_plus_one(s):
    """False twin of h74-chasles-r1-discriminant: +1 in the discriminant."""
    lam = s.lam
    R = -s.resolvent(lam)
    e, p, F = s.X, s.P, s.Phi
    D = s.tr(e.T @ R @ p) ** 2 - s.tr(e.T @ R @ e) * (s.tr(p.T @ R @ p) + 1)
    return {"D - (Re,e) - tr(R Phi R Phi)/2": D - s.tr(e.T @ R @ e) - s.tr(R @ F @ R @ F) / 2}


@claim("n74-cpb-lax-plus", kind="lax", sizes=SMALL, fails_at=N2, erratum="twin: M = h + λA")
def cpb_lax_plus(s):
    """False twin of h74-cpb-lax-generic: M = h + λA."""
    h, v, lam, A = s.xi, s.generic("v", "n", "n", "sym"), s.lam, s.A
    L = h * lam + v - A * (lam * lam)
    Ld = comm(v, A) * lam + comm(h, v)
    return {"Ldot - [M, L]": Ld - comm(h + A * lam, L)}


@claim("n74-coupled-printed-trace-energy", kind="id", sizes=COUPLED, fails_at=ALWAYS,
       erratum="twin: the printed L(ν) gives tr L² = 2ν²trA² − 4H + 2rν⁻²")
def coupled_printed_trace_energy(s):
    """False twin of h74-coupled-trace-energy: the printed L(ν) (with +ν⁻¹) has the energy in tr L²."""
    z = coupled_point(s)
    nu = s.scalar("nu")
    T, V = coupled_T(s, z), coupled_V(s, z)
    base = s.tr(s.A @ s.A) * (2 * nu * nu) + s.tr(s.Ir) * (s.q(2) / (nu * nu))
    Lp = L_so_nn(s, z, nu, 1)
    return {"tr L_printed^2": s.tr(Lp @ Lp) - (base - (T + V) * 4)}


@claim("n74-coupled-energy-moves", kind="not", expect="nonzero", sizes=COUPLED_N2, fails_at=ALWAYS,
       erratum="twin (`not`): the energy T₀ + tr(XᵀAY) is not conserved (it is)")
def coupled_energy_moves(s):
    """False twin of h74-coupled-printed-invariant-moves: d/dt(T₀ + V) ≠ 0."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled0, z, [("X", "P"), ("Y", "Q")])
    return {"d(T + V)/dt": derivative(s, lambda t, w: coupled_T(t, w) + coupled_V(t, w), z, fl)}


@claim("n74-perelomov-energy-sign", kind="id", sizes=SMALL, fails_at=ALWAYS,
       erratum="twin: tr 𝓛(λ)² = r + 4λ²H + λ⁴tr A²")
def perelomov_energy_sign(s):
    """False twin of h74-perelomov-energy: +4λ²H."""
    lam = s.lam
    L = s.Phi * lam + s.X @ s.X.T - s.A * (lam * lam)
    return {"tr L^2 - (r + 4 lam^2 H0 + lam^4 tr A^2)":
            s.tr(L @ L) - (s.tr(s.Ir) + H_neum_0(s) * (4 * lam * lam) + s.tr(s.A @ s.A) * (lam * lam * lam * lam))}


@claim("n74-grassmann-projector-sign", kind="id", sizes=R_IS_2, fails_at=ALWAYS, erratum="twin: W² = XXᵀ")
def grassmann_projector_sign(s):
    """False twin of h74-grassmann-plucker-r2: W² = XXᵀ."""
    X = s.X
    F = s.mat([[0, 1], [-1, 0]], ("r", "r"))
    W = X @ F @ X.T
    return {"W^2 - X X^T": W @ W - X @ X.T}
