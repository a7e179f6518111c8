"""Item 3: twisted.at_point on a derivative's scene t (ConstantScene now).  (a) At a point of constants of the
enclosing scene, (s.X, 2s.P), every value is a constant: its derivative along {"X": U} is 0 (TRUE); the false
twins give the derivative the value would have at t's own moving point.  (b) at_point(t, t.X, t.P) is t's own
point: every derivative there equals t's own (TRUE, both engine roads, U generic or the Dirac flow of a
Hamiltonian); the false twins add a nonzero term.  (c) inside a gradient: ∇ of tr(K Ψ(X, 2P)) is 2∇tr(KΨ)."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import at_point

SZ = admissible(n_max=3)


def H(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.P.T @ t.P) / 2


def G(t):
    return t.tr(t.X.T @ t.A @ t.A @ t.P)


def _quantities(u, K):
    """scalars of the scene u that read its point through Φ, Ψ, flows, gradients and brackets"""
    cf = u.canonical_flow(H)
    df = u.dirac_flow(H)
    gX, gP = u.gradient(G)
    return {"psi": u.tr(u.Psi @ u.Psi @ u.Psi.T),
            "phi": u.tr(K @ u.Phi),
            "canon": u.tr(K @ cf["P"] @ u.X.T),
            "dirac": u.tr(K @ df["P"] @ u.X.T) + u.tr(K @ df["X"] @ u.P.T),
            "grad": u.tr(K @ gX @ gP.T),
            "bracket": u.bracket(H, G)}


def _d_at(s, U, K, where):
    return s.d(lambda t: _quantities(where(t), K), U)


@claim("r3-atp-const-true", kind="id", sizes=SZ)
def const_true(s):
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    return _d_at(s, {"X": U}, K, lambda t: at_point(t, s.X, s.P * 2))


@claim("r3-atp-const-false", kind="id", sizes=SZ)
def const_false(s):
    """FALSE: the derivative of the same values at (t.X, 2t.P) (nonzero)."""
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    got = _d_at(s, {"X": U}, K, lambda t: at_point(t, s.X, s.P * 2))
    moving = _d_at(s, {"X": U}, K, lambda t: at_point(t, t.X, t.P * 2))
    return {k: got[k] - moving[k] for k in got}


@claim("r3-atp-own-true", kind="id", sizes=SZ)
def own_true(s):
    U, K = s.fresh("n", "r"), s.fresh("n", "n")
    got = _d_at(s, {"X": U}, K, lambda t: at_point(t, t.X, t.P))
    own = _d_at(s, {"X": U}, K, lambda t: t)
    return {k: got[k] - own[k] for k in got}


@claim("r3-atp-own-flow-true", kind="id", sizes=SZ)
def own_flow_true(s):
    K = s.fresh("n", "n")
    fl = s.dirac_flow(G)
    got = _d_at(s, fl, K, lambda t: at_point(t, t.X, t.P))
    own = _d_at(s, fl, K, lambda t: t)
    return {k: got[k] - own[k] for k in got}


@claim("r3-atp-own-flow-false", kind="id", sizes=SZ)
def own_flow_false(s):
    """FALSE where r < n (at r = n, G = tr(A²·XSXᵀ) = 0 on T*V and its flow is 0: true there)."""
    K = s.fresh("n", "n")
    fl = s.dirac_flow(G)
    got = _d_at(s, fl, K, lambda t: at_point(t, t.X, t.P * 2))
    own = _d_at(s, fl, K, lambda t: t)
    return {k: got[k] - own[k] for k in got}


@claim("r3-atp-grad-true", kind="id", sizes=SZ)
def grad_true(s):
    K = s.fresh("r", "r")
    gX, gP = s.gradient(lambda t: t.tr(K @ at_point(t, t.X, t.P * 2).Psi))
    hX, hP = s.gradient(lambda t: t.tr(K @ t.Psi))
    return {"X": gX - hX * 2, "P": gP - hP * 2}


@claim("r3-atp-grad-false", kind="id", sizes=SZ)
def grad_false(s):
    """FALSE (r >= 2; Ψ = 0 at r = 1): the gradient at t's own Ψ (factor 1)."""
    K = s.fresh("r", "r")
    gX, gP = s.gradient(lambda t: t.tr(K @ at_point(t, t.X, t.P * 2).Psi))
    hX, hP = s.gradient(lambda t: t.tr(K @ t.Psi))
    return {"X": gX - hX, "P": gP - hP}


@claim("r3-atp-grad-const-true", kind="id", sizes=SZ)
def grad_const_true(s):
    """∇ of a function of an at_point of constants (s.X, s.P) is 0."""
    K = s.fresh("n", "n")
    gX, gP = s.gradient(lambda t: _quantities(at_point(t, s.X, s.P), K)["dirac"])
    return {"X": gX, "P": gP}
