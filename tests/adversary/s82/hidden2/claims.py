"""s82 hidden2 (h5): statements of §5, §6, §8 of Fedorov & Jovanović written from the text in my own way
(consequences, composites, special cases, ranks with kernel certificates).  Each is true; derivations by hand in
each docstring, numpy checks (no stiefelsym) in indep.py.in / indep_output.txt.  The false twins are in twins.py."""
from __future__ import annotations

from stiefelsym import Rank, admissible, block, claim, comm, elementary
from stiefelsym.bases import matrix_of, matrix_units, so_basis  # noqa: F401

from _common import (H_kappa, H_kappa0, J_r, L_star, centralizer_kernel, e2_explicit, gl_orbit_rank,
                     l1_kernel, l1_matrix, so_r_fields, theta, theta_jacobian)

ALL = admissible(n_max=5)
N2 = admissible(n_max=5, n_min=2, condition="n >= 2 (so(1) = 0)")
R1 = admissible(n_max=5, r_max=1, condition="r = 1 (the line l(t) of Prop. Mum_geod)")


# ------------------------------------------------------------------------------------------- §5

@claim("h5-neumann-potential-rate", paper=("neumann", "No", "Neumann_potential"), kind="id", section="5", sizes=ALL)
def potential_rate(s):
    """Along (No) for every κ, the potential V = ½tr XᵀAX changes at the rate tr(XᵀAP), independent of κ.
    Hand: dV/dt = tr(XᵀA Ẋ) = tr(XᵀAP) − (1+2κ) tr(XᵀAX·PᵀX); XᵀAX is symmetric and PᵀX is skew on T*V
    (XᵀP + PᵀX = 0), so the last trace vanishes."""
    flow = s.dirac_flow(H_kappa)
    V = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2
    return {"dV/dt - tr(X^T A P)": s.d(V, flow) - s.tr(s.X.T @ s.A @ s.P)}


@claim("h5-neumann-quadratic-integral", paper=("prep", "perelomov", "No"), kind="pb", section="5", sizes=ALL)
def quadratic_integral(s):
    """The λ² coefficient of tr 𝓛_neum(λ)² (perelomov, k = 2) is tr Φ² − 2 tr(XᵀAX), conserved along (No) for
    every κ.  Hand from (prep): d tr Φ²/dt = 2tr(Φ[XXᵀ, A]) = 2tr([Φ, XXᵀ]A) = 2 tr(d(XXᵀ)/dt · A)
    = 2 d tr(XᵀAX)/dt."""
    flow = s.dirac_flow(H_kappa)
    I = lambda t: t.tr(t.Phi @ t.Phi) - 2 * t.tr(t.X.T @ t.A @ t.X)
    return {"d/dt (tr Phi^2 - 2 tr X^T A X)": s.d(I, flow)}


@claim("h5-neumann-kappa-linear", paper=("No", "N0_XP2"), kind="id", section="5", sizes=ALL)
def kappa_linear(s):
    """(No) is affine in κ: flow_κ − flow_0 = κ(−2XPᵀX, 2PXᵀP).  Hand: read off (No): Ẋ has −(1+2κ)XPᵀX,
    Ṗ has +(1+2κ)PXᵀP, the other terms (P, −AX − XPᵀP + XXᵀAX) do not contain κ."""
    f, f0 = s.dirac_flow(H_kappa), s.dirac_flow(H_kappa0)
    X, P, k = s.X, s.P, s.kappa
    return {"X: difference": f.Xdot - f0.Xdot - k * (-2 * (X @ P.T @ X)),
            "P: difference": f.Pdot - f0.Pdot - k * (2 * (P @ X.T @ P))}


# ------------------------------------------------------------------------------------------- §6





@claim("h5-theta-rank", paper=("LAMBDA12", "dimension", "REDUCED_BRACKET"), kind="dim", section="6", sizes=ALL)
def theta_rank(s):
    """Θ = Φ + XXᵀ restricted to T*V has rank 2 dim V(n, r) − dim so(r): it is right SO(r)-invariant, and the
    orbits are its generic fibres up to the ℤ₂ (X, P) ↦ (−X, −P).  Written ambiently: the 2nr columns of
    [dΘ; d(XᵀX); d(XᵀP + PᵀX)] (upper triangles) have rank 2nr − r(r−1)/2, since the kernel of the stacked
    Jacobian is T(T*V) ∩ ker dΘ = the so(r) fields (Xη, Pη).  Certificate: those fields (they kill dΘ because
    Θ(Xg, Pg) = Θ(X, P) for g ∈ O(r), and kill the constraints' differentials [XᵀX, η], [XᵀP + PᵀX, η] on
    T*V).  numpy: indep_output.txt S4."""
    n, r = int(s.n), int(s.r)
    K = so_r_fields(s)
    expected = 2 * n * r - r * (r - 1) // 2
    return {"rank [dTheta; dC]": Rank(theta_jacobian(s), expected, generic=True, kernel=K)}






