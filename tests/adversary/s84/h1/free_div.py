"""h1 (stop 84): divisions on the free scene (and the same claims at fixed sizes).

Notation: n = tr I_n, r = tr I_r (traced sizes), w = tr(PᵀP).

h1-pole-rn        k = 1/(n+r) − 1/(2n) = (n−r)/(2n(n+r)), 0 at r = n.  x = (k·(1/k) − 1)·w.  0/0 at r = n (ill-formed
                  there, an `error` at fixed sizes), 0 where r < n.  Stated for 2 ≤ n ≤ 3 with r = n included: no
                  statement for every n, r follows (the same as s84-inv-size-nr): `proved` under free is WRONG.
h1-pole-rn-x      the same pole, as a matrix: P/k·k − P (ill-formed at r = n).
h1-pole-2r        k = 1/(n+r) − 1/(3r) = (2r−n)/(3r(n+r)), 0 at n = 2r ((2,1), (4,2)).  x = (1/k)·k·X − X: ill-formed
                  at n = 2r, 0 elsewhere.  `proved` for all n, r is WRONG.
h1-pole-2r-f      false twin: (1/k)·k·X − 2X (= −X ≠ 0 where defined): must not be proved.
h1-pole-nested    k = 1/n + 1/r − 4/(n+r) = (n−r)²/(nr(n+r)), 0 at r = n; x = (1/k)·k − 1 (ill-formed at r = n).
h1-nested-ok      k = 1/n + 1/r − 2/(n+r) = (n²+r²)/(nr(n+r)) > 0; x = (1/k)·k − 1: TRUE at every size.
h1-pole-rn-old    the pole of h1-pole-rn written without a number-first division (1/(n+r) as tr(I_n/(n+r))/n): the
                  same ill-formed claim, to see whether the hole predates the new __rtruediv__.
h1-pole-quot      (n−r)/k − 2n(n+r) with k = 1/(n+r) − 1/(2n): 0 where r < n (TRUE there), 0/0 at r = n; stated r < n.
h1-pole-quot-f    false twin: (n−r)/k − 2n(n+r) − 1 (= −1), stated r < n: FALSE.
h1-zero-rational  k = 1/(n+r) − 1/(n+2r) − r/((n+r)(n+2r)) ≡ 0 (identically, as a rational function); x = (1/k)·k − 1:
                  a division by 0 at every size: `error` expected everywhere.
h1-zero-rat-coef  x = k·w with the same k ≡ 0: TRUE (0 at every size; its denominators never vanish).
h1-zero-rat-coef-f false twin: (k + 1/(n+r))·w: FALSE (w ≠ 0).
h1-size-ok        (1/(n+r))·(n+r) − 1: TRUE (n + r > 0).
h1-negpow         r**−1 · r − 1: TRUE (r ≥ 1; x**−1 goes through 1/x, the new __rtruediv__).
h1-negpow-f       r**−2 · r − 1 = 1/r − 1: FALSE at r ≥ 2 (stated with r up to 3; true at r = 1 only).
h1-lam-lam        1/(λ − λ): division by an identically 0 expression: `error` everywhere.
h1-lam-n          X/(λ + n)·(λ + n) − X: TRUE (λ generic).
h1-lam-mix        k = λ(n − r) + λ²: nonzero as a polynomial in λ at every size; (1/k)·k − 1: TRUE.
h1-lam-mix-f      false twin: (1/k)·k·λ − 1 (= λ − 1): FALSE.
h1-tr-xtx-minus-r d = tr(XᵀX) − r = 0 on the Stiefel variety; x = (1/d)·d − 1: a division by 0 at every point:
                  `error` at fixed sizes; free must not prove it (it is not 0 as a free polynomial before rewriting).
h1-tr-xtx         r/tr(XᵀX) − 1: TRUE (tr XᵀX = r); free may refuse (a trace divisor).
h1-fraction       X/Fraction(3, 2)·s.q(3, 2) − X: TRUE.
h1-fraction-f     X/Fraction(2, 3)·s.q(3, 2) − X (= 5/4 X): FALSE.
h1-num-first      (2/n)·n/2 − 1: TRUE (number first, the new __rtruediv__).
h1-num-first-f    2/n − 1: FALSE at n ≠ 2 (stated n = 2..3).
h1-r-minus-1      (1/(r − 1))·(r − 1) − 1 stated at r ≥ 1 (0/0 at r = 1): must not be proved; `error` at r = 1.
h1-q-zero         X / s.q(0, 1): a division by the constant 0 (traced): `error` everywhere.
h1-q-minus        X / (s.q(1, 2) − Fraction(1, 2)): a division by 0 after arithmetic of constants: `error` everywhere.
h1-lam-pole       k = λ·(1/(n+r) − 1/(2n)), 0 at r = n for every λ; x = (1/k)·k·λ − λ: 0/0 at r = n (ill-formed there):
                  `proved` for every n, r is WRONG (the hole of h1-pole-rn with a λ factor).
h1-kappa-zero     1/(κ − κ)·w − 1/(κ − κ)·w: a division by an identically 0 scalar parameter: `error` everywhere (free
                  evaluates 1/0 with symengine: zoo).
"""
from fractions import Fraction

