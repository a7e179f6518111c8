"""s58 batch 2: entry indices (commit 90b6f14: an int index outside a known axis length refused at trace
time).  Run each at --size 3,2 under exact, rational, modular, float, auto, and free."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _H(t):
    return t.tr(t.P.T @ t.A @ t.P)


# -- true claims that index near the edges --------------------------------------------------------
@claim("s58-neg-index-true", kind="id", sizes=SZ)
def neg_index_true(s):
    """X[-1, -1] = X[n-1, r-1] (TRUE)."""
    return {"x": s.X[-1, -1] - s.X[int(s.n) - 1, int(s.r) - 1]}


@claim("s58-neg-step-true", kind="id", sizes=SZ)
def neg_step_true(s):
    """tr(X[::-1,:]ᵀ X[::-1,:]) = r (TRUE: a row permutation)."""
    Y = s.X[::-1, :]
    return {"x": s.tr(Y.T @ Y) - s.tr(s.Ir)}


@claim("s58-odd-step-true", kind="id", sizes=SZ)
def odd_step_true(s):
    """X[::2,:] + X[1::2,:]-pieces: sum of squares over even and odd rows is r (TRUE)."""
    E, O = s.X[::2, :], s.X[1::2, :]
    return {"x": s.tr(E.T @ E) + s.tr(O.T @ O) - s.tr(s.Ir)}


@claim("s58-clamped-slice-true", kind="id", sizes=SZ)
def clamped_slice_true(s):
    """X[-100:100, :] is X (slices clamp) (TRUE)."""
    return {"x": s.X[-100:100, :] - s.X}


@claim("s58-empty-slice-true", kind="id", sizes=SZ)
def empty_slice_true(s):
    """an empty block: tr(X[7:, :]ᵀ X[7:, :]) = 0 (TRUE, 0×2 block)."""
    E = s.X[7:, :]
    return {"x": s.tr(E.T @ E)}


@claim("s58-empty-slice-false", kind="id", sizes=SZ)
def empty_slice_false(s):
    """tr(X[7:, :]ᵀ X[7:, :]) = 1 (FALSE: 0)."""
    E = s.X[7:, :]
    return {"x": s.tr(E.T @ E) - 1}


@claim("s58-empty-sq-matrix", kind="id", sizes=SZ)
def empty_sq_matrix(s):
    """X[7:,:] X[7:,:]ᵀ is 0×0; its trace 0 (TRUE)."""
    E = s.X[7:, :]
    return {"x": s.tr(E @ E.T)}


@claim("s58-empty-inv", kind="id", sizes=SZ)
def empty_inv(s):
    """(E Eᵀ)^{-1} of a 0×0 matrix, trace 0 (TRUE? empty inverse)."""
    E = s.X[7:, :]
    return {"x": s.tr((E @ E.T).inv())}


@claim("s58-empty-inv-false", kind="id", sizes=SZ)
def empty_inv_false(s):
    """1 + tr of the 0x0 inverse = 0 (FALSE)."""
    E = s.X[7:, :]
    return {"x": s.tr((E @ E.T).inv()) + 1}


# -- indices of derived matrices ----------------------------------------------------------------
@claim("s58-resolvent-entry-oob", kind="id", sizes=SZ)
def resolvent_entry_oob(s):
    """R(λ)[5, 0] at n = 3 (out of range: refused)."""
    return {"x": s.resolvent(s.lam)[5, 0]}


@claim("s58-resolvent-entry-neg-true", kind="id", sizes=SZ)
def resolvent_entry_neg_true(s):
    """R(λ)[-1, 0] - R(λ)[0, -1] = 0 (TRUE: R symmetric)."""
    R = s.resolvent(s.lam)
    return {"x": R[-1, 0] - R[0, -1]}


@claim("s58-inv-entry-oob", kind="id", sizes=SZ)
def inv_entry_oob(s):
    """(XᵀX)^{-1}[2, 0] at r = 2 (out of range)."""
    return {"x": (s.X.T @ s.X).inv()[2, 0]}


@claim("s58-flow-entry-oob", kind="id", sizes=SZ)
def flow_entry_oob(s):
    """dirac_flow(H).Xdot[3, 0] at n = 3 (out of range)."""
    return {"x": s.dirac_flow(_H).Xdot[3, 0]}


@claim("s58-flow-item-entry-oob", kind="id", sizes=SZ)
def flow_item_entry_oob(s):
    """dirac_flow(H)["X"][0, 2] at r = 2 (out of range)."""
    return {"x": s.dirac_flow(_H)["X"][0, 2]}


@claim("s58-multipliers-entry-oob", kind="id", sizes=SZ)
def multipliers_entry_oob(s):
    """dirac_flow(H).multipliers[...] far out of range (an engine value of unknown shape)."""
    m = s.dirac_flow(_H).multipliers
    return {"x": m[0][7, 7]}


@claim("s58-multipliers-item-oob", kind="id", sizes=SZ)
def multipliers_item_oob(s):
    """dirac_flow(H).multipliers[9] (an item out of range of an engine value)."""
    m = s.dirac_flow(_H).multipliers
    return {"x": m[9]}


@claim("s58-mat-any-oob", kind="id", sizes=SZ)
def mat_any_oob(s):
    """s.mat(engine value)[9, 9] (a matrix of unknown shape)."""
    m = s.dirac_flow(_H).multipliers
    return {"x": s.mat(m[0])[9, 9]}


@claim("s58-untyped-mat-oob", kind="id", sizes=SZ)
def untyped_mat_oob(s):
    """s.mat([[1,2],[3,4]])[2, 0] (out of range of a 2x2)."""
    M = s.mat([[1, 2], [3, 4]])
    return {"x": M[2, 0]}


@claim("s58-untyped-mat-neg-true", kind="id", sizes=SZ)
def untyped_mat_neg_true(s):
    """s.mat([[1,2],[3,4]])[-2, -1] = 2 (TRUE)."""
    M = s.mat([[1, 2], [3, 4]])
    return {"x": M[-2, -1] - 2}


@claim("s58-index-of-index-oob", kind="id", sizes=SZ)
def index_of_index_oob(s):
    """X[1:, :][2, 0] at n = 3 (the block has 2 rows: out of range)."""
    return {"x": s.X[1:, :][2, 0]}


@claim("s58-index-of-index-neg-true", kind="id", sizes=SZ)
def index_of_index_neg_true(s):
    """X[1:, :][-1, 0] = X[-1, 0] (TRUE)."""
    return {"x": s.X[1:, :][-1, 0] - s.X[-1, 0]}


@claim("s58-dim-index-oob", kind="id", sizes=SZ)
def dim_index_oob(s):
    """X[s.n, 0] (index n: out of range)."""
    return {"x": s.X[s.n, 0]}


@claim("s58-dim-neg-index-true", kind="id", sizes=SZ)
def dim_neg_index_true(s):
    """X[-s.n, 0] = X[0, 0] (TRUE)."""
    return {"x": s.X[-s.n, 0] - s.X[0, 0]}


@claim("s58-dim-slice-true", kind="id", sizes=SZ)
def dim_slice_true(s):
    """X[s.r:s.n, :] stacked under X[:s.r, :] is X: sum of squares r (TRUE)."""
    T, B = s.X[:s.r, :], s.X[s.r:s.n, :]
    return {"x": s.tr(T.T @ T) + s.tr(B.T @ B) - s.tr(s.Ir)}


@claim("s58-zc-entry-edge-true", kind="id", sizes=SZ)
def zc_entry_edge_true(s):
    """Zc (2n×2r) entry [2n-1, 2r-1] read twice (TRUE)."""
    return {"x": s.Zc[2 * int(s.n) - 1, 2 * int(s.r) - 1] - s.Zc[-1, -1]}


@claim("s58-zc-entry-oob", kind="id", sizes=SZ)
def zc_entry_oob(s):
    """Zc[2n, 0] (out of range)."""
    return {"x": s.Zc[2 * int(s.n), 0]}


@claim("s58-gradient-entry-oob", kind="id", sizes=SZ)
def gradient_entry_oob(s):
    """gradient(H)["X"][0, 5] (out of range)."""
    return {"x": s.gradient(_H)["X"][0, 5]}


@claim("s58-d-entry-oob", kind="id", sizes=SZ)
def d_entry_oob(s):
    """s.d(F, flow) of a matrix-valued F, entry out of range."""
    D = s.d(lambda t: t.X.T @ t.P, {"X": s.P, "P": s.zeros(s.n, s.r, ("n", "r"))})
    return {"x": D[4, 0]}


@claim("s58-inside-fn-oob", kind="id", sizes=SZ)
def inside_fn_oob(s):
    """a derivative of a function that reads an out-of-range entry."""
    return {"x": s.d(lambda t: t.X[5, 0], {"X": s.P})}


@claim("s58-step-zero", kind="id", sizes=SZ)
def step_zero(s):
    """X[::0, :] (a slice step 0)."""
    return {"x": s.X[::0, :]}


@claim("s58-realify-oob", kind="id", sizes=SZ)
def realify_oob(s):
    """realify(X, P) is 2n×2r: entry [2n, 0]."""
    return {"x": s.realify(s.X, s.P)[6, 0]}


@claim("s58-block-oob", kind="id", sizes=SZ)
def block_oob(s):
    """block([[X, P]]) is n×2r: entry [0, 4] out of range."""
    from stiefelsym import block
    return {"x": block([[s.X, s.P]])[0, 4]}


@claim("s58-matmul-any-oob", kind="id", sizes=SZ)
def matmul_any_oob(s):
    """an engine value times X, entry out of range."""
    m = s.dirac_flow(_H).multipliers
    return {"x": (s.X @ m[0])[8, 0]}
