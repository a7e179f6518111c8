"""Claims that read the momentum P only indirectly (Phi, Psi, a flow, s.d, a gradient, a bracket, the constraints,
a tangent scene, the second point, systems.derivative at coupled_point), or not at all, for --hard large-momenta /
huge-momenta.  Each docstring states the truth and whether the claim's value depends on P."""
from stiefelsym import admissible, claim, comm
from stiefelsym import systems


def H_neu(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def K(t):
    return t.tr(t.P.T @ t.P)


def U(t):
    return t.tr(t.X.T @ t.A @ t.X)


@claim("r2-m-xonly-false", kind="id", sizes=admissible(n_max=3))
def xonly_false(s):
    """XᵀX = 2 I_r: FALSE; reads no P."""
    return {"w": s.X.T @ s.X - s.Ir * 2}


@claim("r2-m-phi-false", kind="id", sizes=admissible(n_max=3))
def phi_false(s):
    """tr(Φ Φᵀ) = 0: FALSE; reads P through Phi only."""
    return {"w": s.tr(s.Phi @ s.Phi.T)}


@claim("r2-m-psi-true", kind="id", sizes=admissible(n_max=3))
def psi_true(s):
    """Ψ = −Ψᵀ: TRUE; reads P through Psi only."""
    return {"w": s.Psi + s.Psi.T}


@claim("r2-m-flow-true", kind="id", sizes=admissible(n_max=3))
def flow_true(s):
    """Along the Neumann flow dΦ/dt = [XXᵀ, A]: TRUE; P read through a flow and s.d."""
    flow = s.dirac_flow(H_neu)
    return {"w": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A)}


@claim("r2-m-flow-false", kind="id", sizes=admissible(n_max=3))
def flow_false(s):
    """Along the Neumann flow dΦ/dt = 2[XXᵀ, A]: FALSE; P read through a flow and s.d."""
    flow = s.dirac_flow(H_neu)
    return {"w": s.d(lambda t: t.Phi, flow) - comm(s.X @ s.X.T, s.A) * 2}


@claim("r2-m-xdot-false", kind="id", sizes=admissible(n_max=3))
def xdot_false(s):
    """Ẋ of the Neumann flow = 0: FALSE (Ẋ = P on T*V); P read only inside H, handed to the engine."""
    flow = s.dirac_flow(H_neu)
    return {"w": flow["X"]}


@claim("r2-m-xdot-true", kind="id", sizes=admissible(n_max=3))
def xdot_true(s):
    """Ẋ of the potential flow (H = tr XᵀAX) is 0: TRUE (H reads no P); P is not read by the claim, but the flow's
    multipliers may."""
    flow = s.dirac_flow(U)
    return {"w": flow["X"]}


@claim("r2-m-pdot-potential", kind="id", sizes=admissible(n_max=3))
def pdot_potential(s):
    """Ṗ of the potential flow H = tr XᵀAX: Ṗ = −2AX + X Λ with Λ = XᵀAX·2 ... stated as XᵀṖ symmetric: TRUE (Ṗ
    = −H_X + XΛ + PΠ, Π = 0 here, XᵀṖ = −2XᵀAX + Λ, symmetric)."""
    flow = s.dirac_flow(U)
    M = s.X.T @ flow["P"]
    return {"w": M - M.T}


@claim("r2-m-grad-false", kind="id", sizes=admissible(n_max=3))
def grad_false(s):
    """∂K/∂P = P for K = tr PᵀP: FALSE (it is 2P); P read by the claim (s.P) and by K."""
    HX, HP = s.gradient(K)
    return {"w": HP - s.P}


@claim("r2-m-grad-hidden-false", kind="id", sizes=admissible(n_max=3))
def grad_hidden_false(s):
    """tr(∂K/∂P ᵀ ∂K/∂P) = 0 for K = tr PᵀP: FALSE (4 tr PᵀP); P read only inside K."""
    HX, HP = s.gradient(K)
    return {"w": s.tr(HP.T @ HP)}


@claim("r2-m-bracket-false", kind="id", sizes=admissible(n_max=3))
def bracket_false(s):
    """{tr PᵀP, tr XᵀAX} = 0 (Dirac): FALSE; P read only inside the functions."""
    return {"w": s.bracket(K, U)}


@claim("r2-m-canon-bracket-false", kind="id", sizes=admissible(n_max=3))
def canon_bracket_false(s):
    """{tr PᵀP, tr XᵀAX}₀ = 0 (ambient): FALSE; P read only inside the functions."""
    return {"w": s.canonical_bracket(K, U)}


@claim("r2-m-d-tangent-false", kind="id", sizes=admissible(n_max=3))
def d_tangent_false(s):
    """d/dε tr((P+εX)ᵀ(P+εX)) = 0 along {"P": X}: FALSE (2 tr XᵀP = 0 on T*V ... TRUE in fact: XᵀP skew); the
    claim reads P only inside F. TRUE."""
    return {"w": s.d(K, {"P": s.X})}


@claim("r2-m-d-tangent-false2", kind="id", sizes=admissible(n_max=3))
def d_tangent_false2(s):
    """d/dε tr((P+εA X)ᵀ(P+εAX)) = 0 along {"P": AX}: FALSE (2 tr XᵀAP ≠ 0); P read only inside F."""
    return {"w": s.d(K, {"P": s.A @ s.X})}


@claim("r2-m-constraints-false", kind="id", sizes=admissible(n_max=3))
def constraints_false(s):
    """The second constraint function XᵀP + PᵀX plus I_r vanishes: FALSE; P read only through s.constraints."""
    c = s.constraints.build(s)
    return {"w": c[1] + s.Ir}


@claim("r2-m-second-false", kind="id", sizes=admissible(n_max=3))
def second_false(s):
    """tr(QᵀQ) = 0 for the second point: FALSE; the claim reads Q, not P."""
    return {"w": s.tr(s.Q.T @ s.Q)}


@claim("r2-m-coupled-false", kind="id", sizes=admissible(n_max=3))
def coupled_false(s):
    """d/dε of tr(p ᵀp) at the coupled point along {"p": X} ... 2 tr(XᵀP) = 0: TRUE; along {"p": AX}: FALSE."""
    pt = {"x": s.X, "p": s.P}
    return {"w": systems.derivative(s, lambda t, z: t.tr(z["p"].T @ z["p"]), pt, {"p": s.A @ s.X})}


@claim("r2-m-tangent-scene-false", kind="id", sizes=admissible(n_max=3))
def tangent_scene_false(s):
    """Φ of the tangent scene along {"X": AX}: its derivative part is (P XᵀA − A X Pᵀ) ... stated 0: FALSE; reads P
    through Phi of a lifted scene."""
    return {"w": s.d(lambda t: t.Phi, {"X": s.A @ s.X})}
