"""s77 levels3: the second point (Y, Q) moved at different levels, the complex scene (Zc) with nested
derivatives, four levels, a derivative on an enclosing scene along an inner scene's flow, canonical brackets
at an inner level from an outer level's Hamiltonian, Rank of nested values.  -true: TRUE, -false: FALSE."""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=3)


def _nr(s):
    return s.fresh("n", "r")


# -- d_U(X)[t -> d_V(Y)[u -> d_W(Q)[w -> tr(X_tᵀY_u)tr(Y_uᵀQ_w)]]] = tr(UᵀV)tr(YᵀW) + tr(UᵀY)tr(VᵀW)
def _yq(s, U, V, W):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: w.tr(t.X.T @ u.Y) * w.tr(u.Y.T @ w.Q), {"Q": W}),
                             {"Y": V}), {"X": U})


@claim("s77n-yq-true", kind="id", sizes=SZ)
def yq_true(s):
    """tr(UᵀV)tr(YᵀW) + tr(UᵀY)tr(VᵀW): TRUE."""
    U, V, W = _nr(s), _nr(s), _nr(s)
    return {"w": _yq(s, U, V, W) - s.tr(U.T @ V) * s.tr(s.Y.T @ W) - s.tr(U.T @ s.Y) * s.tr(V.T @ W)}


@claim("s77n-yq-false", kind="id", sizes=SZ)
def yq_false(s):
    """tr(UᵀV)tr(YᵀW): FALSE."""
    U, V, W = _nr(s), _nr(s), _nr(s)
    return {"w": _yq(s, U, V, W) - s.tr(U.T @ V) * s.tr(s.Y.T @ W)}


# -- Y moved at t and again at u: d_U(Y)[t -> d_V(Y)[u -> tr(Y_tᵀ Y_u)·tr(Q_uᵀQ_u)]] = tr(UᵀV)|Q|²
def _yy(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.tr(t.Y.T @ u.Y) * u.tr(u.Q.T @ u.Q), {"Y": V}), {"Y": U})


@claim("s77n-yy-true", kind="id", sizes=SZ)
def yy_true(s):
    """tr(UᵀV)|Q|²: TRUE."""
    U, V = _nr(s), _nr(s)
    return {"w": _yy(s, U, V) - s.tr(U.T @ V) * s.tr(s.Q.T @ s.Q)}


@claim("s77n-yy-false", kind="id", sizes=SZ)
def yy_false(s):
    """tr(UᵀU)|Q|²: FALSE."""
    U, V = _nr(s), _nr(s)
    return {"w": _yy(s, U, V) - s.tr(U.T @ U) * s.tr(s.Q.T @ s.Q)}


# -- complex: d_W1(Zc)[t -> d_W2(Zc)[u -> tr(conj(Z_t)ᵀZ_u)]] = tr(conj(W1)ᵀW2)
def _cx(s, W1, W2):
    return s.d(lambda t: t.d(lambda u: u.tr(u.conj(t.Zc).T @ u.Zc), {"Zc": W2}), {"Zc": W1})


def _ws(s):
    return s.realify(_nr(s), _nr(s)), s.realify(_nr(s), _nr(s))


@claim("s77n-cx-true", kind="id", sizes=SZ)
def cx_true(s):
    """tr(conj(W1)ᵀW2): TRUE."""
    W1, W2 = _ws(s)
    return {"w": _cx(s, W1, W2) - s.tr(s.conj(W1).T @ W2)}


@claim("s77n-cx-false", kind="id", sizes=SZ)
def cx_false(s):
    """tr(conj(W1)ᵀW1): FALSE."""
    W1, W2 = _ws(s)
    return {"w": _cx(s, W1, W2) - s.tr(s.conj(W1).T @ W1)}


# -- complex, three levels, the innermost flow read from the outermost scene:
#    d_W1[t -> d_W2[u -> d_{Z_t}[w -> tr(Z_wᵀZ_w)]]] = d_W1 d_W2 [2tr(Z_tᵀZ_u)] = 2tr(W1ᵀW2)
def _cx3(s, W1, W2):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: w.tr(w.Zc.T @ w.Zc), {"Zc": t.Zc}), {"Zc": W2}),
               {"Zc": W1})


