"""Large exponents: a residual that is nonzero but tiny (float underflow) or of huge degree (Schwartz-Zippel)."""
from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3)


def c(s):
    t = s.tr(s.P.T @ s.P) + s.tr(s.X.T @ s.A @ s.X) ** 2
    return t / (t + 1)


@claim("h2f-pow-small", kind="id", sizes=SZ)
def pow_small(s):
    """False: (t/(t+1))^4096 = 0."""
    return {"r": c(s) ** 4096}


@claim("h2f-pow-huge", kind="id", sizes=SZ)
def pow_huge(s):
    """False: (t/(t+1))^(2^40) = 0."""
    return {"r": c(s) ** (2 ** 40)}


@claim("h2f-pow-diff", kind="id", sizes=SZ)
def pow_diff(s):
    """False: u^(2^62) - u^(2^62 + 2^61) = 0 with u = t + 2."""
    u = s.tr(s.P.T @ s.P) + 2
    return {"r": u ** (2 ** 62) - u ** (2 ** 62 + 2 ** 61)}


@claim("h2f-pow-nonzero", kind="not", expect="nonzero", sizes=SZ)
def pow_nonzero(s):
    """True: (t/(t+1))^(2^40) is not identically 0."""
    return {"r": c(s) ** (2 ** 40)}


@claim("h2f-sum-cancel", kind="id", sizes=SZ)
def sum_cancel(s):
    """False: (u + 2^-2000... ) written as u*2^2000 + 1 - u*2^2000 = 0 (it is 1)."""
    u = s.tr(s.P.T @ s.P) + 1
    big = 2 ** 2000
    return {"r": (u * big + 1) - u * big}


@claim("h2f-neg-pow", kind="id", sizes=SZ)
def neg_pow(s):
    """False: u^-3000 = 0 with u = tr P^T P + 2."""
    u = s.tr(s.P.T @ s.P) + 2
    return {"r": u ** -3000}
