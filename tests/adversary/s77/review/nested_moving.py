"""s77 review: nested derivatives along directions that move with the point.  Ambient derivatives (X, P free,
f(X + εV)); V, U, W constant n×r directions.  Ids ending in -true are TRUE, -false are FALSE (the docstring
says which term was dropped or changed).  The key identity for a moving inner direction v(x):
d_U[dF(x)(v(x))] = d²F(v, U) + dF(dv(U)), so the commutator d_U d_v F − d_v d_U F = dF(dv(U)) − dF(dU(v))."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def quad(u):
    return u.tr(u.X.T @ u.A @ u.X)


def cubic(u):
    """a non-homogeneous mix of X and P: tr(XᵀAX XᵀP) + tr(PᵀAP)."""
    return u.tr(u.X.T @ u.A @ u.X @ u.X.T @ u.P) + u.tr(u.P.T @ u.A @ u.P)


# -- commutator with a moving direction v = AX: d_U d_v F − d_v d_U F = dF(AU)
@claim("s77r-comm-ax-true", kind="id", sizes=SZ)
def comm_ax_true(s):
    U = s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.A @ t.X}), {"X": U})
    two = s.d(lambda t: t.d(cubic, {"X": U}), {"X": s.A @ s.X})
    return {"w": one - two - s.d(cubic, {"X": s.A @ U})}


@claim("s77r-comm-ax-false", kind="id", sizes=SZ)
def comm_ax_false(s):
    """FALSE: the two orders taken to agree (they differ by dF(AU))."""
    U = s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.A @ t.X}), {"X": U})
    two = s.d(lambda t: t.d(cubic, {"X": U}), {"X": s.A @ s.X})
    return {"w": one - two}


# -- a direction with both components, v = (P, X) (swap), U moving X, W moving P:
# d_(U,W)[dF(v)] − d_v[dF(U,W)] = dF(dv(U,W)) = dF(W, U)  (the swap of (U, W))
@claim("s77r-comm-swap-true", kind="id", sizes=SZ)
def comm_swap_true(s):
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.P, "P": t.X}), {"X": U, "P": W})
    two = s.d(lambda t: t.d(cubic, {"X": U, "P": W}), {"X": s.P, "P": s.X})
    return {"w": one - two - s.d(cubic, {"X": W, "P": U})}


@claim("s77r-comm-swap-false", kind="id", sizes=SZ)
def comm_swap_false(s):
    """FALSE: dF(U, W) in place of dF(W, U)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.P, "P": t.X}), {"X": U, "P": W})
    two = s.d(lambda t: t.d(cubic, {"X": U, "P": W}), {"X": s.P, "P": s.X})
    return {"w": one - two - s.d(cubic, {"X": U, "P": W})}


