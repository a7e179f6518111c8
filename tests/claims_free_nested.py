"""Derivatives along flows nested in derivatives (second and third derivatives, mixed ones, along moving flows,
along P, of products and of matrix values, of functions that close over a value of an enclosing scene).  Claims
ending in -true are true, those ending in -false are false (each a true twin with one term changed); the values
are worked by hand from f(X + εV) (X, P free: the derivatives are ambient, as the scene's dual numbers take them)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def quad(u):
    return u.tr(u.X.T @ u.A @ u.X)


# -- third derivative: f(ε) = tr((M + εS + ε²W)²), M = XᵀX, S = XᵀV + VᵀX, W = VᵀV, so f''' = 12 tr(SW)
def third(s, F, T):
    return s.d(lambda t: t.d(lambda u: u.d(F, T), T), T)


def quartic(u):
    return u.tr(u.X.T @ u.X @ u.X.T @ u.X)


@claim("fnd-third-true", kind="id", sizes=SZ)
def third_true(s):
    V = s.fresh("n", "r")
    S, W = s.X.T @ V + V.T @ s.X, V.T @ V
    return {"w": third(s, quartic, {"X": V}) - s.tr(S @ W) * 12}


@claim("fnd-third-false", kind="id", sizes=SZ)
def third_false(s):
    V = s.fresh("n", "r")
    S, W = s.X.T @ V + V.T @ s.X, V.T @ V
    return {"w": third(s, quartic, {"X": V}) - s.tr(S @ W) * 6}


@claim("fnd-third-of-quadratic-true", kind="id", sizes=SZ)
def third_quadratic_true(s):
    """d³ tr(XᵀAX) = 0 (the value of the outermost derivative is a zero of the inner one's)."""
    V = s.fresh("n", "r")
    return {"w": third(s, quad, {"X": V})}


@claim("fnd-third-of-quadratic-false", kind="id", sizes=SZ)
def third_quadratic_false(s):
    V = s.fresh("n", "r")
    return {"w": third(s, quad, {"X": V}) - s.tr(V.T @ s.A @ V)}


# -- along a moving flow: d_{AX} tr(XᵀX) = 2 tr(XᵀAX), whose derivative along V is 4 tr(VᵀAX)
@claim("fnd-moving-flow-true", kind="id", sizes=SZ)
def moving_true(s):
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.X.T @ u.X), {"X": t.A @ t.X}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ s.X) * 4}


@claim("fnd-moving-flow-false", kind="id", sizes=SZ)
def moving_false(s):
    """2 tr(VᵀAX): the inner flow's motion along V forgotten."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.X.T @ u.X), {"X": t.A @ t.X}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ s.X) * 2}


@claim("fnd-euler-flow-true", kind="id", sizes=SZ)
def euler_true(s):
    """d_X tr(XᵀAX) = 2 tr(XᵀAX) (Euler), its derivative along V: 4 tr(VᵀAX)."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.X}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ s.X) * 4}


@claim("fnd-euler-flow-false", kind="id", sizes=SZ)
def euler_false(s):
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.X}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ s.X) * 2}


# -- along P: the inner along {"X": P} gives 2 tr(PᵀAX); along {"P": W} its derivative is 2 tr(WᵀAX)
@claim("fnd-along-p-true", kind="id", sizes=SZ)
def along_p_true(s):
    W = s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.P}), {"P": W})
    return {"w": got - s.tr(W.T @ s.A @ s.X) * 2}


@claim("fnd-along-p-false", kind="id", sizes=SZ)
def along_p_false(s):
    W = s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.P}), {"P": W})
    return {"w": got - s.tr(W.T @ s.A @ s.P) * 2}


