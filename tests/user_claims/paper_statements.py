"""Statements of Fedorov and Jovanović's paper as a reader would write them from the text.

Each claim is written from the paper's own formulas (its label in ``paper=``), in the
form the text gives it; several have a deliberately wrong twin (a sign, a factor, a
transpose, an index range), stated with ``fails_at`` and ``erratum`` as a reader who
suspects a misprint would, or as ``kind="not"`` where the wrong formula must not hold.
"""
from stiefelsym import Count, Rank, admissible, block, claim, comm


# --- Hamiltonians, as printed -------------------------------------------------------------

def H_E(t):
    """(Euclidean): the Euclidean kinetic energy ½ tr PᵀP."""
    return t.tr(t.P.T @ t.P) / 2


def H_0(t):
    """(normal_metric): ½⟨Φ, Φ⟩."""
    return t.killing(t.Phi, t.Phi) / 2


def H_neumann(t):
    """(neumann): ½tr PᵀP − (½ + κ)tr((XᵀP)²) + ½tr XᵀAX."""
    K = t.X.T @ t.P
    return (t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K)
            + t.tr(t.X.T @ t.A @ t.X) / 2)


def H_neumann_euclidean(t):
    """(NE_XP): κ = −1/2."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_neumann_normal(t):
    """(N0_XP2): κ = 0."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


SMALL = admissible(n_max=4)


# --- Section 2: T*V, momentum mappings, brackets -------------------------------------------

@claim("u-phi-x", paper="dot_X3", kind="id", section="3", sizes=SMALL,
       statement=r"\Phi X = P - XP^TX,\quad \Phi P = -XP^TP + PX^TP")
def phi_acts_on_x_and_p(s):
    """On T*V, ΦX = P − XPᵀX and ΦP = −XPᵀP + PXᵀP."""
    X, P, Phi = s.X, s.P, s.Phi
    return {"Phi X": Phi @ X - (P - X @ P.T @ X),
            "Phi P": Phi @ P - (-(X @ P.T @ P) + P @ X.T @ P)}


@claim("u-phi-x-transposed", paper="dot_X3", kind="id", section="3", sizes=SMALL,
       statement=r"\Phi X = P - XX^TP \;(\text{suspected misprint})",
       fails_at=lambda n, r: r >= 2, erratum="XXᵀP in place of XPᵀX (a transposed product; the same at r = 1)")
def phi_acts_on_x_transposed(s):
    """On T*V, ΦX = P − XXᵀP (XPᵀX with the wrong factor order)."""
    X, P, Phi = s.X, s.P, s.Phi
    return {"Phi X": Phi @ X - (P - X @ X.T @ P)}


@claim("u-lie-poisson-phi", paper="Phi", kind="pb", section="2", sizes=SMALL,
       statement=r"\{\langle\Phi,\xi\rangle,\langle\Phi,\eta\rangle\} = \langle\Phi,[\xi,\eta]\rangle")
def phi_is_a_poisson_map(s):
    """The momentum mapping Φ is Poisson for the (+) Lie–Poisson bracket of so(n): {Φ_ξ, Φ_η} = ⟨Φ, [ξ, η]⟩."""
    xi = s.fresh("n", "n")
    eta = s.fresh("n", "n")
    xi, eta = xi - xi.T, eta - eta.T
    lhs = s.bracket(lambda t: t.killing(t.Phi, xi), lambda t: t.killing(t.Phi, eta))
    return {"{Phi_xi, Phi_eta}": lhs - s.killing(s.Phi, comm(xi, eta))}


@claim("u-lie-poisson-psi", paper="Phi", kind="pb", section="2", sizes=SMALL,
       statement=r"\{\langle\Psi,\zeta\rangle,\langle\Psi,\theta\rangle\} = -\langle\Psi,[\zeta,\theta]\rangle")
def psi_is_anti_poisson(s):
    """The momentum mapping Ψ is Poisson for the (−) Lie–Poisson bracket of so(r): {Ψ_ζ, Ψ_θ} = −⟨Ψ, [ζ, θ]⟩."""
    z = s.fresh("r", "r")
    w = s.fresh("r", "r")
    z, w = z - z.T, w - w.T
    lhs = s.bracket(lambda t: t.killing(t.Psi, z), lambda t: t.killing(t.Psi, w))
    return {"{Psi_z, Psi_w}": lhs + s.killing(s.Psi, comm(z, w))}


