"""Values paired with degree markers: the randomized methods' degree bound, from the very
evaluation that is sampled.

The randomized exact methods (``rational``, ``modular``) evaluate a claim at seeded random
points; Schwartz–Zippel turns "the residual vanished at the points" into a bound on the chance
that a nonzero residual did so, from a bound d on the degree of its numerator.  That bound must
belong to the polynomial actually evaluated.  A structural pass on degree markers alone is a
separate call of the claim, and a claim that keeps state between calls (a counter) could show
it a harmless expression and show the sampled points x^p − x, which vanishes at every point of
GF(p).  Here every number of a sampled evaluation is a :class:`Pair` (its value at the point,
the degree marker of the expression that computed it), and every whole matrix a pair of native
matrices (value backend, :class:`~stiefelsym.backends.native.DegreeBackend`): one call of the claim gives
both the values and the degree bound of what was evaluated.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from stiefelsym.backends.fields import LAYERED, Deg, DegreeField, Field, _is_matrix
from stiefelsym.backends.matrix import engine_number_type
from stiefelsym.backends.native import Backend, DegMat, DegreeBackend, _times, backend


@engine_number_type
class Pair:
    """A value of the point's field with the degree marker of the expression that computed it."""

    __slots__ = ("v", "d")

    def __init__(self, v: Any, d: Deg) -> None:
        self.v, self.d = v, d

    def __add__(self, o):
        if type(o) is Pair:
            return Pair(self.v + o.v, self.d + o.d)
        if _is_matrix(o) or type(o) in LAYERED:
            return NotImplemented    # a matrix, or a number of a field over the point's (dual, reverse)
        return Pair(self.v + o, self.d + o)

    __radd__ = __add__

    def __neg__(self):
        return Pair(-self.v, self.d)

    def __sub__(self, o):
        if type(o) is Pair:
            return Pair(self.v - o.v, self.d - o.d)
        if _is_matrix(o) or type(o) in LAYERED:
            return NotImplemented    # a matrix, or a number of a field over the point's (dual, reverse)
        return Pair(self.v - o, self.d - o)

    def __rsub__(self, o):
        return Pair(o - self.v, self.d - o)

    def __mul__(self, o):
        if type(o) is Pair:
            return Pair(self.v * o.v, self.d * o.d)
        if _is_matrix(o) or type(o) in LAYERED:
            return NotImplemented    # a matrix, or a number of a field over the point's (dual, reverse)
        return Pair(self.v * o, self.d * o)

    __rmul__ = __mul__

    def __truediv__(self, o):
        if type(o) is Pair:
            return Pair(self.v / o.v, self.d / o.d)
        if _is_matrix(o) or type(o) in LAYERED:
            return NotImplemented    # a matrix, or a number of a field over the point's (dual, reverse)
        return Pair(self.v / o, self.d / o)

    def __rtruediv__(self, o):
        return Pair(o / self.v, self.d.__rtruediv__(o))

    def __eq__(self, o):
        return self.v == (o.v if type(o) is Pair else o)

    def __ne__(self, o):
        return not self.__eq__(o)

    __hash__ = None

    def __repr__(self):
        return f"Pair({self.v!r}, {self.d!r})"


LAYERED[Pair] = "v"


class PairField(Field):
    """A point's field (rational or modular) whose elements carry degree markers (:class:`Pair`).

    Decisions that depend on values (zero tests, pivots, ranks, the description of a witness)
    are the value field's; the markers follow every operation, so the marker of a residual
    bounds the degree and height of the numerator of the rational function whose value at the
    point was computed."""

    def __init__(self, values: Field) -> None:
        self.values = values
        self.degrees = DegreeField()
        # markers are never changed once made: every parameter shares one, every constant its own
        self._param = self.degrees.param("")
        self._consts: dict = {}
        self.name = values.name
        self.exact = values.exact
        self.sample_size = values.sample_size
        if hasattr(values, "p"):
            self.p = values.p

    # -- elements ----------------------------------------------------------
    def lift(self, x: Any) -> Pair:
        if type(x) is Pair:
            return x
        if type(x) is int or type(x) is Fraction:
            return self.const(x)
        raise TypeError(f"not a number of the paired field: {type(x).__name__}")

    def record(self) -> tuple:
        """What the degree markers met so far, and the constants made (whose markers name the
        denominators met): see :meth:`restore`."""
        return self.degrees.record(), dict(self._consts)

    def restore(self, rec: tuple) -> None:
        """Back to a :meth:`record`: a constant made since then is made again, with its denominator
        registered again."""
        degrees, consts = rec
        self.degrees.restore(degrees)
        self._consts = dict(consts)

    def const(self, q):
        x = self._consts.get(q)
        if x is None:    # a constant that vanishes mod p is refused by the value field (not kept)
            x = self._consts[q] = Pair(self.values.const(q), self.degrees.const(q))
        return x

    def param(self, name, rng):
        return Pair(self.values.param(name, rng), self._param)

    def param_values(self, rng, count):
        return self.values.param_values(rng, count)

    def param_from_raw(self, x):
        return Pair(self.values.param_from_raw(x), self._param)

    def exact_input(self, x):
        # a hard case's chosen value stands where a parameter was: kept as a parameter's marker
        return Pair(self.values.exact_input(x.v if type(x) is Pair else x), self._param)

    def is_zero(self, x):
        return self.values.is_zero(x.v if type(x) is Pair else x)

    def is_exact_zero(self, x):
        # an elimination step is skipped only for a structural zero, so that the markers follow
        # every operation that a nonzero polynomial (vanishing at this point) would need
        return self.marker(x).zero

    def normalize(self, x):
        return x

    def pivot_cost(self, x):
        return self.values.pivot_cost(x.v if type(x) is Pair else x)

    def describe(self, x):
        return self.values.describe(x.v if type(x) is Pair else x)

    def value(self, x):
        """The value part (of a Pair, or a constant of the value field)."""
        return x.v if type(x) is Pair else (self.values.const(x) if type(x) in (int, Fraction) else x)

    def marker(self, x):
        """The degree marker (of a Pair, or of a constant)."""
        return x.d if type(x) is Pair else self.const(x).d if type(x) in (int, Fraction) else self.degrees._lift(x)

    # -- linear algebra: values by the value field, markers by Cramer's rule --------------------
    def solve(self, M, B):
        V = self.values.solve([[self.value(x) for x in r] for r in M], [[self.value(x) for x in r] for r in B])
        D = self.degrees.solve([[self.marker(x) for x in r] for r in M], [[self.marker(x) for x in r] for r in B])
        return [[Pair(v, d) for v, d in zip(rv, rd)] for rv, rd in zip(V, D)]

    def rank(self, M):
        return self.values.rank([[self.value(x) for x in r] for r in M])

    def native_backend(self):
        vb = backend(self.values)
        return None if vb is None else PairBackend(self, vb, backend(self.degrees))


