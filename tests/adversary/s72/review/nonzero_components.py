"""s72 review: 'does not vanish' claims at r = n built from det X (attempts Z1-Z5).  X is n x r even at r = n, so det X
enters only through det(GX), det(MᵀX) with generic G, M: every such term carries det X times generic factors, and a
residual that vanishes on one component of O(n) alone cannot be written this way (the parity argument in FINDINGS.md)."""
from stiefelsym import admissible, claim, det

SQ = admissible(n_max=3, where=lambda n, r: r == n, n_min=2)


@claim("s72-nz-det-minus-one", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def det_minus_one(s):
    """det(GX) + det(GM)·det(MᵀX)/det(MᵀM) = 2·det G·det X is not identically 0 (TRUE nonzero claim)."""
    G = s.generic("G", "r", "n")
    M = s.generic("M", "n", "r")
    a = det(s, G @ s.X)
    b = det(s, G @ M) * det(s, M.T @ s.X) / det(s, M.T @ M)
    return {"det(GX) + ...": a + b}


@claim("s72-nz-one-component", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def one_component(s):
    """det(GX) − det(GM)·det(MᵀX)/det(MᵀM) = det G det X − det G det X = 0: FALSE nonzero claim."""
    G = s.generic("G", "r", "n")
    M = s.generic("M", "n", "r")
    a = det(s, G @ s.X)
    b = det(s, G @ M) * det(s, M.T @ s.X) / det(s, M.T @ M)
    return {"det(GX) - det(GM)det(MᵀX)/det(MᵀM)": a - b}


@claim("s72-nz-so-only", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def so_only(s):
    """det(GX)·det(XᵀM) − det(GM) = det G det M ((det X)² − 1) = 0 on O(n) (FALSE nonzero claim)."""
    G = s.generic("G", "r", "n")
    M = s.generic("M", "n", "r")
    return {"r": det(s, G @ s.X) * det(s, s.X.T @ M) - det(s, G @ M)}


@claim("s72-nz-det-sign", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def det_sign(s):
    """det(GX)·det(MᵀM) − det(GM)·det(MᵀX) = 0 identically (FALSE nonzero claim)."""
    G = s.generic("G", "r", "n")
    M = s.generic("M", "n", "r")
    return {"r": det(s, G @ s.X) * det(s, M.T @ M) - det(s, G @ M) * det(s, M.T @ s.X)}


@claim("s72-nz-det-minus-plus", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def det_minus_plus(s):
    """det(GX)·det(MᵀM) + det(GM)·det(MᵀX) = 2 det G (det M)² det X is not identically 0 (TRUE nonzero claim)."""
    G = s.generic("G", "r", "n")
    M = s.generic("M", "n", "r")
    return {"r": det(s, G @ s.X) * det(s, M.T @ M) + det(s, G @ M) * det(s, M.T @ s.X)}


@claim("s72-nz-second-point", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def second_point(s):
    """det(XᵀY) − 1 is not identically 0 (TRUE: it is −2 where X and Y lie on different components of O(n))."""
    return {"det(XᵀY) - 1": det(s, s.X.T @ s.Y) - 1}


@claim("s72-nz-second-point-square", paper="No", kind="not", expect="nonzero", section="t", sizes=SQ)
def second_point_square(s):
    """det(XᵀY)² − 1 is not identically 0 (FALSE: it vanishes on all four pairs of components)."""
    d = det(s, s.X.T @ s.Y)
    return {"det(XᵀY)^2 - 1": d * d - 1}
