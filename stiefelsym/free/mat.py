"""The whole-matrix backend of the dimension-free field: one block without per-entry array machinery.

Almost every matrix of a dimension-free claim is one block (X, P, A, Φ, a flow's components).
The matrices of the free scene are plain :class:`~stiefelsym.backends.matrix.Mat`, of the same class as
those of every other scene; their field brings this backend (``FreeField.native_backend``, the
hook of :func:`stiefelsym.backends.native._make`), so ``Mat`` runs its native path: the storage of a 1×1
matrix is its entry itself (a word polynomial, a dual number over them, a scalar), and sums,
products, transposes and scalings of such blocks compute the one entry directly, with the same
arithmetic and the same normalization as the generic path of ``Mat``.  A block matrix (k×k
blocks) is stored as a private numpy array of its entries and takes the generic arithmetic.
Index spaces, shapes and the record of looks at coordinates stay ``Mat``'s.
"""
from __future__ import annotations

from typing import Any, Callable

import numpy as np

from stiefelsym.backends.fields import Dual
from stiefelsym.backends.matrix import Mat
from stiefelsym.backends.native import Backend
from stiefelsym.free.algebra import NCPoly


def _one(x: Any) -> np.ndarray:
    a = np.empty((1, 1), dtype=object)
    a[0, 0] = x
    return a


def _arr(s: Any) -> np.ndarray:
    """A storage as an array (read-only use)."""
    return s if type(s) is np.ndarray else _one(s)


def _out(a: np.ndarray) -> Any:
    """The storage of an array of entries (a 1×1 array is stored as its entry)."""
    return a[0, 0] if a.shape == (1, 1) else a


# The arithmetic of a lazy free field, memoized.  On a lazy field the value of a + b, a − b, a·b, −a
# and c·a for polynomials a, b (immutable) and a coefficient c is a function of the operands alone:
# the polynomial arithmetic of :mod:`.algebra` followed by the collection of coefficients (no rule of
# the scene's rewriting system is applied), both pure.  Every lazy scene builds its expressions from
# the same letter polynomials, so a warm run meets the very operands of the last one: the memo
# returns the very value.  Polynomials are keyed by identity, and an entry holds its operands, so an
# id cannot be reused while its entry lives, and a hit is an operation on the same objects; a
# coefficient is keyed by its type and value.  Only values are stored: an operation that raises (a
# refusal, recorded as it is raised) stores nothing, and one that succeeds has no other effect.
_VALUES: dict = {}
_VALUES_MAX = 4096   # (entries hold polynomials: a bound on memory, not a cache of whole catalogs)
#: 1 while the memo is used; 0 once the engine is sealed for a user's claims file (:func:`_on_seal`):
#: claim code could otherwise write into the memo (this constant is in the seal's fingerprint)
VALUE_MEMO = 1


def forget_values() -> None:
    """Empty the memo (tests that replace engine functions start from an empty one)."""
    _VALUES.clear()


def _on_seal() -> None:
    """Called by :func:`stiefelsym.ir.seal.seal` before the first user claims file runs."""
    global VALUE_MEMO
    VALUE_MEMO = 0
    _VALUES.clear()


def _remember(key: tuple, a: Any, b: Any, value: Any) -> Any:
    if len(_VALUES) >= _VALUES_MAX:
        _VALUES.clear()
    _VALUES[key] = (a, b, value)
    return value


def _memoized(op: str, a: Any, b: Any, compute: Callable[[], Any]) -> Any:
    """compute() of two polynomials, remembered by the operands' identity (each entry keeps its
    operands alive, so their ids are not reused while it stands)."""
    key = (op, id(a), id(b))
    hit = _VALUES.get(key)
    if hit is not None and hit[0] is a and hit[1] is b:
        return hit[2]
    return _remember(key, a, b, compute())