from stiefelsym import admissible, claim

SZ = admissible(n_max=3, n_min=2)
SZ4 = admissible(n_max=4, n_min=2)
LT = admissible(n_max=3, n_min=2, where=lambda n, r: r < n)


def _n(s):
    return s.tr(s.In)


def _r(s):
    return s.tr(s.Ir)


def _w(s):
    return s.tr(s.P.T @ s.P)


def _k_rn(s):
    n, r = _n(s), _r(s)
    return 1 / (n + r) - 1 / (2 * n)


@claim("h1-pole-rn", kind="id", sizes=SZ)
def pole_rn(s):
    k = _k_rn(s)
    return {"x": (k * (1 / k) - 1) * _w(s)}


@claim("h1-pole-rn-x", kind="id", sizes=SZ)
def pole_rn_x(s):
    k = _k_rn(s)
    return {"x": s.P / k * k - s.P}


@claim("h1-pole-2r", kind="id", sizes=SZ4)
def pole_2r(s):
    n, r = _n(s), _r(s)
    k = 1 / (n + r) - 1 / (3 * r)
    return {"x": (1 / k) * k * s.X - s.X}


@claim("h1-pole-2r-f", kind="id", sizes=SZ4)
def pole_2r_f(s):
    n, r = _n(s), _r(s)
    k = 1 / (n + r) - 1 / (3 * r)
    return {"x": (1 / k) * k * s.X - 2 * s.X}


@claim("h1-pole-nested", kind="id", sizes=SZ)
def pole_nested(s):
    n, r = _n(s), _r(s)
    k = 1 / n + 1 / r - 4 / (n + r)
    return {"x": (1 / k) * k - 1}


@claim("h1-nested-ok", kind="id", sizes=SZ)
def nested_ok(s):
    n, r = _n(s), _r(s)
    k = 1 / n + 1 / r - 2 / (n + r)
    return {"x": (1 / k) * k - 1}


@claim("h1-pole-rn-old", kind="id", sizes=SZ)
def pole_rn_old(s):
    n, r = _n(s), _r(s)
    k = s.tr(s.In / (n + r)) / n - s.tr(s.In / (2 * n)) / n
    return {"x": s.P / k * k - s.P}


@claim("h1-pole-quot", kind="id", sizes=LT)
def pole_quot(s):
    n, r = _n(s), _r(s)
    k = _k_rn(s)
    return {"x": (n - r) / k - 2 * n * (n + r)}


@claim("h1-pole-quot-f", kind="id", sizes=LT)
def pole_quot_f(s):
    n, r = _n(s), _r(s)
    k = _k_rn(s)
    return {"x": (n - r) / k - 2 * n * (n + r) - 1}


