"""Exact linear algebra for dimension statements, with two-sided certificates.

A dimension statement of the paper ("the generic orbit has dimension 2l", "the functions are
independent", "the kernel has dimension n") is an equality between an integer computed from a
matrix and a printed formula.  This module computes such integers with python-flint and says,
for each side, whether it is *proved* or holds with a stated probability:

* the rank of a matrix at an exact point is certified from below by a rank modulo a prime
  (a minor that is nonzero modulo p is a nonzero integer) and from above by kernel vectors
  verified exactly over ℤ (``M v = 0``, computed without any rounding);
* the *generic* rank of a polynomial matrix M(x) (x in ℤ^m) is at least its rank at any
  point, so the lower side is always proved; the upper side ("no larger minor is a nonzero
  polynomial") is either proved by polynomial kernel vectors checked identically
  (:func:`symbolic_kernel_bound`), trivially proved when the rank is full, or *checked*: at a
  point drawn uniformly from [-2^62, 2^62]^m the rank is smaller than the generic rank only if
  a nonzero minor of degree <= g·d vanishes there (Schwartz–Zippel, probability <= g·d/(2^63+1)),
  or if the random prime p in [2^62, 2^63) divides that nonzero integer minor (at most
  log2|minor|/62 primes do, |minor| <= the Hadamard bound of the point's matrix, among more than
  7.6·10^16 primes in the range, by Rosser–Schoenfeld).  Independent points multiply.

No numeric derivative and no floating-point rank is used anywhere: callers build Jacobians with
exact integer arithmetic (directional derivatives of polynomials written out by hand).
"""
from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Iterable, Sequence

import flint

from stiefelsym.ir.notation import power_of_ten

#: every randomized upper bound is pushed below this false-pass probability
TARGET = 1e-30
#: random points are drawn from [-2^BITS, 2^BITS]^m
BITS = 62
#: primes are drawn from [2^62, 2^63): more than PRIMES_IN_RANGE of them (Rosser–Schoenfeld:
#: pi(2^63) - pi(2^62) > 2^63/ln 2^63 - 1.25506·2^62/ln 2^62 > 7.6e16)
PRIME_LOW, PRIME_HIGH = 1 << 62, 1 << 63
PRIMES_IN_RANGE = 7.6e16
#: at most this many random points for one generic rank
MAX_POINTS = 12


# -- certificates ----------------------------------------------------------------------------

@dataclass(frozen=True)
class Side:
    """One side of a two-sided bound: the bound, how it was obtained, and the probability that it
    is false (0: proved)."""

    bound: int
    how: str
    false_probability: float = 0.0

    @property
    def proved(self) -> bool:
        return self.false_probability == 0.0