@claim("h5-l1-rank", paper=("L1", "LEMA1"), kind="dim", section="6", sizes=N2)
def l1_rank(s):
    """(L1) of Lemma LEMA1: the solutions ξ ∈ so(n) of [ξ, v] = 0, v = XXᵀ, form so(r) ⊕ so(n−r); so the map
    ξ ↦ [ξ, XXᵀ] on so(n) has rank dim so(n) − dim so(r) − dim so(n−r) = r(n − r).  Certificate: XηXᵀ and
    (I − XXᵀ)E(I − XXᵀ) commute with XXᵀ (XXᵀ is the projector on span X; both are block-diagonal for it)."""
    n, r = int(s.n), int(s.r)
    return {"rank ad_v on so(n)": Rank(l1_matrix(s), r * (n - r), generic=True, kernel=l1_kernel(s))}


@claim("h5-l1-rank-everywhere", paper=("L1", "LEMA1"), kind="dim", section="6", sizes=N2)
def l1_rank_everywhere(s):
    """The same rank r(n − r) at every point of V(n, r) (SO(n) moves X to X₀ = (E₁ … E_r), where it is the
    number of pairs (i ≤ r < j))."""
    n, r = int(s.n), int(s.r)
    return {"rank ad_v on so(n) everywhere": Rank(l1_matrix(s), r * (n - r), generic=False)}






@claim("h5-gl-orbit-at-theta", paper=("LAMBDA12", "FF", "dimension"), kind="dim", section="6", sizes=ALL)
def gl_orbit_at_theta(s):
    """With A = 0 the tensor Λ2 is the Lie–Poisson tensor of gl(n); at x = Θ(X, P) its rank is the dimension of
    the adjoint orbit of x: x maps span(X, P)^⊥ to 0 and span(X, P) (dim m = min(2r, n)) to itself, x = diag(x', 0)
    with x' regular and invertible, so its centralizer is {diag(p(x'), M)} of dimension m + (n − m)², and the rank
    of u ↦ [x, u] on gl(n) is n² − m − (n − m)² (n² − n when 2r ≥ n).  Certificate: powers of x and E0 M E0."""
    n, r = int(s.n), int(s.r)
    x = theta(s)
    M = matrix_of(s, lambda u: comm(x, u), matrix_units(s, "n", "n"))
    return {"rank ad_Theta on gl(n)": Rank(M, gl_orbit_rank(n, r), generic=True, kernel=centralizer_kernel(s, x))}


# ------------------------------------------------------------------------------------------- §8

@claim("h5-dual-e2-trace", paper=("LA3", "2r-integrals"), kind="id", section="8", sizes=ALL)
def dual_e2_trace(s):
    """The w^{2r−2} coefficient of the dual spectral curve is a(λ)·𝓘₂(λ)/a(λ)² scaled: e₂(𝓛*(λ)) equals the
    printed 𝓘₂(λ)/a(λ) = Σ_i (XXᵀ)_ii/(λ − a_i) + Σ_{i<j} Φ_ij²/((λ − a_i)(λ − a_j)) = tr(R XXᵀ) − ½tr(RΦRΦ),
    R = (λ − A)⁻¹; and since tr 𝓛* = 0, e₂ = −½ tr 𝓛*².  Hand: with 𝓛* = [[a, b], [c, −aᵀ]], a = −XᵀRP,
    b = −XᵀRX, c = I + PᵀRP: tr 𝓛*² = 2tr a² + 2tr(bc) = 2tr(XᵀRPXᵀRP) − 2tr(XᵀRX) − 2tr(XᵀRXPᵀRP), and
    tr(RΦRΦ) = 2tr(RPXᵀRPXᵀ) − 2tr(XᵀRXPᵀRP).  (No constraint is used.)"""
    L = L_star(s, s.lam)
    e = elementary(s, L, 2)
    rhs = e2_explicit(s, s.lam)
    return {"e2(L*) - (tr RXX^T - 1/2 tr R Phi R Phi)": e[2] - rhs,
            "-1/2 tr L*^2 - (...)": -s.tr(L @ L) / 2 - rhs,
            "tr L*": s.tr(L)}


