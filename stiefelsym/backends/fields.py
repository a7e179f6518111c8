"""Number systems a scene can be evaluated over.

Every field supplies constants, fresh parameters (a symbol, a random exact
number, a random float or a degree marker), a zero test and linear solves.
Matrices are numpy object arrays of field elements, so one piece of claim code
runs over all of them.
"""
from __future__ import annotations

import itertools
import math
import random
from fractions import Fraction
from typing import Any, Callable, Sequence

import numpy as np

from stiefelsym._lazy import lazy, symengine_opaque

flint = lazy("flint", globals())
mpmath = lazy("mpmath", globals())
se = lazy("symengine", globals(), "se")

MERSENNE_61 = 2**61 - 1

#: the modular method draws a fresh prime for every point, uniformly among the primes in
#: [2^PRIME_BITS, 2^(PRIME_BITS + 1)) = [2^62, 2^63): the largest such range whose residues are int64
#: (numpy's parameter draws) and nmod (one machine word).  A point's false-pass bound is about
#: 1/K + d/2^62 (content and Schwartz-Zippel, see ``fixed_size._per_point_bound``), 4 times smaller
#: than over [2^60, 2^61): 2 points reach the target 1e-30 where a point's bound over [2^60, 2^61)
#: was up to about 4e-15, a third point was needed above 1e-15
PRIME_BITS = 62
PRIME_LOW, PRIME_HIGH = 2**PRIME_BITS, 2**(PRIME_BITS + 1)
#: a proven lower bound on the number of primes in [2^62, 2^63).  Rosser-Schoenfeld (1962):
#: x/ln x < pi(x) for x >= 17 and pi(x) < 1.25506 x/ln x for x > 1, hence
#: pi(2^63) - pi(2^62) > 2^63/ln 2^63 - 1.25506 * 2^62/ln 2^62 = 7.65...e16 >= K (checked in the tests)
PRIMES_IN_RANGE_LOWER = 76 * 10**15


def primes_in_range_lower_bound() -> float:
    """Rosser-Schoenfeld's lower bound on pi(PRIME_HIGH) - pi(PRIME_LOW), evaluated at 50 digits."""
    with mpmath.workdps(50):
        lo, hi = mpmath.mpf(PRIME_LOW), mpmath.mpf(PRIME_HIGH)
        return hi / mpmath.log(hi) - mpmath.mpf("1.25506") * lo / mpmath.log(lo)


