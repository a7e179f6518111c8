# ruff: noqa
"""s75 hidden round: thirteen further statements of Fedorov & Jovanović, written with the public API only.

Every claim here is true as stated (checked independently in indep.py.in); the false twins are in negatives.py.
Helpers (no claims) are in _h75_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis
from stiefelsym.systems import coupled_point, derivative, stiefel_pairs_flow

from _h75_helpers import (H_kappa_of, pf4, H_B, H_K_of, H_coupled0, H_neum_kappa_A, H_normal, H_sp1, H_submersion,
                          block_projectors, cross3, dim_fol, killing, lambda1_form, lambda1_op, repeated_A)

SMALL = admissible(n_max=4)
R_GE_2 = admissible(n_max=5, r_min=2, condition="r >= 2 (so(1) = 0)")
R_GE_3 = admissible(n_max=5, r_min=3, condition="r >= 3 (two nonzero blocks of so(r) that do not commute)")
N_GE_2 = admissible(n_max=4, n_min=2, condition="n >= 2 (a₁ = a₂ needs two eigenvalues)")
N_GE_3 = admissible(n_max=4, n_min=3, condition="n >= 3 (so(2) is abelian)")
R_LT_N = admissible(n_max=5, where=lambda n, r: r < n, condition="r < n (G(n, n) is a point)")
R_IS_N = admissible(n_max=5, n_min=2, where=lambda n, r: r == n, condition="r = n >= 2 (T*SO(n))")
R_IS_4 = admissible(n_max=5, r_min=4, r_max=4, condition="r = 4 (so(4) is not simple)")
SMALL5 = admissible(n_max=5)
COUPLED_R2 = admissible(n_max=3, r_min=2, condition="r >= 2 (so(1) = 0)")
N3_R1 = admissible(n_min=3, stated_n_max=3, r_max=1, condition="n = 3, r = 1 (the Poisson sphere S²)")


# 1 ---------------------------------------------------------------------------------------------------
@claim("h75-hb-euler-psi", paper=("e-so(r)", "HB", "CIF", "momentum_right_map"), kind="id", sizes=SMALL)
def hb_euler_psi(s):
    """§6, Theorem CIF(ii) and (e-so(r)): along the geodesic flow of H_𝔹 = ½tr(PᵀP) − ¼tr(Ψ𝔹(Ψ)) (𝔹 a
    symmetric operator on so(r)) the right momentum Ψ obeys the Euler equations (e-so(r)) of h_𝔹,
    Ψ̇ = [Ψ, 𝔹Ψ], while the left momentum Φ is conserved (H_𝔹 is SO(n)-invariant)."""
    fl = s.dirac_flow(H_B)
    BB = s.sym_operator("BB")
    return {"Psidot - [Psi, B Psi]": s.d(lambda t: t.Psi, fl) - comm(s.Psi, BB(s.Psi)),
            "Phidot": s.d(lambda t: t.Phi, fl)}


# 2 ---------------------------------------------------------------------------------------------------
@claim("h75-jensen-blocks-conserved", paper=("EM2", "EM3", "nikinorov"), kind="id", sizes=R_GE_2)
def jensen_blocks_conserved(s):
    """§3 (EM2), (EM3) and Corollary nikinorov: for so(r₁) ⊕ so(r₂) ⊂ so(r) (r₁ = ⌈r/2⌉), the flow of
    H_K = ½<Φ,Φ> + κ₀/2<Ψ,Ψ> + κ₁/2<Ψ₁,Ψ₁> + κ₂/2<Ψ₂,Ψ₂> conserves Φ, the block momenta Ψ₁, Ψ₂ (the
    momentum of SO(r₁) × SO(r₂)) and <Ψ, Ψ>."""
    D1, D2 = block_projectors(s)
    H = H_K_of(D1, D2)
    fl = s.dirac_flow(H)
    return {"Phidot": s.d(lambda t: t.Phi, fl),
            "Psi_1 dot": s.d(lambda t: D1 @ t.Psi @ D1, fl),
            "Psi_2 dot": s.d(lambda t: D2 @ t.Psi @ D2, fl),
            "<Psi,Psi> dot": s.d(lambda t: killing(t, t.Psi, t.Psi), fl)}


# 3 ---------------------------------------------------------------------------------------------------
@claim("h75-jensen-offdiag-moves", paper=("EM2", "EM3"), kind="not", expect="nonzero", sizes=R_GE_3)
def jensen_offdiag_moves(s):
    """§3 (EM2), (EM3): for r ≥ 3 (and generic κ₁, κ₂) H_K is SO(r₁) × SO(r₂)-invariant only: the
    off-diagonal block D₁ΨD₂ of Ψ is not conserved."""
    D1, D2 = block_projectors(s)
    fl = s.dirac_flow(H_K_of(D1, D2))
    return {"d(D1 Psi D2)/dt": s.d(lambda t: D1 @ t.Psi @ D2, fl)}


# 4 ---------------------------------------------------------------------------------------------------
@claim("h75-submersion-psi-conserved", paper=("submersion_metric", "dot_XP2", "momentum_right_map"),
       kind="pb", sizes=SMALL)
def submersion_psi_conserved(s):
    """§3 (submersion_metric): H_𝔸 = h_𝔸∘Φ is a function of the left momentum Φ, which is SO(r)-invariant:
    {Ψ_η, H_𝔸} = 0 and Ψ is conserved by (dot_XP2), for every symmetric 𝔸; the normal metric also
    commutes with Φ ({Φ_ξ, H_0} = 0)."""
    fl = s.dirac_flow(H_submersion)
    return {"{Psi_eta, H_AA}": s.bracket(lambda t: killing(t, t.Psi, s.eta), H_submersion),
            "Psidot": s.d(lambda t: t.Psi, fl),
            "{Phi_xi, H_0}": s.bracket(lambda t: killing(t, t.Phi, s.xi), H_normal)}


# 5 ---------------------------------------------------------------------------------------------------
@claim("h75-submersion-phi-moves", paper=("submersion_metric", "normal_metric", "dot_XP2"), kind="not",
       expect="nonzero", sizes=N_GE_3)
def submersion_phi_moves(s):
    """§3, the normal metric: "contrary to a generic submersion metric, the normal metric is also
    SO(n)-invariant": for a generic symmetric 𝔸 on so(n) (n ≥ 3) Φ is not conserved by (dot_XP2)."""
    fl = s.dirac_flow(H_submersion)
    return {"Phidot": s.d(lambda t: t.Phi, fl)}


