"""Further statements of Fedorov & Jovanović that the catalog states differently or not at all:
equations inside proofs and remarks, the special cases r = 1 and r = n, and consequences such as
conserved quantities and the Uhlenbeck form of the spectral invariants.

    stiefelsym verify --claims examples/paper_extra.py --method auto --jobs 1
    stiefelsym verify --claims examples/paper_extra.py --method free
    stiefelsym mutate --claims examples/paper_extra.py x-uhlenbeck-conserved --size 3,2

Every claim is written as a user would write it: only the public API (`stiefelsym`'s exports and the
scene `s`), no import of the catalog.
"""
from stiefelsym import Inverse, Rank, admissible, block, claim, comm, det, elementary

#: r = n: T*V(n, n) = T*SO(n)
R_IS_N = admissible(n_max=4, n_min=1, r_is_n=True, condition="r = n")
#: r = 1: T*S^{n-1}
R_IS_1 = admissible(n_max=5, n_min=2, r_in=(1,), condition="r = 1")


# -- the objects of the paper -------------------------------------------------------------

def H_E(t):
    """(Euclidean): H_E = ½tr(PᵀP)."""
    return t.tr(t.P.T @ t.P) / 2


def H_normal(t):
    """(normal_metric): H_0 = ½<Φ, Φ>."""
    return t.killing(t.Phi, t.Phi) / 2


def H_jensen(t):
    """(EM): H_κ = ½<Φ, Φ> + κ/2 <Ψ, Ψ>."""
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


