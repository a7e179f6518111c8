# ruff: noqa
"""Stop 71, second round of hidden statements of Fedorov & Jovanovic: the blocks of the proofs at
X0 = (E_1 … E_r) (LEMA1, LEMA2, (ddim), NEUMANN2, the Proposition on SO(n)×SO(r)-invariant metrics),
(LAMBDA) and (L3)/(L4), the chain rule in the proofs of (dot_XP2) and (No), the metric ds²_A, §7, §8,
Appendix 1.  Public API only.  True as printed unless marked."""
from stiefelsym import Count, Rank, admissible, block, claim, comm, det
from stiefelsym.brackets import lambda1, lambda2

# --------------------------------------------------------------------------------------------------
# helpers: the chart of the proofs at X0 = (E_1 … E_r): P0 = (P1; P2), P1 skew r×r, P2 (n−r)×r

r_lt_n = dict(where=lambda n, r: r < n, condition="r < n (the block n − r is not empty)")


def X0_of(s):
    return block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])


def Zrr(s):
    return s.zeros(s.r, s.r, ("r", "r"))


def Znr(s, k):
    return s.zeros(s.n - s.r, k, ("n-r", k))


def I_nr(s):
    m = s.n - s.r
    return s.mat([[1 if i == j else 0 for j in range(m)] for i in range(m)], ("n-r", "n-r"))


def skew_nr(s, name):
    G = s.generic(name, "n-r", "n-r")
    return G - G.T


def sym_nr(s, name):
    G = s.generic(name, "n-r", "n-r")
    return G + G.T


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


def diag_blocks(s, a, b):
    """diag(a, b) on ℝⁿ = ℝʳ ⊕ ℝⁿ⁻ʳ."""
    return block([[a, s.zeros(s.r, s.n - s.r, ("r", "n-r"))], [s.zeros(s.n - s.r, s.r, ("n-r", "r")), b]])


# --- 1. proof of LEMA1 (and (iso), (P-neutral)): h = Φ(X0, P0) has the printed block form ----------------

@claim("h71b-lema1-h-blocks", paper=("LEMA1", "P-neutral", "iso"), kind="id",
       sizes=admissible(n_max=5, **r_lt_n))
def lema1_h_blocks(s):
    """Proof of LEMA1: at X0 = (E_1 … E_r), P0 = (P1; P2) with P1 skew, h = Φ(X0, P0) = [[h1, h2], [−h2ᵀ, 0]]
    with h1 = 2P1 = Ψ(X0, P0) ∈ so(r), h2 = −P2ᵀ; v = X0X0ᵀ = diag(I_r, 0); h ⟂ so(n − r) (h ∈ 𝔳, (iso))."""
    P1 = s.generic("P1", "r", "r", "skew")
    P2 = s.generic("P2", "n-r", "r")
    X0 = X0_of(s)
    P0 = block([[P1], [P2]])
    h1, h2 = 2 * P1, -P2.T
    h = block([[h1, h2], [-h2.T, s.zeros(s.n - s.r, s.n - s.r, ("n-r", "n-r"))]])
    gamma = skew_nr(s, "gam")
    return {"(cond_XP) at X0": X0.T @ P0 + P0.T @ X0,
            "Φ(X0,P0) − [[h1,h2],[−h2ᵀ,0]]": Phi_of(X0, P0) - h,
            "Ψ(X0,P0) − h1": Psi_of(X0, P0) - h1,
            "v − diag(I,0)": X0 @ X0.T - diag_blocks(s, s.Ir, s.zeros(s.n - s.r, s.n - s.r, ("n-r", "n-r"))),
            "⟨h, diag(0, γ)⟩": s.killing(h, diag_blocks(s, Zrr(s), gamma))}


# --- 2. (iso), (SO(n-r)-action), (hat): the SO(n − r) action is the adjoint action on 𝔳 -------------------

@claim("h71b-iso-adjoint", paper=("iso", "SO(n-r)-action", "hat"), kind="id",
       sizes=admissible(n_max=5, **r_lt_n))