@claim("h5-dual-so-r-covariance", paper=("LA3", "2r-integrals", "right_action"), kind="id", section="8", sizes=ALL)
def dual_so_r_covariance(s):
    """'𝓛* is not invariant under the right SO(r)-action, the spectral curve is': infinitesimally, along
    (δX, δP) = (Xη, Pη), η ∈ so(r), δ𝓛* = [𝓛*, diag(η, η)].  Hand: δ(−XᵀRP) = −ηᵀXᵀRP − XᵀRPη = [a, η] (ηᵀ = −η),
    likewise for b, d and c − I."""
    eta = s.eta
    z = s.zeros(s.r, s.r, ("r", "r"))
    D = block([[eta, z], [z, eta]])
    dL = s.d(lambda t: L_star(t, s.lam), {"X": s.X @ eta, "P": s.P @ eta})
    return {"dL* - [L*, diag(eta, eta)]": dL - comm(L_star(s, s.lam), D)}


@claim("h5-dual-hamiltonian-matrix", paper=("LA3", "2r-integrals"), kind="id", section="8", sizes=ALL)
def dual_hamiltonian_matrix(s):
    """'Due to the symplectic block structure of 𝓛*, the coefficients at odd powers of w vanish': J𝓛*(λ) is
    symmetric (J = [[0, I], [−I, 0]]), i.e. 𝓛* ∈ sp(2r), whose characteristic polynomial is even: e₁ = e₃ = 0.
    Hand: J𝓛* = [[c, −aᵀ], [−a, −b]] with b, c symmetric."""
    L = L_star(s, s.lam)
    JL = J_r(s) @ L
    e = elementary(s, L, 3)
    return {"J L* - (J L*)^T": JL - JL.T, "e3(L*)": e[3]}


@claim("h5-chasles-r1-discriminant", paper=("Mum_geod", "2r-integrals", "conf0", "Gen_Chasles"), kind="geo",
       section="8", sizes=R1)
def chasles_r1_discriminant(s):
    """r = 1: the line l = p + span(e) meets Q(λ) = {Σ x_i²/(a_i − λ) = 1} where s²⟨e,Ce⟩ + 2s⟨e,Cp⟩ + ⟨p,Cp⟩ − 1 = 0,
    C = (A − λ)⁻¹; it is tangent iff the discriminant ⟨e,Ce⟩(⟨p,Cp⟩ − 1) − ⟨e,Cp⟩² vanishes, and that discriminant
    is exactly e₂(𝓛*(λ)) = 𝓘₂(λ)/a(λ) (C = −R: (−eᵀRe)(−pᵀRp − 1) − (eᵀRp)² = eᵀRe + eᵀRe·pᵀRp − (eᵀRp)², which is
    tr(RXXᵀ) − ½tr(RΦRΦ) at r = 1)."""
    C = -s.resolvent(s.lam)
    e, p = s.X, s.P
    disc = s.tr(e.T @ C @ e) * (s.tr(p.T @ C @ p) - 1) - s.tr(e.T @ C @ p) * s.tr(e.T @ C @ p)
    return {"disc - e2(L*)": disc - elementary(s, L_star(s, s.lam), 2)[2]}


@claim("h5-dual-e2-conserved-every-kappa", paper=("DUAL", "2r-integrals", "prep", "No"), kind="pb", section="8",
       sizes=ALL)
def dual_e2_conserved(s):
    """tr(R XXᵀ) − ½tr(RΦRΦ) (= e₂(𝓛*(λ))) is a function of Φ and XXᵀ only, whose derivatives (prep) do not
    depend on κ: so it is conserved along (No) for every κ, not only the two flows of Theorem DUAL.  Hand:
    d/dt = tr(R[Φ, v]) − tr(R[v, A]RΦ) (v = XXᵀ) = tr(Φ[v, R]) − tr(Φ[R, v]) ... the λ-expansion gives at
    order λ⁻² the integral of h5-neumann-quadratic-integral (times −½), and at every order the Perelomov
    integrals' combination; numpy: indep_output.txt S11 at κ = random, 0, −½."""
    flow = s.dirac_flow(H_kappa)
    return {"d e2/dt": s.d(lambda t: e2_explicit(t, s.lam), flow)}
