# ruff: noqa
"""s80 hidden round (h2): statements of Fedorov & Jovanović (§3, §4, §6, §7, §8) that neither the catalog nor the
earlier rounds (s71–s79) nor the shipped examples state (true; numpy check in indep.py.in).  Run with
    stiefelsym verify --claims tests/adversary/s80/hidden/claims.py --method M --jobs 1 --timeout 120 --no-report
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Rank, admissible, claim, comm, elementary
from stiefelsym.bases import matrix_of, matrix_units, so_basis

from _h80_helpers import (H_E, H_kappa_of, H_metric, H_neum_of, H_sub, dual_L, lam1, lam1_vec, lam2, lam2_vec)

ALL = admissible(n_max=5)
RN = admissible(n_max=5, r_is_n=True, condition="r = n: T*V(n, n) = T*O(n)")
DIM = admissible(n_max=5)


def dim_so(m):
    return m * (m - 1) // 2 if m > 1 else 0


# 1 ------------------------------------------------------------------------------------------------------------
@claim("h80-submersion-gradient", paper=("submersion_metric", "dot_XP2"), kind="id", sizes=ALL,
       statement=r"H_{\mathbb A}=\tfrac12\langle\mathbb A\Phi,\Phi\rangle:\quad \frac{\partial H_{\mathbb A}}{\partial P}=\mathbb A(\Phi)X,\ "
                 r"-\frac{\partial H_{\mathbb A}}{\partial X}=\mathbb A(\Phi)P")
def submersion_gradient(s):
    """§3, proof of the Proposition (dot_XP2): 'by using the chain rule dH = dh_𝔸∘dΦ, one gets expressions
    (dot_XP2) for the derivatives of the Hamiltonian (submersion_metric) with respect to P and −X' (ambient
    gradient of the printed trace form; by hand dH = ⟨𝔸Φ, dP Xᵀ − X dPᵀ + P dXᵀ − dX Pᵀ⟩ gives
    ∂H/∂P = 𝔸(Φ)X, ∂H/∂X = −𝔸(Φ)P)."""
    AA = s.sym_operator("AA")
    HX, HP = s.gradient(lambda t: -t.tr(t.sym_operator("AA")(t.P @ t.X.T - t.X @ t.P.T) @ (t.P @ t.X.T - t.X @ t.P.T)) / 4)
    return {"dH/dP - AA(Phi) X": HP - AA(s.Phi) @ s.X, "-dH/dX - AA(Phi) P": -HX - AA(s.Phi) @ s.P}


# 2 ------------------------------------------------------------------------------------------------------------
@claim("h80-euclid-commutes-submersion", paper=("so(n)+so(r)", "ET", "submersion_metric", "EM"), kind="pb", sizes=ALL,
       statement=r"\{H_E,H_{\mathbb A}\}=0,\ \{H_\kappa,H_{\mathbb A}\}=0\ \text{for every symmetric }\mathbb A\text{ on }so(n)")
def euclid_commutes_submersion(s):
    """§4, Remark after Theorem ET: the Euclidean and the normal geodesic flows share the foliation of the
    integrals (so(n)+so(r)), which contain Φ*(C^∞(so(n))).  Hence every submersion Hamiltonian H_𝔸 = h_𝔸∘Φ
    Poisson-commutes with H_E and with every Jensen H_κ (by hand: H_κ = ½⟨Φ,Φ⟩ + κ/2⟨Ψ,Ψ⟩; ½⟨Φ,Φ⟩∘Φ is a
    Casimir pull-back, and Ψ commutes with Φ)."""
    return {"{H_E, H_AA}": s.bracket(H_E, H_sub),
            "{H_kappa, H_AA}": s.bracket(H_kappa_of(s.kappa), H_sub)}


# 3 ------------------------------------------------------------------------------------------------------------
@claim("h80-lambda-1m1-kernel-explicit", paper=("LEMA2", "LAMBDA", "L3", "L4", "LAMBDA12"), kind="pb", sizes=ALL,
       statement=r"\eta_k=A^k,\ \xi_k=-\sum_{a+b=k-1}A^ahA^b:\ (\Lambda_1-\Lambda_2)(\xi_k+\eta_k,\zeta+\theta)|_{h+v}=0,\ k=0..3,\ "
                 r"h+v=\Theta(X,P)")
def lambda_1m1_kernel_explicit(s):
    """§6, proof of Lemma LEMA2, (L3), (L4): the solutions of [η, A] = 0 are the diagonal matrices, and ξ is then
    determined by [ξ, A] = [η, h]; for η = A^k this is ξ = −ad_A⁻¹ad_{A^k}h = −Σ_{a+b=k−1} A^a h A^b (a Manakov
    operator).  These ξ + η lie in the kernel of Λ_{1,−1} = Λ1 − Λ2 (both from the definition (LAMBDA12)) at
    x = h + v = Θ(X, P), tested against a generic ζ + θ ∈ so(n) ⊕ Sym(n)."""
    h, v, A = s.Phi, s.X @ s.X.T, s.A
    x = h + v
    G = s.fresh("n", "n")
    z = G            # a generic element of gl(n) = ζ + θ
    out = {}
    xi = s.zeros(s.n, s.n, ("n", "n"))
    Ak = s.In
    for k in range(4):
        if k > 0:
            xi = -sum((_pow(A, a, s) @ h @ _pow(A, k - 1 - a, s) for a in range(k)), s.zeros(s.n, s.n, ("n", "n")))
            Ak = Ak @ A
        y = xi + Ak
        out[f"Lambda_(1,-1)(xi_{k} + A^{k}, z)"] = lam1(x, y, z) - lam2(x, A, y, z)
    return out


def _pow(A, a, s):
    M = s.In
    for _ in range(a):
        M = M @ A
    return M


# 4 ------------------------------------------------------------------------------------------------------------
@claim("h80-a1-rank-psi-zero", paper=("NEUMANN2", "LEMA2", "LAMBDA12"), kind="dim", sizes=admissible(n_max=4),
       statement=r"X^TP=0:\ \rank\Lambda_{1,1}\big(\Theta(X,P)\big)=n^2-n\quad\text{((A1) for }h_1=0)")
def a1_rank_psi_zero(s):
    """§7, proof of Theorem NEUMANN2: 'by modifying the proof of Lemma LEMA1 one can prove (A1) … for x = h + v
    with h₁ = 0 as well': at x = Θ(X, P̃), P̃ = (I − XXᵀ)P (so XᵀP̃ = 0: a generic point of Ψ⁻¹(0)), the bracket
    Λ_{1,1} = Λ1 + Λ2 of the pencil has the maximal rank n² − n (the rank of the linear map y ↦ Λ_{1,1}(y, ·)
    on gl(n), written from (LAMBDA12))."""
    n = int(s.n)
    Pt = s.P - s.X @ (s.X.T @ s.P)
    x = (Pt @ s.X.T - s.X @ Pt.T) + s.X @ s.X.T
    M = matrix_of(s, lambda y: lam1_vec(x, y) + lam2_vec(x, s.A, y), matrix_units(s, "n", "n"))
    return {"rank Lambda_(1,1) at Theta(Psi^-1(0))": Rank(M, n * n - n)}


# 5 ------------------------------------------------------------------------------------------------------------
@claim("h80-metric-psi-momentum-map", paper=("cond_XP2", "momentum_right_map", "right_action", "A_XP"), kind="pb",
       realization="metric", sizes=ALL,
       statement=r"(\text{cond\_XP2}):\ X_{\Psi_\eta}=(X\eta,P\eta),\ \{\Psi_\eta,\Psi_\zeta\}_A=-\langle\Psi,[\eta,\zeta]\rangle")
def metric_psi_momentum_map(s):
    """§3, SO(r)-invariant metrics: 'ds²_A is right SO(r)-invariant and, via submersion, induces a metric on G_{n,r}'.
    In the realization (cond_XP2) of T*V the right action (XQ, PQ) still preserves the constraints, so
    Ψ = XᵀP − PᵀX is its momentum map for the Dirac bracket {,}_A: the Hamiltonian vector field of
    Ψ_η = ⟨Ψ, η⟩ is (Xη, Pη), and Ψ is Poisson for the (−) Lie–Poisson bracket of so(r)."""
    eta, zeta = s.eta, s.generic("Z", "r", "r", "skew")
    psi_eta = lambda t: t.killing(t.X.T @ t.P - t.P.T @ t.X, t.eta)
    psi_zeta = lambda t: t.killing(t.X.T @ t.P - t.P.T @ t.X, t.generic("Z", "r", "r", "skew"))
    flow = s.dirac_flow(psi_eta)
    return {"X-flow of Psi_eta - X eta": flow.Xdot - s.X @ eta,
            "P-flow of Psi_eta - P eta": flow.Pdot - s.P @ eta,
            "{Psi_eta, Psi_zeta}_A + <Psi, [eta, zeta]>": s.bracket(psi_eta, psi_zeta) + s.killing(s.Psi, comm(eta, zeta))}


# 6 ------------------------------------------------------------------------------------------------------------
@claim("h80-dual-lax-bi-invariant-r-n", paper=("DUAL", "LA3", "Neumann_LA", "normal_metric"), kind="pb", sizes=RN,
       statement=r"r=n:\ \tfrac{d}{dt}e_k\big(\mathcal L^*_{neum}(\lambda)\big)=\tfrac{d}{dt}\tr\mathcal L_{neum}(\lambda)^k=0\ "
                 r"\text{along the geodesic flows of }H_0,\ H_E")
def dual_lax_bi_invariant_r_n(s):
    """§8, Remark after Theorem DUAL: 'for r = n the considered Neumann flows become geodesic flows of bi-invariant
    metrics on SO(n). Then both Lax representations (n×n and 2n×2n) give the integrals for the geodesic flow of a
    bi-invariant metric'.  Stated with the Dirac flows of the normal and Euclidean Hamiltonians H_0, H_E (no
    potential): e₂, e₄ of 𝓛*_neum(λ) (LA3) and tr 𝓛_neum(λ)^k, k = 2, 3, (LA2) are conserved."""
    lam = s.lam
    out = {}
    for name, H in (("H_0", H_kappa_of(0)), ("H_E", H_E)):
        flow = s.dirac_flow(H)
        for k in (2, 4):
            out[f"d e_{k}(L*) along {name}"] = s.d(lambda t, k=k: elementary(t, dual_L(t, t.lam), k)[k], flow)
        for k in (2, 3):
            def big(t, k=k):
                L = t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
                M = L
                for _ in range(k - 1):
                    M = M @ L
                return t.tr(M)
            out[f"d tr L^{k} along {name}"] = s.d(big, flow)
    return out


# 7 ------------------------------------------------------------------------------------------------------------
def semidirect_tensor(s, mu, Y):
    """The Lie–Poisson tensor of (so(n) ⊕_ρ M_{n,r})* at (μ, Y) as the matrix of (α, U) ↦ π((α, U), ·) in the bases
    E_i∧E_j of so(n) and E_ab of M_{n,r}: π((α,U),(β,W)) = ⟨μ,[α,β]⟩ + tr(UᵀβY) − tr(WᵀαY) (the relations of
    Θ₁ = Φ + X: {Φ_ξ,Φ_ζ} = ⟨Φ,[ξ,ζ]⟩, {Φ_ξ, tr UᵀX} = −tr(UᵀξX), {tr UᵀX, tr WᵀX} = 0)."""
    so = so_basis(s, "n")
    units = matrix_units(s, "n", "r")
    zero_n = s.zeros(s.n, s.n, ("n", "n"))
    zero_r = s.zeros(s.n, s.r, ("n", "r"))
    cov = [(a, zero_r) for a in so] + [(zero_n, U) for U in units]
    cols = []
    for (al, U) in cov:
        col = [s.killing(mu, comm(al, be)) + s.tr(U.T @ be @ Y) for be in so]
        aY = al @ Y
        col += [-s.tr(W.T @ aY) for W in units]
        cols.append(col)
    m = len(cov)
    return s.mat([[cols[j][i] for j in range(m)] for i in range(m)], ("?", "?"))


@claim("h80-theta1-coadjoint-orbit", paper=("LAMBDA12", "momentum_map", "NEUMANN"), kind="dim", sizes=DIM,
       statement=r"\rank\pi_{so(n)\oplus_\rho M_{n,r}}\big(\Phi(X,P),X\big)=\dim T^*V_{n,r}=2nr-r(r+1)")
def theta1_coadjoint_orbit(s):
    """§6, proof of Theorem NEUMANN: 'the mapping Θ₁(X, P) = Φ(X, P) + X realizes T*V_{n,r} as a coadjoint orbit in
    the dual space of the semi-direct product so(n) ⊕_ρ M_{n,r}(ℝ)': the Lie–Poisson tensor at Θ₁(X, P) has rank
    dim T*V = 2nr − r(r + 1) (the dimension of the orbit through that point)."""
    n, r = int(s.n), int(s.r)
    return {"rank at Theta_1(X, P)": Rank(semidirect_tensor(s, s.Phi, s.X), 2 * n * r - r * (r + 1))}


# 8 ------------------------------------------------------------------------------------------------------------
@claim("h80-so-n-orbit-dimension", paper=("ddim", "P-neutral", "SO(n-r)-action"), kind="dim", sizes=admissible(n_max=5, n_min=2, condition="n >= 2 (so(1) = 0)"),
       statement=r"\rank\{\xi\mapsto(\xi X,\xi P)\}=\dim so(n)-\dim so(n-2r)\ (n>2r),\ \dim so(n)\ (n\le2r)")
def so_n_orbit_dimension(s):
    """§2, proof of Lemma ddim: the isotropy group of a generic P₀ ∈ T*_{X₀}V in SO(n − r) is trivial for n ≤ 2r and
    SO(n − 2r) for n > 2r (P₀ = (E_{r+1}, …, E_{2r})).  Covariantly: the isotropy algebra of a generic (X, P) in
    so(n) has dimension dim so(n − 2r) (0 for n ≤ 2r), i.e. the generic SO(n)-orbit in T*V has dimension
    dim so(n) − dim so(n − 2r) = dim T*V − ddim."""
    n, r = int(s.n), int(s.r)
    so = so_basis(s, "n")
    rows = []
    cols = []
    for xi in so:
        a, b = xi @ s.X, xi @ s.P
        cols.append([a[i, j] for i in range(n) for j in range(r)] + [b[i, j] for i in range(n) for j in range(r)])
    expected = dim_so(n) - (dim_so(n - 2 * r) if n > 2 * r else 0)
    M = s.mat([[cols[j][i] for j in range(len(so))] for i in range(2 * n * r)], ("?", "?"))
    return {"rank xi -> (xi X, xi P)": Rank(M, expected)}
