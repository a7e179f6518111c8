"""Adversary (generic kinds): a matrix times an identically zero scalar divided by it (tr K for K skew, compared
with tr xi and q(0), which predate the feature): undefined, so `error`, not `fails`."""
from stiefelsym import claim, admissible

S = admissible(n_max=4)


@claim("adv-gk-mdiv-trK", paper="adv", kind="id", sizes=S)
def mdiv_trK(s):
    """Undefined: X·tr(K)/tr(K) − X."""
    K = s.generic("K", "n", "n", "skew")
    return {"x": s.X * K.trace() / K.trace() - s.X}


@claim("adv-gk-mdiv-trxi", paper="adv", kind="id", sizes=S)
def mdiv_trxi(s):
    """Undefined: X·tr(xi)/tr(xi) − X (xi skew, an engine letter)."""
    return {"x": s.X * s.xi.trace() / s.xi.trace() - s.X}


@claim("adv-gk-mdiv-q0", paper="adv", kind="id", sizes=S)
def mdiv_q0(s):
    """Undefined: X·0/0 − X."""
    return {"x": s.X * s.q(0) / s.q(0) - s.X}


@claim("adv-gk-mdiv-K", paper="adv", kind="id", sizes=S)
def mdiv_K(s):
    """Undefined: K·tr(K)/tr(K) (a matrix whose entries do not all vanish times 0 / 0), residual − K."""
    K = s.generic("K", "n", "n", "skew")
    return {"x": K * K.trace() / K.trace() - K}


@claim("adv-gk-mdiv-zero", paper="adv", kind="id", sizes=S)
def mdiv_zero(s):
    """Undefined: X·tr(K)/tr(K) (the zero matrix over an identically zero scalar)."""
    K = s.generic("K", "n", "n", "skew")
    return {"x": s.X * K.trace() / K.trace()}


@claim("adv-gk-mdiv-nonzero-expect", paper="adv", kind="id", sizes=S, expect="nonzero")
def mdiv_nonzero_expect(s):
    """Undefined, stated not to vanish: X·tr(K)/tr(K) − X."""
    K = s.generic("K", "n", "n", "skew")
    return {"x": s.X * K.trace() / K.trace() - s.X}
