"""Ranks at every point that hold over the reals only (sums of squares)."""
from stiefelsym import Rank, admissible, claim

SZ = admissible(n_max=4, n_min=2)


@claim("rr-i-plus-psi", paper="test", kind="dim", section="2", sizes=SZ,
       statement=r"\rank(I_r+\Psi)=r \text{ at every point}")
def i_plus_psi(s):
    """I + Psi is invertible at every point (Psi skew): TRUE."""
    return {"rank": Rank(s.Ir + s.Psi, s.r if False else int(s.r), generic=False)}


@claim("rr-ptp-plus-i", paper="test", kind="dim", section="2", sizes=SZ,
       statement=r"\rank(I_r+P^TP)=r")
def ptp(s):
    """I + PᵀP is positive definite: TRUE."""
    return {"rank": Rank(s.Ir + s.P.T @ s.P, int(s.r), generic=False)}


@claim("rr-one-plus-trptp", paper="test", kind="dim", section="2", sizes=SZ,
       statement=r"\rank[1+tr P^TP]=1")
def onep(s):
    """[[1 + tr PᵀP]] has rank 1 everywhere: TRUE."""
    M = s.mat([[s.const(1) + s.tr(s.P.T @ s.P)]])
    return {"rank": Rank(M, 1, generic=False)}


@claim("rr-xx-col", paper="test", kind="dim", section="2", sizes=SZ,
       statement=r"\rank X=r")
def xrank(s):
    """X has rank r everywhere (XᵀX = I): TRUE."""
    return {"rank": Rank(s.X, int(s.r), generic=False)}