# 6 ---------------------------------------------------------------------------------------------------
@claim("h75-pfaffian-invariant-form", paper=("EM", "P-neutral", "SO(n-r)-action"), kind="id", sizes=R_IS_4)
def pfaffian_invariant_form(s):
    """§4, the Proposition on SO(n) × SO(r)-invariant metrics, another form of the catalog's erratum
    (invariant-metrics) at r = 4: the quadratic form Pf(XᵀP) = K₁₂K₃₄ − K₁₃K₂₄ + K₁₄K₂₃ (K = XᵀP) is invariant
    under the left SO(n) and the right SO(r) actions (its derivatives along (ξX, ξP) and (Xη, Pη) vanish), so
    ½tr(PᵀP) + b Pf(XᵀP) (b small) is an SO(n) × SO(4)-invariant metric; it changes sign under the reflection
    (X, P) ↦ (XD, PD), D = diag(−1, 1, 1, 1), which leaves every H_κ of (EM) unchanged, so it is not a ds²_κ."""
    D = s.mat([[(-1 if i == 0 else 1) if i == j else 0 for j in range(4)] for i in range(4)], ("r", "r"))
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    K = s.X.T @ s.P
    return {"d Pf along left so(n)": s.d(lambda t: pf4(t.X.T @ t.P), left),
            "d Pf along right so(r)": s.d(lambda t: pf4(t.X.T @ t.P), right),
            "Pf(DKD) + Pf(K)": pf4(D @ K @ D) + pf4(K),
            "H_kappa(XD, PD) - H_kappa(X, P)": H_kappa_of(s, s.X @ D, s.P @ D) - H_kappa_of(s, s.X, s.P)}