def _k0(s):
    n, r = _n(s), _r(s)
    return 1 / (n + r) - 1 / (n + 2 * r) - r / ((n + r) * (n + 2 * r))


@claim("h1-zero-rational", kind="id", sizes=SZ)
def zero_rational(s):
    k = _k0(s)
    return {"x": (1 / k) * k - 1}


@claim("h1-zero-rat-coef", kind="id", sizes=SZ)
def zero_rat_coef(s):
    return {"x": _k0(s) * _w(s)}


@claim("h1-zero-rat-coef-f", kind="id", sizes=SZ)
def zero_rat_coef_f(s):
    n, r = _n(s), _r(s)
    return {"x": (_k0(s) + 1 / (n + r)) * _w(s)}


@claim("h1-size-ok", kind="id", sizes=SZ)
def size_ok(s):
    n, r = _n(s), _r(s)
    return {"x": (1 / (n + r)) * (n + r) - 1}


@claim("h1-negpow", kind="id", sizes=SZ)
def negpow(s):
    r = _r(s)
    return {"x": r ** -1 * r - 1}


@claim("h1-negpow-f", kind="id", sizes=SZ)
def negpow_f(s):
    r = _r(s)
    return {"x": r ** -2 * r - 1}


@claim("h1-lam-lam", kind="id", sizes=SZ)
def lam_lam(s):
    return {"x": 1 / (s.lam - s.lam) * _w(s)}


@claim("h1-lam-n", kind="id", sizes=SZ)
def lam_n(s):
    k = s.lam + _n(s)
    return {"x": s.X / k * k - s.X}


@claim("h1-lam-mix", kind="id", sizes=SZ)
def lam_mix(s):
    k = s.lam * (_n(s) - _r(s)) + s.lam * s.lam
    return {"x": (1 / k) * k - 1}


@claim("h1-lam-mix-f", kind="id", sizes=SZ)
def lam_mix_f(s):
    k = s.lam * (_n(s) - _r(s)) + s.lam * s.lam
    return {"x": (1 / k) * k * s.lam - 1}


@claim("h1-tr-xtx-minus-r", kind="id", sizes=SZ)
def tr_xtx_minus_r(s):
    d = s.tr(s.X.T @ s.X) - _r(s)
    return {"x": (1 / d) * d - 1}


@claim("h1-tr-xtx", kind="id", sizes=SZ)
def tr_xtx(s):
    return {"x": _r(s) / s.tr(s.X.T @ s.X) - 1}


@claim("h1-fraction", kind="id", sizes=SZ)
def fraction(s):
    return {"x": s.X / Fraction(3, 2) * s.q(3, 2) - s.X}


@claim("h1-fraction-f", kind="id", sizes=SZ)
def fraction_f(s):
    return {"x": s.X / Fraction(2, 3) * s.q(3, 2) - s.X}


@claim("h1-num-first", kind="id", sizes=SZ)
def num_first(s):
    n = _n(s)
    return {"x": (2 / n) * n / 2 - 1}


@claim("h1-num-first-f", kind="id", sizes=SZ)
def num_first_f(s):
    return {"x": 2 / _n(s) - 1}


@claim("h1-r-minus-1", kind="id", sizes=SZ)
def r_minus_1(s):
    d = _r(s) - 1
    return {"x": (1 / d) * d - 1}


@claim("h1-q-zero", kind="id", sizes=SZ)
def q_zero(s):
    return {"x": s.X / s.q(0, 1)}


@claim("h1-q-minus", kind="id", sizes=SZ)
def q_minus(s):
    return {"x": s.X / (s.q(1, 2) - Fraction(1, 2))}


@claim("h1-lam-pole", kind="id", sizes=SZ)
def lam_pole(s):
    k = s.lam * _k_rn(s)
    return {"x": (1 / k) * k * s.lam - s.lam}


@claim("h1-kappa-zero", kind="id", sizes=SZ)
def kappa_zero(s):
    d = s.kappa - s.kappa
    return {"x": 1 / d * _w(s) - 1 / d * _w(s)}
