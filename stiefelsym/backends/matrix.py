"""Matrices over any field of :mod:`stiefelsym.backends.fields`, typed by index spaces.

A :class:`Mat` is a dense array of field elements together with the spaces of
its rows and columns.  A space is *definite* when it is a direct sum of copies
of ℝⁿ and ℝʳ (tags ``"n"``, ``"r"``, ``"n+n"``, ``"2r"``, ``"n+r"``, ...) and
*opaque* otherwise: ``"?"`` (untyped) or a named coordinate space (``"so"``,
``"n-r"``, ``"cond"``, ...).  The types make two things impossible by design:

* an ill-typed sum or product: ℝⁿ- and ℝʳ-indexed objects are never added,
  multiplied or compared, even when n = r numerically (a :class:`TypeError`
  when the expression is written);
* an unrecorded look at coordinates of ℝⁿ: the entries are private, and the
  only doors to them (indexing, building a matrix from entries, an untyped
  index meeting ℝⁿ, slicing) record the access in the scene's
  :class:`CoordinateTracker`.  A claim that went through such a door loses
  the equivariance reduction unless the catalog states why it still holds.

Engine code reads the private array ``_a``; claim code has no business there.
"""
from __future__ import annotations

import operator
import re
from fractions import Fraction
from functools import lru_cache
from typing import Any, Callable, Sequence

import numpy as np

from stiefelsym._lazy import symengine_opaque
from stiefelsym.backends.fields import LAYERED, Deg, Dual, ErrNum, Field, tower_level
from stiefelsym.backends.native import backend


class CoordinateTracker:
    """Records, append-only, how claim code looked at coordinates of ℝⁿ; knows the sizes n, r."""

    __slots__ = ("_used", "dims", "_sizes", "_refused", "_spaces", "_log")

    def __init__(self, dims: dict[str, int] | None = None) -> None:
        self._used: list[str] = []
        self._refused: list[str] = []
        #: while a node of a graph is evaluated for values shared between graphs (the mutation
        #: analysis), every look at coordinates and every refusal, in order, repeats included: what a
        #: graph that takes the node's value instead of computing it records again (engine only)
        self._log: list[tuple[bool, str]] | None = None
        #: the spaces whose coordinates are recorded: ℝⁿ, and ℝʳ too where the chart's reduction
        #: also uses O(r) (the equivariant chart of the metric realization)
        self._spaces: tuple[str, ...] = ("n",)
        #: numeric sizes of the definite spaces (None for the dimension-free scene)
        self.dims = dict(dims) if dims is not None else None
        self._sizes: dict[str, int | None] = {}

    def size(self, tag: str) -> int | None:
        """The dimension of a space tag at these sizes (None for an indefinite one), memoized."""
        try:
            return self._sizes[tag]
        except KeyError:
            v = self._sizes[tag] = space_size(tag, self.dims)
            return v

    def touch(self, what: str) -> None:
        if self._log is not None:
            self._log.append((True, what))
        if what not in self._used:
            self._used.append(what)

    @property
    def used(self) -> tuple[str, ...]:
        return tuple(self._used)

    @property
    def spaces(self) -> tuple[str, ...]:
        """The spaces whose coordinates are recorded (read-only; see :meth:`watch_r`)."""
        return self._spaces

    def watch_r(self) -> None:
        """Record reads of coordinates of ℝʳ too (a chart that also reduces by O(r); engine only)."""
        self._spaces = ("n", "r")

    def refuse(self, what: str) -> None:
        """Record something the engine refused to claim code (before the refusal is raised):
        the record outlives the exception, whatever the claim does with it."""
        if self._log is not None:
            self._log.append((False, what))
        if what not in self._refused:
            self._refused.append(what)

    @property
    def refused(self) -> tuple[str, ...]:
        return tuple(self._refused)

    def replay(self, log: tuple[tuple[bool, str], ...]) -> None:
        """Record again what a log of :attr:`_log` recorded (looks at coordinates, refusals), in order."""
        for looked, what in log:
            if looked:
                self.touch(what)
            else:
                self.refuse(what)

    def restart(self) -> None:
        """Forget every record (engine only: a chart lent again to the next graph evaluated on it, whose
        matrices of earlier evaluations record into this very object)."""
        self._used.clear()
        self._refused.clear()


class NeedsCoordinates(Exception):
    """The claim needs an object the dimension-free backend cannot provide."""

    def __init__(self, what: str) -> None:
        super().__init__(f"{what} needs coordinates (fixed n, r); use a coordinate backend")
        self.what = what


def _refused(tracker: "CoordinateTracker | None", what: str) -> NeedsCoordinates:
    """The dimension-free scene's refusal of ``what``, recorded in the run's record first (the record
    outlives the exception): ``raise _refused(tracker, what)``."""
    if tracker is not None:
        tracker.refuse(what)
    return NeedsCoordinates(what)


_SCALARS = (int, Fraction)


