"""§5 The Neumann systems on Stiefel varieties: the Hamiltonians H_neum,κ, their
flows (No), (N0_XP2), (NE_XP), the conserved momentum Ψ, the equations (prep),
the Lax pair (LA1), (LA2) and the spectral invariants (perelomov)."""
from __future__ import annotations

from stiefelsym import claim, comm

SECTION = "5"

#: the powers k of the spectral invariants tr L(λ)^k checked (the paper: k = 1, ..., n)
POWERS = (1, 2, 3)


# -- the Hamiltonians (neumann) ----------------------------------------------------

def neumann_hamiltonian(s, kappa):
    """(neumann): H = ½tr(PᵀP) − (½ + κ)tr((XᵀP)²) + ½tr(XᵀAX)."""
    XtP = s.X.T @ s.P
    return (s.tr(s.P.T @ s.P) / 2 - (s.q(1, 2) + kappa) * s.tr(XtP @ XtP)
            + s.tr(s.X.T @ s.A @ s.X) / 2)


def H_neumann(s):
    """(neumann) for a free parameter κ."""
    return neumann_hamiltonian(s, s.kappa)


def H_neumann_normal(s):
    """(neumann) for κ = 0: the normal metric."""
    return neumann_hamiltonian(s, s.q(0))


def H_neumann_euclidean(s):
    """(neumann) for κ = −½: the Euclidean metric."""
    return neumann_hamiltonian(s, s.q(-1, 2))


def potential(s):
    """(Neumann_potential): V = ½tr(XᵀAX)."""
    return s.tr(s.X.T @ s.A @ s.X) / 2


# -- the printed flows ----------------------------------------------------------------

def flow_No(s, kappa):
    """(No): Ẋ = P − (1+2κ)XPᵀX, Ṗ = −AX − XPᵀP + (1+2κ)PXᵀP + XXᵀAX."""
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * kappa
    return {"X": P - c * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + c * (P @ X.T @ P) + X @ X.T @ A @ X}


