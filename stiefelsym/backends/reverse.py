"""Reverse-mode derivatives over whole-matrix operations.

The gradient (∂H/∂X, ∂H/∂P) of a scalar function H of a scene is computed in one evaluation of
H over *reverse numbers* plus one backward sweep, instead of 2nr forward passes.  A reverse
number (:class:`Rev`) or matrix (:class:`RevMat`) is a value of the base field together with
the node of a tape that records how it was computed; the backward sweep applies the adjoint of
each operation (for C = AB: Ā += C̄Bᵀ, B̄ += AᵀC̄; for C = A⁻¹: Ā −= CᵀC̄Cᵀ; for s = tr A:
Ā += s̄I; ...).  Operations without an adjoint here (reading entries of a matrix that depends on
X or P, solving a linear system of such entries) raise :class:`Unsupported`, and the engine
falls back to forward mode, so the reverse path is an optimization that never changes a result:
the tests compare both on every catalog Hamiltonian.
"""
from __future__ import annotations

import heapq
import itertools
from fractions import Fraction
from typing import Any, Callable

import numpy as np

from stiefelsym.backends.fields import LAYERED, Field, _above, tower_level
from stiefelsym.backends.matrix import _ELEMENT_CHECKS, Mat, check_element, scalar_matrix
from stiefelsym.backends.native import backend, register_backend

_ids = itertools.count()


class Unsupported(Exception):
    """An operation reverse mode does not differentiate; the caller uses forward mode."""


class Node:
    """One recorded operation: ``backward(g)`` yields (parent node, adjoint contribution)."""

    __slots__ = ("id", "backward")

    def __init__(self, backward: Callable[[Any], list]) -> None:
        self.id = next(_ids)
        self.backward = backward


class Rev:
    """A scalar of the base field with its tape node (None: a constant)."""

    __slots__ = ("v", "node")

    def _symengine_(self):
        from stiefelsym._lazy import symengine_opaque
        return symengine_opaque()

    def __init__(self, v: Any, node: Node | None = None) -> None:
        self.v, self.node = v, node

    def _of(self, o):
        if type(o) is Rev and (type(o.v) not in LAYERED and type(self.v) not in LAYERED
                               or tower_level(o) == tower_level(self)):
            return o
        if isinstance(o, (int, Fraction)) or not (_is_matrix(o) or _above(o, self)):
            return Rev(o)       # a constant of this field's base (a lower layer's number included)
        return NotImplemented   # a matrix, or a number of a field over this one: the operation is o's

    def __add__(self, o):
        x = self._of(o)
        if x is NotImplemented:
            return _reflected(o, self, "__radd__")
        o = x
        return _scalar_op(self.v + o.v, [(self, lambda g: g), (o, lambda g: g)])

    __radd__ = __add__

    def __neg__(self):
        return _scalar_op(-self.v, [(self, lambda g: -g)])

    def __sub__(self, o):
        x = self._of(o)
        if x is NotImplemented:
            return _reflected(o, self, "__rsub__")
        o = x
        return _scalar_op(self.v - o.v, [(self, lambda g: g), (o, lambda g: -g)])

    def __rsub__(self, o):
        x = self._of(o)
        return _reflected(o, self, "__sub__") if x is NotImplemented else x - self

    def __mul__(self, o):
        x = self._of(o)
        if x is NotImplemented:
            return _reflected(o, self, "__rmul__")
        o = x
        a, b = self.v, o.v
        return _scalar_op(a * b, [(self, lambda g: g * b), (o, lambda g: g * a)])

    __rmul__ = __mul__

    def __truediv__(self, o):
        x = self._of(o)
        if x is NotImplemented:
            return _reflected(o, self, "__rtruediv__")
        o = x
        q = self.v / o.v
        b = o.v
        return _scalar_op(q, [(self, lambda g: g / b), (o, lambda g: -(g * q) / b)])

    def __rtruediv__(self, o):
        x = self._of(o)
        return _reflected(o, self, "__truediv__") if x is NotImplemented else x / self

    def __repr__(self):
        return f"Rev({self.v!r}{'' if self.node is None else ', tracked'})"


def _reflected(o, x: "Rev", name: str):
    """The operation of o, a number of a field over x's (x a constant of its base); NotImplemented for a
    matrix (Python asks the matrix).  A reverse number of a higher layer is asked directly: Python tries no
    reflected operation between two numbers of one class."""
    if type(o) is Rev:
        return getattr(o, name)(x)
    return NotImplemented


