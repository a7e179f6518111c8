"""§3 Geodesic flows: Euclidean, submersion, normal, Jensen (Einstein) and
SO(r)-invariant metrics on V(n, r)."""
from __future__ import annotations

from functools import lru_cache

from stiefelsym import Rank, admissible, claim, comm, twisted

SECTION = "3"


# -- Hamiltonians of the section ---------------------------------------------

def H_euclidean(s):
    """(Euclidean) H_E = 1/2 tr(P^T P)."""
    return s.tr(s.P.T @ s.P) / 2


def H_normal(s):
    """(normal_metric) H_0 = 1/2 <Phi, Phi>."""
    return s.killing(s.Phi, s.Phi) / 2


def H_jensen(s):
    """(EM) H_kappa = 1/2 <Phi, Phi> + kappa/2 <Psi, Psi>."""
    return s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2


def H_submersion(s):
    """(submersion_metric) H_AA = 1/2 <AA Phi, Phi> for a generic symmetric operator AA on so(n)."""
    return s.killing(s.sym_operator("AA")(s.Phi), s.Phi) / 2


def H_metric_A(s):
    """H_A = 1/2 tr(P^T A^{-1} P)."""
    return s.tr(s.P.T @ s.Ainv @ s.P) / 2


# -- the Euclidean metric ------------------------------------------------------

@claim("euclidean-flow", paper=("Euclidean", "Euclidean_XP"), kind="id",
       statement=r"H_E=\tfrac12\tr(P^TP):\quad \dot X=P,\ \dot P=-XP^TP")
def euclidean_geodesic_flow(s):
    """The Dirac flow of H_E = ½tr(PᵀP) is Ẋ = P, Ṗ = −XPᵀP."""
    flow = s.dirac_flow(H_euclidean)
    return {
        "dX/dt": flow.Xdot - s.P,
        "dP/dt": flow.Pdot - (-s.X @ s.P.T @ s.P),
    }


@claim("euclidean-multipliers", paper=("Euclidean", "dot_XP"), kind="id",
       statement=r"\ddot X=X\Lambda,\quad \Lambda=-\dot X^T\dot X,\quad \Pi=0")
def euclidean_lagrange_multipliers(s):
    """In the Lagrange form (dot_XP) of the Euclidean geodesic flow, Π = 0 and Λ = −ẊᵀẊ, so that Ẍ = XΛ."""
    flow = s.multiplier_flow(H_euclidean)
    return {
        "Lambda": flow["Lambda"] - (-(flow.Xdot.T @ flow.Xdot)),
        "Pi": flow["Pi"],
        "d^2X/dt^2 = X Lambda": s.d(lambda t: t.P, flow) - s.X @ flow["Lambda"],
    }


@claim("euclidean-invariance", paper=("Euclidean_XP",), kind="id",
       statement=r"\tfrac{d}{dt}(X^TX)=0,\ \tfrac{d}{dt}(X^TP+P^TX)=0 \text{ along } \dot X=P,\ \dot P=-XP^TP")
def euclidean_flow_keeps_the_cotangent_bundle(s):
    """The printed Euclidean flow Ẋ = P, Ṗ = −XPᵀP is tangent to T*V (it keeps the constraints)."""
    printed = {"X": s.P, "P": -s.X @ s.P.T @ s.P}
    return {
        "d(X^T X)/dt": s.d(lambda t: t.X.T @ t.X, printed),
        "d(X^T P + P^T X)/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, printed),
    }


# -- submersion metrics --------------------------------------------------------

@claim("submersion-hamiltonian", paper=("submersion_metric",), kind="id",
       statement=r"\tfrac12\langle\mathbb A\Phi,\Phi\rangle=-\tfrac14\tr\big(\mathbb A(PX^T-XP^T)(PX^T-XP^T)\big)")
def submersion_hamiltonian_trace_form(s):
    """For every symmetric operator 𝔸 on so(n), H_𝔸 = ½⟨𝔸Φ, Φ⟩ equals the printed trace form."""
    AA = s.sym_operator("AA")
    Phi = s.P @ s.X.T - s.X @ s.P.T
    return {"H_AA": H_submersion(s) - (-(s.tr(AA(Phi) @ Phi)) / 4)}


