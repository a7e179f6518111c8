"""Ambient quantities on the r = n family: XXᵀ = Iₙ holds on V(n, n) only, not off it, so the gradient,
the canonical flow, the Lagrange multipliers and a derivative along a non-tangent vector of a function
that reads XXᵀ must be taken of the function as written.  True claims paired with false twins that
would follow from rewriting XXᵀ → Iₙ inside the function."""
from stiefelsym import admissible, claim

SQ = admissible(r_is_n=True, n_max=3)


def H(t):
    return t.tr(t.X @ t.X.T @ t.A) / 2


@claim("s78-sq-grad-true", paper="prep", kind="id", sizes=SQ)
def grad_true(s):
    """∂/∂X of ½tr(XXᵀA) is AX (as written)."""
    g = s.gradient(H)
    return {"gX": g["X"] - s.A @ s.X}


@claim("s78-sq-grad-false", paper="prep", kind="id", sizes=SQ)
def grad_false(s):
    """False: ∂/∂X of ½tr(XXᵀA) is 0 (as if XXᵀ = I off V)."""
    g = s.gradient(H)
    return {"gX": g["X"]}


@claim("s78-sq-dnontangent-true", paper="prep", kind="id", sizes=SQ)
def dnt_true(s):
    """d/dε tr(XXᵀA) along X + εU (U generic, not tangent) is 2tr(UᵀAX)."""
    U = s.fresh("n", "r")
    return {"d": s.d(lambda t: t.tr(t.X @ t.X.T @ t.A), {"X": U}) - 2 * s.tr(U.T @ s.A @ s.X)}


@claim("s78-sq-dnontangent-false", paper="prep", kind="id", sizes=SQ)
def dnt_false(s):
    """False: d/dε tr(XXᵀA) along X + εU (U generic, not tangent) is 0."""
    U = s.fresh("n", "r")
    return {"d": s.d(lambda t: t.tr(t.X @ t.X.T @ t.A), {"X": U})}


def H2(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X @ t.X.T @ t.A) / 2


@claim("s78-sq-canon-true", paper="prep", kind="id", sizes=SQ)
def canon_true(s):
    """The canonical flow of ½tr PᵀP + ½tr(XXᵀA) has Ṗ = −AX."""
    f = s.canonical_flow(H2)
    return {"P": f["P"] + s.A @ s.X}


@claim("s78-sq-canon-false", paper="prep", kind="id", sizes=SQ)
def canon_false(s):
    """False: the canonical flow of ½tr PᵀP + ½tr(XXᵀA) has Ṗ = 0."""
    f = s.canonical_flow(H2)
    return {"P": f["P"]}


@claim("s78-sq-lambda-true", paper="prep", kind="id", sizes=SQ)
def lam_true(s):
    """Λ of ½tr PᵀP + ½tr(XXᵀA) as written is XᵀAX − PᵀP (ΠXX... solved from the constraints)."""
    f = s.multiplier_flow(H2)
    X, P, A = s.X, s.P, s.A
    return {"Lambda": f["Lambda"] - (X.T @ A @ X - P.T @ P)}


@claim("s78-sq-lambda-false", paper="prep", kind="id", sizes=SQ)
def lam_false(s):
    """False: Λ of ½tr PᵀP + ½tr(XXᵀA) is −PᵀP (as for ½tr PᵀP + ½tr A)."""
    f = s.multiplier_flow(H2)
    return {"Lambda": f["Lambda"] + s.P.T @ s.P}
