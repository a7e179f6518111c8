"""s77 review: nested derivatives whose inner function returns containers, inner derivatives used twice,
discarded, multiplied, third and fourth derivatives, directions whose value is itself an inner derivative.
Ambient derivatives (f(X + εV)); U, V, W constant.  -true: TRUE, -false: FALSE (docstring: what changed)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def quad(u):
    return u.tr(u.X.T @ u.A @ u.X)


def cubic(u):
    return u.tr(u.X.T @ u.A @ u.X @ u.X.T @ u.P) + u.tr(u.P.T @ u.A @ u.P)


def G(u):
    """an n×r matrix function: X XᵀX."""
    return u.X @ u.X.T @ u.X


def dG(X, V):
    return V @ X.T @ X + X @ V.T @ X + X @ X.T @ V


def d2G(X, V, U):
    return V @ U.T @ X + V @ X.T @ U + U @ V.T @ X + X @ V.T @ U + U @ X.T @ V + X @ U.T @ V


# -- containers: nested lists/dicts, items of items, negative indices
@claim("s77r-cont-nested-true", kind="id", sizes=SZ)
def cont_nested_true(s):
    """inner returns {"a": [XᵀX, [G, tr(XᵀAX)]]}; item ["a"][1][-1] is d_V tr(XᵀAX) = 2tr(VᵀAX); outer: 2tr(VᵀAV)."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: {"a": [u.X.T @ u.X, [G(u), quad(u)]]}, {"X": V})["a"][1][-1], {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ V) * 2}


@claim("s77r-cont-nested-false", kind="id", sizes=SZ)
def cont_nested_false(s):
    """FALSE: half."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: {"a": [u.X.T @ u.X, [G(u), quad(u)]]}, {"X": V})["a"][1][-1], {"X": V})
    return {"w": got - s.tr(V.T @ s.A @ V)}


@claim("s77r-cont-matrix-item-true", kind="id", sizes=SZ)
def cont_matrix_item_true(s):
    """["a"][1][-2] is d_V G = dG(X, V); outer along U: d²G(V, U)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: {"a": [u.X.T @ u.X, [G(u), quad(u)]]}, {"X": V})["a"][1][-2], {"X": U})
    return {"w": got - d2G(s.X, V, U)}


@claim("s77r-cont-matrix-item-false", kind="id", sizes=SZ)
def cont_matrix_item_false(s):
    """FALSE: the item [-1] in place of [-2] (a wrong part)... here: d²G missing UXᵀV."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: {"a": [u.X.T @ u.X, [G(u), quad(u)]]}, {"X": V})["a"][1][-2], {"X": U})
    return {"w": got - d2G(s.X, V, U) + U @ s.X.T @ V}


@claim("s77r-cont-first-true", kind="id", sizes=SZ)
def cont_first_true(s):
    """["a"][0]: d_V(XᵀX) = VᵀX + XᵀV; outer along U: VᵀU + UᵀV."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: {"a": [u.X.T @ u.X, [G(u), quad(u)]]}, {"X": V})["a"][0], {"X": U})
    return {"w": got - V.T @ U - U.T @ V}


@claim("s77r-cont-first-false", kind="id", sizes=SZ)
def cont_first_false(s):
    """FALSE: 2UᵀV (asymmetric part wrong)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: {"a": [u.X.T @ u.X, [G(u), quad(u)]]}, {"X": V})["a"][0], {"X": U})
    return {"w": got - U.T @ V * 2}


@claim("s77r-cont-tuple-pair-true", kind="id", sizes=SZ)
def cont_tuple_pair_true(s):
    """outer returns a tuple of the inner's parts, combined: (a, b) = d_V(tr XᵀAX, tr XᵀX); d_U(a·b)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def mid(t):
        a, b = t.d(lambda u: (quad(u), u.tr(u.X.T @ u.X)), {"X": V})
        return a * b
    got = s.d(mid, {"X": U})
    X, A = s.X, s.A
    a, b = s.tr(V.T @ A @ X) * 2, s.tr(V.T @ X) * 2
    da, db = s.tr(V.T @ A @ U) * 2, s.tr(V.T @ U) * 2
    return {"w": got - da * b - a * db}