def flow_N0(s):
    """(N0_XP2), right-hand forms: Ẋ = P − XPᵀX, Ṗ = −AX + PXᵀP − XPᵀP + XXᵀAX."""
    X, P, A = s.X, s.P, s.A
    return {"X": P - X @ P.T @ X,
            "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}


def flow_NE(s):
    """(NE_XP), right-hand forms: Ẋ = P, Ṗ = −AX − XPᵀP + XXᵀAX."""
    X, P, A = s.X, s.P, s.A
    return {"X": P, "P": -(A @ X) - X @ P.T @ P + X @ X.T @ A @ X}


def cond_XP(t):
    """(cond_XP): XᵀX − I_r and XᵀP + PᵀX."""
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def flow_checks(s, H, printed):
    """The Dirac flow of H equals the printed flow, and the printed flow keeps T*V."""
    flow = s.dirac_flow(H)
    kept = s.d(cond_XP, printed)
    return {
        "dX/dt": flow.Xdot - printed["X"],
        "dP/dt": flow.Pdot - printed["P"],
        "d(X^T X)/dt along the printed flow": kept[0],
        "d(X^T P + P^T X)/dt along the printed flow": kept[1],
    }


# -- the Lax matrices (LA2) -------------------------------------------------------------

def L_neum(s):
    """(LA2): 𝓛(λ) = λΦ + XXᵀ − λ²A."""
    return s.lam * s.Phi + s.X @ s.X.T - s.lam * s.lam * s.A


def A_neum(s):
    """(LA2): 𝓐(λ) = Φ − λA."""
    return s.Phi - s.lam * s.A


def L_neum_at(s, mu):
    """(perelomov): λ(PXᵀ − XPᵀ) + XXᵀ − λ²A at λ = mu."""
    return mu * (s.P @ s.X.T - s.X @ s.P.T) + s.X @ s.X.T - mu * mu * s.A


def power_trace(s, M, k):
    """tr M^k."""
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


# -- the Hamiltonian and its flow ---------------------------------------------------------

@claim("neumann-hamiltonian", paper=("Neumann_potential", "neumann", "EM"), kind="id",
       statement=r"H_{neum,\kappa}=\tfrac12\langle\Phi,\Phi\rangle+\tfrac{\kappa}{2}\langle\Psi,\Psi\rangle+V,\quad "
                 r"V=\tfrac12\tr(X^TAX)=\tfrac12\sum_{i=1}^r(e_i,Ae_i)")
def neumann_hamiltonian_is_jensen_plus_potential(s):
    """H_neum,κ is the Jensen kinetic energy (EM) of ds²_κ plus the potential V = ½tr(XᵀAX) = ½Σ(eᵢ, Aeᵢ), and it is right SO(r)-invariant."""
    kinetic = s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    return {
        "H_neum = H_kappa + V": H_neumann(s) - (kinetic + potential(s)),
        "H_neum right SO(r)-invariant": s.d(H_neumann, right),
    }


@claim("neumann-flow", paper=("neumann", "No"), kind="id",
       statement=r"\dot X=\{X,H_{neum,\kappa}\}=P-(1+2\kappa)XP^TX,\quad "
                 r"\dot P=\{P,H_{neum,\kappa}\}=-AX-XP^TP+(1+2\kappa)PX^TP+XX^TAX")
def neumann_flow_is_No(s):
    """For every κ, the Dirac flow of H_neum,κ is the printed (No), and (No) is tangent to T*V."""
    return flow_checks(s, H_neumann, flow_No(s, s.kappa))


@claim("neumann-multipliers", paper=("No", "dot_XP"), kind="id",
       statement=r"\dot X=\tfrac{\partial H}{\partial P}-X\Pi=P-(1+2\kappa)XP^TX-X\Pi,\ "
                 r"\dot P=-\tfrac{\partial H}{\partial X}+X\Lambda+P\Pi=-AX+(1+2\kappa)PX^TP+X\Lambda+P\Pi,\quad "
                 r"\Pi=0,\ \Lambda=X^TAX-P^TP")
def neumann_lagrange_multipliers(s):
    """In the Lagrange form (dot_XP) of the flow of H_neum,κ, the printed partial derivatives are the gradients of H, Π = 0 and Λ = XᵀAX − PᵀP (the proof of the Proposition)."""
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * s.kappa
    HX, HP = s.gradient(H_neumann)
    mult = s.multiplier_flow(H_neumann)
    return {
        "dH/dP": HP - (P - c * (X @ P.T @ X)),
        "-dH/dX": -HX - (-(A @ X) + c * (P @ X.T @ P)),
        "Pi": mult["Pi"],
        "Lambda": mult["Lambda"] - (X.T @ A @ X - P.T @ P),
        "dX/dt": mult.Xdot - flow_No(s, s.kappa)["X"],
        "dP/dt": mult.Pdot - flow_No(s, s.kappa)["P"],
    }


@claim("neumann-normal-flow", paper=("N0_XP2",), kind="id",
       statement=r"\kappa=0:\quad \dot X=P-XP^TX,\quad \dot P=-AX+PX^TP-XP^TP+XX^TAX")
def neumann_flow_normal_metric(s):
    """For κ = 0 the Dirac flow of H_neum,0 is the printed Neumann system with the normal metric (N0_XP2), which is tangent to T*V."""
    return flow_checks(s, H_neumann_normal, flow_N0(s))


@claim("neumann-euclidean-flow", paper=("NE_XP",), kind="id",
       statement=r"\kappa=-\tfrac12:\quad \dot X=P,\quad \dot P=-AX-XP^TP+XX^TAX")
def neumann_flow_euclidean_metric(s):
    """For κ = −½ the Dirac flow of H_neum,−½ is the printed Neumann system with the Euclidean metric (NE_XP), which is tangent to T*V."""
    return flow_checks(s, H_neumann_euclidean, flow_NE(s))


@claim("neumann-psi-conserved", paper=("No", "momentum_right_map"), kind="pb",
       statement=r"\tfrac{d}{dt}\Psi=\{\Psi,H_{neum,\kappa}\}=0\ \text{along (No)},\quad \Psi=X^TP-P^TX")
def right_momentum_is_conserved(s):
    """For every κ, the right SO(r) momentum Ψ = XᵀP − PᵀX is conserved by the Dirac flow of H_neum,κ."""
    return {"dPsi/dt": s.d(lambda t: t.Psi, s.dirac_flow(H_neumann))}


@claim("prep", paper=("prep", "No"), kind="id",
       statement=r"\tfrac{d}{dt}\Phi=[XX^T,A],\qquad \tfrac{d}{dt}(XX^T)=[\Phi,XX^T]\ \text{along (No)}")
def momentum_and_projector_evolve_by_commutators(s):
    """For every κ, along the Dirac flow of H_neum,κ, dΦ/dt = [XXᵀ, A] and d(XXᵀ)/dt = [Φ, XXᵀ]."""
    flow = s.dirac_flow(H_neumann)
    XX = s.X @ s.X.T
    return {
        "dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(XX, s.A),
        "d(XX^T)/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(s.Phi, XX),
    }


# -- the Lax pair -------------------------------------------------------------------------

@claim("neumann-lax", paper=("Neumann_LA", "LA1", "LA2"), kind="lax",
       statement=r"\tfrac{d}{dt}\mathcal L_{neum}(\lambda)=[\mathcal A_{neum}(\lambda),\mathcal L_{neum}(\lambda)],\quad "
                 r"\mathcal L_{neum}=\lambda\Phi+XX^T-\lambda^2A,\ \mathcal A_{neum}=\Phi-\lambda A")
def neumann_lax_pair(s):
    """Theorem Neumann_LA: for every κ (so for (N0_XP2) and (NE_XP)), the Dirac flow of H_neum,κ implies d𝓛/dt = [𝓐, 𝓛] with the printed 𝓛(λ), 𝓐(λ)."""
    flow = s.dirac_flow(H_neumann)
    return {"LA1": s.d(L_neum, flow) - comm(A_neum(s), L_neum(s))}


@claim("neumann-spectral-invariants", paper=("spectral-curve", "perelomov"), kind="pb",
       statement=r"\tfrac{d}{dt}\tr\mathcal L_{neum}(\lambda)^k=0\ \text{along (No)},\quad "
                 r"\{\tr\mathcal L_{neum}(\lambda)^k,\tr\mathcal L_{neum}(\mu)^m\}=0,\quad k,m=1,2,3")
def spectral_invariants_are_commuting_integrals(s):
    """The functions tr(λ(PXᵀ − XPᵀ) + XXᵀ − λ²A)^k of (perelomov), k = 1, 2, 3, are integrals of the Dirac flow of H_neum,κ for every κ and Poisson-commute for two values λ, μ of the spectral parameter."""
    flow = s.dirac_flow(H_neumann)
    checks = {}
    for k in POWERS:
        checks[f"d tr L(lambda)^{k}/dt"] = s.d(lambda t, k=k: power_trace(t, L_neum_at(t, t.lam), k), flow)
    for k in POWERS:
        for m in POWERS:
            if m < k:   # the pairs m < k are these with λ and μ exchanged
                continue
            checks[f"{{tr L(lambda)^{k}, tr L(mu)^{m}}}"] = s.bracket(
                lambda t, k=k: power_trace(t, L_neum_at(t, t.lam), k),
                lambda t, m=m: power_trace(t, L_neum_at(t, t.scalar("mu")), m))
    return checks
