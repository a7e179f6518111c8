"""s77 levels: values of an outer function's scene t inside a gradient, a bracket or a Dirac flow taken in a
function of a tangent scene of t's (the Hamiltonian's reverse scene is two levels below t), a derivative inside
a gradient, derivatives along P, a value smuggled from a sibling scene; and one-level controls (the same truths
with the value read one function down, where the evaluator lifts it).  -true: TRUE, -false: FALSE."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _pair(s):
    return s.fresh("n", "r"), s.fresh("n", "r")


# -- one-level controls of skip_level.py's truths: d_U [t -> d_V [u -> tr(M(t)ᵀX_u)]] = tr(M'ᵀV)
def _two(s, U, V, body):
    return s.d(lambda t: t.d(lambda u: body(t, u), {"X": V}), {"X": U})


@claim("s77l-ctl-inv-true", kind="id", sizes=SZ)
def ctl_inv_true(s):
    """M = BK⁻¹, K = I + X_tᵀX_t, read one level down: -tr((BK⁻¹(UᵀX + XᵀU)K⁻¹)ᵀV): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    Ki = (s.Ir + s.X.T @ s.X).inv()
    want = -s.tr((B @ Ki @ (U.T @ s.X + s.X.T @ U) @ Ki).T @ V)
    got = _two(s, U, V, lambda t, u: u.tr((B @ (t.Ir + t.X.T @ t.X).inv()).T @ u.X))
    return {"w": got - want}


@claim("s77l-ctl-res-true", kind="id", sizes=SZ)
def ctl_res_true(s):
    """u.resolvent(λ + tr(X_tᵀX_t)) one level down: -2tr(XᵀU)tr((R²B)ᵀV): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    R = s.resolvent(s.lam + s.tr(s.X.T @ s.X))
    want = -(s.tr(s.X.T @ U) * 2) * s.tr((R @ R @ B).T @ V)
    got = _two(s, U, V, lambda t, u: u.tr((u.resolvent(t.lam + t.tr(t.X.T @ t.X)) @ B).T @ u.X))
    return {"w": got - want}


@claim("s77l-ctl-entry-true", kind="id", sizes=SZ)
def ctl_entry_true(s):
    """(X_tᵀX_u)[0, 0] one level down: (UᵀV)[0, 0]: TRUE."""
    U, V = _pair(s)
    return {"w": _two(s, U, V, lambda t, u: (t.X.T @ u.X)[0, 0]) - (U.T @ V)[0, 0]}


# -- a gradient in u's function of a Hamiltonian reading X_t: ∇_X tr(X_tᵀX_h) = X_t; tr(X_tᵀX_u) -> tr(UᵀV)
def _grad(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.tr(u.gradient(lambda h: h.tr(t.X.T @ h.X))[0].T @ u.X), {"X": V}),
               {"X": U})


@claim("s77l-grad-skip-true", kind="id", sizes=SZ)
def grad_skip_true(s):
    """tr(UᵀV): TRUE."""
    U, V = _pair(s)
    return {"w": _grad(s, U, V) - s.tr(U.T @ V)}


@claim("s77l-grad-skip-false", kind="id", sizes=SZ)
def grad_skip_false(s):
    """tr(UᵀU) (V confused with U: X_t = X + ε₁U read as X + ε₂U): FALSE."""
    U, V = _pair(s)
    return {"w": _grad(s, U, V) - s.tr(U.T @ U)}


# -- the Hamiltonian reads X_t and is quadratic: H = tr(X_tᵀX_h)·tr(X_hᵀX_h); ∇_X = 2tr(X_tᵀX)X + tr(XᵀX)X_t
#    at u: g(u) = tr(Bᵀ∇_X) = 2tr(X_tᵀX_u)tr(BᵀX_u) + tr(X_uᵀX_u)tr(BᵀX_t)
#    d_V at u = t: 2tr(X_tᵀV)tr(BᵀX_t) + 2tr(X_tᵀX_t)tr(BᵀV) + 2tr(X_tᵀV)tr(BᵀX_t)
#                = 4tr(X_tᵀV)tr(BᵀX_t) + 2tr(X_tᵀX_t)tr(BᵀV)
#    d_U: 4tr(UᵀV)tr(BᵀX) + 4tr(XᵀV)tr(BᵀU) + 4tr(XᵀU)tr(BᵀV)
def _grad2(s, U, V, B):
    def g(u):
        return u.tr(B.T @ u.gradient(lambda h: h.tr(t_box[0].X.T @ h.X) * h.tr(h.X.T @ h.X))[0])
    t_box = []

    def mid(t):
        t_box.append(t)
        return t.d(g, {"X": V})
    return s.d(mid, {"X": U})


def _grad2_direct(s, U, V, B):
    return s.d(lambda t: t.d(lambda u: u.tr(B.T @ u.gradient(
        lambda h: h.tr(t.X.T @ h.X) * h.tr(h.X.T @ h.X))[0]), {"X": V}), {"X": U})


def _grad2_truth(s, U, V, B):
    X = s.X
    return (s.tr(U.T @ V) * s.tr(B.T @ X) + s.tr(X.T @ V) * s.tr(B.T @ U) + s.tr(X.T @ U) * s.tr(B.T @ V)) * 4


@claim("s77l-grad-quad-true", kind="id", sizes=SZ)
def grad_quad_true(s):
    """4[tr(UᵀV)tr(BᵀX) + tr(XᵀV)tr(BᵀU) + tr(XᵀU)tr(BᵀV)]: TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _grad2_direct(s, U, V, B) - _grad2_truth(s, U, V, B)}


