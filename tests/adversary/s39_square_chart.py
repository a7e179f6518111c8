"""Round 10, the chart X = I at r = n (and the Woodbury chart just below): statements true on the chart's
point X = I but false on T*V(n, n), written with the public API.  ℝⁿ and ℝʳ stay different spaces at r = n,
and an untyped identity or zero takes the spaces of what it meets, so each false statement is refused when
traced; the true controls are proved."""
from stiefelsym import Size, SizeSpec, claim

SQ = SizeSpec((Size(3, 3), Size(4, 4)), r_is_n=True)      # stated at r = n only
NEAR = SizeSpec((Size(4, 3), Size(5, 4)), where=lambda n, r: r == n - 1, condition="r = n - 1")


@claim("adv-s39-sq-p-skew", paper="adv", kind="id", sizes=SQ)
def p_skew(s):
    """False: P + Pᵀ = 0 (P = W skew on the chart)."""
    return {"P + P^T": s.P + s.P.T}


@claim("adv-s39-sq-trace-x", paper="adv", kind="id", sizes=SQ)
def trace_x(s):
    """False: tr X = n."""
    return {"tr X - n": s.X.trace() - s.n}


@claim("adv-s39-sq-x-sym-untyped-identity", paper="adv", kind="id", sizes=SQ)
def x_sym(s):
    """False: X symmetric, X's sides closed by an untyped identity."""
    E = s.identity(s.n, "?")
    return {"XE - EX^T": s.X @ E - E @ s.X.T}


@claim("adv-s39-sq-x-sym-untyped-zero", paper="adv", kind="id", sizes=SQ)
def x_sym_zero(s):
    """False: X symmetric, X made square by an untyped identity on ℝʳ and an untyped zero."""
    Xu = s.X @ s.identity(s.r, "?") + s.zeros(s.n, s.n, ("?", "?"))
    return {"Xu - Xu^T": Xu - Xu.T}


@claim("adv-s39-sq-xxt-true", paper="adv", kind="id", sizes=SQ)
def xxt(s):
    """True at r = n: XXᵀ = I."""
    return {"XX^T - I": s.X @ s.X.T - s.In}


@claim("adv-s39-sq-untyped-true", paper="adv", kind="id", sizes=SQ)
def untyped_true(s):
    """True: XᵀEX = I_r with E an untyped identity."""
    E = s.identity(s.n, "?")
    return {"X^T E X - I": s.X.T @ E @ s.X - s.Ir}


@claim("adv-s39-near-xtax-true", paper="adv", kind="id", sizes=NEAR)
def xtax(s):
    """True: XᵀAX symmetric (the Woodbury chart, n - r < r)."""
    M = s.X.T @ s.A @ s.X
    return {"M - M^T": M - M.T}
