# ruff: noqa
"""Stop 71 (hidden): statements of Fedorov & Jovanovic that the catalog does not state (or states in
another form), written as a reader would, with the public API only.  True as printed unless marked."""
from stiefelsym import Count, Rank, admissible, block, claim, comm
from stiefelsym.systems import coupled_point, derivative, double_point, stiefel_pairs_flow

half = lambda s: s.q(1, 2)


def wedge(a, b):
    """a ∧ b = a bᵀ − b aᵀ (§2)."""
    return a @ b.T - b @ a.T


def cayley(s, M, I):
    """(I − M)(I + M)⁻¹: a rotation for a skew M."""
    return (I - M) @ (I + M).inv()


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


# --- §2 (Prop. Phi, right_action) and §3 ("Einstein metrics": Φ and Ψ are invariant under the SO(r) and SO(n)
# actions respectively), with finite rotations (Cayley transforms), not infinitesimal ones --------------

@claim("h71-momentum-maps-finite", paper=("momentum_map", "momentum_right_map", "EM"), kind="id",
       sizes=admissible(n_max=4))
def momentum_maps_finite(s):
    """Φ(XQ, PQ) = Φ, Ψ(RX, RP) = Ψ (invariance), Φ(RX, RP) = RΦRᵀ, Ψ(XQ, PQ) = QᵀΨQ (equivariance), and both
    actions keep T*V, for rotations Q = cay(η) ∈ SO(r), R = cay(ξ) ∈ SO(n)."""
    X, P = s.X, s.P
    Q = cayley(s, s.eta, s.Ir)
    R = cayley(s, s.xi, s.In)
    XQ, PQ, RX, RP = X @ Q, P @ Q, R @ X, R @ P
    return {"QᵀQ − I": Q.T @ Q - s.Ir,
            "RᵀR − I": R.T @ R - s.In,
            "Φ(XQ,PQ) − Φ": Phi_of(XQ, PQ) - s.Phi,
            "Ψ(RX,RP) − Ψ": Psi_of(RX, RP) - s.Psi,
            "Φ(RX,RP) − RΦRᵀ": Phi_of(RX, RP) - R @ s.Phi @ R.T,
            "Ψ(XQ,PQ) − QᵀΨQ": Psi_of(XQ, PQ) - Q.T @ s.Psi @ Q,
            "(XQ)ᵀXQ − I": XQ.T @ XQ - s.Ir,
            "(XQ)ᵀPQ + (PQ)ᵀXQ": XQ.T @ PQ + PQ.T @ XQ,
            "(RX)ᵀRX − I": RX.T @ RX - s.Ir,
            "(RX)ᵀRP + (RP)ᵀRX": RX.T @ RP + RP.T @ RX}


# --- §2 (Dirac_bracket): the printed formula, built by hand from the canonical bracket -------------------

def constraints(s):
    """(scalar): F_ij = (e_i, e_j) − δ_ij, G_ij = (e_i, p_j) + (e_j, p_i), i ≤ j, as functions of the scene."""
    r = int(s.r)
    out = []
    for i in range(r):
        for j in range(i, r):
            out.append(lambda t, i=i, j=j: (t.X.T @ t.X)[i, j] - (1 if i == j else 0))
            out.append(lambda t, i=i, j=j: (t.X.T @ t.P + t.P.T @ t.X)[i, j])
    return out


def H_neum(t):
    return (t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(t.X.T @ t.P @ t.X.T @ t.P)
            + t.tr(t.X.T @ t.A @ t.X) / 2)


@claim("h71-dirac-bracket-printed", paper=("Dirac_bracket", "dot_XP"), kind="pb",
       sizes=admissible(n_max=3, r_max=2))
