"""Derivatives along letters other than X and P: A, Y, Zc."""
from stiefelsym import claim

SZ = [(3, 2), (4, 4)]


@claim("s76-d-along-a", kind="id", sizes=SZ)
def d_along_a(s):
    """d tr(XᵀAX) along A ↦ A + εG equals tr(XᵀGX) (true)."""
    G = s.generic("G", "n", "n", "sym")
    return {"dA": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), {"A": G}) - s.tr(s.X.T @ G @ s.X)}


@claim("s76-d-along-y", kind="id", sizes=SZ)
def d_along_y(s):
    """d tr(YᵀAX) along Y ↦ Y + εV equals tr(VᵀAX) (true)."""
    V = s.fresh("n", "r")
    return {"dY": s.d(lambda t: t.tr(t.Y.T @ t.A @ t.X), {"Y": V}) - s.tr(V.T @ s.A @ s.X)}


@claim("s76-d-along-y-twin", kind="id", sizes=SZ)
def d_along_y_twin(s):
    """FALSE: d tr(YᵀAX) along Y ↦ Y + εV equals tr(VᵀAY)."""
    V = s.fresh("n", "r")
    return {"dY": s.d(lambda t: t.tr(t.Y.T @ t.A @ t.X), {"Y": V}) - s.tr(V.T @ s.A @ s.Y)}


@claim("s76-d-along-x-of-y", kind="id", sizes=SZ)
def d_along_x_of_y(s):
    """d (YᵀY) along X ↦ X + εV is 0 (Y does not move with X) (true)."""
    V = s.fresh("n", "r")
    return {"dYtY": s.d(lambda t: t.Y.T @ t.Y + t.Y.T @ t.X, {"X": V}) - s.Y.T @ V}


@claim("s76-d-along-lam", kind="id", sizes=SZ)
def d_along_lam(s):
    """d tr R(λ) along λ ↦ λ + ε equals −tr R(λ)² (true)."""
    R = s.resolvent(s.lam)
    return {"dlam": s.d(lambda t: t.tr(t.resolvent(t.lam)), {"lam": s.q(1, 1)}) + s.tr(R @ R)}
