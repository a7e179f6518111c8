"""Free method: scalars that are 1×1 words (a row vector times a column vector), not traces.  NCPoly._divisor_value
refuses trace monomials only, and scalar_value() returns the coefficient of the empty word: a word of a scalar
would be dropped from a divisor.

Truth (by hand): u (1×r) and v (r×1) generic, u·v a generic nonzero number; w = XᵀX-free constants.
rv-inv-f     1/(1 + u v) − 1 = 0                       FALSE (u v ≠ 0 generic)
rv-inv-t     (1 + u v)·(1/(1 + u v)) − 1 = 0           TRUE
rv-uv-f      1/(u v) − 1                               FALSE
rv-x-f       X·(1/(2 + u Xᵀ X v)) − X/2              FALSE (uXᵀXv = uv ≠ 0)
rv-fresh-f   the same with s.fresh(1, "r"), s.fresh("r", 1)   FALSE
rv-mul-t     (u v)·X − X·(u v)                          TRUE (a scalar commutes) -- control that words work at all
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def _uv(s):
    u = s.generic("u", 1, "r")
    v = s.generic("v", "r", 1)
    return u, v


@claim("rv-inv-f", kind="id", sizes=SZ)
def inv_f(s):
    u, v = _uv(s)
    return {"x": 1 / (1 + u @ v) - 1}


@claim("rv-inv-t", kind="id", sizes=SZ)
def inv_t(s):
    u, v = _uv(s)
    w = u @ v
    return {"x": (1 + w) * (1 / (1 + w)) - 1}


@claim("rv-uv-f", kind="id", sizes=SZ)
def uv_f(s):
    u, v = _uv(s)
    return {"x": 1 / (u @ v) - 1}


@claim("rv-x-f", kind="id", sizes=SZ)
def x_f(s):
    u, v = _uv(s)
    return {"x": s.X * (1 / (2 + u @ s.X.T @ s.X @ v)) - s.X / 2}


@claim("rv-fresh-f", kind="id", sizes=SZ)
def fresh_f(s):
    u, v = s.fresh(1, "r"), s.fresh("r", 1)
    return {"x": 1 / (1 + u @ v) - 1}


@claim("rv-mul-t", kind="id", sizes=SZ)
def mul_t(s):
    u, v = _uv(s)
    return {"x": (u @ v) * s.X - s.X * (u @ v)}