@claim("u-lie-poisson-psi-plus", paper="Phi", kind="not", expect="nonzero", section="2",
       sizes=admissible(n_max=4, r_min=3),
       statement=r"\{\Psi_\zeta,\Psi_\theta\} \ne +\langle\Psi,[\zeta,\theta]\rangle")
def psi_is_not_plus_poisson(s):
    """For r ≥ 3 (so(2) is abelian) the (+) sign for Ψ is wrong: {Ψ_ζ, Ψ_θ} − ⟨Ψ, [ζ, θ]⟩ is not identically 0."""
    z = s.fresh("r", "r")
    w = s.fresh("r", "r")
    z, w = z - z.T, w - w.T
    lhs = s.bracket(lambda t: t.killing(t.Psi, z), lambda t: t.killing(t.Psi, w))
    return {"{Psi_z, Psi_w} - <Psi,[z,w]>": lhs - s.killing(s.Psi, comm(z, w))}


@claim("u-invariants-commute-with-phi", paper=("SO(n)-inv", "LEMA"), kind="pb", section="2", sizes=SMALL,
       statement=r"\{\Phi_\xi, \Psi_{ij}\} = \{\Phi_\xi, (P^TP)_{ij}\} = 0")
def so_n_invariants_commute_with_phi(s):
    """The SO(n)-invariant functions Ψ_ij and (PᵀP)_ij Poisson commute with every Φ_ξ."""
    xi = s.fresh("n", "n")
    xi = xi - xi.T
    z = s.fresh("r", "r")
    S = s.fresh("r", "r")
    return {"{Phi_xi, tr(z Psi)}": s.bracket(lambda t: t.killing(t.Phi, xi), lambda t: t.tr(z @ t.Psi)),
            "{Phi_xi, tr(S PᵀP)}": s.bracket(lambda t: t.killing(t.Phi, xi), lambda t: t.tr(S @ t.P.T @ t.P))}


@claim("u-constraints-are-casimirs", paper="Dirac_bracket", kind="pb", section="2", sizes=SMALL,
       statement=r"\{X^TX, f\} = \{X^TP + P^TX, f\} = 0")
