"""Whole-matrix backends: one class per number system, each keeping a matrix in native code.

A :class:`~stiefelsym.backends.matrix.Mat` holds its entries either as a numpy array of field elements
(the generic representation every field supports: symbols, degree markers, duals over them) or
as the native storage of its field's backend, converting between the two only where an entry is
read or written.  Every backend implements the same operations on whole matrices:

=========================  =====================================================================
``ModularBackend``         GF(p) matrices in flint's ``nmod_mat``
``RationalBackend``        ℚ matrices in flint's ``fmpq_mat``
``Float64Backend``         numpy float64 values with a normwise (Frobenius) bound on their
                           rounding error (products by the dot-product bound γ_k ‖A‖_F ‖B‖_F,
                           inverses by a residual bound) and the scale of their terms
``DegreeBackend``          one degree/height marker bounding every entry (a structural bound:
                           O(1) per operation instead of one marker per entry)
``DualBackend``            pairs (value, derivative) over any backend: forward mode in one pass
=========================  =====================================================================

A backend never decides a verdict: it computes the same numbers the generic representation
would (or, for float64 and degree markers, sound bounds on them), and the tests compare the two
on random matrices.
"""
from __future__ import annotations

import contextlib
import math
import mmap
import sys
import threading
import weakref
from typing import Any

import numpy as np

from stiefelsym.backends.fields import FLOAT_UNDERFLOW, DegenerateError, Deg, Dual, ErrNum, FloatField, log2_add, log2_up

U64 = 2.0**-53

_LOCAL = threading.local()
_NULL = contextlib.nullcontext()


def _quiet() -> Any:
    """``np.errstate(all="ignore")`` for one operation (inf and nan are values of the error model,
    not warnings), or nothing inside :class:`quiet_numpy`, which has set it once (numpy's errstate
    costs about 2 µs per entry, a tenth of a 200 x 200 sum)."""
    return _NULL if getattr(_LOCAL, "quiet", False) else np.errstate(all="ignore")


class quiet_numpy:
    """A context (of the calling thread) in which numpy ignores floating-point errors, and the
    float64 backend's operations do not set that again one by one."""

    def __enter__(self):
        self._err = np.errstate(all="ignore")
        self._err.__enter__()
        self._old = getattr(_LOCAL, "quiet", False)
        _LOCAL.quiet = True
        return self

    def __exit__(self, *exc):
        _LOCAL.quiet = self._old
        self._err.__exit__(*exc)
        return False


class Backend:
    """Whole-matrix operations over one field (storage is backend-specific)."""

    #: whether :meth:`T` applies the field's involution ``field.star`` to every entry (a field with an
    #: involution takes the native transpose only from a backend that does)
    stars = False

    #: whether the solves and the cuts of the stacked gradients (:mod:`stiefelsym.systems`) are made in this
    #: backend, their results kept in it (the symbolic backend's; the other fields keep their own solvers)
    keeps_solutions = False

    def from_obj(self, a: np.ndarray) -> Any:
        raise NotImplementedError

    def to_obj(self, s: Any) -> np.ndarray:
        raise NotImplementedError

    def shape(self, s: Any) -> tuple[int, int]:
        raise NotImplementedError

    def zeros(self, m: int, k: int) -> Any:
        return self.from_obj(_fill(m, k, self.field.const(0)))

    def identity(self, m: int) -> Any:
        a = _fill(m, m, self.field.const(0))
        one = self.field.const(1)
        for i in range(m):
            a[i, i] = one
        return self.from_obj(a)

    def from_consts(self, a: np.ndarray) -> Any:
        """Native storage of a numpy array of integer constants."""
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = self.field.const(int(x))
        return self.from_obj(out)

    def unit(self, m: int, k: int, idx: tuple[int, int], x: Any) -> Any:
        """The m x k matrix with the field element x at idx and zeros elsewhere."""
        return self.sparse(m, k, {idx: x})

    def sparse(self, m: int, k: int, entries: dict) -> Any:
        """The m x k matrix with the given entries {(i, j): x} and zeros elsewhere."""
        a = _fill(m, k, self.field.const(0))
        for idx, x in entries.items():
            a[idx] = x
        return self.from_obj(a)

    def diag(self, xs: list[Any]) -> Any:
        """The diagonal matrix with the field elements xs on its diagonal."""
        a = _fill(len(xs), len(xs), self.field.const(0))
        for i, x in enumerate(xs):
            a[i, i] = x
        return self.from_obj(a)

    def block(self, grid: list[list[Any]]) -> Any:
        a = np.concatenate([np.concatenate([self.to_obj(b) for b in row], axis=1) for row in grid], axis=0)
        return self.from_obj(a)

    def accepts(self, x: Any) -> bool:
        """Whether a scalar can multiply a native matrix directly."""
        return True

    def take(self, s: Any, rows: np.ndarray, cols: np.ndarray) -> Any:
        """The sub-matrix of s on these rows and columns (index arrays), in native storage; or
        ``NotImplemented``, where the backend has no native form of it (the caller then reads the
        entries through the generic representation)."""
        return NotImplemented

    def entry(self, s: Any, i: int, j: int) -> Any:
        """The field element at (i, j) of s; or ``NotImplemented`` (as for :meth:`take`)."""
        return NotImplemented


def _fill(m: int, k: int, x: Any) -> np.ndarray:
    a = np.empty((m, k), dtype=object)
    a.fill(x)
    return a


# ----------------------------------------------------------------------------- flint
class _FlintBackend(Backend):
    mat: Any = None

    def shape(self, s):
        return (s.nrows(), s.ncols())

    def identity(self, m):
        M = self.zeros(m, m)
        for i in range(m):
            M[i, i] = 1
        return M

    def diag(self, xs):
        M = self.zeros(len(xs), len(xs))
        for i, x in enumerate(xs):
            M[i, i] = x
        return M

    def sparse(self, m, k, entries):
        M = self.zeros(m, k)
        for (i, j), x in entries.items():
            M[i, j] = x
        return M

    def to_obj(self, s):
        m, k = s.nrows(), s.ncols()
        a = np.empty((m, k), dtype=object)
        if m and k:
            a[:, :] = np.array(s.entries(), dtype=object).reshape(m, k)
        return a

    def add(self, a, b):
        return a + b

    def sub(self, a, b):
        return a - b

    def neg(self, a):
        return -a

    def matmul(self, a, b):
        if a.ncols() == 0:
            return self.zeros(a.nrows(), b.ncols())
        return a * b

    def smul(self, a, c):
        return a * c

    def T(self, a):
        return a.transpose()

    def trace(self, a):
        acc = self.field.const(0)
        for i in range(a.nrows()):
            acc = acc + a[i, i]
        return acc

    def inv(self, a):
        try:
            return a.inv()
        except ZeroDivisionError as exc:
            raise DegenerateError("singular matrix") from exc

    def is_zero(self, a):
        return a == self.zeros(a.nrows(), a.ncols())


class ModularBackend(_FlintBackend):
    """GF(p) matrices as flint ``nmod_mat``."""

    def __init__(self, field) -> None:
        import flint
        self.field, self.p, self._flint = field, field.p, flint

    def from_obj(self, a):
        m, k = a.shape
        nm = self._flint.nmod
        flat = [x if type(x) is nm else nm(int(x), self.p) for x in a.flat]
        return self._flint.nmod_mat(m, k, flat, self.p) if m and k else self._flint.nmod_mat(m, k, self.p)

    def zeros(self, m, k):
        return self._flint.nmod_mat(m, k, self.p)

    def accepts(self, x):
        return type(x) is self._flint.nmod

    def from_consts(self, a):
        return self.from_array(a)

    def from_array(self, a):
        """Native storage of an integer array (a block of parameters), reduced mod p."""
        m, k = a.shape
        return self._flint.nmod_mat(m, k, a.ravel().tolist(), self.p) if m and k else self.zeros(m, k)


class RationalBackend(_FlintBackend):
    """ℚ matrices as flint ``fmpq_mat``."""

    def __init__(self, field) -> None:
        import flint
        self.field, self._flint = field, flint

    def from_obj(self, a):
        m, k = a.shape
        q = self._flint.fmpq
        flat = [x if type(x) is q else q(x) for x in a.flat]
        return self._flint.fmpq_mat(m, k, flat) if m and k else self._flint.fmpq_mat(m, k)

    def zeros(self, m, k):
        return self._flint.fmpq_mat(m, k)

    def accepts(self, x):
        return type(x) in (self._flint.fmpq, self._flint.fmpz)

    def from_consts(self, a):
        return self.from_array(a)

    def from_array(self, a):
        """Native storage of an integer array (a block of parameters)."""
        m, k = a.shape
        return self._flint.fmpq_mat(m, k, a.ravel().tolist()) if m and k else self.zeros(m, k)


