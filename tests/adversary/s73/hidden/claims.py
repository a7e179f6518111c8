# ruff: noqa
"""s73 hidden round: further statements of Fedorov & Jovanović, written with the public API only.

Every claim here is true as stated (checked independently in indep.py); the false twins are in negatives.py.
Helpers (no claims) are in _h73_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, Rank, admissible, block, claim, comm, det, twisted
from stiefelsym.systems import complex_point, coupled_point, derivative, re_trace, realify_real, stiefel_pairs_flow

from _h73_helpers import (H_coupled, H_quartic, H_sphere, L_big, L_dual, Lambda_complex, Phi_of, Psi_of, cayley,
                          cstar, lagrangian_complex, psi0_complex, sphere_flow, tr_pow, uhlenbeck_F, unitary_r,
                          wedge2)

R_IS_1 = admissible(n_max=4, n_min=2, r_max=1, condition="r = 1, n >= 2 (distinct a_i)")


# 1 ---------------------------------------------------------------------------------------------------
@claim("h73-uhlenbeck-sums", paper=("Mum_geod", "sphere_neum"), kind="id", sizes=R_IS_1)
def uhlenbeck_sums(s):
    """§8, Proposition Mum_geod (Moser), r = 1: the functions F_i = e_i² + Σ_{j≠i}(e_ip_j − e_jp_i)²/(a_i − a_j)
    satisfy on T*S^{n−1}: Σ F_i = (e, e) = 1, Σ a_iF_i = (Ae, e) + (p, p) (twice the Neumann energy of
    (sphere_neum)), and the Hamiltonian of (ii) is Σ F_i/a_i = (A⁻¹e, e) + ½tr(A⁻¹ΦA⁻¹Φ)."""
    F, a, e, p, A, Ai = uhlenbeck_F(s), s.a, s.X, s.P, s.A, s.Ainv
    n = int(s.n)
    S1 = F[0]
    Sa = a[0] * F[0]
    Sinv = F[0] / a[0]
    for i in range(1, n):
        S1 = S1 + F[i]
        Sa = Sa + a[i] * F[i]
        Sinv = Sinv + F[i] / a[i]
    Phi = s.Phi
    return {"sum F_i - 1": S1 - 1,
            "sum a_i F_i - (Ae,e) - (p,p)": Sa - s.tr(e.T @ A @ e) - s.tr(p.T @ p),
            "sum F_i/a_i - (A^-1 e,e) - tr(A^-1 Phi A^-1 Phi)/2":
                Sinv - s.tr(e.T @ Ai @ e) - s.tr(Ai @ Phi @ Ai @ Phi) / 2}


# 2 ---------------------------------------------------------------------------------------------------
def H_uhlenbeck_half(t):
    """½Σ a_iF_i (Mum_geod (i) with α_i = a_i/2)."""
    F, a = uhlenbeck_F(t), t.a
    acc = a[0] * F[0]
    for i in range(1, int(t.n)):
        acc = acc + a[i] * F[i]
    return acc / 2


@claim("h73-uhlenbeck-neumann-flow", paper=("Mum_geod", "sphere_neum"), kind="id", sizes=R_IS_1)
def uhlenbeck_neumann_flow(s):
    """§8, Proposition Mum_geod (i) with α_i = a_i/2: the system on T*S^{n−1} with Hamiltonian ½Σ a_iF_i (written
    in coordinates, with the divisions by a_i − a_j) is the Neumann system (sphere_neum): its Dirac flow is
    ė = p, ṗ = −Ae + ((Ae, e) − (p, p))e."""
    fl = s.dirac_flow(H_uhlenbeck_half)
    ref = sphere_flow(s)
    return {"edot": fl["X"] - ref["X"], "pdot": fl["P"] - ref["P"]}


# 3 ---------------------------------------------------------------------------------------------------
@claim("h73-quartic-flow", paper=("quartic", "dot_XP", "grassmannian"), kind="id", sizes=admissible(n_max=4))
def quartic_flow(s):
    """§7, (quartic): the Hamiltonian flow on T*V_{n,r} of H = ½tr(PᵀP) + tr(XᵀA²X) − tr(XᵀAXXᵀAX) in the
    Lagrange form (dot_XP): ∂H/∂X = 2A²X − 4AX(XᵀAX), ∂H/∂P = P, Π = 0, and
    Ẋ = P, Ṗ = −2A²X + 4AX(XᵀAX) + XΛ, Λ = 2XᵀA²X − 4(XᵀAX)² − PᵀP; the flow is tangent to Ψ⁻¹(0)
    (dΨ/dt = 0), so it reduces to T*G_{n,r}."""
    X, P, A = s.X, s.P, s.A
    M = X.T @ A @ X
    HX, HP = s.gradient(H_quartic)
    fl = s.dirac_flow(H_quartic)
    Lam = (X.T @ A @ A @ X) * 2 - (M @ M) * 4 - P.T @ P
    Pdot = -(A @ A @ X) * 2 + (A @ X @ M) * 4 + X @ Lam
    return {"H_X": HX - ((A @ A @ X) * 2 - (A @ X @ M) * 4), "H_P": HP - P,
            "Xdot": fl["X"] - P, "Pdot": fl["P"] - Pdot,
            "dPsi/dt": s.d(lambda t: Psi_of(t.X, t.P), fl)}


# 4 ---------------------------------------------------------------------------------------------------
R_IS_2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2")


@claim("h73-so2-wedge-invariant", paper=("grassmannian", "neum-gras"), kind="id", sizes=R_IS_2)
def so2_wedge_invariant(s):
    """§7: the quotient map V_{n,2} → G_{n,2}, X ↦ e_1∧e_2, is invariant under the right SO(2)-action, and so is
    every term of (neum-gras) ("Note that (neum-gras) is SO(r)-invariant"): for h = (I − η)(I + η)⁻¹ ∈ SO(2)
    (η ∈ so(2)), (Xh, Ph) gives the same e_1∧e_2, Ae_1∧e_2 + e_1∧Ae_2, ė_1∧ė_2 (ė = p) and
    λ = tr(XᵀAX − ẊᵀẊ)."""
    X, P, A = s.X, s.P, s.A
    h = cayley(s, s.eta, s.Ir)
    Xh, Ph = X @ h, P @ h
    W, Wh = wedge2(s, X), wedge2(s, Xh)
    return {"e1^e2": Wh - W,
            "Ae1^e2 + e1^Ae2": (A @ Wh + Wh @ A) - (A @ W + W @ A),
            "p1^p2": wedge2(s, Ph) - wedge2(s, P),
            "lambda": s.tr(Xh.T @ A @ Xh - Ph.T @ Ph) - s.tr(X.T @ A @ X - P.T @ P),
            "h^T h - I": h.T @ h - s.Ir}


# 5 ---------------------------------------------------------------------------------------------------
@claim("h73-psi-zero-regular", paper=("grassmannian", "momentum_right_map"), kind="dim",
       sizes=admissible(n_max=4))
def psi_zero_regular(s):
    """§7: Ψ⁻¹(0) = {XᵀX = I, XᵀP = 0} is a submanifold of ℝ^{2nr}: the Jacobian of (XᵀX, XᵀP) has rank
    r(r + 1)/2 + r² at a generic point (so dim Ψ⁻¹(0) = 2nr − r(r+1)/2 − r² and
    dim Ψ⁻¹(0)/SO(r) = 2r(n − r) = dim T*G_{n,r})."""
    r = int(s.r)
    J = s.mat(s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P]))
    return {"rank": Rank(J, r * (r + 1) // 2 + r * r)}


# 6 ---------------------------------------------------------------------------------------------------
R_IS_N_1 = admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1")


@claim("h73-mag0-rank", paper=("mag0", "iden1", "YM"), kind="dim", sizes=R_IS_N_1)
def mag0_rank(s):
    """Appendix 1, (mag0): (T*V_{n,n−1})/SO(n−1) ≅ so(n) × S^{n−1}: the right SO(n−1)-invariant map
    (X, P) ↦ (Φ, XXᵀ) = (Ω, I − e_n⊗e_n) restricted to T*V_{n,n−1} has rank dim so(n) + (n − 1) at a
    generic point (stacked with the r(r+1) independent constraints (cond_XP): rank n(n−1) + (n−1)(n+2)/2)."""
    n, r = int(s.n), int(s.r)
    rows = s.jacobian(s.constraints.build) + s.jacobian(lambda t: [Phi_of(t.X, t.P), t.X @ t.X.T])
    return {"rank": Rank(s.mat(rows), r * (r + 1) + n * (n - 1) // 2 + (n - 1))}


# 7 ---------------------------------------------------------------------------------------------------
@claim("h73-mag0-count", paper=("mag0",), kind="dim", sizes=admissible(n_max=6, n_min=2,
       where=lambda n, r: r == n - 1, condition="r = n - 1"))
def mag0_count(s):
    """Appendix 1, (mag0): dim (T*V_{n,n−1})/SO(n−1) = 2 dim V_{n,n−1} − dim SO(n−1) = dim so(n) + dim S^{n−1}."""
    n, r = int(s.n), int(s.r)
    dimV = n * r - r * (r + 1) // 2
    return {"dim": Count(2 * dimV - r * (r - 1) // 2, n * (n - 1) // 2 + (n - 1))}


# 8 ---------------------------------------------------------------------------------------------------
@claim("h73-dual-big-commute", paper=("DUAL", "LA3", "perelomov", "2r-integrals"), kind="pb",
       sizes=admissible(n_max=4))
def dual_big_commute(s):
    """§8 (the integrals of the dual Lax matrix are those of the "big" one, (perelomov)): the spectral invariants
    of 𝓛*_neum(λ) and of 𝓛_neum(μ) = μΦ + XXᵀ − μ²A Poisson-commute (Dirac bracket) for all λ, μ:
    {tr 𝓛*(λ)², tr 𝓛(μ)²} = 0 and {tr 𝓛*(λ)⁴, tr 𝓛(μ)³} = 0."""
    mu = s.scalar("mu")
    return {"{tr L*^2, tr L^2}": s.bracket(lambda t: tr_pow(t, L_dual(t, t.lam), 2),
                                           lambda t: tr_pow(t, L_big(t, mu), 2)),
            "{tr L*^4, tr L^3}": s.bracket(lambda t: tr_pow(t, L_dual(t, t.lam), 4),
                                           lambda t: tr_pow(t, L_big(t, mu), 3))}


# 9 ---------------------------------------------------------------------------------------------------
@claim("h73-invariants-noncommutative", paper=("SO(n)-inv", "LEMA", "iso"), kind="not", expect="nonzero",
       sizes=admissible(n_max=4, r_min=2, where=lambda n, r: (n, r) != (2, 2),
                        condition="r >= 2, (n, r) != (2, 2)"))
def invariants_noncommutative(s):
    """§2, Lemma LEMA and (iso): the algebra C^∞(T*V)^{SO(n)} of the invariants (SO(n)-inv) is not commutative
    (its bracket is that of C^∞(𝔳)^{SO(n−r)}): {tr(S PᵀP), Ψ_η} ≠ 0 for a symmetric S and η ∈ so(r), r ≥ 2
    (at n = r = 2, PᵀP is a multiple of I and the bracket vanishes)."""
    S = s.generic("S", "r", "r", "sym")
    eta = s.eta
    return {"{tr(S P^TP), Psi_eta}": s.bracket(lambda t: t.tr(S @ t.P.T @ t.P),
                                               lambda t: t.tr(eta @ Psi_of(t.X, t.P)))}


# 10 --------------------------------------------------------------------------------------------------
R_IS_N = admissible(n_max=4, r_is_n=True, condition="r = n")


@claim("h73-dual-det-r-n", paper=("2r-integrals", "LA3", "DUAL"), kind="id", sizes=R_IS_N)
def dual_det_r_n(s):
    """§8 after (2r-integrals): 𝓘_{2r}(λ) = a(λ)det 𝓛*_neum(λ) is a polynomial of degree n − r whose leading
    coefficient is a trivial constant; at r = n (T*SO(n)) it is that constant: a(λ)·det 𝓛*(λ) = 1, with
    a(λ) = det(λI − A)."""
    n = int(s.n)
    a = det(s, s.lam * s.In - s.A)
    return {"a(lambda) det L*(lambda) - 1": a * det(s, L_dual(s, s.lam)) - 1}


# 11 --------------------------------------------------------------------------------------------------
@claim("h73-complex-u-r-symmetry", paper=("W0", "W-Lag", "W-L", "dual-complex"), kind="id",
       sizes=admissible(n_max=3, r_max=2))
def complex_u_r_symmetry(s):
    """Appendix 2 ("the system is invariant with respect to a right U(r)-action"): for U = (I − K)(I + K)⁻¹,
    K = η + iS skew-Hermitian, Z ↦ ZU, Ż ↦ ŻU keeps (W0) and its tangency, the Lagrangian (W-Lag), and
    transforms Λ of (W-L) to U*ΛU and the u(n)-momentum ψ₀ = ZᵀŻ̄ − ŻᵀZ̄ to Uᵀψ₀Ū."""
    z = complex_point(s)
    Z, Zd = z["Z"], z["Zdot"]
    U = unitary_r(s, s.eta, s.generic("S", "r", "r", "sym"))
    ZU, ZdU = Z @ U, Zd @ U
    I = realify_real(s, s.Ir)
    Ubar, UT = s.conj(U), cstar(s.conj(U))
    return {"U*U - I": cstar(U) @ U - I,
            "(ZU)*(ZU) - I": cstar(ZU) @ ZU - I,
            "tangency": cstar(ZU) @ ZdU + cstar(ZdU) @ ZU,
            "L(ZU) - L(Z)": lagrangian_complex(s, ZU, ZdU) - lagrangian_complex(s, Z, Zd),
            "Lambda(ZU) - U* Lambda U": Lambda_complex(s, ZU, ZdU) - cstar(U) @ Lambda_complex(s, Z, Zd) @ U,
            "psi0(ZU) - U^T psi0 Ubar": psi0_complex(s, ZU, ZdU) - UT @ psi0_complex(s, Z, Zd) @ Ubar}


# 12 --------------------------------------------------------------------------------------------------
@claim("h73-coupled-prep", paper=("C-neumann", "so(n,n)", "prep"), kind="pb", sizes=admissible(n_max=3))
def coupled_prep(s):
    """Appendix 2, the r-coupled Neumann system (C-neumann), for every κ (the Dirac flow of H = T_κ + tr(XᵀAY) on
    T*V × T*V): the analogue of (prep) that the diagonal blocks of the so(n,n) Lax pair express, the sum of the
    two left SO(n)-momenta moves only by the interaction: d/dt(Φ(X,P) + Φ(Y,Q)) = [XYᵀ + YXᵀ, A]."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled, z, [("X", "P"), ("Y", "Q")])
    X, Y, A = z["X"], z["Y"], s.A
    M = X @ Y.T + Y @ X.T
    return {"d(Phi_X + Phi_Y)/dt - [XY^T + YX^T, A]":
                derivative(s, lambda t, w: Phi_of(w["X"], w["P"]) + Phi_of(w["Y"], w["Q"]), z, fl) - comm(M, A)}


# 13 --------------------------------------------------------------------------------------------------
def H_neum_kappa(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("h73-twisted-psi12-any-kappa", paper=("twisted", "mag-euk", "mag-nor", "neumann"), kind="pb", sizes=R_IS_2)
def twisted_psi12_any_kappa(s):
    """Appendix 1: the Neumann Hamiltonians H_neum,κ are right SO(2)-invariant and ω_mag = de_1∧de_2 is too, so
    for every κ (not only the Euclidean κ = −½ (mag-euk) and the normal κ = 0 (mag-nor)) the twisted flow on
    (T*V_{n,2}, ω_ε) conserves Ψ_12 = (e_1, p_2) − (e_2, p_1) and the energy; and so does the twisted flow of the
    quartic Hamiltonian (quartic)."""
    fk = twisted.flow(s, H_neum_kappa)
    fq = twisted.flow(s, H_quartic)
    psi12 = lambda t: Psi_of(t.X, t.P)[0, 1]
    return {"dPsi12/dt (kappa)": s.d(psi12, fk), "dH/dt (kappa)": s.d(H_neum_kappa, fk),
            "dPsi12/dt (quartic)": s.d(psi12, fq)}