@lru_cache(maxsize=None)
def _is_rational_type(t: type) -> bool:
    """Whether values of type t are the Python constants of :data:`_SCALARS` (by type: the check
    through the number ABCs costs more than the product it guards)."""
    return issubclass(t, _SCALARS)

UNTYPED = "?"


@lru_cache(maxsize=None)
def definite(tag: str) -> tuple[str, ...] | None:
    """The atoms of a definite space ("n+2r" -> ("n", "r", "r")), or None for an opaque one."""
    atoms: list[str] = []
    for part in str(tag).split("+"):
        m = re.fullmatch(r"(\d*)([nr])", part.strip())
        if m is None:
            return None
        atoms.extend([m.group(2)] * (int(m.group(1)) if m.group(1) else 1))
    return tuple(atoms)


def involves_Rn(tag: str) -> bool:
    """Whether a space is a definite space with a summand ℝⁿ."""
    d = definite(tag)
    return d is not None and "n" in d


def watched(tags, tracker: "CoordinateTracker | None") -> bool:
    """Whether reading coordinates of a matrix with these spaces is recorded: indexed by ℝⁿ, or by
    ℝʳ where the tracker's chart also reduces by O(r)."""
    if tracker is None or tracker.spaces == ("n",):
        return indexed_by_Rn(tags)
    for t in tags:
        d = definite(t)
        if d is not None and any(x in d for x in tracker.spaces):
            return True
    return False


def indexed_by_Rn(tags) -> bool:
    """Whether one of the index spaces has a summand ℝⁿ.

    Untyped ("?") and named coordinate spaces ("so", "cond") are not: a named one never
    meets ℝⁿ (a type error), and an untyped one that meets ℝⁿ is recorded then."""
    return any(involves_Rn(t) for t in tags)


def _space_text(tag: str) -> str:
    d = definite(tag)
    if d is None:
        parts = tag.split("+")
        if len(parts) > 1 and all(p in ("n", "r", "n-r") for p in parts):
            # a block's sum of spaces: R^r + R^(n-r) is not R^n (splitting R^n so is a choice of coordinates)
            return "the sum " + " + ".join("R^" + (p if len(p) == 1 else f"({p})") for p in parts) + \
                " (never R^n: splitting R^n so is a choice of coordinates)"
        return "an untyped index" if tag == UNTYPED else f"the coordinate space {tag!r}"
    return "R^" + "+".join(d) if len(d) > 1 else "R^" + d[0]


def unify(a: str, b: str, what: str, tracker: "CoordinateTracker | None") -> str:
    """The common space of two indices that must agree, or a TypeError.

    Definite spaces must be equal (ℝⁿ is never ℝʳ, whatever the sizes); an untyped
    index takes the other's type, and meeting ℝⁿ that way is a recorded look at
    coordinates; two different named coordinate spaces never agree."""
    if a == b:
        return a
    da, db = definite(a), definite(b)
    if da is not None and db is not None:
        if da == db:
            return a
        raise TypeError(f"{what}: {_space_text(a)} and {_space_text(b)} do not match "
                        "(index types are checked even when the sizes agree)")
    if a == UNTYPED or b == UNTYPED:
        other = b if a == UNTYPED else a
        if tracker is not None and watched((other,), tracker):
            tracker.touch("untyped matrices used as R^n-indexed")
        return other
    raise TypeError(f"{what}: {_space_text(a)} and {_space_text(b)} do not match")


def space_size(tag: str, dims: dict[str, int]) -> int | None:
    d = definite(tag)
    if d is None:
        return None
    return sum(dims[x] for x in d)


_ENGINE_TYPES: set[type] = {ErrNum, Deg}

#: number types of modules above this one whose elements are checked by a rule of their own:
#: type -> check(field, x) (registered by those modules)
_ELEMENT_CHECKS: dict[type, Any] = {}


def engine_number_type(cls: type) -> type:
    """Register an engine number type (error-bounded floats, degree markers, dual numbers, words)."""
    _ENGINE_TYPES.add(cls)
    return cls


@lru_cache(maxsize=None)
def _library_types() -> frozenset:
    """The number types of symengine, python-flint and mpmath (the classes themselves)."""
    import flint
    import mpmath
    import symengine.lib.symengine_wrapper as sw
    out = {t for t in vars(sw).values() if isinstance(t, type)}
    out |= {flint.fmpq, flint.fmpz, flint.nmod, mpmath.mpf}
    return frozenset(out)


def is_scene_number(x: Any) -> bool:
    """Whether x is a number of one of the engine's number systems (exact type; a Python int or
    a claim's own object is not)."""
    t = type(x)
    if t is Dual:
        return is_scene_number(x.a) and (is_scene_number(x.b) or type(x.b) is int and x.b == 0)
    if t in _ENGINE_TYPES:
        return True
    # the libraries' types, without importing a library the value cannot come from
    return t.__module__.startswith(("flint", "symengine", "mpmath")) and t in _library_types()


