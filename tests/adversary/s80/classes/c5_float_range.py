"""Class 5: constants and powers outside the float range, new shapes.

f5-inf-true:   TRUE  (c·X)·(1/c) − X with c = 10^400 (inf in float64; inf·0 or inf/inf = nan)
f5-inf-sub-true: TRUE (c + tr(XᵀX)) − c − r with c = 10^400 (inf − inf)
f5-tiny-false: FALSE (c·c)·(XXᵀ − I_n) with c = 2^-600 (c² underflows to 0 in float64)
f5-tiny-true:  TRUE  (c·c)·(XᵀX − I_r)
f5-digits-true: TRUE  s.q(1, 10^5000)·(XᵀX − I_r): a constant of 5001 digits (Python's int→str limit is 4300)
f5-digits-false: FALSE s.q(1, 10^5000)·(XXᵀ − I_n)
f5-pow-true:   TRUE  u^(2^20) − u^(2^20) · 1 written as u^(2^20)·(tr XᵀX − r + 1) − u^(2^20), u = tr PᵀP + 3
f5-pow-false:  FALSE u^(2^20)·(XXᵀ − I_n)·c, u = tr PᵀP + 3 (overflow to inf times a residual), c = 10^-400
f5-denorm-false: FALSE 2^-1074·(XXᵀ − I_n)·2^1000 (a subnormal times a huge number; ok in exact)
"""
from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)
BIG = 10 ** 400


@claim("f5-inf-true", kind="id", sizes=SZ)
def f5_inf_true(s):
    c = s.q(BIG, 1)
    return {"r": (s.X * c) * (1 / c) - s.X}


@claim("f5-inf-sub-true", kind="id", sizes=SZ)
def f5_inf_sub_true(s):
    c = s.q(BIG, 1)
    return {"r": (c + s.tr(s.X.T @ s.X)) - c - s.tr(s.Ir)}


@claim("f5-tiny-false", kind="id", sizes=SZ)
def f5_tiny_false(s):
    c = s.q(1, 2 ** 600)
    return {"r": (c * c) * (s.X @ s.X.T - s.In)}


@claim("f5-tiny-true", kind="id", sizes=SZ)
def f5_tiny_true(s):
    c = s.q(1, 2 ** 600)
    return {"r": (c * c) * (s.X.T @ s.X - s.Ir)}


@claim("f5-digits-true", kind="id", sizes=SZ)
def f5_digits_true(s):
    return {"r": s.q(1, 10 ** 5000) * (s.X.T @ s.X - s.Ir)}


@claim("f5-digits-false", kind="id", sizes=SZ)
def f5_digits_false(s):
    return {"r": s.q(1, 10 ** 5000) * (s.X @ s.X.T - s.In)}


@claim("f5-pow-true", kind="id", sizes=SZ)
def f5_pow_true(s):
    u = s.tr(s.P.T @ s.P) + 3
    k = u ** (2 ** 20)
    return {"r": k * (s.tr(s.X.T @ s.X) - s.tr(s.Ir) + 1) - k}


@claim("f5-pow-false", kind="id", sizes=SZ)
def f5_pow_false(s):
    u = s.tr(s.P.T @ s.P) + 3
    return {"r": (u ** (2 ** 20)) * s.q(1, BIG) * (s.X @ s.X.T - s.In)}


@claim("f5-denorm-false", kind="id", sizes=SZ)
def f5_denorm_false(s):
    return {"r": s.q(1, 2 ** 1074) * (s.X @ s.X.T - s.In) * s.q(2 ** 1000, 1)}
