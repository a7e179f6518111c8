"""Ball arithmetic: rigorous enclosures of exact values (arb, from python-flint).

Every number is a ball [mid ± rad] that contains the exact value of the same computation done
over the reals at the same exact inputs.  arb's arithmetic guarantees this for every operation
(the inclusion property), at a working precision in bits: a wider precision gives a smaller
ball, never a different exact value.  Inputs are exact: the chart's parameters are dyadic
rationals k / 2^40 (the points the float method draws, see :class:`BallField`), integers are
exact, and a rational constant such as 1/3 enters as a ball containing it.

Besides its ball, each number carries its *term scale*: the sum of the absolute values of the
terms that went into it, as the float method's error model does (a float64 magnitude, not a
rigorous quantity: it only says what "small" means for the resolution test of the ball method,
whose printed bound is the ball's, and rigorous).

A matrix is one ``arb_mat`` (whole-matrix products, inverses and solves in flint's native
code) with a numpy array of term scales beside it.  Complex scenes are realified by the scene
(U + iV as [[U, -V], [V, U]]), so real balls are enough; acb is not needed.
"""
from __future__ import annotations

import contextlib
import math
import random
from fractions import Fraction
from typing import Any, Iterator, Sequence

import numpy as np

from stiefelsym.backends.fields import DegenerateError, Field, _generator
from stiefelsym.backends.matrix import engine_number_type
from stiefelsym.backends.native import Backend, register_backend

import flint

#: the precision ladder of the ball method, in bits (53: the precision of float64)
BALL_LADDER = (53, 106, 212, 424)
#: the parameters of the chart are the float method's: integers k in [-2^40, 2^40] over 2^40
PARAM_BITS = 40


@contextlib.contextmanager
def working_precision(bits: int) -> Iterator[None]:
    """arb's working precision (a global of python-flint) for the duration of a block."""
    old = flint.ctx.prec
    flint.ctx.prec = bits
    try:
        yield
    finally:
        flint.ctx.prec = old


def _fraction_ball(q: Fraction | int) -> Any:
    if isinstance(q, int):
        return flint.arb(q)
    return flint.arb(flint.fmpq(q.numerator, q.denominator))


def _scale_of(q: Fraction | int) -> float:
    try:
        return abs(float(q))
    except OverflowError:
        return math.inf


@engine_number_type
class BallNum:
    """A ball (flint.arb) containing an exact real number, with the term scale ``m`` of the
    computation that produced it (see the module's docstring)."""

    __slots__ = ("b", "m")

    def __init__(self, b: Any, m: float) -> None:
        self.b, self.m = b, m

    @staticmethod
    def _lift(o: Any) -> Any:
        if type(o) is BallNum:
            return o
        if isinstance(o, (int, Fraction)):
            return BallNum(_fraction_ball(o), _scale_of(o))
        return NotImplemented

    def __add__(self, o):
        o = BallNum._lift(o)
        if o is NotImplemented:
            return o
        return BallNum(self.b + o.b, self.m + o.m)

    __radd__ = __add__

    def __neg__(self):
        return BallNum(-self.b, self.m)

    def __sub__(self, o):
        o = BallNum._lift(o)
        if o is NotImplemented:
            return o
        return BallNum(self.b - o.b, self.m + o.m)

    def __rsub__(self, o):
        o = BallNum._lift(o)
        if o is NotImplemented:
            return o
        return BallNum(o.b - self.b, self.m + o.m)

    def __mul__(self, o):
        o = BallNum._lift(o)
        if o is NotImplemented:
            return o
        return BallNum(self.b * o.b, self.m * o.m)

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = BallNum._lift(o)
        if o is NotImplemented:
            return o
        if o.b.contains(0):
            raise DegenerateError("division by a ball that contains zero")
        # a divisor below float64's range (w^(2^21) of a w < 1): the ball is exact, its term scale overflows float64
        # (the resolution test is then not made, as for any term scale that overflows)
        low = float(abs(o.b).lower())
        return BallNum(self.b / o.b, self.m / low if low > 0.0 else math.inf)

    def __rtruediv__(self, o):
        o = BallNum._lift(o)
        if o is NotImplemented:
            return o
        return o / self

    def __repr__(self) -> str:
        return self.b.str(5, radius=True)

    # what the ball method reads
    @property
    def bound(self) -> float:
        """An upper bound of |x| for every x in the ball (|mid| + rad, rounded up)."""
        return _upper(abs(self.b))

    def excludes_zero(self) -> bool:
        return not self.b.contains(0)