@dataclass(frozen=True)
class Certificate:
    """lower <= quantity <= upper, each side with its own justification.

    ``value`` is the quantity when both sides meet.  ``kind`` says how much of it is proved:
    ``proved`` (both sides exact), ``checked`` (one side holds up to ``false_probability``),
    ``bounds`` (the sides do not meet)."""

    quantity: str
    lower: Side
    upper: Side
    notes: tuple[str, ...] = field(default=())

    @property
    def value(self) -> int | None:
        return self.lower.bound if self.lower.bound == self.upper.bound else None

    @property
    def false_probability(self) -> float:
        return min(1.0, self.lower.false_probability + self.upper.false_probability)

    @property
    def proved(self) -> bool:
        return self.value is not None and self.lower.proved and self.upper.proved

    @property
    def kind(self) -> str:
        if self.value is None:
            return "bounds"
        return "proved" if self.proved else "checked"

    def describe(self) -> str:
        """One line: the value (or the bounds) and how each side is known."""
        if self.value is None:
            head = f"{self.quantity} in [{self.lower.bound}, {self.upper.bound}]"
        else:
            head = f"{self.quantity} = {self.value}"
        tail = f"{self.kind}" + (f", p <= {power_of_ten(self.false_probability)}" if self.kind == "checked" else "")
        return f"{head} ({tail}; >= by {self.lower.how}; <= by {self.upper.how})"

    def as_dict(self) -> dict:
        return {"quantity": self.quantity, "value": self.value, "kind": self.kind,
                "lower": self.lower.bound, "upper": self.upper.bound,
                "lower_how": self.lower.how, "upper_how": self.upper.how,
                "false_probability": self.false_probability, "notes": list(self.notes)}

    # -- arithmetic: dimensions computed from ranks (dim V - rank, 2 dim V - ddim - 2l, ...)
    def renamed(self, quantity: str, note: str | None = None) -> Certificate:
        return Certificate(quantity, self.lower, self.upper, self.notes + ((note,) if note else ()))

    def __neg__(self) -> Certificate:
        return Certificate(f"-({self.quantity})", Side(-self.upper.bound, self.upper.how, self.upper.false_probability),
                           Side(-self.lower.bound, self.lower.how, self.lower.false_probability), self.notes)

    def __add__(self, other: Certificate | int) -> Certificate:
        if isinstance(other, int):
            return Certificate(f"{self.quantity} + {other}", Side(self.lower.bound + other, self.lower.how,
                                                                   self.lower.false_probability),
                               Side(self.upper.bound + other, self.upper.how, self.upper.false_probability), self.notes)
        if not isinstance(other, Certificate):
            return NotImplemented
        return Certificate(f"{self.quantity} + {other.quantity}",
                           Side(self.lower.bound + other.lower.bound, _join(self.lower.how, other.lower.how),
                                self.lower.false_probability + other.lower.false_probability),
                           Side(self.upper.bound + other.upper.bound, _join(self.upper.how, other.upper.how),
                                self.upper.false_probability + other.upper.false_probability),
                           self.notes + other.notes)

    __radd__ = __add__

    def __sub__(self, other: Certificate | int) -> Certificate:
        return self + (-other)

    def __rsub__(self, other: int) -> Certificate:
        return (-self) + other

    def scaled(self, k: int) -> Certificate:
        """k·quantity for an integer k >= 0."""
        if k < 0:
            return (-self).scaled(-k)
        return Certificate(f"{k}·{self.quantity}", Side(k * self.lower.bound, self.lower.how, self.lower.false_probability),
                           Side(k * self.upper.bound, self.upper.how, self.upper.false_probability), self.notes)


def _join(a: str, b: str) -> str:
    return a if a == b else f"{a}; {b}"


def exact(quantity: str, value: int, how: str) -> Certificate:
    """A quantity known exactly (a printed constant, a count)."""
    return Certificate(quantity, Side(value, how), Side(value, how))


# -- integer matrices --------------------------------------------------------------------------

Rows = Sequence[Sequence[int | Fraction]]


def as_fmpz(M: flint.fmpz_mat | flint.fmpq_mat | Rows) -> flint.fmpz_mat:
    """An integer matrix with the same rank and kernel (rational rows are scaled by a common
    denominator)."""
    if isinstance(M, flint.fmpz_mat):
        return M
    if isinstance(M, flint.fmpq_mat):
        return M.numer_denom()[0]
    rows = [list(row) for row in M]
    if not rows:
        return flint.fmpz_mat(0, 0, [])
    if any(isinstance(x, Fraction) for row in rows for x in row):
        Q = flint.fmpq_mat([[flint.fmpq(Fraction(x).numerator, Fraction(x).denominator) for x in row] for row in rows])
        return Q.numer_denom()[0]
    return flint.fmpz_mat(rows)


def random_prime(rng: random.Random) -> int:
    """A prime drawn uniformly among the primes in [2^62, 2^63) (rejection sampling)."""
    while True:
        p = rng.randrange(PRIME_LOW, PRIME_HIGH) | 1
        if flint.fmpz(p).is_prime():
            return p


