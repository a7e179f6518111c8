"""h3 hidden statements on §3 (geodesic flows: the metrics, their Hamiltonians and flows)."""
from stiefelsym import admissible, claim, comm


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2


def H_kappa(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


def H_sub(t):
    return t.killing(t.sym_operator("AA")(t.Phi), t.Phi) / 2


def H_A(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


# --- B1 ----------------------------------------------------------------------------------------

@claim("h3-euclid-gram", kind="id", section="3", sizes=admissible(5))
def euclid_gram(s):
    """Along Ẋ = P, Ṗ = −XPᵀP (the Euclidean flow): d(XᵀP)/dt = PᵀP − XᵀXPᵀP = 0, and with K = XᵀP (skew)
    d(PᵀP)/dt = −PᵀPXᵀP − PᵀXPᵀP = −PᵀP K + K PᵀP = [K, PᵀP]."""
    flow = s.dirac_flow(H_E)
    K = s.X.T @ s.P
    return {"d(P^T P)/dt": s.d(lambda t: t.P.T @ t.P, flow) - comm(K, s.P.T @ s.P),
            "d(X^T P)/dt": s.d(lambda t: t.X.T @ t.P, flow)}


@claim("h3-euclid-gram-twin", kind="id", section="3",
       sizes=admissible(5, where=lambda n, r: 1 < r < n, condition="1 < r < n"))
def euclid_gram_twin(s):
    """FALSE twin (for 1 < r < n; at r = 1 and r = n the commutator vanishes): [PᵀP, K]."""
    flow = s.dirac_flow(H_E)
    K = s.X.T @ s.P
    return {"d(P^T P)/dt": s.d(lambda t: t.P.T @ t.P, flow) - comm(s.P.T @ s.P, K),
            "d(X^T P)/dt": s.d(lambda t: t.X.T @ t.P, flow)}


# --- B3 ----------------------------------------------------------------------------------------

@claim("h3-jensen-flow", kind="id", section="3", sizes=admissible(5))
def jensen_flow(s):
    """H_κ = H_0 + κ·½⟨Ψ,Ψ⟩.  The Dirac flow of H_0 is (ΦX, ΦP) (normal-flow); the flow of ½⟨Ψ,Ψ⟩ =
    ½Σ_k Ψ_{η_k}² is Σ_k Ψ_{η_k}(Xη_k, Pη_k) = (XΨ, PΨ) (the flow of Ψ_η is (Xη, Pη)).  So Ẋ = ΦX + κXΨ,
    Ṗ = ΦP + κPΨ (check: κ = −½ gives Ẋ = P − XPᵀX + X(PᵀX... ) = P since XΨ = 2XXᵀP... on T*V)."""
    flow = s.dirac_flow(H_kappa)
    return {"dX/dt": flow.Xdot - (s.Phi @ s.X + s.kappa * s.X @ s.Psi),
            "dP/dt": flow.Pdot - (s.Phi @ s.P + s.kappa * s.P @ s.Psi)}


@claim("h3-jensen-flow-twin", kind="id", section="3", sizes=admissible(5, r_min=2, condition="r >= 2"))
def jensen_flow_twin(s):
    """FALSE twin (r ≥ 2; Ψ = 0 at r = 1): −κ in the P equation."""
    flow = s.dirac_flow(H_kappa)
    return {"dX/dt": flow.Xdot - (s.Phi @ s.X + s.kappa * s.X @ s.Psi),
            "dP/dt": flow.Pdot - (s.Phi @ s.P - s.kappa * s.P @ s.Psi)}


# --- B4: metric realization ----------------------------------------------------------------------

@claim("h3-metric-psi", kind="id", section="3", realization="metric", sizes=admissible(5))
def metric_psi(s):
    """Realization (cond_XP2): XᵀX = I, XᵀA⁻¹P + PᵀA⁻¹X = 0; H_A = ½tr(PᵀA⁻¹P) and the constraints are invariant
    under (X, P) ↦ (XQ, PQ), so Ψ = XᵀP − PᵀX, the momentum of that action for ω₀, is conserved (Noether; directly,
    with Ẋ = A⁻¹P, Ṗ = XΛ: dΨ/dt = PᵀA⁻¹P + Λ − Λ − PᵀA⁻¹P = 0), and so is XᵀA⁻¹P + PᵀA⁻¹X."""
    flow = s.dirac_flow(H_A)
    return {"dPsi/dt": s.d(lambda t: t.Psi, flow),
            "d cond_XP2": s.d(lambda t: t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X, flow)}


@claim("h3-metric-psi-twin", kind="id", section="3", realization="metric", sizes=admissible(5, n_min=2, condition="n >= 2 (P = 0 at n = 1)"))
def metric_psi_twin(s):
    """FALSE twin: XᵀP + PᵀX (sign) is not conserved: its derivative is 2PᵀA⁻¹P + 2Λ."""
    flow = s.dirac_flow(H_A)
    return {"dPsi/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, flow),
            "d cond_XP2": s.d(lambda t: t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X, flow)}


# --- B5: submersion metrics: Euler–Arnold on so(n) -------------------------------------------------

@claim("h3-submersion-euler", kind="id", section="3", sizes=admissible(5, n_min=2))
def submersion_euler(s):
    """With Ω = 𝔸(Φ) skew and the flow Ẋ = ΩX, Ṗ = ΩP (dot_XP2): dΦ/dt = ΩPXᵀ + PXᵀΩᵀ − ΩXPᵀ − XPᵀΩᵀ = [Ω, Φ]
    (Euler–Arnold equation); dΨ/dt = XᵀΩᵀP + XᵀΩP − PᵀΩX − PᵀΩᵀX = 0."""
    flow = s.dirac_flow(H_sub)
    AA = s.sym_operator("AA")
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(AA(s.Phi), s.Phi), "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("h3-submersion-euler-twin", kind="id", section="3", sizes=admissible(5, n_min=3, condition="n >= 3"))
def submersion_euler_twin(s):
    """FALSE twin (n ≥ 3; so(2) abelian): [Φ, 𝔸Φ]."""
    flow = s.dirac_flow(H_sub)
    AA = s.sym_operator("AA")
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(s.Phi, AA(s.Phi)), "dPsi/dt": s.d(lambda t: t.Psi, flow)}


# --- B6: the Legendre transform of the Jensen metrics -------------------------------------------------

@claim("h3-jensen-legendre", kind="id", section="3", sizes=admissible(5))
def jensen_legendre(s):
    """The velocity of H_κ is Ẋ = P − (1 + 2κ)XPᵀX = P + (1 + 2κ)XK (K = XᵀP skew), so XᵀẊ = (2 + 2κ)K and
    P = Ẋ − (1 + 2κ)/(2 + 2κ) XXᵀẊ (κ ≠ −1); κ = 0 gives (P(dot_X)), κ = −½ gives P = Ẋ."""
    k = s.kappa
    Xd = s.dirac_flow(H_kappa).Xdot
    return {"P": s.P - (Xd - (1 + 2 * k) / (2 + 2 * k) * s.X @ s.X.T @ Xd)}


@claim("h3-jensen-legendre-twin", kind="id", section="3", sizes=admissible(5, r_min=2, condition="r >= 2"))
def jensen_legendre_twin(s):
    """FALSE twin (r ≥ 2): 1 − 2κ in place of 1 + 2κ in the numerator."""
    k = s.kappa
    Xd = s.dirac_flow(H_kappa).Xdot
    return {"P": s.P - (Xd - (1 - 2 * k) / (2 + 2 * k) * s.X @ s.X.T @ Xd)}
