"""Adversary (generic kinds): symmetric/skew generic matrices inside derivatives, gradients and brackets (constants
along every flow; the gradient of tr(Xᵀ S X) is 2 S X only for S symmetric)."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-d-true", paper="adv", kind="id", sizes=S)
def d_true(s):
    """True: d tr(Xᵀ S X)[V] = 2 tr(Vᵀ S X); the ambient gradient of tr(Xᵀ S X) is (2 S X, 0); d tr(Xᵀ K P)[V] = tr(Vᵀ K P)."""
    V = s.generic("V", "n", "r")
    f = lambda t: (t.X.T @ t.generic("S", "n", "n", "sym") @ t.X).trace()
    HX, HP = s.gradient(f)
    Sm = s.generic("S", "n", "n", "sym")
    g = lambda t: (t.X.T @ t.generic("K", "n", "n", "skew") @ t.P).trace()
    return {"d": s.d(f, {"X": V}) - (V.T @ Sm @ s.X).trace() * 2,
            "grad X": HX - Sm @ s.X * 2, "grad P": HP,
            "d skew": s.d(g, {"X": V}) - (V.T @ s.generic("K", "n", "n", "skew") @ s.P).trace()}


@claim("adv-gk-d-false-general", paper="adv", kind="id", sizes=S)
def d_false_general(s):
    """False: d tr(Xᵀ G X)[V] = 2 tr(Vᵀ G X) for a general G."""
    V = s.generic("V", "n", "r")
    f = lambda t: (t.X.T @ t.generic("G", "n", "n") @ t.X).trace()
    return {"d": s.d(f, {"X": V}) - (V.T @ s.generic("G", "n", "n") @ s.X).trace() * 2}


@claim("adv-gk-d-false-skew", paper="adv", kind="id", sizes=S)
def d_false_skew(s):
    """False: d tr(Xᵀ K P)[V] = 2 tr(Vᵀ K P) (the factor 2 of the symmetric case, for K skew)."""
    V = s.generic("V", "n", "r")
    g = lambda t: (t.X.T @ t.generic("K", "n", "n", "skew") @ t.P).trace()
    return {"d": s.d(g, {"X": V}) - (V.T @ s.generic("K", "n", "n", "skew") @ s.P).trace() * 2}


@claim("adv-gk-d-moves", paper="adv", kind="id", sizes=S)
def d_moves(s):
    """False: d S[V] = V Vᵀ (a generic matrix is constant along a flow: d S = 0, so the residual is -V Vᵀ)."""
    V = s.generic("V", "n", "r")
    return {"dS": s.d(lambda t: t.generic("S", "n", "n", "sym"), {"X": V}) - V @ V.T}


@claim("adv-gk-bracket-true", paper="adv", kind="id", sizes=S)
def bracket_true(s):
    """True: the Dirac bracket of tr(Xᵀ S X) with itself vanishes, and {tr(XᵀSX), tr(XᵀKX)} = -{tr(XᵀKX), tr(XᵀSX)}."""
    f = lambda t: (t.X.T @ t.generic("S", "n", "n", "sym") @ t.X).trace()
    h = lambda t: (t.X.T @ t.generic("K", "n", "n", "skew") @ t.P).trace()
    return {"{f,f}": s.bracket(f, f), "anti": s.bracket(f, h) + s.bracket(h, f)}