def iso_adjoint(s):
    """(hat): diag(I_r, B) fixes X0; under (iso) the action (SO(n-r)-action) P2 ↦ BP2 is the adjoint action on 𝔳:
    Φ(X0, diag(I, B)P0) = diag(I, B) Φ(X0, P0) diag(I, B)ᵀ, B = (I − β)(I + β)⁻¹ ∈ SO(n − r)."""
    P1 = s.generic("P1", "r", "r", "skew")
    P2 = s.generic("P2", "n-r", "r")
    X0 = X0_of(s)
    beta = skew_nr(s, "beta")
    I = I_nr(s)
    B = (I - beta) @ (I + beta).inv()
    Bh = diag_blocks(s, s.Ir, B)
    P0 = block([[P1], [P2]])
    P0b = block([[P1], [B @ P2]])
    return {"BᵀB − I": B.T @ B - I,
            "B̂X0 − X0": Bh @ X0 - X0,
            "B̂P0 − (P1; BP2)": Bh @ P0 - P0b,
            "Φ(X0, B̂P0) − B̂ΦB̂ᵀ": Phi_of(X0, P0b) - Bh @ Phi_of(X0, P0) @ Bh.T}


# --- 3. §4, proof of the Proposition on SO(n)×SO(r)-invariant metrics -----------------------------------

@claim("h71b-so-r-at-x0", paper=("P-neutral", "SO(n-r)-action", "EM", "so(n)+so(r)"), kind="id",
       sizes=admissible(n_max=5, **r_lt_n))
def so_r_at_x0(s):
    """Proof of the Proposition after Remark (§4): the right SO(r) action, brought back to X0 by R = diag(Qᵀ, I),
    is P1 ↦ Q⁻¹P1Q, P2 ↦ P2Q (R X0 Q = X0), and the restriction of H_κ to T*_{X0}V,
    ½tr P0ᵀP0 − (½ + κ) tr (X0ᵀP0)² = ½tr P2ᵀP2 − (1 + κ) tr P1², is invariant under it."""
    P1 = s.generic("P1", "r", "r", "skew")
    P2 = s.generic("P2", "n-r", "r")
    X0 = X0_of(s)
    Q = (s.Ir - s.eta) @ (s.Ir + s.eta).inv()
    R = diag_blocks(s, Q.T, I_nr(s))
    P0 = block([[P1], [P2]])
    Hk = lambda X, P: (s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(X.T @ P @ X.T @ P))
    return {"R X0 Q − X0": R @ X0 @ Q - X0,
            "R P0 Q − (Q⁻¹P1Q; P2Q)": R @ P0 @ Q - block([[Q.inv() @ P1 @ Q], [P2 @ Q]]),
            "H_κ(X0,P0) − (½tr P2ᵀP2 − (1+κ)tr P1²)": Hk(X0, P0) - (s.tr(P2.T @ P2) / 2
                                                                 - (1 + s.kappa) * s.tr(P1 @ P1)),
            "H_κ(X0, RP0Q) − H_κ(X0, P0)": Hk(X0, R @ P0 @ Q) - Hk(X0, P0)}


# --- 4. proof of (ddim): the isotropy of P0 in SO(n − r) -------------------------------------------------

def so_nr_basis(s):
    m = s.n - s.r
    out = []
    for i in range(m):
        for j in range(i + 1, m):
            out.append(s.mat([[(1 if (a, b) == (i, j) else -1 if (a, b) == (j, i) else 0) for b in range(m)]
                              for a in range(m)], ("n-r", "n-r")))
    return out


def action_matrix(s, P2):
    """columns: the entries of βP2 for β in the basis of so(n − r)."""
    r, m = s.r, s.n - s.r
    cols = []
    for beta in so_nr_basis(s):
        M = beta @ P2
        cols.append([M[i, j] for i in range(m) for j in range(r)])
    return s.mat([list(row) for row in zip(*cols)])


def dso(m):
    return m * (m - 1) // 2 if m > 1 else 0


@claim("h71b-ddim-isotropy", paper=("ddim", "SO(n-r)-action", "P-neutral"), kind="dim",
       sizes=admissible(n_max=6, where=lambda n, r: n - r >= 2, condition="n − r ≥ 2 (so(n − r) ≠ 0)"))