#: the refusal of a number of a derivative level deeper than the field it is made an entry of
DEEPER_NUMBER = ("a value of a scene inside this scene's function (a derivative's scene, one or more levels deeper) "
                 "cannot be an entry of this scene's matrices: its derivative parts would be read as this scene's; "
                 "build the matrix on that scene (w.mat(...), w.scalar_matrix(...), w.resolvent(...))")


def _deeper(x: Any, field: Field) -> bool:
    """Whether x is a number of a field built over ``field`` (more layers of engine numbers than its own; a dual
    number of plain Python numbers is no layer's)."""
    if type(x) is Dual and type(x.a) in (int, Fraction) and type(x.b) in (int, Fraction):
        return False
    return tower_level(x) > field.level


def check_element(field: Field, x: Any) -> Any:
    """x as an entry of a matrix or a residual over ``field``: integers and fractions become
    constants of the field; anything else must be a number of the engine's or its libraries'
    own types, exactly (an object of a claim's own class that says it equals 0 is refused)."""
    t = type(x)
    if t is int or t is Fraction:
        return field.const(x)
    if t in LAYERED and _deeper(x, field):
        raise TypeError(DEEPER_NUMBER)
    if t is Dual:
        check_element(field, x.a)
        check_element(field, x.b)
        return x
    check = _ELEMENT_CHECKS.get(t)
    if check is not None:
        return check(field, x)
    if t in _ENGINE_TYPES:
        return x
    if t in _library_types():
        return x
    raise TypeError(f"a {t.__name__} is not a number of the scene (use s.q(num, den) for constants)")


def _coordinates(field: Field) -> bool:
    return getattr(field, "coordinates", True)


