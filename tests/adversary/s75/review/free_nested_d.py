"""Nested derivatives s.d(lambda t: t.d(F, T), T) under the dimension-free method: the inner derivative inside a
function whose derivative is taken.  TRUE claims end in -true, FALSE ones in -false (the hand value of the
second derivative along a constant direction V, ambient)."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def second(s, F, T):
    return s.d(lambda t: t.d(F, T), T)


@claim("s75-nd-xtx-true", kind="id", sizes=SZ)
def nd_xtx_true(s):
    """d² tr(XᵀX) along V = 2 tr(VᵀV): TRUE."""
    V = s.fresh("n", "r")
    return {"w": second(s, lambda t: t.tr(t.X.T @ t.X), {"X": V}) - s.tr(V.T @ V) * 2}


@claim("s75-nd-xtx-false", kind="id", sizes=SZ)
def nd_xtx_false(s):
    """d² tr(XᵀX) along V = 0: FALSE."""
    V = s.fresh("n", "r")
    return {"w": second(s, lambda t: t.tr(t.X.T @ t.X), {"X": V})}


@claim("s75-nd-xax-true", kind="id", sizes=SZ)
def nd_xax_true(s):
    """d² tr(XᵀAX) along V = 2 tr(VᵀAV): TRUE."""
    V = s.fresh("n", "r")
    return {"w": second(s, lambda t: t.tr(t.X.T @ t.A @ t.X), {"X": V}) - s.tr(V.T @ s.A @ V) * 2}


@claim("s75-nd-matrix-true", kind="id", sizes=SZ)
def nd_matrix_true(s):
    """d² (XᵀX) along V = 2VᵀV (a matrix): TRUE."""
    V = s.fresh("n", "r")
    return {"w": second(s, lambda t: t.X.T @ t.X, {"X": V}) - V.T @ V * 2}


@claim("s75-nd-matrix-false", kind="id", sizes=SZ)
def nd_matrix_false(s):
    """d² (XᵀX) along V = VᵀV + XᵀX − I: FALSE (= VᵀV on T*V... the claim says 2VᵀV = VᵀV)."""
    V = s.fresh("n", "r")
    return {"w": second(s, lambda t: t.X.T @ t.X, {"X": V}) - V.T @ V - s.X.T @ s.X + s.Ir}


@claim("s75-nd-p-direction-true", kind="id", sizes=SZ)
def nd_p_dir_true(s):
    """Inner along {"X": t.P} (moving), outer along {"X": V}: d/dε [2 tr(Pᵀ A X)] at X + εV = 2 tr(PᵀAV): TRUE."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.X.T @ u.A @ u.X), {"X": t.P}), {"X": V})
    return {"w": got - s.tr(s.P.T @ s.A @ V) * 2}


@claim("s75-nd-p-direction-false", kind="id", sizes=SZ)
def nd_p_dir_false(s):
    """... = 2 tr(XᵀAV): FALSE."""
    V = s.fresh("n", "r")
    got = s.d(lambda t: t.d(lambda u: u.tr(u.X.T @ u.A @ u.X), {"X": t.P}), {"X": V})
    return {"w": got - s.tr(s.X.T @ s.A @ V) * 2}


@claim("s75-nd-quartic-true", kind="id", sizes=SZ)
def nd_quartic_true(s):
    """d² tr((XᵀX)²) along V = 2 tr((VᵀX + XᵀV)²) + 4 tr(XᵀX VᵀV): TRUE."""
    V = s.fresh("n", "r")
    S = V.T @ s.X + s.X.T @ V
    got = second(s, lambda t: t.tr(t.X.T @ t.X @ t.X.T @ t.X), {"X": V})
    return {"w": got - s.tr(S @ S) * 2 - s.tr(s.X.T @ s.X @ V.T @ V) * 4}
