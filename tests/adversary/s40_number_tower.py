"""Round 11, the number tower (`backends/fields.tower_level`, `LAYERED`, `Mat._raised`): derivatives inside
derivatives (the graph's pass leaves a derivative inside a function to the scene's dual numbers), gradients (reverse
numbers) and brackets mixed with them in any order, with values captured from every enclosing scene; each against a
truth written out by hand (A = diag(a); f = tr(XᵀAX); the flow X' = AX, P' = 0)."""
from stiefelsym import Size, SizeSpec, block, claim

S = SizeSpec((Size(3, 2),))


def Z(s):
    return s.zeros(s.n, s.r, ("n", "r"))


def V(t):
    return {"X": t.A @ t.X, "P": Z(t)}


def f(u):
    return u.tr(u.X.T @ u.A @ u.X)


def h(u):
    return u.tr(u.P.T @ u.P) / 2


def _trA(s, k):
    M = s.A
    for _ in range(k - 1):
        M = M @ s.A
    return s.tr(s.X.T @ M @ s.X)


@claim("adv-s40-tower-second-d-captured", paper="adv", kind="id", sizes=S)
def second_d_captured(s):
    """True: d/dt of (d/du f along A X₀), X₀ captured from the claim's scene, = 2 tr(XᵀA³X)."""
    X0 = s.X
    g = lambda t: t.d(f, {"X": t.A @ X0, "P": Z(t)})
    return {"x": s.d(g, V(s)) - _trA(s, 3) * 2}


@claim("adv-s40-tower-second-d-captured-false", paper="adv", kind="id", sizes=S)
def second_d_captured_false(s):
    """False: the same = 4 tr(XᵀA³X) (as if X₀ moved)."""
    X0 = s.X
    g = lambda t: t.d(f, {"X": t.A @ X0, "P": Z(t)})
    return {"x": s.d(g, V(s)) - _trA(s, 3) * 4}


def _h3(t):
    c = t.tr(t.X.T @ t.A @ t.X)
    return t.d(lambda u: c * u.d(f, V(u)), V(t))


@claim("adv-s40-tower-third-d-middle-capture", paper="adv", kind="id", sizes=S)
def third_d(s):
    """True: d/dt [c(t)·4tr(XᵀA³X)] with c captured by the middle layer = 2tr(XᵀA²X)·4tr(XᵀA³X) + c·8tr(XᵀA⁴X)."""
    return {"x": s.d(_h3, V(s)) - (_trA(s, 2) * _trA(s, 3) * 8 + _trA(s, 1) * _trA(s, 4) * 8)}


@claim("adv-s40-tower-third-d-middle-capture-false", paper="adv", kind="id", sizes=S)
def third_d_false(s):
    """False: c's derivative dropped."""
    return {"x": s.d(_h3, V(s)) - _trA(s, 1) * _trA(s, 4) * 8}


def _inner(force):
    def g(t):
        c = t.tr(t.X.T @ t.A @ t.X)

        def k(u):
            B = u.X.T @ u.A @ u.X
            out = u.tr(block([[u.Ir * c, B], [B, u.Ir * c]]).inv())
            if force:
                out = out + u.tr(u.resolvent(u.tr(u.X.T @ u.A @ u.X) + 7)) * 0
            return out
        return t.d(k, V(t))
    return g


def _by_hand(t):
    c = t.tr(t.X.T @ t.A @ t.X)
    B = t.X.T @ t.A @ t.X
    B1 = t.X.T @ t.A @ t.A @ t.X * 2
    Rp, Rm = (t.Ir * c + B).inv(), (t.Ir * c - B).inv()
    return t.tr(Rm @ B1 @ Rm) - t.tr(Rp @ B1 @ Rp)


@claim("adv-s40-tower-captured-in-an-inverse", paper="adv", kind="id", sizes=S)
def captured_in_inverse(s):
    """True: a captured c in the diagonal blocks of an inverse of the inner layer (a resolvent at a moving μ
    beside it): the outer derivative equals that of the inner derivative written out by hand."""
    return {"x": s.d(_inner(True), V(s)) - s.d(_by_hand, V(s))}


def _rdr(s):
    c0 = s.tr(s.X.T @ s.A @ s.X)

    def F(t):
        c1 = t.tr(t.X.T @ t.A @ t.X)
        return t.d(lambda u: u.tr(u.gradient(lambda w: f(w) * c0 * c1)[0].T @ u.X), V(t))
    return s.gradient(F)


@claim("adv-s40-tower-rev-dual-rev", paper="adv", kind="id", sizes=S)
def rev_dual_rev(s):
    """True: ∇_X of F(t) = d/du tr(∇_X(c₀c₁f)ᵀX) (c₀ from the claim's scene, c₁ from the gradient's) is
    8c(tr(XᵀA²X)AX + cA²X) at the claim's point (c₀ = c₁ = c), ∇_P F = 0."""
    A, X = s.A, s.X
    gX, gP = _rdr(s)
    return {"gX": gX - (A @ X * _trA(s, 2) + A @ A @ X * _trA(s, 1)) * _trA(s, 1) * 8, "gP": gP}


@claim("adv-s40-tower-rev-dual-rev-false", paper="adv", kind="id", sizes=S)
def rev_dual_rev_false(s):
    """False: as if c₀ moved with the gradient's point."""
    A, X = s.A, s.X
    gX, _ = _rdr(s)
    return {"gX": gX - (A @ X * _trA(s, 2) * 2 + A @ A @ X * _trA(s, 1)) * _trA(s, 1) * 8}


@claim("adv-s40-tower-dual-rev-dual", paper="adv", kind="id", sizes=S)
def dual_rev_dual(s):
    """True: d/dt tr(∇_X Gᵀ X) along AX for G(u) = d/dw(c₀f) along AX (c₀ captured from the claim) = 8c₀tr(XᵀA³X)."""
    c0 = _trA(s, 1)

    def H(t):
        return t.tr(t.gradient(lambda u: u.d(lambda w: f(w) * c0, V(u)))[0].T @ t.X)
    return {"x": s.d(H, V(s)) - c0 * _trA(s, 3) * 8}


@claim("adv-s40-tower-bracket-capture", paper="adv", kind="id", sizes=S)
def bracket_capture(s):
    """True: d/dt {c f, h} = d/dt (c {f, h}), c = tr(XᵀAX) captured inside the bracket's function."""
    def K1(t):
        c = t.tr(t.X.T @ t.A @ t.X)
        return t.bracket(lambda u: f(u) * c, h)

    def K2(t):
        return t.bracket(f, h) * t.tr(t.X.T @ t.A @ t.X)
    return {"x": s.d(K1, V(s)) - s.d(K2, V(s))}


@claim("adv-s40-tower-bracket-capture-false", paper="adv", kind="id", sizes=S)
def bracket_capture_false(s):
    """False: d/dt {c f, h} = c d/dt {f, h}."""
    def K1(t):
        c = t.tr(t.X.T @ t.A @ t.X)
        return t.bracket(lambda u: f(u) * c, h)
    return {"x": s.d(K1, V(s)) - s.d(lambda t: t.bracket(f, h), V(s)) * _trA(s, 1)}
