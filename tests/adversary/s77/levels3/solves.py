"""s77 levels3: numbers of a HIGHER level (w's, two dual levels) handed to methods of the enclosing scene t
(one level) that solve or invert: t.mat(...).inv(), t.scalar_matrix(...).inv(), t.resolvent, t.killing;
G = d_U[t -> d_V[w -> body(t, w)]], c_w = |X_w|².  -true: TRUE, -false: FALSE."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)
R2 = admissible(n_max=3, r_min=2, r_max=2, condition="r = 2")


def _nr(s):
    return s.fresh("n", "r")


def _two(s, U, V, body):
    return s.d(lambda t: t.d(lambda w: body(t, w), {"X": V}), {"X": U})


def _c(w):
    return w.tr(w.X.T @ w.X)


def _inv_truth(s, U, V, k):
    # d_U d_V [k/|X|²] = -2tr(UᵀV)k/|X|⁴ + 8tr(XᵀU)tr(XᵀV)k/|X|⁶
    n2 = s.tr(s.X.T @ s.X)
    return -(s.tr(U.T @ V) * 2 * k) / (n2 * n2) + s.tr(s.X.T @ U) * 8 * s.tr(s.X.T @ V) * k / (n2 * n2 * n2)


@claim("s77n-tmat-inv-true", kind="id", sizes=R2)
def tmat_inv_true(s):
    """body = tr(K·t.mat(c_w I)⁻¹) = tr(K)/c_w: TRUE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: w.tr(K @ t.mat([[_c(w), 0], [0, _c(w)]], ("r", "r")).inv()))
    return {"w": got - _inv_truth(s, U, V, s.tr(K))}


@claim("s77n-tmat-inv-false", kind="id", sizes=R2)
def tmat_inv_false(s):
    """the same with U for V: FALSE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: w.tr(K @ t.mat([[_c(w), 0], [0, _c(w)]], ("r", "r")).inv()))
    return {"w": got - _inv_truth(s, U, U, s.tr(K))}


@claim("s77n-tsmat-inv-true", kind="id", sizes=SZ)
def tsmat_inv_true(s):
    """body = tr(K·t.scalar_matrix(c_w, r)⁻¹): TRUE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: w.tr(K @ t.scalar_matrix(_c(w), t.r, "r").inv()))
    return {"w": got - _inv_truth(s, U, V, s.tr(K))}


@claim("s77n-tsmat-inv-false", kind="id", sizes=SZ)
def tsmat_inv_false(s):
    """the same = 0: FALSE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: w.tr(K @ t.scalar_matrix(_c(w), t.r, "r").inv()))
    return {"w": got}


# -- a mixed matrix: M = I + X_tᵀX_w (t's and w's entries), inverted in w: d_V d_U of tr(K M⁻¹) at X_t = X_w:
#    checked against the same expression written on one level (h = the plain function of two points)
def _mixed(t, w, K):
    return w.tr(K @ (t.Ir + t.X.T @ w.X).inv())


def _mixed_truth(s, U, V, K):
    # f(A, B) = tr(K (I + AᵀB)⁻¹), A = X + εU, B = X + εU + δV; ∂δ∂ε f at X:
    X, I = s.X, s.Ir
    Mi = (I + X.T @ X).inv()
    dB = lambda D: -(Mi @ (X.T @ D) @ Mi)  # noqa: E731
    # ∂δ: -tr(K Mi XᵀV Mi); ∂ε of that with A and B both moving along U:
    dM_U = U.T @ X + X.T @ U
    dMi_U = -(Mi @ dM_U @ Mi)
    return -s.tr(K @ (dMi_U @ X.T @ V @ Mi + Mi @ U.T @ V @ Mi + Mi @ X.T @ V @ dMi_U)) + 0 * s.tr(K @ dB(V))


@claim("s77n-mixed-inv-true", kind="id", sizes=SZ)
def mixed_inv_true(s):
    """tr(K(I + X_tᵀX_w)⁻¹): -tr(K(dMi XᵀV Mi + Mi UᵀV Mi + Mi XᵀV dMi)): TRUE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    return {"w": _two(s, U, V, lambda t, w: _mixed(t, w, K)) - _mixed_truth(s, U, V, K)}


