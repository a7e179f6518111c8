"""Matrices over any field of :mod:`stiefelsym.fields`.

A :class:`Mat` is a numpy object array of field elements plus two index
labels (``"n"``, ``"r"``, ``"2r"``, ...).  The labels let the engine know
whether a claim looked at coordinates of R^n, which breaks O(n)-equivariance
and therefore the equivariance reduction of the exact method.
"""
from __future__ import annotations

import re
from fractions import Fraction
from typing import Any, Sequence

import numpy as np

from .fields import Field


class CoordinateTracker:
    """Records whether claim code read individual entries of R^n-indexed matrices."""

    def __init__(self) -> None:
        self.used: list[str] = []

    def touch(self, what: str) -> None:
        if what not in self.used:
            self.used.append(what)


_SCALARS = (int, Fraction)


def indexed_by_Rn(tags) -> bool:
    """Whether index labels such as "n", "2n", "n+r" or "?" (unknown) involve R^n."""
    return any(part == "?" or re.fullmatch(r"\d*n", part) for t in tags for part in t.split("+"))


class Mat:
    """A dense matrix over a field, with index labels."""

    __array_priority__ = 1000
    __slots__ = ("_a", "field", "tags", "tracker")

    def __init__(self, a: np.ndarray, field: Field, tags=("?", "?"), tracker: CoordinateTracker | None = None):
        self._a = a
        self.field = field
        self.tags = tuple(tags)
        self.tracker = tracker

    # -- construction -----------------------------------------------------
    @classmethod
    def from_rows(cls, rows: Sequence[Sequence[Any]], field: Field, tags=("?", "?"), tracker=None) -> "Mat":
        m = len(rows)
        k = len(rows[0]) if m else 0
        a = np.empty((m, k), dtype=object)
        for i in range(m):
            for j in range(k):
                a[i, j] = rows[i][j]
        return cls(a, field, tags, tracker)

    @classmethod
    def zeros(cls, m: int, k: int, field: Field, tags=("?", "?"), tracker=None) -> "Mat":
        a = np.empty((m, k), dtype=object)
        z = field.const(0)
        for i in range(m):
            for j in range(k):
                a[i, j] = z
        return cls(a, field, tags, tracker)

    @classmethod
    def identity(cls, m: int, field: Field, tag="?", tracker=None) -> "Mat":
        M = cls.zeros(m, m, field, (tag, tag), tracker)
        one = field.const(1)
        for i in range(m):
            M._a[i, i] = one
        return M

    def _new(self, a, tags=None) -> "Mat":
        return Mat(a, self.field, self.tags if tags is None else tags, self.tracker)

    def _norm(self, a: np.ndarray) -> np.ndarray:
        f = self.field.normalize
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = f(x)
        return out

    # -- shape ------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, int]:
        return self._a.shape

    @property
    def T(self) -> "Mat":
        star = self.field.star
        a = self._a.T.copy()
        if star is not None:
            for idx, x in np.ndenumerate(a):
                a[idx] = star(x)
        return self._new(a, (self.tags[1], self.tags[0]))

    # -- arithmetic -------------------------------------------------------
    def _check(self, o: "Mat") -> None:
        if self.shape != o.shape:
            raise ValueError(f"shape mismatch {self.shape} vs {o.shape}")

    def __add__(self, o):
        if not isinstance(o, Mat):
            return NotImplemented
        self._check(o)
        return self._new(self._norm(self._a + o._a))

    def __sub__(self, o):
        if not isinstance(o, Mat):
            return NotImplemented
        self._check(o)
        return self._new(self._norm(self._a - o._a))

    def __neg__(self):
        return self._new(-self._a)

    def __matmul__(self, o):
        if not isinstance(o, Mat):
            return NotImplemented
        if self.shape[1] != o.shape[0]:
            raise ValueError(f"cannot multiply {self.shape} by {o.shape}")
        m, k = self.shape[0], o.shape[1]
        if self.shape[1] == 0:
            return Mat.zeros(m, k, self.field, (self.tags[0], o.tags[1]), self.tracker)
        return self._new(self._norm(np.dot(self._a, o._a)), (self.tags[0], o.tags[1]))

    def _scalar(self, c):
        if isinstance(c, Mat):
            return NotImplemented
        if isinstance(c, float):
            raise TypeError("use integers or fractions, not floats, as constants in claims")
        if isinstance(c, Fraction):
            c = self.field.const(c)
        out = np.empty(self._a.shape, dtype=object)
        for idx, x in np.ndenumerate(self._a):
            out[idx] = self.field.normalize(x * c)
        return self._new(out)

    def __mul__(self, c):
        return self._scalar(c)

    def __rmul__(self, c):
        return self._scalar(c)

    def __truediv__(self, c):
        if isinstance(c, int):
            c = self.field.const(Fraction(1, c))
            return self._scalar(c)
        return self._scalar(self.field.const(1) / c)

    # -- linear algebra ---------------------------------------------------
    def trace(self):
        if self.shape[0] != self.shape[1]:
            raise ValueError("trace of a non-square matrix")
        entry_trace = self.field.entry_trace
        acc = self.field.const(0) if entry_trace is None else None
        for i in range(self.shape[0]):
            x = self._a[i, i] if entry_trace is None else entry_trace(self._a[i, i])
            acc = x if acc is None else acc + x
        return self.field.normalize(acc)

    def inv(self) -> "Mat":
        m = self.shape[0]
        I = Mat.identity(m, self.field)
        sol = self.field.solve(self._a.tolist(), I._a.tolist())
        return Mat.from_rows(sol, self.field, (self.tags[1], self.tags[0]), self.tracker)

    def is_zero(self) -> bool:
        return all(self.field.is_zero(x) for x in self._a.flat)

    # -- coordinates (flagged) ---------------------------------------------
    def _touch(self, what: str) -> None:
        if self.tracker is not None and indexed_by_Rn(self.tags):
            self.tracker.touch(what)

    def __getitem__(self, idx):
        """Entries or sub-blocks (reading entries of an R^n-indexed matrix is recorded)."""
        self._touch("matrix entries")
        out = self._a[idx]
        if isinstance(out, np.ndarray):
            if out.ndim == 1:
                out = out.reshape(1, -1) if isinstance(idx, tuple) and isinstance(idx[0], int) else out.reshape(-1, 1)
            return self._new(out.copy(), self.tags)
        return out

    def entries(self) -> list[Any]:
        """All entries, row by row (engine use: residual tests)."""
        return list(self._a.flat)

    def rows(self) -> list[list[Any]]:
        return self._a.tolist()

    def __repr__(self) -> str:
        return f"Mat{self.shape}[{self.tags[0]}x{self.tags[1]}]({self.field.name})"


def block(rows: Sequence[Sequence[Mat]]) -> Mat:
    """Block matrix from a grid of Mats."""
    first = rows[0][0]
    a = np.concatenate([np.concatenate([b._a for b in row], axis=1) for row in rows], axis=0)
    rt = "+".join(row[0].tags[0] for row in rows)
    ct = "+".join(b.tags[1] for b in rows[0])
    return Mat(a, first.field, (rt, ct), first.tracker)


def comm(A: Mat, B: Mat) -> Mat:
    """The commutator [A, B] = AB - BA."""
    return A @ B - B @ A


def scalar_matrix(c, m: int, field: Field, tag="?", tracker=None) -> Mat:
    M = Mat.zeros(m, m, field, (tag, tag), tracker)
    for i in range(m):
        M._a[i, i] = c
    return M


def mat_map(M: Mat, f) -> Mat:
    out = np.empty(M._a.shape, dtype=object)
    for idx, x in np.ndenumerate(M._a):
        out[idx] = f(x)
    return Mat(out, M.field, M.tags, M.tracker)