def _is_matrix(o) -> bool:
    return getattr(o, "__array_priority__", 0) >= 1000


def _scalar_op(v, parents) -> Rev:
    live = [(p.node, f) for p, f in parents if p.node is not None]
    if not live:
        return Rev(v)
    return Rev(v, Node(lambda g: [(node, f(g)) for node, f in live]))


class RevMat:
    """A matrix of the base field (a :class:`~stiefelsym.backends.matrix.Mat`) with its tape node."""

    __slots__ = ("v", "node")

    def __init__(self, v, node: Node | None = None) -> None:
        self.v, self.node = v, node


def _mat_op(v, parents) -> RevMat:
    live = [(p.node, f) for p, f in parents if p.node is not None]
    if not live:
        return RevMat(v)
    return RevMat(v, Node(lambda g: [(node, f(g)) for node, f in live]))


def linear(a: RevMat, value, adjoint: Callable[[Any], Any]) -> RevMat:
    """A linear map of a matrix on the tape as one node: its value (a base-field Mat) and the
    adjoint map, applied to the adjoint of the result."""
    return _mat_op(value, [(a, adjoint)])


LAYERED[Rev] = "v"


class RevField(Field):
    """Reverse numbers over a base field (used only to take gradients)."""

    def __init__(self, base: Field) -> None:
        self.base = base
        self.name = f"reverse({base.name})"
        self.exact = base.exact

    def const(self, q):
        return Rev(self.base.const(q))

    def lift(self, x):
        if type(x) in LAYERED and tower_level(x) < self.level:
            # a number of a field below this one's: a constant of the tape, its own layers kept (see DualField.lift)
            return Rev(self.base.lift(x) if tower_level(x) < self.level - 1 else x)
        return x if isinstance(x, Rev) else Rev(x)

    def normalize(self, x):
        return x

    def is_zero(self, x):
        x = self.lift(x)
        if x.node is not None:
            raise Unsupported("a zero test of a number that depends on X, P")
        return self.base.is_zero(x.v)

    def solve(self, M, B):
        cells = [x for row in list(M) + list(B) for x in row]
        if any(isinstance(x, Rev) and x.node is not None for x in cells):
            raise Unsupported("a linear solve whose entries depend on X, P")
        val = lambda x: x.v if isinstance(x, Rev) else x
        sol = self.base.solve([[val(x) for x in r] for r in M], [[val(x) for x in r] for r in B])
        return [[Rev(x) for x in row] for row in sol]

    def rank(self, M):
        raise Unsupported("a rank")


class RevBackend:
    """The whole-matrix backend of :class:`RevField`: values are base-field Mats."""

    def __init__(self, field: RevField) -> None:
        self.field = field
        self.base = field.base

    def _mat(self, a: np.ndarray):
        return Mat._wrap(a, self.base)

    def accepts(self, x):
        return isinstance(x, Rev) or type(x) is not Fraction and not isinstance(x, int) and not _is_matrix(x)

    def from_obj(self, a: np.ndarray) -> RevMat:
        """A matrix from entries; the adjoint of a tracked entry is the matching entry of the
        matrix's adjoint."""
        out = np.empty(a.shape, dtype=object)
        tracked = []
        for idx, x in np.ndenumerate(a):
            if isinstance(x, Rev):
                if x.node is not None:
                    tracked.append((idx, x.node))
                x = x.v
            out[idx] = x
        v = self._mat(out)
        if not tracked:
            return RevMat(v)
        return RevMat(v, Node(lambda g: [(node, g._view()[idx]) for idx, node in tracked]))

    def to_obj(self, s: RevMat) -> np.ndarray:
        """The entries; the adjoint of entry (i, j) is the matrix with that entry alone."""
        v = s.v._view()
        out = np.empty(v.shape, dtype=object)
        for idx, x in np.ndenumerate(v):
            if s.node is None:
                out[idx] = Rev(x)
            else:
                out[idx] = Rev(x, Node(lambda g, idx=idx, node=s.node, shape=v.shape:
                                       [(node, _EntryAdjoints(shape, idx, g, self.base))]))
        return out

    def shape(self, s):
        return s.v._shape()

    def zeros(self, m, k):
        return RevMat(Mat.zeros(m, k, self.base))

    def identity(self, m):
        return RevMat(Mat.identity(m, self.base))

    def add(self, a, b):
        return _mat_op(a.v + b.v, [(a, lambda g: g), (b, lambda g: g)])

    def sub(self, a, b):
        return _mat_op(a.v - b.v, [(a, lambda g: g), (b, lambda g: -g)])

    def neg(self, a):
        return _mat_op(-a.v, [(a, lambda g: -g)])

    def matmul(self, a, b):
        A, B = a.v, b.v
        return _mat_op(A @ B, [(a, lambda g: g @ B.T), (b, lambda g: A.T @ g)])

    def smul(self, a, c):
        c = c if isinstance(c, Rev) else Rev(c)
        A, cv = a.v, c.v
        out = _mat_op(A * cv, [(a, lambda g: g * cv)])
        if c.node is None:
            return out
        # d(cA) = c dA + A dc: the adjoint of c is <A, g> = tr(Aᵀ g)
        parents = [(c.node, lambda g: (A.T @ g).trace())]
        if out.node is not None:
            parents.append((out.node, lambda g: g))
        return RevMat(out.v, Node(lambda g: [(node, f(g)) for node, f in parents]))

    def T(self, a):
        return _mat_op(a.v.T, [(a, lambda g: g.T)])

    def trace(self, a):
        m = a.v._shape()[0]
        base = self.base
        return _scalar_op(a.v.trace(), [(a, lambda g: _scaled_identity(base, m, g))])

    def inv(self, a):
        Z = a.v.inv()
        return _mat_op(Z, [(a, lambda g: -(Z.T @ g @ Z.T))])

    def is_zero(self, a):
        if a.node is not None:
            raise Unsupported("a zero test of a matrix that depends on X, P")
        return a.v.is_zero()

    def block(self, grid):
        raise Unsupported("a block matrix")