class FreeBackend(Backend):
    """The operations of :class:`Mat` on the storage described above, over a free field (or the
    dual numbers over it): each one computes what the generic path computes."""

    #: :meth:`T` applies ``field.star`` to every entry, as the generic path of ``Mat.T`` does
    stars = True

    def __init__(self, field: Any, values: bool = False) -> None:
        self.field = field
        self._nf = field.normalize
        #: the field is a plain free field (not dual numbers over one): its arithmetic is memoized
        #: while it is lazy (see _VALUES)
        self._values = values and type(self) is FreeBackend

    def _memo(self) -> bool:
        return self._values and VALUE_MEMO == 1 and self.field.lazy is True

    # -- storage ---------------------------------------------------------------
    def from_obj(self, a: np.ndarray) -> Any:
        return a[0, 0] if a.shape == (1, 1) else a.copy()

    def to_obj(self, s: Any) -> np.ndarray:
        return s.copy() if type(s) is np.ndarray else _one(s)

    def shape(self, s: Any) -> tuple[int, int]:
        return s.shape if type(s) is np.ndarray else (1, 1)

    def _norm(self, a: np.ndarray) -> Any:
        nf = self._nf
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = nf(x)
        return _out(out)

    # -- arithmetic --------------------------------------------------------------
    def add(self, a: Any, b: Any) -> Any:
        if type(a) is NCPoly and type(b) is NCPoly:
            if self._memo():
                return _memoized("+", a, b, lambda: self._nf(a.__add__(b)))
            return self._nf(a.__add__(b))   # (what a + b calls)
        if type(a) is not np.ndarray and type(b) is not np.ndarray:
            return self._nf(a + b)
        return self._norm(_arr(a) + _arr(b))

    def sub(self, a: Any, b: Any) -> Any:
        if type(a) is NCPoly and type(b) is NCPoly:
            if self._memo():
                return _memoized("-", a, b, lambda: self._nf(a.__sub__(b)))
            return self._nf(a.__sub__(b))   # (what a - b calls)
        if type(a) is not np.ndarray and type(b) is not np.ndarray:
            return self._nf(a - b)
        return self._norm(_arr(a) - _arr(b))

    def neg(self, a: Any) -> Any:
        if type(a) is NCPoly and self._memo():
            key = ("neg", id(a))
            hit = _VALUES.get(key)
            if hit is not None and hit[0] is a:
                return hit[2]
            return _remember(key, a, None, -a)
        return -a

    def matmul(self, a: Any, b: Any) -> Any:
        if type(a) is NCPoly and type(b) is NCPoly:
            if self._memo():
                return _memoized("*", a, b, lambda: self._nf(a._mul_poly(b)))
            return self._nf(a._mul_poly(b))   # (what a * b calls)
        if type(a) is not np.ndarray and type(b) is not np.ndarray:
            return self._nf(a * b)
        return self._norm(np.dot(_arr(a), _arr(b)))

    def smul(self, a: Any, c: Any) -> Any:
        if type(a) is NCPoly and self._memo():
            key = ("c*", id(a), type(c), c)
            try:
                hit = _VALUES.get(key)
            except TypeError:   # an unhashable scalar: no memo
                return self._nf(a * c)
            if hit is not None and hit[0] is a:
                return hit[2]
            return _remember(key, a, c, self._nf(a * c))
        if type(a) is not np.ndarray:
            return self._nf(a * c)
        nf = self._nf
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = nf(x * c)
        return out

    def accepts(self, x: Any) -> bool:
        return True

    def T(self, a: Any) -> Any:
        star = self.field.star
        if type(a) is not np.ndarray:
            return star(a)
        out = a.T.copy()
        for idx, x in np.ndenumerate(out):
            out[idx] = star(x)
        return out

    def trace(self, a: Any) -> Any:
        a = _arr(a)
        acc = None
        for i in range(a.shape[0]):
            x = self.field.entry_trace(a[i, i])
            acc = x if acc is None else acc + x
        return self._nf(acc)

    def inner(self, a: Any, b: Any) -> Any:
        acc = self.field.const(0)
        for x, y in zip(_arr(a).flat, _arr(b).flat):
            acc = acc + x * y
        return self._nf(acc)

    def inv(self, a: Any) -> Any:
        m = self.shape(a)[0]
        ident = self.to_obj(self.identity(m))
        return self.from_obj(np.array(self.field.solve(_arr(a).tolist(), ident.tolist()), dtype=object))

    def is_zero(self, a: Any) -> bool:
        if type(a) is not np.ndarray:
            return self.field.is_zero(a)
        return all(self.field.is_zero(x) for x in a.flat)


class FreeDualBackend(FreeBackend):
    """The backend of the dual numbers a + bε over a free field: a product of two one-block
    entries skips the products with a vanishing ε-part (the generic path multiplies them out to
    the zero polynomial and adds it, which returns the other summand: the same values)."""

    def __init__(self, field: Any) -> None:
        super().__init__(field)
        self._base_nf = field.base.normalize

    def matmul(self, a: Any, b: Any) -> Any:
        if type(a) is Dual and type(b) is Dual:
            aa, ab, ba, bb = a.a, a.b, b.a, b.b
            if type(aa) is NCPoly and type(ab) is NCPoly and type(ba) is NCPoly and type(bb) is NCPoly:
                nf = self._base_nf
                v = aa * ba
                if bb.terms:
                    d = aa * bb
                    if ab.terms:
                        d = d + ab * ba
                elif ab.terms:
                    d = ab * ba
                else:
                    d = NCPoly._raw({}, v.row, v.col)
                return Dual(nf(v), nf(d))
        return super().matmul(a, b)

    def smul(self, a: Any, c: Any) -> Any:
        if type(a) is Dual and type(c) is not Dual:   # (x + yε)·c = xc + ycε, each normalized
            nf = self._base_nf
            return Dual(nf(a.a * c), nf(a.b * c))
        return super().smul(a, c)

    def add(self, a: Any, b: Any) -> Any:
        if type(a) is Dual and type(b) is Dual:
            nf = self._base_nf
            return Dual(nf(a.a + b.a), nf(a.b + b.b))
        return super().add(a, b)

    def sub(self, a: Any, b: Any) -> Any:
        if type(a) is Dual and type(b) is Dual:
            nf = self._base_nf
            return Dual(nf(a.a - b.a), nf(a.b - b.b))
        return super().sub(a, b)


def one_block(x: Any, field: Any, tags, tracker: Any) -> Mat:
    """The 1×1 matrix of the entry x (engine door, no record)."""
    return Mat._wrap_native(x, field, tags, tracker)


def entry_of(M: Mat) -> Any:
    """The entry of a 1×1 matrix (engine only)."""
    s = M._n
    if s is not None and type(s) is not np.ndarray:
        return s
    return M._view()[0, 0]