class PairBackend(Backend):
    """Whole matrices as (value matrix, DegMat): every operation on both, in one pass."""

    def __init__(self, field: PairField, values: Backend, degrees: DegreeBackend) -> None:
        self.field, self.vb, self.db = field, values, degrees
        self._zero = Deg(-1, None, field.degrees)

    def accepts(self, x):
        return type(x) is Pair and self.vb.accepts(x.v)

    def from_obj(self, a):
        """The value matrix, and the marker DegreeBackend.from_obj gives the entries' markers:
        a sum over the entries, taken as one term per distinct marker with its multiplicity
        (k equal terms: the same degree, the height plus log2 k; sums do not depend on the order)."""
        f = self.field
        vals = []
        seen: dict[int, list] = {}
        for x in a.ravel().tolist():
            if type(x) is not Pair:
                x = f.lift(x)
            vals.append(x.v)
            d = x.d
            if not d.zero:
                c = seen.get(id(d))
                if c is None:
                    seen[id(d)] = [d, 1]
                else:
                    c[1] += 1
        V = np.empty(a.shape, dtype=object)
        if vals:
            V.reshape(-1)[:] = vals
        acc = self._zero
        for d, k in seen.values():
            acc = acc + _times(d, k)
        return (self.vb.from_obj(V), DegMat(a.shape, acc))

    def to_obj(self, s):
        V = self.vb.to_obj(s[0])
        d = s[1].d
        out = np.empty(V.shape, dtype=object)
        if V.size:
            out.reshape(-1)[:] = [Pair(v, d) for v in V.flat]
        return out

    def shape(self, s):
        return s[1].shape

    def zeros(self, m, k):
        return (self.vb.zeros(m, k), self.db.zeros(m, k))

    def identity(self, m):
        return (self.vb.identity(m), self.db.identity(m))

    def from_consts(self, a):
        return (self.vb.from_consts(a), self.db.from_consts(a))

    def from_array(self, a):
        return (self.vb.from_array(a), self.db.from_array(a))

    def sparse(self, m, k, entries):
        f = self.field
        return (self.vb.sparse(m, k, {i: f.value(x) for i, x in entries.items()}),
                self.db.sparse(m, k, {i: f.marker(x) for i, x in entries.items()}))

    def diag(self, xs):
        f = self.field
        return (self.vb.diag([f.value(x) for x in xs]), self.db.diag([f.marker(x) for x in xs]))

    def add(self, a, b):
        return (self.vb.add(a[0], b[0]), self.db.add(a[1], b[1]))

    def sub(self, a, b):
        return (self.vb.sub(a[0], b[0]), self.db.sub(a[1], b[1]))

    def neg(self, a):
        return (self.vb.neg(a[0]), self.db.neg(a[1]))

    def matmul(self, a, b):
        return (self.vb.matmul(a[0], b[0]), self.db.matmul(a[1], b[1]))

    def smul(self, a, c):
        f = self.field
        return (self.vb.smul(a[0], f.value(c)), self.db.smul(a[1], f.marker(c)))

    def T(self, a):
        return (self.vb.T(a[0]), self.db.T(a[1]))

    def trace(self, a):
        return Pair(self.vb.trace(a[0]), self.db.trace(a[1]))

    def inner(self, a, b):
        vb = self.vb
        v = vb.inner(a[0], b[0]) if hasattr(vb, "inner") else vb.trace(vb.matmul(vb.T(a[0]), b[0]))
        return Pair(v, self.db.inner(a[1], b[1]))

    def inv(self, a):
        v = self.vb.inv(a[0])               # a singular value matrix: DegenerateError (resample)
        return (v, self.db.inv(a[1]))

    def is_zero(self, a):
        return self.vb.is_zero(a[0])

    def block(self, grid):
        return (self.vb.block([[b[0] for b in row] for row in grid]),
                self.db.block([[b[1] for b in row] for row in grid]))


def marker_of(value: Any, field: PairField) -> Deg | None:
    """The one marker bounding every entry of a residual held natively, or None (read entries)."""
    from stiefelsym.backends.matrix import Mat
    if isinstance(value, Mat) and type(value._n) is tuple and type(value._n[1]) is DegMat and all(value._shape()):
        return value._n[1].d
    return None


__all__ = ["Pair", "PairField", "PairBackend", "marker_of"]
