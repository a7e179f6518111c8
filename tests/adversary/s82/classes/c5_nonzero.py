"""Class 5 (float range, error model) on "does not vanish" claims (kind="not", expect="nonzero").

t = tr(PᵀP) (not identically 0 on T*V: TRUE that it does not vanish).
 nz-tiny-true:     2^-1100·t does not vanish: TRUE (a nonzero constant times t).  Underflows to 0 in float64.
 nz-huge-false:    (2^1100·t) − (2^1100·t) does not vanish: FALSE (identically 0).  inf − inf = nan in float64.
 nz-huge2-false:   (2^600·t)·(2^600·t) − (2^600·t)·(2^600·t): FALSE (0).  Overflow to inf, inf − inf.
 nz-absorb-false:  (2^80 + t) − 2^80 − t does not vanish: FALSE (0); absorbed in float to −t or 0.
 nz-absorb-true:   (2^80 + t) − 2^80 does not vanish: TRUE (= t); in float64 the sum may absorb t when t ≪ 2^80·ε.
 nz-div-false:     t/t − 1 does not vanish: FALSE (0 where t ≠ 0).
"""
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)


def _t(s):
    return s.tr(s.P.T @ s.P)


@claim("nz-tiny-true", kind="not", expect="nonzero", sizes=SZ)
def tiny_true(s):
    return {"tiny": _t(s) * Fraction(1, 2 ** 1100)}


@claim("nz-huge-false", kind="not", expect="nonzero", sizes=SZ)
def huge_false(s):
    return {"nan": _t(s) * 2 ** 1100 - _t(s) * 2 ** 1100}


@claim("nz-huge2-false", kind="not", expect="nonzero", sizes=SZ)
def huge2_false(s):
    u = _t(s) * 2 ** 600
    return {"nan": u * u - u * u}


@claim("nz-absorb-false", kind="not", expect="nonzero", sizes=SZ)
def absorb_false(s):
    return {"0": (_t(s) + 2 ** 80) - 2 ** 80 - _t(s)}


@claim("nz-absorb-true", kind="not", expect="nonzero", sizes=SZ)
def absorb_true(s):
    return {"t": (_t(s) + 2 ** 80) - 2 ** 80}


@claim("nz-div-false", kind="not", expect="nonzero", sizes=SZ)
def div_false(s):
    return {"0": _t(s) / _t(s) - 1}