@claim("s77r-cont-tuple-pair-false", kind="id", sizes=SZ)
def cont_tuple_pair_false(s):
    """FALSE: parts swapped in one term (da·a)."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")

    def mid(t):
        a, b = t.d(lambda u: (quad(u), u.tr(u.X.T @ u.X)), {"X": V})
        return a * b
    got = s.d(mid, {"X": U})
    X, A = s.X, s.A
    a = s.tr(V.T @ A @ X) * 2
    da, db = s.tr(V.T @ A @ U) * 2, s.tr(V.T @ U) * 2
    return {"w": got - da * a - a * db}


# -- the same inner derivative used twice (a square), an inner derivative discarded
@claim("s77r-twice-square-true", kind="id", sizes=SZ)
def twice_square_true(s):
    """g = d_{AX} cubic (a moving direction); d_U(g·g) = 2 g d_U g, with d_U g written as its own nested claim."""
    U = s.fresh("n", "r")

    def g(t):
        return t.d(cubic, {"X": t.A @ t.X})
    got = s.d(lambda t: g(t) * g(t), {"X": U})
    return {"w": got - s.d(g, {"X": U}) * g(s) * 2}


@claim("s77r-twice-square-false", kind="id", sizes=SZ)
def twice_square_false(s):
    """FALSE: g d_U g (the factor 2 lost)."""
    U = s.fresh("n", "r")

    def g(t):
        return t.d(cubic, {"X": t.A @ t.X})
    got = s.d(lambda t: g(t) * g(t), {"X": U})
    return {"w": got - s.d(g, {"X": U}) * g(s)}


@claim("s77r-discarded-true", kind="id", sizes=SZ)
def discarded_true(s):
    """the inner derivative computed and thrown away: d_V tr(XᵀAX) = 2 tr(VᵀAX)."""
    V = s.fresh("n", "r")

    def mid(t):
        t.d(cubic, {"X": t.P})          # discarded on purpose
        return quad(t)
    return {"w": s.d(mid, {"X": V}) - s.tr(V.T @ s.A @ s.X) * 2}


@claim("s77r-discarded-false", kind="id", sizes=SZ)
def discarded_false(s):
    V = s.fresh("n", "r")

    def mid(t):
        t.d(cubic, {"X": t.P})          # discarded on purpose
        return quad(t)
    return {"w": s.d(mid, {"X": V}) - s.tr(V.T @ s.A @ s.X)}


# -- a product of two inner derivatives along different moving flows: Leibniz
@claim("s77r-product-two-true", kind="id", sizes=SZ)
def product_two_true(s):
    U = s.fresh("n", "r")

    def g(t):
        return t.d(cubic, {"X": t.A @ t.X})

    def h(t):
        return t.d(quad, {"X": t.P, "P": t.X})
    got = s.d(lambda t: g(t) * h(t), {"X": U})
    return {"w": got - s.d(g, {"X": U}) * h(s) - g(s) * s.d(h, {"X": U})}


@claim("s77r-product-two-false", kind="id", sizes=SZ)
def product_two_false(s):
    """FALSE: the second Leibniz term dropped."""
    U = s.fresh("n", "r")

    def g(t):
        return t.d(cubic, {"X": t.A @ t.X})

    def h(t):
        return t.d(quad, {"X": t.P, "P": t.X})
    got = s.d(lambda t: g(t) * h(t), {"X": U})
    return {"w": got - s.d(g, {"X": U}) * h(s)}


# -- third derivative, moving at every level: consistency with written-out Leibniz/chain
@claim("s77r-third-moving-sym-true", kind="id", sizes=SZ)
def third_moving_sym_true(s):
    """d_U d_V d_W F for constant U, V, W is symmetric: (U, V, W) and (W, U, V) agree."""
    U, V, W = s.fresh("n", "r"), s.fresh("n", "r"), s.fresh("n", "r")

    def third(a, b, c):
        return s.d(lambda t: t.d(lambda u: u.d(cubic, {"X": c}), {"X": b}), {"X": a})
    return {"w": third(U, V, W) - third(W, U, V)}


@claim("s77r-third-moving-true", kind="id", sizes=SZ)
def third_moving_true(s):
    """innermost along v = AX (moving), then along X-direction V, then U: d_U d_V [dF(AX)] equals
    d_U[d²F(AX, V) + dF(AV)] — written as the nested d of (x ↦ d_V(dF(AX))) with the AV term separate."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.d(cubic, {"X": u.A @ u.X}), {"X": V}), {"X": U})
    # d_V [dF(AX)] = d_V[dF(w)]|_{w=AX frozen} + dF(AV); then d_U of both (w moves with U too)
    part1 = s.d(lambda t: t.d(lambda u: u.d(cubic, {"X": t.A @ t.X}), {"X": V}), {"X": U})
    part2 = s.d(lambda t: t.d(cubic, {"X": t.A @ V}), {"X": U})
    return {"w": got - part1 - part2}


