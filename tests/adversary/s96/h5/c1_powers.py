"""Degree without pow nodes (repeated squaring by products), and exponents the power gate may not read."""
from fractions import Fraction

import numpy as np

from stiefelsym import admissible, claim

SZ = admissible(n_min=2, n_max=3, r_max=1)


def u(s):
    return s.tr(s.X.T @ s.A @ s.X)


def squarings(x, k):
    for _ in range(k):
        x = x * x
    return x


@claim("h5p-mono-squarings-true", kind="id", sizes=SZ)
def mono_squarings_true(s):
    """True: u^(2^40) (u + 1) - u^(2^40) u - u^(2^40) = 0, u^(2^40) by 40 products."""
    w = squarings(u(s), 40)
    return {"r": w * (u(s) + 1) - w * u(s) - w}


@claim("h5p-mono-squarings-false", kind="id", sizes=SZ)
def mono_squarings_false(s):
    """False: u^(2^40) - u^(2^40 - 1)... as w*u - w = 0."""
    w = squarings(u(s), 40)
    return {"r": w * u(s) - w}


@claim("h5p-binom-squarings-true", kind="id", sizes=SZ)
def binom_squarings_true(s):
    """True: w (u + 2) - w u - 2 w = 0 with w = (u + 1)^(2^30) by 30 products."""
    w = squarings(u(s) + 1, 30)
    return {"r": w * (u(s) + 2) - w * u(s) - 2 * w}


@claim("h5p-ratio-squarings-false", kind="id", sizes=SZ)
def ratio_squarings_false(s):
    """False: w - 1 = 0 with w = ((u + 1)/(u + 2))^(2^30) by 30 products."""
    w = squarings((u(s) + 1) / (u(s) + 2), 30)
    return {"r": w - 1}


@claim("h5p-numpy-exp-false", kind="id", sizes=SZ)
def numpy_exp_false(s):
    """False: u^(2^40) - u^(2^40 - 1) = 0, exponents numpy ints."""
    return {"r": u(s) ** np.int64(2 ** 40) - u(s) ** np.int64(2 ** 40 - 1)}


@claim("h5p-fraction-exp-false", kind="id", sizes=SZ)
def fraction_exp_false(s):
    """False: u^(2^40) - u^(2^40 - 1) = 0, exponents Fractions with denominator 1."""
    return {"r": u(s) ** Fraction(2 ** 40) - u(s) ** Fraction(2 ** 40 - 1)}


@claim("h5p-bool-exp-true", kind="id", sizes=SZ)
def bool_exp_true(s):
    """True: u^True - u = 0."""
    return {"r": u(s) ** True - u(s)}


def p20(x):
    return x ** 20


@claim("h5p-nested-user-pow-false", kind="id", sizes=SZ)
def nested_user_pow_false(s):
    """False: p20 applied 8 times (u^(20^8)) minus u."""
    w = u(s)
    for _ in range(8):
        w = p20(w)
    return {"r": w - u(s)}


@claim("h5p-matpow-false", kind="id", sizes=SZ)
def matpow_false(s):
    """False: (X^T A X)^(2^40) - (X^T A X)^(2^40 - 1) via matrix products by squaring (r = 1: 1x1)."""
    m = s.X.T @ s.A @ s.X
    w = m
    for _ in range(40):
        w = w @ w
    return {"r": w @ m - w}


@claim("h5p-trace-squarings-false", kind="id", sizes=SZ)
def trace_squarings_false(s):
    """False: t = tr((t I_r)(t I_r)) / r forty times from t = u, i.e. u^(2^40), minus itself times u (each squaring
    passes through a call of the scene, s.tr, whose argument sits in a tuple of the call node)."""
    t = u(s)
    for _ in range(40):
        m = s.Ir * t
        t = s.tr(m @ m) / s.r
    return {"r": t * u(s) - t}


@claim("h5p-squarings-then-power-false", kind="id", sizes=SZ)
def squarings_then_power_false(s):
    """False: x u − x = 0 for x = (u^(2^14))^256, fourteen squarings then a power 256: each below its own gate (the
    products' degree 3·2^14, the power 256), the two together of degree 3·2^22 (the exact method ran past 100 s)."""
    x = u(s)
    for _ in range(14):
        x = x * x
    x = x ** 256
    return {"r": x * u(s) - x}
