"""Statements that something does not vanish, where the something is identically 0 on T*V (a constraint) but not
off it: all FALSE.  A ball or float point slightly off T*V would "prove" them."""
from stiefelsym import claim

SZ = [(3, 2), (4, 4)]


@claim("s75-nz-xtx", kind="not", expect="nonzero", sizes=SZ)
def nz_xtx(s):
    """XᵀX − I does not vanish: FALSE."""
    return {"w": s.X.T @ s.X - s.Ir}


@claim("s75-nz-xtp", kind="not", expect="nonzero", sizes=SZ)
def nz_xtp(s):
    """(XᵀP + PᵀX)·10²⁰⁰ does not vanish: FALSE."""
    return {"w": (s.X.T @ s.P + s.P.T @ s.X) * s.q(10**200, 1)}


@claim("s75-nz-xxt-square", kind="not", expect="nonzero", sizes=[(4, 4), (3, 3)])
def nz_xxt_square(s):
    """(XXᵀ − I)·10³⁰ does not vanish at r = n: FALSE."""
    return {"w": (s.X @ s.X.T - s.In) * s.q(10**30, 1)}


@claim("s75-nz-phi-psi", kind="not", expect="nonzero", sizes=SZ)
def nz_phi_psi(s):
    """(tr ΦΦᵀ − 2tr PᵀP − 2tr K²)·10⁵⁰ does not vanish, K = XᵀP: TRUE (a control; on T*V
    tr ΦΦᵀ = 2tr PᵀP − 2tr K², so the residual is −4 tr K² · 10⁵⁰ = 4|K|²·10⁵⁰, not identically 0)."""
    K = s.X.T @ s.P
    return {"w": (s.tr(s.Phi @ s.Phi.T) - s.tr(s.P.T @ s.P) * 2 - s.tr(K @ K) * 2) * s.q(10**50, 1)}