@claim("s77n-cx3-true", kind="id", sizes=SZ)
def cx3_true(s):
    """2tr(W1ᵀW2): TRUE."""
    W1, W2 = _ws(s)
    return {"w": _cx3(s, W1, W2) - s.tr(W1.T @ W2) * 2}


@claim("s77n-cx3-false", kind="id", sizes=SZ)
def cx3_false(s):
    """2tr(W1ᵀW1): FALSE."""
    W1, W2 = _ws(s)
    return {"w": _cx3(s, W1, W2) - s.tr(W1.T @ W1) * 2}


# -- four levels: d_U[t -> d_V[u -> d_C[w -> d_D[z -> tr(X_tᵀX_u X_wᵀX_z)]]]] = tr(UᵀV CᵀD)
def _four(s, U, V, C, D):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: w.d(
        lambda z: z.tr(t.X.T @ u.X @ w.X.T @ z.X), {"X": D}), {"X": C}), {"X": V}), {"X": U})


@claim("s77n-four-true", kind="id", sizes=SZ)
def four_true(s):
    """tr(UᵀVCᵀD): TRUE."""
    U, V, C, D = _nr(s), _nr(s), _nr(s), _nr(s)
    return {"w": _four(s, U, V, C, D) - s.tr(U.T @ V @ C.T @ D)}


@claim("s77n-four-false", kind="id", sizes=SZ)
def four_false(s):
    """tr(UᵀUCᵀD): FALSE."""
    U, V, C, D = _nr(s), _nr(s), _nr(s), _nr(s)
    return {"w": _four(s, U, V, C, D) - s.tr(U.T @ U @ C.T @ D)}


# -- four levels, scalars of every level multiplied, innermost flow from t:
#    d_U[t -> d_V[u -> d_C[w -> d_{X_t}[z -> tr(X_zᵀX_z)·tr(X_uᵀX_w)]]]]
#    z: 2tr(X_wᵀX_t)tr(X_uᵀX_w) ... computed: = 2[tr(UᵀC)tr(XᵀV)+tr(XᵀC)tr(UᵀV) ... ] see truth below
def _four_s(s, U, V, C):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: w.d(
        lambda z: z.tr(z.X.T @ z.X) * z.tr(u.X.T @ w.X), {"X": t.X}), {"X": C}), {"X": V}), {"X": U})


def _four_s_truth(s, U, V, C):
    # f = 2tr(X_wᵀX_t)tr(X_uᵀX_w); X_w = X_u + ε₃C, X_u = X_t + ε₂V, X_t = X + ε₁U
    # d_C: 2tr(CᵀX_t)tr(X_uᵀX_u) + 2tr(X_uᵀX_t)tr(X_uᵀC)
    # d_V: 2tr(CᵀX_t)2tr(X_tᵀV) + 2tr(VᵀX_t)tr(X_tᵀC) + 2tr(X_tᵀX_t)tr(VᵀC)
    # d_U: 4tr(CᵀU)tr(XᵀV) + 4tr(CᵀX)tr(UᵀV) + 2tr(VᵀU)tr(XᵀC) + 2tr(VᵀX)tr(UᵀC) + 4tr(XᵀU)tr(VᵀC)
    X = s.X
    return (s.tr(C.T @ U) * 6 * s.tr(X.T @ V) + s.tr(C.T @ X) * 6 * s.tr(U.T @ V)
            + s.tr(X.T @ U) * 4 * s.tr(V.T @ C))


@claim("s77n-four-s-true", kind="id", sizes=SZ)
def four_s_true(s):
    """6tr(CᵀU)tr(XᵀV) + 6tr(CᵀX)tr(UᵀV) + 4tr(XᵀU)tr(VᵀC): TRUE."""
    U, V, C = _nr(s), _nr(s), _nr(s)
    return {"w": _four_s(s, U, V, C) - _four_s_truth(s, U, V, C)}


