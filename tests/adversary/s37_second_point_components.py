"""Round 7: the second point (Y, Q) at r = n.  V(n, n) = O(n) has two components and a second point lies on
either, independently of the first: det(XᵀY) = det X · det Y = ±1.  The Cayley chart of the point methods (and
of the exact method when a claim reads coordinates of R^n) built Y with the sign matrix D of X's component, so
(X, Y) was always on one component: every statement true there only was passed.  Each claim below but the
controls is false."""
from stiefelsym import admissible, claim


def _det2(M):
    return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]


@claim("adv-s37-det-xty", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def det_xty(s):
    """det(XᵀY) = 1 at r = n = 2 (false: XᵀY is any point of O(2))."""
    return {"det": _det2(s.X.T @ s.Y) - 1}


@claim("adv-s37-det-product", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def det_product(s):
    """det X · det Y = 1 at r = n = 2 (false)."""
    return {"det": _det2(s.X) * _det2(s.Y) - 1}


@claim("adv-s37-same-det", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def same_det(s):
    """det X = det Y at r = n = 2 (false)."""
    return {"det": _det2(s.X) - _det2(s.Y)}


@claim("adv-s37-rotation", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def rotation(s):
    """M + Mᵀ = tr(M) I_r for M = XᵀY at r = n = 2, no coordinate read: true where M is a rotation only
    (false)."""
    M = s.X.T @ s.Y
    return {"rot": M + M.T - s.tr(M) * s.Ir}


@claim("adv-s37-det-traces", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def det_traces(s):
    """det(XᵀY) = ((tr M)² − tr M²)/2 = 1 for M = XᵀY at r = n = 2, no coordinate read (false)."""
    M = s.X.T @ s.Y
    return {"det": (s.tr(M) * s.tr(M) - s.tr(M @ M)) / 2 - 1}


@claim("adv-s37-cofactor", kind="id", sizes=admissible(n_min=3, n_max=3, r_is_n=True))
def cofactor(s):
    """M₁₁ = its cofactor for M = XᵀY at r = n = 3 (M = cof(M)/det M holds for det M = 1 only: false)."""
    M = s.X.T @ s.Y
    return {"cof": M[0, 0] - (M[1, 1] * M[2, 2] - M[1, 2] * M[2, 1])}


@claim("adv-s37-det-product-true", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def det_product_true(s):
    """det(XᵀY) = det X · det Y (true, control)."""
    return {"det": _det2(s.X.T @ s.Y) - _det2(s.X) * _det2(s.Y)}


@claim("adv-s37-orthogonal-true", kind="id", sizes=admissible(n_min=2, n_max=3, r_is_n=True))
def orthogonal_true(s):
    """(XᵀY)ᵀ(XᵀY) = I_r at r = n (true, control)."""
    M = s.X.T @ s.Y
    return {"o": M.T @ M - s.Ir}


@claim("adv-s37-pole-mixed", kind="id", sizes=admissible(n_min=2, n_max=2, r_is_n=True))
def pole_mixed(s):
    """tr(M)·(1/tr M) = 1 for M = XᵀY at r = n = 2: tr M vanishes identically where XᵀY is a reflection, so the
    statement is undefined on half of the pairs of components (never a pass)."""
    M = s.X.T @ s.Y
    t = s.tr(M)
    return {"p": t * (1 / t) - 1}