class Mat:
    """A dense matrix over a field, typed by the spaces of its rows and columns.

    The entries live either in a numpy array of field elements (``_obj``, every field) or in
    the native storage of the field's whole-matrix backend (``_n``, see :mod:`.native`); each
    operation uses the native form when both operands have one, and an entry read or write
    converts."""

    __array_priority__ = 1000
    __slots__ = ("_obj", "_n", "_field", "_tags", "_tracker", "_coords")

    def _symengine_(self) -> Any:
        return symengine_opaque()

    def __init__(self, a: Any, field: Field, tags=(UNTYPED, UNTYPED), tracker: CoordinateTracker | None = None):
        """A matrix from a 2-d array of entries: building an ℝⁿ-indexed matrix entrywise is a
        (recorded) look at coordinates.  Engine code uses :meth:`_wrap`."""
        arr = np.empty(np.shape(a), dtype=object)
        if arr.ndim != 2:
            raise ValueError("a matrix needs a 2-d array of entries")
        for idx in np.ndindex(arr.shape):
            arr[idx] = check_element(field, a[idx])
        self._init(arr, field, tags, tracker, watched(tags, tracker))

    def _init(self, a: np.ndarray | None, field: Field, tags, tracker, coords: bool, native: Any = None) -> None:
        self._obj = a
        self._n = native
        self._field = field
        self._tags = (str(tags[0]), str(tags[1]))
        self._tracker = tracker
        self._coords = coords
        if tracker is not None:
            if coords:
                tracker.touch("matrices built entrywise")
            if tracker.dims is not None:
                shape = self._shape()
                for tag, size in zip(self._tags, shape):
                    want = tracker.size(tag)
                    if want is not None and want != size:
                        raise TypeError(f"a {shape[0]}x{shape[1]} matrix cannot be indexed by "
                                        f"{_space_text(tag)}, of dimension {want}")

    @classmethod
    def _wrap(cls, a: np.ndarray, field: Field, tags=(UNTYPED, UNTYPED), tracker=None, coords: bool = False) -> "Mat":
        """Engine door: wrap an array the engine built (no record, the types are checked)."""
        m = object.__new__(cls)
        m._init(a, field, tags, tracker, coords)
        return m

    @classmethod
    def _wrap_native(cls, s: Any, field: Field, tags=(UNTYPED, UNTYPED), tracker=None, coords: bool = False) -> "Mat":
        """Engine door: wrap a backend's native storage."""
        m = object.__new__(cls)
        m._init(None, field, tags, tracker, coords, native=s)
        return m

    # -- the two representations ---------------------------------------------
    @property
    def _a(self) -> np.ndarray:
        """The entries as a numpy array (engine only).  The caller may write into it, so the
        native form is dropped and rebuilt when next needed."""
        if self._obj is None:
            self._obj = backend(self._field).to_obj(self._n)
        self._n = None
        return self._obj

    @_a.setter
    def _a(self, a: np.ndarray) -> None:
        self._obj, self._n = a, None

    def _view(self) -> np.ndarray:
        """The entries as a numpy array, read-only (engine only: never write into it)."""
        if self._obj is None:
            self._obj = backend(self._field).to_obj(self._n)
        return self._obj

    def _entry_reader(self) -> Callable[[int, int], Any]:
        """(i, j) ↦ the entry, read from the native storage where the backend reads one entry alone
        (the exact backend: no conversion of the whole matrix), else from the generic entries (engine
        only: not recorded as an entry read)."""
        if self._obj is None:
            be = backend(self._field)
            entry = getattr(be, "entry", None)
            if entry is not None and 0 not in self._shape() and entry(self._n, 0, 0) is not NotImplemented:
                nat = self._n
                return lambda i, j: entry(nat, i, j)
        a = self._view()
        return lambda i, j: a[i, j]

    def _nat(self) -> Any:
        """The native storage, or None when the field has no whole-matrix backend."""
        if self._n is None:
            be = backend(self._field)
            if be is None:
                return None
            self._n = be.from_obj(self._obj)
        return self._n

    def _shape(self) -> tuple[int, int]:
        if self._obj is not None:
            return self._obj.shape
        return tuple(backend(self._field).shape(self._n))

    def _native_pair(self, o: "Mat"):
        """The backend and both native storages, when both matrices have one over one field."""
        if o._field is not self._field:
            return None
        be = backend(self._field)
        if be is None:
            return None
        return be, self._nat(), o._nat()

    def _dual(self, dot: "Mat | None", field: Field, tracker) -> "Mat":
        """This matrix plus ε·dot over the dual numbers ``field`` of this matrix's field."""
        be = backend(field)
        if be is not None and (dot is None or dot._field is self._field):
            d = dot._nat() if dot is not None else be.base.zeros(*self._shape())
            return Mat._wrap_native((self._nat(), d), field, self._tags, tracker, self._coords)
        a = np.empty(self._shape(), dtype=object)
        zero = self._field.const(0)
        dv = dot._view() if dot is not None else None
        for idx, x in np.ndenumerate(self._view()):
            a[idx] = Dual(x, dv[idx] if dv is not None else zero)
        return Mat._wrap(a, field, self._tags, tracker, self._coords)

    def _retyped(self, field: Field, tags, tracker) -> "Mat":
        """The same entries as a matrix of ``field`` (the same number system) with other spaces."""
        if self._n is not None:
            return Mat._wrap_native(self._n, field, tags, tracker)
        return Mat._wrap(self._view().copy(), field, tags, tracker)

    def _untyped(self) -> "Mat":
        """The same entries, untyped and unrecorded (engine-internal values, e.g. on a tape)."""
        if self._n is not None or backend(self._field) is not None:
            return Mat._wrap_native(self._nat(), self._field)
        return Mat._wrap(self._view(), self._field)

    @property
    def field(self) -> Field:
        """The number system."""
        return self._field

    @property
    def tags(self) -> tuple[str, str]:
        """The spaces of the rows and the columns."""
        return self._tags

    @property
    def tracker(self) -> CoordinateTracker | None:
        """The record of looks at coordinates."""
        return self._tracker

    # -- construction -----------------------------------------------------
    @classmethod
    def _rows(cls, rows: Sequence[Sequence[Any]], field: Field, tags=(UNTYPED, UNTYPED), tracker=None) -> "Mat":
        """Engine door: a matrix from rows of entries the engine computed."""
        m = len(rows)
        k = len(rows[0]) if m else 0
        a = np.empty((m, k), dtype=object)
        for i in range(m):
            for j in range(k):
                a[i, j] = rows[i][j]
        return cls._wrap(a, field, tags, tracker)

    @classmethod
    def from_rows(cls, rows: Sequence[Sequence[Any]], field: Field, tags=(UNTYPED, UNTYPED), tracker=None) -> "Mat":
        """A matrix from rows of scalars (a recorded look at coordinates when ℝⁿ-indexed)."""
        if any(len(row) != len(rows[0]) for row in rows):
            raise ValueError("the rows of a matrix must have equal lengths")
        M = cls._rows([[check_element(field, x) for x in row] for row in rows], field, tags, tracker)
        M._coords = watched(M._tags, tracker)
        if M._coords and tracker is not None:
            tracker.touch("matrices built entrywise")
        return M

    @classmethod
    def _consts(cls, a: np.ndarray, field: Field, tags=(UNTYPED, UNTYPED), tracker=None) -> "Mat":
        """Engine door: the matrix of integer constants ``a`` (no record)."""
        be = backend(field)
        if be is not None:
            return cls._wrap_native(be.from_consts(a), field, tags, tracker)
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = field.const(int(x))
        return cls._wrap(out, field, tags, tracker)

    @classmethod
    def zeros(cls, m: int, k: int, field: Field, tags=(UNTYPED, UNTYPED), tracker=None) -> "Mat":
        be = backend(field)
        if be is not None:
            return cls._wrap_native(be.zeros(m, k), field, tags, tracker)
        a = np.empty((m, k), dtype=object)
        a.fill(field.const(0))
        return cls._wrap(a, field, tags, tracker)

    @classmethod
    def identity(cls, m: int, field: Field, tag=UNTYPED, tracker=None) -> "Mat":
        be = backend(field)
        if be is not None:
            return cls._wrap_native(be.identity(m), field, (tag, tag), tracker)
        M = cls.zeros(m, m, field, (tag, tag), tracker)
        one = field.const(1)
        a = M._a
        for i in range(m):
            a[i, i] = one
        return M

    def _derived(self, a, s, tags, other: "Mat | None") -> "Mat":
        """The result of an operation on this matrix (and ``other``): its spaces come from the
        operands' (already checked against the sizes, and any look at coordinates recorded when
        they were made), so it is made without checking them again."""
        m = object.__new__(Mat)
        m._obj, m._n, m._field = a, s, self._field
        m._tags = self._tags if tags is None else tags
        t = self._tracker
        m._tracker = t if t is not None or other is None else other._tracker
        m._coords = self._coords or (other is not None and other._coords)
        return m

    def _raised(self, o: "Mat") -> "Mat | None":
        """This matrix as one of o's field, where o's field is built over this one's (dual or reverse
        numbers over it, perhaps several layers: a matrix a function captured from an outer scene, met by
        the numbers of the scene the function is evaluated on, inside a derivative or a bracket taken
        inside another); None otherwise."""
        chain = []
        f = o._field
        while f is not None and f is not self._field:
            chain.append(f)
            f = getattr(f, "base", None)
        if f is None or not chain:
            return None
        a = np.empty(self._shape(), dtype=object)
        for idx, x in np.ndenumerate(self._view()):
            for F in reversed(chain):
                x = F.lift(x)
            a[idx] = x
        m = self._derived(a, None, None, o)
        m._field = o._field
        return m

    def _common(self, o: "Mat") -> "tuple[Mat, Mat]":
        """Both operands over one field where one's field is built over the other's (else as they are)."""
        if o._field is not self._field:
            up = self._raised(o)
            if up is not None:
                return up, o
            down = o._raised(self)
            if down is not None:
                return self, down
        return self, o

    def _new(self, a, tags=None, other: "Mat | None" = None) -> "Mat":
        return self._derived(a, None, tags, other)

    def _new_n(self, s, tags=None, other: "Mat | None" = None) -> "Mat":
        return self._derived(None, s, tags, other)

    def _norm(self, a: np.ndarray) -> np.ndarray:
        f = self._field.normalize
        out = np.empty(a.shape, dtype=object)
        for idx, x in np.ndenumerate(a):
            out[idx] = f(x)
        return out

    def _tracker_of(self, o: "Mat") -> CoordinateTracker | None:
        return self._tracker if self._tracker is not None else o._tracker

    # -- shape ------------------------------------------------------------
    @property
    def shape(self) -> tuple[int, int]:
        """The numbers of rows and columns (sizes: not offered by the dimension-free backend)."""
        if not _coordinates(self._field):
            raise _refused(self._tracker, "the shape of a matrix")
        return self._shape()

    @property
    def T(self) -> "Mat":
        tags = (self._tags[1], self._tags[0])
        star = self._field.star
        if self._n is not None:
            be = backend(self._field)
            # a backend whose transpose applies the field's involution to every entry (what the
            # generic path below does) takes the native path over a field with one as well
            if star is None or getattr(be, "stars", False):
                return self._new_n(be.T(self._n), tags)
        a = self._view().T.copy()
        if star is not None:
            for idx, x in np.ndenumerate(a):
                a[idx] = star(x)
        return self._new(a, tags)

    # -- arithmetic -------------------------------------------------------
    def _sizes_disagree(self, message: str) -> Exception:
        """The error for operands whose sizes do not fit: on the dimension-free scene, where a shape
        counts blocks of sizes n, r (n blocks of one size may equal m of another for some n, r), a
        refusal on record; at fixed sizes a ValueError."""
        if not _coordinates(self._field):
            return _refused(self._tracker, "operands whose sizes fit only for some n, r")
        return ValueError(message)

    def _sum_tags(self, o: "Mat", what: str) -> tuple[str, str]:
        if self._shape() != o._shape():
            raise self._sizes_disagree(f"{what}: shape mismatch {self._shape()} vs {o._shape()}")
        t = self._tracker_of(o)
        return (unify(self._tags[0], o._tags[0], what, t), unify(self._tags[1], o._tags[1], what, t))

    def _native_sum_tags(self, o: "Mat", what: str):
        """Both native storages over one field, their backend and the spaces of their sum (the
        checks of :meth:`_sum_tags`), or None when one operand has no native form."""
        a, b = self._n, o._n
        if a is None or b is None or o._field is not self._field:
            return None
        be = backend(self._field)
        if be.shape(a) != be.shape(b):
            raise self._sizes_disagree(f"{what}: shape mismatch {be.shape(a)} vs {be.shape(b)}")
        (s0, s1), (o0, o1) = self._tags, o._tags
        if s0 != o0 or s1 != o1:
            t = self._tracker_of(o)
            s0, s1 = unify(s0, o0, what, t), unify(s1, o1, what, t)
        return be, a, b, (s0, s1)

    def __add__(self, o):
        if type(o) is Mat:
            fast = self._native_sum_tags(o, "a sum")
            if fast is not None:
                be, a, b, tags = fast
                return self._derived(None, be.add(a, b), tags, o)
        if not isinstance(o, Mat):
            return NotImplemented
        if o._field is not self._field:
            x, y = self._common(o)
            if x is not self or y is not o:
                return x.__add__(y)
        tags = self._sum_tags(o, "a sum")
        nat = self._native_pair(o)
        if nat is not None:
            be, a, b = nat
            return self._new_n(be.add(a, b), tags, o)
        return self._new(self._norm(self._view() + o._view()), tags, o)

    def __sub__(self, o):
        if type(o) is Mat:
            fast = self._native_sum_tags(o, "a difference")
            if fast is not None:
                be, a, b, tags = fast
                return self._derived(None, be.sub(a, b), tags, o)
        if not isinstance(o, Mat):
            return NotImplemented
        if o._field is not self._field:
            x, y = self._common(o)
            if x is not self or y is not o:
                return x.__sub__(y)
        tags = self._sum_tags(o, "a difference")
        nat = self._native_pair(o)
        if nat is not None:
            be, a, b = nat
            return self._new_n(be.sub(a, b), tags, o)
        return self._new(self._norm(self._view() - o._view()), tags, o)

    def __neg__(self):
        if self._n is not None:
            return self._new_n(backend(self._field).neg(self._n))
        return self._new(-self._view())

    def __matmul__(self, o):
        if type(o) is Mat and self._n is not None and o._n is not None and o._field is self._field:
            # both native over one field: the checks below, each done once
            be = backend(self._field)
            a, b = self._n, o._n
            (m, k1), (k2, k) = be.shape(a), be.shape(b)
            if k1 != k2:
                raise self._sizes_disagree(f"cannot multiply {(m, k1)} by {(k2, k)}")
            t1, t2 = self._tags[1], o._tags[0]
            if t1 != t2:
                unify(t1, t2, "a product", self._tracker_of(o))
            return self._derived(None, be.matmul(a, b), (self._tags[0], o._tags[1]), o)
        if not isinstance(o, Mat):
            return NotImplemented
        if o._field is not self._field:
            x, y = self._common(o)
            if x is not self or y is not o:
                return x @ y
        (m, k1), (k2, k) = self._shape(), o._shape()
        if k1 != k2:
            raise self._sizes_disagree(f"cannot multiply {(m, k1)} by {(k2, k)}")
        unify(self._tags[1], o._tags[0], "a product", self._tracker_of(o))
        tags = (self._tags[0], o._tags[1])
        nat = self._native_pair(o)
        if nat is not None:
            be, a, b = nat
            return self._new_n(be.matmul(a, b), tags, o)
        if k1 == 0:
            z = Mat.zeros(m, k, self._field, tags, self._tracker_of(o))
            return self._new(z._obj, tags, o)
        return self._new(self._norm(np.dot(self._view(), o._view())), tags, o)

    def _scalar(self, c):
        t = type(c)
        if _is_rational_type(t):
            c = self._field.const(c)
        elif issubclass(t, Mat):
            return NotImplemented
        elif issubclass(t, float):
            raise TypeError("use integers or fractions, not floats, as constants in claims")
        be = backend(self._field)
        if be is not None and be.accepts(c):
            return self._new_n(be.smul(self._nat(), c))
        out = np.empty(self._shape(), dtype=object)
        for idx, x in np.ndenumerate(self._view()):
            out[idx] = self._field.normalize(x * c)
        return self._new(out)

    def __mul__(self, c):
        return self._scalar(c)

    def __rmul__(self, c):
        return self._scalar(c)

    def __truediv__(self, c):
        if isinstance(c, Mat):
            return NotImplemented
        if isinstance(c, _SCALARS):
            return self._scalar(self._field.const(Fraction(1) / Fraction(c)))
        reciprocal = getattr(self._field, "reciprocal", None)     # (a field with a door for divisors: free)
        return self._scalar(reciprocal(c) if reciprocal is not None else self._field.const(1) / c)

    # -- linear algebra ---------------------------------------------------
    def trace(self):
        """The trace (a number of the scene)."""
        return self._trace()

    def _trace(self):
        m, k = self._shape()
        if m != k:
            raise ValueError("trace of a non-square matrix")
        unify(self._tags[0], self._tags[1], "a trace", self._tracker)
        entry_trace = self._field.entry_trace
        if entry_trace is None and self._n is not None:
            return backend(self._field).trace(self._n)
        a = self._view()
        acc = self._field.const(0) if entry_trace is None else None
        for i in range(m):
            x = a[i, i] if entry_trace is None else entry_trace(a[i, i])
            acc = x if acc is None else acc + x
        return self._field.normalize(acc)

    def _product_cost(self, o: "Mat") -> int:
        """An estimate of the work of self @ o: the backend's (the term products of two polynomial matrices),
        else the product of the three sizes."""
        (m, k), n = self._shape(), o._shape()[1]
        if type(o) is Mat and self._n is not None and o._n is not None and o._field is self._field:
            cost = getattr(backend(self._field), "product_cost", None)
            if cost is not None:
                return cost(self._n, o._n)
        return m * k * n

    def _trace_product(self, o: "Mat") -> Any:
        """tr(self @ o), with the checks and the joins of spaces of the product and of its trace; a
        backend that offers it (``trace_matmul``) computes the product's diagonal only."""
        if type(o) is Mat and self._n is not None and o._n is not None and o._field is self._field \
                and self._field.entry_trace is None:
            be = backend(self._field)
            fused = getattr(be, "trace_matmul", None)
            if fused is not None:
                (m, k1), (k2, k) = be.shape(self._n), be.shape(o._n)
                if k1 != k2:
                    raise self._sizes_disagree(f"cannot multiply {(m, k1)} by {(k2, k)}")
                tracker = self._tracker_of(o)
                if self._tags[1] != o._tags[0]:
                    unify(self._tags[1], o._tags[0], "a product", tracker)
                if m != k:
                    raise ValueError("trace of a non-square matrix")
                unify(self._tags[0], o._tags[1], "a trace", tracker)
                return fused(self._n, o._n)
        return (self @ o)._trace()

    def inv(self) -> "Mat":
        """The inverse."""
        return self._inv()

    def _inv(self) -> "Mat":
        m, k = self._shape()
        if m != k:
            raise ValueError("inverse of a non-square matrix")
        t = unify(self._tags[0], self._tags[1], "an inverse", self._tracker)
        be = backend(self._field)
        if be is not None:
            out = Mat._wrap_native(be.inv(self._nat()), self._field, (t, t), self._tracker)
        else:
            I = Mat.identity(m, self._field)
            sol = self._field.solve(self._view().tolist(), I._obj.tolist())
            out = Mat._rows(sol, self._field, (t, t), self._tracker)
        out._coords = self._coords
        return out

    def _inner(self, o: "Mat"):
        """The Frobenius pairing sum_ij a_ij b_ij = tr(AᵀB) (engine only: shapes are the caller's)."""
        nat = self._native_pair(o)
        if nat is not None and hasattr(nat[0], "inner"):
            be, a, b = nat
            return be.inner(a, b)
        if nat is not None:
            return (self.T @ o)._trace()
        acc = self._field.const(0)
        for x, y in zip(self._view().flat, o._view().flat):
            acc = acc + x * y
        return self._field.normalize(acc)

    def is_zero(self) -> bool:
        """Whether every entry is zero at this point."""
        if self._n is not None:
            return backend(self._field).is_zero(self._n)
        return all(self._field.is_zero(x) for x in self._view().flat)

    # -- the one door to entries (recorded) ----------------------------------
    def __getitem__(self, idx):
        """Entries or sub-blocks.  Reading an ℝⁿ-indexed (or untyped) matrix entrywise is
        recorded; the dimension-free backend has no entries."""
        if not _coordinates(self._field):
            raise _refused(self._tracker, "an entry or a block of a matrix")
        if not isinstance(idx, tuple) or len(idx) != 2:
            raise TypeError("index a matrix with two indices, M[i, j] or M[i0:i1, j0:j1]")
        if self._tracker is not None and watched(self._tags, self._tracker):
            self._tracker.touch("matrix entries")
        if self._obj is None and all(isinstance(i, (int, np.integer, slice)) for i in idx):
            got = self._take_native(idx)
            if got is not NotImplemented:
                return got
        out = self._view()[idx]
        if isinstance(out, np.ndarray):
            if out.ndim == 1:
                out = out.reshape(1, -1) if isinstance(idx[0], (int, np.integer)) else out.reshape(-1, 1)
            return Mat._wrap(out.copy(), self._field, self._block_tags(idx), self._tracker, self._block_coords())
        return out

    def _block_tags(self, idx: tuple) -> tuple:
        """The spaces of a block: a side read whole keeps its space, a part of it is untyped."""
        full = [isinstance(i, slice) and i == slice(None) for i in idx]
        return tuple(t if f else UNTYPED for t, f in zip(self._tags, full))

    def _block_coords(self) -> bool:
        return self._coords or (self._tracker is None and indexed_by_Rn(self._tags))

    def _take_native(self, idx: tuple) -> Any:
        """``self[idx]`` (integers and slices) read from the native storage, without building the
        generic representation of the whole matrix; ``NotImplemented`` where the backend has no
        native form of it.  The same values, shapes and types as the generic path."""
        be = backend(self._field)
        if be is None:
            return NotImplemented
        m, k = self._shape()
        rows, cols = np.arange(m)[idx[0]], np.arange(k)[idx[1]]   # numpy's rules (and IndexError)
        if rows.ndim == 0 and cols.ndim == 0:
            entry = getattr(be, "entry", None)       # a backend outside the Backend class has neither
            return NotImplemented if entry is None else entry(self._n, int(rows), int(cols))
        take = getattr(be, "take", None)
        sub = NotImplemented if take is None else take(self._n, np.atleast_1d(rows), np.atleast_1d(cols))
        if sub is NotImplemented:
            return NotImplemented
        return Mat._wrap_native(sub, self._field, self._block_tags(idx), self._tracker, self._block_coords())

    def __iter__(self):
        raise TypeError("a matrix is not iterable: read entries as M[i, j]")

    def __array__(self, *args, **kwargs):
        raise TypeError("a matrix does not convert to a numpy array: read entries as M[i, j]")

    def __bool__(self):
        raise TypeError("a matrix has no truth value: return it as a residual")

    def __repr__(self) -> str:
        return f"Mat{self._shape()}[{self._tags[0]}x{self._tags[1]}]({self._field.name})"