@claim("s77r-comm-swap-false2", kind="id", sizes=SZ)
def comm_swap_false2(s):
    """FALSE: the orders taken to agree."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.P, "P": t.X}), {"X": U, "P": W})
    two = s.d(lambda t: t.d(cubic, {"X": U, "P": W}), {"X": s.P, "P": s.X})
    return {"w": one - two}


# -- both directions move: v = AX (X), w = XWᵀ... on P: w = {"P": X Vᵀ X}; commutator:
# d_w d_v F − d_v d_w F = dF(dv(w)) − dF(dw(v)) = dF(A·0 ...)  v reads X only, w moves P only: dv(w) = 0;
# dw(v) = (AX)VᵀX + XVᵀ(AX) on P.  So d_w d_v F − d_v d_w F = −dF(P: AXVᵀX + XVᵀAX).
@claim("s77r-comm-both-true", kind="id", sizes=SZ)
def comm_both_true(s):
    V = s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.A @ t.X}), {"P": s.X @ V.T @ s.X})
    two = s.d(lambda t: t.d(cubic, {"P": t.X @ V.T @ t.X}), {"X": s.A @ s.X})
    X, A = s.X, s.A
    return {"w": one - two + s.d(cubic, {"P": A @ X @ V.T @ X + X @ V.T @ A @ X})}


@claim("s77r-comm-both-false", kind="id", sizes=SZ)
def comm_both_false(s):
    """FALSE: the sign of the bracket term flipped."""
    V = s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.A @ t.X}), {"P": s.X @ V.T @ s.X})
    two = s.d(lambda t: t.d(cubic, {"P": t.X @ V.T @ t.X}), {"X": s.A @ s.X})
    X, A = s.X, s.A
    return {"w": one - two - s.d(cubic, {"P": A @ X @ V.T @ X + X @ V.T @ A @ X})}


@claim("s77r-comm-both-false2", kind="id", sizes=SZ)
def comm_both_false2(s):
    """FALSE: half the bracket term (only AXVᵀX)."""
    V = s.fresh("n", "r")
    one = s.d(lambda t: t.d(cubic, {"X": t.A @ t.X}), {"P": s.X @ V.T @ s.X})
    two = s.d(lambda t: t.d(cubic, {"P": t.X @ V.T @ t.X}), {"X": s.A @ s.X})
    X, A = s.X, s.A
    return {"w": one - two + s.d(cubic, {"P": A @ X @ V.T @ X})}


# -- the direction's own derivative dropped: d_U[dF(v)] = d²F(v, U) + dF(dv(U)) with v = XXᵀP (moves X)
@claim("s77r-dv-term-true", kind="id", sizes=SZ)
def dv_term_true(s):
    U = s.fresh("n", "r")
    got = s.d(lambda t: t.d(cubic, {"X": t.X @ t.X.T @ t.P}), {"X": U})
    X, P = s.X, s.P
    v = X @ X.T @ P
    d2 = s.d(lambda t: t.d(cubic, {"X": v}), {"X": U})       # v frozen at the claim's point
    return {"w": got - d2 - s.d(cubic, {"X": U @ X.T @ P + X @ U.T @ P})}


@claim("s77r-dv-term-false", kind="id", sizes=SZ)
def dv_term_false(s):
    """FALSE: the dF(dv(U)) term dropped."""
    U = s.fresh("n", "r")
    got = s.d(lambda t: t.d(cubic, {"X": t.X @ t.X.T @ t.P}), {"X": U})
    v = s.X @ s.X.T @ s.P
    d2 = s.d(lambda t: t.d(cubic, {"X": v}), {"X": U})
    return {"w": got - d2}


@claim("s77r-dv-term-false2", kind="id", sizes=SZ)
def dv_term_false2(s):
    """FALSE: only half of dv(U) (U XᵀP, without X UᵀP)."""
    U = s.fresh("n", "r")
    got = s.d(lambda t: t.d(cubic, {"X": t.X @ t.X.T @ t.P}), {"X": U})
    X, P = s.X, s.P
    v = X @ X.T @ P
    d2 = s.d(lambda t: t.d(cubic, {"X": v}), {"X": U})
    return {"w": got - d2 - s.d(cubic, {"X": U @ X.T @ P})}


# -- inner direction read from the claim's scene (constant) vs the outer function's (moving)
@claim("s77r-dir-claim-vs-outer-true", kind="id", sizes=SZ)
def dir_claim_vs_outer_true(s):
    """d_U[dF(X_t)] − d_U[dF(X_s)] = dF(U) (Euler-free: F = cubic is not homogeneous)."""
    U = s.fresh("n", "r")
    moving = s.d(lambda t: t.d(cubic, {"X": t.X}), {"X": U})
    frozen = s.d(lambda t: t.d(cubic, {"X": s.X}), {"X": U})
    return {"w": moving - frozen - s.d(cubic, {"X": U})}


@claim("s77r-dir-claim-vs-outer-false", kind="id", sizes=SZ)
def dir_claim_vs_outer_false(s):
    """FALSE: the closure over s.X taken to move like t.X."""
    U = s.fresh("n", "r")
    moving = s.d(lambda t: t.d(cubic, {"X": t.X}), {"X": U})
    frozen = s.d(lambda t: t.d(cubic, {"X": s.X}), {"X": U})
    return {"w": moving - frozen}


# -- the direction read inside the inner function (a value of the outer point, constant for the inner one)
@claim("s77r-dir-read-inside-true", kind="id", sizes=SZ)
def dir_read_inside_true(s):
    """inner: u ↦ tr(Xᵤᵀ D) along D = A X_t: tr(DᵀD) = tr(XᵀA²X); outer along U: 2 tr(UᵀA²X)."""
    U = s.fresh("n", "r")

    def inner(t):
        D = t.A @ t.X
        return t.d(lambda u: u.tr(u.X.T @ D), {"X": D})
    got = s.d(inner, {"X": U})
    return {"w": got - s.tr(U.T @ s.A @ s.A @ s.X) * 2}


@claim("s77r-dir-read-inside-false", kind="id", sizes=SZ)
def dir_read_inside_false(s):
    """FALSE: D read inside taken as constant for the outer derivative too (only tr(UᵀA²X))."""
    U = s.fresh("n", "r")

    def inner(t):
        D = t.A @ t.X
        return t.d(lambda u: u.tr(u.X.T @ D), {"X": D})
    got = s.d(inner, {"X": U})
    return {"w": got - s.tr(U.T @ s.A @ s.A @ s.X)}


# -- the inner direction built from a value the inner function also returns (values mixed with the direction)
@claim("s77r-dir-mixed-value-true", kind="id", sizes=SZ)
def dir_mixed_value_true(s):
    """G(t) = d_{v}[tr(XᵀX)] + tr(vᵀv), v = Pᵗ... v = t.P: 2tr(PᵀX) + tr(PᵀP); along {P: W}: 2tr(WᵀX) + 2tr(WᵀP)."""
    W = s.fresh("n", "r")

    def inner(t):
        v = t.P
        return t.d(lambda u: u.tr(u.X.T @ u.X), {"X": v}) + t.tr(v.T @ v)
    got = s.d(inner, {"P": W})
    return {"w": got - s.tr(W.T @ s.X) * 2 - s.tr(W.T @ s.P) * 2}


@claim("s77r-dir-mixed-value-false", kind="id", sizes=SZ)
def dir_mixed_value_false(s):
    """FALSE: the inner derivative's motion through its direction dropped (2tr(WᵀX))."""
    W = s.fresh("n", "r")

    def inner(t):
        v = t.P
        return t.d(lambda u: u.tr(u.X.T @ u.X), {"X": v}) + t.tr(v.T @ v)
    got = s.d(inner, {"P": W})
    return {"w": got - s.tr(W.T @ s.P) * 2}


# -- inner direction in P built from X: {"P": X W}... (X Wᵀ X shape n×r); F = tr(PᵀAP): dF = 2tr(PᵀA XWᵀX)
# outer along {"X": U}: 2tr(PᵀA(UWᵀX + XWᵀU))
@claim("s77r-p-from-x-true", kind="id", sizes=SZ)
def p_from_x_true(s):
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.P.T @ u.A @ u.P), {"P": t.X @ W.T @ t.X}), {"X": U})
    X, P, A = s.X, s.P, s.A
    return {"w": got - s.tr(P.T @ A @ (U @ W.T @ X + X @ W.T @ U)) * 2}


@claim("s77r-p-from-x-false", kind="id", sizes=SZ)
def p_from_x_false(s):
    """FALSE: the product rule on XWᵀX missing XWᵀU."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.P.T @ u.A @ u.P), {"P": t.X @ W.T @ t.X}), {"X": U})
    X, P, A = s.X, s.P, s.A
    return {"w": got - s.tr(P.T @ A @ (U @ W.T @ X)) * 2}
