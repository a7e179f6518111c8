"""s77 levels3: gradients of gradients, a gradient inside a derivative inside a gradient, two tapes meeting,
a Jacobian of a gradient inside a derivative (ambient gradients in X; truths by hand in the docstrings).
-true: TRUE, -false: FALSE."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _nr(s):
    return s.fresh("n", "r")


# -- d_U[t -> tr(Cᵀ ∇_X[h -> tr(Bᵀ ∇_X[k -> tr(X_tᵀX_k)tr(X_hᵀX_k)])])]
#    = 3tr(BᵀU)tr(CᵀX) + 3tr(BᵀX)tr(CᵀU) + 2tr(XᵀU)tr(CᵀB)
def _gg(s, U, B, C):
    def q(t):
        def h1(h):
            g = h.gradient(lambda k: k.tr(t.X.T @ k.X) * k.tr(h.X.T @ k.X))[0]
            return h.tr(B.T @ g)
        return t.tr(C.T @ t.gradient(h1)[0])
    return s.d(q, {"X": U})


@claim("s77n-gradgrad-true", kind="id", sizes=SZ)
def gradgrad_true(s):
    """3tr(BᵀU)tr(CᵀX) + 3tr(BᵀX)tr(CᵀU) + 2tr(XᵀU)tr(CᵀB): TRUE."""
    U, B, C = _nr(s), _nr(s), _nr(s)
    X = s.X
    want = (s.tr(B.T @ U) * 3 * s.tr(C.T @ X) + s.tr(B.T @ X) * 3 * s.tr(C.T @ U)
            + s.tr(X.T @ U) * 2 * s.tr(C.T @ B))
    return {"w": _gg(s, U, B, C) - want}


@claim("s77n-gradgrad-false", kind="id", sizes=SZ)
def gradgrad_false(s):
    """2tr(BᵀU)tr(CᵀX) + 2tr(BᵀX)tr(CᵀU) + 2tr(XᵀU)tr(CᵀB): FALSE."""
    U, B, C = _nr(s), _nr(s), _nr(s)
    X = s.X
    want = (s.tr(B.T @ U) * 2 * s.tr(C.T @ X) + s.tr(B.T @ X) * 2 * s.tr(C.T @ U)
            + s.tr(X.T @ U) * 2 * s.tr(C.T @ B))
    return {"w": _gg(s, U, B, C) - want}


# -- tr(Eᵀ ∇_X[h -> d_V[t -> tr(Cᵀ ∇_X[k -> tr(X_hᵀX_k)|X_k|²])]])
#    = 4tr(EᵀC)tr(XᵀV) + 4tr(CᵀX)tr(EᵀV) + 4tr(CᵀV)tr(EᵀX)
def _gdg(s, V, C, E):
    def H(h):
        def g(t):
            return t.tr(C.T @ t.gradient(lambda k: k.tr(h.X.T @ k.X) * k.tr(k.X.T @ k.X))[0])
        return h.d(g, {"X": V})
    return s.tr(E.T @ s.gradient(H)[0])


@claim("s77n-grad-d-grad-true", kind="id", sizes=SZ)
def grad_d_grad_true(s):
    """4tr(EᵀC)tr(XᵀV) + 4tr(CᵀX)tr(EᵀV) + 4tr(CᵀV)tr(EᵀX): TRUE."""
    V, C, E = _nr(s), _nr(s), _nr(s)
    X = s.X
    want = (s.tr(E.T @ C) * 4 * s.tr(X.T @ V) + s.tr(C.T @ X) * 4 * s.tr(E.T @ V)
            + s.tr(C.T @ V) * 4 * s.tr(E.T @ X))
    return {"w": _gdg(s, V, C, E) - want}


@claim("s77n-grad-d-grad-false", kind="id", sizes=SZ)
def grad_d_grad_false(s):
    """2tr(EᵀC)tr(XᵀV) + 4tr(CᵀX)tr(EᵀV) + 4tr(CᵀV)tr(EᵀX): FALSE."""
    V, C, E = _nr(s), _nr(s), _nr(s)
    X = s.X
    want = (s.tr(E.T @ C) * 2 * s.tr(X.T @ V) + s.tr(C.T @ X) * 4 * s.tr(E.T @ V)
            + s.tr(C.T @ V) * 4 * s.tr(E.T @ X))
    return {"w": _gdg(s, V, C, E) - want}


# -- two tapes on h: g1 = ∇_X[k1 -> |X|²] = 2X read in the Hamiltonian of a second gradient k2
#    H(h) = tr(Bᵀ∇_X[k2 -> tr(g1ᵀX_k2)|X_k2|²]) = 6|X|²tr(BᵀX); tr(Cᵀ∇H) = 12tr(BᵀX)tr(CᵀX) + 6|X|²tr(CᵀB)
def _tapes(s, B, C):
    def H(h):
        g1 = h.gradient(lambda k1: k1.tr(k1.X.T @ k1.X))[0]
        g2 = h.gradient(lambda k2: k2.tr(g1.T @ k2.X) * k2.tr(k2.X.T @ k2.X))[0]
        return h.tr(B.T @ g2)
    return s.tr(C.T @ s.gradient(H)[0])


@claim("s77n-tapes-true", kind="id", sizes=SZ)
def tapes_true(s):
    """12tr(BᵀX)tr(CᵀX) + 6|X|²tr(CᵀB): TRUE."""
    B, C = _nr(s), _nr(s)
    X = s.X
    want = s.tr(B.T @ X) * 12 * s.tr(C.T @ X) + s.tr(X.T @ X) * 6 * s.tr(C.T @ B)
    return {"w": _tapes(s, B, C) - want}


@claim("s77n-tapes-false", kind="id", sizes=SZ)
def tapes_false(s):
    """8tr(BᵀX)tr(CᵀX) + 6|X|²tr(CᵀB) (g1 taken as constant 2X in the outer gradient): FALSE."""
    B, C = _nr(s), _nr(s)
    X = s.X
    want = s.tr(B.T @ X) * 8 * s.tr(C.T @ X) + s.tr(X.T @ X) * 6 * s.tr(C.T @ B)
    return {"w": _tapes(s, B, C) - want}


# -- two tapes inside a derivative: d_U[t -> tr(Bᵀ∇_X[k2 -> tr(g1ᵀX_k2)|X_k2|²])], g1 = ∇_X[k1 -> tr(X_tᵀX_k1)²]
#    g1 = 2tr(X_tᵀX_t)X_t = 2|Y|²Y (Y = X_t); ∇ k2 at Y: g1|Y|² + 2tr(g1ᵀY)Y = 6|Y|⁴Y; value 6|Y|⁴tr(BᵀY)
#    d_U: 24|X|²tr(XᵀU)tr(BᵀX) + 6|X|⁴tr(BᵀU)
def _tapes_d(s, U, B):
    def q(t):
        g1 = t.gradient(lambda k1: k1.tr(t.X.T @ k1.X) * k1.tr(t.X.T @ k1.X))[0]
        g2 = t.gradient(lambda k2: k2.tr(g1.T @ k2.X) * k2.tr(k2.X.T @ k2.X))[0]
        return t.tr(B.T @ g2)
    return s.d(q, {"X": U})


@claim("s77n-tapes-d-true", kind="id", sizes=SZ)
def tapes_d_true(s):
    """24|X|²tr(XᵀU)tr(BᵀX) + 6|X|⁴tr(BᵀU): TRUE."""
    U, B = _nr(s), _nr(s)
    X = s.X
    n2 = s.tr(X.T @ X)
    want = n2 * 24 * s.tr(X.T @ U) * s.tr(B.T @ X) + n2 * n2 * 6 * s.tr(B.T @ U)
    return {"w": _tapes_d(s, U, B) - want}


@claim("s77n-tapes-d-false", kind="id", sizes=SZ)
def tapes_d_false(s):
    """12|X|²tr(XᵀU)tr(BᵀX) + 6|X|⁴tr(BᵀU): FALSE."""
    U, B = _nr(s), _nr(s)
    X = s.X
    n2 = s.tr(X.T @ X)
    want = n2 * 12 * s.tr(X.T @ U) * s.tr(B.T @ X) + n2 * n2 * 6 * s.tr(B.T @ U)
    return {"w": _tapes_d(s, U, B) - want}


# -- Hessian-like: d_U[t -> t.jacobian(h -> [∇_X[k -> tr(X_tᵀX_k)|X_k|²] at h])[0][0]]
#    J[(ab),(cd)] = 4Y_ab Y_cd + 2|Y|²δ (Y = X_t); J[0][0] = 4Y00² + 2|Y|²; d_U = 8X00U00 + 4tr(XᵀU)
def _hess(s, U, col=0):
    def q(t):
        J = t.jacobian(lambda h: [h.gradient(lambda k: k.tr(t.X.T @ k.X) * k.tr(k.X.T @ k.X))[0]])
        return J[0][col]
    return s.d(q, {"X": U})


@claim("s77n-hess-true", kind="id", sizes=SZ)
def hess_true(s):
    """8X00U00 + 4tr(XᵀU): TRUE."""
    U = _nr(s)
    return {"w": _hess(s, U) - s.X[0, 0] * 8 * U[0, 0] - s.tr(s.X.T @ U) * 4}


@claim("s77n-hess-false", kind="id", sizes=SZ)
def hess_false(s):
    """4tr(XᵀU): FALSE."""
    U = _nr(s)
    return {"w": _hess(s, U) - s.tr(s.X.T @ U) * 4}


@claim("s77n-hess-p-true", kind="id", sizes=SZ)
def hess_p_true(s):
    """the P-column of the same Jacobian (column nr) is 0, so is its derivative: TRUE."""
    U = _nr(s)
    return {"w": _hess(s, U, col=s.n * s.r)}


# -- a Jacobian of a function returning only t's number (constant in h) times h's: the Jacobian is
#    tr(X_tᵀX_t)·[d of h-part]; with F = [t.tr(X_tᵀX_t)] alone the Jacobian is 0.
@claim("s77n-jac-const-true", kind="id", sizes=SZ)
def jac_const_true(s):
    """d_U[t -> |X_t|²·J[0][0]] with J the Jacobian of h -> [|X_t|²]: 0: TRUE."""
    U = _nr(s)

    def q(t):
        c = t.tr(t.X.T @ t.X)
        return c * t.jacobian(lambda h: [c + t.tr(t.X.T @ t.X)])[0][0]
    return {"w": s.d(q, {"X": U})}


@claim("s77n-jac-const-false", kind="id", sizes=SZ)
def jac_const_false(s):
    """the same = 2tr(XᵀU): FALSE."""
    U = _nr(s)

    def q(t):
        c = t.tr(t.X.T @ t.X)
        return c * t.jacobian(lambda h: [c + t.tr(t.X.T @ t.X)])[0][0]
    return {"w": s.d(q, {"X": U}) - s.tr(s.X.T @ U) * 2}