def _upper(x: Any) -> float:
    """A float64 upper bound of the upper end of a ball (rounded up, never down)."""
    u = x.upper()
    f = float(u)
    if math.isfinite(f) and flint.arb(f) < u:
        f = math.nextafter(f, math.inf)
    return f


class BallField(Field):
    """Real balls at ``prec`` bits (flint.arb), evaluated at the float method's exact points."""

    exact = False
    #: the chart's point is exactly on V (exact inputs) and every ball contains the exact value
    #: there, so identities that hold exactly on V (the closed-form Dirac multipliers) apply
    encloses_exact_point = True

    def __init__(self, prec: int = 53) -> None:
        self.prec = prec
        self.name = f"arb{prec}"

    def const(self, q):
        q = Fraction(q)
        if q.denominator == 1:
            return BallNum(flint.arb(q.numerator), _scale_of(q))
        return BallNum(_fraction_ball(q), _scale_of(q))

    def param_values(self, rng, count):
        # the float64 method's draw (FloatField.param_values): exact dyadic values
        return _generator(rng).integers(-2**PARAM_BITS, 2**PARAM_BITS, size=count, endpoint=True) / 2.0**PARAM_BITS

    def param_from_raw(self, x):
        v = float(x)
        return BallNum(flint.arb(v), abs(v))

    def param(self, name, rng: random.Random | None):
        if rng is None:
            raise ValueError("ball parameters are drawn from a random source")
        k = rng.randint(-2**PARAM_BITS, 2**PARAM_BITS)
        v = k / 2**PARAM_BITS                 # exact in float64 and in arb
        return BallNum(flint.arb(v), abs(v))

    def is_zero(self, x):
        return x.b.contains(0) if type(x) is BallNum else x == 0

    def is_exact_zero(self, x):
        return x.b.is_zero() if type(x) is BallNum else x == 0

    def exact_input(self, x):
        """A computed value taken as an exact input (a hard case): the midpoint of its ball."""
        return BallNum(flint.arb(x.b.mid()), x.m) if type(x) is BallNum else x

    def pivot_cost(self, x):
        if type(x) is not BallNum:
            return math.inf if x == 0 else 0.0
        if x.b.contains(0):
            return math.inf
        return -float(abs(x.b.mid()))

    def describe(self, x):
        """An exact ball (an input) as the exact rational it is; any other as a rigorous enclosure."""
        if type(x) is BallNum and x.b.is_exact():
            man, exp = x.b.mid().man_exp()
            q = Fraction(int(man)) * (Fraction(2) ** int(exp))
            return str(q)
        return x.b.str(17, radius=True) if type(x) is BallNum else str(x)

    def solve(self, M: Sequence[Sequence[Any]], B: Sequence[Sequence[Any]]) -> list[list[Any]]:
        """A rigorous enclosure of M⁻¹B (flint's preconditioned solve); DegenerateError when the
        balls of M contain a singular matrix (or flint cannot exclude one)."""
        m, k = len(M), len(B[0]) if B else 0
        A = flint.arb_mat(m, m, [_ball(self, x) for row in M for x in row])
        Bm = flint.arb_mat(m, k, [_ball(self, x) for row in B for x in row])
        try:
            Y = A.solve(Bm)
        except ZeroDivisionError as exc:
            raise DegenerateError("a linear system whose balls contain a singular matrix") from exc
        # each entry's term scale: the largest entry of its column (see FloatField.solve: an entry's own
        # size is no scale for an entry that is 0)
        tops = [max((_upper(abs(Y[i, j])) for i in range(m)), default=0.0) for j in range(k)]
        return [[BallNum(Y[i, j], tops[j]) for j in range(k)] for i in range(m)]


def _ball(field: BallField, x: Any) -> Any:
    if type(x) is BallNum:
        return x.b
    return field.const(x).b


