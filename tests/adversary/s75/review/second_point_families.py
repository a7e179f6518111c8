"""The second point (Y, Q) of T*V in the families r = 1 and r = n, where the dimension-free method has column
and square scenes.  Docstrings state the truth."""
from stiefelsym import admissible, claim

R1 = admissible(n_max=4, r_max=1, condition="r = 1")
RN = admissible(n_max=4, where=lambda n, r: r == n, condition="r = n")


@claim("s75-y-r1-qty", kind="id", sizes=R1)
def y_r1_qty(s):
    """QᵀY = 0 at r = 1: TRUE (YᵀQ + QᵀY = 2QᵀY = 0)."""
    return {"w": s.Q.T @ s.Y}


@claim("s75-y-r1-pty", kind="id", sizes=R1)
def y_r1_pty(s):
    """PᵀY = 0 at r = 1: FALSE (P is tangent at X, not at Y)."""
    return {"w": s.P.T @ s.Y}


@claim("s75-y-r1-xty-sym", kind="id", sizes=R1)
def y_r1_xty_sym(s):
    """XᵀY − YᵀX = 0 at r = 1: TRUE (1 x 1)."""
    return {"w": s.X.T @ s.Y - s.Y.T @ s.X}


@claim("s75-y-rn-yyt", kind="id", sizes=RN)
def y_rn_yyt(s):
    """YYᵀ = I_n at r = n: TRUE."""
    return {"w": s.Y @ s.Y.T - s.In}


@claim("s75-y-rn-p-through-y", kind="id", sizes=RN)
def y_rn_p_through_y(s):
    """P = YYᵀP at r = n: TRUE (YYᵀ = I)."""
    return {"w": s.P - s.Y @ s.Y.T @ s.P}


@claim("s75-y-rn-xyt-sym", kind="id", sizes=RN)
def y_rn_xyt_sym(s):
    """XᵀY symmetric at r = n: FALSE (n >= 2)."""
    return {"w": s.X.T @ s.Y - s.Y.T @ s.X}


@claim("s75-y-rn-cross-tangent", kind="id", sizes=RN)
def y_rn_cross_tangent(s):
    """YᵀP + PᵀY = 0 at r = n: FALSE (P tangent at X only)."""
    return {"w": s.Y.T @ s.P + s.P.T @ s.Y}


@claim("s75-y-rn-tr-xty-sq", kind="id", sizes=RN)
def y_rn_tr(s):
    """tr((XᵀY)(XᵀY)ᵀ) = n at r = n: TRUE (XᵀY orthogonal)."""
    M = s.X.T @ s.Y
    return {"w": s.tr(M @ M.T) - s.tr(s.In)}


@claim("s75-y-all-tr", kind="id", sizes=admissible(n_max=4))
def y_all_tr(s):
    """tr((XᵀY)(XᵀY)ᵀ) = r: FALSE for r < n (true at r = n)."""
    M = s.X.T @ s.Y
    return {"w": s.tr(M @ M.T) - s.tr(s.Ir)}
