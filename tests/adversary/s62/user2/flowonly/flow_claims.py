# ruff: noqa: F841, E702, F401
"""True identities for the Jensen-type flow with a quartic potential (see common.py)."""
from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

from common import hamiltonian, hand_flow

ALL = admissible(n_max=4)


@claim("u2-flow", kind="id", sizes=ALL, statement=r"\dot X=P-2cXX^TP,\ \dot P=-AXM+XM^2-XP^TP-2cPX^TP")
def flow_is_the_hand_formula(s):
    """The Dirac flow of H_c is the hand-derived formula, at a free parameter c."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    hand = hand_flow(s, c)
    return {"dX/dt": flow["X"] - hand["X"], "dP/dt": flow["P"] - hand["P"]}


@claim("u2-multipliers", kind="id", sizes=ALL, statement=r"\Pi=0,\ \Lambda=(X^TAX)^2-P^TP")
def multipliers(s):
    """The Lagrange multipliers of (dot_XP) for H_c as written: Pi = 0, Lambda = M^2 - P^T P."""
    c = s.scalar("c")
    mult = s.multiplier_flow(hamiltonian(c))
    M = s.X.T @ s.A @ s.X
    return {"Pi": mult["Pi"], "Lambda": mult["Lambda"] - (M @ M - s.P.T @ s.P)}


@claim("u2-conserved", kind="id", sizes=ALL, statement=r"\dot H=0,\ \dot\Psi=0")
def conserved(s):
    """H_c and the right momentum Psi are conserved along the Dirac flow."""
    c = s.scalar("c")
    H = hamiltonian(c)
    flow = s.dirac_flow(H)
    return {"dH/dt": s.d(H, flow), "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("u2-conserved-hand", kind="id", sizes=ALL, statement=r"\dot\Psi=0 \text{ along the hand flow}")
def conserved_along_hand_flow(s):
    """H_c and Psi are conserved along the hand-written flow (as a tangent vector)."""
    c = s.scalar("c")
    H = hamiltonian(c)
    flow = hand_flow(s, c)
    return {"dH/dt": s.d(H, flow), "dPsi/dt": s.d(lambda t: t.Psi, flow)}


@claim("u2-phi-dot", kind="id", sizes=ALL, statement=r"\dot\Phi=[XX^TAXX^T, A]")
def phi_dot(s):
    """The left momentum evolves by dPhi/dt = [X M X^T, A], independently of c."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    X, A = s.X, s.A
    return {"dPhi/dt": s.d(lambda t: t.Phi, flow) - comm(X @ X.T @ A @ X @ X.T, A)}


@claim("u2-lax", kind="id", sizes=ALL, statement=r"\tfrac{d}{dt}XX^T=[\Phi, XX^T]")
def lax(s):
    """Lax equation dL/dt = [L, M] with L = XX^T, M = -Phi."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    L = s.X @ s.X.T
    return {"dL/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(L, -s.Phi)}


@claim("u2-lax-spectrum", kind="id", sizes=ALL, statement=r"\tfrac{d}{dt}\operatorname{tr}(L^kA)")
def lax_traces(s):
    """Consequence of the Lax form: tr((XX^T)^2) is constant (it equals r), and d/dt tr(XX^T A) = tr([Phi, XX^T] A)."""
    c = s.scalar("c")
    flow = s.dirac_flow(hamiltonian(c))
    L = s.X @ s.X.T
    return {"d tr L^2": s.d(lambda t: t.tr(t.X @ t.X.T @ t.X @ t.X.T), flow),
            "d tr LA": s.d(lambda t: t.tr(t.X @ t.X.T @ t.A), flow) - s.tr(comm(s.Phi, L) @ s.A)}


