# ruff: noqa
"""Control for c3-half-bracket-true: the same bracket with no exception (TRUE if the convention is dF along G's flow)."""
from stiefelsym import admissible, claim
SZ = admissible(n_max=3, n_min=3, r_min=1, r_max=2)

@claim("c3-bracket-control", kind="pb", sizes=SZ)
def d2(s):
    """TRUE: {½tr XᵀAX, ½tr PᵀP} − tr(PᵀAX) = 0."""
    F = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2
    G = lambda t: t.tr(t.P.T @ t.P) / 2
    return {"pb": s.bracket(F, G) - s.tr(s.P.T @ s.A @ s.X)}

@claim("c3-bracket-raise-unused", kind="pb", sizes=SZ)
def d3(s):
    """TRUE: the same, after a different helper function raised (caught) inside s.d."""
    def bad(t):
        t.tr(t.P.T @ t.P)
        raise RuntimeError("x")
    try:
        s.d(bad, {"P": s.P})
    except RuntimeError:
        pass
    F = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2
    G = lambda t: t.tr(t.P.T @ t.P) / 2
    return {"pb": s.bracket(F, G) - s.tr(s.P.T @ s.A @ s.X)}

@claim("c3-raise-no-nodes", kind="id", sizes=SZ)
def d4(s):
    """TRUE: XᵀX = I_r, after a function handed to s.d raised before computing anything (caught)."""
    def bad(t):
        raise RuntimeError("x")
    try:
        s.d(bad, {"P": s.P})
    except RuntimeError:
        pass
    return {"r": s.X.T @ s.X - s.Ir}