# ----------------------------------------------------------------------------- float64
class F64:
    """A float64 matrix v with a normwise error bound e (a float: the Frobenius norm of the error,
    hence a bound on every entry's error) and entrywise term scales m.

    No operation writes into v or m (each makes new arrays, a transpose is a view), so an F64
    never changes once built, and the backend keeps what it learns about one: ``nv``, the bound
    on ‖v‖_F once computed; ``t``, its transpose; ``prods``, the products it was the left factor
    of ({id(right factor): (right factor, product)}: the same two matrices are never multiplied
    twice), and likewise its sums, differences ({("+" or "-", id(other)): (other, result)}) and
    multiples by a scalar ({("*", value, bound, scale): (None, result)}); ``diag``, its diagonal (values, term scales) when it is diagonal by construction;
    ``sel``, (rows, signs) when every column j is signs[j] times the unit vector of rows[j]
    (signs[j] = 0: a zero column; a diagonal keeps its full arrays deferred until read, see
    below); ``msym``, whether the term scales are a symmetric matrix.

    The term scales are kept in one of two forms.  Either m is a float64 array, or they are
    ``m32`` (float32) with a factor ``mf`` <= 1 such that mf·m32 is at most the exact term scales
    (the recurrences |A|_m + |B|_m, |A|_m |B|_m, |c|_m |A|_m evaluated in ℝ) entrywise, and
    ``mtop`` >= every entry of m32; m is then made from them when read, rounded down (see
    :func:`_s32`).  Sums, products and scalar multiples of scales in float32 move half the bytes
    of float64 and need no conversion in between; each only lowers mf by its own rounding bound,
    so the resolution test is never easier than with the exact scales.  ``m32`` also holds the
    float32 copy of a float64 m once made (``False``: they do not fit in float32); ``msrc``,
    (matrix, transposed) when the scales are another matrix's (a transpose, a negation), whose
    float64 m is then shared.  ``fac``, (c, d) when the matrix was computed as the product c d
    (see :meth:`Float64Backend._reassociated`).

    An F64 may also be *deferred* (``lazy`` holds how to compute it, ``defer`` what it is: the
    inverse of a matrix whose inverse is known to exist with a bounded norm, or a product with
    such an inverse): v, e and m are computed when first read, by the same operations an eager
    computation makes, and the backend may instead use what it is for a cheaper product (a
    deferred inverse times B is a solve; a deferred product times a selection of columns is
    reassociated), each with a bound of its own."""

    __slots__ = ("_v", "_e", "_m", "nv", "t", "prods", "diag", "sel", "m32", "mf", "mtop", "msrc", "msym",
                 "fac", "lazy", "defer", "__weakref__")

    def __init__(self, v: np.ndarray, e: float, m: np.ndarray | None, nv: float | None = None) -> None:
        self._v, self._e, self._m, self.nv = v, e, m, nv
        self.t = self.prods = self.diag = self.sel = self.m32 = self.mf = self.mtop = self.msym = None
        self.msrc = self.fac = self.lazy = self.defer = None

    @classmethod
    def deferred(cls, build: Any, defer: tuple, e: float | None = None, nv: float | None = None) -> "F64":
        """A matrix computed by build() (an eager F64 with the bound e, when given) when its values
        are first read; defer is (kind, shape, ...) for the backend."""
        out = cls.__new__(cls)
        out._v = out._m = None
        out._e, out.nv = e, nv
        out.t = out.prods = out.diag = out.sel = out.m32 = out.mf = out.mtop = out.msym = out.msrc = None
        out.fac = None
        out.lazy, out.defer = build, defer
        return out

    def _force(self) -> None:
        build = self.lazy
        done = build()
        self._v, self._e, self._m = done._v, done._e, done._m
        self.m32, self.mf, self.mtop, self.msrc = done.m32, done.mf, done.mtop, done.msrc
        if self.nv is None:
            self.nv = done.nv
        self.lazy = self.defer = None

    @property
    def v(self) -> np.ndarray:
        if self.lazy is not None:
            self._force()
        return self._v

    @property
    def e(self) -> float:
        if self._e is None:
            self._force()
        return self._e

    @property
    def m(self) -> np.ndarray:
        if self.lazy is not None:
            self._force()
        m = self._m
        if m is None:
            src = self.msrc
            if src is not None:                # the scales of another matrix (transposed): its m
                m = src[0].m.T if src[1] else src[0].m
            else:
                # float64 of mf·m32, rounded down: the float32 entries are exact in float64, and
                # the factor 1 − 2⁻⁴⁰ covers the roundings of mf·(1 − 2⁻⁴⁰) and of the product
                m = np.multiply(self.m32, self.mf * (1.0 - 2.0**-40), dtype=np.float64,
                                out=_out_like(self.m32, np.float64))
            self._m = m
        return m


#: arrays of the float backend from this many bytes up to POOL_MAX_BYTES come from a pool of its own
#: (see :func:`_buf`); smaller ones come from the allocator's heap, without page faults
POOL_MIN_BYTES = 1 << 16
POOL_MAX_BYTES = 1 << 22
#: at most this many bytes are pooled per thread, and this many arrays of one shape and type (a
#: search for a free one looks at each); beyond, arrays are allocated as usual
POOL_TOTAL_BYTES = 1 << 26
POOL_PER_SHAPE = 32
#: whether the pool is used (the tests compare every value, bound and scale with it and without it)
POOL = True


class _Pool(threading.local):
    """The arrays the float backend reuses, by (shape, dtype) as the callers name them, per thread:
    the list of arrays of that kind, or None for a size outside the pool's range."""

    def __init__(self) -> None:
        self.bufs: dict[tuple, list | None] = {}
        self.total = 0


_POOL = _Pool()


def _refs_when_free() -> int:
    """The reference count :func:`_buf` sees for a pooled array nothing else refers to (the pool's
    list, the loop's name and the argument of sys.getrefcount), measured the way _buf measures it."""
    bufs = [np.empty(1)]
    for b in bufs:
        return sys.getrefcount(b)
    raise AssertionError


_FREE_REFS = _refs_when_free()


def _buf(shape: tuple, dtype: Any = np.float64) -> np.ndarray:
    """An uninitialised C-contiguous array (a view of a pooled one): from the pool when one of that
    shape and type is free, that is when nothing but the pool refers to it (every array made from
    a pooled one, a view, a transpose, a slice, refers to it through its base).  A fresh 200 x 200
    array is otherwise paged in from the kernel on every evaluation (the allocator returns the
    heap's top when the evaluation frees its values); a pooled one is reused.  Each pooled array is
    an anonymous mapping of its own, so that the pool pins no part of the allocator's heap (which
    the arrays of the rest of the process reuse).  The arrays are only where the results go: every
    value is computed by the same numpy or BLAS call as without the pool, into an array of the
    same layout."""
    if not POOL:
        return np.empty(shape, dtype=dtype)
    if isinstance(dtype, np.dtype):
        dtype = dtype.type                  # one pool for np.float64 and np.dtype("float64")
    pool = _POOL
    key = (shape, dtype)
    bufs = pool.bufs.get(key, _MISSING)
    if bufs is _MISSING:
        nbytes = math.prod(shape) * np.dtype(dtype).itemsize
        bufs = pool.bufs[key] = [] if POOL_MIN_BYTES <= nbytes <= POOL_MAX_BYTES else None
    if bufs is None:
        return np.empty(shape, dtype=dtype)
    for b in bufs:
        if sys.getrefcount(b) == _FREE_REFS:
            return b.reshape(shape)
    dt = np.dtype(dtype)
    nbytes = math.prod(shape) * dt.itemsize
    if _PRIVATE is not None and len(bufs) < POOL_PER_SHAPE and pool.total + nbytes <= POOL_TOTAL_BYTES:
        # a private anonymous mapping of its own (copied on write in a forked process, never shared),
        # outside the allocator's heap (which the pool would otherwise pin)
        root = np.frombuffer(mmap.mmap(-1, nbytes, flags=_PRIVATE), dtype=dt)
        bufs.append(root)
        pool.total += nbytes
        return root.reshape(shape)
    return np.empty(shape, dtype=dtype)


_MISSING = object()
#: mmap's flag of a private mapping (None where mmap has none: the pool then keeps nothing)
_PRIVATE = getattr(mmap, "MAP_PRIVATE", None)


def _out_like(x: np.ndarray, dtype: Any = None) -> np.ndarray | None:
    """A pooled array for the result of an elementwise operation on x (and operands of x's
    layout), in the layout numpy gives it (order K: C for C-contiguous x, the transpose of a C
    array for a transposed one); None for another layout (numpy then allocates)."""
    dt = x.dtype if dtype is None else dtype
    if x.ndim != 2:
        return None
    if x.flags.c_contiguous:
        return _buf(x.shape, dt)
    if x.flags.f_contiguous:
        return _buf((x.shape[1], x.shape[0]), dt).T
    return None


def _same_layout(x: np.ndarray, y: np.ndarray) -> bool:
    """Whether x and y are both C-contiguous or both transposes of C-contiguous arrays (numpy's
    order K then lays their elementwise result out as they are)."""
    fx, fy = x.flags, y.flags
    return (fx.c_contiguous and fy.c_contiguous) or (fx.f_contiguous and fy.f_contiguous
                                                     and not fx.c_contiguous and not fy.c_contiguous)


def _mixed_layout_is_c() -> bool:
    """Whether numpy lays out the elementwise result of a C-contiguous and a transposed
    (F-contiguous) operand in C order, either way round (order K; measured once)."""
    c, f = np.ones((2, 3)), np.ones((3, 2)).T
    return bool(np.add(c, f).flags.c_contiguous and np.add(f, c).flags.c_contiguous)


_MIXED_C = _mixed_layout_is_c()


