"""s77 levels: a value of the OUTERMOST function's scene t read two functions down (in w, whose scene is the
tangent scene of u's, whose scene is the tangent scene of t's).  Pattern (M(t) an n x r value of t's scene):

    G = d_U [ t -> d_V [ u -> d_{u.X} [ w -> tr(M(t)ᵀ X_w) ] ] ]

innermost: tr(M(t)ᵀ X_u) (linear in X_w, flow u.X); middle along V: tr(M(t)ᵀ V); outer along U: tr(M'ᵀ V), M' the
derivative of M(t) along U.  -true: TRUE; -false: FALSE (the outer level's part dropped, G = 0, or as stated).
Each door: how M(t) enters w's computation."""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=3)


def _three(s, U, V, body):
    return s.d(lambda t: t.d(lambda u: u.d(lambda w: body(t, w), {"X": u.X}), {"X": V}), {"X": U})


def _pair(s):
    return s.fresh("n", "r"), s.fresh("n", "r")


# -- matrix factor: M = X_t (through a transpose), M' = U
def _mat(t, w):
    return w.tr(t.X.T @ w.X)


@claim("s77l-skip-matrix-true", kind="id", sizes=SZ)
def skip_matrix_true(s):
    """G = tr(UᵀV): TRUE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _mat) - s.tr(U.T @ V)}


@claim("s77l-skip-matrix-false", kind="id", sizes=SZ)
def skip_matrix_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _mat)}


# -- the product on the other side, no transpose of t's value: tr(X_wᵀ X_t)
def _mat_right(t, w):
    return w.tr(w.X.T @ t.X)


@claim("s77l-skip-matright-true", kind="id", sizes=SZ)
def skip_matright_true(s):
    """G = tr(UᵀV): TRUE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _mat_right) - s.tr(U.T @ V)}


@claim("s77l-skip-matright-false", kind="id", sizes=SZ)
def skip_matright_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _mat_right)}


# -- a sum of matrices of two levels: tr(Bᵀ(X_t + X_w)) = tr(BᵀX_t) + tr(BᵀX_w); innermost tr(BᵀX_u), G = 0
def _sum(t, w, B):
    return w.tr(B.T @ (t.X + w.X))


@claim("s77l-skip-sum-true", kind="id", sizes=SZ)
def skip_sum_true(s):
    """G = 0 (the X_t term is constant along the innermost flow; the rest does not see U): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _sum(t, w, B))}


@claim("s77l-skip-sum-false", kind="id", sizes=SZ)
def skip_sum_false(s):
    """G = tr(BᵀU): FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _sum(t, w, B)) - s.tr(B.T @ U)}


# -- scalar factor, scalar times scalar: c_t·tr(BᵀX_w), c_t = tr(X_tᵀX_t): M = c_t B, M' = 2tr(XᵀU) B
def _cscal(t, w, B):
    return t.tr(t.X.T @ t.X) * w.tr(B.T @ w.X)


@claim("s77l-skip-scalar-true", kind="id", sizes=SZ)
def skip_scalar_true(s):
    """G = 2tr(XᵀU)tr(BᵀV): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _cscal(t, w, B)) - s.tr(s.X.T @ U) * 2 * s.tr(B.T @ V)}


@claim("s77l-skip-scalar-false", kind="id", sizes=SZ)
def skip_scalar_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _cscal(t, w, B))}


# -- scalar factor times a matrix of w's scene: tr(Bᵀ (c_t X_w)), the product a scalar multiple of w's matrix
def _csmul(t, w, B):
    return w.tr(B.T @ (w.X * t.tr(t.X.T @ t.X)))


@claim("s77l-skip-smul-true", kind="id", sizes=SZ)
def skip_smul_true(s):
    """G = 2tr(XᵀU)tr(BᵀV): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _csmul(t, w, B)) - s.tr(s.X.T @ U) * 2 * s.tr(B.T @ V)}