# ----------------------------------------------------------------------------- matrices
class Balls:
    """A matrix of balls (``M``, an arb_mat) with its entries' term scales (``m``, float64).

    Never written into once built, so the backend may remember what it learns about one: its
    transpose ``t`` (whose ``t`` is the matrix again).  An inverse (or a product with one) may be
    *deferred*: ``defer`` says what it is, and ``M``, ``m`` are computed only if read (a product
    of it with another matrix is a rigorous solve instead, see :meth:`BallBackend.matmul`)."""

    __slots__ = ("_M", "_m", "t", "defer", "_build", "diag")

    def __init__(self, M: Any, m: np.ndarray | None, defer: tuple | None = None, build: Any = None) -> None:
        self._M, self._m, self.t, self.defer, self._build = M, m, None, defer, build
        #: the diagonal (a list of balls) of a matrix that is diagonal by construction, else None
        self.diag: list | None = None

    def _force(self) -> None:
        self._M, self._m = self._build()
        self._build = None

    @property
    def M(self) -> Any:
        if self._M is None:
            self._force()
        return self._M

    @property
    def m(self) -> np.ndarray:
        if self._m is None:
            self._force()
        return self._m

    def shape(self) -> tuple[int, int]:
        if self._M is None:
            return self.defer[-1]
        return (self._M.nrows(), self._M.ncols())


def _arb_mat(m: int, k: int, flat: list) -> Any:
    return flint.arb_mat(m, k, flat) if m and k else flint.arb_mat(m, k)


def _mids(M: Any) -> np.ndarray:
    """The midpoints of a ball matrix as float64 (rounded to nearest)."""
    m, k = M.nrows(), M.ncols()
    return np.array([float(x) for x in M.mid().entries()], dtype=float).reshape(m, k)


class EnclosureBackend(Backend):
    """What the two backends of the ball method share: scalars are balls (:class:`BallNum`), and the
    products of one evaluation are remembered with their operands."""

    def __init__(self, field: BallField) -> None:
        self.field = field
        #: products computed in this evaluation: {(id(a), id(b)): (a, b, a b)} (the operands are
        #: kept, so an id is never reused while its entry lives); see :meth:`release`
        self._products: dict[tuple[int, int], tuple] = {}

    def release(self) -> None:
        """Forget the remembered products and transposes (the method calls it when an evaluation
        is over: they tie matrices to each other)."""
        for a, b, c in self._products.values():
            a.t = b.t = c.t = None
        self._products = {}

    def accepts(self, x):
        return type(x) is BallNum

    def _remembered(self, a, b):
        """a b if this evaluation computed it, or its transpose (a b = (bᵀ aᵀ)ᵀ), else None (the same
        enclosure either way: both backends' products are deterministic)."""
        hit = self._products.get((id(a), id(b)))
        if hit is not None:
            return hit[2]
        if a.t is not None and b.t is not None:
            hit = self._products.get((id(b.t), id(a.t)))
            if hit is not None:
                out = self.T(hit[2])
                self._products[(id(a), id(b))] = (a, b, out)
                return out
        return None


