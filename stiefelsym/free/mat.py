"""1×1 block matrices of the dimension-free scene, without per-entry array machinery.

Almost every matrix of a dimension-free claim is one block (X, P, A, Φ, a flow's
components): a :class:`FreeMat` is a :class:`~stiefelsym.matrix.Mat` whose
sums, products, transposes and scalings of two such blocks compute the one
entry directly (the same arithmetic and the same normalization as the generic
path, one entry instead of a loop over an object array).  The index spaces are
unified exactly as :class:`~stiefelsym.matrix.Mat` does, with the same
:class:`TypeError`; anything else (block matrices, another field, a matrix of
another class) takes the generic path of ``Mat``.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any

import numpy as np

from ..matrix import Mat, unify
from .algebra import SYMENGINE_OPAQUE


def _one(x: Any) -> np.ndarray:
    a = np.empty((1, 1), dtype=object)
    a[0, 0] = x
    return a


def _entry(M: Mat) -> Any:
    """The entry of a 1×1 FreeMat held as an object array, or None (then: the generic path)."""
    a = M._obj
    if a is None or a.shape != (1, 1):
        return None
    return a[0, 0]


class FreeMat(Mat):
    """A Mat of the free scene with a fast path for 1×1 operands of one field."""

    __slots__ = ()

    def _symengine_(self) -> Any:
        """What symengine sees: an opaque symengine matrix, so that ``c * M`` with a symengine scalar
        c comes to :meth:`__rmul__` at once (see :data:`~stiefelsym.free.algebra.SYMENGINE_OPAQUE`)."""
        return SYMENGINE_OPAQUE

    def _fast(self, o: Any) -> tuple[Any, Any] | None:
        if type(o) is not FreeMat or o._field is not self._field:
            return None
        x, y = _entry(self), _entry(o)
        if x is None or y is None:
            return None
        return x, y

    def _made(self, x: Any, tags, o: "Mat | None" = None) -> "FreeMat":
        tracker = self._tracker if self._tracker is not None else (o._tracker if o is not None else None)
        coords = self._coords or (o is not None and o._coords)
        return FreeMat._wrap(_one(self._field.normalize(x)), self._field, tags, tracker, coords)

    def __add__(self, o):
        pair = self._fast(o)
        if pair is None:
            return super().__add__(o)
        t = self._tracker_of(o)
        tags = (unify(self._tags[0], o._tags[0], "a sum", t), unify(self._tags[1], o._tags[1], "a sum", t))
        return self._made(pair[0] + pair[1], tags, o)

    def __sub__(self, o):
        pair = self._fast(o)
        if pair is None:
            return super().__sub__(o)
        t = self._tracker_of(o)
        tags = (unify(self._tags[0], o._tags[0], "a difference", t),
                unify(self._tags[1], o._tags[1], "a difference", t))
        return self._made(pair[0] - pair[1], tags, o)

    def __neg__(self):
        x = _entry(self)
        if x is None:
            return super().__neg__()
        return FreeMat._wrap(_one(-x), self._field, self._tags, self._tracker, self._coords)

    def __matmul__(self, o):
        pair = self._fast(o)
        if pair is None:
            return super().__matmul__(o)
        unify(self._tags[1], o._tags[0], "a product", self._tracker_of(o))
        return self._made(pair[0] * pair[1], (self._tags[0], o._tags[1]), o)

    @property
    def T(self) -> Mat:
        x = _entry(self)
        star = self._field.star
        if x is None or star is None:
            return Mat.T.fget(self)
        return FreeMat._wrap(_one(star(x)), self._field, (self._tags[1], self._tags[0]), self._tracker,
                             self._coords)

    def _scalar(self, c):
        x = _entry(self)
        if x is None or isinstance(c, (Mat, float)) or c.__class__ is bool:
            return super()._scalar(c)
        if type(c) is int or type(c) is Fraction:
            c = self._field.const(c)
        return FreeMat._wrap(_one(self._field.normalize(x * c)), self._field, self._tags, self._tracker,
                             self._coords)

    def __mul__(self, c):
        return self._scalar(c)

    def __rmul__(self, c):
        return self._scalar(c)