# 7 ---------------------------------------------------------------------------------------------------
@claim("h75-ad-psi-rank", paper=("dim_fol", "torus", "momentum_right_map"), kind="dim", sizes=R_GE_2)
def ad_psi_rank(s):
    """§6, proof of Theorem NEUMANN ((dim_fol), (torus)): at a generic point Ψ(X, P) is regular in so(r),
    i.e. its Ad_{SO(r)}-orbit has dimension r(r − 1)/2 − [r/2]: rank ad_Ψ = r(r − 1)/2 − [r/2]."""
    r = int(s.r)
    M = matrix_of(s, lambda eta: comm(s.Psi, eta), so_basis(s, "r"), "skew")
    return {"rank ad_Psi": Rank(M, r * (r - 1) // 2 - r // 2)}


# 8 ---------------------------------------------------------------------------------------------------
@claim("h75-theta-covering-rank", paper=("LAMBDA12", "REDUCED_BRACKET", "dimension"), kind="dim", sizes=SMALL5)
def theta_covering_rank(s):
    """§6, proof of Theorem NEUMANN: Θ = Φ + XXᵀ is invariant under the right SO(r)-action (and (X, P) ↦
    (−X, −P)) and induces a ℤ₂-covering θ: (T*V)/SO(r) → Θ(T*V); so the differential of Θ on T(T*V) has rank
    dim T*V − dim SO(r) = 2nr − r(r + 1) − r(r − 1)/2.  Tangent vectors of T*V: (ξX, ξP) (ξ ∈ so(n), SO(n) is
    transitive on V) and (0, Xw + (I − XXᵀ)Z) (w ∈ so(r), Z ∈ ℝ^{n×r})."""
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
    return {"rank dTheta on T(T*V)": Rank(M, 2 * n * r - r * (r + 1) - r * (r - 1) // 2)}


# 9 ---------------------------------------------------------------------------------------------------
@claim("h75-manakov-r-n-velocity", paper=("dot_XP2", "submersion_metric", "Euler-so(n)"), kind="id",
       sizes=R_IS_N)
def manakov_r_n_velocity(s):
    """§3, remark after (dot_XP2): for r = n (dot_XP2) is the right-invariant geodesic flow on SO(n): the
    space angular velocity is ẊX⁻¹ = ẊXᵀ = 𝔸(Φ), and the space momentum obeys Φ̇ = [𝔸(Φ), Φ]."""
    AA = s.sym_operator("AA")
    fl = s.dirac_flow(H_submersion)
    W = AA(s.Phi)
    return {"Xdot X^T - AA(Phi)": fl["X"] @ s.X.T - W,
            "Phidot - [AA Phi, Phi]": s.d(lambda t: t.Phi, fl) - comm(W, s.Phi)}


# 10 --------------------------------------------------------------------------------------------------
@claim("h75-coupled-single-momentum-moves", paper=("C-eq", "C-neumann", "C-L"), kind="not", expect="nonzero",
       sizes=COUPLED_R2)
def coupled_single_momentum_moves(s):
    """Appendix 2, after (C-L): the r-coupled systems are invariant only under the diagonal right SO(r)-action;
    the momentum XᵀP − PᵀX of the first factor alone is not conserved (κ = 0; r ≥ 2)."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled0, z, [("X", "P"), ("Y", "Q")])
    return {"d(X^T P - P^T X)/dt": derivative(s, lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"], z, fl)}


# 11 --------------------------------------------------------------------------------------------------
@claim("h75-dimfol-r-n", paper=("dim_fol", "NEUMANN", "2l"), kind="dim", sizes=R_IS_N)
def dimfol_r_n(s):
    """§6, (dim_fol) at r = n (T*SO(n)): the isotropic tori have dimension ½(dim so(n) + rank so(n)) =
    (n(n − 1)/2 + [n/2])/2, where rank so(n) = [n/2] is the dimension of the kernel of ad_Φ at a generic Φ
    (rank ad_Φ = n(n − 1)/2 − [n/2])."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: comm(s.Phi, xi), so_basis(s, "n"), "skew")
    return {"dim_fol(n, n)": Count(dim_fol(n, n), (n * (n - 1) // 2 + n // 2) // 2,
                                   "(dim_fol) at r = n against (dim so(n) + rank so(n))/2"),
            "rank ad_Phi": Rank(M, n * (n - 1) // 2 - n // 2)}


# 12 --------------------------------------------------------------------------------------------------
@claim("h75-lambda1-casimirs-tr-v", paper=("LAMBDA12", "central", "symmetric-pair"), kind="pb", sizes=SMALL)
def lambda1_casimirs_tr_v(s):
    """§6: the λ = 0 members of (central), tr v^k, are Casimirs of Λ₁ (the Lie–Poisson bracket of
    so(n) ⊕_ad Sym(n)): ∇ tr v^k = −2k v^{k−1} ∈ Sym(n), and Λ₁(∇ tr v^k, ζ + θ) = 0 at a generic
    x = h + v for every ζ ∈ so(n), θ ∈ Sym(n) (k = 2, 3, 4)."""
    h, v = s.xi, s.generic("v", "n", "n", "sym")
    zeta, theta = s.zeta, s.generic("theta_s", "n", "n", "sym")
    x = h + v
    Z = h - h
    out = {}
    vpow = v  # v^{k-1}
    for k in (2, 3, 4):
        out[f"Lambda_1(grad tr v^{k}, .)"] = lambda1_form(s, x, Z, vpow * (-2 * k), zeta, theta)
        vpow = vpow @ v
    return out


# 13 --------------------------------------------------------------------------------------------------
@claim("h75-poisson-sphere-rigid-body", paper=("sp1", "P_q", "Chasles-Manakov"), kind="id", sizes=N3_R1)
def poisson_sphere_rigid_body(s):
    """§8, the Poisson sphere: for n = 3 the metric (sp1) is proportional to the metric of the SO(2)-reduced
    free rigid body with inertia tensor I = A⁻¹: with the angular momentum m = e × p,
    H_{sp1} = −¼tr(A⁻¹ΦA⁻¹Φ) = ½(det A)⁻¹ mᵀI⁻¹m = ½(det A)⁻¹ mᵀAm."""
    e, p = s.X, s.P
    m = cross3(s, e, p)
    detA = s.A[0, 0] * s.A[1, 1] * s.A[2, 2]
    return {"det A H - m^T A m / 2": H_sp1(s) * detA - s.tr(m.T @ s.A @ m) / 2}