class BallBackend(EnclosureBackend):
    """Whole ball matrices in flint's arb_mat at the working precision (see
    :func:`working_precision`); the term scales follow the float method's rules (sums add, a
    product's is the product of the scales, an inverse's is the size of its entries)."""

    def from_array(self, a):
        """Exact float64 inputs (a block of the chart's parameters)."""
        v = np.asarray(a, dtype=float)
        m, k = v.shape
        return Balls(_arb_mat(m, k, v.ravel().tolist()), np.abs(v))

    def from_consts(self, a):
        m, k = a.shape
        return Balls(_arb_mat(m, k, [int(x) for x in a.ravel().tolist()]),
                     np.abs(a.astype(float)))

    def from_obj(self, a):
        m, k = a.shape
        balls, scales = [], np.empty((m, k))
        for idx, x in np.ndenumerate(a):
            if type(x) is not BallNum:
                x = self.field.const(x)
            balls.append(x.b)
            scales[idx] = x.m
        return Balls(_arb_mat(m, k, balls), scales)

    def to_obj(self, s):
        m, k = s.M.nrows(), s.M.ncols()
        out = np.empty((m, k), dtype=object)
        entries = s.M.entries() if m and k else []
        for idx, b in zip(np.ndindex(m, k), entries):
            out[idx] = BallNum(b, float(s.m[idx]))
        return out

    def shape(self, s):
        return s.shape()

    def zeros(self, m, k):
        return Balls(flint.arb_mat(m, k), np.zeros((m, k)))

    def identity(self, m):
        M = flint.arb_mat(m, m)
        for i in range(m):
            M[i, i] = 1
        return Balls(M, np.eye(m))

    def diag(self, xs):
        if not all(type(x) is BallNum for x in xs):
            return Backend.diag(self, xs)
        k = len(xs)
        M = flint.arb_mat(k, k)
        for i, x in enumerate(xs):
            M[i, i] = x.b
        out = Balls(M, np.diag([x.m for x in xs]))
        out.diag = [x.b for x in xs]
        return out

    def add(self, a, b):
        return Balls(a.M + b.M, a.m + b.m)

    def sub(self, a, b):
        return Balls(a.M - b.M, a.m + b.m)

    def neg(self, a):
        return Balls(-a.M, a.m)

    def matmul(self, a, b):
        """a b; a product already computed in this evaluation, or its transpose (a b = (bᵀ aᵀ)ᵀ),
        is not computed again (the same balls: arb's product is deterministic)."""
        out = self._remembered(a, b)
        if out is not None:
            return out
        out = self._deferred_product(a, b)
        if out is None and (a.diag is not None or b.diag is not None) and a.defer is None and b.defer is None:
            out = _diagonal_product(a, b)
        if out is None:
            (m, j), k = a.shape(), b.shape()[1]
            if j == 0:
                return self.zeros(m, k)
            out = Balls(a.M * b.M, a.m @ b.m)
        self._products[(id(a), id(b))] = (a, b, out)
        return out

    def _deferred_product(self, a, b) -> Balls | None:
        """Products with a deferred inverse A⁻¹ (see :meth:`inv`): c A⁻¹ stays deferred, and
        (c A⁻¹) b = c (A⁻¹ b), A⁻¹ b a rigorous solve (the Cayley chart's X = (I − S)(I + S)⁻¹ J
        without the n x n inverse)."""
        if a.defer is None and b.defer is not None and b.defer[0] == "inv" and b._M is None:
            _, A, beta, shape = b.defer
            return Balls(None, None, ("mulinv", a, A, beta, (a.shape()[0], shape[1])),
                         lambda: _forced_product(a, b))
        if b.defer is None and a.defer is not None and a._M is None:
            if a.defer[0] == "inv":
                _, A, beta, _shape = a.defer
                return _cayley_solve(A, beta, b)
            if a.defer[0] == "mulinv":
                _, c, A, beta, _shape = a.defer
                return self.matmul(c, _cayley_solve(A, beta, b))
        return None

    def smul(self, a, c):
        out = Balls(a.M * c.b, a.m * c.m)
        if a.diag is not None:
            out.diag = [x * c.b for x in a.diag]
        return out

    def T(self, a):
        if a.t is None:
            a.t = Balls(a.M.transpose(), a.m.T)
            a.t.t = a
            a.t.diag = a.diag
            self._products[(id(a), -1)] = (a, a.t, a.t)      # keeps both alive until release
        return a.t

    def trace(self, a):
        return BallNum(a.M.trace(), float(np.trace(a.m)))

    def inner(self, a, b):
        """sum_ij a_ij b_ij = tr(aᵀb)."""
        return BallNum((a.M.transpose() * b.M).trace(), float(np.sum(a.m * b.m)))

    def inv(self, a):
        """A rigorous enclosure of the inverse of every matrix in the balls (flint); its entries'
        scales are their sizes, as for the float method's inverse.  An exact matrix whose symmetric
        part is diagonal and positive (I + S, S skew: the Cayley chart's) is invertible with
        ‖A⁻¹‖₂ ≤ 1/min d; its inverse is deferred, and a product with it is a solve."""
        beta = _skew_plus_diagonal(a)
        if beta is not None:
            k = a.shape()[0]
            return Balls(None, None, ("inv", a, beta, (k, k)), lambda: _inverse(a))
        return Balls(*_inverse(a))

    def is_zero(self, a):
        m, k = a.M.nrows(), a.M.ncols()
        return bool(a.M.contains(flint.arb_mat(m, k)))

    def block(self, grid):
        M = np.concatenate([np.concatenate([self.to_obj(b) for b in row], axis=1) for row in grid], axis=0)
        return self.from_obj(M)