def _join(tags: Sequence[str]) -> str:
    if any(t == UNTYPED for t in tags):
        return UNTYPED
    return "+".join(tags)


def block(rows: Sequence[Sequence[Mat]]) -> Mat:
    """Block matrix from a grid of Mats; its spaces are the direct sums of the blocks' spaces."""
    rows = [list(row) for row in rows]
    if not rows or not rows[0] or any(len(row) != len(rows[0]) for row in rows):
        raise ValueError("a block matrix needs a rectangular, non-empty grid of blocks")
    if not all(isinstance(b, Mat) for row in rows for b in row):
        raise TypeError("the blocks of a block matrix must be matrices")
    tracker = next((b._tracker for row in rows for b in row if b._tracker is not None), None)
    row_tags = []
    for i, row in enumerate(rows):
        t = row[0]._tags[0]
        for b in row[1:]:
            t = unify(t, b._tags[0], f"block row {i + 1}", tracker)
        row_tags.append(t)
    col_tags = []
    for j in range(len(rows[0])):
        t = rows[0][j]._tags[1]
        for row in rows[1:]:
            t = unify(t, row[j]._tags[1], f"block column {j + 1}", tracker)
        col_tags.append(t)
    coords = any(b._coords for row in rows for b in row)
    field = rows[0][0]._field
    tags = (_join(row_tags), _join(col_tags))
    be = backend(field)
    try:
        if be is not None and all(b._field is field for row in rows for b in row):
            return Mat._wrap_native(be.block([[b._nat() for b in row] for row in rows]), field, tags, tracker, coords)
        a = np.concatenate([np.concatenate([b._view() for b in row], axis=1) for row in rows], axis=0)
    except ValueError as exc:
        raise rows[0][0]._sizes_disagree(f"the blocks do not fit: {exc}") from None
    return Mat._wrap(a, field, tags, tracker, coords)