@claim("submersion-flow", paper=("dot_XP2",), kind="id",
       statement=r"\dot X=\mathbb A(\Phi)X,\quad \dot P=\mathbb A(\Phi)P,\quad \Lambda=\Pi=0")
def submersion_geodesic_flow(s):
    """The Dirac flow of H_𝔸 is Ẋ = 𝔸(Φ)X, Ṗ = 𝔸(Φ)P, and its Lagrange multipliers Λ, Π vanish."""
    AA = s.sym_operator("AA")
    flow = s.dirac_flow(H_submersion)
    mult = s.multiplier_flow(H_submersion)
    return {
        "dX/dt": flow.Xdot - AA(s.Phi) @ s.X,
        "dP/dt": flow.Pdot - AA(s.Phi) @ s.P,
        "Lambda": mult["Lambda"],
        "Pi": mult["Pi"],
    }


@claim("right-invariant-geodesic-flow", paper=("dot_XP2", "submersion_metric", "momentum_map", "killing"),
       unlabelled=("Remark 3.1",), kind="id",
       sizes=admissible(n_max=5, n_min=2, r_is_n=True, condition="r = n: T*V(n, n) = T*O(n), whose component det X = 1 is T*SO(n)"),
       statement=r"r=n:\ XX^T=\mathbf I_n,\ \tr(X^T\dot X)=0,\quad \Omega=\dot XX^T=\mathbb A(\Phi),\quad \Phi=2PX^T,\quad "
                 r"H_{\mathbb A}=\tfrac12\langle\Phi,\Omega\rangle,\quad \tfrac{d}{ds}H_{\mathbb A}(Xe^{s\eta},Pe^{s\eta})\big|_{s=0}=0,\quad "
                 r"\dot\Phi=[\mathbb A(\Phi),\Phi],\quad \tfrac{d}{dt}(X^T\Phi X)=0")
def right_invariant_geodesic_flow(s):
    """At r = n, where V(n, n) = O(n) (XXᵀ = I), the system (dot_XP2) keeps det X (so it keeps SO(n)) and is the geodesic flow of the right-invariant metric ½⟨𝔸⁻¹Ω, Ω⟩ of the space angular velocity Ω = ẊX⁻¹: the momentum Φ of the left action is the right-translated momentum 2PXᵀ (the factor 2 of ⟨ξ, η⟩ = −½tr(ξη)), Ω = 𝔸(Φ), H_𝔸 = ½⟨Φ, Ω⟩ is invariant under the right action (X, P) ↦ (XR, PR), and the flow is the Euler–Arnold equation Φ̇ = [𝔸(Φ), Φ] of that metric with the body momentum XᵀΦX conserved."""
    AA = s.sym_operator("AA")
    X, P, Phi = s.X, s.P, s.Phi
    flow = s.dirac_flow(H_submersion)
    Omega = flow.Xdot @ X.T
    right = {"X": X @ s.eta, "P": P @ s.eta}
    return {
        "X X^T = I": X @ X.T - s.In,
        "tr(X^T dX/dt) = 0": s.tr(X.T @ flow.Xdot),
        "Omega = dX/dt X^T = AA(Phi)": Omega - AA(Phi),
        "Phi = 2 P X^T": Phi - 2 * (P @ X.T),
        "H_AA = 1/2 <Phi, Omega>": H_submersion(s) - s.killing(Phi, Omega) / 2,
        "H_AA right-invariant": s.d(H_submersion, right),
        "dPhi/dt = [AA(Phi), Phi]": s.d(lambda t: t.Phi, flow) - comm(AA(Phi), Phi),
        "d(X^T Phi X)/dt = 0": s.d(lambda t: t.X.T @ t.Phi @ t.X, flow),
    }


# -- the normal metric ---------------------------------------------------------

@claim("normal-hamiltonian", paper=("normal_metric",), kind="id",
       statement=r"H_0=\tfrac12\langle\Phi,\Phi\rangle=\tfrac12\tr(P^TP)-\tfrac12\tr\big((X^TP)^2\big)")
def normal_hamiltonian_trace_form(s):
    """On T*V, ½⟨Φ, Φ⟩ = ½tr(PᵀP) − ½tr((XᵀP)²)."""
    XtP = s.X.T @ s.P
    return {"H_0": H_normal(s) - (s.tr(s.P.T @ s.P) / 2 - s.tr(XtP @ XtP) / 2)}


