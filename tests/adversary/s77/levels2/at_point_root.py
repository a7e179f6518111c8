"""s77 levels2: a value of the claim's scene s (the root) read inside a function handed to a scene at another
point (twisted.at_point(s, X, P): a copy of s, not a lift of it, so not in the function scene's `.base` chain).
The value is a constant of s's numbers: every level may take it as one.  -true: TRUE, -false: FALSE."""
from stiefelsym import admissible, claim
from stiefelsym.twisted import at_point

SZ = admissible(n_max=3)


def _other(s):
    # the same point (a legitimate point of T*V), as a scene of its own
    return at_point(s, s.X, s.P)


@claim("s77m-atp-d-root-true", kind="id", sizes=SZ)
def atp_d_root_true(s):
    """h.d(w -> tr(BᵀX_w), {X: V}) = tr(BᵀV), B a fresh matrix of s: TRUE."""
    B, V = s.fresh("n", "r"), s.fresh("n", "r")
    h = _other(s)
    return {"w": h.d(lambda w: w.tr(B.T @ w.X), {"X": V}) - s.tr(B.T @ V)}


@claim("s77m-atp-d-root-false", kind="id", sizes=SZ)
def atp_d_root_false(s):
    """= 0: FALSE."""
    B, V = s.fresh("n", "r"), s.fresh("n", "r")
    h = _other(s)
    return {"w": h.d(lambda w: w.tr(B.T @ w.X), {"X": V})}


@claim("s77m-atp-grad-root-true", kind="id", sizes=SZ)
def atp_grad_root_true(s):
    """∇_X of tr(BᵀX) at the other point = B: TRUE."""
    B = s.fresh("n", "r")
    h = _other(s)
    return {"w": h.gradient(lambda w: w.tr(B.T @ w.X))[0] - B}


@claim("s77m-atp-grad-root-false", kind="id", sizes=SZ)
def atp_grad_root_false(s):
    """= 0: FALSE."""
    B = s.fresh("n", "r")
    h = _other(s)
    return {"w": h.gradient(lambda w: w.tr(B.T @ w.X))[0]}


@claim("s77m-atp-d-scal-true", kind="id", sizes=SZ)
def atp_d_scal_true(s):
    """h.d(w -> c·tr(X_wᵀX_w), {X: V}), c = tr(XᵀAX) a number of s: 2c·tr(XᵀV): TRUE."""
    V = s.fresh("n", "r")
    c = s.tr(s.X.T @ s.A @ s.X)
    h = _other(s)
    return {"w": h.d(lambda w: w.tr(w.X.T @ w.X) * c, {"X": V}) - c * 2 * s.tr(s.X.T @ V)}


@claim("s77m-atp-d-scal-false", kind="id", sizes=SZ)
def atp_d_scal_false(s):
    """= 2tr(XᵀV): FALSE."""
    V = s.fresh("n", "r")
    c = s.tr(s.X.T @ s.A @ s.X)
    h = _other(s)
    return {"w": h.d(lambda w: w.tr(w.X.T @ w.X) * c, {"X": V}) - s.tr(s.X.T @ V) * 2}