def H_neum(t):
    """(neumann): H_neum,κ = ½tr(PᵀP) − (½ + κ)tr((XᵀP)²) + ½tr(XᵀAX)."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def flow_No(t):
    """(No): Ẋ = P − (1+2κ)XPᵀX, Ṗ = −AX − XPᵀP + (1+2κ)PXᵀP + XXᵀAX."""
    X, P, A = t.X, t.P, t.A
    c = 1 + 2 * t.kappa
    return {"X": P - c * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + c * (P @ X.T @ P) + X @ X.T @ A @ X}


def flow_manakov_square(t):
    """(dot_XP3*): Ẋ = AΦX + ΦAX, Ṗ = AΦP + ΦAP (the Manakov flow for B = A²)."""
    A, Phi = t.A, t.Phi
    return {"X": A @ Phi @ t.X + Phi @ A @ t.X, "P": A @ Phi @ t.P + Phi @ A @ t.P}


def power_trace(t, M, k):
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return t.tr(acc)


def L_neum(t, lam):
    """(LA2): 𝓛(λ) = λΦ + XXᵀ − λ²A."""
    return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A


def L_dual(t, lam):
    """(LA3): 𝓛*(λ) = [[−XᵀRP, −XᵀRX], [I + PᵀRP, PᵀRX]], R = (λI − A)⁻¹."""
    R, X, P = t.resolvent(lam), t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def uhlenbeck(t, lam):
    """𝓘₂(λ)/a(λ) written with the resolvent R = (λI − A)⁻¹: tr(XᵀRX) − ½tr(RΦRΦ)
    (= Σᵢ Fᵢ/(λ − aᵢ), Fᵢ = |eⁱ|² + Σ_{j≠i} Φᵢⱼ²/(aᵢ − aⱼ), by the explicit 𝓘₂ of (2r-integrals))."""
    R = t.resolvent(lam)
    return t.tr(t.X.T @ R @ t.X) - t.tr(R @ t.Phi @ R @ t.Phi) / 2


# -- §3 geodesic flows ------------------------------------------------------------------------

@claim("x-euclidean-geodesic-equation", paper=("Euclidean", "Euclidean_XP"), kind="id", section="3",
       statement=r"\ddot X=-X\dot X^T\dot X\ \text{along the Dirac flow of } H_E")
def euclidean_second_derivative(s):
    """The Euler–Lagrange equations with multipliers of §3: along the Dirac flow of H_E, the second derivative of X (the derivative of the flow's Ẋ along the flow) is Ẍ = XΛ with Λ = −ẊᵀẊ."""
    flow = s.dirac_flow(H_E)
    Xddot = s.d(lambda t: t.dirac_flow(H_E).Xdot, flow)
    return {"X'' + X X'^T X'": Xddot + s.X @ flow.Xdot.T @ flow.Xdot}


@claim("x-normal-geodesic-equation", paper=("dot_X3", "dot_P3"), kind="id", section="3",
       statement=r"\ddot X+\dot X\dot X^TX+X\big((X^T\dot X)^2+\dot X^T\dot X\big)=0")
def normal_geodesic_equation(s):
    """Along the geodesic flow (dot_X3), (dot_P3) of the normal metric, X(t) solves the second-order equation Ẍ + ẊẊᵀX + X((XᵀẊ)² + ẊᵀẊ) = 0 (the geodesic equation of the canonical metric of Edelman–Arias–Smith)."""
    X, P = s.X, s.P
    flow = {"X": P - X @ P.T @ X, "P": -(X @ P.T @ P) + P @ X.T @ P}
    Xd = flow["X"]
    Xdd = s.d(lambda t: t.P - t.X @ t.P.T @ t.X, flow)
    K = X.T @ Xd
    return {"geodesic equation": Xdd + Xd @ Xd.T @ X + X @ (K @ K + Xd.T @ Xd)}


@claim("x-submersion-right-invariant", paper=("dot_XP2", "submersion_metric"), kind="id", section="3",
       sizes=R_IS_N, statement=r"r=n:\ \dot XX^T=\mathbb A(\Phi),\ \tfrac{d}{dt}\Phi=[\mathbb A\Phi,\Phi]")
def submersion_flow_on_so_n(s):
    """The remark after (dot_XP2): for r = n the submersion flow is the right-invariant geodesic flow on SO(n): its angular velocity ẊXᵀ is 𝔸(Φ), and Φ obeys the Euler equations (Euler-so(n))."""
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(lambda t: t.killing(t.sym_operator("AA")(t.Phi), t.Phi) / 2)
    return {
        "X' X^T - AA(Phi)": flow.Xdot @ s.X.T - AA(s.Phi),
        "Phi' - [AA Phi, Phi]": s.d(lambda t: t.Phi, flow) - comm(AA(s.Phi), s.Phi),
    }


def legendre_normal(t, V):
    """(P(dot_X)): Ẋ ↦ P = Ẋ − ½XXᵀẊ, on all of ℝ^{n×r}."""
    return (V - t.X @ t.X.T @ V / 2,)


def legendre_normal_inverse(t, P):
    """P ↦ Ẋ = P + XXᵀP, which is (dot_X3) Ẋ = P − XPᵀX on T*V (there PᵀX = −XᵀP)."""
    return (P + t.X @ t.X.T @ P,)


@claim("x-normal-legendre-inverse", paper=("P(dot_X)", "dot_X3"), kind="id", section="3",
       statement=r"\dot X\mapsto\dot X-	frac12XX^T\dot X\ 	ext{is invertible with inverse } P\mapsto P+XX^TP"
                 r"=P-XP^TX")
def normal_legendre_is_invertible(s):
    """(P(dot_X)) inverts (dot_X3) uniquely: the map Ẋ ↦ Ẋ − ½XXᵀẊ is a bijection of ℝ^{n×r} at every point of V with inverse P ↦ P + XXᵀP, which equals P − XPᵀX on T*V."""
    return {
        "P(dot X) invertible": Inverse(legendre_normal, legendre_normal_inverse, on=("R^{n×r}",)),
        "inverse = (dot_X3)": legendre_normal_inverse(s, s.P)[0] - (s.P - s.X @ s.P.T @ s.X),
    }


@claim("x-jensen-flow", paper=("EM", "dot_XP"), kind="id", section="3",
       statement=r"\dot X=P-(1+2\kappa)XP^TX,\ \dot P=-XP^TP+(1+2\kappa)PX^TP,\ \Pi=0,\ \Lambda=-P^TP")
def jensen_geodesic_flow(s):
    """The geodesic flow of the Jensen metric ds²_κ (EM) is (No) with A = 0, with multipliers Π = 0 and Λ = −PᵀP (the proof of the Proposition of §5 at A = 0), and H_κ is conserved along it."""
    X, P = s.X, s.P
    c = 1 + 2 * s.kappa
    # the multipliers depend on how H is extended off T*V: the (EM) trace form, as in the proof of (No)
    flow = s.multiplier_flow(lambda t: t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(t.X.T @ t.P @ t.X.T @ t.P))
    printed = {"X": P - c * (X @ P.T @ X), "P": -(X @ P.T @ P) + c * (P @ X.T @ P)}
    return {
        "dX/dt": flow.Xdot - printed["X"],
        "dP/dt": flow.Pdot - printed["P"],
        "Pi": flow["Pi"],
        "Lambda": flow["Lambda"] + P.T @ P,
        "dH/dt along the printed flow": s.d(H_jensen, printed),
    }


@claim("x-a-metric-manakov-on-so-n", paper=("leg2", "Manakov*"), kind="id", section="3", sizes=R_IS_N,
       statement=r"r=n,\ \dot X=\xi X:\ \tfrac12\tr(\dot X^TA\dot X)=\tfrac12\langle\xi,A\xi+\xi A\rangle")
def a_metric_is_manakov_on_so_n(s):
    """The remark after (A_XP): for r = n the metric ds²_A is the right-invariant Manakov metric on SO(n): with Ẋ = ξX, ξ ∈ so(n), L_A = ½tr(ẊᵀAẊ) = ½<ξ, Aξ + ξA>, the operator (Manakov*)."""
    Xd = s.xi @ s.X
    return {"L_A - 1/2 <xi, A xi + xi A>":
            s.tr(Xd.T @ s.A @ Xd) / 2 - s.killing(s.xi, s.A @ s.xi + s.xi @ s.A) / 2}


# -- §4 the Manakov flows --------------------------------------------------------------------------

@claim("x-manakov-square-integrals", paper=("man", "dot_XP3*", "Manakov*"), kind="pb", section="4",
       sizes=admissible(n_max=4), statement=r"\tfrac{d}{dt}\tr(\Phi+\lambda A)^k=0,\ k=1..4,\ \text{along (dot\_XP3*)}")
def manakov_square_integrals(s):
    """The integrals (man) tr(Φ + λA)^k, k = 1, …, 4, are conserved by the Manakov flow (dot_XP3*) (B = A²), and the flow is the Dirac flow of H_𝔸 = ½<AΦ + ΦA, Φ>."""
    flow = flow_manakov_square(s)
    dirac = s.dirac_flow(lambda t: t.killing(t.A @ t.Phi + t.Phi @ t.A, t.Phi) / 2)
    checks = {"dX/dt": dirac.Xdot - flow["X"], "dP/dt": dirac.Pdot - flow["P"]}
    for k in (1, 2, 3, 4):
        checks[f"d/dt tr(Phi + lambda A)^{k}"] = s.d(
            lambda t, k=k: power_trace(t, t.Phi + t.lam * t.A, k), flow)
    return checks


@claim("x-big-lax-integrals-manakov-r-n", paper=("DUAL", "LA2", "Manakov*"), kind="pb", section="8",
       sizes=R_IS_N, statement=r"r=n:\ \tfrac{d}{dt}\tr\mathcal L_{neum}(\lambda)^k=0\ \text{along (dot\_XP3*)}")
def big_lax_gives_manakov_integrals(s):
    """The remark after Theorem DUAL: for r = n the integrals tr 𝓛_neum(λ)^k, k = 2, 3, of the Neumann Lax matrix are integrals of the right-invariant Manakov flow (dot_XP3*) as well."""
    flow = flow_manakov_square(s)
    return {f"d/dt tr L(lambda)^{k}": s.d(lambda t, k=k: power_trace(t, L_neum(t, t.lam), k), flow)
            for k in (2, 3)}


# -- §5 the Neumann systems ---------------------------------------------------------------------

@claim("x-potential-constant-r-n", paper=("Neumann_potential",), kind="id", section="5", sizes=R_IS_N,
       statement=r"r=n:\ \tfrac12\tr(X^TAX)=\tfrac12\tr A")
def potential_is_constant_for_r_n(s):
    """The remark after (Neumann_potential): for r = n the potential V = ½tr(XᵀAX) is the constant ½tr A."""
    return {"V - tr(A)/2": s.tr(s.X.T @ s.A @ s.X) / 2 - s.tr(s.A) / 2}


@claim("x-neumann-is-geodesic-r-n", paper=("No", "EM", "DUAL"), kind="id", section="5", sizes=R_IS_N,
       statement=r"r=n:\ \text{(No)}=\text{the flow of }H_\kappa=\tfrac{1+\kappa}2\langle\Phi,\Phi\rangle,\ \dot\Phi=0")
def neumann_is_bi_invariant_geodesic_for_r_n(s):
    """The remark after Theorem DUAL: for r = n the Neumann flows (No) are the geodesic flows of bi-invariant metrics: the flow of H_neum,κ is that of H_κ, H_κ = (1 + κ)/2 <Φ, Φ>, and Φ is conserved."""
    neum = s.dirac_flow(H_neum)
    geo = s.dirac_flow(H_jensen)
    return {
        "dX/dt": neum.Xdot - geo.Xdot,
        "dP/dt": neum.Pdot - geo.Pdot,
        "H_kappa - (1 + kappa)/2 <Phi, Phi>": H_jensen(s) - (1 + s.kappa) * s.killing(s.Phi, s.Phi) / 2,
        "dPhi/dt": s.d(lambda t: t.Phi, flow_No(s)),
    }


@claim("x-neumann-energy", paper=("No", "neumann"), kind="pb", section="5",
       statement=r"\tfrac{d}{dt}H_{neum,\kappa}=0,\ \tfrac{d}{dt}\Psi=0\ \text{along the printed (No)}")
def neumann_energy_conserved(s):
    """Along the printed flow (No), for every κ, the Hamiltonian H_neum,κ and the momentum Ψ are conserved."""
    flow = flow_No(s)
    return {"dH/dt": s.d(H_neum, flow), "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("x-neumann-proof-constraints", paper=("No",), kind="id", section="5",
       statement=r"\dot X^TX+X^T\dot X=0\Rightarrow\Pi=0,\quad"
                 r"\dot X^TP+X^T\dot P+\dot P^TX+P^T\dot X=0\Rightarrow\Lambda=X^TAX-P^TP")
def neumann_proof_multipliers(s):
    """The proof of the Proposition of §5: with Ẋ = P − (1+2κ)XPᵀX − XΠ, Ṗ = −AX + (1+2κ)PXᵀP + XΛ + PΠ, the derivatives of the constraints vanish for Π = 0, Λ = XᵀAX − PᵀP."""
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * s.kappa
    Lam = X.T @ A @ X - P.T @ P
    Xd = P - c * (X @ P.T @ X)
    Pd = -(A @ X) + c * (P @ X.T @ P) + X @ Lam
    return {
        "Xd^T X + X^T Xd": Xd.T @ X + X.T @ Xd,
        "Xd^T P + X^T Pd + Pd^T X + P^T Xd": Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd,
    }


@claim("x-perelomov-k4", paper=("perelomov", "LA1"), kind="pb", section="5", sizes=admissible(n_max=4),
       statement=r"\tfrac{d}{dt}\tr\mathcal L_{neum}(\lambda)^4=0,\ \{\tr\mathcal L(\lambda)^4,\tr\mathcal L(\mu)^2\}=0")
def perelomov_fourth_power(s):
    """The integral tr 𝓛_neum(λ)⁴ of (perelomov) is conserved by the flow of H_neum,κ and commutes with tr 𝓛_neum(μ)²."""
    mu = s.scalar("mu")
    flow = s.dirac_flow(H_neum)
    F4 = lambda t: power_trace(t, L_neum(t, t.lam), 4)
    return {
        "d/dt tr L^4": s.d(F4, flow),
        "{tr L(lambda)^4, tr L(mu)^2}": s.bracket(F4, lambda t: power_trace(t, L_neum(t, mu), 2)),
    }


# -- §8 the dual Lax pair: the Uhlenbeck integrals ---------------------------------------------------

@claim("x-resolvent-identity", paper=("DUAL",), kind="id", section="8",
       statement=r"A(\lambda I-A)^{-1}=(\lambda I-A)^{-1}A=\lambda(\lambda I-A)^{-1}-I")
def resolvent_identity(s):
    """The matrix identities used in the proof of Theorem DUAL: A(λI − A)⁻¹ = (λI − A)⁻¹A = λ(λI − A)⁻¹ − I."""
    R = s.resolvent(s.lam)
    return {"AR - (lambda R - I)": s.A @ R - (s.lam * R - s.In),
            "RA - (lambda R - I)": R @ s.A - (s.lam * R - s.In)}


@claim("x-dual-trace-square", paper=("2r-integrals", "LA3"), kind="id", section="8",
       statement=r"e_2(\mathcal L^*)=-\tfrac12\tr\mathcal L^*(\lambda)^2=\tr(X^TRX)-\tfrac12\tr(R\Phi R\Phi),\ "
                 r"e_1(\mathcal L^*)=e_3(\mathcal L^*)=0")
def dual_trace_square_is_uhlenbeck(s):
    """The coefficient 𝓘₂(λ)/a(λ) = e₂(𝓛*(λ)) = −½tr 𝓛*(λ)² of w^{2r−2} in the spectral curve of the dual Lax matrix is tr(XᵀRX) − ½tr(RΦRΦ), R = (λI − A)⁻¹, and the odd coefficients e₁ = tr 𝓛*(λ) and e₃ vanish."""
    L = L_dual(s, s.lam)
    e = elementary(s, L, 3)
    return {"-1/2 tr L*^2 - I_2/a": -s.tr(L @ L) / 2 - uhlenbeck(s, s.lam), "tr L*": s.tr(L),
            "e_2(L*) - I_2/a": e[2] - uhlenbeck(s, s.lam), "e_3(L*)": e[3]}


@claim("x-dual-r1-determinant", paper=("2r-integrals", "LA3"), kind="id", section="8", sizes=R_IS_1,
       statement=r"r=1:\ \det\mathcal L^*(\lambda)=(x,Rx)\,(1+(p,Rp))-(x,Rp)^2=\mathcal I_2(\lambda)/a(\lambda)")
def dual_determinant_r1(s):
    """For r = 1 the spectral curve of the 2×2 dual Lax matrix is w² + a(λ)²det 𝓛*(λ) = 0, with det 𝓛*(λ) = 𝓘₂(λ)/a(λ) = (x, Rx) + (x, Rx)(p, Rp) − (x, Rp)²."""
    L = L_dual(s, s.lam)
    by_entries = L[0, 0] * L[1, 1] - L[0, 1] * L[1, 0]
    return {"det L* - I_2/a": det(s, L) - uhlenbeck(s, s.lam), "det L* by its entries": by_entries - det(s, L)}


@claim("x-uhlenbeck-conserved", paper=("2r-integrals", "prep", "No"), kind="pb", section="8",
       statement=r"\tfrac{d}{dt}\big(\tr(X^TRX)-\tfrac12\tr(R\Phi R\Phi)\big)=0\ \text{along (No), every }\kappa")
def uhlenbeck_conserved(s):
    """The integrals 𝓘₂(λ)/a(λ) = tr(XᵀRX) − ½tr(RΦRΦ) of the dual Lax matrix are conserved along (No) for every κ (not only κ = 0, −½ of Theorem DUAL), since they depend on Φ and XXᵀ only, whose derivatives (prep) do not depend on κ."""
    return {"dI/dt": s.d(lambda t: uhlenbeck(t, t.lam), flow_No(s))}


@claim("x-uhlenbeck-involution", paper=("2r-integrals", "spectral-curve"), kind="pb", section="8",
       statement=r"\{\mathcal I_2(\lambda)/a(\lambda),\ \mathcal I_2(\mu)/a(\mu)\}=0")
def uhlenbeck_involution(s):
    """The integrals 𝓘₂(λ)/a(λ) = tr(XᵀRX) − ½tr(RΦRΦ) Poisson-commute for two values λ, μ of the spectral parameter."""
    mu = s.scalar("mu")
    return {"{I(lambda), I(mu)}": s.bracket(lambda t: uhlenbeck(t, t.lam), lambda t: uhlenbeck(t, mu))}


# it reads entries and the eigenvalues a_i, so the exact method works on the full Cayley chart, whose
# rational functions in a_i, λ and the chart's parameters outgrow 4 GiB at (4, 3): auto takes the
# modular method from n = 4 on (exact_max_n), where the symbolic attempt would die after ~20 s
@claim("x-uhlenbeck-coordinates", paper=("2r-integrals",), kind="id", section="8",
       sizes=admissible(n_max=4, n_min=2), exact_max_n=3,
       statement=r"\tr(X^TRX)-\tfrac12\tr(R\Phi R\Phi)=\sum_i\frac{F_i}{\lambda-a_i},\ "
                 r"F_i=|e^i|^2+\sum_{j\ne i}\frac{\Phi_{ij}^2}{a_i-a_j},\ \sum F_i=r,\ \sum a_iF_i=2H_{neum,0}")
def uhlenbeck_partial_fractions(s):
    """By the explicit 𝓘₂(λ) of (2r-integrals), 𝓘₂(λ)/a(λ) = Σᵢ Fᵢ/(λ − aᵢ) with the Uhlenbeck integrals Fᵢ = |eⁱ|² + Σ_{j≠i} Φᵢⱼ²/(aᵢ − aⱼ) (eⁱ the i-th row of X); Σ Fᵢ = r and Σ aᵢFᵢ = 2H_neum,0."""
    n, a, X, Phi = s.n, s.a, s.X, s.Phi
    G = X @ X.T
    F = []
    for i in range(n):
        f = G[i, i]
        for j in range(n):
            if j != i:
                f = f + Phi[i, j] * Phi[i, j] / (a[i] - a[j])
        F.append(f)
    total, weighted, fractions = F[0], a[0] * F[0], F[0] / (s.lam - a[0])
    for i in range(1, n):
        total = total + F[i]
        weighted = weighted + a[i] * F[i]
        fractions = fractions + F[i] / (s.lam - a[i])
    K = X.T @ s.P
    H0 = s.tr(s.P.T @ s.P) / 2 - s.tr(K @ K) / 2 + s.tr(X.T @ s.A @ X) / 2
    return {
        "I_2/a - sum F_i/(lambda - a_i)": uhlenbeck(s, s.lam) - fractions,
        "sum F_i - r": total - s.tr(s.Ir),
        "sum a_i F_i - 2 H_neum,0": weighted - 2 * H0,
    }


@claim("x-uhlenbeck-independent-r1", paper=("2r-integrals", "Mum_geod"), kind="dim", section="8",
       sizes=R_IS_1, statement=r"r=1:\ \rank\,d\big(\mathcal I_2(\mu_1)/a,\dots,\mathcal I_2(\mu_{n-1})/a,\ F\big)=n-1+2")
def uhlenbeck_independent_r1(s):
    """For r = 1 (the Neumann system on S^{n−1}), the n − 1 integrals 𝓘₂(μₖ)/a(μₖ) at distinct values μₖ, together with the two constraints, have independent differentials at a generic point: n − 1 independent integrals on T*S^{n−1}."""
    mus = [s.scalar(f"mu_{k}") for k in range(s.n - 1)]

    def functions(t):
        return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X] + [
            uhlenbeck(t, m) * t.Ir for m in mus]
    return {"rank": Rank(s.mat(s.jacobian(functions)), s.n - 1 + 2, generic=True,
                         meaning="n - 1 integrals and 2 constraints")}


