"""Fourth round (AK): the multipliers of the metric realization's Dirac flows (free/metric.py: Π = 0 by the
uniqueness of its Sylvester equation, Λ a letter bound by its relation ρ).  Π of a Hamiltonian that vanishes on
T*V but whose gradient as written does not (Π ≠ 0); its multiplier flow against its Dirac flow; Λ of one Hamiltonian built twice (two letters of one
value); tr Λ = 0; ΛMΛ = −MΛ²; and the relation ρ itself, true."""
from stiefelsym import admissible, claim

S = admissible(n_max=3)


def H_A(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


def H_A_again(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


def H_vanishing_term(t):
    """½ tr(PᵀA⁻¹P) plus a term that vanishes on T*V (cond_XP2) with a gradient in P that does not."""
    c = t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X
    return t.tr(t.X.T @ t.A @ t.X @ c) + t.tr(t.P.T @ t.Ainv @ t.P) / 2


@claim("adv-s34-metric-pi-zero", paper="t", kind="id", sizes=S, realization="metric")
def pi_zero(s):
    """False: the multiplier Π of H = ½tr(PᵀA⁻¹P) + tr(XᵀAX(XᵀA⁻¹P + PᵀA⁻¹X)) is 0 (it is 2XᵀAX)."""
    return {"Pi": s.multiplier_flow(H_vanishing_term).multipliers["Pi"]}


@claim("adv-s34-metric-mflow-is-dflow", paper="t", kind="id", sizes=S, realization="metric")
def mflow_is_dflow(s):
    """Where Π != 0: the multiplier flow of H is its Dirac flow.  The free scene's metric multiplier flow is the
    Dirac flow (X' = H_P − A⁻¹XΠ) and refuses Π != 0; the fixed-size scene's multiplier_flow takes the form of
    (dot_XP), X' = H_P − XΠ, P' = −H_X + XΛ + PΠ, in the metric realization too, which is another field tangent to
    T*V when Π != 0 (so this fails at fixed sizes).  Where Π = 0 (all the free scene handles) the two agree."""
    return {"Xdot": s.multiplier_flow(H_vanishing_term).Xdot - s.dirac_flow(H_vanishing_term).Xdot}


@claim("adv-s34-metric-two-lambdas", paper="t", kind="id", sizes=S, realization="metric")
def two_lambdas(s):
    """True: the multiplier Λ of one Hamiltonian written twice is one matrix."""
    f1, f2 = s.dirac_flow(H_A), s.dirac_flow(H_A_again)
    return {"Lambda1 - Lambda2": s.X.T @ (f1.Pdot - f2.Pdot)}


@claim("adv-s34-metric-trace-lambda", paper="t", kind="id", sizes=S, realization="metric")
def trace_lambda(s):
    """False: tr Λ = 0."""
    return {"tr": s.tr(s.multiplier_flow(H_A).multipliers["Lambda"])}


@claim("adv-s34-metric-lambda-square", paper="t", kind="id", sizes=S, realization="metric")
def lambda_square(s):
    """False: ΛMΛ = −MΛ² (the relation gives ΛMΛ = −MΛ² + CΛ, C = −2PᵀA⁻²P)."""
    L = s.multiplier_flow(H_A).multipliers["Lambda"]
    M = s.X.T @ s.Ainv @ s.X
    return {"x": L @ M @ L + M @ L @ L}


@claim("adv-s34-metric-relation", paper="t", kind="id", sizes=S, realization="metric")
def relation(s):
    """True: ΛM + MΛ = −2PᵀA⁻²P, the relation of the multiplier of H = ½tr(PᵀA⁻¹P)."""
    L = s.multiplier_flow(H_A).multipliers["Lambda"]
    M = s.X.T @ s.Ainv @ s.X
    return {"rho": L @ M + M @ L + 2 * (s.P.T @ s.Ainv @ s.Ainv @ s.P)}


def H_neumann(t):
    """½ tr(PᵀA⁻¹P) + tr(XᵀAX): a Hamiltonian with a gradient in X too."""
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X)


@claim("adv-s34-metric-energy", paper="t", kind="id", sizes=S, realization="metric")
def energy(s):
    """True: H is conserved along its own Dirac flow."""
    return {"dH/dt": s.d(H_neumann, s.dirac_flow(H_neumann))}


@claim("adv-s34-metric-potential-conserved", paper="t", kind="id", sizes=S, realization="metric")
def potential(s):
    """False: tr(XᵀAX) alone is conserved along the flow of H."""
    return {"dV/dt": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), s.dirac_flow(H_neumann))}


@claim("adv-s34-metric-lambda-of-neumann", paper="t", kind="id", sizes=S, realization="metric")
def lambda_of_neumann(s):
    """False: the multiplier of H is that of ½tr(PᵀA⁻¹P) (the potential adds −(XᵀAX M + M XᵀAX)-type terms)."""
    L1 = s.multiplier_flow(H_neumann).multipliers["Lambda"]
    L2 = s.multiplier_flow(H_A).multipliers["Lambda"]
    return {"Lambda": L1 - L2}
