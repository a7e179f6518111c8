"""Class 2 and 5: constants in disguise and constants at the edge of the float range (new variants).

* A Fraction whose internals are not ints (made with Fraction.__new__ and its slots set by hand): type(c) is
  Fraction, so the tracer's type test passes; c._numerator a float 0.1, a numpy float, an int subclass
  that lies about equality, or a zero denominator.
* Constants beyond Python's int<->str digit limit (sys.int_info.default_max_str_digits = 4300 in 3.11):
  10**5000 as a factor of a true identity (cX − cX = 0, TRUE) and of a false one (cX = 0, FALSE).
* Fraction(1, 10**5000): far below the float range.
Truth is stated per claim.
"""
from fractions import Fraction
from stiefelsym import admissible, claim

SZ = admissible(n_max=3)


def forged(num, den=1):
    f = Fraction.__new__(Fraction)
    object.__setattr__(f, "_numerator", num) if False else None
    f._numerator = num
    f._denominator = den
    return f


class LyingInt(int):
    def __eq__(self, other):
        return False

    def __ne__(self, other):
        return True

    __hash__ = int.__hash__

    def __bool__(self):
        return True


@claim("c2-fraction-float-inside", paper="t", kind="id", section="0", sizes=SZ)
def frac_float(s):
    """(0.1 + 0.2 − 0.3)·tr(PᵀP) with each as a Fraction holding a float: exactly 1/10+2/10-3/10 = 0 (TRUE as
    exact numbers); in floats 5.55e-17·tr PᵀP ≠ 0."""
    a, b, c = forged(0.1), forged(0.2), forged(0.3)
    return {"x": (a + b - c) * s.tr(s.P.T @ s.P)}


@claim("c2-fraction-float-inside-false", paper="t", kind="id", section="0", sizes=SZ)
def frac_float_false(s):
    """forged(1e-300)·X = 0: FALSE as an exact constant 10⁻³⁰⁰ (X ≠ 0)."""
    return {"x": forged(1e-300) * s.X}


@claim("c2-fraction-lying-zero", paper="t", kind="id", section="0", sizes=SZ)
def frac_lying_zero(s):
    """X / c with c a Fraction whose numerator is LyingInt(0) (== 0 says False): a division by 0, undefined."""
    return {"x": s.X / forged(LyingInt(0)) - s.X}


@claim("c2-fraction-zero-den", paper="t", kind="id", section="0", sizes=SZ)
def frac_zero_den(s):
    """c·X with c = 1/0 forged: undefined."""
    return {"x": forged(1, 0) * s.X}


@claim("c2-fraction-unnormalised", paper="t", kind="id", section="0", sizes=SZ)
def frac_unnormalised(s):
    """c·tr(PᵀP) − tr(PᵀP)/2·... with c = 2/4 unreduced (value 1/2): c·tr PᵀP − ½ tr PᵀP = 0, TRUE."""
    return {"x": forged(2, 4) * s.tr(s.P.T @ s.P) - s.q(1, 2) * s.tr(s.P.T @ s.P)}


@claim("c2-fraction-negative-den", paper="t", kind="id", section="0", sizes=SZ)
def frac_negative_den(s):
    """c·X + X with c = 1/(−1) forged (value −1): −X + X = 0, TRUE (but c._numerator = 1 > 0)."""
    return {"x": forged(1, -1) * s.X + s.X}


BIG = 10 ** 5000


@claim("c2-huge-int-true", paper="t", kind="id", section="0", sizes=SZ)
def huge_true(s):
    """(10^5000 X) − 10^5000 X = 0: TRUE."""
    return {"x": BIG * s.X - BIG * s.X}


@claim("c2-huge-int-false", paper="t", kind="id", section="0", sizes=SZ)
def huge_false(s):
    """(10^5000 + 1) X − 10^5000 X = 0: FALSE (= X)."""
    return {"x": (BIG + 1) * s.X - BIG * s.X}


@claim("c2-tiny-fraction-false", paper="t", kind="id", section="0", sizes=SZ)
def tiny_false(s):
    """10^-5000 · tr(PᵀP) = 0: FALSE."""
    return {"x": Fraction(1, BIG) * s.tr(s.P.T @ s.P)}


@claim("c2-tiny-cancel-true", paper="t", kind="id", section="0", sizes=SZ)
def tiny_true(s):
    """(1 + 10^-400) tr(PᵀP) − tr(PᵀP) − 10^-400 tr(PᵀP) = 0: TRUE; in floats (1+ε) = 1 absorbs."""
    e = Fraction(1, 10 ** 400)
    t = s.tr(s.P.T @ s.P)
    return {"x": (1 + e) * t - t - e * t}


@claim("c2-tiny-absorbed-false", paper="t", kind="id", section="0", sizes=SZ)
def tiny_absorbed_false(s):
    """(1 + 10^-300) tr(PᵀP) − tr(PᵀP) = 0: FALSE (= 10^-300 tr PᵀP); both constants within 2^±1000."""
    e = Fraction(1, 10 ** 300)
    t = s.tr(s.P.T @ s.P)
    return {"x": (1 + e) * t - t}


@claim("c2-pow-underflow-false", paper="t", kind="id", section="0", sizes=SZ)
def pow_underflow_false(s):
    """(10^-200 tr PᵀP)^2 = 0: FALSE; each constant in range, the power underflows float64."""
    return {"x": (Fraction(1, 10 ** 200) * s.tr(s.P.T @ s.P)) ** 2}


@claim("c2-pow-overflow-true", paper="t", kind="id", section="0", sizes=SZ)
def pow_overflow_true(s):
    """(10^200 tr PᵀP)^2 − 10^400 (tr PᵀP)^2 ... written (c t)^2 − c (c t^2) with c = 10^200: TRUE; the
    float evaluation overflows to inf − inf."""
    c = 10 ** 200
    t = s.tr(s.P.T @ s.P)
    return {"x": (c * t) ** 2 - c * (c * (t * t))}