def dirac_bracket_printed(s):
    """(Dirac_bracket) as printed: {f1, f2} = {f1, f2}_0 + Σ_ij {F_i, f1}_0 C_ij {F_j, f2}_0, C = ({F_i, F_j}_0)⁻¹,
    for f1 linear and f2 = H_neum,κ; and the Hamiltonian equation ḟ = {f, H} along the Dirac flow of H."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    f1 = lambda t: t.tr(U.T @ t.X) + t.tr(V.T @ t.P)
    f2 = H_neum
    F = constraints(s)
    m = len(F)
    M = s.mat([[s.canonical_bracket(F[i], F[j]) for j in range(m)] for i in range(m)], ("cond", "cond"))
    C = M.inv()
    b1 = [s.canonical_bracket(F[i], f1) for i in range(m)]
    b2 = [s.canonical_bracket(F[j], f2) for j in range(m)]
    dirac = s.canonical_bracket(f1, f2)
    for i in range(m):
        for j in range(m):
            dirac = dirac + b1[i] * C[i, j] * b2[j]
    return {"printed Dirac bracket − engine's": dirac - s.bracket(f1, f2),
            "ḟ1 − {f1, H}": s.d(f1, s.dirac_flow(f2)) - s.bracket(f1, f2)}


# --- §5 (N0_XP2), (NE_XP): the middle forms of Ṗ with the multiplier Λ ------------------------------------

@claim("h71-neumann-middle-forms", paper=("N0_XP2", "NE_XP"), kind="id", sizes=admissible(n_max=4))
def neumann_middle_forms(s):
    """For κ = 0: Ṗ = −AX + PXᵀP + XΛ; for κ = −½: Ṗ = −AX + XΛ, Λ = XᵀAX − PᵀP (the middle expressions of
    (N0_XP2), (NE_XP)); the multiplier of the Lagrange form is that Λ, and Π = 0."""
    X, P, A = s.X, s.P, s.A
    Lam = X.T @ A @ X - P.T @ P

    def H(c):
        return lambda t: (t.tr(t.P.T @ t.P) / 2 - c(t) * t.tr(t.X.T @ t.P @ t.X.T @ t.P)
                          + t.tr(t.X.T @ t.A @ t.X) / 2)
    f0 = s.multiplier_flow(H(lambda t: t.q(1, 2)))
    fe = s.multiplier_flow(H(lambda t: t.q(0)))
    return {"N0: Ṗ − (−AX + PXᵀP + XΛ)": f0["P"] - (-(A @ X) + P @ X.T @ P + X @ Lam),
            "N0: Ẋ − (P − XPᵀX)": f0["X"] - (P - X @ P.T @ X),
            "NE: Ṗ − (−AX + XΛ)": fe["P"] - (-(A @ X) + X @ Lam),
            "NE: Λ − (XᵀAX − PᵀP)": fe["Lambda"] - Lam,
            "NE: Π": fe["Pi"]}


# --- §6, proof of Lemma LEMA1: [η, v] for v = XXᵀ, in a form free of the chart X0 ---------------------------

@claim("h71-lema1-eta-v", paper=("LEMA1", "L1", "L2"), kind="id", sizes=admissible(n_max=4))
def lema1_eta_v(s):
    """Proof of LEMA1: for symmetric η, [η, v] = [[0, −η3], [η3ᵀ, 0]] (v = diag(I_r, 0) at X0), i.e. in any frame
    [η, v] = (I − v)ηv − vη(I − v), v = XXᵀ; and ξ = XθXᵀ + (I − v)ζ(I − v) (so(r) ⊕ so(n − r)) solves (L1) [ξ, v] = 0."""
    v = s.X @ s.X.T
    eta = s.generic("etaS", "n", "n", "sym")
    Qp = s.In - v
    xi = s.X @ s.theta @ s.X.T + Qp @ s.zeta @ Qp
    return {"[η, v] − ((I − v)ηv − vη(I − v))": comm(eta, v) - (Qp @ eta @ v - v @ eta @ Qp),
            "[ξ, v]": comm(xi, v)}


# --- §4 / §8: relations between the dual Lax matrices of the Manakov and Neumann flows, as printed -------------

def L_star(s, lam, neumann):
    R = s.resolvent(lam)
    X, P = s.X, s.P
    lower = P.T @ R @ P + (s.Ir if neumann else 0 * s.Ir)
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [lower, P.T @ R @ X]])


@claim("h71-dual-lax-relations", paper=("MAN-LA2", "LA-MAN3", "LA3"), kind="id", sizes=admissible(n_max=4))
def dual_lax_relations(s):
    """𝓛*_neum(λ) − 𝓛*_man(λ) = [[0, 0], [I_r, 0]] (the printed (LA3) and (MAN-LA2)); the printed 𝓐*_man(λ) of
    (LA-MAN3), with (A + λI)⁻¹, is 𝓛*_man(−λ)."""
    lam = s.lam
    X, P = s.X, s.P
    Rp = (s.A + lam * s.In).inv()
    A_man = block([[X.T @ Rp @ P, X.T @ Rp @ X], [-(P.T @ Rp @ P), -(P.T @ Rp @ X)]])
    Z = s.zeros(s.r, s.r, ("r", "r"))
    return {"𝓛*_neum − 𝓛*_man − [[0,0],[I,0]]": L_star(s, lam, True) - L_star(s, lam, False)
            - block([[Z, Z], [s.Ir, Z]]),
            "𝓐*_man(λ) − 𝓛*_man(−λ)": A_man - L_star(s, -lam, False)}


# --- §4 / §8: Manakov flows with different B commute (they share the isotropic foliation) ----------------------

@claim("h71-manakov-flows-commute", paper=("Manakov", "man", "Chasles-Manakov"), kind="pb", sizes=admissible(n_max=4))
def manakov_flows_commute(s):
    """The Manakov Hamiltonians H_B = ½⟨ad_A⁻¹ad_B Φ, Φ⟩ for B = A² (𝔸ξ = Aξ + ξA) and B = A³
    (𝔸ξ = A²ξ + AξA + ξA²) Poisson-commute, and each conserves tr(Φ + λA)²."""
    A = s.A
    A2 = lambda t, x: t.A @ x + x @ t.A
    A3 = lambda t, x: t.A @ t.A @ x + t.A @ x @ t.A + x @ t.A @ t.A
    H2 = lambda t: -t.tr(A2(t, t.Phi) @ t.Phi) / 4
    H3 = lambda t: -t.tr(A3(t, t.Phi) @ t.Phi) / 4
    I2 = lambda t: t.tr((t.Phi + s.lam * t.A) @ (t.Phi + s.lam * t.A))
    return {"{H_A², H_A³}": s.bracket(H2, H3),
            "{tr(Φ+λA)², H_A³}": s.bracket(I2, H3)}


# --- Appendix 1, proof of Proposition YM: the chain of equalities for ë_n, at r = 1 ----------------------------

@claim("h71-ym-proof-chain", paper=("YM", "mag6", "mag3"), kind="id",
       sizes=admissible(n_max=5, r_max=1, condition="r = 1: e = X, ė = P ∈ T_eS^{n−1}"))
def ym_proof_chain(s):
    """(Ae⊗e − e⊗eA)e + (ė∧e)ė = Ae − ((e, Ae) + (ė, ė))e on TS^{n−1}; and with ė = Ωe (Ω ∈ so(n)),
    pr_e(Ω)e = ė, pr_e(Ω) = Ωe⊗e + e⊗eΩ = ė∧e (mag3)."""
    e, ed, A = s.X, s.P, s.A
    lhs = (A @ e @ e.T - e @ e.T @ A) @ e + wedge(ed, e) @ ed
    Om = s.xi
    edd = Om @ e
    pr = Om @ e @ e.T + e @ e.T @ Om
    return {"chain": lhs - (A @ e - e @ (e.T @ A @ e + ed.T @ ed)),
            "pr_e(Ω)e − ė": pr @ e - edd,
            "pr_e(Ω) − ė∧e": pr - wedge(edd, e)}


# --- Appendix 2: the κ = −½ perturbed coupled system (Euclidean metric with the interacting term) -------------

def H_pert_euclid(t, z):
    X, P, Y, Q = z["X"], z["P"], z["Y"], z["Q"]
    return (t.tr(P.T @ P) / 2 + t.tr(Q.T @ Q) / 2 + t.tr(X.T @ t.A @ Y)
            + t.tr(X.T @ P @ Y.T @ Q))


def F_lam(t, U, V):
    return U.T @ t.resolvent(t.lam) @ t.resolvent(-t.lam) @ V


@claim("h71-coupled-euclidean-interacting-dual", paper=("dual-DC", "LA3*C", "LA4*C", "C-neumann"), kind="lax",
       sizes=admissible(n_max=3))
def coupled_euclidean_interacting_dual(s):
    """App. 2, end of the coupled paragraph: at κ = −½ the perturbed Hamiltonian is
    ½tr PᵀP + ½tr QᵀQ + tr(XᵀAY) + tr(XᵀP YᵀQ) (the Euclidean metric and the interacting term), and its flow
    has the Lax pair (LA3*C) with the diagonal of 𝓐(λ): D1 = −YᵀQ, D2 = −XᵀP."""
    z = coupled_point(s)
    flow = stiefel_pairs_flow(s, H_pert_euclid, z, [("X", "P"), ("Y", "Q")])

    def L(t, w):
        X, P, Y, Q, A, lam, I = w["X"], w["P"], w["Y"], w["Q"], t.A, t.lam, t.Ir
        F = lambda U, V: F_lam(t, U, V)
        return block([
            [lam * F(P, X), lam * F(P, P), F(A @ P, Y), -I + F(A @ P, Q)],
            [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
            [F(A @ Q, X), -I + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
            [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])
    X, P, Y, Q, A = z["X"], z["P"], z["Y"], z["Q"], s.A
    S = (X.T @ A @ Y + Y.T @ A @ X) / 2
    Lam, Pi = S - P.T @ P, S - Q.T @ Q
    O, I, lam = s.zeros(s.r, s.r, ("r", "r")), s.Ir, s.lam * s.Ir
    d1, d2 = -(Y.T @ Q), -(X.T @ P)
    Am = block([[d1, Lam, O, -lam], [I, d1, O, O], [O, -lam, d2, Pi], [O, O, I, d2]])
    return {"LA3*C at κ = −½": derivative(s, L, z, flow) - comm(L(s, z), Am)}


# --- Appendix 2, the double system: the finite GL(r) symmetry ----------------------------------------------

@claim("h71-double-gl-symmetry", paper=("D-Lag", "D0", "dual-D"), kind="id", sizes=admissible(n_max=4))
def double_gl_symmetry(s):
    """(X, Y, Ẋ, Ẏ) ↦ (XRᵀ, YR⁻¹, ẊRᵀ, ẎR⁻¹) keeps (D0) and the Lagrangian (D-Lag) (R ∈ GL(r), the size of XᵀY)."""
    z = double_point(s)
    R = s.generic("Rgl", "r", "r")
    Ri = R.inv()
    X, Y, Xd, Yd = z["X"] @ R.T, z["Y"] @ Ri, z["Xdot"] @ R.T, z["Ydot"] @ Ri
    L = lambda X, Y, Xd, Yd: s.tr(Xd.T @ Yd) - s.tr(X.T @ s.A @ Y)
    return {"(XRᵀ)ᵀ(YR⁻¹) − I": X.T @ Y - s.Ir,
            "L(g·) − L": L(X, Y, Xd, Yd) - L(z["X"], z["Y"], z["Xdot"], z["Ydot"])}


# --- §3 after (A_XP): for r = 1 ds²_A is the metric of the ellipsoid (x, A⁻¹x) = 1 (A = C², C symmetric) -------

@claim("h71-a-metric-ellipsoid", paper=("leg2", "A_XP"), kind="id",
       sizes=admissible(n_max=4, r_max=1, condition="r = 1"))
def a_metric_ellipsoid(s):
    """For r = 1 and A = C² (C symmetric, invertible), y = Cx maps the sphere to the ellipsoid (y, A⁻¹y) = 1 and
    (ẏ, ẏ) = (ẋ, Aẋ) = 2L_A."""
    C = s.generic("Csym", "n", "n", "sym")
    Aown = C @ C
    x, xd = s.X, s.P
    y, yd = C @ x, C @ xd
    return {"(y, A⁻¹y) − 1": y.T @ Aown.inv() @ y - s.Ir,
            "(ẏ, ẏ) − (ẋ, Aẋ)": yd.T @ yd - xd.T @ Aown @ xd}


# --- §3, end of "The normal metric": the Legendre transform maps (cond_X) to (cond_XP) --------------------------

@claim("h71-normal-legendre-constraints", paper=("normal_metric_lagrangian", "cond_X", "cond_XP"), kind="id",
       sizes=admissible(n_max=4))
def normal_legendre_constraints(s):
    """For a tangent vector Ẋ (XᵀẊ + ẊᵀX = 0; here Ẋ = the scene's P, which satisfies it), the momentum
    P = Ẋ − ½XXᵀẊ satisfies XᵀP + PᵀX = 0, and XᵀP = ½XᵀẊ, so Ψ(X, P) = XᵀẊ."""
    X, Xd = s.X, s.P
    P = Xd - X @ X.T @ Xd / 2
    return {"XᵀP + PᵀX": X.T @ P + P.T @ X, "Ψ(X,P) − XᵀẊ": Psi_of(X, P) - X.T @ Xd}


# --- counts of §2, §6, §7, §8 -------------------------------------------------------------------------------

@claim("h71-counts", paper=("hat", "dim_fol", "NEUMANN2", "2r-integrals"), kind="dim", sizes=admissible(n_max=6))
def counts(s):
    """dim V = dim SO(n) − dim SO(n − r) (V = SO(n)/SO(n − r)); N = (n−1)+…+(n−r) = r(n−r) + r(r−1)/2 = dim V;
    dim G_{n,r} = dim V − dim SO(r) = r(n − r); (dim_fol) = l + [r/2] with 2l of (dimension)."""
    n, r = int(s.n), int(s.r)
    so = lambda m: m * (m - 1) // 2
    dimV = r * n - r * (r + 1) // 2
    N = sum(n - l for l in range(1, r + 1))
    two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
    dim_fol2 = two_l + 2 * (r // 2)  # twice (dim_fol)
    return {"dim SO(n) − dim SO(n−r)": Count(so(n) - so(n - r), dimV),
            "N": Count(N, r * (n - r) + r * (r - 1) // 2),
            "N = dim V": Count(N, dimV),
            "dim G": Count(dimV - so(r), r * (n - r)),
            "2·(dim_fol)": Count(dim_fol2, two_l + 2 * (r // 2))}


@claim("h71-n-bigger-than-half", paper=("2r-integrals", "dimension"), kind="dim", sizes=admissible(n_max=6),
       fails_at=lambda n, r: r == 1, place="the paragraph after (2r-integrals), §8",
       erratum="N = n − 1 equals half of (dimension) = 2(n − 1) at r = 1 (the Neumann system on the sphere); "
               "N exceeds it only for r ≥ 2")
def n_bigger_than_half(s):
    """§8 after (2r-integrals): "the number N is bigger than half of dimension (dimension) of a generic symplectic
    leaf within (T*V)/SO(r)": 2N > 2l (as printed; 1 = true)."""
    n, r = int(s.n), int(s.r)
    N = r * (n - r) + r * (r - 1) // 2
    two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
    return {"2N > 2l": Count(int(2 * N > two_l), 1)}


@claim("h71-n-bigger-than-half-corrected", paper=("2r-integrals", "dimension"), kind="dim", sizes=admissible(n_max=6))
def n_bigger_than_half_corrected(s):
    """Corrected: 2N − 2l = r(r − 1)/2 + [r/2], so N > l exactly when r ≥ 2 (N = l = n − 1 at r = 1)."""
    n, r = int(s.n), int(s.r)
    N = r * (n - r) + r * (r - 1) // 2
    two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
    return {"2N − 2l": Count(2 * N - two_l, r * (r - 1) // 2 + r // 2),
            "N > l iff r >= 2": Count(int(2 * N > two_l), int(r >= 2))}


# --- §6, Theorem CIF (ii) with 𝔹 = (½ + κ)·id is the Jensen Hamiltonian (EM) --------------------------------

@claim("h71-hb-jensen", paper=("HB", "EM", "CIF"), kind="id", sizes=admissible(n_max=4))
def hb_jensen(s):
    """H_𝔹 = ½tr(PᵀP) − ¼tr(Ψ𝔹(Ψ)) with 𝔹 = (½ + κ)·id on so(r) is H_κ of (EM); for a generic symmetric 𝔹 the flow
    of H_𝔹 conserves Φ (SO(n)-invariance)."""
    P, Psi = s.P, s.Psi
    c = s.q(1, 2) + s.kappa
    H_B = s.tr(P.T @ P) / 2 - s.tr(Psi @ (c * Psi)) / 4
    H_k = s.tr(P.T @ P) / 2 - c * s.tr(s.X.T @ P @ s.X.T @ P)
    BB = s.sym_operator("BB")
    HBgen = lambda t: t.tr(t.P.T @ t.P) / 2 - t.tr(t.Psi @ BB(t.Psi)) / 4
    return {"H_𝔹 − H_κ": H_B - H_k,
            "dΦ/dt along H_𝔹": s.d(lambda t: t.Phi, s.dirac_flow(HBgen))}


# --- §6, proof of Theorem NEUMANN: J_k = tr Ψ^{2k}, k = 1..[r/2], are independent at a generic point ----------------

@claim("h71-jk-independent", paper=("torus", "REDUCED_BRACKET"), kind="dim",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"))
def jk_independent(s):
    """The functions J_1, …, J_{[r/2]} (J_k = tr Ψ^{2k}) have independent differentials at a generic point of T*V
    (the regularity of the Ad_{SO(r)}-orbit of Ψ), while J_1, …, J_r have only [r/2] independent ones."""
    r = int(s.r)
    k0 = r // 2
    pw = lambda t, k: _power(t.Psi, 2 * k)
    F_half = lambda t: [t.tr(pw(t, k)) for k in range(1, k0 + 1)]
    F_all = lambda t: [t.tr(pw(t, k)) for k in range(1, r + 1)]
    return {"rank d(J_1..J_[r/2])": Rank(s.mat(s.jacobian(F_half)), k0),
            "rank d(J_1..J_r)": Rank(s.mat(s.jacobian(F_all)), k0)}


def _power(M, k):
    out = M
    for _ in range(k - 1):
        out = out @ M
    return out


# --- §2 (P-neutral), (SO(n-r)-action): coordinates at X0 = (E_1 … E_r) --------------------------------------

@claim("h71-p-neutral", paper=("P-neutral", "SO(n-r)-action", "SO(n)-inv"), kind="id",
       sizes=admissible(n_max=4, where=lambda n, r: r < n, condition="r < n"))
def p_neutral(s):
    """At X0 = (E_1 … E_r), P0 = (P_1; P_2) with P_1 skew satisfies (cond_XP); B·P_2 (B = cay(β) ∈ SO(n − r)) does
    too, and Ψ = 2P_1, PᵀP = P_1ᵀP_1 + P_2ᵀP_2 are invariant under P_2 ↦ BP_2."""
    n, r = int(s.n), int(s.r)
    W = s.generic("W", "r", "r", "skew")
    Zg = s.generic("Zg", "n", "r")
    Sk = s.generic("beta", "n", "n", "skew")
    X0 = s.mat([[1 if i == j else 0 for j in range(r)] for i in range(n)], ("n", "r"))
    P0 = s.mat([[W[i, j] for j in range(r)] if i < r else [Zg[i, j] for j in range(r)] for i in range(n)], ("n", "r"))
    m = n - r
    beta = s.mat([[Sk[r + i, r + j] for j in range(m)] for i in range(m)], ("n-r", "n-r"))
    Im = s.mat([[1 if i == j else 0 for j in range(m)] for i in range(m)], ("n-r", "n-r"))
    B = (Im - beta) @ (Im + beta).inv()
    P2 = s.mat([[Zg[i, j] for j in range(r)] for i in range(r, n)], ("n-r", "r"))
    BP2 = B @ P2
    P0b = s.mat([[W[i, j] for j in range(r)] if i < r else [BP2[i - r, j] for j in range(r)] for i in range(n)],
                ("n", "r"))
    Psi = lambda X, P: X.T @ P - P.T @ X
    return {"X0ᵀP0 + P0ᵀX0": X0.T @ P0 + P0.T @ X0,
            "X0ᵀ(BP0) + (BP0)ᵀX0": X0.T @ P0b + P0b.T @ X0,
            "Ψ − 2P_1": Psi(X0, P0) - 2 * W,
            "Ψ(B·) − Ψ": Psi(X0, P0b) - Psi(X0, P0),
            "PᵀP(B·) − PᵀP": P0b.T @ P0b - P0.T @ P0}