@claim("s77l-skip-smul-false", kind="id", sizes=SZ)
def skip_smul_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _csmul(t, w, B))}


# -- scalar multiple of a claim constant made in t's scene: M = c_t B (a t-matrix)
def _csmul_t(t, w, B):
    return w.tr((B * t.tr(t.X.T @ t.X)).T @ w.X)


@claim("s77l-skip-smul-t-true", kind="id", sizes=SZ)
def skip_smul_t_true(s):
    """G = 2tr(XᵀU)tr(BᵀV): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _csmul_t(t, w, B)) - s.tr(s.X.T @ U) * 2 * s.tr(B.T @ V)}


@claim("s77l-skip-smul-t-false", kind="id", sizes=SZ)
def skip_smul_t_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _csmul_t(t, w, B))}


# -- an entry of a product of two levels: (X_tᵀX_w)[0, 0]; G = (UᵀV)[0, 0]
def _entry(t, w):
    return (t.X.T @ w.X)[0, 0]


@claim("s77l-skip-entry-true", kind="id", sizes=SZ)
def skip_entry_true(s):
    """G = (UᵀV)[0, 0]: TRUE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _entry) - (U.T @ V)[0, 0]}


@claim("s77l-skip-entry-false", kind="id", sizes=SZ)
def skip_entry_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _entry)}


# -- an inverse made in t's scene: M = B K⁻¹, K = I + X_tᵀX_t; M' = -B K⁻¹(UᵀX + XᵀU)K⁻¹
def _inv_t(t, w, B):
    K = t.Ir + t.X.T @ t.X
    return w.tr((B @ K.inv()).T @ w.X)


def _inv_truth(s, U, V, B):
    Ki = (s.Ir + s.X.T @ s.X).inv()
    return -s.tr((B @ Ki @ (U.T @ s.X + s.X.T @ U) @ Ki).T @ V)


@claim("s77l-skip-inv-true", kind="id", sizes=SZ)
def skip_inv_true(s):
    """G = -tr((BK⁻¹(UᵀX + XᵀU)K⁻¹)ᵀV), K = I + XᵀX: TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _inv_t(t, w, B)) - _inv_truth(s, U, V, B)}


@claim("s77l-skip-inv-false", kind="id", sizes=SZ)
def skip_inv_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _inv_t(t, w, B))}


# -- the inverse taken in w's scene, of t's matrix plus a w-matrix: (K_t + X_wᵀX_w - X_wᵀX_w)⁻¹ = K_t⁻¹
def _inv_w(t, w, B):
    K = t.Ir + t.X.T @ t.X + w.X.T @ w.X - w.X.T @ w.X
    return w.tr((B @ K.inv()).T @ w.X)


@claim("s77l-skip-inv-w-true", kind="id", sizes=SZ)
def skip_inv_w_true(s):
    """Same truth as s77l-skip-inv-true: TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _inv_w(t, w, B)) - _inv_truth(s, U, V, B)}


@claim("s77l-skip-inv-w-false", kind="id", sizes=SZ)
def skip_inv_w_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _inv_w(t, w, B))}


# -- a resolvent of w's scene at a number of t's: M = R(μ_t) B, μ_t = λ + tr(X_tᵀX_t); M' = -2tr(XᵀU) R² B
def _res_w(t, w, B):
    return w.tr((w.resolvent(t.lam + t.tr(t.X.T @ t.X)) @ B).T @ w.X)


def _res_t(t, w, B):
    return w.tr((t.resolvent(t.lam + t.tr(t.X.T @ t.X)) @ B).T @ w.X)


def _res_truth(s, U, V, B):
    R = s.resolvent(s.lam + s.tr(s.X.T @ s.X))
    return -(s.tr(s.X.T @ U) * 2) * s.tr((R @ R @ B).T @ V)