def constraints_are_casimirs(s):
    """The constraint functions XᵀX and XᵀP + PᵀX are Casimirs of the Dirac bracket (tested on tr UᵀX + tr WᵀP)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    C1, C2 = s.fresh("r", "r"), s.fresh("r", "r")

    def f(t):
        return t.tr(U.T @ t.X) + t.tr(W.T @ t.P) + t.tr(t.X.T @ t.A @ t.P)

    return {"{tr C1 XᵀX, f}": s.bracket(lambda t: t.tr(C1 @ t.X.T @ t.X), f),
            "{tr C2 (XᵀP + PᵀX), f}": s.bracket(lambda t: t.tr(C2 @ (t.X.T @ t.P + t.P.T @ t.X)), f)}


@claim("u-constraints-independent", paper="scalar", kind="dim", section="2", sizes=SMALL,
       statement=r"\operatorname{rank}\{F_i,F_j\}_0 = r(r+1)")
def constraint_bracket_matrix_is_invertible(s):
    """The r(r+1) scalar constraints (scalar) are second class: the matrix {F_i, F_j}_0 has full rank r(r+1)."""
    r = s.r
    return {"rank {F_i,F_j}_0": Rank(s.mat(s.constraint_bracket_matrix()), r * (r + 1))}


# --- Section 3: metrics and geodesic flows ---------------------------------------------------

@claim("u-euclidean-geodesics", paper="Euclidean_XP", kind="id", section="3", sizes=SMALL,
       statement=r"\dot X = P,\quad \dot P = -XP^TP")
def euclidean_geodesic_flow(s):
    """The Dirac flow of H_E = ½tr PᵀP is Ẋ = P, Ṗ = −XPᵀP."""
    flow = s.dirac_flow(H_E)
    return {"Xdot": flow["X"] - s.P, "Pdot": flow["P"] + s.X @ s.P.T @ s.P}


@claim("u-euclidean-geodesics-sign", paper="Euclidean_XP", kind="id", section="3", sizes=SMALL,
       statement=r"\dot P = +XP^TP \;(\text{suspected sign})",
       fails_at=lambda n, r: n > 1, erratum="the sign of XPᵀP flipped (P = 0 on T*V(1,1))")
def euclidean_geodesic_flow_wrong_sign(s):
    """The Dirac flow of H_E with Ṗ = +XPᵀP (a flipped sign)."""
    flow = s.dirac_flow(H_E)
    return {"Pdot": flow["P"] - s.X @ s.P.T @ s.P}


@claim("u-euclidean-multiplier", paper="Euclidean_XP", kind="id", section="3", sizes=SMALL,
       statement=r"\ddot X = X\Lambda,\ \Lambda = -\dot X^T\dot X")
def euclidean_acceleration(s):
    """Along the Euclidean geodesic flow, Ẍ = XΛ with Λ = −ẊᵀẊ."""
    flow = s.dirac_flow(H_E)
    Xdot = flow["X"]
    Xddot = s.d(lambda t: t.dirac_flow(H_E)["X"], flow)
    return {"Xddot - X Lambda": Xddot + s.X @ Xdot.T @ Xdot}


@claim("u-normal-geodesics", paper=("dot_X3", "dot_P3"), kind="id", section="3", sizes=SMALL,
       statement=r"\dot X = \Phi X,\ \dot P = \Phi P")
def normal_geodesic_flow(s):
    """The Dirac flow of the normal metric H_0 = ½⟨Φ, Φ⟩ is Ẋ = ΦX, Ṗ = ΦP."""
    flow = s.dirac_flow(H_0)
    return {"Xdot": flow["X"] - s.Phi @ s.X, "Pdot": flow["P"] - s.Phi @ s.P}


@claim("u-normal-hamiltonian", paper="normal_metric", kind="id", section="3", sizes=SMALL,
       statement=r"\tfrac12\langle\Phi,\Phi\rangle = \tfrac12\operatorname{tr}P^TP - \tfrac12\operatorname{tr}(X^TP)^2")
def normal_hamiltonian_on_tv(s):
    """On T*V, ½⟨Φ, Φ⟩ = ½tr(PᵀP) − ½tr((XᵀP)²)."""
    K = s.X.T @ s.P
    return {"H_0": H_0(s) - (s.tr(s.P.T @ s.P) / 2 - s.tr(K @ K) / 2)}


@claim("u-jensen-hamiltonian", paper="EM", kind="id", section="3", sizes=SMALL,
       statement=r"\tfrac12\langle\Phi,\Phi\rangle + \tfrac\kappa2\langle\Psi,\Psi\rangle = \tfrac12\operatorname{tr}P^TP - (\tfrac12+\kappa)\operatorname{tr}(X^TP)^2")
def jensen_hamiltonian_on_tv(s):
    """On T*V, ½⟨Φ, Φ⟩ + κ/2⟨Ψ, Ψ⟩ = ½tr PᵀP − (½ + κ)tr((XᵀP)²)."""
    K = s.X.T @ s.P
    lhs = s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2
    return {"H_kappa": lhs - (s.tr(s.P.T @ s.P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(K @ K))}


@claim("u-jensen-hamiltonian-factor", paper="EM", kind="id", section="3", sizes=admissible(n_max=4, r_min=2),
       statement=r"\ldots = \tfrac12\operatorname{tr}P^TP - (\tfrac12+2\kappa)\operatorname{tr}(X^TP)^2",
       fails_at=lambda n, r: True, erratum="2κ in place of κ")
def jensen_hamiltonian_wrong_factor(s):
    """On T*V, ½⟨Φ, Φ⟩ + κ/2⟨Ψ, Ψ⟩ = ½tr PᵀP − (½ + 2κ)tr((XᵀP)²) (a wrong factor)."""
    K = s.X.T @ s.P
    lhs = s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2
    return {"H_kappa": lhs - (s.tr(s.P.T @ s.P) / 2 - (s.q(1, 2) + 2 * s.kappa) * s.tr(K @ K))}


@claim("u-legendre-normal", paper=("P(dot_X)", "Phi_0"), kind="id", section="3", sizes=SMALL,
       statement=r"P = \dot X - \tfrac12 XX^T\dot X,\quad \Phi_0(X,\dot X) = \Phi")
def normal_legendre_inverse(s):
    """With Ẋ = P − XPᵀX, P = Ẋ − ½XXᵀẊ and Φ₀(X, Ẋ) = ẊXᵀ − XẊᵀ − ½X[XᵀẊ − ẊᵀX]Xᵀ equals Φ."""
    X, P = s.X, s.P
    V = P - X @ P.T @ X
    Phi0 = V @ X.T - X @ V.T - X @ (X.T @ V - V.T @ X) @ X.T / 2
    return {"P(Xdot)": V - X @ X.T @ V / 2 - P, "Phi_0": Phi0 - s.Phi}


@claim("u-submersion-flow", paper="dot_XP2", kind="id", section="3", sizes=SMALL,
       statement=r"\dot X = \mathbb A(\Phi)X,\ \dot P = \mathbb A(\Phi)P")
def submersion_metric_flow(s):
    """The Dirac flow of H_𝔸 = ½⟨𝔸Φ, Φ⟩, 𝔸 a symmetric operator on so(n), is Ẋ = 𝔸(Φ)X, Ṗ = 𝔸(Φ)P."""
    AA = s.sym_operator()
    flow = s.multiplier_flow(lambda t: t.killing(AA(t.Phi), t.Phi) / 2)
    APhi = AA(s.Phi)
    return {"Xdot": flow["X"] - APhi @ s.X, "Pdot": flow["P"] - APhi @ s.P,
            "Lambda": flow["Lambda"], "Pi": flow["Pi"]}


# --- Section 5: the Neumann systems -------------------------------------------------------

@claim("u-neumann-kappa-flow", paper="No", kind="id", section="5", sizes=SMALL,
       statement=r"\dot X = P-(1+2\kappa)XP^TX,\ \dot P = -AX - XP^TP + (1+2\kappa)PX^TP + XX^TAX")
def neumann_kappa_flow(s):
    """The Dirac flow of H_neum,κ is (No)."""
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * s.kappa
    flow = s.dirac_flow(H_neumann)
    return {"Xdot": flow["X"] - (P - c * X @ P.T @ X),
            "Pdot": flow["P"] - (-(A @ X) - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A @ X)}


@claim("u-neumann-kappa-flow-factor", paper="No", kind="id", section="5", sizes=SMALL,
       statement=r"\dot X = P-(1+\kappa)XP^TX \;(\text{suspected misprint})",
       fails_at=lambda n, r: r >= 2, erratum="1 + κ in place of 1 + 2κ (XPᵀX = 0 on T*V at r = 1)")
def neumann_kappa_flow_wrong_factor(s):
    """The Dirac flow of H_neum,κ with Ẋ = P − (1 + κ)XPᵀX (a wrong factor)."""
    X, P = s.X, s.P
    flow = s.dirac_flow(H_neumann)
    return {"Xdot": flow["X"] - (P - (1 + s.kappa) * X @ P.T @ X)}


@claim("u-neumann-multipliers", paper="No", kind="id", section="5", sizes=SMALL,
       statement=r"\Pi = 0,\quad \Lambda = X^TAX - P^TP")
def neumann_multipliers(s):
    """In the Lagrange form (dot_XP) of the Neumann flow with κ = 0, Π = 0 and Λ = XᵀAX − PᵀP."""
    flow = s.multiplier_flow(H_neumann_normal)
    return {"Pi": flow["Pi"], "Lambda": flow["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P)}


@claim("u-prep-projector", paper="prep", kind="id", section="5", sizes=SMALL,
       statement=r"\tfrac{d}{dt}(XX^T) = [\Phi, XX^T]")
def projector_evolves(s):
    """Along every Neumann flow (No), d(XXᵀ)/dt = [Φ, XXᵀ] and dΨ/dt = 0."""
    flow = s.dirac_flow(H_neumann)
    return {"d(XXᵀ)/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(s.Phi, s.X @ s.X.T),
            "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("u-lax-neumann", paper=("LA1", "LA2"), kind="lax", section="5", sizes=SMALL,
       statement=r"\dot{\mathcal L}(\lambda) = [\Phi - \lambda A, \lambda\Phi + XX^T - \lambda^2A]")
def neumann_lax_pair(s):
    """Along (No), L(λ) = λΦ + XXᵀ − λ²A satisfies dL/dt = [Φ − λA, L]."""
    lam = s.lam
    flow = s.dirac_flow(H_neumann)

    def L(t):
        return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A

    return {"LA1": s.d(L, flow) - comm(s.Phi - lam * s.A, L(s))}


@claim("u-lax-neumann-sign", paper=("LA1", "LA2"), kind="not", expect="nonzero", section="5",
       sizes=admissible(n_max=4, n_min=2), statement=r"\dot{\mathcal L} \ne [\Phi + \lambda A, \mathcal L]")
def neumann_lax_pair_wrong_sign(s):
    """With 𝒜 = Φ + λA (the sign of λA flipped) the Lax equation does not hold."""
    lam = s.lam
    flow = s.dirac_flow(H_neumann_euclidean)

    def L(t):
        return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A

    return {"LA1 with +": s.d(L, flow) - comm(s.Phi + lam * s.A, L(s))}


@claim("u-perelomov-integrals", paper="perelomov", kind="id", section="5", sizes=SMALL,
       statement=r"\tfrac{d}{dt}\operatorname{tr}\mathcal L(\lambda)^k = 0,\ k = 1, 2, 3")
def perelomov_integrals_are_conserved(s):
    """The traces tr L(λ)^k, k = 1, 2, 3, are first integrals of the Neumann flow with κ = 0."""
    lam = s.lam
    flow = s.dirac_flow(H_neumann_normal)

    def L(t):
        return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A

    out = {}
    for k in (1, 2, 3):
        def f(t, k=k):
            M = L(t)
            Mk = M
            for _ in range(k - 1):
                Mk = Mk @ M
            return t.tr(Mk)
        out[f"d tr L^{k}/dt"] = s.d(f, flow)
    return out


@claim("u-perelomov-involution", paper=("perelomov", "NEUMANN"), kind="pb", section="5", sizes=SMALL,
       statement=r"\{\operatorname{tr}\mathcal L(\lambda)^2, \operatorname{tr}\mathcal L(\mu)^2\} = 0")
def perelomov_integrals_commute(s):
    """The integrals tr L(λ)² and tr L(μ)² Poisson commute for all λ, μ."""
    lam, mu = s.lam, s.scalar("mu")

    def trL2(c):
        def f(t):
            M = c * t.Phi + t.X @ t.X.T - c * c * t.A
            return t.tr(M @ M)
        return f

    return {"{tr L(lam)^2, tr L(mu)^2}": s.bracket(trL2(lam), trL2(mu))}


# --- Section 6: the dual Lax pair, resolvents -----------------------------------------------

@claim("u-resolvent-identity", paper="LA4", kind="id", section="6", sizes=SMALL,
       statement=r"A(\lambda I-A)^{-1} = (\lambda I-A)^{-1}A = \lambda(\lambda I-A)^{-1} - I")
def resolvent_identity(s):
    """A(λI − A)⁻¹ = (λI − A)⁻¹A = λ(λI − A)⁻¹ − I."""
    R = s.resolvent(s.lam)
    return {"AR": s.A @ R - (s.lam * R - s.In), "RA": R @ s.A - (s.lam * R - s.In)}


def dual_lax(s):
    R = s.resolvent(s.lam)
    X, P = s.X, s.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)],
                  [s.Ir + P.T @ R @ P, P.T @ R @ X]])


@claim("u-dual-lax-euclidean", paper=("LA3", "LA4"), kind="lax", section="6", sizes=SMALL,
       statement=r"\dot{\mathcal L}^* = [\mathcal L^*, \mathcal A^*],\ \mathcal A^* = \begin{pmatrix}0 & I\\ \Lambda-\lambda I & 0\end{pmatrix}")
def dual_lax_pair_euclidean(s):
    """Along (NE_XP), the 2r × 2r dual Lax pair (LA3) holds with 𝒜* = [[0, I], [Λ − λI, 0]], Λ = XᵀAX − PᵀP."""
    flow = s.dirac_flow(H_neumann_euclidean)
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    Astar = block([[s.zeros(s.r, s.r, ("r", "r")), s.Ir], [Lam - s.lam * s.Ir, s.zeros(s.r, s.r, ("r", "r"))]])
    return {"LA3": s.d(dual_lax, flow) - comm(dual_lax(s), Astar)}


@claim("u-dual-lax-normal", paper=("LA3", "LA4"), kind="lax", section="6", sizes=SMALL,
       statement=r"\mathcal A^* = \begin{pmatrix}X^TP & I\\ \Lambda-\lambda I & -P^TX\end{pmatrix}")
def dual_lax_pair_normal(s):
    """Along (N0_XP2), the dual Lax pair (LA3) holds with 𝒜* = [[XᵀP, I], [Λ − λI, −PᵀX]]."""
    flow = s.dirac_flow(H_neumann_normal)
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    Astar = block([[s.X.T @ s.P, s.Ir], [Lam - s.lam * s.Ir, -(s.P.T @ s.X)]])
    return {"LA3": s.d(dual_lax, flow) - comm(dual_lax(s), Astar)}


@claim("u-dual-lax-normal-transposed", paper=("LA3", "LA4"), kind="lax", section="6",
       sizes=admissible(n_max=4, r_min=2),
       statement=r"\mathcal A^* = \begin{pmatrix}P^TX & I\\ \Lambda-\lambda I & -X^TP\end{pmatrix}\;(\text{transposed})",
       fails_at=lambda n, r: r >= 2, erratum="PᵀX and XᵀP exchanged in the diagonal blocks")
def dual_lax_pair_normal_transposed(s):
    """The dual Lax pair along (N0_XP2) with the diagonal blocks of 𝒜* transposed."""
    flow = s.dirac_flow(H_neumann_normal)
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    Astar = block([[s.P.T @ s.X, s.Ir], [Lam - s.lam * s.Ir, -(s.X.T @ s.P)]])
    return {"LA3": s.d(dual_lax, flow) - comm(dual_lax(s), Astar)}


# --- Dimension counts ----------------------------------------------------------------------

def _so_n_invariants_and_constraints(t):
    """Ψ, PᵀP and the constraints XᵀX, XᵀP + PᵀX (their entries: differentials on T*V)."""
    return [t.Psi, t.P.T @ t.P, t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X]


def _ddim(n, r):
    dim_v = n * r - r * (r + 1) // 2
    so = lambda m: m * (m - 1) // 2 if m > 0 else 0  # noqa: E731
    return dim_v - so(n - r) + (so(n - 2 * r) if n > 2 * r else 0)


@claim("u-ddim-invariants", paper=("ddim", "SO(n)-inv"), kind="dim", section="2", sizes=SMALL,
       statement=r"\operatorname{ddim}\{\Psi_{ij},(P^TP)_{ij}\}|_{T^*V} = \operatorname{ddim}C^\infty(T^*V)^{SO(n)}")
def invariants_have_the_differential_dimension(s):
    """The functions Ψ_ij, (PᵀP)_ij restricted to T*V have differential dimension (ddim)."""
    n, r = s.n, s.r
    J = s.mat(s.jacobian(_so_n_invariants_and_constraints, symmetric=False))
    return {"rank [dΨ, d(PᵀP), dF]": Rank(J, _ddim(n, r) + r * (r + 1))}


def _orbit_matrix(s):
    """The matrix of ad_Φ : so(n) → so(n) in the basis E_a ∧ E_b (a < b)."""
    n = s.n
    pairs = [(a, b) for a in range(n) for b in range(a + 1, n)]
    rows = []
    for a, b in pairs:
        E = s.mat([[1 if (i, j) == (a, b) else -1 if (i, j) == (b, a) else 0 for j in range(n)]
                   for i in range(n)], ("n", "n"))
        C = comm(E, s.Phi)
        rows.append([C[i, j] for i, j in pairs])
    return s.mat(rows)


def _two_l(n, r):
    return n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)


@claim("u-orbit-dimension", paper="2l", kind="dim", section="2", sizes=admissible(n_max=5, n_min=2),
       statement=r"\dim \operatorname{Ad}_{SO(n)}\Phi = 2l")
def adjoint_orbit_dimension(s):
    """The adjoint orbit of a generic Φ(X, P) has dimension 2l of Lemma 2l (the rank of ad_Φ on so(n))."""
    return {"rank ad_Phi": Rank(_orbit_matrix(s), _two_l(s.n, s.r))}


@claim("u-phi-rank", paper="momentum_map", kind="dim", section="2", sizes=SMALL,
       statement=r"\operatorname{rank}\Phi = 2\lfloor\min(2r,n)/2\rfloor")
def phi_rank(s):
    """Φ = Σ p_i ∧ e_i has generic rank 2⌊min(2r, n)/2⌋."""
    n, r = s.n, s.r
    return {"rank Phi": Rank(s.Phi, 2 * (min(2 * r, n) // 2))}


@claim("u-phi-rank-2r", paper="momentum_map", kind="dim", section="2", sizes=SMALL,
       statement=r"\operatorname{rank}\Phi = 2r \;(\text{wrong for } 2r > n)",
       fails_at=lambda n, r: 2 * r > n, erratum="rank 2r exceeds n when 2r > n")
def phi_rank_2r(s):
    """Φ has generic rank 2r (true only for 2r ≤ n)."""
    return {"rank Phi": Rank(s.Phi, 2 * s.r)}


@claim("u-dim-stiefel", paper="hat", kind="dim", section="2", sizes=SMALL,
       statement=r"\dim V_{n,r} = \dim SO(n) - \dim SO(n-r) = nr - \tfrac{r(r+1)}2")
def stiefel_dimension(s):
    """V_{n,r} = SO(n)/SO(n−r) has dimension nr − r(r+1)/2."""
    n, r = s.n, s.r
    return {"dim V": Count(n * (n - 1) // 2 - (n - r) * (n - r - 1) // 2, n * r - r * (r + 1) // 2)}


@claim("u-dim-stiefel-wrong", paper="hat", kind="dim", section="2", sizes=SMALL,
       statement=r"\dim V_{n,r} = nr - \tfrac{r(r-1)}2 \;(\text{wrong index range})",
       fails_at=lambda n, r: True, erratum="r(r − 1)/2 in place of r(r + 1)/2")
def stiefel_dimension_wrong(s):
    """V_{n,r} has dimension nr − r(r−1)/2 (a wrong count of the constraints)."""
    n, r = s.n, s.r
    return {"dim V": Count(n * (n - 1) // 2 - (n - r) * (n - r - 1) // 2, n * r - r * (r - 1) // 2)}


# --- More statements: the metric realization, coordinates, spectral invariants --------------

def H_A(t):
    """½ tr PᵀA⁻¹P, the Hamiltonian of ds²_A on the realization (cond_XP2)."""
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


@claim("u-metric-flow", paper=("A_XP", "cond_XP2"), kind="id", section="3", realization="metric",
       sizes=admissible(n_max=3),
       statement=r"\dot X = A^{-1}P,\ \dot P = X\Lambda,\ \Lambda X^TA^{-1}X + X^TA^{-1}X\Lambda + 2P^TA^{-2}P = 0")
def metric_geodesic_flow(s):
    """On (cond_XP2) the flow of H_A is Ẋ = A⁻¹P, Ṗ = XΛ with ΛXᵀA⁻¹X + XᵀA⁻¹XΛ + 2PᵀA⁻²P = 0."""
    flow = s.dirac_flow(H_A)
    X, P, B = s.X, s.P, s.Ainv
    Lam = X.T @ flow["P"]
    return {"Xdot": flow["X"] - B @ P,
            "Pdot in span X": flow["P"] - X @ Lam,
            "Lambda equation": Lam @ X.T @ B @ X + X.T @ B @ X @ Lam + 2 * P.T @ B @ B @ P}


@claim("u-uhlenbeck-integrals", paper=("sphere_neum", "perelomov"), kind="id", section="5",
       sizes=admissible(n_max=4, n_min=2, r_max=1),
       statement=r"F_k = x_k^2 + \sum_{j\ne k}\frac{(x_kp_j - x_jp_k)^2}{a_k - a_j},\ \dot F_k = 0,\ \sum_k F_k = 1")
def uhlenbeck_integrals(s):
    """For r = 1 the Uhlenbeck integrals F_k of the Neumann system on the sphere are conserved and sum to 1."""
    n = s.n
    flow = s.dirac_flow(H_neumann_euclidean)

    def F(k):
        def f(t):
            a = t.a
            x, p = t.X, t.P
            out = x[k, 0] * x[k, 0]
            for j in range(n):
                if j != k:
                    m = x[k, 0] * p[j, 0] - x[j, 0] * p[k, 0]
                    out = out + m * m / (a[k] - a[j])
            return out
        return f

    checks = {f"dF_{k + 1}/dt": s.d(F(k), flow) for k in range(n)}
    total = F(0)(s)
    for k in range(1, n):
        total = total + F(k)(s)
    checks["sum F_k - 1"] = total - 1
    return checks


@claim("u-spectral-curve-coefficients", paper=("spectral-curve", "LA1"), kind="id", section="5",
       sizes=admissible(n_max=4),
       statement=r"\tfrac{d}{dt} e_k(\mathcal L_{neum}(\lambda)) = 0,\ k \le 3")
def spectral_curve_coefficients_conserved(s):
    """The coefficients e_1, e_2, e_3 of det(w − L(λ)) are conserved along (No)."""
    from stiefelsym import elementary
    lam = s.lam
    flow = s.dirac_flow(H_neumann)

    def e(k):
        return lambda t: elementary(t, lam * t.Phi + t.X @ t.X.T - lam * lam * t.A, 3)[k]

    return {f"d e_{k}/dt": s.d(e(k), flow) for k in (1, 2, 3)}


@claim("u-phi-canonical-casimir", paper=("zero", "Phi"), kind="pb", section="2", sizes=SMALL,
       statement=r"\{\Phi_\xi, F_i\}_0 = 0")
def phi_commutes_with_constraints_canonically(s):
    """(zero): Φ_ξ Poisson commutes with the constraint functions in the ambient canonical bracket."""
    xi = s.fresh("n", "n")
    xi = xi - xi.T
    C, D = s.fresh("r", "r"), s.fresh("r", "r")
    return {"{Phi_xi, tr C XᵀX}_0": s.canonical_bracket(lambda t: t.killing(t.Phi, xi), lambda t: t.tr(C @ t.X.T @ t.X)),
            "{Phi_xi, tr D (XᵀP + PᵀX)}_0": s.canonical_bracket(lambda t: t.killing(t.Phi, xi),
                                                                lambda t: t.tr(D @ (t.X.T @ t.P + t.P.T @ t.X)))}


@claim("u-psi-commutes-with-jensen", paper=("EM", "momentum_right_map"), kind="pb", section="3", sizes=SMALL,
       statement=r"\{\Psi_\zeta, H_\kappa\} = 0")
def psi_commutes_with_jensen_hamiltonians(s):
    """H_κ is SO(r)-invariant: {Ψ_ζ, H_κ} = 0 for every ζ ∈ so(r)."""
    z = s.fresh("r", "r")
    z = z - z.T
    K = lambda t: t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(t.X.T @ t.P @ t.X.T @ t.P)  # noqa: E731
    return {"{Psi_z, H_kappa}": s.bracket(lambda t: t.killing(t.Psi, z), K)}


@claim("u-neumann-multiplier-sign", paper="No", kind="id", section="5", sizes=SMALL,
       statement=r"\Lambda = X^TAX + P^TP \;(\text{suspected sign})",
       fails_at=lambda n, r: n > 1, erratum="the sign of PᵀP in Λ flipped")
def neumann_multiplier_wrong_sign(s):
    """In the Lagrange form of the Neumann flow with κ = 0, Λ = XᵀAX + PᵀP (a flipped sign)."""
    flow = s.multiplier_flow(H_neumann_normal)
    return {"Lambda": flow["Lambda"] - (s.X.T @ s.A @ s.X + s.P.T @ s.P)}


@claim("u-prep-commutator-order", paper="prep", kind="not", expect="nonzero", section="5",
       sizes=admissible(n_max=4, n_min=2, where=lambda n, r: r < n, condition="r < n"),
       statement=r"\tfrac{d}{dt}\Phi \ne [A, XX^T]")
def prep_commutator_order(s):
    """The commutator of (prep) in the other order, dΦ/dt = [A, XXᵀ], does not hold for r < n (XXᵀ = I at r = n)."""
    flow = s.dirac_flow(H_neumann)
    return {"dPhi/dt - [A, XXᵀ]": s.d(lambda t: t.Phi, flow) - comm(s.A, s.X @ s.X.T)}


@claim("u-uhlenbeck-denominator", paper=("sphere_neum", "perelomov"), kind="id", section="5",
       sizes=admissible(n_max=4, n_min=2, r_max=1),
       statement=r"F_k = x_k^2 + \sum_{j\ne k}\frac{(x_kp_j - x_jp_k)^2}{a_j - a_k}\;(\text{denominator reversed})",
       fails_at=lambda n, r: True, erratum="a_j − a_k in place of a_k − a_j")
def uhlenbeck_denominator_reversed(s):
    """With the denominators a_j − a_k the functions F_k are not conserved."""
    n = s.n
    flow = s.dirac_flow(H_neumann_euclidean)

    def f(t):
        a, x, p = t.a, t.X, t.P
        out = x[0, 0] * x[0, 0]
        for j in range(1, n):
            m = x[0, 0] * p[j, 0] - x[j, 0] * p[0, 0]
            out = out + m * m / (a[j] - a[0])
        return out

    return {"dF_1/dt": s.d(f, flow)}