@claim("s77n-four-s-false", kind="id", sizes=SZ)
def four_s_false(s):
    """the same with V for U: FALSE."""
    U, V, C = _nr(s), _nr(s), _nr(s)
    return {"w": _four_s(s, U, V, C) - _four_s_truth(s, V, V, C)}


# -- t.d inside u along u's flow: d_U[t -> d_V[u -> t.d(k -> |X_k|², {"X": X_u})]] = 2tr(UᵀV)
def _enc(s, U, V):
    return s.d(lambda t: t.d(lambda u: t.d(lambda k: k.tr(k.X.T @ k.X), {"X": u.X}), {"X": V}), {"X": U})


@claim("s77n-enclosing-d-true", kind="id", sizes=SZ)
def enclosing_d_true(s):
    """2tr(UᵀV): TRUE."""
    U, V = _nr(s), _nr(s)
    return {"w": _enc(s, U, V) - s.tr(U.T @ V) * 2}


@claim("s77n-enclosing-d-false", kind="id", sizes=SZ)
def enclosing_d_false(s):
    """2tr(UᵀU): FALSE."""
    U, V = _nr(s), _nr(s)
    return {"w": _enc(s, U, V) - s.tr(U.T @ U) * 2}


# -- canonical bracket at u of an outer Hamiltonian H_t(h) = tr(X_tᵀP_h) with G(h) = |X_h|²:
#    {H_t, G} = tr(H_Xᵀ G_P) - tr(H_Pᵀ G_X) = -2tr(X_tᵀX_u); d_V d_U: -2tr(UᵀV)
def _cb(s, U, V, flip=False):
    def body(t, u):
        H = lambda h: h.tr(t.X.T @ h.P)  # noqa: E731
        G = lambda h: h.tr(h.X.T @ h.X)  # noqa: E731
        return u.canonical_bracket(G, H) if flip else u.canonical_bracket(H, G)
    return s.d(lambda t: t.d(lambda u: body(t, u), {"X": V}), {"X": U})


@claim("s77n-cbracket-true", kind="id", sizes=SZ)
def cbracket_true(s):
    """-2tr(UᵀV) (and the flipped bracket +2tr(UᵀV)): TRUE."""
    U, V = _nr(s), _nr(s)
    return {"w": _cb(s, U, V) + s.tr(U.T @ V) * 2, "flip": _cb(s, U, V, True) - s.tr(U.T @ V) * 2}


@claim("s77n-cbracket-false", kind="id", sizes=SZ)
def cbracket_false(s):
    """-2tr(UᵀU): FALSE."""
    U, V = _nr(s), _nr(s)
    return {"w": _cb(s, U, V) + s.tr(U.T @ U) * 2}


# -- Rank of a 2x2 matrix of nested values: g(U, V) = d_U[t -> d_V[u -> d_{X_t}[w -> |X_w|²]]] = 2tr(UᵀV);
#    M = [[g(U,V), g(U,U)], [g(V,V), g(V,U)]]: det = 4(tr(UᵀV)² - |U|²|V|²) ≠ 0 generically (r n > 1)
def _g(s, U, V):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: w.tr(w.X.T @ w.X), {"X": t.X}), {"X": V}), {"X": U})


def _m(s):
    U, V = _nr(s), _nr(s)
    return s.mat([[_g(s, U, V), _g(s, U, U)], [_g(s, V, V), _g(s, V, U)]])


@claim("s77n-rank-true", kind="dim", sizes=admissible(n_max=3, n_min=2))
def rank_true(s):
    """generic rank 2: TRUE (n ≥ 2)."""
    return {"rank": Rank(_m(s), 2)}


@claim("s77n-rank-false", kind="dim", sizes=admissible(n_max=3, n_min=2))
def rank_false(s):
    """generic rank 1 (what V-confused-with-U gives): FALSE."""
    return {"rank": Rank(_m(s), 1)}