@claim("s77r-third-moving-false", kind="id", sizes=SZ)
def third_moving_false(s):
    """FALSE: the dF(AV) part dropped."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.d(cubic, {"X": u.A @ u.X}), {"X": V}), {"X": U})
    part1 = s.d(lambda t: t.d(lambda u: u.d(cubic, {"X": t.A @ t.X}), {"X": V}), {"X": U})
    return {"w": got - part1}


@claim("s77r-fourth-true", kind="id", sizes=SZ)
def fourth_true(s):
    """d⁴ of tr((XᵀX)²) along V four times: 24 tr((VᵀV)²)."""
    V = s.fresh("n", "r")
    T = {"X": V}

    def q4(u):
        return u.tr(u.X.T @ u.X @ u.X.T @ u.X)
    got = s.d(lambda a: a.d(lambda b: b.d(lambda c: c.d(q4, T), T), T), T)
    return {"w": got - s.tr(V.T @ V @ V.T @ V) * 24}


@claim("s77r-fourth-false", kind="id", sizes=SZ)
def fourth_false(s):
    V = s.fresh("n", "r")
    T = {"X": V}

    def q4(u):
        return u.tr(u.X.T @ u.X @ u.X.T @ u.X)
    got = s.d(lambda a: a.d(lambda b: b.d(lambda c: c.d(q4, T), T), T), T)
    return {"w": got - s.tr(V.T @ V @ V.T @ V) * 12}


# -- a direction whose value is an inner derivative: t.d(F, {"X": t.d(G, V)})
@claim("s77r-dir-is-deriv-true", kind="id", sizes=SZ)
def dir_is_deriv_true(s):
    """mid(x) = dF(x)(dG(x)V) with F = tr(XᵀAX): 2tr(XᵀA dG(V)); along U:
    2tr(UᵀA dG(V)) + 2tr(XᵀA d²G(V, U))."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.d(G, {"X": V})}), {"X": U})
    X, A = s.X, s.A
    return {"w": got - s.tr(U.T @ A @ dG(X, V)) * 2 - s.tr(X.T @ A @ d2G(X, V, U)) * 2}


@claim("s77r-dir-is-deriv-false", kind="id", sizes=SZ)
def dir_is_deriv_false(s):
    """FALSE: the direction's own derivative (d²G) dropped."""
    U, V = s.fresh("n", "r"), s.fresh("n", "r")
    got = s.d(lambda t: t.d(quad, {"X": t.d(G, {"X": V})}), {"X": U})
    X, A = s.X, s.A
    return {"w": got - s.tr(U.T @ A @ dG(X, V)) * 2}
