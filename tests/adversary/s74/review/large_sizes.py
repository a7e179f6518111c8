"""Claims at large sizes ((40,20), (60,30): the ball method's midpoint-radius rung runs from n = 32 on) with
exact structural zeros, tiny and huge scales, cancellation between terms of very different sizes, residuals that
are sums of many terms, scalar (trace) and matrix residuals, and nonvanishing twins.  The truth is in each
docstring."""
from stiefelsym import admissible, block, claim

SZ = admissible(n_max=3)
C = 2**60


@claim("s74-big-power", kind="id", sizes=SZ)
def big_power(s):
    """(XXᵀ)¹² X − X = 0: TRUE on V (XᵀX = I)."""
    M = s.X
    for _ in range(12):
        M = s.X @ (s.X.T @ M)
    return {"w": M - s.X}


@claim("s74-big-many-terms", kind="id", sizes=SZ)
def many_terms(s):
    """Σ_{k=0}^{30} (Xᵀ(XXᵀ)ᵏX − I_r) = 0 as one residual (31 terms): TRUE."""
    total = s.Ir - s.Ir
    M = s.X
    for _ in range(31):
        total = total + (s.X.T @ M - s.Ir)
        M = s.X @ (s.X.T @ M)
    return {"w": total, "tr": s.tr(total)}


@claim("s74-big-tiny", kind="id", sizes=SZ)
def tiny(s):
    """2⁻¹⁰⁰⁰ (XᵀX − I) and 2⁻¹⁰⁰⁰ tr(XᵀAX − XᵀAX): TRUE (tiny scales)."""
    e = s.q(1, 2**1000)
    return {"w": (s.X.T @ s.X - s.Ir) * e, "t": s.tr(s.X.T @ s.A @ s.X) * e - s.tr(s.A @ s.X @ s.X.T) * e}


@claim("s74-big-huge", kind="id", sizes=SZ)
def huge(s):
    """2¹⁰⁰⁰ (XᵀX − I): TRUE (huge scale)."""
    return {"w": (s.X.T @ s.X - s.Ir) * 2**1000}


@claim("s74-big-cancel", kind="id", sizes=SZ)
def cancel(s):
    """((C XᵀX + XᵀX) − C XᵀX) − I = 0 with C = 2⁶⁰: TRUE (cancellation between terms of sizes 1 and 2⁶⁰)."""
    G = s.X.T @ s.X
    return {"w": ((G * C + G) - G * C) - s.Ir}


@claim("s74-big-structural", kind="id", sizes=SZ)
def structural(s):
    """[[XᵀX − I, 0], [0, PᵀX + XᵀP]] = 0: TRUE (exact zero blocks beside rounded ones)."""
    Z = s.zeros(s.r, s.r, ("r", "r"))
    return {"w": block([[s.X.T @ s.X - s.Ir, Z], [Z, s.P.T @ s.X + s.X.T @ s.P]])}


@claim("s74-big-small-false", kind="id", sizes=SZ)
def small_false(s):
    """XᵀX − I + 2⁻⁶⁰ XᵀAX = 0: FALSE (off by 2⁻⁶⁰ of the terms)."""
    return {"w": s.X.T @ s.X - s.Ir + s.X.T @ s.A @ s.X * s.q(1, 2**60)}


@claim("s74-big-nz-zero", kind="not", expect="nonzero", sizes=SZ)
def nz_zero(s):
    """(XXᵀ)⁸X − X is not identically 0: FALSE (it is 0 on V)."""
    M = s.X
    for _ in range(8):
        M = s.X @ (s.X.T @ M)
    return {"w": M - s.X, "t": s.tr(M.T @ M) - s.tr(s.Ir)}


@claim("s74-big-nz-tiny", kind="not", expect="nonzero", sizes=SZ)
def nz_tiny(s):
    """2⁻¹⁰⁶⁰ tr(PᵀP) is not identically 0: TRUE."""
    return {"t": s.tr(s.P.T @ s.P) * s.q(1, 2**1060)}