class _EntryAdjoints:
    """The adjoint of a matrix from reads of some of its entries, {(i, j): adjoint}, plus any
    whole-matrix contributions: summed lazily until the matrix's node is swept (one matrix per
    node, not one per entry read)."""

    __slots__ = ("shape", "entries", "dense", "base")

    def __init__(self, shape, idx, g, base) -> None:
        self.shape, self.entries, self.dense, self.base = shape, {idx: g}, None, base

    def __add__(self, o):
        if isinstance(o, _EntryAdjoints):
            for idx, g in o.entries.items():
                self.entries[idx] = self.entries[idx] + g if idx in self.entries else g
            if o.dense is not None:
                self._add_dense(o.dense)
        else:
            self._add_dense(o)
        return self

    __radd__ = __add__

    def _add_dense(self, M) -> None:
        self.dense = M if self.dense is None else self.dense + M

    def materialize(self):
        be = backend(self.base)
        if be is not None and hasattr(be, "sparse"):     # not for a tape over reverse numbers
            M = Mat._wrap_native(be.sparse(self.shape[0], self.shape[1], self.entries), self.base)
        else:
            M = Mat.zeros(self.shape[0], self.shape[1], self.base)
            a = M._a
            for idx, g in self.entries.items():
                a[idx] = g
        return M if self.dense is None else self.dense + M


def _scaled_identity(base: Field, m: int, g):
    return scalar_matrix(g, m, base)


def leaf(v) -> RevMat:
    """An independent variable: a base-field Mat whose adjoint the sweep returns."""
    return RevMat(v, Node(lambda g: []))


def gradient(root: Any, leaves: list[RevMat], one: Any) -> list:
    """The adjoints d(root)/d(leaf) (None where root does not depend on a leaf); ``one`` is the
    base field's 1.  Nodes are swept in decreasing creation order (a node is created after its
    parents), each once, after every contribution to its adjoint has arrived."""
    if not isinstance(root, Rev):
        raise Unsupported("a value that is not a scalar")
    if root.node is None:
        return [None for _ in leaves]
    heap = [(-root.node.id, root.node)]
    grads: dict[int, Any] = {root.node.id: one}
    done: dict[int, Any] = {}
    while heap:
        _, node = heapq.heappop(heap)
        g = grads.pop(node.id)
        if isinstance(g, _EntryAdjoints):
            g = g.materialize()
        done[node.id] = g
        for parent, contrib in node.backward(g):
            if parent.id in grads:
                grads[parent.id] = grads[parent.id] + contrib
            else:
                grads[parent.id] = contrib
                heapq.heappush(heap, (-parent.id, parent))
    return [done.get(leaf.node.id) for leaf in leaves]


def _check_rev(field: Any, x: "Rev") -> "Rev":
    """A reverse number is an element when its value is one of the base field."""
    check_element(getattr(field, "base", field), x.v)
    return x


_ELEMENT_CHECKS[Rev] = _check_rev
register_backend(RevField, RevBackend, always=True)