@claim("s77l-skip-res-w-true", kind="id", sizes=SZ)
def skip_res_w_true(s):
    """G = -2tr(XᵀU) tr((R²B)ᵀV), R = (μI - A)⁻¹, μ = λ + tr(XᵀX): TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _res_w(t, w, B)) - _res_truth(s, U, V, B)}


@claim("s77l-skip-res-w-false", kind="id", sizes=SZ)
def skip_res_w_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _res_w(t, w, B))}


@claim("s77l-skip-res-t-true", kind="id", sizes=SZ)
def skip_res_t_true(s):
    """The resolvent made in t's scene: the same truth: TRUE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _res_t(t, w, B)) - _res_truth(s, U, V, B)}


@claim("s77l-skip-res-t-false", kind="id", sizes=SZ)
def skip_res_t_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B = s.fresh("n", "r")
    return {"w": _three(s, U, V, lambda t, w: _res_t(t, w, B))}


# -- a block matrix whose first block is t's: tr([X_t; B]ᵀ[X_w; C]) = tr(X_tᵀX_w) + tr(BᵀC): G = tr(UᵀV)
def _blk(t, w, B, C):
    return w.tr(block([[t.X], [B]]).T @ block([[w.X], [C]]))


@claim("s77l-skip-block-true", kind="id", sizes=SZ)
def skip_block_true(s):
    """G = tr(UᵀV): TRUE."""
    U, V = _pair(s)
    B, C = _pair(s)
    return {"w": _three(s, U, V, lambda t, w: _blk(t, w, B, C)) - s.tr(U.T @ V)}


@claim("s77l-skip-block-false", kind="id", sizes=SZ)
def skip_block_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    B, C = _pair(s)
    return {"w": _three(s, U, V, lambda t, w: _blk(t, w, B, C))}


# -- a block matrix mixing the two levels in one block row: [X_t, X_w] (n x 2r), tr of its Gram's corner
def _blk_mixed(t, w):
    Z = block([[t.X, w.X]])
    return w.tr(Z.T @ Z @ block([[t.Ir * 0, t.Ir], [t.Ir * 0, t.Ir * 0]]))


@claim("s77l-skip-blockmix-true", kind="id", sizes=SZ)
def skip_blockmix_true(s):
    """tr(ZᵀZ E) with E = [[0, I], [0, 0]] is tr(X_wᵀX_t) (the (2,1) block of ZᵀZ): G = tr(UᵀV): TRUE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _blk_mixed) - s.tr(U.T @ V)}


@claim("s77l-skip-blockmix-false", kind="id", sizes=SZ)
def skip_blockmix_false(s):
    """G = 0: FALSE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _blk_mixed)}


# -- the innermost function returns t's number itself: its derivative along u.X is 0, G = 0
def _ret(t, w):
    return t.tr(t.X.T @ t.X)


@claim("s77l-skip-return-true", kind="id", sizes=SZ)
def skip_return_true(s):
    """G = 0: TRUE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _ret)}


@claim("s77l-skip-return-false", kind="id", sizes=SZ)
def skip_return_false(s):
    """G = 2tr(UᵀU)·… anything nonzero; stated: G = 2tr(UᵀU)... as tr(XᵀU)·2: FALSE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _ret) - s.tr(s.X.T @ U) * 2}


# -- the innermost function returns t's matrix: d of a constant matrix is 0; G (a trace of it) = 0
def _retm(t, w):
    return w.tr(t.X.T @ t.X) + w.tr(w.X.T @ w.X) * 0


@claim("s77l-skip-return-sum-true", kind="id", sizes=SZ)
def skip_return_sum_true(s):
    """G = 0: TRUE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _retm)}


@claim("s77l-skip-return-sum-false", kind="id", sizes=SZ)
def skip_return_sum_false(s):
    """G = 2tr(XᵀU): FALSE."""
    U, V = _pair(s)
    return {"w": _three(s, U, V, _retm) - s.tr(s.X.T @ U) * 2}
