"""Derivatives along a flow of functions that read the second point, user scalars, generic letters."""
from stiefelsym import admissible, claim

SZ = admissible(n_max=4, n_min=2)


def H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("fp-y-const", paper="t", kind="id", section="5", sizes=SZ)
def y_const(s):
    """TRUE: Y is constant along the Neumann flow of (X, P): d/dt tr(YᵀX) = tr(Yᵀ Ẋ) = tr(YᵀP)."""
    fl = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.Y.T @ t.X), fl) - s.tr(s.Y.T @ fl["X"])}


@claim("fp-y-moves", paper="t", kind="id", section="5", sizes=SZ)
def y_moves(s):
    """FALSE: d/dt tr(YᵀQ) = tr(QᵀQ) (Y does not move)."""
    fl = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.Y.T @ t.Q), fl) - s.tr(s.Q.T @ s.Q)}


@claim("fp-y-xdot", paper="t", kind="id", section="5", sizes=SZ)
def y_xdot(s):
    """FALSE: d/dt tr(YᵀX) = tr(Yᵀ X) ."""
    fl = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.Y.T @ t.X), fl) - s.tr(s.Y.T @ s.X)}


@claim("fp-scalar-in-fn", paper="t", kind="id", section="5", sizes=SZ)
def scalar_in_fn(s):
    """TRUE (fixed-size reading: one scalar c): d/dt (c H2) = c d/dt H2, H2 = tr(XᵀAAX)."""
    fl = s.dirac_flow(H)
    f = lambda t: t.tr(t.X.T @ t.A @ t.A @ t.X)
    return {"r": s.d(lambda t: t.scalar("c") * f(t), fl) - s.scalar("c") * s.d(f, fl)}


@claim("fp-scalar-zero", paper="t", kind="id", section="5", sizes=SZ)
def scalar_zero(s):
    """FALSE: d/dt (c tr(XᵀAAX)) = 0."""
    fl = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.scalar("c") * t.tr(t.X.T @ t.A @ t.A @ t.X), fl)}


@claim("fp-gen-fn", paper="t", kind="id", section="5", sizes=SZ)
def gen_fn(s):
    """FALSE: d/dt tr(GᵀX) = 0 with G generic."""
    fl = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.generic("G", "n", "r").T @ t.X), fl)}


@claim("fp-gen-fn2", paper="t", kind="id", section="5", sizes=SZ)
def gen_fn2(s):
    """TRUE: d/dt tr(GᵀX) = tr(GᵀẊ) with the generic G read inside and outside the function."""
    fl = s.dirac_flow(H)
    return {"r": s.d(lambda t: t.tr(t.generic("G", "n", "r").T @ t.X), fl)
            - s.tr(s.generic("G", "n", "r").T @ fl["X"])}
