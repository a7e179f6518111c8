"""Engine steps handed functions of the wrong kind (matrix-valued Hamiltonians, lists)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("tc-grad-matrix", paper="t", kind="id", section="2", sizes=SZ)
def tc1(s):
    """gradient of a matrix-valued H = XᵀX: claim H_X = 0 (FALSE for any reading: d(XᵀX) != 0)."""
    HX, HP = s.gradient(lambda t: t.X.T @ t.X)
    return {"r": HX}


@claim("tc-bracket-matrix", paper="t", kind="id", section="2", sizes=SZ)
def tc2(s):
    """{XᵀP, tr PᵀP/2}: matrix-valued F; claim it is 0 (FALSE: d/dt XᵀP = PᵀP - ... )."""
    return {"r": s.bracket(lambda t: t.X.T @ t.P, lambda t: t.tr(t.P.T @ t.P) / 2)}


@claim("tc-flow-matrix", paper="t", kind="id", section="2", sizes=SZ)
def tc3(s):
    """dirac_flow of a matrix-valued H: claim Xdot = 0."""
    return {"r": s.dirac_flow(lambda t: t.P.T @ t.P)["X"]}


@claim("tc-canon-list", paper="t", kind="id", section="2", sizes=SZ)
def tc4(s):
    """canonical bracket of list-valued F with H: claim 0."""
    return {"r": s.canonical_bracket(lambda t: [t.tr(t.X.T @ t.A @ t.X)], lambda t: t.tr(t.P.T @ t.P))}


@claim("tc-jac-dict", paper="t", kind="id", section="2", sizes=SZ)
def tc5(s):
    """Jacobian of a dict-valued F: claim its first entry 0."""
    J = s.jacobian(lambda t: {"a": t.tr(t.X.T @ t.A @ t.X)})
    return {"r": J[0][0]}


@claim("tc-d-bracket-scalar-matrix", paper="t", kind="id", section="2", sizes=SZ)
def tc6(s):
    """s.d of a matrix-valued F along the flow of a scalar H: FALSE claim d(XᵀAX)/dt = 0."""
    fl = s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2)
    return {"r": s.d(lambda t: t.X.T @ t.A @ t.X, fl)}
