# ruff: noqa
"""s75 hidden round: false twins of claims.py, one change each, with `fails_at` where numpy (indep.py.in)
finds the twin false.  Helpers in _h75_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis
from stiefelsym.systems import coupled_point, derivative, stiefel_pairs_flow

from _h75_helpers import (pf4, H_B, H_K_of, H_coupled0, H_neum_kappa_A, H_normal, H_sp1, H_submersion,
                          block_projectors, cross3, dim_fol, killing, lambda1_form, lambda1_op, repeated_A)

SMALL = admissible(n_max=4)
R_GE_2 = admissible(n_max=5, r_min=2, condition="r >= 2")
R_GE_3 = admissible(n_max=5, r_min=3, condition="r >= 3")
N_GE_2 = admissible(n_max=4, n_min=2, condition="n >= 2")
N_GE_3 = admissible(n_max=4, n_min=3, condition="n >= 3")
R_LT_N = admissible(n_max=5, where=lambda n, r: r < n, condition="r < n")
R_IS_N = admissible(n_max=5, n_min=2, where=lambda n, r: r == n, condition="r = n >= 2")
COUPLED_R2 = admissible(n_max=3, r_min=2, condition="r >= 2")
N3_R1 = admissible(n_min=3, stated_n_max=3, r_max=1, condition="n = 3, r = 1")
R_IS_4 = admissible(n_max=5, r_min=4, r_max=4, condition="r = 4")
ALWAYS = lambda n, r: True


@claim("n75-hb-euler-psi-sign", kind="id", sizes=SMALL, fails_at=lambda n, r: r >= 3,
       erratum="twin: Ψ̇ = [𝔹Ψ, Ψ] (the sign of (e-so(r)) reversed; so(r) abelian for r <= 2)")
def hb_euler_psi_sign(s):
    """False twin of h75-hb-euler-psi: Ψ̇ = [𝔹Ψ, Ψ]."""
    fl = s.dirac_flow(H_B)
    BB = s.sym_operator("BB")
    return {"Psidot - [B Psi, Psi]": s.d(lambda t: t.Psi, fl) - comm(BB(s.Psi), s.Psi),
            "Phidot": s.d(lambda t: t.Phi, fl)}


@claim("n75-jensen-psi-conserved", kind="id", sizes=R_GE_2, fails_at=lambda n, r: r >= 3,
       erratum="twin: the whole Ψ conserved by H_K (true at r = 2, where both blocks are so(1) = 0)")
def jensen_psi_conserved(s):
    """False twin of h75-jensen-blocks-conserved: Ψ̇ = 0 (not only its blocks)."""
    D1, D2 = block_projectors(s)
    fl = s.dirac_flow(H_K_of(D1, D2))
    return {"Phidot": s.d(lambda t: t.Phi, fl), "Psidot": s.d(lambda t: t.Psi, fl)}


@claim("n75-jensen-diag-block-moves", kind="not", expect="nonzero", sizes=R_GE_3, fails_at=ALWAYS,
       erratum="twin: the diagonal block D₁ΨD₁ said to move (it is conserved)")
def jensen_diag_block_moves(s):
    """False twin of h75-jensen-offdiag-moves: d(D₁ΨD₁)/dt ≠ 0."""
    D1, D2 = block_projectors(s)
    fl = s.dirac_flow(H_K_of(D1, D2))
    return {"d(D1 Psi D1)/dt": s.d(lambda t: D1 @ t.Psi @ D1, fl)}


@claim("n75-submersion-phi-conserved", kind="pb", sizes=SMALL, fails_at=lambda n, r: n >= 3,
       erratum="twin: Φ conserved by a generic submersion metric (true for n <= 2, so(2) abelian)")
def submersion_phi_conserved(s):
    """False twin of h75-submersion-psi-conserved: Φ̇ = 0 along (dot_XP2) for a generic 𝔸."""
    fl = s.dirac_flow(H_submersion)
    return {"Phidot": s.d(lambda t: t.Phi, fl)}


@claim("n75-normal-phi-moves", kind="not", expect="nonzero", sizes=N_GE_3, fails_at=ALWAYS,
       erratum="twin: Φ said to move along the normal geodesic flow (it is conserved)")
def normal_phi_moves(s):
    """False twin of h75-submersion-phi-moves: the normal metric (𝔸 = 1) in place of a generic 𝔸."""
    fl = s.dirac_flow(H_normal)
    return {"Phidot": s.d(lambda t: t.Phi, fl)}


@claim("n75-pfaffian-reflection-invariant", kind="id", sizes=R_IS_4, fails_at=ALWAYS,
       erratum="twin: Pf(XᵀP) unchanged by the reflection (X, P) ↦ (XD, PD) (it changes sign)")
def pfaffian_reflection_invariant(s):
    """False twin of h75-pfaffian-invariant-form: Pf(DKD) = Pf(K)."""
    D = s.mat([[(-1 if i == 0 else 1) if i == j else 0 for j in range(4)] for i in range(4)], ("r", "r"))
    K = s.X.T @ s.P
    return {"Pf(DKD) - Pf(K)": pf4(D @ K @ D) - pf4(K)}


@claim("n75-ad-psi-rank-ceil", kind="dim", sizes=R_GE_2, fails_at=lambda n, r: r % 2 == 1,
       erratum="twin: rank ad_Ψ = r(r − 1)/2 − ⌈r/2⌉ (ceiling for floor)")
def ad_psi_rank_ceil(s):
    """False twin of h75-ad-psi-rank."""
    r = int(s.r)
    M = matrix_of(s, lambda eta: comm(s.Psi, eta), so_basis(s, "r"), "skew")
    return {"rank ad_Psi": Rank(M, r * (r - 1) // 2 - (r + 1) // 2)}


@claim("n75-theta-rank-no-quotient", kind="dim", sizes=admissible(n_max=5), fails_at=lambda n, r: r >= 2,
       erratum="twin: rank dΘ = dim T*V (the right SO(r)-orbits forgotten; true at r = 1)")
def theta_rank_no_quotient(s):
    """False twin of h75-theta-covering-rank: rank 2nr − r(r + 1)."""
    n, r = int(s.n), int(s.r)
    X, P = s.X, s.P
    Pr = s.In - X @ X.T

    def tangent(b):
        kind, E = b
        if kind == "xi":
            return E @ X, E @ P
        if kind == "w":
            return X - X, X @ E
        return X - X, Pr @ E

    def dTheta(b):
        dX, dP = tangent(b)
        return dP @ X.T + P @ dX.T - dX @ P.T - X @ dP.T + dX @ X.T + X @ dX.T

    basis = ([("xi", E) for E in so_basis(s, "n")] + [("w", E) for E in (so_basis(s, "r") if r >= 2 else [])]
             + [("Z", E) for E in matrix_units(s, "n", "r")])
    M = matrix_of(s, dTheta, basis, "general")
    return {"rank dTheta": Rank(M, 2 * n * r - r * (r + 1))}


@claim("n75-manakov-r-n-euler-sign", kind="id", sizes=R_IS_N, fails_at=lambda n, r: n >= 3,
       erratum="twin: Φ̇ = [Φ, 𝔸Φ] (sign)")
def manakov_r_n_euler_sign(s):
    """False twin of h75-manakov-r-n-velocity."""
    AA = s.sym_operator("AA")
    fl = s.dirac_flow(H_submersion)
    W = AA(s.Phi)
    return {"Xdot X^T - AA(Phi)": fl["X"] @ s.X.T - W,
            "Phidot - [Phi, AA Phi]": s.d(lambda t: t.Phi, fl) - comm(s.Phi, W)}


@claim("n75-coupled-diagonal-momentum-moves", kind="not", expect="nonzero", sizes=COUPLED_R2, fails_at=ALWAYS,
       erratum="twin: the diagonal momentum XᵀP − PᵀX + YᵀQ − QᵀY said to move (it is conserved)")
def coupled_diagonal_momentum_moves(s):
    """False twin of h75-coupled-single-momentum-moves."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled0, z, [("X", "P"), ("Y", "Q")])
    return {"d(Psi_X + Psi_Y)/dt": derivative(
        s, lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"] + w["Y"].T @ w["Q"] - w["Q"].T @ w["Y"], z, fl)}


@claim("n75-dimfol-r-n-minus", kind="dim", sizes=R_IS_N, fails_at=ALWAYS,
       erratum="twin: (dim so(n) − rank so(n))/2")
def dimfol_r_n_minus(s):
    """False twin of h75-dimfol-r-n: a minus sign for the rank of so(n)."""
    n = int(s.n)
    return {"dim_fol(n, n)": Count(dim_fol(n, n), (n * (n - 1) // 2 - n // 2) // 2, "twin")}


@claim("n75-lambda1-casimir-tr-h2", kind="pb", sizes=SMALL, fails_at=lambda n, r: n >= 2,
       erratum="twin: tr h² (the so(n) part) said to be a Casimir of Λ₁")
def lambda1_casimir_tr_h2(s):
    """False twin of h75-lambda1-casimirs-tr-v: ∇ tr h² = −4h ∈ so(n) in the ξ slot."""
    h, v = s.xi, s.generic("v", "n", "n", "sym")
    zeta, theta = s.zeta, s.generic("theta_s", "n", "n", "sym")
    x = h + v
    Z = v - v
    return {"Lambda_1(grad tr h^2, .)": lambda1_form(s, x, h * (-4), Z, zeta, theta)}


@claim("n75-poisson-sphere-inertia-a", kind="id", sizes=N3_R1, fails_at=ALWAYS,
       erratum="twin: inertia tensor A (mᵀA⁻¹m) in place of A⁻¹")
def poisson_sphere_inertia_a(s):
    """False twin of h75-poisson-sphere-rigid-body."""
    m = cross3(s, s.X, s.P)
    detA = s.A[0, 0] * s.A[1, 1] * s.A[2, 2]
    return {"det A H - m^T A^-1 m / 2": H_sp1(s) * detA - s.tr(m.T @ s.Ainv @ m) / 2}
