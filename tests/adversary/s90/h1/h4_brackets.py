# ruff: noqa: F401
"""h4: the Dirac bracket and momentum maps, own formulations, with false twins."""
from stiefelsym import admissible, claim, comm

SZ = admissible(n_max=4)


@claim("h4-x-p-bracket", paper=("Dirac_bracket", "dot_XP"), kind="pb", sizes=SZ)
def xp(s):
    """{tr UᵀX, tr WᵀP} = tr UᵀW − ½tr(UᵀX(XᵀW + WᵀX))."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    b = s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.P))
    return {"pb": b - (s.tr(U.T @ W) - s.tr(U.T @ s.X @ (s.X.T @ W + W.T @ s.X)) / 2)}


@claim("h4-x-p-bracket-TWIN", paper=("Dirac_bracket", "dot_XP"), kind="pb", sizes=SZ)
def xp_twin(s):
    """(false twin) without the ½."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    b = s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.P))
    return {"pb": b - (s.tr(U.T @ W) - s.tr(U.T @ s.X @ (s.X.T @ W + W.T @ s.X)))}


@claim("h4-x-x-bracket", paper="Dirac_bracket", kind="pb", sizes=SZ)
def xx(s):
    """Positions commute: {tr UᵀX, tr WᵀX} = 0."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {"pb": s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.X))}


@claim("h4-p-p-bracket-TWIN", paper="Dirac_bracket", kind="pb", sizes=SZ)
def pp(s):
    """(false twin) momenta commute: {tr UᵀP, tr WᵀP} = 0."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {"pb": s.bracket(lambda t: t.tr(U.T @ t.P), lambda t: t.tr(W.T @ t.P))}


@claim("h4-psi-flow", paper=("right_action", "momentum_right_map"), kind="pb", sizes=SZ)
def psi_flow(s):
    """The Hamiltonian flow of ⟨Ψ, η⟩ (η ∈ so(r)) is Ẋ = Xη, Ṗ = Pη."""
    eta = s.eta
    f = s.dirac_flow(lambda t: t.killing(t.Psi, eta))
    return {"Xdot": f["X"] - s.X @ eta, "Pdot": f["P"] - s.P @ eta}


@claim("h4-psi-flow-TWIN", paper=("right_action", "momentum_right_map"), kind="pb", sizes=SZ)
def psi_flow_twin(s):
    """(false twin) Ẋ = −Xη."""
    eta = s.eta
    f = s.dirac_flow(lambda t: t.killing(t.Psi, eta))
    return {"Xdot": f["X"] + s.X @ eta}


@claim("h4-potential-phi-bracket", paper=("momentum_map", "Neumann_potential"), kind="pb", sizes=SZ)
def pot_phi(s):
    """{tr XᵀAX, ⟨Φ, ξ⟩} = 2tr(XᵀAξX)."""
    xi = s.xi
    b = s.bracket(lambda t: t.tr(t.X.T @ t.A @ t.X), lambda t: t.killing(t.Phi, xi))
    return {"pb": b - 2 * s.tr(s.X.T @ s.A @ xi @ s.X)}


@claim("h4-potential-phi-bracket-TWIN", paper=("momentum_map", "Neumann_potential"), kind="pb", sizes=SZ)
def pot_phi_twin(s):
    """(false twin) {tr XᵀAX, ⟨Φ, ξ⟩} = tr(XᵀAξX)."""
    xi = s.xi
    b = s.bracket(lambda t: t.tr(t.X.T @ t.A @ t.X), lambda t: t.killing(t.Phi, xi))
    return {"pb": b - s.tr(s.X.T @ s.A @ xi @ s.X)}
