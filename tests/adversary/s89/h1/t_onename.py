"""s89h1: one name, one parameter, across the claim's scene and the scenes of the functions it hands to the engine.

 s89h1-name-nested-scalar-generic (FALSE): the claim reads c = s.scalar("c"); the Hamiltonian H(t) reads
     t.generic("c", "r", "r", "sym") (a second parameter named c, of another kind).  Residual: d/dt of
     tr XᵀX along the Dirac flow of H = ½tr PᵀP + tr(C XᵀX) minus c·0 ... see code: states
     c · tr(C_sym) - c · tr(C_sym)... (a TRUE control) and a FALSE twin below.
 s89h1-name-nested-false (FALSE): H(t) = tr(G XᵀP) with G = t.generic("c", "r", "r") and the claim's c = s.scalar("c"):
     {tr XᵀAX ... }: residual  d(tr XᵀP)/dt along the flow of H  -  c·tr(XᵀP)  (false: it has no reason to hold).
 s89h1-name-nested-scalar-scalar (TRUE control): both sides read s.scalar("c") / t.scalar("c"): the same parameter.
"""
from stiefelsym import claim, admissible

S = admissible(n_max=3)


@claim("s89h1-name-nested-false", kind="id", sizes=S)
def nested_false(s):
    """c is a scalar in the claim and a generic r×r matrix inside H (false statement)."""
    c = s.scalar("c")

    def H(t):
        G = t.generic("c", "r", "r")
        return t.tr(G @ t.X.T @ t.P)
    flow = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), flow) - c * s.tr(s.X.T @ s.P)}


@claim("s89h1-name-nested-same", kind="id", sizes=S)
def nested_same(s):
    """c read in the claim and in H: one parameter. d(tr XᵀAX)/dt along the flow of H = c·½tr PᵀP equals
    c·2tr(XᵀAP)... (TRUE: Ẋ = cP − XΠ with Π = sym(cXᵀP) = 0, so d tr XᵀAX = 2c tr XᵀAP)."""
    c = s.scalar("c")

    def H(t):
        return t.scalar("c") * t.tr(t.P.T @ t.P) / 2
    flow = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), flow) - 2 * c * s.tr(s.X.T @ s.A @ s.P)}


@claim("s89h1-name-nested-other-kind", kind="id", sizes=S)
def nested_other_kind(s):
    """c a scalar in the claim; inside H a scalar of the same name times a generic named c (refused?).  The
    statement, H = c tr(XᵀG P)?? : residual d(tr XᵀAX) along the flow of H minus 2c tr(XᵀAP) (FALSE)."""
    c = s.scalar("c")

    def H(t):
        return t.tr(t.generic("c", "n", "n", "sym") @ t.P @ t.P.T) / 2
    flow = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), flow) - 2 * c * s.tr(s.X.T @ s.A @ s.P)}
