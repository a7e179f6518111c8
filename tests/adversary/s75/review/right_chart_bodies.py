"""Reads of R^r coordinates hidden inside the bodies of functions handed to the scene (s.d, s.dirac_flow,
s.bracket, s.gradient).  On the right-reduced Cayley chart (S11 = 0) the top r x r block X1 of X is symmetric,
so a false statement "X1 is symmetric" would be proved there if the pass missed the read.  All FALSE
(X₀₁ ≠ X₁₀ on V(n, r), r >= 2), except where stated."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4, r_min=2, n_min=3, where=lambda n, r: r < n, condition="2 <= r < n")


def F(t):
    return t.X[0, 1] - t.X[1, 0]


@claim("s75-rc-direct", kind="id", sizes=SZ)
def rc_direct(s):
    """X₀₁ − X₁₀ = 0: FALSE."""
    return {"w": F(s)}


@claim("s75-rc-in-d", kind="id", sizes=SZ)
def rc_in_d(s):
    """d/dε F(X + εX) = X₀₁ − X₁₀ = 0: FALSE (F is linear)."""
    return {"w": s.d(F, {"X": s.X})}


@claim("s75-rc-in-flow", kind="id", sizes=SZ)
def rc_in_flow(s):
    """The X-part of the ambient (canonical) flow of H = tr(PᵀE) ... via gradient of H = X₀₁P... :
    gradient of H(t) = (tᵀ...)  — HP = ∂H/∂P of H = P₀₁ − P₁₀ is E₀₁ − E₁₀; residual tr(Xᵀ HP) = X₀₁ − X₁₀: FALSE."""
    HX, HP = s.gradient(lambda t: t.P[0, 1] - t.P[1, 0])
    return {"w": s.tr(s.X.T @ HP)}


@claim("s75-rc-in-bracket", kind="id", sizes=SZ)
def rc_in_bracket(s):
    """{tr(XᵀP)/2... } canonical bracket {F, ½tr PᵀP}: {X₀₁ − X₁₀, ½ tr PᵀP}_can = P₀₁ − P₁₀; residual = 0: FALSE.
    (On the S11 = 0 chart P's top block is not symmetric in general, so this one is a control.)"""
    return {"w": s.canonical_bracket(F, lambda t: t.tr(t.P.T @ t.P) / 2)}


@claim("s75-rc-in-d-true", kind="id", sizes=SZ)
def rc_in_d_true(s):
    """d/dε F(X + εX) − (X₀₁ − X₁₀) = 0: TRUE."""
    return {"w": s.d(F, {"X": s.X}) - F(s)}