def comm(A: Mat, B: Mat) -> Mat:
    """The commutator [A, B] = AB - BA."""
    return A @ B - B @ A


def elementary(s: Any, M: Mat, k: int) -> list:
    """[e_0(M), ..., e_k(M)]: the coefficients of the characteristic polynomial of the square matrix M,
    det(wI - M) = sum_j (-1)^j e_j(M) w^(m-j), from its power traces by Newton's identities
    j e_j = sum_{i=1..j} (-1)^(i-1) e_(j-i) tr M^i: no entry is read, so a claim written with them
    runs on every scene, the dimension-free one included (for a k that does not depend on n, r)."""
    try:
        k = operator.index(k)
    except TypeError:
        raise ValueError(f"elementary(s, M, k) needs an integer k >= 0, not {k!r}") from None
    if k < 0:
        raise ValueError(f"elementary(s, M, k) needs an integer k >= 0, not {k}")
    p: list = [None]
    power = None
    for _ in range(k):
        power = M if power is None else power @ M
        p.append(s.tr(power))
    e = [s.q(1)]
    for j in range(1, k + 1):
        acc = s.q(0)
        for i in range(1, j + 1):
            term = e[j - i] * p[i]
            acc = acc + term if i % 2 else acc - term
        e.append(acc * s.q(1, j))
    return e


def det(s: Any, M: Mat) -> Any:
    """det M of a square matrix, as e_m(M) of :func:`elementary` (m its size, so fixed sizes only)."""
    m = M.shape[0]
    return elementary(s, M, m)[m]


def scalar_matrix(c, m: int, field: Field, tag=UNTYPED, tracker=None) -> Mat:
    M = Mat.zeros(m, m, field, (tag, tag), tracker)
    for i in range(m):
        M._a[i, i] = c
    return M


def mat_map(M: Mat, f) -> Mat:
    out = np.empty(M._shape(), dtype=object)
    for idx, x in np.ndenumerate(M._view()):
        out[idx] = f(x)
    return Mat._wrap(out, M._field, M._tags, M._tracker, M._coords)