@claim("fnd-momenta-true", kind="id", sizes=SZ)
def momenta_true(s):
    """d_V d_W tr(ΨΨᵀ), Ψ = XᵀP − PᵀX, W moving P, V moving X:
    2 tr((VᵀP − PᵀV)(XᵀW − WᵀX)ᵀ) + 2 tr(Ψ(VᵀW − WᵀV)ᵀ)."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.Psi @ u.Psi.T), {"P": W}), {"X": V})
    X, P = s.X, s.P
    dV, dW, dVW = V.T @ P - P.T @ V, X.T @ W - W.T @ X, V.T @ W - W.T @ V
    return {"w": got - s.tr(dV @ dW.T) * 2 - s.tr(s.Psi @ dVW.T) * 2}


@claim("fnd-momenta-false", kind="id", sizes=SZ)
def momenta_false(s):
    """... without the term of the mixed derivative of Ψ."""
    V, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.Psi @ u.Psi.T), {"P": W}), {"X": V})
    X, P = s.X, s.P
    dV, dW = V.T @ P - P.T @ V, X.T @ W - W.T @ X
    return {"w": got - s.tr(dV @ dW.T) * 2}


# -- mixed: d_U d_V tr(XᵀAX) = 2 tr(UᵀAV)
@claim("fnd-mixed-true", kind="id", sizes=SZ)
def mixed_true(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": V}), {"X": U})
    return {"w": got - s.tr(U.T @ s.A @ V) * 2}


@claim("fnd-mixed-false", kind="id", sizes=SZ)
def mixed_false(s):
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": V}), {"X": U})
    return {"w": got - s.tr(V.T @ s.A @ V) * 2}


# -- a matrix-valued inner result, multiplied by the point: d_V[(VXᵀ + XVᵀ)X] = 2VVᵀX + VXᵀV + XVᵀV
@claim("fnd-matrix-product-true", kind="id", sizes=SZ)
def matrix_product_true(s):
    V = s.fresh("n", "r")
    X = s.X
    got = s.d(lambda t: t.d(lambda u: u.X @ u.X.T, {"X": V}) @ t.X, {"X": V})
    return {"w": got - V @ V.T @ X * 2 - V @ X.T @ V - X @ V.T @ V}


@claim("fnd-matrix-product-false", kind="id", sizes=SZ)
def matrix_product_false(s):
    V = s.fresh("n", "r")
    X = s.X
    got = s.d(lambda t: t.d(lambda u: u.X @ u.X.T, {"X": V}) @ t.X, {"X": V})
    return {"w": got - V @ V.T @ X * 2 - V @ X.T @ V}


# -- a product with an inner derivative: d_V[tr(XᵀAX)·2tr(VᵀX)] = 4 tr(VᵀAX) tr(VᵀX) + 2 tr(XᵀAX) tr(VᵀV)
@claim("fnd-product-true", kind="id", sizes=SZ)
def product_true(s):
    V = s.fresh("n", "r")
    X, A = s.X, s.A
    got = s.d(lambda t: quad(t) * t.d(lambda u: u.tr(u.X.T @ u.X), {"X": V}), {"X": V})
    return {"w": got - s.tr(V.T @ A @ X) * s.tr(V.T @ X) * 4 - s.tr(X.T @ A @ X) * s.tr(V.T @ V) * 2}


@claim("fnd-product-false", kind="id", sizes=SZ)
def product_false(s):
    V = s.fresh("n", "r")
    X, A = s.X, s.A
    got = s.d(lambda t: quad(t) * t.d(lambda u: u.tr(u.X.T @ u.X), {"X": V}), {"X": V})
    return {"w": got - s.tr(X.T @ A @ X) * s.tr(V.T @ V) * 2}


# -- captured values: the inner function closes over the enclosing function's point (constant for the inner
# derivative, moving for the outer) or over the claim's (constant for both)
@claim("fnd-captured-outer-true", kind="id", sizes=SZ)
def captured_outer_true(s):
    """inner: d_V tr(X₀ᵀAX) = tr(X₀ᵀAV), X₀ = t.X; outer: tr(VᵀAV)."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(t.X.T @ u.A @ u.X), {"X": V}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ V)}


@claim("fnd-captured-outer-false", kind="id", sizes=SZ)
def captured_outer_false(s):
    """2 tr(VᵀAV): the captured point taken to move with the inner derivative."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(t.X.T @ u.A @ u.X), {"X": V}), {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ V) * 2}


@claim("fnd-captured-claim-true", kind="id", sizes=SZ)
def captured_claim_true(s):
    """the claim's X is a constant of both derivatives: d_V d_V tr(XᵀU) = 0 (U = u.X)."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(s.X.T @ u.X), {"X": V}), {"X": V})
    return {"w": got}


@claim("fnd-captured-claim-false", kind="id", sizes=SZ)
def captured_claim_false(s):
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(s.X.T @ u.X), {"X": V}), {"X": V})
    return {"w": got - s.tr(V.T @ V)}


# -- a part of a container returned by the inner derivative: d_V² (XᵀX) = 2VᵀV
@claim("fnd-container-true", kind="id", sizes=SZ)
def container_true(s):
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: [u.X.T @ u.X, u.X], {"X": V})[0], {"X": V})
    return {"w": got - V.T @ V * 2}


@claim("fnd-container-false", kind="id", sizes=SZ)
def container_false(s):
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: [u.X.T @ u.X, u.X], {"X": V})[0], {"X": V})
    return {"w": got - V.T @ V}


# -- a derivative nested in a bracket (the scene's own Dirac flow): F = d_P tr(XᵀX) = 2 tr(PᵀX) vanishes on T*V,
# so its bracket with any H does (the flow is tangent to T*V)
def _h(u):
    return u.tr(u.P.T @ u.P) / 2 + quad(u)


@claim("fnd-bracket-true", kind="id", sizes=SZ)
def bracket_true(s):
    return {"w": s.bracket(lambda t: t.d(lambda u: u.tr(u.X.T @ u.X), {"X": t.P}), _h)}


@claim("fnd-bracket-false", kind="id", sizes=SZ)
def bracket_false(s):
    return {"w": s.bracket(lambda t: t.d(lambda u: u.tr(u.X.T @ u.X), {"X": t.P}), _h) - s.tr(s.P.T @ s.P)}


# -- a derivative nested in a gradient: H = d_P tr(XᵀAX) = 2 tr(PᵀAX), ∂H/∂X = 2AP, ∂H/∂P = 2AX
@claim("fnd-gradient-true", kind="id", sizes=SZ)
def gradient_true(s):
    HX, HP = s.gradient(lambda t: t.d(quad, {"X": t.P}))
    return {"x": HX - s.A @ s.P * 2, "p": HP - s.A @ s.X * 2}


@claim("fnd-gradient-false", kind="id", sizes=SZ)
def gradient_false(s):
    HX, HP = s.gradient(lambda t: t.d(quad, {"X": t.P}))
    return {"x": HX - s.A @ s.P, "p": HP - s.A @ s.X * 2}


# -- an inner derivative along the Dirac flow (a flow the scene solves, not given by its components), whose
# derivative along V is not 0
@claim("fnd-dirac-inner-false", kind="id", sizes=SZ)
def dirac_inner_false(s):
    V = s.fresh("n", "r")
    return {"w": s.d(lambda t: t.d(quad, t.dirac_flow(_h)), {"X": V})}