@claim("s77l-grad-quad-false", kind="id", sizes=SZ)
def grad_quad_false(s):
    """What X_t = X + ε₁U read as X + ε₂U gives: 2[tr(UᵀU)tr(BᵀX) + tr(XᵀU)tr(BᵀV) + tr(XᵀV)tr(BᵀU)
    + 2tr(XᵀU)tr(BᵀU) + tr(UᵀV)tr(BᵀX)]: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    X = s.X
    tr = s.tr
    conf = (tr(U.T @ U) * tr(B.T @ X) + tr(X.T @ U) * tr(B.T @ V) + tr(X.T @ V) * tr(B.T @ U)
            + tr(X.T @ U) * tr(B.T @ U) * 2 + tr(U.T @ V) * tr(B.T @ X)) * 2
    return {"w": _grad2_direct(s, U, V, B) - conf}


# -- a derivative inside a gradient: H(h) = d_B [u -> d_{u.X} [w -> tr(X_hᵀX_w)]] = tr(X_hᵀB); ∇_X H = B
def _dgrad(s, B):
    return s.gradient(lambda h: h.d(lambda u: u.d(lambda w: w.tr(h.X.T @ w.X), {"X": u.X}), {"X": B}))[0]


@claim("s77l-grad-of-d-true", kind="id", sizes=SZ)
def grad_of_d_true(s):
    """∇_X H = B: TRUE."""
    B = s.fresh("n", "r")
    return {"w": _dgrad(s, B) - B}


@claim("s77l-grad-of-d-false", kind="id", sizes=SZ)
def grad_of_d_false(s):
    """∇_X H = 0: FALSE."""
    B = s.fresh("n", "r")
    return {"w": _dgrad(s, B)}


# -- a bracket in u's function whose first function reads X_t: F_c(h) = tr(cᵀX_h) is linear in c, so
#    d_U d_V [{F_{X_t}, G}] = d_V {F_U, G} + d_U d_V {F_{X₀}, G} with X₀ = s.X held fixed
def _G(h):
    return h.tr(h.P.T @ h.A @ h.X)


def _bracket_skip(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.bracket(lambda h: h.tr(t.X.T @ h.X), _G), {"X": V}), {"X": U})


def _bracket_parts(s, U, V):
    X0 = s.X
    a = s.d(lambda u: u.bracket(lambda h: h.tr(U.T @ h.X), _G), {"X": V})
    b = s.d(lambda t: t.d(lambda u: u.bracket(lambda h: h.tr(X0.T @ h.X), _G), {"X": V}), {"X": U})
    return a, b


@claim("s77l-bracket-skip-true", kind="id", sizes=SZ)
def bracket_skip_true(s):
    """= d_V{F_U, G} + d_U d_V{F_X₀, G}: TRUE."""
    U, V = _pair(s)
    a, b = _bracket_parts(s, U, V)
    return {"w": _bracket_skip(s, U, V) - a - b}


@claim("s77l-bracket-skip-false", kind="id", sizes=SZ)
def bracket_skip_false(s):
    """= d_U d_V{F_X₀, G} + d_U{F_U, G} (X_t = X + ε₁U read as X + ε₂U: V confused with U): FALSE."""
    U, V = _pair(s)
    a, b = _bracket_parts(s, U, V)
    conf = s.d(lambda u: u.bracket(lambda h: h.tr(U.T @ h.X), _G), {"X": U})
    return {"w": _bracket_skip(s, U, V) - b - conf}


# -- a Dirac flow made in u's function of a Hamiltonian reading X_t (linear in X_t), K = tr(PᵀAX)
def _K(w):
    return w.tr(w.P.T @ w.A @ w.X)


def _dirac_skip(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.d(_K, u.dirac_flow(lambda h: h.tr(t.X.T @ h.X))), {"X": V}), {"X": U})


def _dirac_parts(s, U, V):
    X0 = s.X
    a = s.d(lambda u: u.d(_K, u.dirac_flow(lambda h: h.tr(U.T @ h.X))), {"X": V})
    b = s.d(lambda t: t.d(lambda u: u.d(_K, u.dirac_flow(lambda h: h.tr(X0.T @ h.X))), {"X": V}), {"X": U})
    return a, b


@claim("s77l-dirac-skip-true", kind="id", sizes=SZ)
def dirac_skip_true(s):
    """= d_V[dK(flow of H_U)] + d_U d_V[dK(flow of H_X₀)]: TRUE."""
    U, V = _pair(s)
    a, b = _dirac_parts(s, U, V)
    return {"w": _dirac_skip(s, U, V) - a - b}


@claim("s77l-dirac-skip-false", kind="id", sizes=SZ)
def dirac_skip_false(s):
    """= d_U d_V[dK(flow of H_X₀)] + d_U[dK(flow of H_U)] (V confused with U): FALSE."""
    U, V = _pair(s)
    a, b = _dirac_parts(s, U, V)
    conf = s.d(lambda u: u.d(_K, u.dirac_flow(lambda h: h.tr(U.T @ h.X))), {"X": U})
    return {"w": _dirac_skip(s, U, V) - b - conf}


# -- along P: d_U [t -> d_V [u -> d_{u.P} [w -> tr(P_tᵀP_w)]]] (flows on P) = tr(UᵀV)
def _alongP(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: w.tr(t.P.T @ w.P), {"P": u.P}), {"P": V}), {"P": U})


@claim("s77l-skip-p-true", kind="id", sizes=SZ)
def skip_p_true(s):
    """tr(UᵀV): TRUE."""
    U, V = _pair(s)
    return {"w": _alongP(s, U, V) - s.tr(U.T @ V)}


@claim("s77l-skip-p-false", kind="id", sizes=SZ)
def skip_p_false(s):
    """0: FALSE."""
    U, V = _pair(s)
    return {"w": _alongP(s, U, V)}


# -- a value of a sibling scene (kept in a list) used as a matrix factor in another derivative: refused
@claim("s77l-sibling-factor", kind="id", sizes=SZ)
def sibling_factor(s):
    """kept[0] = X + ε₁U of a finished derivative, used as a factor in a derivative along V: must be refused
    (no verdict); a confusion of the two ε would give tr(UᵀV) + tr(XᵀV) instead of tr(XᵀV) (residual 0 here
    only under the confusion)."""
    U, V = _pair(s)
    kept = []

    def grab(t):
        kept.append(t.X)
        return t.tr(t.X.T @ t.X)
    s.d(grab, {"X": U})
    got = s.d(lambda t: t.tr(kept[0].T @ t.X), {"X": V})
    return {"w": got - s.tr(U.T @ V) - s.tr(s.X.T @ V)}