def ddim_isotropy(s):
    """Proof of (ddim): SO(n−r)_{P0} is trivial for generic P0 when n ≤ 2r; for n > 2r at P0 = (E_{r+1} … E_{2r})
    (P1 = 0, P2 = (I_r; 0)) it is SO(n − 2r) (rank of β ↦ βP2 on so(n − r) is dim so(n−r) − dim so(n−2r), at
    every point); the fibre T*_{X0}V has dimension dim V, and the codimension of the generic orbit is (ddim)."""
    n, r = int(s.n), int(s.r)
    m = n - r
    P2 = s.generic("P2", "n-r", "r")
    iso = dso(n - 2 * r) if n > 2 * r else 0
    out = {"rank at generic P2": Rank(action_matrix(s, P2), dso(m) - iso)}
    if n > 2 * r:
        E = s.mat([[1 if i == j else 0 for j in range(r)] for i in range(m)], ("n-r", "r"))
        out["rank at P2 = (I; 0)"] = Rank(action_matrix(s, E), dso(m) - dso(n - 2 * r), generic=False)
    dimV = r * n - r * (r + 1) // 2
    out["dim fibre = r(r−1)/2 + r(n−r) = dim V"] = Count(r * (r - 1) // 2 + r * m, dimV)
    ddim = dimV - dso(m) + (dso(n - 2 * r) if n > 2 * r else 0)
    out["codim of generic orbit = (ddim)"] = Count(dimV - (dso(m) - iso), ddim)
    return out


# --- 5. proof of LEMA1: the printed equation for η3 and the kernel of Λ1(h + v) in blocks ------------------

@claim("h71b-lema1-kernel-blocks", paper=("LEMA1", "L1", "L2", "LAMBDA12"), kind="id",
       sizes=admissible(n_max=5, **r_lt_n))
def lema1_kernel_blocks(s):
    """Proof of LEMA1 at X0: with ξ = diag(ξ1, ξ2), [ξ1, h1] = 0 (ξ1 = h1³), ξ2 ∈ so(n−r), η1, η2 symmetric
    arbitrary, the printed equation [diag(ξ1, ξ2), [[0, h2], [−h2ᵀ, 0]]] + [[0, −η3], [η3ᵀ, 0]] = 0 holds with
    η3 = ξ1h2 − h2ξ2; the printed [η, v] = [[0, −η3], [η3ᵀ, 0]]; then (L1), (L2) hold and ξ + η ∈ ker Λ1(h + v)."""
    P1 = s.generic("P1", "r", "r", "skew")
    P2 = s.generic("P2", "n-r", "r")
    X0 = X0_of(s)
    h = Phi_of(X0, block([[P1], [P2]]))
    h1, h2 = 2 * P1, -P2.T
    v = X0 @ X0.T
    xi1 = h1 @ h1 @ h1
    xi2 = skew_nr(s, "xi2")
    eta1 = s.generic("eta1", "r", "r", "sym")
    eta2 = sym_nr(s, "eta2")
    eta3 = xi1 @ h2 - h2 @ xi2
    Znn = s.zeros(s.n - s.r, s.n - s.r, ("n-r", "n-r"))
    Zrn = s.zeros(s.r, s.n - s.r, ("r", "n-r"))
    xi = diag_blocks(s, xi1, xi2)
    eta = block([[eta1, eta3], [eta3.T, eta2]])
    H2 = block([[Zrr(s), h2], [-h2.T, Znn]])
    E3 = block([[Zrr(s), -eta3], [eta3.T, Znn]])
    # test elements ζ ∈ so(n), θ ∈ Sym(n) in the same blocks (a block matrix lives on ℝʳ ⊕ ℝⁿ⁻ʳ, not on ℝⁿ)
    z1, z2, z3 = s.generic("z1", "r", "r", "skew"), s.generic("z2", "n-r", "r"), skew_nr(s, "z3")
    t1, t2, t3 = s.generic("t1", "r", "r", "sym"), s.generic("t2", "n-r", "r"), sym_nr(s, "t3")
    zeta = block([[z1, -z2.T], [z2, z3]])
    theta = block([[t1, t2.T], [t2, t3]])
    return {"printed η3 equation": comm(xi, H2) + E3,
            "[η, v] − [[0,−η3],[η3ᵀ,0]]": comm(eta, v) - E3,
            "(L1) [ξ, v]": comm(xi, v),
            "(L2) [ξ, h] + [η, v]": comm(xi, h) + comm(eta, v),
            "Λ1(ξ+η, ζ+θ)|_{h+v}": lambda1()(s, h + v, xi + eta, zeta + theta)}


# --- 6. proof of LEMA2: (LAMBDA) ------------------------------------------------------------------------

@claim("h71b-lambda-1m1", paper=("LAMBDA", "LAMBDA12", "symmetric-pair", "killing"), kind="id",
       sizes=admissible(n_max=5))
def lambda_1m1(s):
    """(LAMBDA): Λ_{1,−1}(ξ + η, ζ + θ)|_{h+v} = −⟨h, [η, θ]⟩ + ⟨A, [ξ, θ] + [η, ζ]⟩ at h + v = Θ(X, P), for
    ξ, ζ ∈ so(n), η, θ ∈ Sym(n); and ⟨,⟩ is positive definite on so(n), negative definite on Sym(n),
    so(n) ⟂ Sym(n): ⟨ξ, ξ⟩ = ½tr ξᵀξ, ⟨η, η⟩ = −½tr ηᵀη, ⟨ξ, η⟩ = 0."""
    h, v = s.Phi, s.X @ s.X.T
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta", "n", "n", "sym"), s.generic("theta", "n", "n", "sym")
    L = lambda1()(s, h + v, xi + eta, zeta + theta) - lambda2()(s, h + v, xi + eta, zeta + theta)
    printed = -s.killing(h, comm(eta, theta)) + s.killing(s.A, comm(xi, theta) + comm(eta, zeta))
    return {"(LAMBDA)": L - printed,
            "⟨ξ,ξ⟩ − ½tr ξᵀξ": s.killing(xi, xi) - s.tr(xi.T @ xi) / 2,
            "⟨η,η⟩ + ½tr ηᵀη": s.killing(eta, eta) + s.tr(eta.T @ eta) / 2,
            "⟨ξ,η⟩": s.killing(xi, eta)}


# --- 7. proof of LEMA2: (L3), (L4) solved in coordinates --------------------------------------------------

@claim("h71b-l3-l4-coordinates", paper=("L3", "L4", "LAMBDA", "LEMA2"), kind="id",
       sizes=admissible(n_max=5))
def l3_l4_coordinates(s):
    """Proof of (A1): for a diagonal η = diag(d) (the solutions of (L3)), ξ is uniquely determined from (L4):
    ξ_ij = [η, h]_ij / (a_j − a_i); it is skew, (L3), (L4) hold, and ξ + η ∈ ker Λ_{1,−1}(h + v)."""
    n = int(s.n)
    h, v = s.Phi, s.X @ s.X.T
    a = s.a
    d = [s.scalar(f"d{i}") for i in range(n)]
    eta = s.mat([[d[i] if i == j else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    C = comm(eta, h)
    xi = s.mat([[C[i, j] / (a[j] - a[i]) if i != j else 0 for j in range(n)] for i in range(n)], ("n", "n"))
    zeta, theta = s.zeta, s.generic("theta", "n", "n", "sym")
    L = lambda1()(s, h + v, xi + eta, zeta + theta) - lambda2()(s, h + v, xi + eta, zeta + theta)
    return {"ξ + ξᵀ": xi + xi.T,
            "(L3) [η, A]": comm(eta, s.A),
            "(L4) [ξ, A] − [η, h]": comm(xi, s.A) - comm(eta, h),
            "Λ_{1,−1}(ξ+η, ζ+θ)": L}


# --- 8. proof of the Proposition (dot_XP2): the chain rule dH = dh_𝔸 ∘ dΦ ----------------------------------

@claim("h71b-submersion-chain-rule", paper=("submersion_metric", "dot_XP2", "dot_XP"), kind="id",
       sizes=admissible(n_max=4))
def submersion_chain_rule(s):
    """Proof of the Proposition of (dot_XP2): for H_𝔸 = −¼tr(𝔸(PXᵀ − XPᵀ)(PXᵀ − XPᵀ)) on the ambient space,
    ∂H/∂P = 𝔸(Φ)X and −∂H/∂X = 𝔸(Φ)P (the chain rule), so Ẋ = ∂H/∂P − XΠ, Ṗ = −∂H/∂X + XΛ + PΠ with Λ = Π = 0."""
    AA = s.sym_operator("AA")
    H = lambda t: -t.tr(AA(t.P @ t.X.T - t.X @ t.P.T) @ (t.P @ t.X.T - t.X @ t.P.T)) / 4
    HX, HP = s.gradient(H)
    w = AA(s.Phi)
    return {"∂H/∂P − 𝔸(Φ)X": HP - w @ s.X, "−∂H/∂X − 𝔸(Φ)P": -HX - w @ s.P}


# --- 9. proof of the Proposition (No): the ambient gradients --------------------------------------------------

@claim("h71b-neumann-proof-gradients", paper=("No", "neumann", "dot_XP"), kind="id", sizes=admissible(n_max=4))
def neumann_proof_gradients(s):
    """Proof of (No): ∂H/∂P = P − (1 + 2κ)XPᵀX and −∂H/∂X = −AX + (1 + 2κ)PXᵀP for H_neum,κ (neumann)."""
    H = lambda t: (t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(t.X.T @ t.P @ t.X.T @ t.P)
                   + t.tr(t.X.T @ t.A @ t.X) / 2)
    HX, HP = s.gradient(H)
    X, P, c = s.X, s.P, 1 + 2 * s.kappa
    return {"∂H/∂P": HP - (P - c * (X @ P.T @ X)), "−∂H/∂X": -HX - (-(s.A @ X) + c * (P @ X.T @ P))}


# --- 10. proof of NEUMANN2: the counts ------------------------------------------------------------------------

@claim("h71b-neumann2-counts", paper=("NEUMANN2", "LEMA1", "KER"), kind="dim", sizes=admissible(n_max=7))
def neumann2_counts(s):
    """Proof of NEUMANN2: with h1 = 0 the LEMA1 kernel so(r)_{h1} ⊕ so(n−r) ⊕ Sym(r) ⊕ Sym(n−r) has the dimension
    of gl(r) ⊕ gl(n − r), and r(n − r) = ½(dim gl(n) − dim gl(r) − dim gl(n − r)) = dim G_{n,r}."""
    n, r = int(s.n), int(s.r)
    sym = lambda m: m * (m + 1) // 2
    return {"dim so(r) + dim so(n−r) + dim Sym(r) + dim Sym(n−r)": Count(dso(r) + dso(n - r) + sym(r) + sym(n - r),
                                                                         r * r + (n - r) ** 2),
            "½(n² − r² − (n−r)²)": Count((n * n - r * r - (n - r) ** 2) // 2, r * (n - r)),
            "even": Count((n * n - r * r - (n - r) ** 2) % 2, 0),
            "= dim V − dim SO(r)": Count(r * n - r * (r + 1) // 2 - dso(r), r * (n - r))}


# --- 11. proof of Proposition YM: space and body angular velocities (r = n, normal metric) ---------------------

@claim("h71b-cp-frames", paper=("mag*", "Euler*", "Poisson", "dot_X3"), kind="id",
       sizes=admissible(n_max=5, r_is_n=True, condition="r = n: T*SO(n)"))
def cp_frames(s):
    """Proof of Proposition YM: for the identity inertia operator (normal metric on V_{n,n} = O(n)), the angular
    velocity in the space frame Ω = Ẋ𝒳⁻¹ is M = 𝒫𝒳ᵀ − 𝒳𝒫ᵀ, in the body frame ω = 𝒳⁻¹Ẋ is m = 𝒳⁻¹M𝒳; the
    Poisson equations ė_i = Ωe_i hold (𝒳⁻¹ = 𝒳ᵀ on O(n))."""
    X = s.X
    flow = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 - t.tr(t.X.T @ t.P @ t.X.T @ t.P) / 2)
    Xd = flow["X"]
    M = s.Phi
    return {"Ẋ𝒳ᵀ − M": Xd @ X.T - M,
            "𝒳ᵀẊ − 𝒳ᵀM𝒳": X.T @ Xd - X.T @ M @ X,
            "Ẋ − M𝒳 (Poisson)": Xd - M @ X}


# --- 12. §8: the Plücker coordinates of span(e_1 … e_r) among the minors of 𝒱 -----------------------------------

@claim("h71b-vv-minors-with-identity", paper=("VV", "forms"), kind="id",
       sizes=admissible(n_max=5, where=lambda n, r: 2 * r <= n + r, condition="every size"))
def vv_minors(s):
    """§8 after (VV): the 2r×2r minors of 𝒱 that contain the block I_r completely are the Plücker coordinates of
    span(e_1 … e_r): the minor on the rows I ∪ {n+1 … n+r} is det X_I (I an r-subset of {1 … n}); every first
    r-subset and the last one are checked.  The point Σ̄ ∩ {y = 1} is p_1 + … + p_r (𝒱 (0; 1))."""
    n, r = int(s.n), int(s.r)
    X, P = s.X, s.P
    subsets = [list(range(r)), list(range(n - r, n))]
    out = {}
    for k, I in enumerate(subsets):
        rows = [[X[i, j] for j in range(r)] + [P[i, j] for j in range(r)] for i in I]
        rows += [[0] * r + [1 if a == b else 0 for b in range(r)] for a in range(r)]
        V = s.mat(rows, ("?", "?"))
        XI = s.mat([[X[i, j] for j in range(r)] for i in I], ("?", "?"))
        out[f"minor {k} − det X_I"] = det(s, V) - det(s, XI)
    ones = s.mat([[1] for _ in range(r)], ("r", "?"))
    Vmat = block([[X, P], [Zrr(s), s.Ir]])
    c = block([[s.zeros(s.r, 1, ("r", "?"))], [ones]])
    out["𝒱(0;1) − (Σp_i; 1)"] = Vmat @ c - block([[P @ ones], [ones]])
    return out


# --- 13. §3: ds²_A is right SO(r)-invariant: Noether's Ψ along (A_XP) ---------------------------------------------

@claim("h71b-a-metric-psi-conserved", paper=("A_XP", "leg2", "cond_XP2", "momentum_right_map"), kind="pb",
       realization="metric", sizes=admissible(n_max=4))
def a_metric_psi(s):
    """§3 after (A_XP): ds²_A is right SO(r)-invariant, so the momentum Ψ = XᵀP − PᵀX of the right action is an
    integral of its geodesic flow (Ẋ = A⁻¹P, Ṗ = XΛ); d(XᵀP)/dt = PᵀA⁻¹P + Λ is symmetric."""
    H = lambda t: t.tr(t.P.T @ t.Ainv @ t.P) / 2
    flow = s.dirac_flow(H)
    Lam = s.X.T @ flow["P"]
    return {"dΨ/dt": s.d(lambda t: t.X.T @ t.P - t.P.T @ t.X, flow),
            "d(XᵀP)/dt − (PᵀA⁻¹P + Λ)": s.d(lambda t: t.X.T @ t.P, flow) - (s.P.T @ s.Ainv @ s.P + Lam)}


# --- 14. §7: Ψ⁻¹(0) = {XᵀP = 0} ------------------------------------------------------------------------------

@claim("h71b-psi-zero-iff", paper=("grassmannian", "momentum_right_map", "cond_XP"), kind="id",
       sizes=admissible(n_max=5))
def psi_zero_iff(s):
    """§7: (X, P) ∈ Ψ⁻¹(0) iff XᵀP = 0, because Ψ = 2XᵀP = −2PᵀX on T*V; and then H_κ does not depend on κ
    (H_κ − H_0 = −κ tr(XᵀP)² = −(κ/4) tr Ψ²)."""
    X, P = s.X, s.P
    return {"Ψ − 2XᵀP": s.Psi - 2 * (X.T @ P), "Ψ + 2PᵀX": s.Psi + 2 * (P.T @ X),
            "H_κ − H_0 + (κ/4)trΨ²": (-s.kappa * s.tr(X.T @ P @ X.T @ P)) + s.kappa * s.tr(s.Psi @ s.Psi) / 4}