@claim("normal-flow", paper=("dot_X3", "dot_P3"), kind="id",
       statement=r"\dot X=\Phi X=P-XP^TX,\quad \dot P=\Phi P=-XP^TP+PX^TP")
def normal_geodesic_flow(s):
    """The Dirac flow of H_0 is Ẋ = ΦX = P − XPᵀX, Ṗ = ΦP = −XPᵀP + PXᵀP."""
    flow = s.dirac_flow(H_normal)
    X, P, Phi = s.X, s.P, s.Phi
    return {
        "dX/dt = Phi X": flow.Xdot - Phi @ X,
        "Phi X = P - X P^T X": Phi @ X - (P - X @ P.T @ X),
        "dP/dt = Phi P": flow.Pdot - Phi @ P,
        "Phi P = -X P^T P + P X^T P": Phi @ P - (-X @ P.T @ P + P @ X.T @ P),
    }


def _normal_velocity(s):
    return s.P - s.X @ s.P.T @ s.X


@claim("normal-legendre-inverse", paper=("P(dot_X)",), kind="id",
       statement=r"\dot X=P-XP^TX\ \Longrightarrow\ P=\dot X-\tfrac12XX^T\dot X")
def normal_metric_inverse_legendre(s):
    """On T*V the velocity Ẋ = P − XPᵀX of the normal metric determines P = Ẋ − ½XXᵀẊ."""
    Xdot = _normal_velocity(s)
    return {"P": s.P - (Xdot - s.X @ s.X.T @ Xdot / 2)}


def _Phi0(s, V):
    """(Phi_0) with V in the role of the velocity."""
    X = s.X
    return V @ X.T - X @ V.T - X @ (X.T @ V - V.T @ X) @ X.T / 2


@claim("normal-momentum-of-velocity", paper=("Phi_0",), kind="id",
       statement=r"\Phi_0(X,\dot X)=\dot XX^T-X\dot X^T-\tfrac12X\big[X^T\dot X-\dot X^TX\big]X^T=\Phi\big(X,P(X,\dot X)\big)")
def momentum_as_function_of_velocity(s):
    """For every tangent vector Ẋ of V, Φ(X, Ẋ − ½XXᵀẊ) equals the printed Φ₀(X, Ẋ)."""
    V = s.P  # a generic tangent vector: X^T V + V^T X = 0 is the same constraint
    P_of_V = V - s.X @ s.X.T @ V / 2
    return {"Phi_0": _Phi0(s, V) - (P_of_V @ s.X.T - s.X @ P_of_V.T)}


def L_normal(s):
    """(normal_metric_lagrangian) L_0 = ½⟨Φ₀, Φ₀⟩ with the slot P holding the velocity."""
    Phi0 = _Phi0(s, s.P)
    return s.killing(Phi0, Phi0) / 2


@claim("normal-lagrangian", paper=("normal_metric_lagrangian", "P(dot_X)"), kind="id",
       statement=r"L_0=\tfrac12\langle\Phi_0,\Phi_0\rangle:\quad \frac{\partial L_0}{\partial\dot X}=\dot X-\tfrac12XX^T\dot X,"
                 r"\quad L_0(X,\dot X)=H_0\big(X,P(X,\dot X)\big)")
def normal_lagrangian_legendre(s):
    """The Legendre transform of L₀ = ½⟨Φ₀, Φ₀⟩ on TV is P = Ẋ − ½XXᵀẊ, and L₀ equals H₀ there."""
    V = s.P
    P_of_V = V - s.X @ s.X.T @ V / 2
    dL_dV = s.gradient(L_normal)[1]
    XtP = s.X.T @ P_of_V
    H0_at = s.tr(P_of_V.T @ P_of_V) / 2 - s.tr(XtP @ XtP) / 2
    return {"dL/dXdot": dL_dV - P_of_V, "L_0 = H_0": L_normal(s) - H0_at}


# -- Jensen metrics ------------------------------------------------------------

@claim("jensen-hamiltonian", paper=("EM",), kind="id",
       statement=r"H_\kappa=\tfrac12\langle\Phi,\Phi\rangle+\tfrac{\kappa}{2}\langle\Psi,\Psi\rangle"
                 r"=\tfrac12\tr(P^TP)-\big(\tfrac12+\kappa\big)\tr\big((X^TP)^2\big)")
