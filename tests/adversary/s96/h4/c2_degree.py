"""Stop 96, h4: the degree guard of the exact and rational methods (EXPANDABLE_DEGREE = 2^20) against powers that
cancel, negative powers, powers hidden in resolvents, inverses and derivatives, and degree-0 powers of huge bases."""
from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3, r_max=1)
K = 2 ** 21


def u(s):
    return s.tr(s.X.T @ s.A @ s.X)


@claim("h4t-negpow-true", kind="id", sizes=SZ)
def negpow_true(s):
    """True: w^(-2^21) w^(2^21) - 1 = 0, w = (u + 1)/(u + 2)."""
    w = (u(s) + 1) / (u(s) + 2)
    return {"r": w ** (-K) * w ** K - 1}


@claim("h4t-negpow-false", kind="id", sizes=SZ)
def negpow_false(s):
    """False: w^(2^21) - w^(2^21 - 1) = 0."""
    w = (u(s) + 1) / (u(s) + 2)
    return {"r": w ** K - w ** (K - 1)}


@claim("h4t-zero-pow-true", kind="id", sizes=SZ)
def zero_pow_true(s):
    """True: (u - u)^(2^40) = 0."""
    return {"r": (u(s) - u(s)) ** (2 ** 40)}


@claim("h4t-pow0-true", kind="id", sizes=SZ)
def pow0_true(s):
    """True: (u^(2^40))^0 - 1 = 0."""
    return {"r": (u(s) ** (2 ** 40)) ** 0 - 1}


@claim("h4t-resolvent-pow-false", kind="id", sizes=SZ)
def resolvent_pow_false(s):
    """False: (mu I - A)^-1 (mu I - A) - I + X X^T = 0 at mu = (u + 3)^(2^21) (it is X X^T)."""
    mu = (u(s) + 3) ** K
    return {"r": s.resolvent(mu) @ (s.In * mu - s.A) - s.In + s.X @ s.X.T}


@claim("h4t-resolvent-pow-true", kind="id", sizes=SZ)
def resolvent_pow_true(s):
    """True: (mu I - A)^-1 (mu I - A) - I = 0 at mu = (u + 3)^(2^21)."""
    mu = (u(s) + 3) ** K
    return {"r": s.resolvent(mu) @ (s.In * mu - s.A) - s.In}


@claim("h4t-d-pow-false", kind="id", sizes=SZ)
def d_pow_false(s):
    """False: d/dt (u^(2^21)) along X' = X, P' = 0 equals 0 (it is 2^22 u^(2^21))."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X) ** K, {"X": s.X, "P": s.P * 0})}


@claim("h4t-d-pow-true", kind="id", sizes=SZ)
def d_pow_true(s):
    """True: d/dt (u^(2^21)) along X' = X, P' = 0 equals 2^22 u^(2^21)."""
    return {"r": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X) ** K, {"X": s.X, "P": s.P * 0}) - 2 * K * u(s) ** K}


@claim("h4t-sum-degree-false", kind="id", sizes=SZ)
def sum_degree_false(s):
    """False: sum over j of (u^(2^19))^4 - u^(2^21) ... one term short: u^(2^21) = 0 remains."""
    a = u(s) ** (2 ** 19)
    return {"r": a * a * a * a * 2 - u(s) ** K}


@claim("h4t-times-zero-true", kind="id", sizes=SZ)
def times_zero_true(s):
    """True: 0 u^(2^40) = 0 (a value of degree 2^40 on the way to a residual of none)."""
    return {"r": u(s) ** (2 ** 40) * 0}


@claim("h4t-recip-pow0-true", kind="id", sizes=SZ)
def recip_pow0_true(s):
    """True: ((1/u)^(2^40))^0 - 1 = 0 (a denominator of degree 2^40 on the way)."""
    return {"r": ((1 / u(s)) ** (2 ** 40)) ** 0 - 1}


@claim("h4t-pow0-false", kind="id", sizes=SZ)
def pow0_false(s):
    """False: (u^(2^40))^0 - 1 + tr(X^T X) = 0 (it is r)."""
    return {"r": (u(s) ** (2 ** 40)) ** 0 - 1 + s.tr(s.X.T @ s.X)}