def rank_mod(M: flint.fmpz_mat, p: int) -> int:
    """The rank of M modulo p: a proved lower bound on its rank over ℚ."""
    if M.nrows() == 0 or M.ncols() == 0:
        return 0
    return flint.nmod_mat(M.nrows(), M.ncols(), [int(x) % p for x in M.entries()], p).rank()


def hadamard_log2(M: flint.fmpz_mat, g: int) -> float:
    """log2 of a bound on |every g x g minor| of M: the product of the g largest Euclidean row norms."""
    if g <= 0:
        return 0.0
    m, c = M.nrows(), M.ncols()
    norms = []
    for i in range(m):
        s = 0
        for j in range(c):
            x = int(M[i, j])
            s += x * x
        norms.append(0.5 * math.log2(s) if s else 0.0)
    norms.sort(reverse=True)
    return sum(norms[:g])


def verified_kernel(M: flint.fmpz_mat, K: flint.fmpz_mat) -> int:
    """The number of independent columns of K, after checking M K = 0 exactly over ℤ (0 if not)."""
    if K.ncols() == 0:
        return 0
    if not (M * K).is_zero():
        return 0
    return K.rank()


def rank_at_point(M: flint.fmpz_mat | Rows, quantity: str = "rank", *, seed: int = 0,
                  where: str = "at the point") -> Certificate:
    """The rank of one exact matrix, proved on both sides: from below by the rank modulo a random
    prime, from above by an exact kernel basis (fmpz nullspace, re-checked by M X = 0)."""
    Z = as_fmpz(M)
    m, c = Z.nrows(), Z.ncols()
    if m == 0 or c == 0:
        return exact(quantity, 0, "empty matrix")
    p = random_prime(random.Random(f"{seed}|{quantity}|rank_at_point"))
    low = rank_mod(Z, p)
    lower = Side(low, f"rank mod p={p} {where}")
    if low == min(m, c):
        return Certificate(quantity, lower, Side(low, "full rank"))
    K = _kernel(_independent_rows(Z, p, low))
    k = verified_kernel(Z, K)
    if k != c - low:   # the rows independent mod p miss a rational relation: the whole matrix
        K = _kernel(Z)
        k = verified_kernel(Z, K)
    upper = Side(c - k, f"{k} kernel vectors checked exactly {where}")
    return Certificate(quantity, lower, upper)


def _kernel(Z: flint.fmpz_mat) -> flint.fmpz_mat:
    """An integer basis of the kernel of Z (columns)."""
    c = Z.ncols()
    if Z.nrows() == 0:
        return flint.fmpz_mat([[1 if i == j else 0 for j in range(c)] for i in range(c)])
    X, nullity = Z.nullspace()
    if not nullity:
        return flint.fmpz_mat(c, 0, [])
    return flint.fmpz_mat([[X[i, j] for j in range(nullity)] for i in range(c)])


def _independent_rows(Z: flint.fmpz_mat, p: int, rank: int) -> flint.fmpz_mat:
    """``rank`` rows of Z independent modulo p (the pivots of Zᵀ mod p): their kernel over ℚ
    contains the kernel of Z, with equality when the rank over ℚ is ``rank``."""
    if rank == Z.nrows():
        return Z
    T = flint.nmod_mat(Z.ncols(), Z.nrows(), [int(Z[i, j]) % p for j in range(Z.ncols()) for i in range(Z.nrows())], p)
    R, rk = T.rref()
    pivots, col = [], 0
    for i in range(rk):
        while int(R[i, col]) == 0:
            col += 1
        pivots.append(col)
        col += 1
    return flint.fmpz_mat([[Z[i, j] for j in range(Z.ncols())] for i in pivots])


