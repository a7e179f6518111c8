"""Derivatives along flows whose keys are not the point's letters."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


@claim("fk-move-A", paper="t", kind="id", section="2", sizes=SZ)
def fk_a(s):
    """d/dt tr(A) along A' = I is n, not 0: FALSE statement d tr A = 0 (or refused)."""
    return {"r": s.d(lambda t: t.tr(t.A), {"X": s.P, "A": s.In})}


@claim("fk-move-Phi", paper="t", kind="id", section="2", sizes=SZ)
def fk_phi(s):
    """Moving 'Phi' directly."""
    return {"r": s.d(lambda t: t.tr(t.Phi @ t.Phi), {"Phi": s.xi})}


@claim("fk-move-Y", paper="t", kind="id", section="2", sizes=SZ)
def fk_y(s):
    """Moving Y along Y' = Q: d/dt tr(YᵀY) = 2tr(YᵀQ) = 0 (tangent) -- TRUE; d tr(Yᵀ A Y) = 2 tr(YᵀAQ) TRUE."""
    return {"r": s.d(lambda t: t.tr(t.Y.T @ t.A @ t.Y), {"Y": s.Q}) - 2 * s.tr(s.Y.T @ s.A @ s.Q)}


@claim("fk-move-Y-false", paper="t", kind="id", section="2", sizes=SZ)
def fk_y_false(s):
    """FALSE: d/dt tr(YᵀAY) along Y' = Q is 0."""
    return {"r": s.d(lambda t: t.tr(t.Y.T @ t.A @ t.Y), {"Y": s.Q})}


@claim("fk-move-Xdot-key", paper="t", kind="id", section="2", sizes=SZ)
def fk_xdot(s):
    """A key 'Xdot' (the flow's attribute name) instead of 'X': d tr(XᵀAX) = 0 FALSE (or refused)."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), {"Xdot": s.P})}


@claim("fk-move-lam", paper="t", kind="id", section="2", sizes=SZ)
def fk_lam(s):
    """Moving lambda: d/dt lam along lam' = 1: FALSE d lam = 0 (or refused)."""
    return {"r": s.d(lambda t: t.lam * t.tr(t.X.T @ t.X), {"X": s.P, "lam": s.q(1)})}