@claim("x-dual-lax-not-right-invariant", paper=("2r-integrals", "LA3"), kind="not", expect="nonzero",
       section="8", sizes=admissible(n_max=4, r_min=2, condition="r >= 2 (so(1) = 0)"),
       statement=r"\tfrac{d}{ds}\mathcal L^*(\lambda)(Xe^{s\eta},Pe^{s\eta})\big|_{s=0}\neq0")
def dual_lax_is_not_right_invariant(s):
    """The remark after (2r-integrals): the dual Lax matrix 𝓛*(λ) is not invariant under the right SO(r) action (its derivative along the action of η ∈ so(r) is not 0), although its spectral curve is."""
    return {"d L*(lambda) along (X eta, P eta)":
            s.d(lambda t: L_dual(t, t.lam), {"X": s.X @ s.eta, "P": s.P @ s.eta})}


@claim("x-dirac-positions-commute", paper=("Dirac_bracket",), kind="pb", section="2",
       statement=r"\{\tr(U^TX),\tr(W^TX)\}=0\ \text{for the Dirac bracket}")
def positions_commute(s):
    """The positions commute for the Dirac bracket (Dirac_bracket): {tr(UᵀX), tr(WᵀX)} = 0 for all U, W ∈ ℝ^{n×r}, while {tr(UᵀX), tr(WᵀP)}_0 = tr(UᵀW) for the ambient bracket."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {
        "{tr U^T X, tr W^T X}": s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.X)),
        "{tr U^T X, tr W^T P}_0 - tr U^T W": s.canonical_bracket(lambda t: t.tr(U.T @ t.X),
                                                                 lambda t: t.tr(W.T @ t.P)) - s.tr(U.T @ W),
    }