def random_prime(rng: random.Random) -> int:
    """A prime uniform among the primes in [PRIME_LOW, PRIME_HIGH): uniform odd integers of the range,
    rejected until one is prime (a proven primality test); the seed reproduces it."""
    while True:
        x = PRIME_LOW + 1 + 2 * rng.randrange((PRIME_HIGH - PRIME_LOW) // 2)
        if flint.fmpz(x).is_prime():
            return x


def log2_up(x: int | float) -> float:
    """An upper bound on log2 |x| (x != 0), safe against rounding."""
    v = math.log2(abs(x))
    return v + 1e-9 * max(1.0, abs(v))


_log2 = math.log2


def log2_add(a: float, b: float) -> float:
    """An upper bound on log2(2^a + 2^b), safe against rounding."""
    if a < b:
        a, b = b, a
    if b == -math.inf:
        return a
    # 1e-9 * max(1.0, |a|), without the calls (the markers' sums call this once each)
    return a + _log2(1.0 + 2.0 ** (b - a)) + 1e-9 * (a if a > 1.0 else -a if a < -1.0 else 1.0)


def log2_sum(hs: Sequence[float]) -> float:
    """An upper bound on log2(sum 2^h) (-inf for an empty sum), safe against rounding."""
    hs = [h for h in hs if h != -math.inf]
    if not hs:
        return -math.inf
    top = max(hs)
    s = sum(2.0 ** (h - top) for h in hs)
    return top + math.log2(s) + 1e-9 * max(1.0, abs(top))


class DegenerateError(ArithmeticError):
    """A division by zero at a sampled point (pole, singular system)."""


class ConstantDegenerate(DegenerateError):
    """A constant of the claim vanishes (or has no inverse) modulo the sampled prime: draw another prime."""


class SymbolicBudget(ArithmeticError):
    """A symbolic computation beyond what the exact method attempts."""


def _generator(rng: random.Random) -> "np.random.Generator":
    """A numpy generator seeded by one 64-bit draw of ``rng`` (a block of parameters at once)."""
    return np.random.default_rng(rng.getrandbits(64))


class Field:
    """Base class: exact or approximate scalar arithmetic for scenes."""

    name = "field"
    exact = True
    #: size of the set random parameters are drawn from (Schwartz-Zippel), or None
    sample_size: int | None = None
    #: involution applied to entries by Mat.T (None: entries are commuting scalars)
    star = None
    #: map applied to diagonal entries by Mat.trace (None: entries are scalars)
    entry_trace = None

    @property
    def level(self) -> int:
        """How many layers of engine numbers (dual, reverse, degree-paired) this field's numbers have (see
        :func:`tower_level`): a dual or reverse field lifts a number of a lower level as a constant."""
        lv = self.__dict__.get("_level")
        if lv is None:
            lv = self.__dict__["_level"] = tower_level(self.const(0))
        return lv

    def const(self, q: int | Fraction) -> Any:
        raise NotImplementedError

    def param(self, name: str, rng: random.Random | None) -> Any:
        raise NotImplementedError

    def param_values(self, rng: random.Random, count: int) -> "np.ndarray | None":
        """``count`` parameters drawn at once as raw numbers (the distribution of :meth:`param`,
        from a numpy generator seeded by one draw of ``rng``), or None where the field draws one
        at a time.  :meth:`param_from_raw` turns one raw number into a field element."""
        return None

    def param_from_raw(self, x: Any) -> Any:
        raise NotImplementedError

    def params_from_raw(self, vals: "np.ndarray") -> list:
        """[param_from_raw(x) for x in vals], in order."""
        return [self.param_from_raw(x) for x in vals.tolist()]

    def is_zero(self, x: Any) -> bool:
        raise NotImplementedError

    def normalize(self, x: Any) -> Any:
        return x

    def pairing(self, x: Any) -> Any:
        """A scalar a pairing or trace of matrices computed, as the scene hands it on (by default
        normalized; a backend may keep a scalar of its own that computes exactly as it is)."""
        return self.normalize(x)

    def exact_input(self, x: Any) -> Any:
        """A computed value taken as an exact input of the problem (hard cases)."""
        return x

    def is_exact_zero(self, x: Any) -> bool:
        """Whether x is exactly zero (an elimination step with it may be skipped)."""
        return self.is_zero(x)

    def absorb(self, a: Any, g: Any, b: Any) -> Any:
        """a - g b where g is zero up to its error bound: an approximate field keeps a and widens
        its bound by |g b| instead (no cancellation noise, no growth of the scale)."""
        return self.normalize(a - g * b)

    def pivot_cost(self, x: Any) -> float:
        """Smaller is a better pivot; inf means the entry is zero."""
        return 0.0 if not self.is_zero(x) else math.inf

    def describe(self, x: Any) -> str:
        return str(x)

    # -- linear algebra ---------------------------------------------------
    def solve(self, M: Sequence[Sequence[Any]], B: Sequence[Sequence[Any]]) -> list[list[Any]]:
        """Solve M Y = B by Gaussian elimination with the field's pivot choice."""
        m = len(M)
        k = len(B[0]) if B else 0
        rows = [list(M[i]) + list(B[i]) for i in range(m)]
        for col in range(m):
            best, best_cost = None, math.inf
            for i in range(col, m):
                c = self.pivot_cost(rows[i][col])
                if c < best_cost:
                    best, best_cost = i, c
            if best is None:
                raise DegenerateError("singular linear system")
            rows[col], rows[best] = rows[best], rows[col]
            piv = rows[col][col]
            for i in range(m):
                if i == col:
                    continue
                f = rows[i][col]
                if self.is_exact_zero(f):
                    continue
                f = self.normalize(f / piv)
                if not self.exact and self.is_zero(f):      # zero only up to its error bound
                    rows[i] = [self.absorb(a, f, b) if j >= col else a
                               for j, (a, b) in enumerate(zip(rows[i], rows[col]))]
                    continue
                rows[i] = [self.normalize(a - f * b) if j >= col else a
                           for j, (a, b) in enumerate(zip(rows[i], rows[col]))]
            rows[col] = [self.normalize(a / piv) if j >= col else a for j, a in enumerate(rows[col])]
        return [row[m:m + k] for row in rows]

    def rank(self, M: Sequence[Sequence[Any]]) -> int:
        rows = [list(r) for r in M]
        if not rows:
            return 0
        rank, ncols = 0, len(rows[0])
        for col in range(ncols):
            best, best_cost = None, math.inf
            for i in range(rank, len(rows)):
                c = self.pivot_cost(rows[i][col])
                if c < best_cost:
                    best, best_cost = i, c
            if best is None:
                continue
            rows[rank], rows[best] = rows[best], rows[rank]
            piv = rows[rank][col]
            for i in range(rank + 1, len(rows)):
                f = rows[i][col]
                if self.is_exact_zero(f):
                    continue
                f = self.normalize(f / piv)
                if not self.exact and self.is_zero(f):
                    rows[i] = [self.absorb(a, f, b) for a, b in zip(rows[i], rows[rank])]
                    continue
                rows[i] = [self.normalize(a - f * b) for a, b in zip(rows[i], rows[rank])]
            rank += 1
        return rank


# ---------------------------------------------------------------------------
class RationalField(Field):
    """Exact rationals (python-flint fmpq); parameters are uniform integers in [-B, B]."""

    name = "rational"

    def __init__(self, bound: int = 2**62) -> None:
        self.bound = bound
        self.sample_size = 2 * bound + 1

    def const(self, q):
        q = Fraction(q)
        return flint.fmpq(q.numerator, q.denominator)

    def param(self, name, rng):
        return flint.fmpq(rng.randint(-self.bound, self.bound))

    def param_values(self, rng, count):
        if self.bound >= 2**63:
            return None
        return _generator(rng).integers(-self.bound, self.bound, size=count, endpoint=True)

    def param_from_raw(self, x):
        return flint.fmpq(int(x))

    def is_zero(self, x):
        return x == 0

    def solve(self, M, B):
        try:
            sol = flint.fmpq_mat([list(map(self._q, r)) for r in M]).solve(
                flint.fmpq_mat([list(map(self._q, r)) for r in B]))
        except ZeroDivisionError as exc:
            raise DegenerateError("singular linear system") from exc
        return [[sol[i, j] for j in range(sol.ncols())] for i in range(sol.nrows())]

    def rank(self, M):
        if not M or not M[0]:
            return 0
        return flint.fmpq_mat([list(map(self._q, r)) for r in M]).rank()

    @staticmethod
    def _q(x):
        return x if isinstance(x, flint.fmpq) else flint.fmpq(x)


class ModularField(Field):
    """The prime field GF(p) (the modular method draws p per point); parameters uniform in GF(p)."""

    name = "modular"

    def __init__(self, p: int = MERSENNE_61) -> None:
        self.p = p
        self.sample_size = p

    def const(self, q):
        q = Fraction(q)
        if q == 0:
            return flint.nmod(0, self.p)
        if q.numerator % self.p == 0 or q.denominator % self.p == 0:
            # the constant would vanish, or have no inverse, mod p: this prime says nothing about it
            raise ConstantDegenerate(f"the constant {q} is divisible by p = {self.p} in its numerator or "
                                     f"denominator")
        return flint.nmod(q.numerator, self.p) / flint.nmod(q.denominator, self.p)

    def param(self, name, rng):
        return flint.nmod(rng.randrange(self.p), self.p)

    def param_values(self, rng, count):
        if self.p > 2**63:
            return None
        return _generator(rng).integers(0, self.p, size=count)

    def param_from_raw(self, x):
        return flint.nmod(int(x), self.p)

    def is_zero(self, x):
        return int(x) == 0 if isinstance(x, flint.nmod) else x == 0

    def describe(self, x):
        v = int(x)
        return str(v if v <= self.p // 2 else v - self.p) + f" (mod {self.p})"

    def solve(self, M, B):
        cast = lambda r: [x if isinstance(x, flint.nmod) else flint.nmod(int(x), self.p) for x in r]
        try:
            sol = flint.nmod_mat([cast(r) for r in M], self.p).solve(
                flint.nmod_mat([cast(r) for r in B], self.p))
        except ZeroDivisionError as exc:
            raise DegenerateError("singular linear system mod p") from exc
        return [[sol[i, j] for j in range(sol.ncols())] for i in range(sol.nrows())]

    def rank(self, M):
        if not M or not M[0]:
            return 0
        cast = lambda r: [x if isinstance(x, flint.nmod) else flint.nmod(int(x), self.p) for x in r]
        return flint.nmod_mat([cast(r) for r in M], self.p).rank()


# ---------------------------------------------------------------------------
FLOAT_MIN_NORMAL = 2.0**-1022
FLOAT_UNDERFLOW = 2.0**-1074


class ErrNum:
    """A float (or mpf) with a first-order running bound on its rounding error.

    ``e`` bounds |computed - exact| and ``m`` bounds the sum of the absolute
    values of all terms that went into the number (its scale; the terms of a
    quotient a/b are those of a divided by |b|).  In float64 a value, bound or
    scale can stop being finite (overflow, inf - inf, 0 * inf): the error model
    is then void.  Such a number is *poisoned* (e or m is inf or nan) and every
    number computed from it is poisoned too (no operation can turn inf or nan
    back into a finite bound), so the engine sees it in the result and repeats the
    evaluation at a higher precision (mpmath does not overflow).  Nothing is
    raised inside the arithmetic (numpy's object dot does not propagate exceptions
    cleanly).
    """

    __slots__ = ("v", "e", "m", "u")

    def __init__(self, v, e=0, m=None, u=2.0**-53):
        self.v, self.e, self.u = v, e, u
        self.m = abs(v) if m is None else m

    def _new(self, v, e, m):
        return ErrNum(v, e, m, self.u)

    @property
    def poisoned(self) -> bool:
        """The error model is void: e or m is not finite (nan fails both comparisons)."""
        return not (self.e < math.inf and self.m < math.inf)

    def _lift(self, o):
        if isinstance(o, ErrNum):
            return o
        if isinstance(o, (int, Fraction)):
            try:
                v = self._num(o)
            except OverflowError:
                return ErrNum(0.0, math.inf, math.inf, self.u)     # poisoned: float64 cannot hold it
            err = 0 if v == o else self.u * abs(v) + (FLOAT_UNDERFLOW if isinstance(v, float) else 0)
            return self._new(v, err, abs(v))
        return NotImplemented

    def _num(self, q):
        if isinstance(self.v, float):
            return float(q)
        return mpmath.mpf(q.numerator) / q.denominator if isinstance(q, Fraction) else mpmath.mpf(q)

    def __add__(self, o):
        o = self._lift(o)
        if o is NotImplemented:
            return o
        v = self.v + o.v
        return self._new(v, self.e + o.e + self.u * abs(v), self.m + o.m)

    __radd__ = __add__

    def __neg__(self):
        return ErrNum(-self.v, self.e, self.m, self.u)

    def __sub__(self, o):
        o = self._lift(o)
        if o is NotImplemented:
            return o
        return self + (-o)

    def __rsub__(self, o):
        return (-self) + o

    def __mul__(self, o):
        o = self._lift(o)
        if o is NotImplemented:
            return o
        v = self.v * o.v
        e = abs(self.v) * o.e + abs(o.v) * self.e + self.e * o.e + self.u * abs(v)
        if isinstance(v, float) and abs(v) < FLOAT_MIN_NORMAL and not (
                (self.v == 0 and self.e == 0) or (o.v == 0 and o.e == 0)):
            e += FLOAT_UNDERFLOW   # a gradual underflow adds an absolute error < 2^-1074
        return self._new(v, e, self.m * o.m)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self._lift(o)
        if o is NotImplemented:
            return o
        if o.poisoned:
            return ErrNum(0.0, math.inf, math.inf, self.u)
        if o.v == 0 or o.e >= abs(o.v):
            raise DegenerateError("division by a number indistinguishable from zero")
        v = self.v / o.v
        e = (self.e + abs(v) * o.e) / (abs(o.v) - o.e) + self.u * abs(v)
        if isinstance(v, float) and abs(v) < FLOAT_MIN_NORMAL and not (self.v == 0 and self.e == 0):
            e += FLOAT_UNDERFLOW
        # the terms of a/b are those of a divided by b; through a long elimination this scale can
        # exceed float64 (then the result is poisoned, and mpmath, which does not overflow, takes
        # over).  The divisor's scale does not enter the quotient's: its poison was passed on above.
        return self._new(v, e, self.m / (abs(o.v) - o.e))

    def __rtruediv__(self, o):
        return self._lift(o) / self

    def __repr__(self):
        return f"{float(self.v):.3e}±{float(self.e):.1e}"


def _column_scaled(out: list[list[Any]], size: Callable[[Any], Any], scaled: Callable[[Any, Any], Any],
                   kind: type) -> list[list[Any]]:
    """The solution ``out`` of a linear system (rows of entries) with every entry of type ``kind`` given the
    largest ``size`` of the entries of its column as its term scale (``scaled(x, m)``)."""
    if not out:
        return out
    tops = []
    for j in range(len(out[0])):
        sizes = [size(row[j]) for row in out if type(row[j]) is kind]
        tops.append(max(sizes) if sizes else None)
    return [[scaled(x, tops[j]) if type(x) is kind else x for j, x in enumerate(row)] for row in out]


class FloatField(Field):
    """float64 (or mpmath at ``dps`` digits) with running error bounds."""

    exact = False

    def __init__(self, dps: int | None = None, scale: float = 1.0) -> None:
        self.dps = dps
        self.scale = scale
        self.name = "float64" if dps is None else f"mpmath{dps}"
        self.u = 2.0**-53 if dps is None else mpmath.mpf(10) ** (-dps)

    def _num(self, x):
        if self.dps is None:
            return float(x)
        if isinstance(x, Fraction):
            return mpmath.mpf(x.numerator) / x.denominator
        return mpmath.mpf(x)

    def const(self, q):
        q = Fraction(q)
        if self.dps is None:
            try:
                v = q.numerator / q.denominator
            except OverflowError:
                return ErrNum(0.0, math.inf, math.inf, self.u)      # poisoned: float64 cannot hold it
        else:
            v = mpmath.mpf(q.numerator) / q.denominator
        err = 0 if q.denominator == 1 and abs(q.numerator) < 2**53 else self.u * abs(v)
        if self.dps is None and err and abs(v) < FLOAT_MIN_NORMAL:
            err += FLOAT_UNDERFLOW
        return ErrNum(v, err, abs(v), self.u)

    def param_values(self, rng, count):
        if self.scale != 1 or self.dps is not None:
            return None
        # exact: |k| <= 2^40 and the product with 2^-40 is a power-of-two scaling (the quotient by
        # 2^40 bit for bit, at a fraction of a division's cost)
        return _generator(rng).integers(-2**40, 2**40, size=count, endpoint=True) * 2.0**-40

    def param_from_raw(self, x):
        return ErrNum(float(x), 0, abs(float(x)), self.u)

    def params_from_raw(self, vals):
        if type(self).param_from_raw is not FloatField.param_from_raw:
            return Field.params_from_raw(self, vals)
        u = self.u
        # vals.tolist() gives Python floats: float(x) is x itself
        return [ErrNum(x, 0, abs(x), u) for x in vals.astype(float).tolist()]

    def param(self, name, rng):
        k = rng.randint(-2**40, 2**40)
        if self.scale == 1 and self.dps is None:
            v = k / 2**40        # exact: |k| <= 2^40 and the quotient is a power-of-two scaling
        else:
            v = self._num(Fraction(k, 2**40) * Fraction(self.scale).limit_denominator())
        return ErrNum(v, 0, abs(v), self.u)

    def is_zero(self, x):
        return abs(x.v) <= x.e if isinstance(x, ErrNum) else x == 0

    def is_exact_zero(self, x):
        return x.v == 0 and x.e == 0 if isinstance(x, ErrNum) else x == 0

    def solve(self, M, B):
        """Gaussian elimination with the running error bounds; each solution entry then takes as its
        term scale the size |v| + e of the largest entry of its column of the solution: the scales
        carried through elimination multiply by pivot ratios at every step and would grow without
        meaning (10^2699 at n = 16), which would make the resolution test e <= 10^-8 m vacuous; and an
        entry's own size is no scale for an entry that is 0 (a multiplier Π = 0 beside Λ: its bound,
        of the size of the rounding of the terms that cancel in it, is then never below 10^-8 of
        itself, at any precision)."""
        return _column_scaled(Field.solve(self, M, B), lambda x: abs(x.v) + x.e,
                              lambda x, m: ErrNum(x.v, x.e, m, x.u), ErrNum)

    def absorb(self, a, g, b):
        """a - g b for g = 0 within its bound: |g b| <= (|g.v| + g.e)(|b.v| + b.e) joins a's error."""
        a, g, b = (x if isinstance(x, ErrNum) else self.const(x) for x in (a, g, b))
        return ErrNum(a.v, a.e + (abs(g.v) + g.e) * (abs(b.v) + b.e), a.m, a.u)

    def exact_input(self, x):
        return ErrNum(x.v, 0, abs(x.v), self.u) if isinstance(x, ErrNum) else x

    def pivot_cost(self, x):
        if not isinstance(x, ErrNum):
            return math.inf if x == 0 else 0.0
        if abs(x.v) <= x.e:
            return math.inf
        return -float(abs(x.v))

    def describe(self, x):
        return repr(x)


# ---------------------------------------------------------------------------
#: the empty denominator of a marker (shared: markers never change their ``den``)
_NO_DEN: dict = {}


class Deg:
    """Degree and height bookkeeping for a rational function N/D of the parameters.

    D is a product of named factors ``den`` (factor -> exponent); each factor is an
    integer polynomial (the numerator of a divisor, a determinant, or the integer
    denominator b of a constant a/b) whose degree and height the field records.  N is
    the integer polynomial with N/D equal to the value: ``num`` bounds its total degree
    (-1: identically zero) and ``h`` bounds log2 of its L1 norm (sum of the absolute
    values of its coefficients).  Sums use the largest exponent of every factor
    (N = N1 D/D1 + N2 D/D2), products add them; the L1 norm is subadditive and
    submultiplicative, so every bound is conservative."""

    __slots__ = ("num", "den", "f", "h", "c", "zero")

    def __init__(self, num: int, den: dict | None = None, field: "DegreeField" = None, h: float = 0.0,
                 c: Fraction | None = None):
        # a marker is never changed once made (``den`` neither: operations build new dicts)
        self.num, self.den, self.f = num, (den if den is not None else _NO_DEN), field
        #: identically zero
        self.zero = num < 0
        self.h = -math.inf if num < 0 else (h if h > 0.0 else 0.0)
        #: the value, when the marker stands for a rational constant
        self.c = c
        if field is not None and num > field.peak:
            field.peak = num

    def _lift(self, o):
        if type(o) is Deg:
            return o
        if isinstance(o, (int, Fraction)):
            return self.f.const(o)
        return NotImplemented

    def _dd(self, den):
        return sum(self.f.factor_degree[k] * e for k, e in den.items())

    def _dh(self, den):
        return sum(self.f.factor_height[k] * e for k, e in den.items())

    def __add__(self, o):
        if type(o) is not Deg:
            o = self._lift(o)
            if o is NotImplemented:
                return o
        if self.zero:
            return o
        if o.zero:
            return self
        if self.den is o.den or self.den == o.den:
            a, b = self.num, o.num
            return Deg(a if a >= b else b, self.den, self.f, log2_add(self.h, o.h))
        # the common denominator takes every factor to its larger exponent; each side's numerator
        # is multiplied by the factors it lacks (their degrees and heights add), in one pass
        sd, od = self.den, o.den
        den = dict(sd)
        for k, e in od.items():
            if e > den.get(k, 0):
                den[k] = e
        fdeg, fh = self.f.factor_degree, self.f.factor_height
        da = do = 0
        ha = ho = 0.0
        for k, e in den.items():
            a, b = e - sd.get(k, 0), e - od.get(k, 0)
            if a:
                da += fdeg[k] * a
                ha += fh[k] * a
            if b:
                do += fdeg[k] * b
                ho += fh[k] * b
        return Deg(max(self.num + da, o.num + do), den, self.f, log2_add(self.h + ha, o.h + ho))

    __radd__ = __add__

    def __neg__(self):
        return self

    def __sub__(self, o):
        return self.__add__(o)

    __rsub__ = __sub__

    def __mul__(self, o):
        if type(o) is not Deg:
            o = self._lift(o)
            if o is NotImplemented:
                return o
        if self.zero or o.zero:
            return Deg(-1, None, self.f)
        if not o.den:
            den = self.den
        elif not self.den:
            den = o.den
        else:
            den = dict(self.den)
            for k, e in o.den.items():
                den[k] = den.get(k, 0) + e
            self.f.note_denominator(den)
        return Deg(self.num + o.num, den, self.f, self.h + o.h)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = self._lift(o)
        if o is NotImplemented:
            return o
        if o.zero:
            raise DegenerateError("division by an identically zero expression")
        if self.zero:
            return self
        if o.c is not None:
            # (N/D) / (a/b) = N b / (D a): the integer a is the field's shared factor for |a|
            key = self.f.integer_factor(abs(o.c.numerator))
            den = dict(self.den)
            den[key] = den.get(key, 0) + 1
            return Deg(self.num, den, self.f, self.h + log2_up(o.c.denominator) if o.c.denominator > 1 else self.h)
        # (N/D) / (No/Do) = N Do / (D No): No becomes a factor of the denominator
        key = self.f.new_factor(o.num, o.h)
        den = dict(self.den)
        den[key] = den.get(key, 0) + 1
        self.f.note_denominator(den)
        return Deg(self.num + self._dd(o.den), den, self.f, self.h + self._dh(o.den))

    def __rtruediv__(self, o):
        return self._lift(o) / self

    def __repr__(self):
        return f"Deg({self.num}/{self._dd(self.den)}, h<={self.h:.1f})"


class DegreeField(Field):
    """Runs a claim on degree markers to bound the degree and the height of its residual's numerator."""

    name = "degree"

    def __init__(self) -> None:
        self.factor_degree: dict[int, int] = {}
        self.factor_height: dict[int, float] = {}
        self._ids = itertools.count()
        self._const_factor: dict[int, int] = {}
        #: the distinct constants a/b met; sum of log2|a| + log2 b over them
        self.constants: set[Fraction] = set()
        self.constant_bits = 0.0
        #: the largest degree of a numerator or a denominator of any value the markers stood for, the
        #: residuals' and every value computed on the way (u^(2^40) in (u^(2^40))^0 or 0 * u^(2^40)): what
        #: an exact evaluation of the same computation writes out
        self.peak = 0

    def note_denominator(self, den: dict) -> None:
        """Record the degree of a denominator made by a product or a division in :attr:`peak`."""
        d = self.den_degree(den)
        if d > self.peak:
            self.peak = d

    def record(self) -> tuple:
        """What the markers met so far (denominator factors, constants), copied: see :meth:`restore`."""
        nxt = next(self._ids)
        self._ids = itertools.count(nxt)
        return (dict(self.factor_degree), dict(self.factor_height), nxt, dict(self._const_factor),
                set(self.constants), self.constant_bits)

    def restore(self, rec: tuple) -> None:
        """Back to a :meth:`record` (the markers made since then still read their own factors)."""
        fd, fh, nxt, cf, consts, bits = rec
        self.factor_degree, self.factor_height = dict(fd), dict(fh)
        self._ids = itertools.count(nxt)
        self._const_factor, self.constants, self.constant_bits = dict(cf), set(consts), bits

    def new_factor(self, degree: int, height: float = 0.0) -> int:
        k = next(self._ids)
        self.factor_degree[k] = max(degree, 0)
        self.factor_height[k] = max(height, 0.0)
        return k

    def const(self, q):
        q = Fraction(q)
        if q == 0:
            return Deg(-1, None, self)
        if q not in self.constants:
            self.constants.add(q)
            self.constant_bits += log2_up(q.numerator) + (log2_up(q.denominator) if q.denominator > 1 else 0.0)
        den = None
        if q.denominator > 1:
            den = {self.integer_factor(q.denominator): 1}
        return Deg(0, den, self, log2_up(q.numerator), q)

    def integer_factor(self, b: int) -> int:
        """The denominator factor standing for the positive integer b (one per integer)."""
        key = self._const_factor.get(b)
        if key is None:
            key = self._const_factor[b] = self.new_factor(0, log2_up(b))
        return key

    def param(self, name, rng=None):
        return Deg(1, None, self, 0.0)

    def param_values(self, rng, count):
        return np.zeros(count)

    def param_from_raw(self, x):
        return self.param("", None)

    def is_zero(self, x):
        return isinstance(x, Deg) and x.zero or (not isinstance(x, Deg) and x == 0)

    def _lift(self, x):
        return x if isinstance(x, Deg) else self.const(x)

    def den_degree(self, den: dict) -> int:
        return sum(self.factor_degree[k] * e for k, e in den.items())

    def den_height(self, den: dict) -> float:
        return sum(self.factor_height[k] * e for k, e in den.items())

    def cleared(self, cells) -> tuple[dict, list[list[tuple[int, float]]]]:
        """A common denominator C of a matrix of markers and the (degree, height) bounds of the
        entries of C * M (degree -1 for a zero entry)."""
        common: dict[int, int] = {}
        for row in cells:
            for x in row:
                for k, e in x.den.items():
                    common[k] = max(common.get(k, 0), e)
        out = []
        done: dict[int, tuple[int, float]] = {}     # markers are immutable: once per distinct one
        for row in cells:
            out_row = []
            for x in row:
                b = done.get(id(x))
                if b is None:
                    if x.zero:
                        b = (-1, -math.inf)
                    else:
                        rest = {k: common[k] - x.den.get(k, 0) for k in common}
                        b = (x.num + self.den_degree(rest), x.h + self.den_height(rest))
                    done[id(x)] = b
                out_row.append(b)
            out.append(out_row)
        return common, out

    def minor_bound(self, cleared: list[list[tuple[int, float]]], size: int) -> tuple[int, float]:
        """(degree, log2 L1 height) bounds for every size x size minor of a cleared matrix: the sum
        of the ``size`` largest row (or column) degree maxima, and the product of the ``size``
        largest row (or column) L1 sums (a determinant's L1 norm is at most its permanent in the
        entries' L1 norms, at most the product of the row sums)."""
        if not cleared or not cleared[0] or size <= 0:
            return 0, 0.0
        cols = [list(c) for c in zip(*cleared)]

        def side(lines):
            degs = sorted((max(0, max(d for d, _ in line)) for line in lines), reverse=True)[:size]
            hts = sorted((max(0.0, log2_sum([h for _, h in line])) for line in lines), reverse=True)[:size]
            return sum(degs), sum(hts)

        (d1, h1), (d2, h2) = side(cleared), side(cols)
        return min(d1, d2), min(h1, h2)

    def solve(self, M, B):
        """Cramer's rule bound, independent of the pivots a concrete solve uses: with C a
        common denominator of M and M' = C M (integer polynomials), Y = C adj(M') B / det(M')."""
        M = [[self._lift(x) for x in row] for row in M]
        B = [[self._lift(x) for x in row] for row in B]
        m = len(M)
        common, cleared = self.cleared(M)
        det_deg, det_h = self.minor_bound(cleared, m)      # also bounds every cofactor
        det_key = self.new_factor(det_deg, det_h)
        column = []                # the bound of column j of the solution: the same for every row
        for j in range(len(B[0])):
            acc = Deg(-1, None, self)
            for b in (B[l][j] for l in range(m)):
                acc = acc + b
            if acc.zero:
                column.append(acc)
                continue
            den = dict(acc.den)
            den[det_key] = den.get(det_key, 0) + 1
            column.append(Deg(acc.num + det_deg + self.den_degree(common), den, self,
                              acc.h + det_h + self.den_height(common)))
        return [list(column) for _ in range(m)]

    def rank(self, M):
        raise TypeError("ranks are not defined over degree markers")


# ---------------------------------------------------------------------------
def _is_matrix(o) -> bool:
    return getattr(o, "__array_priority__", 0) >= 1000


#: the number types that wrap a value of another field, by the attribute holding it (Dual: a; the
#: reverse and degree-paired numbers register theirs): a derivative taken inside a function whose
#: derivative is taken evaluates numbers of a field over a field over the point's field, and a value
#: the function captured from an outer scene is a number of a lower field of that tower
LAYERED: dict[type, str] = {}


def tower_level(x: Any) -> int:
    """How many layers of engine numbers (dual, reverse, degree-paired) wrap a value of a point's field (a
    dual number by the higher of its two parts: one of them may be a plain 0)."""
    n = 0
    while True:
        t = type(x)
        if t is Dual:
            return n + 1 + max(tower_level(x.a), tower_level(x.b))
        attr = LAYERED.get(t)
        if attr is None:
            return n
        x = getattr(x, attr)
        n += 1


def _above(o: Any, x: Any) -> bool:
    """Whether o is a number of a field built over x's (a layered number of a higher level): the
    operation is o's, with x a constant of its base (a dual number of plain Python numbers is no layer's)."""
    if type(o) not in LAYERED or type(o) is Dual and all(type(p) in (int, Fraction) for p in (o.a, o.b)):
        return False
    return tower_level(o) > tower_level(x)


class Dual:
    """a + b·ε with ε² = 0: forward-mode derivative over any field."""

    __slots__ = ("a", "b")

    def _symengine_(self):
        return symengine_opaque()

    def __init__(self, a, b=0):
        self.a, self.b = a, b

    def __add__(self, o):
        if type(o) is Dual:
            if _same_level(self, o):
                return Dual(self.a + o.a, self.b + o.b)
            if tower_level(o) > tower_level(self):
                return o.__add__(self)       # this number is a constant of o's base
        elif _is_matrix(o) or _above(o, self):
            return NotImplemented
        return Dual(self.a + o, self.b)

    __radd__ = __add__

    def __neg__(self):
        return Dual(-self.a, -self.b)

    def __sub__(self, o):
        if type(o) is Dual:
            if _same_level(self, o):
                return Dual(self.a - o.a, self.b - o.b)
            if tower_level(o) > tower_level(self):
                return o.__rsub__(self)       # this number is a constant of o's base
        elif _is_matrix(o) or _above(o, self):
            return NotImplemented
        return Dual(self.a - o, self.b)

    def __rsub__(self, o):
        return Dual(o - self.a, -self.b)

    def __mul__(self, o):
        if type(o) is Dual:
            if _same_level(self, o):
                return Dual(self.a * o.a, self.a * o.b + self.b * o.a)
            if tower_level(o) > tower_level(self):
                return o.__mul__(self)       # this number is a constant of o's base
        elif _is_matrix(o) or _above(o, self):
            return NotImplemented
        return Dual(self.a * o, self.b * o)

    __rmul__ = __mul__

    def __truediv__(self, o):
        if type(o) is Dual:
            if _same_level(self, o):
                q = self.a / o.a
                return Dual(q, (self.b - q * o.b) / o.a)
            if tower_level(o) > tower_level(self):
                return o.__rtruediv__(self)
        elif _is_matrix(o) or _above(o, self):
            return NotImplemented
        return Dual(self.a / o, self.b / o)

    def __rtruediv__(self, o):
        q = o / self.a
        return Dual(q, -(q * self.b) / self.a)

    def __repr__(self):
        return f"Dual({self.a!r}, {self.b!r})"


LAYERED[Dual] = "a"


_PLAIN = (int, Fraction)


def _same_level(x: Dual, o: Dual) -> bool:
    """Two dual numbers of one field (the common case: no part is layered); a dual number of a lower field
    is a constant of the higher one's base (a value a function captured).  A dual number made of plain
    Python numbers only fits any layer (as before layers were told apart)."""
    if not (type(x.a) in LAYERED or type(x.b) in LAYERED or type(o.a) in LAYERED or type(o.b) in LAYERED):
        return True
    if all(type(p) in _PLAIN for p in (x.a, x.b)) or all(type(p) in _PLAIN for p in (o.a, o.b)):
        return True
    return tower_level(x) == tower_level(o)


class DualField(Field):
    """Elements a + bε over a base field; used for derivatives along flows."""

    def __init__(self, base: Field) -> None:
        self.base = base
        self.name = f"dual({base.name})"
        self.exact = base.exact

    def const(self, q):
        return Dual(self.base.const(q), self.base.const(0))

    def lift(self, x):
        if type(x) in LAYERED and tower_level(x) < self.level:
            # a number of a field below this one's (a value of an enclosing scene): a constant here, its own ε
            # kept in its level, never taken for this one's
            return Dual(self.base.lift(x) if tower_level(x) < self.level - 1 else x, self.base.const(0))
        return x if isinstance(x, Dual) else Dual(x, self.base.const(0))

    def _above(self, x) -> bool:
        """Whether x is a number of a field built over this one (a value of the scene of a function inside this
        scene's, handed to one of its methods): the helpers below take it part by part, each part a number of
        this field or again of one above it, never reading its parts as this field's value and ε-part."""
        return type(x) is Dual and tower_level(x) > self.level

    def is_zero(self, x):
        if self._above(x):
            return self.is_zero(x.a) and self.is_zero(x.b)
        x = self.lift(x)
        return self.base.is_zero(x.a) and self.base.is_zero(x.b)

    def is_exact_zero(self, x):
        if self._above(x):
            return self.is_exact_zero(x.a) and self.is_exact_zero(x.b)
        x = self.lift(x)
        return self.base.is_exact_zero(x.a) and self.base.is_exact_zero(x.b)

    def absorb(self, a, g, b):
        # (a - g b) = (a.a - g.a b.a) + eps (a.b - g.a b.b - g.b b.a), every g part zero within its bound
        a, g, b = self.lift(a), self.lift(g), self.lift(b)
        base = self.base
        return Dual(base.absorb(a.a, g.a, b.a), base.absorb(base.absorb(a.b, g.a, b.b), g.b, b.a))

    def normalize(self, x):
        if self._above(x):
            return Dual(self.normalize(x.a), self.normalize(x.b))
        x = self.lift(x)
        return Dual(self.base.normalize(x.a), self.base.normalize(x.b))

    def pivot_cost(self, x):
        return self.base.pivot_cost(self.lift(x).a)

    def solve(self, M, B):
        M = [[self.lift(x) for x in r] for r in M]
        B = [[self.lift(x) for x in r] for r in B]
        M0 = [[x.a for x in r] for r in M]
        Y0 = self.base.solve(M0, [[x.a for x in r] for r in B])
        m, k = len(M), len(B[0])
        rhs = [[B[i][j].b - sum((M[i][l].b * Y0[l][j] for l in range(m)), self.base.const(0))
                for j in range(k)] for i in range(m)]
        Y1 = self.base.solve(M0, rhs)
        return [[Dual(Y0[i][j], Y1[i][j]) for j in range(k)] for i in range(m)]