@claim("s77n-mixed-inv-false", kind="id", sizes=SZ)
def mixed_inv_false(s):
    """the same with U for V: FALSE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    return {"w": _two(s, U, V, lambda t, w: _mixed(t, w, K)) - _mixed_truth(s, U, U, K)}


# -- the same mixed matrix inverted by t's scene method (t.mat of its entries is not needed: Mat.inv of a
#    matrix whose factors are t's, built in t, times w's): tr(K (I + X_tᵀX_t)⁻¹ X_tᵀX_w), three levels with
#    the flow read from t: d_U[t -> d_V[u -> d_{X_t}[w -> ...]]] = d_U d_V [tr(K Mi(X_t) X_tᵀX_t)]... kept simple:
#    g(t, w) = tr(K (I + X_tᵀX_t)⁻¹ X_tᵀ X_w); d_V: tr(K Mi(X_t) X_tᵀV); d_U: tr(K(dMi_U XᵀV + Mi UᵀV))
def _t_inv(s, U, V, K):
    return _two(s, U, V, lambda t, w: w.tr(K @ (t.Ir + t.X.T @ t.X).inv() @ t.X.T @ w.X))


@claim("s77n-tinv-true", kind="id", sizes=SZ)
def tinv_true(s):
    """tr(K(dMi_U XᵀV + Mi UᵀV)): TRUE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    X = s.X
    Mi = (s.Ir + X.T @ X).inv()
    dMi = -(Mi @ (U.T @ X + X.T @ U) @ Mi)
    return {"w": _t_inv(s, U, V, K) - s.tr(K @ (dMi @ X.T @ V + Mi @ U.T @ V))}


@claim("s77n-tinv-false", kind="id", sizes=SZ)
def tinv_false(s):
    """tr(K Mi UᵀV) (dMi dropped): FALSE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    X = s.X
    Mi = (s.Ir + X.T @ X).inv()
    return {"w": _t_inv(s, U, V, K) - s.tr(K @ (Mi @ U.T @ V))}


# -- t.resolvent(λ + c_w) (levels2 crashed under exact) and t.tr_product(w-matrices)
def _res_truth(s, U, V, B, C):
    R = s.resolvent(s.lam + s.tr(s.X.T @ s.X))
    return (-(s.tr(U.T @ V) * 2) * s.tr(B.T @ R @ R @ C)
            + s.tr(s.X.T @ U) * 8 * s.tr(s.X.T @ V) * s.tr(B.T @ R @ R @ R @ C))


@claim("s77n-tres-true", kind="id", sizes=SZ)
def tres_true(s):
    """w.tr(Bᵀ t.resolvent(λ + c_w) C): TRUE."""
    U, V, B, C = _nr(s), _nr(s), s.fresh("n", "n"), s.fresh("n", "n")
    got = _two(s, U, V, lambda t, w: w.tr(B.T @ t.resolvent(t.lam + _c(w)) @ C))
    return {"w": got - _res_truth(s, U, V, B, C)}


@claim("s77n-tres-false", kind="id", sizes=SZ)
def tres_false(s):
    """the same with U for V: FALSE."""
    U, V, B, C = _nr(s), _nr(s), s.fresh("n", "n"), s.fresh("n", "n")
    got = _two(s, U, V, lambda t, w: w.tr(B.T @ t.resolvent(t.lam + _c(w)) @ C))
    return {"w": got - _res_truth(s, U, U, B, C)}


@claim("s77n-tkilling-true", kind="id", sizes=SZ)
def tkilling_true(s):
    """t.killing(X_wᵀX_w, K) -> -1/2 tr((VᵀU + UᵀV)K) (levels2 F3, after the fix): TRUE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: t.killing(w.X.T @ w.X, K))
    return {"w": got + s.tr((V.T @ U + U.T @ V) @ K) * s.q(1, 2)}


@claim("s77n-tkilling-false", kind="id", sizes=SZ)
def tkilling_false(s):
    """= 0: FALSE."""
    U, V, K = _nr(s), _nr(s), s.fresh("r", "r")
    return {"w": _two(s, U, V, lambda t, w: t.killing(w.X.T @ w.X, K))}