def _binop(f: Any, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """f(x, y) for a numpy ufunc f and two arrays of one shape and type, into a pooled array of the
    layout numpy's own result would have (the operands', or C order for one C-contiguous and one
    transposed operand where numpy chooses it)."""
    if x.shape == y.shape and x.dtype == y.dtype and x.ndim == 2:
        if _same_layout(x, y):
            out = _out_like(x)
            if out is not None:
                return f(x, y, out=out)
        elif _MIXED_C and ((x.flags.c_contiguous and y.flags.f_contiguous)
                           or (x.flags.f_contiguous and y.flags.c_contiguous)):
            return f(x, y, out=_buf(x.shape, x.dtype))
    return f(x, y)


def _matmul(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """x @ y into a pooled C-contiguous array (numpy's own result is C-contiguous: the same BLAS
    call writes it)."""
    if x.ndim == 2 and y.ndim == 2 and x.dtype == y.dtype and x.dtype in (np.float64, np.float32):
        return np.matmul(x, y, out=_buf((x.shape[0], y.shape[1]), x.dtype))
    return x @ y


#: identity matrices of the float backend, read-only, by size (up to POOL_MAX_BYTES each, the last few sizes)
_EYES: dict[int, np.ndarray] = {}


def _eye(m: int) -> np.ndarray:
    """np.eye(m), shared and read-only (an identity's values are never written into; a write would
    raise) up to POOL_MAX_BYTES."""
    i = _EYES.get(m)
    if i is None:
        i = np.eye(m)
        if POOL and i.nbytes <= POOL_MAX_BYTES:
            i.flags.writeable = False
            if len(_EYES) >= 8:
                del _EYES[next(iter(_EYES))]
            _EYES[m] = i
    return i


def _copy(x: np.ndarray) -> np.ndarray:
    """x.copy() (C order) into a pooled array."""
    if x.ndim != 2:
        return x.copy()
    out = _buf(x.shape, x.dtype)
    np.copyto(out, x)
    return out


def _gamma(k: int) -> float:
    """γ_k = k u / (1 − k u), the dot-product rounding constant (Higham, Thm 3.5), padded for the
    rounding of the bound's own evaluation."""
    ku = (k + 2) * U64
    return ku / (1.0 - ku) * (1.0 + 1e-6)


def _up(x: float, k: int) -> float:
    """Inflate a bound computed in float64 (k operations) so that its own rounding errors cannot
    make it too small."""
    return x * (1.0 + _gamma(k + 4))


#: below this sum of squares, squares that fell under the normal range could matter: rescale
_SQUARES_TINY = 2.0**-900


def _fro(x: np.ndarray) -> float:
    """An upper bound on the Frobenius norm of x (inf on overflow): one BLAS dot product of x with
    itself, whose rounding in any order of summation is within γ_N of the sum of the squares, plus
    at most 2⁻¹⁰⁷⁵ per operation where a square or a partial sum falls below the normal range;
    relative to a sum of squares above 2⁻⁹⁰⁰ that is far inside the padding of γ, and below it
    the dot product is redone on x scaled by a power of two (exactly) to the size of 1."""
    f = x.ravel(order="K")
    with _quiet():
        s = float(np.dot(f, f))
        if not s < _SQUARES_TINY:               # normal size, inf or nan
            return math.sqrt(s) * (1.0 + _gamma(f.size + 4))
        mx = float(np.max(np.abs(f))) if f.size else 0.0
        if mx == 0.0:
            return 0.0
        k = math.frexp(mx)[1]
        g = np.ldexp(f, -k)                      # exact: the largest entry becomes [1/2, 1)
        s = float(np.dot(g, g))
    return math.nextafter(math.ldexp(math.sqrt(s) * (1.0 + _gamma(f.size + 4)), k), math.inf)


def _norm(a: F64) -> float:
    """The bound on ‖a.v‖_F, computed once per matrix."""
    nv = a.nv
    if nv is None:
        nv = a.nv = _fro(a.v)
    return nv


#: term scales up to this size go through float32 products (k·(2^56)^2 < 2^127 for k <= 2^14)
_M32_MAX = 2.0**56
_M32_K_MAX = 2**14
#: term scales up to this size take float32 sums and multiples (a sum of two stays below 2^127)
_S32_MAX = 2.0**120
#: one float32 rounding of the result and one of an input (2^-24 each), with room for the float64
#: rounding of the factor itself: (1 − 2^-22)(1 + 2^-24)^2 (1 + 2^-53) < 1
_R32 = 1.0 - 2.0**-22


def _f32(v: np.ndarray, e: float, m32: np.ndarray, mf: float, top: float, nv: float | None = None) -> F64:
    """An F64 whose term scales are mf·m32 (float32, see :class:`F64`), every entry of m32 <= top."""
    out = F64(v, e, None, nv)
    out.m32, out.mf, out.mtop = m32, mf, top
    return out


def _down32(x: np.ndarray) -> np.ndarray:
    """x (float64, >= 0) in float32 rounded down, entry by entry, also below float32's normal range
    (rounded to nearest, then one step towards 0)."""
    out = _out_like(x, np.float32)
    if out is None:
        y = x.astype(np.float32)
    else:
        y = out                                  # the same conversion, into a pooled array of astype's layout
        np.copyto(y, x, casting="unsafe")
    # one step towards 0 is one unit less in the bits of a positive float32 (+inf becomes the largest
    # finite float32, as nextafter does); 0 and -0 stay; ten times faster than np.nextafter
    bits = y.view(np.int32)
    bits -= bits > 0                     # 1 where the bits are positive, 0 elsewhere (twice as fast as where=)
    return y


def _s32(a: F64, limit: float = _M32_MAX) -> tuple[np.ndarray, float, float] | None:
    """(m32, mf, top): a's term scales in float32 with mf·m32 <= the exact scales and every entry
    of m32 <= top < limit; None when they do not fit (not all finite, or a largest entry at or
    above the limit).  A float64 m is converted once per matrix (a transpose shares it), rounded
    down (:func:`_down32`): m32 <= m, and m itself is at most (1 + 2⁻³⁹) above the exact scales
    (float64 sums of at most 2¹⁴ terms), inside the factor 1 − 2⁻²²."""
    if a.lazy is not None:
        a._force()
    m32 = a.m32
    if m32 is None:
        t = a.t
        if t is not None and t.m32 is not None:
            if t.m32 is False:
                m32 = False
            else:
                m32, a.mf, a.mtop = t.m32.T, t.mf, t.mtop
        else:
            m = a._m
            with _quiet():
                top = float(m.max()) if m.size else 0.0
            if 0.0 <= top < _M32_MAX:
                m32, a.mf, a.mtop = _down32(m), _R32, top * (1.0 + 2.0**-20)
            else:
                m32 = False
        a.m32 = m32
    if m32 is False:
        return None
    if not a.mtop < limit:
        # the stored top is a bound grown by products: the largest entry itself (one pass)
        with _quiet():
            top = float(m32.max()) if m32.size else 0.0
        if not 0.0 <= top < math.inf:
            return None
        a.mtop = top
        if not top < limit:
            return None
    return m32, a.mf, a.mtop


def _scales_of(a: F64, transpose: bool = False) -> tuple:
    """a's term scales in its own form, transposed if asked: (m, m32, mf, mtop, msrc) for a new
    F64 (msrc: its float64 m, when read, is a's, transposed if asked)."""
    if a.lazy is not None:
        a._force()
    if a._m is None:
        return None, (a.m32.T if transpose else a.m32), a.mf, a.mtop, (a, transpose)
    m32 = a.m32
    if transpose and m32 is not None and m32 is not False:
        m32 = m32.T
    return (a._m.T if transpose else a._m), m32, a.mf, a.mtop, None


def _like(v: np.ndarray, e: float, a: F64, nv: float | None, transpose: bool = False) -> F64:
    """A new F64 (values v, bound e) with a's term scales (transposed if asked), in a's form."""
    return _with_scales(v, e, _scales_of(a, transpose), nv)


def _msym(a: F64) -> bool:
    """Whether a's term scales are a symmetric matrix (exactly, in the form they are kept), once per
    matrix."""
    sym = a.msym
    if sym is None:
        if a.lazy is not None:
            a._force()
        m = a._m if a._m is not None else a.m32
        sym = a.msym = m.shape[0] == m.shape[1] and bool(np.array_equal(m, m.T))
    return sym


def _scale_product(a: F64, b: F64) -> tuple:
    """The term scales |A|_m |B|_m of a product, as (m, m32, mf, top, msrc) for
    :func:`_with_scales`.  They are the scale the resolution test compares the error bound with,
    not a bound on anything, and a few digits describe them: one float32 product (half the time
    of float64) of the scales in float32, whose factor mf is the product of the inputs' times
    1 − 2(k + 4)·2⁻²⁴ (above the float32 dot-product bound γ_k), so that mf·m32 never exceeds
    the exact scales Σ_k m_ik m_kj (only sums below float32's normal range, 10^-38, may differ by
    its underflow unit): the test is never easier to pass than with the exact scales.  Scales
    too large for float32 take one float64 product."""
    k = a.v.shape[1]
    sa = _s32(a) if k <= _M32_K_MAX else None
    sb = _s32(b) if sa is not None else None
    if sb is None:
        return a.m @ b.m, None, None, None, None
    (a32, fa, ta), (b32, fb, tb) = sa, sb
    g = 2.0 * (k + 4) * 2.0**-24
    return None, _matmul(a32, b32), fa * fb * (1.0 - g) * (1.0 - 2.0**-50), k * ta * tb * (1.0 + g), None


def _scales_sum(a: F64, b: F64) -> tuple:
    """The term scales |A|_m + |B|_m of a sum or difference, as (m, m32, mf, top, msrc): in float32
    when either operand keeps its scales there (and both fit), with mf = min(mf_a, mf_b)(1 − 2⁻²²)
    for the sum's rounding; in float64 otherwise."""
    if a.lazy is not None:
        a._force()
    if b.lazy is not None:
        b._force()
    if a._m is None or b._m is None:
        sa = _s32(a, _S32_MAX)
        sb = _s32(b, _S32_MAX) if sa is not None else None
        if sb is not None:
            (a32, fa, ta), (b32, fb, tb) = sa, sb
            return None, _binop(np.add, a32, b32), min(fa, fb) * _R32, (ta + tb) * (1.0 + 2.0**-22), None
    return _binop(np.add, a.m, b.m), None, None, None, None


def _with_scales(v: np.ndarray, e: float, sc: tuple, nv: float | None = None) -> F64:
    """A new F64 with the term scales sc = (m, m32, mf, top, msrc) (see :func:`_scales_of`)."""
    out = F64(v, e, sc[0], nv)
    out.m32, out.mf, out.mtop, out.msrc = sc[1:]
    return out


def _exact_zero(a: F64) -> bool:
    """Whether a is the zero matrix exactly (a selection of zero columns with no error)."""
    sel = a.sel
    return sel is not None and a.lazy is None and a._e == 0.0 and not sel[1].any()


def _uf(shape) -> float:
    """The Frobenius norm of a matrix of one underflow unit per entry (subnormal rounding)."""
    return FLOAT_UNDERFLOW * math.sqrt(shape[0] * shape[1]) * 2.0


#: X = (I − S)(I + S)⁻¹ J from the solve Y = (I + S)⁻¹ J as 2Y − J (see :meth:`Float64Backend._cayley`)
CAYLEY_BY_SOLVE = True


#: up to this many rows a block inverse is LAPACK's; above, it is split in two (see :func:`_block_inverse`)
BLOCK_INVERSE_LEAF = 32


def _block_inverse(a: np.ndarray) -> np.ndarray:
    """An approximate inverse of a square matrix by the 2 x 2 block formula: A11⁻¹ and the inverse
    of the Schur complement Σ = A22 − A21 A11⁻¹ A12 recursively, the rest by matrix products.  Both
    exist when the symmetric part of A is positive definite (I + S with S skew): so is that of A11,
    and of Σ (for z = (−A11⁻¹A12 x, x), zᵀAz = xᵀΣx).  LAPACK's factorizations of small matrices
    run far below the speed of its products (at 100 rows a solve with 100 right-hand sides took 8
    times as long as a product of that size); the Cayley solve at n = 200, r = 100 (two inverses of
    100 rows) took 2/3 of the time of LAPACK's.  Only values: callers bound the error of what they
    compute with it by a residual.  Raises LinAlgError where a block is singular."""
    n = a.shape[0]
    if n <= BLOCK_INVERSE_LEAF:
        return np.linalg.inv(a)
    h = n // 2
    a12, a21 = a[:h, h:], a[h:, :h]
    i11 = _block_inverse(a[:h, :h])
    t = _matmul(a21, i11)               # A21 A11⁻¹
    out = _buf((n, n))
    out[h:, h:] = _block_inverse(a[h:, h:] - _matmul(t, a12))
    u = _matmul(i11, a12)               # A11⁻¹ A12
    np.matmul(u, out[h:, h:], out=out[:h, h:])
    np.negative(out[:h, h:], out=out[:h, h:])             # −A11⁻¹ A12 Σ⁻¹
    np.matmul(out[h:, h:], t, out=out[h:, :h])
    np.negative(out[h:, :h], out=out[h:, :h])             # −Σ⁻¹ A21 A11⁻¹
    np.matmul(out[:h, h:], t, out=out[:h, :h])
    np.subtract(i11, out[:h, :h], out=out[:h, :h])        # A11⁻¹ + A11⁻¹ A12 Σ⁻¹ A21 A11⁻¹
    return out


def _solve_top(v: np.ndarray, sel: tuple) -> np.ndarray | None:
    """Y ≈ v⁻¹ [D; 0] (D = diag(signs), r x r, the selection sel of the first r unit vectors) by
    blocks: W = v22⁻¹ v21, the Schur complement C = v11 − v12 W, Y = [C⁻¹ D; −W C⁻¹ D], the two
    inverses by :func:`_block_inverse` (v = I + S: every block and Schur complement has a
    positive definite symmetric part).  Only the values: the caller bounds the error of Y by its
    residual, whatever the method.  None when sel is not of that form, r = n, or a block is
    singular or the result not finite."""
    rows, signs = sel
    n, r = v.shape[0], len(rows)
    if not 0 < r < n or v.shape[1] != n or not np.array_equal(rows, np.arange(r)):
        return None
    try:
        W = _matmul(_block_inverse(v[r:, r:]), v[r:, :r])
        C = v[:r, :r] - _matmul(v[:r, r:], W)
        Y = _buf((n, r))
        np.multiply(_block_inverse(C), signs, out=Y[:r])   # C⁻¹ D: columns times ±1 or 0, exactly
    except np.linalg.LinAlgError:
        return None
    np.matmul(W, Y[:r], out=Y[r:])
    np.negative(Y[r:], out=Y[r:])
    if not np.isfinite(Y).all():
        return None
    return Y


#: from this many rows on, an inverse known to exist (see :meth:`Float64Backend.inv`) is deferred
DEFERRED_INVERSE_MIN = 32


def _skew_plus_diagonal(a: F64) -> tuple[float, float] | None:
    """(beta0, beta) with ‖a.v⁻¹‖₂ ≤ beta0 and ‖A⁻¹‖₂ ≤ beta for every A within a's bound, when
    the values are a positive diagonal plus an exactly skew matrix (v_ij + v_ji = 0 for i ≠ j, a
    floating-point sum that is 0 exactly when it is 0 in ℚ; d = diag v > 0): then
    xᵀ v x = Σ d_i x_i² ≥ min d ‖x‖², so σ_min(v) ≥ min d and σ_min(A) ≥ min d − e.  None
    otherwise, or when e is not below min d / 2."""
    v = a.v
    d = float(np.diagonal(v).min())
    if not d > 0.0 or not a.e < 0.5 * d:
        return None
    with _quiet():
        h = np.add(v, v.T, out=_buf(v.shape))         # only tested for zeros (any layout)
    np.fill_diagonal(h, 0.0)
    if h.any():
        return None
    beta0 = _up(1.0 / d, 1)
    beta = _up(1.0 / ((d - a.e) * (1.0 - 4 * U64)), 2)
    return beta0, beta


class Float64Backend(Backend):
    """float64 matrices with a sound first-order normwise error bound (the Frobenius norm of the
    error of every operation: Higham's γ_k bounds with ‖|A||B|‖_F ≤ ‖A‖_F ‖B‖_F, propagated
    errors by the triangle inequality) and a residual-checked inverse; numpy/BLAS does the
    arithmetic, one float64 product per product (and one float32 product for the term scales, see
    :func:`_scale_product`).

    The bound of an operation depends only on the bounds, norms and shapes of its operands, never
    on how the values were computed, so the backend computes them as cheaply as it can: a product
    already computed (or its transpose: AB = (BᵀAᵀ)ᵀ, a transpose keeps the norm and the bound) is
    not computed again; a product with a diagonal matrix scales rows or columns, a product with a
    signed selection (the constant [D; 0] of the Cayley chart) takes columns, each with one
    rounding at most where a BLAS product would sum k terms, so the dot-product bound γ_k covers
    them as it covers BLAS."""

    def __init__(self, field) -> None:
        self.field = field
        #: the matrices holding a remembered product or transpose, by id, weakly (see :meth:`release`):
        #: a matrix nothing else refers to goes at once, with what it remembers
        self._holders: dict[int, weakref.ref] = {}
        #: where a matrix is remembered as the other operand: {id(b): [(holder, key), ...]}
        self._as_operand: dict[int, list] = {}

    def release(self) -> None:
        """Forget every remembered product and transpose.  They tie matrices to each other in
        cycles, which only the garbage collector would free; the float method releases them when an
        evaluation is over, so its arrays go as soon as the scene does."""
        holders, self._holders = self._holders, {}
        self._as_operand = {}
        for ref in holders.values():
            a = ref()
            if a is not None:
                a.prods = a.t = None

    def forget(self, a: F64, live: Any = ()) -> None:
        """The evaluation reads a no more (the graph evaluator's word, see
        :func:`.ir.evaluate.release_plan`; ``live``: the ids of the matrices it still reads): forget
        what a remembers (its products, sums, multiples and transpose) and the results remembered
        with a as the other operand, so that those arrays go as soon as nothing else reads them,
        not at the end of the evaluation (a graph of LA1 at n = 200 otherwise keeps every
        200 x 200 intermediate alive to the end, and the allocator hands their pages back and
        faults them in again on every run).  While a's transpose is still read, a stays as it
        is: a product or sum with the transpose is looked up through a ((A Bᵀ)ᵀ = B Aᵀ; the
        evaluator keeps the nodes such a lookup finds).  A result stays while its operands do,
        whatever becomes of it: a later product may find it (a chain reassociated through a
        product already known, see :meth:`_reassociated`), and computing it again could take
        another association.  Only what is remembered goes: a's values, bound and scales stay, and
        a later operation with a computes what it needs again."""
        t = a.t
        if t is not None and id(t) in live:
            return
        for x in (a,) if t is None else (a, t):
            self._holders.pop(id(x), None)
            x.prods = None
            for ref, key in self._as_operand.pop(id(x), ()):
                h = ref()
                if h is not None and h.prods is not None:
                    hit = h.prods.get(key)
                    if hit is not None and hit[0] is x:
                        del h.prods[key]
        if t is not None:
            a.t = None
            if t.t is a:
                t.t = None

    def _remember(self, memo: dict, a: F64, key: Any, b: F64, out: F64) -> None:
        """memo[key] = (b, out) in a's memo, noted under b (see :meth:`forget`)."""
        memo[key] = (b, out)
        notes = self._as_operand.get(id(b))
        if notes is None:
            notes = self._as_operand[id(b)] = []
        notes.append((weakref.ref(a), key))

    def accepts(self, x):
        return type(x) is ErrNum and isinstance(x.v, float)

    def from_array(self, a):
        """Native storage of exact float64 inputs (a block of parameters): no error, scale |v|."""
        out = _out_like(a, np.dtype(np.float64)) if isinstance(a, np.ndarray) else None
        if out is None:
            v = np.array(a, dtype=float)
        else:
            v = out                     # np.array's copy (and conversion), into a pooled array of its layout
            np.copyto(v, a, casting="unsafe")
        return F64(v, 0.0, np.abs(v, out=_out_like(v)))

    def from_consts(self, a):
        # max(0, max |a|) without the array of |a| (its negation of a.min() wraps as abs does)
        if a.dtype.kind in "if":
            top = max(0, a.max(initial=0), -a.min(initial=0))
        else:
            top = np.max(np.abs(a), initial=0)
        if top >= 2**53:
            return Backend.from_consts(self, a)
        out = self.from_array(a)
        if a.ndim == 2 and a.size and top <= 1:
            nz = a != 0
            if np.all(np.count_nonzero(nz, axis=0) <= 1):
                rows = np.argmax(nz, axis=0)
                out.sel = (rows, out.v[rows, np.arange(a.shape[1])].copy())
        return out

    def from_obj(self, a):
        m, k = a.shape
        v, e, s = np.empty((m, k)), np.empty((m, k)), np.empty((m, k))
        for idx, x in np.ndenumerate(a):
            if type(x) is not ErrNum:
                x = self.field.const(x)
            v[idx], e[idx], s[idx] = float(x.v), float(x.e), float(x.m)
        return F64(v, _fro(e), s)

    def to_obj(self, s):
        out = np.empty(s.v.shape, dtype=object)
        u, e = self.field.u, float(s.e)
        for idx in np.ndindex(s.v.shape):
            out[idx] = ErrNum(float(s.v[idx]), e, float(s.m[idx]), u)
        return out

    def shape(self, s):
        return s._v.shape if s.lazy is None else s.defer[1]

    def zeros(self, m, k):
        z = np.zeros((m, k))                 # values and scales: one array (never written into)
        out = F64(z, 0.0, z, 0.0)
        out.sel = (np.zeros(k, dtype=np.intp), np.zeros(k))
        return out

    def identity(self, m):
        i = _eye(m)                          # values and scales: one array (never written into)
        out = F64(i, 0.0, i)
        out.diag = (np.ones(m), np.ones(m))
        out.sel = (np.arange(m), np.ones(m))
        return out

    def sparse(self, m, k, entries):
        if not all(type(x) is ErrNum for x in entries.values()):
            return Backend.sparse(self, m, k, entries)
        v, s, e = np.zeros((m, k)), np.zeros((m, k)), 0.0
        for idx, x in entries.items():
            v[idx], s[idx] = float(x.v), float(x.m)
            e += float(x.e)
        return F64(v, _up(e, len(entries)), s)

    def diag(self, xs):
        if not all(type(x) is ErrNum for x in xs):
            return Backend.diag(self, xs)
        dv = np.array([float(x.v) for x in xs])
        dm = np.array([float(x.m) for x in xs])
        return self._diagonal(dv, dm, _fro(np.array([float(x.e) for x in xs])), None)

    def diag_from_raw(self, field: Any, vals: np.ndarray) -> F64 | None:
        """:meth:`diag` of ``field.params_from_raw(vals)`` (parameters drawn at once) from the array
        itself: values vals, scales |vals|, bound 0 (an exact parameter's), as :meth:`diag` reads
        them from those numbers; None unless they are the float64 field's own parameters."""
        if (type(field).param_from_raw is not FloatField.param_from_raw or field.dps is not None
                or vals.ndim != 1 or vals.dtype != np.float64):
            return None
        dv = vals.copy()
        return self._diagonal(dv, np.abs(dv), _fro(np.zeros(len(dv))), None)

    def _diagonal(self, dv: np.ndarray, dm: np.ndarray, e: float, nv: float | None) -> F64:
        """The diagonal matrix of dv (term scales dm, bound e), whose full arrays are made only when
        read: products with it scale rows or columns, a scalar multiple stays diagonal."""
        k = len(dv)
        if nv is None:
            nv = _fro(dv)                  # ‖diag(dv)‖_F = ‖dv‖_2
        out = F64.deferred(lambda: F64(np.diag(dv), e, np.diag(dm), nv), ("diag", (k, k)), e, nv)
        out.diag = (dv, dm)
        return out

    def _memo(self, a: F64) -> dict:
        """a's remembered results (products, sums, scalar multiples), as :meth:`release` forgets them."""
        prods = a.prods
        if prods is None:
            prods = a.prods = {}
            self._holders[id(a)] = weakref.ref(a)
        return prods

    def _with_diagonal(self, a, b, sign: float) -> F64:
        """a + sign·b where a or b is diagonal by construction (its full arrays made or not, see
        :meth:`_diagonal`): the other operand's arrays with the diagonal changed, the same values
        and scales as the full sum (x ± 0 = x exactly) under the same bound."""
        k = self.shape(a)[0]
        i = np.arange(k)
        with _quiet():
            if a.diag is not None and b.diag is not None and a.lazy is not None and b.lazy is not None:
                (av, am), (bv, bm) = a.diag, b.diag
                v = av + bv if sign > 0 else av - bv
                nv = _fro(v)
                return self._diagonal(v, am + bm, _up(a.e + b.e + U64 * nv + _uf((k, k)), 3), nv)
            if b.diag is not None:
                dv, dm = b.diag
                full = a
                v = _copy(a.v)
                v[i, i] = a.v[i, i] + dv if sign > 0 else a.v[i, i] - dv
            else:
                dv, dm = a.diag
                full = b
                v = _copy(b.v) if sign > 0 else np.negative(b.v, out=_out_like(b.v))
                v[i, i] = dv + b.v[i, i] if sign > 0 else dv - b.v[i, i]
            nv = _fro(v)
            e = _up(a.e + b.e + U64 * nv + _uf(v.shape), 3)
            dtop = float(dm.max()) if k else 0.0
            sf = _s32(full, _S32_MAX) if 0.0 <= dtop < _S32_MAX else None
            if sf is not None:
                # in float32 (a float64 operand's scales converted once, see _s32): dm rounded down,
                # the sum rounded once on the diagonal, the rest copied
                f32, ff, ft = sf
                m32 = _copy(f32)
                m32[i, i] = f32[i, i] + _down32(dm)
                return _f32(v, e, m32, min(ff, 1.0) * _R32, (ft + dtop) * (1.0 + 2.0**-22), nv)
            m = _copy(full.m)
            m[i, i] = full.m[i, i] + dm
            return F64(v, e, m, nv)

    def add(self, a, b):
        # a sum met again (the value part of a dual evaluation repeats the plain one) is the stored one
        memo = self._memo(a)
        hit = memo.get(("+", id(b)))
        if hit is not None:
            return hit[1]
        if _exact_zero(b):
            out = a                            # x + 0 = x exactly, under x's bound
        elif _exact_zero(a):
            out = b
        elif a.diag is not None or b.diag is not None:
            out = self._with_diagonal(a, b, 1.0)
        else:
            out = self._transposed_sum(a, b, "+")
        if out is not None:
            self._remember(memo, a, ("+", id(b)), b, out)
            return out
        with _quiet():
            v = _binop(np.add, a.v, b.v)
            nv = _fro(v)
            out = _with_scales(v, _up(a.e + b.e + U64 * nv + _uf(v.shape), 3), _scales_sum(a, b), nv)
        self._remember(memo, a, ("+", id(b)), b, out)
        return out

    def sub(self, a, b):
        memo = self._memo(a)
        hit = memo.get(("-", id(b)))
        if hit is not None:
            return hit[1]
        if _exact_zero(b):
            out = a                            # x - 0 = x exactly, under x's bound
        elif _exact_zero(a):
            out = self.neg(b)
        elif a.diag is not None or b.diag is not None:
            out = self._with_diagonal(a, b, -1.0)
        else:
            out = self._transposed_sum(a, b, "-")
        if out is not None:
            self._remember(memo, a, ("-", id(b)), b, out)
            return out
        with _quiet():
            v = _binop(np.subtract, a.v, b.v)
            nv = _fro(v)
            out = _with_scales(v, _up(a.e + b.e + U64 * nv + _uf(v.shape), 3), _scales_sum(a, b), nv)
        self._remember(memo, a, ("-", id(b)), b, out)
        return out

    def _transposed_sum(self, a, b, op: str) -> F64 | None:
        """a ± b as the transpose of aᵀ ± bᵀ (or of bᵀ + aᵀ) when that was computed (the derivative
        of X Pᵀ along a flow is that of P Xᵀ transposed): entry for entry the same rounding, and the
        same bound and scales, which depend only on the operands' bounds and scales and on the norm
        of the result, all kept by a transpose; None when it was not."""
        at, bt = a.t, b.t
        if at is None or bt is None:
            return None
        hit = at.prods.get((op, id(bt))) if at.prods is not None else None
        if hit is None and op == "+" and bt.prods is not None:
            hit = bt.prods.get(("+", id(at)))         # floating-point addition commutes
        return None if hit is None else self.T(hit[1])

    def neg(self, a):
        return _like(np.negative(a.v, out=_out_like(a.v)), a.e, a, a.nv)

    def matmul(self, a, b):
        (ma, k), (_kb, nb) = self.shape(a), self.shape(b)
        if k == 0:
            return self.zeros(ma, nb)
        prods = self._memo(a)
        hit = prods.get(id(b))
        if hit is not None:
            return hit[1]
        at, bt = a.t, b.t
        if at is not None and bt is not None and bt.prods is not None:
            hit = bt.prods.get(id(at))
            if hit is not None:                      # a b = (bᵀ aᵀ)ᵀ, computed already
                out = self.T(hit[1])
                self._remember(prods, a, id(b), b, out)
                return out
        out = None
        if a.lazy is not None:
            out = self._through(a, b)
        elif b.lazy is None and (a.fac is not None or (at is not None and at.fac is not None)):
            out = self._reassociated(a, b)
        elif b.lazy is not None and b.defer[0] == "inv":
            # a A⁻¹: deferred, so that (a A⁻¹) J with J a selection of columns is a (A⁻¹ J)
            out = F64.deferred(lambda: self._product(a, b), ("prod", (ma, nb), a, b))
        if out is None:
            out = self._product(a, b)
        self._remember(prods, a, id(b), b, out)
        return out

    def _known(self, a, b):
        """The product a b if it is remembered (or its transpose is), else None."""
        hit = a.prods.get(id(b)) if a.prods is not None else None
        if hit is None and a.t is not None and b.t is not None and b.t.prods is not None:
            hit = b.t.prods.get(id(a.t))
        return hit

    def _reassociated(self, a, b):
        """(c d) b as c (d b) when a = c d was computed as a product (or is the transpose of one)
        with an inner dimension k below a's columns n and that costs no more multiplications:
        k n p (none if d b is remembered) + m k p <= m n p, for a (m x n) and b (n x p).  The
        chains of a flow, (X Pᵀ) X, (P Xᵀ) P, (X Pᵀ) P, then share Pᵀ X and take thin products.
        The values are those of the product c (d b) (its own bound); the term scales |c|(|d||b|)
        are the exact (|c||d|)|b|, in float32 as any product's.  None where it does not apply."""
        fac = a.fac
        if fac is None:
            c0, d0 = a.t.fac                         # a = (c0 d0)ᵀ = d0ᵀ c0ᵀ
            fac = (self.T(d0), self.T(c0))
        c, d = fac
        (m, n), (_n, p) = self.shape(a), self.shape(b)
        k = self.shape(c)[1]
        if not k < n:
            return None
        first = 0 if self._known(d, b) is not None else k * n * p
        if first + m * k * p > m * n * p:
            return None
        return self.matmul(c, self.matmul(d, b))

    def _through(self, a, b):
        """A product with a deferred left factor computed without computing that factor: A⁻¹ b as a
        solve when b has fewer columns than A (one LU factorization and the triangular solves for
        those columns instead of the inverse and a product), (c A⁻¹) J as c (A⁻¹ J) when J selects
        columns (:meth:`_cayley` when c + A = 2I); None where neither applies (a is then computed
        when its values are read)."""
        kind, shape = a.defer[0], a.defer[1]
        if kind == "inv" and self.shape(b)[1] < shape[0]:
            _kind, _shape, src, beta0, beta = a.defer
            return self._solve(src, beta0, beta, b.v, b.e, _norm(b), b.sel if b.lazy is None else None)
        if kind == "prod" and b.lazy is None and b.sel is not None:
            _kind, _shape, c, d = a.defer
            src = d.defer[2] if CAYLEY_BY_SOLVE and d.lazy is not None and d.defer[0] == "inv" else None
            y = self.matmul(d, b)             # a solve, or the inverse (computed) times b
            if src is not None:
                out = self._cayley(c, src, y, b)
                if out is not None:
                    return out
            return self.matmul(c, y)
        return None

    def _cayley(self, c, src, y, j):
        """c A⁻¹ J for c + A = 2I exactly (the Cayley chart's (I − S)(I + S)⁻¹ J), given Y ≈ A⁻¹J
        (a solve, or the inverse times J, with its bound): since c A⁻¹ = 2A⁻¹ − I, the values are
        2Y − J (2Y is exact, the difference rounded once per entry), without the product c Y; None
        when the values of c and A are not so related or Y is not finite.

        Bound: for the exact C, Â, Ĵ within the bounds of c, A, J, C = 2I − Â + Δ with
        ‖Δ‖_F <= e_c + e_A, so C Â⁻¹ Ĵ = 2Y* − Ĵ + Δ Y* (Y* = Â⁻¹Ĵ, within e_Y of Y) and
        ‖C Â⁻¹ Ĵ − (2Y − J)‖_F <= 2 e_Y + e_J + (e_c + e_A)(‖Y‖_F + e_Y) + u ‖2Y − J‖_F.  The term
        scales are those of the product c Y, |c|_m |Y|_m, as the product would have them."""
        if c.lazy is not None or src.lazy is not None or c.v.shape != src.v.shape:
            return None
        k = c.v.shape[0]
        with _quiet():
            h = _binop(np.add, c.v, src.v)   # 0 exactly where c_ij = −A_ij exactly
            dc, ds = np.diagonal(c.v), np.diagonal(src.v)
            if not ((dc == 1.0).all() and (ds == 1.0).all()):
                return None
            np.fill_diagonal(h, 0.0)
            if h.any():
                return None
            rows, signs = j.sel
            w = np.multiply(2.0, y.v, out=_out_like(y.v))
            cols = np.arange(w.shape[1])
            w[rows, cols] -= signs
            nw = _fro(w)
            if not math.isfinite(nw):
                return None
            ny = _norm(y)
            e = 2.0 * y.e + j.e + (c.e + src.e) * (ny + y.e) + U64 * nw + _uf(w.shape)
            return _with_scales(w, _up(e, 8), _scale_product(c, y), nw)

    def _product(self, a, b):
        """The product of two matrices (values read, except a diagonal's), with the dot-product bound."""
        k = self.shape(a)[1]
        with _quiet():
            sc = None
            if a.diag is not None:
                dv, dm = a.diag
                v = np.multiply(dv[:, None], b.v, out=_buf(b.v.shape) if b.v.flags.c_contiguous else None)
                sc = self._scaled(b, dm, 0)
            elif b.diag is not None:
                dv, dm = b.diag
                v = np.multiply(a.v, dv, out=_buf(a.v.shape) if a.v.flags.c_contiguous else None)
                sc = self._scaled(a, dm, 1)
            elif b.sel is not None:
                rows, signs = b.sel
                v = a.v[:, rows] * signs
                sc = self._scaled(a, np.abs(signs), 1, rows)
            else:
                v = _matmul(a.v, b.v)
                back = b.prods.get(id(a)) if b.prods is not None else None
                if back is not None and back[1].lazy is None and _msym(a) and _msym(b):
                    # |A|_m |B|_m = (|B|_m |A|_m)ᵀ for symmetric scales (the two products of a
                    # commutator): the scales of b a, whose rounding bound does not depend on the
                    # order of the sums, transposed
                    sc = _scales_of(back[1], transpose=True)
                else:
                    sc = _scale_product(a, b)
            na, nb = _norm(a), _norm(b)
            e = na * b.e + a.e * nb + a.e * b.e + _gamma(k) * na * nb + k * _uf(v.shape)
            out = _with_scales(v, _up(e, 8), sc)
            if a.diag is None and b.diag is None and b.sel is None:
                out.fac = (a, b)
            return out

    @staticmethod
    def _scaled(a, d: np.ndarray, axis: int, rows: np.ndarray | None = None) -> tuple:
        """The term scales of diag(d)·a (axis 0) or a·diag(d) (axis 1; a's columns ``rows`` first,
        when given): in float32 when a keeps its scales there (d rounded down to float32, the
        product rounded once, inside the factor 1 − 2⁻²²), in float64 otherwise."""
        with _quiet():
            dtop = float(d.max()) if d.size else 0.0
        if a.lazy is None and a._m is None and 0.0 <= dtop < 2.0**60:
            sa = _s32(a, 2.0**60)
            if sa is not None:
                a32, fa, ta = sa
                d32 = _down32(d)
                if rows is not None:
                    a32 = a32[:, rows]
                out = _buf(a32.shape, np.float32) if a32.flags.c_contiguous else None
                m32 = np.multiply(d32[:, None], a32, out=out) if axis == 0 else np.multiply(a32, d32, out=out)
                return None, m32, fa * _R32, ta * dtop * (1.0 + 2.0**-22), None
        m = a.m if rows is None else a.m[:, rows]
        return (d[:, None] * m if axis == 0 else m * d), None, None, None, None

    def smul(self, a, c):
        cv, ce, cm = float(c.v), float(c.e), float(c.m)
        memo = self._memo(a)
        key = ("*", cv, math.copysign(1.0, cv), ce, cm)     # the same scalar (value, bound, scale) again
        hit = memo.get(key)
        if hit is not None:
            return hit[1]
        if _exact_zero(a) and math.isfinite(cv) and math.isfinite(ce) and math.isfinite(cm):
            memo[key] = (None, a)             # 0 times a finite scalar: the same 0 exactly (values,
            return a                          # scales and bound all 0), no new arrays
        if a.diag is not None and math.isfinite(cv) and math.isfinite(ce) and math.isfinite(cm):
            # a diagonal times a finite scalar: the zeros stay zeros (exactly), the diagonal is
            # scaled with the bound the full matrix would get (its norm is the diagonal's)
            dv, dm = a.diag
            with _quiet():
                v = dv * cv
                nv = _fro(v)
                e = _norm(a) * ce + a.e * abs(cv) + a.e * ce + U64 * nv + _uf((len(dv), len(dv)))
                out = self._diagonal(v, dm * cm, _up(e, 6), nv)
            memo[key] = (None, out)
            return out
        with _quiet():
            v = np.multiply(a.v, cv, out=_out_like(a.v))
            nv = _fro(v)
            e = _norm(a) * ce + a.e * abs(cv) + a.e * ce + U64 * nv + _uf(v.shape)
            sa = None
            if a._m is None and 0.0 <= cm < 2.0**60:
                sa = _s32(a, 2.0**60)
            if sa is not None:
                # in float32: cm rounded down to float32, the product rounded once
                a32, fa, ta = sa
                c32 = np.nextafter(np.float32(cm), np.float32(0.0))
                out = _f32(v, _up(e, 6), np.multiply(a32, c32, out=_out_like(a32)), fa * _R32, ta * cm * (1.0 + 2.0**-22), nv)
            else:
                out = F64(v, _up(e, 6), a.m * cm, nv)
        memo[key] = (None, out)
        return out

    def T(self, a):
        t = a.t
        if t is None:
            t = a.t = _like(a.v.T, a.e, a, a.nv, transpose=True)
            t.t = a
            self._holders[id(a)] = weakref.ref(a)
            self._holders[id(t)] = weakref.ref(t)
            if a.diag is not None:
                t.diag = a.diag
        return t

    def trace(self, a):
        d = np.diag(a.v)
        k = len(d)
        with _quiet():
            v = float(np.sum(d))
            e = math.sqrt(k) * a.e + _gamma(k) * float(np.sum(np.abs(d))) + k * FLOAT_UNDERFLOW
            e = e * (1.0 + _gamma(2 * k + 8))
            m = float(np.sum(np.diag(a.m)))
        return ErrNum(v, e, m, self.field.u)

    def inv(self, a):
        """Z ≈ A⁻¹ from LAPACK, then a bound on ‖A⁻¹ − Z‖_F for every A within the error bound:
        with ρ ≥ ‖I − A Z‖_F (the computed residual, its rounding bound and the input's error
        times ‖Z‖_F), ρ < 1 gives ‖A⁻¹ − Z‖_F ≤ ‖Z‖_F ρ / (1 − ρ).

        From :data:`DEFERRED_INVERSE_MIN` rows on, a matrix v whose symmetric part is diagonal
        and positive (vᵀ + v = 2 diag(d) exactly, d > 0: I + S with S skew, the Cayley chart's)
        has σ_min(v) ≥ min d, hence every A within the bound e has ‖A⁻¹‖₂ ≤ 1/(min d − e): its
        inverse exists, and is deferred (see :class:`F64`), computed only if read; a product
        with it is a solve (:meth:`_solve`)."""
        m = a.v.shape[0]
        if not np.isfinite(a.v).all() or not math.isfinite(a.e):
            return F64(np.zeros((m, m)), math.inf, np.full((m, m), math.inf))
        if m >= DEFERRED_INVERSE_MIN:
            beta = _skew_plus_diagonal(a)
            if beta is not None:
                beta0, beta1 = beta
                out = F64.deferred(lambda: self._solve(a, beta0, beta1, np.eye(m), 0.0, _up(math.sqrt(m), 1)),
                                   ("inv", (m, m), a, beta0, beta1))
                return out
        try:
            Z = np.linalg.inv(a.v)
        except np.linalg.LinAlgError as exc:
            raise DegenerateError("singular matrix") from exc
        with _quiet():
            if not np.all(np.isfinite(Z)):
                raise DegenerateError("a matrix indistinguishable from a singular one")
            zf = _fro(Z)
            R = np.eye(m) - a.v @ Z
            rho = _up(_fro(R) + _gamma(m + 1) * (_norm(a) * zf + math.sqrt(m)) + a.e * zf + (m + 1) * _uf((m, m)), 8)
            if not rho < 1.0:
                raise DegenerateError("a matrix too close to singular for a float64 inverse bound")
            bound = zf * rho / (1.0 - rho) * (1.0 + 8 * U64)
            return F64(Z, bound, np.abs(Z) + bound, zf)

    def _solve(self, a, beta0: float, beta: float, bv: np.ndarray, eb: float, nb: float,
               sel: tuple | None = None) -> F64:
        """Y ≈ A⁻¹ B from LAPACK's solve (by blocks when B = [D; 0], see :func:`_solve_top`; the
        bound below holds however Y was found), for A = a known to satisfy ‖a.v⁻¹‖₂ ≤ beta0 and ‖A⁻¹‖₂ ≤
        beta for every A within a's bound (see :meth:`inv`), B the values bv within eb (‖bv‖_F ≤
        nb).  The residual R = bv − a.v Y, computed, is within γ_{k+1}(‖bv‖_F + ‖a.v‖_F ‖Y‖_F) of
        the exact one, so ‖a.v⁻¹ bv − Y‖_F ≤ beta0 (‖R‖_F + that) =: δ; and for the exact A and B,
        A⁻¹B − Y = A⁻¹(B − bv) + A⁻¹(a.v − A) a.v⁻¹ bv + (a.v⁻¹ bv − Y), so
        ‖A⁻¹B − Y‖_F ≤ beta eb + beta e_a (‖Y‖_F + δ) + δ.  Term scales |Y| + bound, as for an
        inverse (a solution entry's scale is its own size)."""
        k = a.v.shape[0]
        shape = bv.shape
        with _quiet():
            Y = _solve_top(a.v, sel) if sel is not None else None
            try:
                if Y is None:
                    Y = np.linalg.solve(a.v, bv)
            except np.linalg.LinAlgError:        # cannot happen for σ_min > 0; no verdict if it does
                return F64(np.zeros(shape), math.inf, np.full(shape, math.inf))
            ny = _fro(Y)                         # inf or nan unless every entry is finite
            if not math.isfinite(ny):
                return F64(Y, math.inf, np.full(shape, math.inf))
            R = _binop(np.subtract, bv, _matmul(a.v, Y))
            r = _fro(R) + _gamma(k + 1) * (nb + _norm(a) * ny) + (k + 1) * _uf(shape)
            delta = _up(beta0 * r, 4)
            e = _up(beta * eb + beta * a.e * (ny + delta) + delta, 8)
            if e < _S32_MAX and ny < _S32_MAX:
                # the scales |Y| + e in float32: |Y| rounded down, e rounded to nearest and the sum
                # once (inside the factor 1 − 2⁻²²); every entry at most ‖Y‖_F + e
                m32 = _down32(np.abs(Y, out=_out_like(Y)))
                m32 += np.float32(e)
                return _f32(Y, e, m32, _R32, (ny + e) * (1.0 + 2.0**-22), ny)
            return F64(Y, e, np.abs(Y) + e, ny)

    def inner(self, a, b):
        """sum_ij a_ij b_ij with the dot-product bound."""
        k = a.v.size
        with _quiet():
            v = float(np.sum(a.v * b.v))
            na, nb = _norm(a), _norm(b)
            e = na * b.e + a.e * nb + a.e * b.e + _gamma(k) * na * nb + k * FLOAT_UNDERFLOW
            e = _up(e, 8)
            m = float(np.sum(a.m * b.m))
        return ErrNum(v, e, m, self.field.u)

    def is_zero(self, a):
        return bool(np.all(np.abs(a.v) <= a.e))

    def block(self, grid):
        cat = lambda attr: np.concatenate([np.concatenate([getattr(b, attr) for b in row], axis=1)
                                           for row in grid], axis=0)
        e = 0.0
        for row in grid:
            for b in row:
                e += b.e
        return F64(cat("v"), _up(e, sum(len(row) for row in grid)), cat("m"))


#: the float method's BLAS setting (threadpoolctl, restored on exit): see :mod:`stiefelsym.backends.blas`
from stiefelsym.backends.blas import one_blas_thread  # noqa: E402,F401


# ----------------------------------------------------------------------------- degree markers
class DegMat:
    """m x k matrix whose every entry is bounded by one degree marker."""

    __slots__ = ("shape", "d")

    def __init__(self, shape: tuple[int, int], d: Deg) -> None:
        self.shape, self.d = shape, d


def _times(d: Deg, k: int) -> Deg:
    """A bound for a sum of k terms each bounded by d."""
    if d.zero or k <= 1:
        return d if k >= 1 else Deg(-1, None, d.f)
    return Deg(d.num, d.den, d.f, d.h + log2_up(k))


def _marker_sum(xs: list[Deg], field) -> Deg:
    """x_1 + x_2 + ... + x_k from the left, as Deg's sum computes it; a run of nonzero markers
    with one denominator (the common case: parameters, integer constants) is summed by the same
    operations without building the intermediate markers."""
    acc = Deg(-1, None, field)
    i, k = 0, len(xs)
    while i < k:
        x = xs[i]
        if acc.zero or x.zero or acc.den != x.den:
            acc = acc + x
            i += 1
            continue
        num, h, den = acc.num, acc.h, acc.den
        while i < k and not xs[i].zero and xs[i].den == den:
            num, h = max(num, xs[i].num), log2_add(h, xs[i].h)
            i += 1
        acc = Deg(num, den, field, h)
    return acc


class DegreeBackend(Backend):
    """Structural degree bounds: one marker per matrix (sums take the larger degree and add the
    heights, products add both, inverses follow Cramer's rule), so a claim's degree bound costs
    O(1) per matrix operation."""

    def __init__(self, field) -> None:
        self.field = field

    def accepts(self, x):
        return type(x) is Deg

    def _lift(self, x):
        return x if type(x) is Deg else self.field.const(x)

    def from_obj(self, a):
        acc = Deg(-1, None, self.field)
        for x in a.flat:
            acc = acc + self._lift(x)
        return DegMat(a.shape, acc)

    def to_obj(self, s):
        return _fill(s.shape[0], s.shape[1], s.d)

    def sparse(self, m, k, entries):
        acc = Deg(-1, None, self.field)
        for x in entries.values():
            acc = acc + self._lift(x)
        return DegMat((m, k), acc)

    def from_array(self, a):
        """A block of parameters: every entry is bounded by one parameter's marker."""
        return DegMat(a.shape, self.field.param("", None))

    def from_consts(self, a):
        """The marker :meth:`from_obj` gives the constants, from the nonzero entries only (a zero
        marker adds nothing), in the same order."""
        flat = a.ravel()
        const, seen = self.field.const, {}
        for x in flat[np.flatnonzero(flat)].tolist():
            if x not in seen:
                seen[x] = const(int(x))
        return DegMat(a.shape, _marker_sum([seen[x] for x in flat[np.flatnonzero(flat)].tolist()], self.field))

    def diag(self, xs):
        """The marker :meth:`from_obj` gives the diagonal matrix (its zeros add nothing)."""
        return DegMat((len(xs), len(xs)), _marker_sum([self._lift(x) for x in xs], self.field))

    def shape(self, s):
        return s.shape

    def zeros(self, m, k):
        return DegMat((m, k), Deg(-1, None, self.field))

    def identity(self, m):
        return DegMat((m, m), self.field.const(1))

    def add(self, a, b):
        return DegMat(a.shape, a.d + b.d)

    sub = add

    def neg(self, a):
        return a

    def matmul(self, a, b):
        return DegMat((a.shape[0], b.shape[1]), _times(a.d * b.d, a.shape[1]))

    def smul(self, a, c):
        return DegMat(a.shape, a.d * self._lift(c))

    def T(self, a):
        return DegMat((a.shape[1], a.shape[0]), a.d)

    def trace(self, a):
        return _times(a.d, a.shape[0])

    def inner(self, a, b):
        return _times(a.d * b.d, a.shape[0] * a.shape[1])

    def inv(self, a):
        """Cramer's rule for a matrix whose entries are all bounded by one marker N/D: every
        cofactor of D·M is bounded by ((m−1) deg N, (m−1)(h + log2 m)) and det(D·M) by
        (m deg N, m (h + log2 m)), so M⁻¹ = D adj(DM)/det(DM)."""
        f = self.field
        m = a.shape[0]
        d = a.d
        if d.zero:
            raise DegenerateError("division by an identically zero expression")
        num, h = max(d.num, 0), d.h + log2_up(m) if m > 1 else d.h
        key = f.new_factor(m * num, m * h)
        den = {key: 1}
        out = Deg((m - 1) * num + f.den_degree(d.den), den, f, (m - 1) * h + f.den_height(d.den))
        return DegMat((m, m), out)

    def is_zero(self, a):
        return a.d.zero

    def block(self, grid):
        acc = Deg(-1, None, self.field)
        for row in grid:
            for b in row:
                acc = acc + b.d
        rows = sum(row[0].shape[0] for row in grid)
        cols = sum(b.shape[1] for b in grid[0])
        return DegMat((rows, cols), acc)


# ----------------------------------------------------------------------------- duals
class DualBackend(Backend):
    """(value, derivative) pairs of matrices over a base backend: a derivative along a
    direction in one pass of native operations."""

    def __init__(self, field, base: Backend) -> None:
        self.field, self.base = field, base

    def accepts(self, x):
        return type(x) is Dual and self.base.accepts(x.a) and self.base.accepts(x.b) or self.base.accepts(x)

    def from_obj(self, a):
        zero = self.field.base.const(0)
        A = np.empty(a.shape, dtype=object)
        B = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            if type(x) is Dual:
                A[idx], B[idx] = x.a, x.b
            else:
                A[idx], B[idx] = x, zero
        return (self.base.from_obj(A), self.base.from_obj(B))

    def to_obj(self, s):
        A, B = self.base.to_obj(s[0]), self.base.to_obj(s[1])
        out = np.empty(A.shape, dtype=object)
        for idx in np.ndindex(A.shape):
            out[idx] = Dual(A[idx], B[idx])
        return out

    def shape(self, s):
        return self.base.shape(s[0])

    def zeros(self, m, k):
        return (self.base.zeros(m, k), self.base.zeros(m, k))

    def identity(self, m):
        return (self.base.identity(m), self.base.zeros(m, m))

    def from_consts(self, a):
        return (self.base.from_consts(a), self.base.zeros(*a.shape))

    def sparse(self, m, k, entries):
        zero = self.field.base.const(0)
        return (self.base.sparse(m, k, {i: (x.a if type(x) is Dual else x) for i, x in entries.items()}),
                self.base.sparse(m, k, {i: (x.b if type(x) is Dual else zero) for i, x in entries.items()}))

    def diag(self, xs):
        if not all(type(x) is Dual for x in xs):
            return Backend.diag(self, xs)
        return (self.base.diag([x.a for x in xs]), self.base.diag([x.b for x in xs]))

    def add(self, a, b):
        return (self.base.add(a[0], b[0]), self.base.add(a[1], b[1]))

    def sub(self, a, b):
        return (self.base.sub(a[0], b[0]), self.base.sub(a[1], b[1]))

    def neg(self, a):
        return (self.base.neg(a[0]), self.base.neg(a[1]))

    def matmul(self, a, b):
        B = self.base
        return (B.matmul(a[0], b[0]), B.add(B.matmul(a[0], b[1]), B.matmul(a[1], b[0])))

    def smul(self, a, c):
        B = self.base
        if type(c) is not Dual:
            return (B.smul(a[0], c), B.smul(a[1], c))
        if self.field.base.is_exact_zero(c.b):       # a constant: (a c)' = a' c, exactly
            return (B.smul(a[0], c.a), B.smul(a[1], c.a))
        return (B.smul(a[0], c.a), B.add(B.smul(a[1], c.a), B.smul(a[0], c.b)))

    def T(self, a):
        return (self.base.T(a[0]), self.base.T(a[1]))

    def trace(self, a):
        return Dual(self.base.trace(a[0]), self.base.trace(a[1]))

    def inner(self, a, b):
        B = self.base
        if not hasattr(B, "inner"):
            T = B.T
            return Dual(B.trace(B.matmul(T(a[0]), b[0])),
                        B.trace(B.matmul(T(a[0]), b[1])) + B.trace(B.matmul(T(a[1]), b[0])))
        return Dual(B.inner(a[0], b[0]), B.inner(a[0], b[1]) + B.inner(a[1], b[0]))

    def inv(self, a):
        B = self.base
        Z = B.inv(a[0])
        return (Z, B.neg(B.matmul(B.matmul(Z, a[1]), Z)))

    def is_zero(self, a):
        return self.base.is_zero(a[0]) and self.base.is_zero(a[1])

    def block(self, grid):
        return (self.base.block([[b[0] for b in row] for row in grid]),
                self.base.block([[b[1] for b in row] for row in grid]))


# ----------------------------------------------------------------------------- dispatch
#: False: every matrix keeps numpy arrays of field elements (the generic path; the tests compare)
ENABLED = True


def backend(field) -> Backend | None:
    """The whole-matrix backend of a field (cached on the field), or None for the generic path."""
    try:
        return field.__dict__["_backend"]
    except KeyError:
        pass
    be = _make(field)
    field.__dict__["_backend"] = be
    return be


#: the field classes _make dispatches on, imported on first use
_KINDS: list = []

#: backends of number systems defined above this module, registered by their modules: field class ->
#: (factory, whether it applies even when the native backends are switched off)
_REGISTERED: dict[type, tuple[Any, bool]] = {}


def register_backend(field_type: type, factory: Any, always: bool = False) -> None:
    """A whole-matrix backend for the fields of ``field_type`` (a module above this one registers its
    own, so that this module imports none of them)."""
    _REGISTERED[field_type] = (factory, always)


def _make(field) -> Backend | None:
    if not _KINDS:
        from stiefelsym.backends.fields import DegreeField, DualField, FloatField, ModularField, RationalField
        _KINDS[:] = [DegreeField, DualField, FloatField, ModularField, RationalField]
    DegreeField, DualField, FloatField, ModularField, RationalField = _KINDS
    t = type(field)
    hit = _REGISTERED.get(t)
    if hit is not None and hit[1]:      # reverse numbers exist only as whole matrices
        return hit[0](field)
    if not ENABLED:
        return None
    if hit is not None:
        return hit[0](field)
    if t is ModularField:
        return ModularBackend(field)
    if t is RationalField:
        return RationalBackend(field)
    if t is FloatField and field.dps is None:
        return Float64Backend(field)
    if t is DegreeField:
        return DegreeBackend(field)
    if t is DualField:
        base = backend(field.base)
        return None if base is None else DualBackend(field, base)
    own = getattr(field, "native_backend", None)    # a field that brings its own backend module
    return own() if own is not None else None
