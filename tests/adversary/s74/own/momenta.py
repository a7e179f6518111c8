"""Stop 74's own attempt on the momenta hard cases: a rewritten parameter of P counts only once the claim reads P.
Claims that read P only through what the scene builds from it (Φ, a flow, a derivative along it) must count as
touched; claims that read X alone, as untouched (verified at random points as without the case)."""
from stiefelsym import admissible, claim

S = admissible(n_max=3)


@claim("s74-own-phi-false", kind="id", sizes=S)
def phi_false(s):
    """Φ = PXᵀ − XPᵀ vanishes: FALSE (P read only through Φ)."""
    return {"Phi": s.Phi}


@claim("s74-own-flow-false", kind="id", sizes=S)
def flow_false(s):
    """d/dt tr(XᵀAX) = 0 along the Neumann flow: FALSE (P read only through the flow)."""
    flow = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2)
    return {"d tr(XtAX)": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), flow)}


@claim("s74-own-x-false", kind="id", sizes=S)
def x_false(s):
    """XᵀX = 2I: FALSE (no momentum read)."""
    return {"XtX - 2I": s.X.T @ s.X - s.Ir * 2}


@claim("s74-own-x-true", kind="id", sizes=S)
def x_true(s):
    """XᵀX = I: TRUE (no momentum read)."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}