def jensen_hamiltonian_trace_form(s):
    """On T*V, ½⟨Φ,Φ⟩ + κ/2⟨Ψ,Ψ⟩ = ½tr(PᵀP) − (½+κ)tr((XᵀP)²); κ = 0 is the normal and κ = −½ the Euclidean metric."""
    XtP = s.X.T @ s.P
    printed = s.tr(s.P.T @ s.P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(XtP @ XtP)
    at = lambda k: s.killing(s.Phi, s.Phi) / 2 + k * s.killing(s.Psi, s.Psi) / 2
    return {
        "H_kappa": H_jensen(s) - printed,
        "kappa = 0": at(s.const(0)) - H_normal(s),
        "kappa = -1/2": at(s.q(-1, 2)) - H_euclidean(s),
    }


@claim("jensen-invariance", paper=("EM",), kind="id",
       statement=r"H_\kappa(gXQ^{-1},gPQ^{-1})=H_\kappa(X,P),\quad g\in SO(n),\ Q\in SO(r)")
def jensen_hamiltonian_is_invariant(s):
    """H_κ is invariant under the left SO(n) and the right SO(r) actions (its derivatives along both vanish)."""
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    return {"left so(n)": s.d(H_jensen, left), "right so(r)": s.d(H_jensen, right)}


def _block_part(s, M, i):
    """The orthogonal projection of M in so(r) to so(r_i), i = 0, 1: D_i M D_i with D_i the projector of
    ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂} onto its block i (r₁ = ⌈r/2⌉ at fixed sizes; any two orthogonal blocks of ℝʳ in
    the free algebra)."""
    D = twisted.block_projector(s, i)
    return D @ M @ D


def H_K(s):
    """(EM2), (EM3): H_K = ½⟨Φ,Φ⟩ + K(Ψ), K(ξ) = κ₀/2⟨ξ,ξ⟩ + Σ κᵢ/2⟨ξᵢ,ξᵢ⟩."""
    K = s.scalar("kappa_0") * s.killing(s.Psi, s.Psi) / 2
    for i in range(2):
        Pi = _block_part(s, s.Psi, i)
        K = K + s.scalar(f"kappa_{i + 1}") * s.killing(Pi, Pi) / 2
    return s.killing(s.Phi, s.Phi) / 2 + K


@claim("block-jensen-hamiltonian", paper=("EM2", "EM3"), kind="id",
       statement=r"H_K=\tfrac12\langle\Phi,\Phi\rangle+K(\Psi),\quad "
                 r"K(\xi)=\tfrac{\kappa_0}{2}\langle\xi,\xi\rangle+\sum_i\tfrac{\kappa_i}{2}\langle\xi_i,\xi_i\rangle")
def block_jensen_hamiltonian(s):
    """H_K is SO(n)-invariant and SO(r₁)×SO(r₂)-invariant and conserves Φ; the block parts ξᵢ are the orthogonal projections of ξ to so(rᵢ) (two blocks, r₁ = ⌈r/2⌉, at fixed sizes; dimension-free, any two orthogonal blocks of ℝʳ)."""
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    eta_b = _block_part(s, s.eta, 0) + _block_part(s, s.eta, 1)
    right = {"X": s.X @ eta_b, "P": s.P @ eta_b}
    flow = s.dirac_flow(H_K)
    checks = {
        "left so(n)": s.d(H_K, left),
        "right block subgroup": s.d(H_K, right),
        "Phi conserved": s.d(lambda t: t.Phi, flow),
    }
    for i in range(2):
        part = _block_part(s, s.Psi, i)
        checks[f"Psi - Psi_{i + 1} orthogonal to so(r_{i + 1})"] = s.killing(s.Psi - part, _block_part(s, s.eta, i))
    return checks


# -- SO(r)-invariant metrics L_A ----------------------------------------------

@claim("metric-legendre", paper=("leg2", "cond_XP2"), kind="id",
       statement=r"P=\frac{\partial L_A}{\partial\dot X}=A\dot X,\qquad X^TA^{-1}P+P^TA^{-1}X=0")
def metric_legendre_transform(s):
    """The Legendre transform of L_A = ½tr(ẊᵀAẊ) is P = AẊ, and it maps TV onto (cond_XP2)."""
    V = s.P  # a generic tangent vector of V at X
    L_A = lambda t: t.tr(t.P.T @ t.A @ t.P) / 2
    P = s.A @ V
    return {
        "dL_A/dXdot": s.gradient(L_A)[1] - P,
        "cond_XP2": s.X.T @ s.Ainv @ P + P.T @ s.Ainv @ s.X,
    }


@claim("metric-flow", paper=("A_XP",), kind="id", realization="metric",
       statement=r"\dot X=A^{-1}P,\ \dot P=X\Lambda,\quad \Lambda X^TA^{-1}X+X^TA^{-1}X\Lambda+2P^TA^{-2}P=0")
def metric_geodesic_flow(s):
    """The Dirac flow of H_A = ½tr(PᵀA⁻¹P) on (cond_XP2) is Ẋ = A⁻¹P, Ṗ = XΛ with Λ symmetric solving the printed equation."""
    flow = s.dirac_flow(H_metric_A)
    Lam = s.X.T @ flow.Pdot
    M = s.X.T @ s.Ainv @ s.X
    return {
        "dX/dt": flow.Xdot - s.Ainv @ s.P,
        "dP/dt = X Lambda": flow.Pdot - s.X @ Lam,
        "Lambda symmetric": Lam - Lam.T,
        "Lambda equation": Lam @ M + M @ Lam + 2 * (s.P.T @ s.Ainv @ s.Ainv @ s.P),
    }


# -- SO(n) x SO(r)-invariant metrics -------------------------------------------

def _fibre_action_matrix(s):
    """Linear conditions T^T G + G T = 0 on a symmetric G: the quadratic forms on T*_{X0}V
    invariant under P1 -> Q P1 Q^{-1}, P2 -> B P2 Q^{-1} (Q in SO(r), B in SO(n-r)).  Each
    condition is listed once (a repeated one, or its negative, and 0 = 0 are left out)."""
    rows, unknowns, N = _fibre_conditions(s.n, s.r)
    return [list(row) for row in rows], unknowns, N


@lru_cache(maxsize=None)
def _fibre_conditions(n, r):
    """The distinct conditions of :func:`_fibre_action_matrix` (integer rows), once per size."""
    coords = [("P1", i, j) for i in range(r) for j in range(i + 1, r)] + \
             [("P2", i, j) for i in range(n - r) for j in range(r)]
    index = {c: k for k, c in enumerate(coords)}
    N = len(coords)

    def action(eta, beta):
        """The matrix T of the infinitesimal action on the fibre coordinates."""
        T = [[0] * N for _ in range(N)]
        for (blk, i, j), k in index.items():
            # image of the unit vector of coordinate k
            if blk == "P1":
                P1 = [[0] * r for _ in range(r)]
                P1[i][j], P1[j][i] = 1, -1
                img1 = [[sum(eta[a][c] * P1[c][b] - P1[a][c] * eta[c][b] for c in range(r))
                         for b in range(r)] for a in range(r)]
                for a in range(r):
                    for b in range(a + 1, r):
                        T[index[("P1", a, b)]][k] += img1[a][b]
            else:
                img2 = [[0] * r for _ in range(n - r)]
                for a in range(n - r):
                    img2[a][j] += beta[a][i]
                for b in range(r):
                    img2[i][b] -= eta[j][b]
                for a in range(n - r):
                    for b in range(r):
                        T[index[("P2", a, b)]][k] += img2[a][b]
        return T

    def skew_basis(m):
        out = []
        for i in range(m):
            for j in range(i + 1, m):
                E = [[0] * m for _ in range(m)]
                E[i][j], E[j][i] = 1, -1
                out.append(E)
        return out

    gens = [action(E, [[0] * (n - r) for _ in range(n - r)]) for E in skew_basis(r)]
    gens += [action([[0] * r for _ in range(r)], B) for B in skew_basis(n - r)]
    unknowns = {(i, j): u for u, (i, j) in enumerate((i, j) for i in range(N) for j in range(i, N))}
    rows = []
    for T in gens:
        for k in range(N):
            for l in range(k, N):
                # (T^T G + G T)_{kl} = sum_a T_ak G_al + G_ka T_al as a linear form in G_ij = G_ji (i <= j)
                row = [0] * len(unknowns)
                for a in range(N):
                    if T[a][k]:
                        row[unknowns[min(a, l), max(a, l)]] += T[a][k]
                    if T[a][l]:
                        row[unknowns[min(k, a), max(k, a)]] += T[a][l]
                lead = next((c for c in row if c), 0)
                if lead:
                    rows.append(tuple(row) if lead > 0 else tuple(-c for c in row))
    return tuple(dict.fromkeys(rows)), len(unknowns), N


def _conditions_matrix(s, rows, unknowns):
    """The integer conditions as a matrix of the scene (one 1 x unknowns zero row when there are none)."""
    if not rows:
        return s.zeros(1, unknowns, ("cond", "coef"))
    const = {c: s.const(c) for c in {c for row in rows for c in row}}
    return s.mat([[const[c] for c in row] for row in rows], tags=("cond", "coef"))


def _extra_invariants(n: int, r: int) -> int:
    """Quadratic invariants beyond tr(P^T P), tr((X^T P)^2) in the exceptional sizes:
    the Pfaffian of P1 (r = 4), det P2 (n - r = r = 2), and <axial vector of P1, P2> (n - r = 1, r = 3)."""
    return int(r == 4) + int(n - r == 2 and r == 2) + int(n - r == 1 and r == 3)


# Proposition 4.6 is a statement of §4 of the paper, about the metrics of §3: filed under §4, written here beside
# the action on the fibre it is computed from
@claim("invariant-metrics", nature="range", paper=("SO(n-r)-action", "P-neutral"), unlabelled=("Proposition 4.6",), kind="dim", sizes=admissible(5, n_min=2),
       exact_max_n=7, section="4",
       fails_at=lambda n, r: _extra_invariants(n, r) > 0,
       place="Proposition 4.6 and its proof",
       erratum="""Proposition 4.6 fails when r = 4 (the Pfaffian of P₁ is an invariant quadratic form),
       when n − r = r = 2 (det P₂ is invariant) and when n − r = 1, r = 3 (the pairing ⟨axial(P₁), P₂⟩ of the axial
       vector of P₁ with P₂ is invariant); there the invariant metrics form a larger family.  For instance at
       (n, r) = (4, 2), where B ∈ SO(2) and Q ∈ SO(2) act by P₁ ↦ Q⁻¹P₁Q = P₁ and P₂ ↦ BP₂Q, the invariant quadratic forms are
       tr(P₁ᵀP₁), tr(P₂ᵀP₂) and det P₂: 3 of them, where the proposition gives 2.  The number the witness computes
       is the rank of the invariance conditions on the 15 coefficients of a quadratic form on the 5-dimensional
       fibre, 15 minus the number of invariant forms: 12 = 15 − 3, where the proposition gives 13 = 15 − 2.""",
       statement=r"\dim\{\text{quadratic forms on }T^*_{X_0}V_{n,r}\text{ invariant under }SO(r)\times SO(n-r)\}"
                 r"=\dim\Span\{\tr(P^TP),\tr((X^TP)^2)\}")
def invariant_quadratic_forms(s):
    """Proposition 4.6: the SO(n)×SO(r)-invariant quadratic forms on T*_{X₀}V (invariant under (SO(n-r)-action) and P₁ ↦ Q⁻¹P₁Q, P₂ ↦ P₂Q) are spanned by tr(PᵀP) and tr((XᵀP)²)."""
    rows, unknowns, N = _fibre_action_matrix(s)
    span = 1 if s.r in (1, s.n) else 2
    M = _conditions_matrix(s, rows, unknowns)
    return {"invariant forms": Rank(M, unknowns - span, generic=False,
                                    meaning=f"invariance conditions on the {unknowns} coefficients of a "
                                            f"quadratic form on the {N}-dimensional fibre; kernel = invariant forms")}


@invariant_quadratic_forms.claim.correction(
    "count also the Pfaffian of P₁ (r = 4), det P₂ (n − r = r = 2) and ⟨axial(P₁), P₂⟩ (n − r = 1, r = 3)")
def invariant_quadratic_forms_corrected(s):
    rows, unknowns, N = _fibre_action_matrix(s)
    span = (1 if s.r in (1, s.n) else 2) + _extra_invariants(s.n, s.r)
    M = _conditions_matrix(s, rows, unknowns)
    return {"invariant forms": Rank(M, unknowns - span, generic=False)}