def _diagonal_product(a: Balls, b: Balls) -> Balls:
    """A product with a diagonal matrix: rows (or columns) scaled, one ball product per entry."""
    if a.diag is not None:
        d, (m, k) = a.diag, b.shape()
        flat = [x * d[i // k] for i, x in enumerate(b.M.entries())] if m and k else []
        scales = np.diag(a.m)[:, None] * b.m
    else:
        d, (m, k) = b.diag, a.shape()
        flat = [x * d[i % k] for i, x in enumerate(a.M.entries())] if m and k else []
        scales = a.m * np.diag(b.m)[None, :]
    out = Balls(_arb_mat(m, k, flat), scales)
    if a.diag is not None and b.diag is not None:
        out.diag = [x * y for x, y in zip(a.diag, b.diag)]
    return out


def _forced_product(a: Balls, b: Balls) -> tuple[Any, np.ndarray]:
    return a.M * b.M, a.m @ b.m


def _inverse(a: Balls) -> tuple[Any, np.ndarray]:
    try:
        Z = a.M.inv()
    except ZeroDivisionError as exc:
        raise DegenerateError("a matrix whose balls contain a singular one") from exc
    return Z, np.abs(_mids(Z))


def _skew_plus_diagonal(a: Balls) -> Any:
    """For an exact square A with A + Aᵀ = 2 diag(d), d > 0: an upper bound β ≥ ‖A⁻¹‖₂ (xᵀAx =
    Σ d_i x_i² ≥ min d ‖x‖², so σ_min(A) ≥ min d); None otherwise."""
    if a.defer is not None or a.shape()[0] < DEFERRED_INVERSE_MIN:
        return None
    M = a.M
    k = M.nrows()
    H = M + M.transpose()
    d = [H[i, i] for i in range(k)]
    D = flint.arb_mat(k, k)
    for i in range(k):
        D[i, i] = d[i]
    if not (H == D) or not all(x.is_exact() and x > 0 for x in d):
        return None
    # d holds 2 d_i: β = max 2/d_i, each rounded up (no comparison of rounded values picks the minimum)
    return flint.arb(max(_upper(2 / x) for x in d))


#: from this many rows on, an inverse of the Cayley chart's kind is deferred (a solve is cheaper)
DEFERRED_INVERSE_MIN = 24


def _cayley_solve(A: Balls, beta: Any, B: Balls) -> Balls:
    """A rigorous enclosure of A⁻¹B for an exact A with ‖A⁻¹‖₂ ≤ β (see :func:`_skew_plus_diagonal`).

    Y₀ from LAPACK (float64), refined while the working precision asks for it (Yᵢ₊₁ = Yᵢ + an
    approximate solve of the residual, every Yᵢ an exact matrix); then, for every B' in the balls
    of B, ‖A⁻¹B' − Y‖_F ≤ β ‖B' − A Y‖_F, and the residual R = B − A Y is enclosed by arb, so
    every entry of A⁻¹B' lies within β · sup ‖R‖_F of Y's.  ‖R‖_F is bounded above in arb from
    tr(RᵀR) (its upper end holds for every matrix in the balls of R)."""
    Amid = _mids(A.M)
    Bmid = _mids(B.M)
    try:
        Y = np.linalg.solve(Amid, Bmid)
    except np.linalg.LinAlgError as exc:
        raise DegenerateError("a singular float64 approximation of a Cayley matrix") from exc
    Ym = flint.arb_mat(Y.tolist())
    # refined until the bound is within 2^20 units of the working precision of Y's size, or
    # stops shrinking (a step gains less than 20 bits)
    target = 2.0 ** (20 - flint.ctx.prec) * (1.0 + float(np.max(np.abs(Y), initial=0.0)))
    previous = math.inf
    while True:
        R = B.M - A.M * Ym
        rr = (R.transpose() * R).trace()
        if not rr.is_finite():
            raise DegenerateError("a Cayley solve whose residual is not finite")
        radius = _upper(beta * rr.upper().sqrt())
        if radius <= target or radius > previous * 2.0**-20:
            break
        previous = radius
        delta = np.linalg.solve(Amid, _mids(R))
        Ym = (Ym + flint.arb_mat(delta.tolist())).mid()
        Y = _mids(Ym)
    e = flint.arb(0, radius)
    rows, cols = Y.shape
    E = flint.arb_mat(rows, cols, [e] * (rows * cols))
    return Balls(Ym + E, np.abs(Y) + radius)


register_backend(BallField, BallBackend)


def entries_of(s: Balls) -> tuple[list, np.ndarray]:
    """The balls of a matrix in row-major order and their term scales (flattened)."""
    m, k = s.M.nrows(), s.M.ncols()
    return (s.M.entries() if m and k else []), s.m.ravel()
