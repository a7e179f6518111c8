"""s60 review probes: block matrices of symbolic sizes under the dimension-free method."""
from stiefelsym import admissible, block, claim

S = admissible(n_max=4)


@claim("s60r-blk-id-offdiag", paper="adv", kind="id", sizes=S)
def blk_id_offdiag(s):
    """True: the (0,1) block of I_{2r} is 0, read by [I_r; 0]^T I_{2r} [0; I_r]."""
    Z = s.zeros(s.r, s.r)
    e0 = block([[s.Ir], [Z]])
    e1 = block([[Z], [s.Ir]])
    return {"off": e0.T @ s.identity(2 * s.r) @ e1}


@claim("s60r-blk-id-diag-false", paper="adv", kind="id", sizes=S)
def blk_id_diag_false(s):
    """False: the (0,1) block of I_{2r} is I_r."""
    Z = s.zeros(s.r, s.r)
    e0 = block([[s.Ir], [Z]])
    e1 = block([[Z], [s.Ir]])
    return {"off": e0.T @ s.identity(2 * s.r) @ e1 - s.Ir}


@claim("s60r-blk-trace-false", paper="adv", kind="id", sizes=S)
def blk_trace_false(s):
    """False: tr of the Gram matrix of [X, P] equals tr(X^T X)."""
    Z = block([[s.X, s.P]])
    return {"tr": (Z.T @ Z).trace() - s.tr(s.X.T @ s.X)}


@claim("s60r-blk-swap-false", paper="adv", kind="id", sizes=S)
def blk_swap_false(s):
    """False: [X, P] [I;0] = P (the first block column is X)."""
    Z = block([[s.X, s.P]])
    e0 = block([[s.Ir], [s.zeros(s.r, s.r)]])
    return {"swap": Z @ e0 - s.P}


@claim("s60r-blk-2r-vs-rr", paper="adv", kind="id", sizes=S)
def blk_2r_vs_rr(s):
    """False: (I_{2r} with its (0,0) block doubled) has trace 2r: tr(I_2r + e0 e0^T) - tr(I_2r) = 0."""
    Z = s.zeros(s.r, s.r)
    e0 = block([[s.Ir], [Z]])
    return {"tr": (s.identity(2 * s.r) + e0 @ e0.T).trace() - s.identity(2 * s.r).trace()}
