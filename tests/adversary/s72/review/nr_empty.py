"""s72 review: blocks on R^(n-r) at n = r, where they are empty (attempts E1-E6).  Truth at n = r: an empty block's
trace is 0, an r x r product through an empty block is the zero matrix."""
from stiefelsym import admissible, block, claim

SQ = admissible(n_max=3, where=lambda n, r: r == n)
ALL = admissible(n_max=3)


@claim("s72-e-trace-empty", paper="No", kind="id", section="t", sizes=SQ)
def trace_empty(s):
    """tr G + tr(XᵀX) − r = 0 at n = r, G on R^(n−r) empty (true)."""
    G = s.generic("G", "n-r", "n-r")
    return {"t": s.tr(G) + s.tr(s.X.T @ s.X) - s.tr(s.Ir)}


@claim("s72-e-trace-empty-false", paper="No", kind="id", section="t", sizes=SQ)
def trace_empty_false(s):
    """tr G + 1 = 0 at n = r (false: the empty trace is 0)."""
    G = s.generic("G", "n-r", "n-r")
    return {"t": s.tr(G) + 1}


@claim("s72-e-gram-empty", paper="No", kind="id", section="t", sizes=SQ)
def gram_empty(s):
    """P2ᵀP2 = 0 at n = r (true: an r x r product through an empty block)."""
    P2 = s.generic("P2", "n-r", "r")
    return {"g": P2.T @ P2}


@claim("s72-e-gram-identity-false", paper="No", kind="id", section="t", sizes=SQ)
def gram_identity_false(s):
    """P2ᵀP2 = I_r at n = r (false)."""
    P2 = s.generic("P2", "n-r", "r")
    return {"g": P2.T @ P2 - s.Ir}


@claim("s72-e-block-x0", paper="No", kind="id", section="t", sizes=ALL)
def block_x0(s):
    """X0ᵀX0 = I_r for X0 = [I_r; 0_(n−r)×r] (true at every size, n = r included)."""
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    return {"g": X0.T @ X0 - s.Ir}


@claim("s72-e-block-x0-false", paper="No", kind="id", section="t", sizes=ALL)
def block_x0_false(s):
    """X0ᵀX0 = 2 I_r (false)."""
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    return {"g": X0.T @ X0 - 2 * s.Ir}


@claim("s72-e-det-empty", paper="No", kind="id", section="t", sizes=SQ)
def det_empty(s):
    """det of an empty (n−r)×(n−r) block = 1 (true by convention), via elementary(): e_0 = 1."""
    from stiefelsym import elementary
    G = s.generic("G", "n-r", "n-r")
    e = elementary(s, G, 1)
    return {"e0 - 1": e[0] - 1}