def generic_rank(evaluate: Callable[[list[int]], flint.fmpz_mat | Rows], nvars: int, degree: int,
                 quantity: str = "generic rank", *, seed: int = 0, target: float = TARGET,
                 max_points: int = MAX_POINTS, bits: int = BITS) -> Certificate:
    """The rank of M(x) over ℚ(x), where ``evaluate(x)`` is the matrix at the integer point x and
    every entry is a polynomial of degree <= ``degree`` in the ``nvars`` variables (with rational
    coefficients; rows may be rescaled by the caller).

    Lower side: the largest rank modulo a random prime at a random integer point (proved).
    Upper side: proved when that rank is full; otherwise it holds unless every point fell into the
    zero set of a nonzero minor or every prime divided one (bound in the module docstring)."""
    rng = random.Random(f"{seed}|{quantity}|generic_rank")
    best, best_how, prob, points = -1, "", 1.0, 0
    m = c = 0
    while points < max_points:
        x = [rng.randint(-(1 << bits), 1 << bits) for _ in range(nvars)]
        Z = as_fmpz(evaluate(x))
        m, c = Z.nrows(), Z.ncols()
        full = min(m, c)
        p = random_prime(rng)
        k = rank_mod(Z, p)
        points += 1
        if k > best:   # a larger rank: earlier points do not bound the generic rank from above any more
            best, prob = k, 1.0
            best_how = f"rank mod p={p} at a random integer point (seed {seed})"
        if best == full:
            return Certificate(quantity, Side(best, best_how), Side(best, "full rank"))
        per_point = full * max(degree, 1) / ((1 << (bits + 1)) + 1) + hadamard_log2(Z, full) / (62 * PRIMES_IN_RANGE)
        if k == best:
            prob *= min(1.0, per_point)
        if prob <= target and points >= 2:
            break
    if prob > target:   # the points never agreed often enough: only the trivial upper bound is certain
        return Certificate(quantity, Side(best, best_how),
                           Side(min(m, c), "min(rows, cols)"), (f"{points} points did not bound the rank from above "
                                                                f"below probability {target:g}",))
    how = (f"Schwartz–Zippel at {points} random integer points of [-2^{bits}, 2^{bits}]^{nvars} "
           f"(minors of degree <= {min(m, c)}·{degree}) and random primes in [2^62, 2^63)")
    return Certificate(quantity, Side(best, best_how), Side(best, how, prob))


# -- symbolic kernels: proved upper bounds on a generic rank ------------------------------------------

def symbolic_kernel_bound(M, K, point: dict, quantity: str = "generic rank", *, seed: int = 0) -> Certificate:
    """Both sides of the generic rank of a sympy matrix M over ℚ(x), proved.

    ``K`` is a sympy matrix of kernel vectors (columns, rational functions of x).  M K is expanded
    and must vanish identically; then rank M <= cols - rank K, and rank K >= its rank at ``point``
    (a dict symbol -> integer or Fraction), computed exactly.  The lower side is the rank of M at
    ``point``."""
    import sympy

    MK = (M * K).applyfunc(lambda e: sympy.cancel(sympy.expand(e)))
    if any(e != 0 for e in MK):
        raise ValueError(f"{quantity}: the proposed kernel vectors are not in the kernel identically")

    def at(A):
        rows = [[Fraction(str(sympy.nsimplify(A[i, j].subs(point)))) for j in range(A.shape[1])]
                for i in range(A.shape[0])]
        return as_fmpz(rows)

    lower = rank_at_point(at(M), quantity, seed=seed, where=f"at {point}").lower
    k_lower = rank_at_point(at(K), "kernel rank", seed=seed, where=f"at {point}").lower.bound
    upper = Side(M.shape[1] - k_lower, f"{k_lower} polynomial kernel vectors, M K = 0 identically")
    return Certificate(quantity, lower, upper)


def iter_pairs(m: int) -> Iterable[tuple[int, int]]:
    """(i, j) with 0 <= i < j < m."""
    for i in range(m):
        for j in range(i + 1, m):
            yield i, j
