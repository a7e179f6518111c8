"""s77 levels2: a method of an ENCLOSING function's scene t (one dual level) called inside w (two dual levels)
with numbers of w's scene, G = d_U [ t -> d_V [ w -> body(t, w) ] ].  The node is w's (it reads w), so the
evaluator's lift does not apply: the method builds a matrix over t's field from w's numbers.
-true: TRUE (by hand, docstrings); -false: FALSE."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _two(s, U, V, body):
    return s.d(lambda t: t.d(lambda w: body(t, w), {"X": V}), {"X": U})


def _pair(s):
    return s.fresh("n", "r"), s.fresh("n", "r")


def _c(w):
    return w.tr(w.X.T @ w.X)


# -- t.scalar_matrix(c_w): c_w·I_n; body = tr(Bᵀ (c_w I) C) = c_w tr(BᵀC); G = 2tr(UᵀV)tr(BᵀC)
def _smat(B, C):
    return lambda t, w: w.tr(B.T @ t.scalar_matrix(_c(w), t.n, "n") @ C)


@claim("s77m-outer-smat-true", kind="id", sizes=SZ)
def outer_smat_true(s):
    """G = 2tr(UᵀV)tr(BᵀC): TRUE."""
    U, V = _pair(s)
    B, C = s.fresh("n", "n"), s.fresh("n", "n")
    return {"w": _two(s, U, V, _smat(B, C)) - s.tr(U.T @ V) * 2 * s.tr(B.T @ C)}


@claim("s77m-outer-smat-false", kind="id", sizes=SZ)
def outer_smat_false(s):
    """G = 2tr(UᵀU)tr(BᵀC) (V confused with U): FALSE."""
    U, V = _pair(s)
    B, C = s.fresh("n", "n"), s.fresh("n", "n")
    return {"w": _two(s, U, V, _smat(B, C)) - s.tr(U.T @ U) * 2 * s.tr(B.T @ C)}


@claim("s77m-outer-smat-false0", kind="id", sizes=SZ)
def outer_smat_false0(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B, C = s.fresh("n", "n"), s.fresh("n", "n")
    return {"w": _two(s, U, V, _smat(B, C))}


# -- t.resolvent(λ_t + c_w): R(μ), μ = λ + tr(XᵀX); G = -2tr(UᵀV)tr(BᵀR²C) + 8tr(XᵀU)tr(XᵀV)tr(BᵀR³C)
def _res(B, C):
    return lambda t, w: w.tr(B.T @ t.resolvent(t.lam + _c(w)) @ C)


def _res_truth(s, U, V, B, C):
    R = s.resolvent(s.lam + s.tr(s.X.T @ s.X))
    return (-(s.tr(U.T @ V) * 2) * s.tr(B.T @ R @ R @ C)
            + s.tr(s.X.T @ U) * 8 * s.tr(s.X.T @ V) * s.tr(B.T @ R @ R @ R @ C))


@claim("s77m-outer-res-true", kind="id", sizes=SZ)
def outer_res_true(s):
    """G = -2tr(UᵀV)tr(BᵀR²C) + 8tr(XᵀU)tr(XᵀV)tr(BᵀR³C): TRUE."""
    U, V = _pair(s)
    B, C = s.fresh("n", "n"), s.fresh("n", "n")
    return {"w": _two(s, U, V, _res(B, C)) - _res_truth(s, U, V, B, C)}


@claim("s77m-outer-res-false", kind="id", sizes=SZ)
def outer_res_false(s):
    """the same with U for V: FALSE."""
    U, V = _pair(s)
    B, C = s.fresh("n", "n"), s.fresh("n", "n")
    return {"w": _two(s, U, V, _res(B, C)) - _res_truth(s, U, U, B, C)}


# -- t.tr(M_w), t.killing(M_w, K): tr(X_wᵀX_w) -> 2tr(UᵀV); -1/2 tr(X_wᵀX_w K) -> -1/2 tr((VᵀU + UᵀV)K)
@claim("s77m-outer-tr-true", kind="id", sizes=SZ)
def outer_tr_true(s):
    """G = 2tr(UᵀV): TRUE."""
    U, V = _pair(s)
    return {"w": _two(s, U, V, lambda t, w: t.tr(w.X.T @ w.X)) - s.tr(U.T @ V) * 2}


@claim("s77m-outer-tr-false", kind="id", sizes=SZ)
def outer_tr_false(s):
    """G = 2tr(UᵀU): FALSE."""
    U, V = _pair(s)
    return {"w": _two(s, U, V, lambda t, w: t.tr(w.X.T @ w.X)) - s.tr(U.T @ U) * 2}


@claim("s77m-outer-killing-true", kind="id", sizes=SZ)
def outer_killing_true(s):
    """G = -1/2 tr((VᵀU + UᵀV)K): TRUE."""
    U, V = _pair(s)
    K = s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: t.killing(w.X.T @ w.X, K))
    return {"w": got + s.tr((V.T @ U + U.T @ V) @ K) * s.q(1, 2)}


@claim("s77m-outer-killing-false", kind="id", sizes=SZ)
def outer_killing_false(s):
    """G = -tr(UᵀUK): FALSE."""
    U, V = _pair(s)
    K = s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: t.killing(w.X.T @ w.X, K))
    return {"w": got + s.tr(U.T @ U @ K)}


# -- t.mat([[c_w, 0], [0, c_w]]) as an r x r factor: tr(K·c_w I_r) = c_w tr(K); G = 2tr(UᵀV)tr(K)
def _mat(K):
    return lambda t, w: w.tr(K @ t.mat([[_c(w), 0], [0, _c(w)]], ("r", "r")))


@claim("s77m-outer-mat-true", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2, condition="r = 2"))
def outer_mat_true(s):
    """G = 2tr(UᵀV)tr(K): TRUE (r = 2)."""
    U, V = _pair(s)
    K = s.fresh("r", "r")
    return {"w": _two(s, U, V, _mat(K)) - s.tr(U.T @ V) * 2 * s.tr(K)}


@claim("s77m-outer-mat-false", kind="id", sizes=admissible(n_max=3, r_min=2, r_max=2, condition="r = 2"))
def outer_mat_false(s):
    """G = 2tr(UᵀU)tr(K): FALSE."""
    U, V = _pair(s)
    K = s.fresh("r", "r")
    return {"w": _two(s, U, V, _mat(K)) - s.tr(U.T @ U) * 2 * s.tr(K)}


@claim("s77m-ctl-killing-w-true", kind="id", sizes=SZ)
def ctl_killing_w_true(s):
    """control: w.killing instead of t.killing, G = -1/2 tr((VᵀU + UᵀV)K): TRUE."""
    U, V = _pair(s)
    K = s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: w.killing(w.X.T @ w.X, K))
    return {"w": got + s.tr((V.T @ U + U.T @ V) @ K) * s.q(1, 2)}


@claim("s77m-outer-killing-false0", kind="id", sizes=SZ)
def outer_killing_false0(s):
    """G = 0: FALSE (what the exact method's symbolic chart computes for t.killing)."""
    U, V = _pair(s)
    K = s.fresh("r", "r")
    got = _two(s, U, V, lambda t, w: t.killing(w.X.T @ w.X, K))
    return {"w": got}
