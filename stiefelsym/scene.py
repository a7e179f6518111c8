"""Scenes: one problem (n, r, field, parameters), built lazily.

A scene hands claims the paper's objects (X, P, A, Phi, Psi, lambda, kappa,
...) as :class:`~stiefelsym.backends.matrix.Mat` over its field, and the Hamiltonian
machinery on T*V_{n,r}: gradients, the Dirac bracket, Dirac flows and the
Lagrange-multiplier form.  Everything is built on first use and cached.

Charts (how a point of T*V_{n,r} is produced from free parameters):

* ``cayley``: X = first r columns of (I - S)(I + S)^{-1} D with S skew
  (D = diag(-1, 1, ..., 1) on the second component of O(n) when r = n),
  P = X W + (I - X X^T) Z with W skew; A = diag(a_1, ..., a_n).  Every point of a
  dense open subset of T*V_{n,r} arises this way.
* ``equivariant``: X = X0 = (E_1, ..., E_r), P = (W; Z2) with W skew, A a generic
  symmetric matrix.  Valid for residuals built from X, P, A by matrix
  operations only (covariant under (X, P, A) -> (gX, gP, g A g^T), g in O(n)),
  which the scene verifies by recording coordinate access.
"""
from __future__ import annotations

import contextlib
import hashlib
import random
import re
from dataclasses import dataclass, field as dc_field
from fractions import Fraction
from typing import Any, Callable, Iterator, Mapping

import numpy as np

from stiefelsym.backends.fields import LAYERED, DegreeField, Dual, DualField, Field, FloatField, DegenerateError
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import (DEEPER_NUMBER, CoordinateTracker, Mat, _deeper, block, check_element, definite,
                                       scalar_matrix, unify)
from stiefelsym.backends.native import _binop, _buf, backend
from stiefelsym.ir.trace import TraceRefused, generic_kind_problem
from stiefelsym.backends.reverse import Rev, RevField, RevMat, Unsupported, gradient as rev_gradient, leaf as rev_leaf

Scalar = Any
Function = Callable[["Scene"], Any]


#: prefixes of the claim's own parameters: they never coincide with a chart parameter
USER_SCALAR = "scalar:"
USER_GENERIC = "generic:"
USER_PARAMS = "params:"
USER_OPERATOR = "operator:"
#: the prefix of the parameters of a fresh element (s.fresh): numbered by the engine, no claim's name
FRESH = "fresh:"
NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def _fresh_key(scene: Any, args: tuple, spaces: Any) -> str:
    """The name of the parameters of a fresh element: ``fresh:i`` for the number i of a graph's
    ``call fresh (i, m, k)``, ``fresh:direct j`` for the j-th fresh(m, k) of engine code on the scene itself."""
    if len(args) == 3 and type(args[0]) is int and args[0] >= 1 and args[1] in spaces and args[2] in spaces:
        return f"{FRESH}{args[0]}[{args[1]}x{args[2]}]"
    if len(args) == 2 and args[0] in spaces and args[1] in spaces:
        scene._fresh_direct = getattr(scene, "_fresh_direct", 0) + 1
        return f"{FRESH}direct{scene._fresh_direct}[{args[0]}x{args[1]}]"
    raise ValueError(f"fresh{args!r}: (an engine number,) the index spaces 'n' or 'r'")


def user_name(name: Any, what: str) -> str:
    """A name for a claim's own parameters: letters, digits and underscores (so that no name,
    however chosen, spells another object's parameters)."""
    if not isinstance(name, str) or not NAME.fullmatch(name):
        raise ValueError(f"{what}({name!r}): a name is a letter followed by letters, digits or underscores")
    return name


def check_generic_kind(m: Any, k: Any, kind: Any) -> str:
    """What the kind of a generic matrix adds to its key ("" for a general matrix, ":sym", ":skew"), or the
    refusal of the trace (:func:`.ir.trace.generic_kind_problem`) as a ValueError."""
    problem = generic_kind_problem(m, k, kind)
    if problem:
        raise ValueError(problem)
    return "" if kind == "general" else f":{kind}"


#: the name of an entry of a parameter matrix (see :func:`param_name`)
_ENTRY_NAME = re.compile(r"(.*)_\d+,\d+")


def param_name(name: str, i: int, j: int) -> str:
    """The name of entry (i, j) of a parameter matrix: "S_1,12" (one name per entry at every size)."""
    return f"{name}_{i + 1},{j + 1}"


#: False: gradients by 2nr forward passes only (the tests compare both ways)
REVERSE_GRADIENTS = True
#: False: the Dirac multipliers always from the solved r(r+1) system (the tests compare both ways)
CLOSED_FORM_MULTIPLIERS = True
#: parameter matrices with fewer entries are drawn one entry at a time (a numpy generator costs
#: more than a few dozen draws)
PARAM_BLOCK_MIN = 64


def _opaque(scene: Any, x: Any) -> Any:
    """A value of a scene as the engine hands it on (claims only meet traced values)."""
    return x


def _number(scene: Any, x: Any) -> Any:
    """A number of a scene as the engine hands it on."""
    return x


def _engine_property(attr: str, what: str) -> property:
    """A read-only attribute of the engine's."""
    def get(self):
        return getattr(self, attr)
    return property(get, doc=f"{what}: engine only")


class SizeError(ValueError):
    """An inadmissible problem size."""


@dataclass
class Flow:
    """A vector field on T*V (or on a larger phase space): derivatives of primitives."""

    Xdot: Mat
    Pdot: Mat
    extra: dict[str, Mat] = dc_field(default_factory=dict)
    multipliers: dict[str, Mat] = dc_field(default_factory=dict)

    def tangent(self) -> dict[str, Mat]:
        out = {"X": self.Xdot, "P": self.Pdot}
        out.update(self.extra)
        return out

    def __getitem__(self, key: str) -> Mat:
        """flow["X"], flow["P"] (and a larger phase space's "Y", "Q", ...): the components of the
        vector field, as in a tangent vector {"X": ..., "P": ...}; flow["Lambda"], flow["Pi"]: the
        multipliers of the Lagrange form (dot_XP)."""
        tangent = self.tangent()
        if key in tangent:
            return tangent[key]
        if key in self.multipliers:
            return self.multipliers[key]
        keys = ", ".join(map(repr, tangent))
        raise KeyError(f"a flow has no component {key!r}: its components are {keys} (Ẋ = flow['X'] or "
                       f"flow.Xdot, Ṗ = flow['P'] or flow.Pdot), and the multipliers of s.multiplier_flow(H) "
                       f"are flow['Lambda'], flow['Pi']")


@dataclass
class Constraints:
    """A realization of T*V as the zero set of symmetric matrix constraints."""

    name: str
    #: the symmetric r x r matrix constraints; their scalar components are the upper triangles
    build: Callable[["Scene"], list[Mat]]


def standard_constraints(s: "Scene") -> list[Mat]:
    """(cond_XP): X^T X = I_r, X^T P + P^T X = 0."""
    return [s.X.T @ s.X - s.Ir, s.X.T @ s.P + s.P.T @ s.X]


def metric_constraints(s: "Scene") -> list[Mat]:
    """(cond_XP2): X^T X = I_r, X^T A^{-1} P + P^T A^{-1} X = 0."""
    return [s.X.T @ s.X - s.Ir, s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X]


REALIZATIONS = {
    "standard": Constraints("standard", standard_constraints),
    "metric": Constraints("metric", metric_constraints),
}


class HermitianComponents:
    """The independent real components of a realified Hermitian matrix M, on a backend without
    coordinates (the dimension-free scene): not a list of scalars, only the matrix they are the
    components of (an Euler–Lagrange solver in the free algebra reads it as the constraint M = 0)."""

    __slots__ = ("matrix",)

    def __init__(self, matrix: Mat) -> None:
        self.matrix = matrix

    def __repr__(self) -> str:
        return "HermitianComponents(...)"


class PaperObjects:
    """What every backend derives the same way from its primitives X, P and its parameters."""

    def _param(self, name: str) -> Scalar:
        raise NotImplementedError

    def _cached(self, key: str, build: Callable[[], Any]) -> Any:
        raise NotImplementedError

    @property
    def Phi(self) -> Mat:
        """The SO(n) momentum map Phi = P X^T - X P^T."""
        return self._cached("Phi", lambda: self.P @ self.X.T - self.X @ self.P.T)

    @property
    def Psi(self) -> Mat:
        """The SO(r) momentum map Psi = X^T P - P^T X."""
        return self._cached("Psi", lambda: self.X.T @ self.P - self.P.T @ self.X)

    # -- complex matrices, realified ----------------------------------------------
    # A complex matrix U + iV is represented by the real block matrix [[U, -V], [V, U]]:
    # sums, products and the conjugate transpose (which becomes the transpose) are preserved.  On
    # the dimension-free scene the same code keeps a realified matrix as its 2×2 blocks.
    def realify(self, U: Mat, V: Mat) -> Mat:
        """The real 2m x 2k form of the complex matrix U + iV."""
        return block([[U, -V], [V, U]])

    def conj(self, M: Mat) -> Mat:
        """The complex conjugate of a realified matrix (spaces V+V for V = R^n or R^r on each side)."""
        for tag in M.tags:
            atoms = definite(tag)
            if atoms is None or len(atoms) != 2 or atoms[0] != atoms[1]:
                raise TypeError(f"conj acts on realified matrices, indexed by n+n or r+r, not by {tag!r}")
        m, k = M._a.shape[0] // 2, M._a.shape[1] // 2
        a = M._a.copy()
        a[:m, k:] = -a[:m, k:]
        a[m:, :k] = -a[m:, :k]
        return Mat._wrap(a, M._field, M.tags, M.tracker, M._coords)   # J M J, J = diag(I, -I): covariant

    def _lent(self) -> "Scene":
        """A copy of this scene in its present state (engine only: the mutation analysis lends the
        point of a claim as printed to its mutants).  The parameters drawn so far and the objects
        built from them are shared; parameters drawn later come from a copy of the generator, so
        nothing done with the copy changes this scene."""
        s = object.__new__(type(self))
        s.__dict__.update(self.__dict__)
        s._params, s._param_blocks, s._cache = dict(self._params), list(self._param_blocks), dict(self._cache)
        s._options = dict(self._options)
        if self._rng is not None:
            s._rng = random.Random()
            s._rng.setstate(self._rng.getstate())
        t = self._tracker
        s._tracker = CoordinateTracker(t.dims)
        s._tracker._used, s._tracker._refused, s._tracker._spaces = list(t._used), list(t._refused), t._spaces
        s._loaned = True
        return s

    def killing(self, a: Mat, b: Mat) -> Scalar:
        """<a, b> = -1/2 tr(ab)."""
        x = self._field.pairing((a @ b)._trace() * self._field.const(Fraction(-1, 2)))
        return _number(self, x)

    def scalar(self, name: str) -> Scalar:
        """A fresh free scalar parameter of the claim's own (never one of the chart's, whatever its name)."""
        x = self._param(USER_SCALAR + user_name(name, "scalar"))
        return _number(self, x)

    @property
    def lam(self) -> Scalar:
        """The spectral parameter lambda."""
        x = self._param("lambda")
        return _number(self, x)

    @property
    def kappa(self) -> Scalar:
        """The parameter kappa of the Jensen metrics (EM)."""
        x = self._param("kappa")
        return _number(self, x)

    @property
    def eps(self) -> Scalar:
        """The magnetic parameter epsilon."""
        x = self._param("epsilon")
        return _number(self, x)


class Scene(PaperObjects):
    """One problem size over one field, with lazily built objects."""

    #: whether the engine's steps may take the closed forms that hold on T*V only (the multipliers of
    #: (dot_XP) where XᵀX = I holds exactly at the point): a scene whose point need not be on T*V (the
    #: exact method's unconstrained chart) and its probe compute the solved systems instead
    ON_V_SHORTCUTS = True
    #: the scene's point is one a claim gave (:func:`stiefelsym.twisted.at_point`), not the chart's: nothing
    #: puts it on V, so floats and balls, whose test of zero only bounds, take no closed form that needs
    #: XᵀX = I_r there (the exact fields test it exactly)
    _point_given = False

    def __init__(self, n: int, r: int, field: Field, *, chart: str = "cayley",
                 rng: random.Random | None = None, component: int = 0,
                 realization: str = "standard", options: Mapping[str, Any] | None = None,
                 tracker: CoordinateTracker | None = None, right_reduction: bool = False,
                 diagonal_A: bool = False, cayley_right: bool = False, unitary_right: bool = False) -> None:
        if not isinstance(n, int) or not isinstance(r, int):
            raise SizeError("n and r must be integers")
        if r < 1:
            raise SizeError(f"r = {r} < 1: a Stiefel variety V(n, r) needs r >= 1")
        if r > n:
            raise SizeError(f"r = {r} > n = {n}: V(n, r) needs r <= n")
        if chart not in ("cayley", "equivariant"):
            raise ValueError(f"unknown chart {chart!r}")
        self._n, self._r = n, r
        self._field = field
        self._chart = chart
        self._rng = rng
        self._component = component
        self._second_point_read = False
        self._complex_point_read = False
        self._realization = realization
        self._options = dict(options or {})
        self._tracker = tracker if tracker is not None else CoordinateTracker({"n": n, "r": r})
        #: the equivariant chart of the standard realization also reduces by O(r) acting on the right
        #: (A11 diagonal); the metric realization's chart always does
        self._right_reduction = chart == "equivariant" and (realization == "metric" or right_reduction)
        if self._right_reduction and tracker is None:
            self._tracker.watch_r()               # the chart's reduction uses O(r) as well
        #: the equivariant chart of a graph that reads no point: O(n) spent on A alone, A = diag(a)
        #: (:meth:`_equivariant_A`); reading a point raises :class:`PointRead`
        if diagonal_A and (chart != "equivariant" or realization != "standard" or right_reduction):
            raise ValueError("the diagonal chart is an equivariant chart of the standard realization, "
                             "reduced by O(n) alone")
        self._diagonal_A = diagonal_A
        #: the symbolic Cayley chart for 2 <= r <= n reduced by O(r) acting on the right as well: S11 = 0
        #: (:meth:`_reduced_cayley_point`; stiefelsym.methods.cayley_right states when it is used)
        if cayley_right and (chart != "cayley" or realization != "standard" or not 2 <= r <= n):
            raise ValueError("the right-reduced Cayley chart is a Cayley chart of the standard realization, "
                             "2 <= r <= n")
        self._cayley_right = cayley_right
        #: the complex point reduced by U(r) acting on the right as well: S11 = 0
        #: (:meth:`_equivariant_complex_point`; stiefelsym.methods.complex_right states when it is used)
        self._unitary_right = unitary_right
        self._params: dict[str, Any] = {}
        self._param_blocks: list[tuple[str, Any, Any]] = []
        self._cache: dict[str, Any] = {}

    def killing(self, a: Mat, b: Mat) -> Scalar:
        """<a, b> = -1/2 tr(ab), as the Frobenius pairing of a and bᵀ (n² products, not n³)."""
        if not (isinstance(a, Mat) and isinstance(b, Mat)):
            return PaperObjects.killing(self, a, b)
        (m, k1), (k2, k) = a._shape(), b._shape()
        if k1 != k2 or m != k:
            raise ValueError(f"cannot pair {(m, k1)} with {(k2, k)} by the trace of their product")
        unify(a.tags[1], b.tags[0], "a product", a.tracker)
        unify(a.tags[0], b.tags[1], "a trace", a.tracker)
        x = self._field.pairing(a._inner(b.T) * self._field.const(Fraction(-1, 2)))
        return _number(self, x)

    @property
    def Phi(self) -> Mat:
        """The SO(n) momentum map Phi = P X^T - X P^T; over an exact field as B - B^T with
        B = P X^T (X P^T is (P X^T)^T exactly: one product instead of two)."""
        if not self._field.exact:
            return PaperObjects.Phi.fget(self)

        def build():
            B = self.P @ self.X.T
            return B - B.T
        return self._cached("Phi", build)

    # the problem is fixed once the scene exists: read-only; what tells the methods (or the
    # sampled point) apart is the engine's, and claim code that asks is refused (and recorded)
    n = property(lambda self: self._n, doc="the size n")
    r = property(lambda self: self._r, doc="the size r")
    tracker = property(lambda self: self._tracker, doc="the record of looks at coordinates")
    field = _engine_property("_field", "the scene's number system (s.field)")
    chart = _engine_property("_chart", "the scene's chart (s.chart)")
    component = _engine_property("_component", "the component of O(n) of the chart (s.component)")
    realization = _engine_property("_realization", "the scene's realization (s.realization)")
    rng = _engine_property("_rng", "the scene's random source (s.rng)")
    params = _engine_property("_params", "the values of the chart's parameters (s.params)")
    options = _engine_property("_options", "the run's options (s.options)")

    # ------------------------------------------------------------------
    # parameters and primitives
    def _param(self, name: str) -> Scalar:
        """A free parameter of the chart (symbol, random number, degree marker)."""
        if name not in self._params and self._param_blocks:
            m = _ENTRY_NAME.fullmatch(name)
            if m and any(b[0] == m.group(1) for b in self._param_blocks):
                self._expand_param_blocks()
        if name not in self._params:
            value = self._field.param(name, self._rng)
            hard = self._options.get("hard")
            if hard is not None and self._rng is not None:
                new = hard.rewrite(self, name, value)
                if new is not value:
                    # a case that rewrites P's parameters (drawn with X's) reaches the claim only when it reads
                    # P (see :meth:`_momenta_read`); any other, when the parameter is drawn
                    state = self._options.get("hard_momenta")
                    if hard.through == "P" and state is not None and not state["read"]:
                        state["pending"].append(name)
                    else:
                        self._options.setdefault("hard_hits", []).append(name)
                    value = self._field.exact_input(new)
            self._params[name] = value
        return self._params[name]

    def _cached(self, key: str, build: Callable[[], Any]) -> Any:
        if key not in self._cache:
            self._cache[key] = build()
        return self._cache[key]

    def _cached_for(self, key: str, obj: Any, build: Callable[[], Any]) -> Any:
        """Cache keyed by an object's identity; the object is kept alive with the value."""
        full = f"{key}:{id(obj)}"
        if full not in self._cache:
            self._cache[full] = (obj, build())
        return self._cache[full][1]

    def const(self, q: int | Fraction) -> Scalar:
        x = self._field.const(q)
        return _number(self, x)

    def q(self, num: int, den: int = 1) -> Scalar:
        """The rational constant num/den as an element of the scene's field."""
        x = self._field.const(Fraction(num, den))
        return _number(self, x)

    def mat(self, rows, tags=("?", "?")) -> Mat:
        """A matrix from rows of scalars, with the spaces of its rows and columns.  An
        R^n-indexed one (tags such as ("n", "n")) is recorded as built from coordinates;
        an untyped one (tags "?") is recorded when it meets R^n; a named coordinate
        space ("so", "cond", ...) never meets R^n or R^r."""
        return Mat.from_rows(rows, self._field, tags, self.tracker)

    def zeros(self, m: int, k: int, tags=("?", "?")) -> Mat:
        return Mat.zeros(m, k, self._field, tags, self.tracker)

    def identity(self, m: int, tag="?") -> Mat:
        return Mat.identity(m, self._field, tag, self.tracker)

    def _param_block(self, name: str, m: int, k: int, kind: str, tags) -> Mat | None:
        """A skew, symmetric or general m x k matrix of fresh parameters drawn at once and kept in
        the backend's native storage (recorded as one block, expanded into :attr:`params` only
        when an entry is asked for by name), or None where parameters are drawn one at a time
        (no backend, hard cases, a field without block draws, or a name already drawn)."""
        be = backend(self._field)
        if (be is None or self._rng is None or not hasattr(be, "from_array") or self._options.get("hard") is not None
                or any(b[0] == name for b in self._param_blocks)
                or param_name(name, 0, 1 if kind == "skew" else 0) in self._params):
            return None
        count = m * k if kind == "general" else m * (m - 1) // 2 if kind == "skew" else m * (m + 1) // 2
        if count < PARAM_BLOCK_MIN:
            return None
        vals = self._field.param_values(self._rng, count)
        if vals is None:
            return None
        if kind == "general":
            arr = vals.reshape(m, k)                  # row by row, as the cells are listed
        else:
            # the upper triangle row by row (a boolean mask selects in that order, as triu_indices
            # lists it), then mirrored: the lower triangle is 0 there, so the sums are exact
            # (the arrays of the float backend's pool: np.zeros's numbers, and numpy's layout of
            # the difference)
            arr = _buf((m, m), vals.dtype)
            arr.fill(0)
            arr[_upper_mask(m, 1 if kind == "skew" else 0)] = vals
            arr = _binop(np.subtract, arr, arr.T) if kind == "skew" else arr + np.triu(arr, 1).T
        self._param_blocks.append((name, (kind, m, k), vals))
        return Mat._wrap_native(be.from_array(arr), self._field, tags, self.tracker)

    def _expand_param_blocks(self) -> None:
        """Enter every parameter drawn in a block into :attr:`params` under its own name."""
        blocks, self._param_blocks[:] = list(self._param_blocks), []
        for name, (kind, m, k), vals in blocks:
            if kind == "general":
                rows, cols = np.repeat(np.arange(m), k), np.tile(np.arange(k), m)
            else:
                rows, cols = np.triu_indices(m, 1 if kind == "skew" else 0)
            for i, j, x in zip(rows.tolist(), cols.tolist(), vals.tolist()):
                self._params[param_name(name, i, j)] = self._field.param_from_raw(x)

    def _point_values(self) -> dict[str, Any]:
        """Every parameter of the point drawn so far, by name (a witness's coordinates)."""
        self._expand_param_blocks()
        return self._params

    def _has_params(self) -> bool:
        """Whether any parameter has been drawn."""
        return bool(self._params) or bool(self._param_blocks)

    def _skew_params(self, name: str, m: int, tag: str) -> Mat:
        M = self._param_block(name, m, m, "skew", (tag, tag))
        if M is not None:
            return M
        M = self.zeros(m, m, (tag, tag))
        a = M._a
        for i in range(m):
            for j in range(i + 1, m):
                x = self._param(param_name(name, i, j))
                a[i, j], a[j, i] = x, -x
        return M

    def _sym_params(self, name: str, m: int, tag: str) -> Mat:
        M = self._param_block(name, m, m, "sym", (tag, tag))
        if M is not None:
            return M
        M = self.zeros(m, m, (tag, tag))
        a = M._a
        for i in range(m):
            for j in range(i, m):
                x = self._param(param_name(name, i, j))
                a[i, j] = a[j, i] = x
        return M

    def general_params(self, name: str, m: int, k: int, tags) -> Mat:
        """A generic m x k matrix of fresh parameters of the claim's own (index spaces ``tags``).  The spaces are
        part of its name, as its size is: at r = n the matrix of one name on R^n x R^n and on R^r x R^r are two
        matrices, as at r < n (one parameter shared by a side that moves with O(r) on the right and one that
        does not would break the equivariance reductions)."""
        spaces = ",".join(tags) if isinstance(tags, tuple) and all(isinstance(x, str) for x in tags) else str(tags)
        return self._general_params(f"{USER_PARAMS}{user_name(name, 'general_params')}[{m}x{k}]@{spaces}", m, k, tags)

    def _general_params(self, name: str, m: int, k: int, tags) -> Mat:
        M = self._param_block(name, m, k, "general", tags)
        if M is not None:
            return M
        M = self.zeros(m, k, tags)
        a = M._a
        for i in range(m):
            for j in range(k):
                a[i, j] = self._param(param_name(name, i, j))
        return M

    def _engine_params(self, tag: str, m: int, k: int, tags=("?", "?")) -> Mat:
        """An m x k matrix of parameters of the engine's own (a generic velocity or element at which a step
        checks a claim's function), independent of the claim's draws: over a field of numbers drawn from a
        generator seeded by a digest of the tag, a count of such draws and the state of the scene's generator,
        which they neither read from nor advance (the claim's next draws are the same with or without them,
        and equal none of them but by chance); over a symbolic field, symbols of names no claim can give.
        Drawn as the scene's own parameters would be, they were the claim's next draws (stop 78).

        Over a symbolic field one matrix of symbols serves every check of its tag and shape on the scene at
        one depth of checks (:func:`engine_check`): each check is an identity in those symbols, and no value
        of the graph holds them (the steps return their values without them), so checks made one after the
        other may share them; a check made while another evaluates the claim's function at its symbols (a
        step nested in the function of another) takes symbols of its own, else it would check its function
        along the other's direction only, at points made of it (stop 79: a nested polynomial_gradient then
        took its degree too low).  The ring of the exact method grows by one set of symbols per depth, not
        by one per check (a new symbol late in an evaluation carries every polynomial to a wider ring)."""
        if self._field.name == "symbolic":
            shared = self.__dict__.setdefault("_engine_symbols", {})
            key = (tag, m, k, tags, ENGINE_CHECK_DEPTH[0])
            if key not in shared:
                shared[key] = self._engine_draw(tag, m, k, tags)
            return shared[key]
        return self._engine_draw(tag, m, k, tags)

    def _engine_draw(self, tag: str, m: int, k: int, tags=("?", "?")) -> Mat:
        """A fresh draw of :meth:`_engine_params`."""
        count = self.__dict__.get("_engine_draws", 0) + 1
        self.__dict__["_engine_draws"] = count
        rng = self._rng
        seed = hashlib.sha256(repr((tag, count, rng.getstate() if rng is not None else None)).encode()).digest()
        own = random.Random(int.from_bytes(seed[:16], "big"))
        M = self.zeros(m, k, tags)
        a = M._a
        for i in range(m):
            for j in range(k):
                a[i, j] = self._field.param(f"{tag}#{count}:{param_name('w', i, j)}", own)
        return M

    def _normal_params(self, name: str, n: int, r: int) -> Mat:
        """The n x r matrix Z of the normal part (I − XXᵀ)Z of a tangent vector at a point X of a
        symbolic chart, with its first r rows 0 and the rest fresh parameters (named by their rows,
        as in a full Z).  At every X whose top r x r block X1 is invertible (a dense open set of the
        chart: X1 = I at its origin), Z2 ↦ (I − XXᵀ)[0; Z2] is injective ([0; Z2] = XC gives X1 C = 0)
        between spaces of the dimension (n − r)r of the normal space {N : XᵀN = 0}, so onto it: the
        chart stays dense in the tangent (cotangent) bundle with r² fewer parameters.  The same holds
        over ℂ with Xᴴ for the realified complex point (then for the real and imaginary parts)."""
        Z = self.zeros(n, r, ("n", "r"))
        for i in range(r, n):
            for j in range(r):
                Z._a[i, j] = self._param(param_name(name, i, j))
        return Z

    def _no_point(self, what: str) -> None:
        """On the diagonal chart (O(n) spent on A alone), a point of T*V has no place: raise
        :class:`PointRead` (the symbolic method then takes the chart that fixes the point)."""
        if self._diagonal_A:
            raise PointRead(what)

    def _stiefel_point(self, prefix: str) -> tuple[Mat, Mat]:
        self._no_point(f"a point {prefix or 'X, P'}")
        n, r = self.n, self.r
        if self.chart == "equivariant":
            D = np.eye(n, r, dtype=np.int64)
            X = Mat._consts(D, self._field, ("n", "r"), self._tracker)
            W = self._skew_params(f"{prefix}W", r, "r")
            if n == r:
                P = Mat._wrap(W._a.copy(), self._field, ("n", "r"), self._tracker)
            else:
                P = Mat._wrap(np.concatenate([W._a, self._Z_block(prefix, n, r)]), self._field, ("n", "r"),
                              self._tracker)
            if self._realization == "metric":
                # (cond_XP2) at X0: B11 P1 + B12 P2 = W skew (B = A⁻¹), with B11 = diag(b) (see
                # _metric_inverse): P1 = B11⁻¹(W − B12 P2), one division per row
                B = self.Ainv._a
                f = self._field
                for i in range(r):
                    for j in range(r):
                        acc = P._a[i, j]
                        for k in range(r, n):
                            acc = acc - B[i, k] * P._a[k, j]
                        P._a[i, j] = f.normalize(acc / B[i, i])
            return X, P
        if isinstance(self._field, SymbolicField) and (r < n or self._cayley_right and not prefix):
            # at r = n the right-reduced chart is X = I, P = W (W skew): K is empty and S11 = 0
            return self._reduced_cayley_point(prefix)
        S = self._skew_params(f"{prefix}S", n, "n")
        In = self.identity(n, "n")
        plus = In + S
        inverse = plus.inv()
        # the first r columns (the first one negated on the second component of O(n)) as one
        # product with the constant n x r matrix J = [D; 0]
        D = _buf((n, r), np.int64)
        D.fill(0)
        D[range(r), range(r)] = 1
        if self._component_of(prefix) == 1:
            D[0, 0] = -1
        J = Mat._consts(D, self._field, ("n", "r"), self.tracker)
        if self._field.exact:
            # Q = (I - S)(I + S)^-1 = 2(I + S)^-1 - I exactly (I - S = 2I - (I + S) commutes with
            # (I + S)^-1): X = QJ = 2(I + S)^-1 J - J, one n x n x r product instead of an n x n x n
            # product and an n x n x r one; and P = XW + (I - XXᵀ)Z = XW + Z - X(XᵀZ), two n x r x r
            # products instead of two n x n x r ones.  Over a float field the rounding (and the
            # error bounds) of the printed construction is kept
            X = (inverse @ J) * 2 - J
            self._done_with(S, plus, inverse, J)
            del S, plus, inverse
            W = self._skew_params(f"{prefix}W", r, "r")
            if r == n and isinstance(self._field, SymbolicField):
                # X is in O(n): I - XXᵀ = 0 identically on the symbolic chart, and P = XW is every
                # tangent vector (no Z, whose parameters would cancel only after every product)
                P0 = X @ W
                if self._realization == "metric":
                    P0 = self.A @ P0
                self._done_with(In, W)
                return X, P0
            Z = self._general_params(f"{prefix}Z", n, r, ("n", "r"))
            XW = X @ W
            P0 = XW + (Z - X @ (X.T @ Z))
            if self._realization == "metric":
                P0 = self.A @ P0
            self._done_with(In, W, Z, XW)
            return X, P0
        minus = In - S
        Q = minus @ inverse                    # in O(n); det Q = 1
        X = Q @ J
        # what only the construction of the point reads goes as soon as it is read, not with the
        # scene (X keeps what it remembers: X Xᵀ is a term of the claims)
        self._done_with(S, In, minus, plus, inverse, Q, J)
        del S, minus, plus, inverse, Q
        W = self._skew_params(f"{prefix}W", r, "r")
        Z = self._general_params(f"{prefix}Z", n, r, ("n", "r"))
        XW, proj = X @ W, In - X @ X.T
        Pz = proj @ Z
        P0 = XW + Pz
        if self._realization == "metric":
            P0 = self.A @ P0
        self._done_with(In, W, Z, XW, proj, Pz)
        return X, P0

    def _reduced_cayley_point(self, prefix: str) -> tuple[Mat, Mat]:
        """The Cayley chart of the symbolic method: the first r columns of the Cayley transform of
        the skew S = [[S11, −Kᵀ], [K, 0]] (S11 skew r × r, K generic (n − r) × r), X = [I − S11 −
        KᵀK; −2K] M⁻¹ with M = I + S11 + KᵀK (one r × r inverse), P = XW + (I − XXᵀ)Z as in the full
        chart (A @ that in the metric realization).  Dense in T*V(n, r) for r < n (see
        :meth:`_equivariant_second_point`); the points of the sampling methods keep the full S."""
        n, r = self.n, self.r
        tr = self._tracker
        Ir = self.identity(r, "r")
        # reduced by O(r) on the right as well (the method's choice, for graphs covariant under it): S11 = 0,
        # X1 = (I - KᵀK)(I + KᵀK)⁻¹ symmetric, and the points X(K)h, h in O(r), fill a dense open set
        S11 = (self.zeros(r, r, ("r", "r")) if self._cayley_right and not prefix
               else self._skew_params(f"{prefix}S", r, "r"))
        Kfull = self.zeros(n, r, ("n", "r"))
        for i in range(r, n):
            for j in range(r):
                Kfull._a[i, j] = self._param(param_name(f"{prefix}K", i, j))
        KtK = Kfull.T @ Kfull
        E = Mat._consts(np.eye(n, r, dtype=np.int64), self._field, ("n", "r"), tr)
        if self._cayley_right and not prefix and n - r < r:
            # S11 = 0 and n - r < r: M⁻¹ = (I + KᵀK)⁻¹ = I − Kᵀ(I + KKᵀ)⁻¹K (Woodbury), the same rational
            # functions (denominator det(I + KKᵀ) = det M) from an (n − r) × (n − r) inverse: I_n + K̂K̂ᵀ
            # for K̂ = [0; K] is diag(I_r, I + KKᵀ), whose off-diagonal entries sit in its last n − r rows
            Minv = Ir - Kfull.T @ (self.identity(n, "n") + Kfull @ Kfull.T).inv() @ Kfull
        else:
            Minv = (Ir + S11 + KtK).inv()
        X = (E @ (Ir - S11 - KtK) - Kfull * self.const(2)) @ Minv
        W = self._skew_params(f"{prefix}W", r, "r")
        Z = self._normal_params(f"{prefix}Z", n, r)      # X1 = (I - S11 - KᵀK)M⁻¹ = I at the origin
        In = self.identity(n, "n")
        P0 = X @ W + (In - X @ X.T) @ Z
        if self._realization == "metric":
            P0 = self.A @ P0
        return X, P0

    def _done_with(self, *mats: Mat) -> None:
        """Tell the backend that the construction of the point reads these matrices no more (see
        :meth:`.native.Float64Backend.forget`): what it remembers of them goes with them."""
        forget = getattr(backend(self._field), "forget", None)
        if forget is not None:
            for M in mats:
                if M._n is not None:
                    forget(M._n)

    def equivariant_reduction(self) -> str | None:
        """What the equivariant chart assumes, stated for reports (engine only; None in the Cayley
        chart); ``{why}`` is where the method says why the claim is covariant."""
        if self._chart != "equivariant":
            return None
        if self._diagonal_A:
            return ("equivariance: A = diag(a_1..a_n) with the a_i free; the claim reads no point of T*V (nor a "
                    "second, complex or double point), so the whole of O(n) acts on A, and it diagonalizes "
                    "every symmetric A; the residuals are covariant under (A, M) -> (gAg^T, gM), g in O(n), "
                    "for the generic parameters M of the claim (acted on by g on their R^n indices, they "
                    "stay generic), because {why}")
        if self._realization == "metric":
            return ("equivariance: X = X0 = (E_1..E_r), B = A^{{-1}} symmetric with its diagonal blocks B11 "
                    "(r x r) and B22 diagonal and B12 generic, P = (B11^{{-1}}(W - B12 Z); Z) with W skew "
                    "(so that X^T A^{{-1}} P is skew); O(n) moves X0 to every point of V(n, r) and the "
                    "stabilizer diag(R, S) of X0, with R in O(r) acting on the right as well, diagonalizes "
                    "B11 and B22; the residuals are covariant under (X, P, A) -> (gXh^T, gPh^T, gAg^T), "
                    "g in O(n), h in O(r), because {why}")
        if self._right_reduction:
            return ("equivariance: X = X0 = (E_1..E_r), P = (W; Z) with W skew, A symmetric with its diagonal "
                    "blocks A11 (r x r) and A22 ((n - r) x (n - r)) diagonal and A12 generic; O(n) moves X0 to "
                    "every point of V(n, r) and the stabilizer diag(R, S) of X0, with R in O(r) acting on the "
                    "right as well, keeps P in the chart and diagonalizes A11 and A22; the residuals are "
                    "covariant under (X, P, A) -> (gXh^T, gPh^T, gAg^T), g in O(n), h in O(r), because {why}")
        if self.n - self.r >= 2:
            return ("equivariance: X = X0 = (E_1..E_r), P = (W; Z) with W skew, A symmetric with its block A22 "
                    "((n - r) x (n - r)) diagonal and A11, A12 generic; O(n) moves X0 to every point of V(n, r) "
                    "and the stabilizer diag(I_r, S), S in O(n - r), of X0 keeps P in the chart and "
                    "diagonalizes A22; the residuals are covariant under (X, P, A) -> (gX, gP, gAg^T), g in "
                    "O(n), because {why}")
        return None

    def _equivariant_A(self) -> Mat:
        """A of the equivariant chart of the standard realization: symmetric, with its block A22
        ((n − r) × (n − r)) diagonal and A12 generic.  The chart's reduction: the stabilizer of
        X0 in O(n), Q = diag(I_r, S) with S ∈ O(n − r), fixes X0, keeps P = (W; Z) in the chart (Z
        generic) and diagonalizes A22 ↦ S A22 Sᵀ; the claims are covariant under O(n).  With the
        O(r) reduction (``right_reduction``: claims covariant under X ↦ QXRᵀ, P ↦ QPRᵀ, A ↦ QAQᵀ as
        well), Q = diag(R, S) with the same R ∈ O(r) keeps X0 and P = (RWRᵀ; SZRᵀ) in the chart and
        diagonalizes A11 ↦ R A11 Rᵀ too."""
        n, r = self.n, self.r
        A = self.zeros(n, n, ("n", "n"))
        a = A._a
        if self._diagonal_A:
            for i in range(n):
                a[i, i] = self._param(param_name("A", i, i))
            return A
        for i in range(n):
            for j in range(i, n):
                if i != j and (i >= r or (j < r and self._right_reduction)):
                    continue                     # A22 is diagonal, and so is A11 with the O(r) reduction
                a[i, j] = a[j, i] = self._param(param_name("A", i, j))
        return A

    def _Z_block(self, prefix: str, n: int, r: int) -> np.ndarray:
        """The (n − r) × r block Z of P at X0: entries named by their rows in P (r..n−1)."""
        Z = np.empty((n - r, r), dtype=object)
        for i in range(r, n):
            for j in range(r):
                Z[i - r, j] = self._param(param_name(f"{prefix}Z", i, j))
        return Z

    def _metric_inverse(self) -> Mat:
        """B = A⁻¹ of the equivariant chart of the metric realization: symmetric, with its diagonal
        blocks B11 = X0ᵀ B X0 (r × r) and B22 ((n − r) × (n − r)) diagonal.  The chart's reduction:
        the claims are covariant under X ↦ QXRᵀ, P ↦ QPRᵀ, A ↦ QAQᵀ (Q ∈ O(n), R ∈ O(r)); Q moves
        X to X0 = [I; 0], and the stabilizer of X0, Q = diag(R, S) with the same R, diagonalizes
        B11 ↦ R B11 Rᵀ and B22 ↦ S B22 Sᵀ."""
        n, r = self.n, self.r
        B = self.zeros(n, n, ("n", "n"))
        a = B._a
        for i in range(n):
            for j in range(i, n):
                if i != j and (j < r or i >= r):
                    continue                     # B11 and B22 are diagonal
                a[i, j] = a[j, i] = self._param(param_name("Ainv", i, j))
        return B

    def _point(self):
        if self.chart == "equivariant" and "double base" in self._cache and "point" not in self._cache:
            self._double_and_own_point()
        return self._cached("point", lambda: self._stiefel_point(""))

    def _double_and_own_point(self) -> None:
        """The equivariant chart spends its O(n) reduction on one point of V(n, r): the scene's (X, P) or
        the double point's X₀, not both (they are independent points)."""
        self.tracker.touch("the double point next to the point (X, P)")
        raise CoordinateAccess("the double point next to the point (X, P)")

    @property
    def X(self) -> Mat:
        return self._point()[0]

    def _momenta_read(self) -> None:
        """The claim reads P (itself, or through Phi, Psi, a flow, a gradient): the parameters of P a hard case
        rewrote reach it."""
        state = self._options.get("hard_momenta")
        if state is not None and not state["read"]:
            state["read"] = True
            self._options.setdefault("hard_hits", []).extend(state["pending"])
            state["pending"].clear()

    @property
    def P(self) -> Mat:
        self._momenta_read()
        return self._point()[1]

    def _second_point(self):
        if self.chart == "equivariant":
            if self._realization == "metric":
                # the metric chart's reduction by O(r) fixes B11 = X0ᵀ A⁻¹ X0 diagonal: a second
                # point has no chart of its own here
                self.tracker.touch("a second point (Y, Q)")
                raise CoordinateAccess("a second point (Y, Q)")
            # the reduction moves the first point to X0; the second stays generic
            self._second_point_read = True
            return self._cached("point2", self._equivariant_second_point)
        # at r = n the two points lie on the components of O(n) independently: the methods that
        # alternate the components evaluate every pair once they see the second point read
        self._second_point_read = True
        return self._cached("point2", lambda: self._stiefel_point("second_"))

    def _component_of(self, prefix: str) -> int:
        """The component of O(n) (0: det = 1, 1: det = −1, for r = n) of the chart's point of this
        prefix: bit 0 of :attr:`component` for the scene's own point (X, P) (and the double point's
        base), bit 1 for the second point (Y, Q), so that the components 0..3 take the four pairs of
        components of (X, Y): a second point on the component of X only passed det(XᵀY) = 1 at r = n."""
        return (self.component // 2) % 2 if prefix == "second_" else self.component % 2

    right_reduction = _engine_property("_right_reduction", "whether the chart reduces by O(r) as well")
    diagonal_A = _engine_property("_diagonal_A", "whether the chart spends O(n) on A alone (A diagonal, no point)")
    second_point_read = _engine_property("_second_point_read", "whether the evaluation read (Y, Q)")

    def second_point_text(self) -> str:
        """The reduction's statement of the second point and of the complex point, when the claim
        read them (else '')."""
        out = ""
        if self._complex_point_read and self._unitary_right:
            from stiefelsym.methods.complex_right import REDUCTION as UNITARY_RIGHT
            out = UNITARY_RIGHT
        elif self._complex_point_read:
            out = ("; the point (Z, Zdot) of TW(n, r), realified, generic: real (g, h) act on it as "
                   "realify(g) Z realify(h)^T and leave it anywhere, Z = [I - S11 - K*K; -2K] M^{-1}, "
                   "M = I + S11 + K*K (the first r columns of the unitary Cayley transform of "
                   "[[S11, -K*], [K, 0]], S11 skew-Hermitian, K generic complex; dense in W(n, r)), "
                   "Zdot = ZW' + (I - ZZ*)Y' (W' skew-Hermitian, Y' generic with its first r rows 0: onto the normal "
                   "space where the top r x r block of Z is invertible, a dense open set)")
        if not self._second_point_read:
            return out
        comp = ""
        if self.n == self.r:
            c = (self.component // 2 if self.chart == "cayley" else self.component) % 2
            comp = (f"; component {c + 1} of O(n) for Y "
                    f"(D = {'I' if c == 0 else 'diag(-1,1,..,1)'})")
        return ("; the second point (Y, Q) of T*V(n, r) generic: (g, h) act on it as on (X, P) and leave "
                "it anywhere, Y = [I - S11 - K^T K; -2K] M^{-1} D, M = I + S11 + K^T K (the first r columns "
                "of the Cayley transform of [[S11, -K^T], [K, 0]], S11 skew, K generic; dense in V(n, r)"
                + comp + "), Q = YW' + (I - YY^T)Z' (W' skew, Z' generic with its first r rows 0: onto the normal space "
                "where the top r x r block of Y is invertible, a dense open set)" + out)

    def _equivariant_second_point(self, prefix: str = "second_") -> tuple[Mat, Mat]:
        """A generic second point (Y, Q) of T*V(n, r) on the equivariant chart: the first r columns
        of the Cayley transform (I − S)(I + S)⁻¹ of the skew S = [[S11, −Kᵀ], [K, 0]] (S11 skew r × r,
        K generic (n − r) × r), which are Y = [I − S11 − KᵀK; −2K] M⁻¹ with M = I + S11 + KᵀK
        (Schur complement of the block I: one r × r inverse, where the full Cayley chart needs an
        n × n one), times D = diag(−1, 1, .., 1) on the second component of O(n) when r = n;
        Q = YW + (I − YYᵀ)Z (W skew, Z generic).  YᵀY = I_r identically (MᵀM = (I − S11 − KᵀK)ᵀ(I −
        S11 − KᵀK) + 4KᵀK), and the map (S11, K) ↦ Y has the injective differential (S11, K) ↦
        −2(S11; K) at 0 between spaces of the dimension of V(n, r): its image contains an open set of
        the irreducible V(n, r) (of the component of O(n) for r = n), so it is Zariski dense there.
        The O(n) reduction of the chart acts on both points: fixing X0 (and diagonalizing A22 by
        the stabilizer of X0) leaves Y anywhere on V(n, r)."""
        self._no_point("a second point (Y, Q)")
        n, r = self.n, self.r
        tr = self._tracker
        Ir = self.identity(r, "r")
        S11 = self._skew_params(f"{prefix}S", r, "r")
        Kfull = self.zeros(n, r, ("n", "r"))
        for i in range(r, n):
            for j in range(r):
                Kfull._a[i, j] = self._param(param_name(f"{prefix}K", i, j))
        KtK = Kfull.T @ Kfull
        M = Ir + S11 + KtK
        D0 = np.eye(n, r, dtype=np.int64)
        E = Mat._consts(D0, self._field, ("n", "r"), tr)
        N = E @ (Ir - S11 - KtK) - Kfull * self.const(2)
        Y = N @ M.inv()
        if n == r and self.component % 2 == 1:
            Dr = np.eye(r, dtype=np.int64)
            Dr[0, 0] = -1
            Y = Y @ Mat._consts(Dr, self._field, ("r", "r"), tr)
        W = self._skew_params(f"{prefix}W", r, "r")
        Z = self._normal_params(f"{prefix}Z", n, r)      # Y1 = I at the chart's origin: generic
        In = self.identity(n, "n")
        Q = Y @ W + (In - Y @ Y.T) @ Z
        self._done_with(Ir, S11, Kfull, KtK, M, E, N, W, Z, In)
        return Y, Q

    @property
    def Y(self) -> Mat:
        """A second point (Y, Q) of T*V_{n,r}."""
        return self._second_point()[0]

    @property
    def Q(self) -> Mat:
        return self._second_point()[1]

    # -- a generic point (X, Y, Ẋ, Ẏ) of the double Neumann system: XᵀY = I_r, ẊᵀY + XᵀẎ = 0 ------------
    def _double(self) -> dict:
        return self._cached("double point", lambda: double_point_of(self))

    def _double_base(self) -> Mat:
        """The point X₀ of V(n, r) that the double point X = X₀DU is built on: a generic point of its
        own, independent of the scene's (X, P) and (Y, Q) (the dimension-free scene's DX, DY, DẊ, DẎ
        are letters of their own, with (D0) only): the chart's own construction.  On the equivariant
        chart the O(n) reduction moves X₀ to E (and the stabilizer of E diagonalizes A22, and A11 with
        the O(r) reduction), as it moves the scene's own X there: a claim that reads both points
        leaves the chart (:class:`CoordinateAccess`; the symbolic method then takes the Cayley chart,
        where the two points are independent)."""
        def build() -> Mat:
            if self.chart == "equivariant":
                if "point" in self._cache:
                    self._double_and_own_point()
                return self._stiefel_point("double_base_")[0]      # X₀ = E (the chart's reduction)
            return self._stiefel_point("double_base_")[0]
        return self._cached("double base", build)

    @property
    def DX(self) -> Mat:
        """X of a generic point of the double Neumann system (see :func:`stiefelsym.systems.double_point`)."""
        return self._double()["X"]

    @property
    def DY(self) -> Mat:
        return self._double()["Y"]

    @property
    def DXdot(self) -> Mat:
        return self._double()["Xdot"]

    @property
    def DYdot(self) -> Mat:
        return self._double()["Ydot"]

    # -- the complex Stiefel variety W(n, r), realified (realify, conj: see PaperObjects) ----
    def _complex_point(self):
        self._no_point("a point of W(n, r)")
        n, r = self.n, self.r
        if (self.chart == "equivariant" and self._realization == "standard"
                or self.chart == "cayley" and isinstance(self._field, SymbolicField)):
            # on the symbolic Cayley chart (A = diag(a)) the point is the same reduced unitary Cayley
            # transform: dense in W(n, r) whatever A is, with one complex r x r inverse instead of a
            # complex n x n one
            self._complex_point_read = True
            return self._equivariant_complex_point()
        S = self.realify(self._skew_params("cS", n, "n"), self._sym_params("cH", n, "n"))
        I2 = self.identity(2 * n, "n+n")
        Q = Mat._rows(self._field.solve((I2 + S).T._a.tolist(), (I2 - S).T._a.tolist()),
                          self._field, ("n+n", "n+n"), self.tracker).T
        cols = list(range(r)) + list(range(n, n + r))
        Z = Mat._wrap(Q._a[:, cols].copy(), self._field, ("n+n", "r+r"), self.tracker)
        W = self.realify(self._skew_params("cW", r, "r"), self._sym_params("cK", r, "r"))
        Y = self.realify(self._general_params("cY", n, r, ("n", "r")), self._general_params("cV", n, r, ("n", "r")))
        return Z, Z @ W + (I2 - Z @ Z.T) @ Y

    def _equivariant_complex_point(self) -> tuple[Mat, Mat]:
        """A generic point (Z, Ż) of the tangent bundle of W(n, r), realified, on the equivariant
        chart: the first r columns of the unitary Cayley transform (I − S)(I + S)⁻¹ of the
        skew-Hermitian S = [[S11, −K*], [K, 0]] (S11 skew-Hermitian r × r, K generic complex
        (n − r) × r), Z = [I − S11 − K*K; −2K] M⁻¹ with M = I + S11 + K*K (one complex r × r
        inverse, as for the second point (Y, Q) of :meth:`_equivariant_second_point`); Ż = ZW +
        (I − ZZ*)Y (W skew-Hermitian, Y generic).  The map (S11, K) ↦ Z has the injective differential
        (S11, K) ↦ −2(S11; K) at 0 between spaces of the real dimension 2nr − r² of W(n, r), the
        image of the connected U(n): its image is Zariski dense.  Real g in O(n) and h in O(r) act
        on it as realify(g) Z realify(h)ᵀ, and the chart's reduction leaves Z anywhere on W(n, r)."""
        n, r = self.n, self.r
        f, tr = self._field, self._tracker
        Kre, Kim = self.zeros(n, r, ("n", "r")), self.zeros(n, r, ("n", "r"))
        for i in range(r, n):
            for j in range(r):
                Kre._a[i, j] = self._param(param_name("cKre", i, j))
                Kim._a[i, j] = self._param(param_name("cKim", i, j))
        Kc = self.realify(Kre, Kim)
        I2r = self.identity(2 * r, "r+r")
        KtK = Kc.T @ Kc
        E0 = np.eye(n, r, dtype=np.int64)
        E = self.realify(Mat._consts(E0, f, ("n", "r"), tr), Mat._consts(0 * E0, f, ("n", "r"), tr))
        if self._unitary_right:
            # reduced by U(r) on the right (stiefelsym.methods.complex_right): S11 = 0, and M^{-1} =
            # (I + K*K)^{-1}; where n - r < r, I - K*(I + KK*)^{-1}K (Woodbury) from the rows r..n-1 of
            # K: an (n - r) x (n - r) complex inverse (none at r = n, where Z = I)
            if r == n:
                Minv = I2r
            elif n - r >= r:
                Minv = (I2r + KtK).inv()
            else:
                rows = list(range(r, n)) + list(range(n + r, 2 * n))
                K2 = Mat._wrap(Kc._a[rows, :].copy(), f, ("?", "r+r"), tr)
                I2m = self.identity(2 * (n - r), "?")
                Minv = I2r - K2.T @ (I2m + K2 @ K2.T).inv() @ K2
            Z = (E @ (I2r - KtK) - Kc * self.const(2)) @ Minv
        else:
            S11 = self.realify(self._skew_params("cS", r, "r"), self._sym_params("cH", r, "r"))
            M = I2r + S11 + KtK
            Z = (E @ (I2r - S11 - KtK) - Kc * self.const(2)) @ M.inv()
        W = self.realify(self._skew_params("cW", r, "r"), self._sym_params("cK", r, "r"))
        Y = self.realify(self._normal_params("cY", n, r), self._normal_params("cV", n, r))
        I2 = self.identity(2 * n, "n+n")
        return Z, Z @ W + (I2 - Z @ Z.T) @ Y

    @property
    def Zc(self) -> Mat:
        """A point Z of W(n, r) (Z^* Z = I_r), realified (2n x 2r)."""
        return self._cached("cpoint", self._complex_point)[0]

    @property
    def Zc_dot(self) -> Mat:
        """A tangent vector at Zc (Z^* V + V^* Z = 0), realified."""
        return self._cached("cpoint", self._complex_point)[1]

    @property
    def a(self) -> list[Scalar]:
        """Eigenvalues a_1..a_n of A (a coordinate object: A is then diagonal)."""
        self.tracker.touch("eigenvalues a_i of A")
        if self._chart == "equivariant":
            raise CoordinateAccess("eigenvalues a_i")
        xs = self._cached("a", self._eigenvalues)
        return _opaque(self, xs)

    def _eigenvalues(self) -> list[Any]:
        """a_1..a_n, drawn at once (one generator draw) from PARAM_BLOCK_MIN on, as parameter
        matrices are; one at a time otherwise (and for hard cases, which rewrite them by name)."""
        n, f = self.n, self._field
        if (n >= PARAM_BLOCK_MIN and self._rng is not None and self._options.get("hard") is None
                and "a_1" not in self._params):
            vals = f.param_values(self._rng, n)
            if vals is not None:
                xs = f.params_from_raw(vals)
                params = self._params
                for i, x in enumerate(xs):
                    params[f"a_{i + 1}"] = x
                self._cache["a raw"] = vals     # the same numbers as one array (see A)
                return xs
        return [self._param(f"a_{i + 1}") for i in range(n)]

    @property
    def A(self) -> Mat:
        """The symmetric matrix A: diag(a_1..a_n), or generic symmetric in the equivariant chart."""
        def build():
            if self._chart == "equivariant":
                if self._realization == "metric":
                    return self.Ainv.inv()
                return self._equivariant_A()
            xs = self._cached("a", self._eigenvalues)
            be = backend(self._field)
            if be is not None:
                raw = self._cache.get("a raw")
                from_raw = getattr(be, "diag_from_raw", None)
                d = from_raw(self._field, raw) if raw is not None and from_raw is not None else None
                return Mat._wrap_native(be.diag(xs) if d is None else d, self._field, ("n", "n"), self.tracker)
            M = self.zeros(self.n, self.n, ("n", "n"))
            a = M._a
            for i, x in enumerate(xs):
                a[i, i] = x
            return M
        return self._cached("A", build)

    @property
    def Ainv(self) -> Mat:
        def build():
            if self._chart == "equivariant" and self._realization == "metric":
                return self._metric_inverse()
            if self.chart == "cayley":
                M = self.zeros(self.n, self.n, ("n", "n"))
                for i in range(self.n):
                    M._a[i, i] = self.const(1) / self.A._a[i, i]
                return M
            return self.A.inv()
        return self._cached("Ainv", build)

    @property
    def xi(self) -> Mat:
        """A generic element of so(n)."""
        return self._cached("xi", lambda: self._skew_params("xi", self.n, "n"))

    @property
    def zeta(self) -> Mat:
        """A second generic element of so(n)."""
        return self._cached("zeta", lambda: self._skew_params("zeta", self.n, "n"))

    @property
    def eta(self) -> Mat:
        """A generic element of so(r)."""
        return self._cached("eta", lambda: self._skew_params("eta", self.r, "r"))

    @property
    def theta(self) -> Mat:
        """A second generic element of so(r)."""
        return self._cached("theta", lambda: self._skew_params("theta", self.r, "r"))

    def generic(self, name: str, m: str, k: str, kind: str = "general") -> Mat:
        """A generic matrix of parameters with index labels m, k in {'n', 'r', 'n-r'} (ℝⁿ⁻ʳ: an opaque coordinate
        space of n − r dimensions, the second block of the chart at X₀ = (E₁ … E_r)): every entry its own
        parameter (``kind`` "general"), or a generic symmetric ("sym") or skew ("skew") m×m matrix, whose
        entries on and above the diagonal (above it, for "skew") are the parameters.  A generic element
        of gl(m) is generic("S", m, m, "sym") + generic("K", m, m, "skew"): the same generic point as
        generic("G", m, m), in parameters in which G + Gᵀ and G − Gᵀ have one term per entry."""
        size = {"n": self.n, "r": self.r, "n-r": self.n - self.r}
        if m not in size or k not in size:
            raise ValueError(f"generic({name!r}, {m!r}, {k!r}): the index spaces are 'n', 'r' or 'n-r'")
        key = f"{USER_GENERIC}{user_name(name, 'generic')}[{m}x{k}]" + check_generic_kind(m, k, kind)
        if kind == "sym":
            return self._cached(key, lambda: self._sym_params(key, size[m], m))
        if kind == "skew":
            return self._cached(key, lambda: self._skew_params(key, size[m], m))
        return self._cached(key, lambda: self._general_params(key, size[m], size[k], (m, k)))

    def fresh(self, *args: Any) -> Mat:
        """fresh(index, m, k): the fresh element number ``index`` of a graph (a claim's ``s.fresh(m, k)``, numbered
        by the engine), a generic matrix of parameters with index labels m, k in {'n', 'r'} that no claim can
        name; fresh(m, k), engine code called on the scene itself (not traced): the next of the scene's own."""
        size = {"n": self.n, "r": self.r}
        key = _fresh_key(self, args, size)
        m, k = args[-2:]
        return self._cached(key, lambda: self._general_params(key, size[m], size[k], (m, k)))

    def sym_operator(self, name: str = "AA") -> Callable[[Mat], Mat]:
        """A generic symmetric linear operator on so(n) (w.r.t. <,>), covariant parameter; applied
        to an r×r matrix, the operator of that name on so(r) (parameters of its own)."""
        basis, coeffs = self._operator_coefficients(name)
        return _on_its_space(self._operator_apply(basis, coeffs),
                             lambda: self._operator_apply(*self._operator_coefficients(name, "r"), "r"))

    def _operator_coefficients(self, name: str, space: str = "n") -> tuple[list[tuple[int, int]], Mat]:
        """The basis E_i ∧ E_j of so(n) (or so(r)) and the symmetric coefficient matrix of the operator
        (one parameter per pair of basis elements, drawn once per scene, name and space)."""
        def build():
            basis = so_basis(self.n if space == "n" else self.r)
            own = USER_OPERATOR + user_name(name, "sym_operator") + ("" if space == "n" else "@so(r)")
            return basis, self._sym_params(own, len(basis), "so")
        return self._cached(f"op:{name}" if space == "n" else f"op:{name}@so(r)", build)

    def _operator_apply(self, basis: list[tuple[int, int]], coeffs: Mat, space: str = "n") -> Callable[[Mat], Mat]:
        n = self.n if space == "n" else self.r

        def apply(xi: Mat) -> Mat:
            """AA applied to the skew part (xi - xi^T)/2 (an O(n)-equivariant extension to gl(n))."""
            if not isinstance(xi, Mat):
                raise TypeError(f"the operator acts on matrices of so({space})")
            unify(xi.tags[0], space, f"the operator on so({space})", xi.tracker)
            unify(xi.tags[1], space, f"the operator on so({space})", xi.tracker)
            f = xi._field
            half = f.const(Fraction(1, 2))
            a = xi._entry_reader()
            # coordinates of the skew part in the orthonormal basis E_i ∧ E_j
            comps = [f.normalize((a(i, j) - a(j, i)) * half) for (i, j) in basis]
            out = Mat.zeros(n, n, f, (space, space), xi.tracker)
            out._coords = xi._coords
            o = out._a
            if f is coeffs._field:
                # one product in the field's backend: the coefficient matrix times the coordinates,
                # placed in the upper triangle W; AA(xi) = W - Wᵀ
                col = np.empty((len(basis), 1), dtype=object)
                col[:, 0] = comps
                v = (coeffs @ Mat._wrap(col, f, ("so", "?")))._entry_reader()
                for k, (i, j) in enumerate(basis):
                    o[i, j] = v(k, 0)
                return out - out.T
            c = coeffs._view()                  # a matrix of another field (a base scene's operator)
            for k, (i, j) in enumerate(basis):
                acc = f.const(0)
                for l, x in enumerate(comps):
                    acc = acc + x * c[k, l]
                acc = f.normalize(acc)
                o[i, j], o[j, i] = acc, -acc
            return out
        return apply

    # ------------------------------------------------------------------
    # derived objects
    @property
    def In(self) -> Mat:
        return self._cached("In", lambda: self.identity(self.n, "n"))

    @property
    def Ir(self) -> Mat:
        return self._cached("Ir", lambda: self.identity(self.r, "r"))

    def tr(self, M: Mat) -> Scalar:
        x = M._trace()
        return _number(self, x)

    def tr_product(self, M: Any, N: Any) -> Scalar:
        """tr(M N), for the evaluator's trace of a product that no other node reads (not a method of
        the claims' API): the same value as ``tr(M @ N)``, without the product's off-diagonal entries
        where the backend offers it."""
        if type(M) is Mat and type(N) is Mat:
            return _number(self, M._trace_product(N))
        return self.tr(M @ N)

    def resolvent(self, mu: Scalar) -> Mat:
        """(mu I_n - A)^{-1}."""
        if type(mu) is Fraction or type(mu) is int:   # a constant of the claim: an element of the field
            mu = self.const(mu)
        if type(mu) in LAYERED and _deeper(mu, self._field):
            raise TypeError(DEEPER_NUMBER)

        def build():
            if self.chart == "cayley":
                M = self.zeros(self.n, self.n, ("n", "n"))
                for i in range(self.n):
                    M._a[i, i] = self.const(1) / (mu - self.A._a[i, i])
                return M
            return (scalar_matrix(mu, self.n, self._field, "n", self.tracker) - self.A).inv()
        return self._cached_for("res", mu, build)

    def scalar_matrix(self, c: Scalar, m: int, tag="?") -> Mat:
        return scalar_matrix(check_element(self._field, c), m, self._field, tag, self._tracker)

    # ------------------------------------------------------------------
    # phase space calculus
    @property
    def constraints(self) -> Constraints:
        return REALIZATIONS[self.realization]

    def _coords(self) -> list[tuple[str, int, int]]:
        n, r = self.n, self.r
        return [(name, i, j) for name in ("X", "P") for i in range(n) for j in range(r)]

    def tangent(self, flow: Mapping[str, Mat]) -> "TangentScene":
        return TangentScene(self, flow)

    def _unit_tangents(self):
        n, r = self.n, self.r
        zero = self.zeros(n, r, ("n", "r"))
        for name, i, j in self._coords():
            E = self.zeros(n, r, ("n", "r"))
            E._a[i, j] = self.const(1)
            yield {"X": E, "P": zero} if name == "X" else {"X": zero, "P": E}

    def jacobian(self, F: Function, symmetric: bool | None = None) -> list[list[Scalar]]:
        """The Jacobian of F in the 2nr coordinates of X, P (a recorded look at coordinates);
        see :meth:`_jacobian`."""
        self.tracker.touch("a Jacobian in the coordinates of X, P")
        J = self._jacobian(F, symmetric)
        return _opaque(self, J)

    def _jacobian(self, F: Function, symmetric: bool | None = None, scalar: bool = False) -> list[list[Scalar]]:
        """Rows: scalar components of F (a scalar or list of Mats); columns: the 2nr coordinates.

        ``symmetric``: F's matrices are symmetric and only their upper triangles count (the
        default for the scene's own constraint functions, whose scalar constraints they are); a
        matrix whose derivative is not symmetric is refused (:meth:`_symmetric_derivative`).
        ``scalar``: F must be a scalar function (a Hamiltonian), never a matrix read at one entry."""
        if symmetric is None:
            symmetric = F is self.constraints.build
        cols = []
        for t in self._unit_tangents():
            value = F(self.tangent(t))
            if scalar and isinstance(value, (Mat, list, tuple, dict)):
                raise TypeError("a Hamiltonian (a function whose gradient, flow or bracket is taken) must be "
                                f"a scalar function of the scene, not a {type(value).__name__}")
            if symmetric:
                self._symmetric_derivative(value, lambda x: x.b if isinstance(x, Dual) else self.const(0))
            values = _flatten_value(value, symmetric)
            cols.append([x.b if isinstance(x, Dual) else self.const(0) for x in values])
        return [list(row) for row in zip(*cols)]

    def _symmetric_derivative(self, value: Any, part: Callable[[Any], Any]) -> None:
        """Refuse a Jacobian read by upper triangles (``symmetric``) of a matrix whose derivative along a unit
        direction (``part`` of each entry of ``value``) is not symmetric: its lower triangle is then not the
        upper one again, and the rows of the upper triangle are not all of F's differentials (their rank
        would be too small).  Decided exactly in the exact fields; floats, balls and degree markers stand for
        the exact evaluation, which the exact methods make."""
        if self._approximates_point():
            return
        if isinstance(value, Mat):
            a, f = value._a, self._field
            m = a.shape[0]
            for i in range(m):
                for j in range(i + 1, m):
                    if not f.is_zero(part(a[i, j]) - part(a[j, i])):
                        raise ValueError("a Jacobian read by upper triangles (symmetric=True) of a matrix that is not "
                                         f"symmetric: its derivative differs at ({i}, {j}) and ({j}, {i})")
        elif isinstance(value, (list, tuple)):
            for x in value:
                self._symmetric_derivative(x, part)

    def _unit_tangent(self, k: int) -> dict[str, Mat]:
        """The k-th of :meth:`_unit_tangents` (a column of a Jacobian the graph computes)."""
        n, r = self.n, self.r
        if not 0 <= k < 2 * n * r:
            raise ValueError(f"no unit tangent vector {k} of the {2 * n * r} coordinates of X, P")
        zero = self.zeros(n, r, ("n", "r"))
        E = self.zeros(n, r, ("n", "r"))
        i, j = divmod(k % (n * r), r)
        E._a[i, j] = self.const(1)
        return {"X": E, "P": zero} if k < n * r else {"X": zero, "P": E}

    def _jacobian_rows(self, symmetric: bool, columns: tuple) -> list[list[Scalar]]:
        """The Jacobian from its columns (the derivatives of F along the unit tangent vectors) the graph
        computed, handed on as :meth:`jacobian` hands its own (its look at coordinates recorded)."""
        self.tracker.touch("a Jacobian in the coordinates of X, P")
        if symmetric:
            for v in columns:
                self._symmetric_derivative(v, lambda x: x)
        cols = [_flatten_value(v, symmetric) for v in columns]
        return _opaque(self, [list(row) for row in zip(*cols)])

    def gradient(self, H: Function) -> tuple[Mat, Mat]:
        """(dH/dX, dH/dP) for a scalar function H of the scene: reverse mode over the matrix
        operations (one evaluation of H and one backward sweep), or 2nr forward passes when H
        uses an operation reverse mode does not differentiate."""
        def build():
            if REVERSE_GRADIENTS:
                try:
                    return self._reverse_gradient(H)
                except Unsupported:
                    pass
            row = self._jacobian(H, scalar=True)[0]
            n, r = self.n, self.r
            HX = self.zeros(n, r, ("n", "r"))
            HP = self.zeros(n, r, ("n", "r"))
            HX._a[:, :] = np.array(row[: n * r], dtype=object).reshape(n, r)
            HP._a[:, :] = np.array(row[n * r:], dtype=object).reshape(n, r)
            return HX, HP
        return self._cached_for("grad", H, build)

    def _reverse_gradient(self, H: Function) -> tuple[Mat, Mat]:
        rs = ReverseScene(self)
        X, P = rs.X, rs.P          # the leaves, created before anything that depends on them
        value = H(rs)
        if isinstance(value, (Mat, list, tuple, dict)):
            raise TypeError("a Hamiltonian (a function whose gradient, flow or bracket is taken) must be "
                            f"a scalar function of the scene, not a {type(value).__name__}")
        if not isinstance(value, Rev):
            raise Unsupported("a value that is not a number of the scene")
        leaves = [rs.leaves[k] for k in ("X", "P")]
        grads = rev_gradient(value, leaves, self.const(1))
        return self._as_nr(grads[0]), self._as_nr(grads[1])

    def _grad_vector(self, H: Function) -> list[Scalar]:
        HX, HP = self.gradient(H)
        return list(HX._view().flat) + list(HP._view().flat)

    def _omega(self, v: list[Scalar]) -> list[Scalar]:
        """Omega v for Omega = [[0, I], [-I, 0]] in (X, P) coordinates."""
        m = len(v) // 2
        return list(v[m:]) + [-x for x in v[:m]]

    # gradients as pairs (d/dX, d/dP) of n x r matrices: <u, v> = tr(u_Xᵀ v_X) + tr(u_Pᵀ v_P)
    def _pair_dot(self, u: tuple[Mat, Mat], v: tuple[Mat, Mat]) -> Scalar:
        return self._field.pairing(u[0]._inner(v[0]) + u[1]._inner(v[1]))

    @staticmethod
    def _pair_omega(u: tuple[Mat, Mat]) -> tuple[Mat, Mat]:
        return (u[1], -u[0])

    def _constraint_gradients(self) -> list[tuple[Mat, Mat]]:
        """The gradients of the scalar constraints F_i (the upper triangles of the realization's
        constraint matrices): in closed form for (cond_XP) (:meth:`_standard_constraint_gradients`),
        elsewhere by reverse mode (or the 2nr-column Jacobian when reverse mode cannot)."""
        def build():
            if self.realization in ("standard", "metric") and not isinstance(self, _LiftedScene):
                return self._standard_constraint_gradients()
            if REVERSE_GRADIENTS:
                try:
                    return self._reverse_constraint_gradients()
                except Unsupported:
                    pass
            n, r = self.n, self.r
            out = []
            for row in self._jacobian(self.constraints.build):
                gX, gP = self.zeros(n, r, ("n", "r")), self.zeros(n, r, ("n", "r"))
                gX._a[:, :] = np.array(row[: n * r], dtype=object).reshape(n, r)
                gP._a[:, :] = np.array(row[n * r:], dtype=object).reshape(n, r)
                out.append((gX, gP))
            return out
        return self._cached("grad F", build)

    def _reverse_constraint_gradients(self) -> list[tuple[Mat, Mat]]:
        """The gradients of the scalar constraints by reverse mode: one evaluation of the constraints,
        one backward sweep per scalar constraint."""
        rs = ReverseScene(self)
        X, P = rs.X, rs.P
        scalars = _flatten_value(self.constraints.build(rs), True)
        leaves = [rs.leaves[k] for k in ("X", "P")]
        out = []
        for F in scalars:
            gX, gP = rev_gradient(F, leaves, self.const(1)) if isinstance(F, Rev) else (None, None)
            out.append((self._as_nr(gX), self._as_nr(gP)))
        return out

    def _standard_constraint_gradients(self) -> list[tuple[Mat, Mat]]:
        """The gradients of the scalar constraints of (cond_XP) in closed form, in the order of
        :meth:`_constraint_gradients` (the upper triangle of XᵀX − I_r, then of XᵀP + PᵀX): with
        S_ij = E_ij + E_ji (2E_ii on the diagonal), the (i, j) entry of XᵀX has the X-gradient XS_ij and
        no P-gradient, the (i, j) entry of XᵀP + PᵀX the X-gradient PS_ij and the P-gradient XS_ij; for
        (cond_XP2) (the metric realization, B = A⁻¹ symmetric), the (i, j) entry of XᵀBP + PᵀBX the
        X-gradient BPS_ij and the P-gradient BXS_ij."""
        n, r = self.n, self.r
        X, P = self.X, self.P
        BX, BP = (self.Ainv @ X, self.Ainv @ P) if self.realization == "metric" else (X, P)
        units = []
        for i in range(r):
            for j in range(i, r):
                S = self.zeros(r, r, ("r", "r"))
                S._a[i, j] = S._a[i, j] + self.const(1)
                S._a[j, i] = S._a[j, i] + self.const(1)
                units.append(S)
        out = [(self._as_nr(X @ S), self.zeros(n, r, ("n", "r"))) for S in units]
        out += [(self._as_nr(BP @ S), self._as_nr(BX @ S)) for S in units]
        return out

    def _as_nr(self, g) -> Mat:
        """An adjoint from the tape as an n x r matrix of the scene (zero when absent)."""
        if g is None:
            return self.zeros(self.n, self.r, ("n", "r"))
        return g._retyped(self._field, ("n", "r"), self.tracker)

    def _constraint_jacobian(self) -> list[list[Scalar]]:
        return self._cached("J", lambda: [list(gX._view().flat) + list(gP._view().flat)
                                          for gX, gP in self._constraint_gradients()])

    def constraint_bracket_matrix(self) -> list[list[Scalar]]:
        """The matrix {F_i, F_j}_0 of the scalar constraints (scalar)."""
        def build():
            # one product of the stacked gradients: C0 = G (ΩG)ᵀ, rows g_i = (d/dX, d/dP) F_i
            G = self._constraint_gradients()
            rows = [list(gX._view().flat) + list(gP._view().flat) for gX, gP in G]
            omega = [list(gP._view().flat) + [-x for x in gX._view().flat] for gX, gP in G]
            C = (Mat._rows(rows, self._field) @ Mat._rows(omega, self._field).T)._view()
            return [[C[i, j] for j in range(len(G))] for i in range(len(G))]
        C0 = self._cached("C0", build)
        return _opaque(self, C0)

    def _dot(self, u, v) -> Scalar:
        acc = self.const(0)
        for x, y in zip(u, v):
            acc = acc + x * y
        return self._field.pairing(acc)

    def canonical_bracket(self, F: Function, G: Function) -> Scalar:
        """{F, G}_0 = sum (dF/de, dG/dp) - (dF/dp, dG/de)."""
        x = self._pair_dot(self.gradient(F), self._pair_omega(self.gradient(G)))
        return _number(self, x)

    def _dirac_inverse(self) -> list[list[Scalar]]:
        def build():
            C0 = self.constraint_bracket_matrix()
            m = len(C0)
            I = [[self.const(1 if i == j else 0) for j in range(m)] for i in range(m)]
            try:
                return self._field.solve(C0, I)
            except DegenerateError as exc:
                raise DegenerateError("the constraint bracket matrix {F_i, F_j}_0 is singular here") from exc
        return self._cached("C", build)

    def bracket(self, F: Function, G: Function) -> Scalar:
        """The Dirac bracket (Dirac_bracket) of two scalar functions:
        {F, G} = {F, G}_0 + sum_ij {F_i, F}_0 C^{ij} {F_j, G}_0 (C = ({F_i, F_j}_0)^{-1})."""
        Gs = self._constraint_gradients()
        C = self._dirac_inverse()
        gF, gG = self.gradient(F), self.gradient(G)
        FiF = [self._pair_dot(g, self._pair_omega(gF)) for g in Gs]  # {F_i, F}_0
        FjG = [self._pair_dot(g, self._pair_omega(gG)) for g in Gs]  # {F_j, G}_0
        acc = self._pair_dot(gF, self._pair_omega(gG))
        for i in range(len(Gs)):
            for j in range(len(Gs)):
                acc = acc + FiF[i] * C[i][j] * FjG[j]
        x = self._field.pairing(acc)
        return _number(self, x)

    def canonical_flow(self, H: Function) -> Flow:
        """The Hamiltonian vector field of H for the ambient bracket {,}_0."""
        HX, HP = self.gradient(H)
        return Flow(HP, -HX)

    def _closed_form_multipliers(self, HX: Mat, HP: Mat) -> tuple[Mat, Mat] | None:
        """Λ, Π of (dot_XP) in closed form, where the constraint set is the standard one and
        XᵀX = I_r holds exactly at the point (checked in the field; every chart's point is on V by
        construction, so for degree markers the structure alone is used):

            Π = sym(XᵀH_P),   Λ = sym(XᵀH_X − H_PᵀP + ΠK − KΠ),   K = XᵀP.

        With XᵀX = I the tangency conditions sym(XᵀẊ) = 0, sym(ẊᵀP + XᵀṖ) = 0 are triangular in
        (Π, Λ) with identity diagonal blocks, so these are the unique multipliers: the Dirac flow
        Ω∇H − Σ wᵢ Ω∇Fᵢ of H (the tests compare it with the solved system in every field).  None
        where the closed form does not apply (another realization, XᵀX ≠ I, dual or reverse numbers)."""
        # floating point: every value approximates, within its error bound, the exact evaluation at
        # the chart's point, which is on V exactly (a Cayley transform of a skew matrix of exact
        # inputs, or [I; 0]); the closed form is exact there, so the bounds carry over.  Degree
        # markers follow the structure of the computation the exact fields make.  Not at a point a
        # claim gave (_point_given): floats and balls solve the system there, as the exact fields do off V
        approx = self._approximates_point()
        if not self._closed_form_applies(approx):
            return None
        X, P, sym = self.X, self.P, self._sym
        Pi = sym(X.T @ HP)
        K = X.T @ P
        Lam = sym(X.T @ HX - HP.T @ P + Pi @ K - K @ Pi)
        return Lam, Pi

    def _closed_form_applies(self, approx: bool) -> bool:
        """The standard constraint set in a chart whose points are on V, and XᵀX = I checked exactly
        (or taken from the chart's construction, ``approx``).  Not in the symbolic Cayley chart over
        symengine: there rational functions make the closed form's products swell past any memory
        budget, where the solved system is refused early by the symbolic budget (over flint, with
        one common denominator and exact cancellation, they do not)."""
        if (not CLOSED_FORM_MULTIPLIERS or not self.ON_V_SHORTCUTS or self.realization != "standard"
                or self.chart not in ("cayley", "equivariant") or not (self._field.exact or approx)
                or isinstance(self._field, SymbolicField) and self.chart == "cayley" and not self._field.native):
            return False
        return approx or (self.X.T @ self.X - self.Ir).is_zero()

    def _sym(self, M: Mat) -> Mat:
        return (M + M.T) * self.q(1, 2)

    def _triangular_multipliers(self, base: tuple[Mat, Mat],
                                direction: Callable[[str, Mat, Mat], tuple[Mat, Mat]]) -> tuple[Mat, Mat] | None:
        """Λ, Π for a Lagrange form whose Π moves X by −XΠ and whose Λ moves only P, by XΛ (the
        forms of (dot_XP) and of the twisted flow), where XᵀX = I holds exactly: Π from
        sym(XᵀẊ) = 0, then Λ from sym(ẊᵀP + XᵀṖ) = 0, each in closed form; the result is kept
        only when both conditions and the assumed shape of the Λ-direction hold exactly at the
        point (over an exact field; elsewhere None, and the r(r+1) system is solved)."""
        if isinstance(self._field, DegreeField) or not self._closed_form_applies(False):
            return None
        X, P, sym = self.X, self.P, self._sym
        Pi = sym(X.T @ base[0])
        dX, dP = direction("Pi", X @ Pi, P @ Pi)
        Xd, Pd = base[0] + dX, base[1] + dP
        T = Xd.T @ P + X.T @ Pd
        Lam = -sym(T)
        lX, lP = direction("Lambda", X @ Lam, P @ Lam)
        Pd = Pd + lP
        T = Xd.T @ P + X.T @ Pd
        if not (lX.is_zero() and sym(X.T @ Xd).is_zero() and (T + T.T).is_zero()):
            return None
        return Lam, Pi

    def _lyapunov_diagonal(self, m: list[Any], C: Mat) -> Mat | None:
        """The symmetric Y with diag(m) Y + Y diag(m) = C (C symmetric): Y_ij = C_ij / (m_i + m_j);
        None when some m_i + m_j vanishes (then the solution is not unique).  Over the exact field's
        flint backend, entry by entry there (see :meth:`_lyapunov_native`)."""
        native = self._lyapunov_native(m, C)
        if native is not NotImplemented:
            return native
        f = self._field
        r = len(m)
        Y = self.zeros(r, r, C.tags)
        c = C._a
        for i in range(r):
            for j in range(i, r):
                d = f.normalize(m[i] + m[j])
                if f.is_zero(d):
                    return None
                Y._a[i, j] = Y._a[j, i] = f.normalize(c[i, j] / d)
        return Y

    #: Y over one common denominator while its numerators stay below about this many terms (the
    #: terms of the entries times the monomials of a product of the other new factors m_i + m_j).
    #: 0: entry by entry always (a RatMat, back to one denominator where its entries share one),
    #: faster at every size measured (metric-flow, exact: (8,4) 0.04 s against 1.5 s, (10,4)
    #: 0.06 s against 3.2 s, (12,3) 0.16 s against 1.3 s); the tests force either representation
    _LYAPUNOV_COMMON = 0

    def _lyapunov_native(self, m: list[Any], C: Mat) -> Mat | None:
        """:meth:`_lyapunov_diagonal` where C is held by the exact field's flint backend (numerators
        over one denominator D, or entry by entry over their own, :class:`~stiefelsym.backends.ratmat.RatMat`):
        Y_ij = C_ij / (m_i + m_j) is formed in flint, each entry over its own denominator
        D_ij (m_i + m_j) (the factors of m_i + m_j registered once as atoms, the entry reduced
        exactly).  One common denominator for Y would be D times every distinct m_i + m_j,
        r(r+1)/2 of them: every numerator multiplied by all the others, a product of degree about
        r²/2 (beyond reach from r ≈ 6 on); so Y is kept entry by entry (a RatMat, whose sums and
        products stay in flint), over one denominator only below ``_LYAPUNOV_COMMON``.
        NotImplemented where C is not held that way (then the generic solve)."""
        be = backend(self._field)
        ring = getattr(be, "ring", None)
        if ring is None or not isinstance(self._field, SymbolicField):
            return NotImplemented
        from math import comb
        from stiefelsym.backends.polyfield import NODEN, NotRational, PolyMat, _merge_add, _merge_max, _minus
        from stiefelsym.backends.ratmat import RatMat, fix, make
        s = C._nat()
        if type(s) is not PolyMat and type(s) is not RatMat:
            return NotImplemented
        r = len(m)
        try:
            while True:                          # again if the flint context grew on the way
                v = ring.version
                sums = {(i, j): ring.from_se(self._field.normalize(m[i] + m[j]))
                        for i in range(r) for j in range(i, r)}
                if v == ring.version:
                    break
        except NotRational:
            return NotImplemented
        for (i, j), (num, den) in sums.items():
            if num.is_zero():
                return None
        if type(s) is PolyMat:
            s = be._fix(s)
            dens = None
        else:
            s = fix(be, s)
            dens = s.d
        ring = be.ring
        ys = {}
        for (i, j), (dn, dd) in sums.items():
            x = s.a[i, j]
            if x.is_zero():
                ys[i, j] = (ring.zero, NODEN)
                continue
            # C_ij / D_ij over (dn / dd) = C_ij dd / (c D_ij atoms), dn = c * prod atoms
            c, atoms = ring.factor(dn)
            num = (x * ring.den_poly(dd)) / c if dd else x / c
            ys[i, j] = ring.rf_reduce((num, _merge_add(s.den if dens is None else dens[i, j], atoms)))
        D = NODEN
        for y in ys.values():
            if y[1] and y[1] != D:
                D = _merge_max(D, y[1])
        Y = self.zeros(r, r, C.tags)
        k = len(_minus(D, s.den)) if dens is None else 0
        if dens is None and sum(len(y[0]) for y in ys.values()) * comb(max(k - 1, 0) + r - 1, r - 1) <= self._LYAPUNOV_COMMON:
            # few new factors: one common denominator (the backend's own representation); the
            # bound: every numerator times a product of k - 1 linear forms in the r values m_i
            a = np.empty((r, r), dtype=object)
            for (i, j), (num, d) in ys.items():
                a[i, j] = a[j, i] = num if d == D else num * ring.den_poly(_minus(D, d))
            Y._n = be._pm(a, D)
        else:
            a, d = np.empty((r, r), dtype=object), np.empty((r, r), dtype=object)
            for (i, j), (num, e) in ys.items():
                a[i, j] = a[j, i] = num
                d[i, j] = d[j, i] = e
            Y._n = make(be, a, d)
        return Y

    def _metric_closed_form_flow(self, HX: Mat, HP: Mat) -> Flow | None:
        """The Dirac flow of H on (cond_XP2) in closed form, where XᵀX = I_r and M = XᵀBX (B = A⁻¹)
        is diagonal exactly (the equivariant chart of the metric realization, see
        :meth:`_metric_inverse`).  The flow is Ω∇(H + ½⟨Π, F₂⟩ − ½⟨Λ, F₁⟩):

            Ẋ = H_P + BXΠ,   Ṗ = −H_X + XΛ − BPΠ,

        and the tangency conditions are two Lyapunov equations with the diagonal M, solved entrywise:
        MΠ + ΠM = −(XᵀH_P + H_PᵀX), then MΛ + ΛM = −(T + Tᵀ) with
        T = H_PᵀBP − XᵀBH_X + ΠK − KΠ, K = XᵀB²P.  (The tests compare it with the solved system.)
        None elsewhere."""
        if (not CLOSED_FORM_MULTIPLIERS or self._realization != "metric" or self._chart != "equivariant"
                or not self._field.exact):
            return None
        X, P, B = self.X, self.P, self.Ainv
        M = X.T @ B @ X
        r = self.r
        off = M - M                              # the off-diagonal part of M must vanish exactly
        off._a[:, :] = M._a
        for i in range(r):
            off._a[i, i] = self.const(0)
        if not ((X.T @ X - self.Ir).is_zero() and off.is_zero()):
            return None
        m = [M._a[i, i] for i in range(r)]
        Pi = self._lyapunov_diagonal(m, -(X.T @ HP + HP.T @ X))
        if Pi is None:
            return None
        BP = B @ P
        K = X.T @ B @ BP
        T = HP.T @ BP - X.T @ B @ HX + Pi @ K - K @ Pi
        Lam = self._lyapunov_diagonal(m, -(T + T.T))
        if Lam is None:
            return None
        return Flow(HP + B @ X @ Pi, -HX + X @ Lam - BP @ Pi)

    def dirac_flow(self, H: Function) -> Flow:
        """dz/dt = {z, H} for the Dirac bracket (Dirac_bracket), z = entries of X, P:
        ż = Ω∇H − Σ_i w_i Ω∇F_i with w = C {F, H}_0 (in closed form where
        :meth:`_closed_form_multipliers` or :meth:`_metric_closed_form_flow` applies)."""
        return self._cached_for("dflow", H, lambda: self._dirac_flow_of(H, *self.gradient(H)))

    def _graph_dirac_flow(self, H: Function, HX: Mat, HP: Mat) -> Flow:
        """The Dirac flow of H from the gradient (H_X, H_P) the graph computed (see
        :mod:`stiefelsym.ir.derivative`), as :meth:`dirac_flow` makes it from its own."""
        return self._cached_for("dflow", H, lambda: self._dirac_flow_of(H, HX, HP))

    def _dirac_flow_of(self, H: Function, HX: Mat, HP: Mat) -> Flow:
        """The body of :meth:`dirac_flow` for H's gradient (H_X, H_P)."""
        closed = self._cached_for("closed", H, lambda: self._closed_form_multipliers(HX, HP))
        if closed is not None:
            Lam, Pi = closed
            return Flow(HP - self.X @ Pi, -HX + self.X @ Lam + self.P @ Pi)
        metric = self._metric_closed_form_flow(HX, HP)
        if metric is not None:
            return metric
        Gs = self._constraint_gradients()
        zX, zP = self._pair_omega((HX, HP))
        FjH = [self._pair_dot(g, (zX, zP)) for g in Gs]
        if "C" in self._cache:
            w = [self._dot(Ci, FjH) for Ci in self._dirac_inverse()]
        else:                                # one right-hand side: solve, do not invert
            try:
                w = [row[0] for row in self._field.solve(self.constraint_bracket_matrix(), [[x] for x in FjH])]
            except DegenerateError as exc:
                raise DegenerateError("the constraint bracket matrix {F_i, F_j}_0 is singular here") from exc
        Xd, Pd = zX, zP
        for wi, (gX, gP) in zip(w, Gs):      # Ω∇F_i = (gP, −gX)
            Xd = Xd - gP * wi
            Pd = Pd + gX * wi
        return Flow(Xd, Pd)

    def _split(self, v: list[Scalar]) -> Flow:
        n, r = self.n, self.r
        Xd = self.zeros(n, r, ("n", "r"))
        Pd = self.zeros(n, r, ("n", "r"))
        Xd._a[:, :] = np.array(v[: n * r], dtype=object).reshape(n, r)
        Pd._a[:, :] = np.array(v[n * r:], dtype=object).reshape(n, r)
        return Flow(Xd, Pd)

    def multiplier_flow(self, H: Function) -> Flow:
        """(dot_XP): X' = H_P - X Pi, P' = -H_X + X Lambda + P Pi with symmetric
        Lambda, Pi solved from the condition that the constraints are preserved (an
        r(r+1)-dimensional linear system: the derivative of every scalar constraint along each
        unit multiplier direction).

        Raises DegenerateError when the multipliers are not unique."""
        def build():
            HX, HP = self.gradient(H)
            closed = self._cached_for("closed", H, lambda: self._closed_form_multipliers(HX, HP))
            Lam, Pi = closed if closed is not None else self._solve_multipliers(
                (HP, -HX), lambda name, XE, PE: (self.zeros(self.n, self.r, ("n", "r")), XE) if name == "Lambda"
                else (-XE, PE))
            Xd = HP - self.X @ Pi
            Pd = -HX + self.X @ Lam + self.P @ Pi
            return Flow(Xd, Pd, multipliers={"Lambda": Lam, "Pi": Pi})
        return self._cached_for("mflow", H, build)

    def _solve_multipliers(self, base: tuple[Mat, Mat], direction: Callable[[str, Mat, Mat], tuple[Mat, Mat]],
                           what: str = "the multipliers Lambda, Pi") -> tuple[Mat, Mat]:
        """Symmetric Λ, Π such that base + Σ Λ_ij u_ij + Σ Π_ij v_ij is tangent to the constraint set:
        an r(r+1)-dimensional linear system, one unknown per unit symmetric E_ij, whose direction
        ``direction(name, X E_ij, P E_ij)`` (a pair (δX, δP)) the flow's form gives.  Where the
        triangular solve of :meth:`_triangular_multipliers` applies and its result is verified
        exactly, that instead."""
        fast = self._triangular_multipliers(base, direction)
        if fast is not None:
            return fast
        r = self.r
        Gs = self._constraint_gradients()
        units = []
        for name in ("Lambda", "Pi"):
            for i in range(r):
                for j in range(i, r):
                    E = self.zeros(r, r, ("r", "r"))
                    E._a[i, j] = E._a[j, i] = self.const(1)
                    units.append((name, i, j, direction(name, self.X @ E, self.P @ E)))
        M = [[self._pair_dot(g, u[3]) for u in units] for g in Gs]
        b = [[-self._pair_dot(g, base)] for g in Gs]
        try:
            sol = self._field.solve(M, b)
        except DegenerateError as exc:
            raise DegenerateError(f"{what} are not unique here") from exc
        Lam = self.zeros(r, r, ("r", "r"))
        Pi = self.zeros(r, r, ("r", "r"))
        for (name, i, j, _v), (c,) in zip(units, sol):
            target = Lam if name == "Lambda" else Pi
            target._a[i, j] = target._a[j, i] = c
        return Lam, Pi

    def _gradient_pair(self, HX: Mat, HP: Mat) -> tuple[Mat, Mat]:
        """A gradient (∂H/∂X, ∂H/∂P) the graph computed, handed on as :meth:`gradient` hands its own:
        n x r matrices of the scene (see :mod:`stiefelsym.ir.derivative`)."""
        return self._as_nr(HX), self._as_nr(HP)

    def _approximates_point(self) -> bool:
        """Floats, balls or degree markers: values that stand for the exact evaluation at the chart's
        point, which is on V by construction (see :meth:`_closed_form_multipliers`).  False at a point a
        claim gave (:attr:`_point_given`): what stands there for the exact evaluation is the solved system."""
        if self._point_given:
            return False
        return isinstance(self._field, (FloatField, DegreeField)) or getattr(self._field, "encloses_exact_point", False)

    def _graph_flows(self) -> frozenset:
        """The flows of a Hamiltonian the graph may compute on this scene (see
        :mod:`stiefelsym.ir.derivative`): the canonical flow (H_P, −H_X) always; the Dirac and
        multiplier flows and the Dirac bracket where the multipliers have the closed forms of
        :meth:`_closed_form_multipliers`, decided without building the point (so parameters are
        drawn in the order the claim uses them); XᵀX = I_r is checked exactly when the flow is handed
        on (:meth:`_graph_flow`).  The magnetic systems' flows and brackets take the graph's gradients
        on every coordinate scene (their multipliers stay the engine's), and so do the derivatives and flows at
        points of the caller's own (:mod:`stiefelsym.systems`); on the metric realization the Dirac flow takes
        the graph's gradient of H (its multipliers the scene's: :meth:`_graph_dirac_flow`)."""
        from stiefelsym.ir.derivative import GRADIENT_FLOW, SYSTEMS, TWISTED, TWISTED_NODES
        kinds = {"canonical_flow", TWISTED, SYSTEMS}
        if self.realization == "metric":
            kinds.add(GRADIENT_FLOW)
        if self.realization == "standard" and not isinstance(self, _LiftedScene):
            kinds.add(TWISTED_NODES)    # (cond_XP)'s constraint gradients in closed form: brackets of brackets
        approx = self._approximates_point()
        if (CLOSED_FORM_MULTIPLIERS and self.ON_V_SHORTCUTS and self.realization == "standard"
                and self.chart in ("cayley", "equivariant") and (self._field.exact or approx)
                and not (isinstance(self._field, SymbolicField) and self.chart == "cayley" and not self._field.native)):
            kinds |= {"dirac_flow", "multiplier_flow", "bracket"}
        return frozenset(kinds)

    def _graph_flow(self, kind: str, H: Function, Xd: Mat, Pd: Mat, Lam: Mat | None, Pi: Mat | None) -> Flow:
        """A flow of H the graph computed (``kind``: canonical_flow, dirac_flow or multiplier_flow),
        handed on as the scene's own method hands it: the Dirac flow without its multipliers, the
        multiplier flow with Λ, Π.  The closed forms hold where XᵀX = I_r: checked exactly over an
        exact field (a chart's point is on V by construction; elsewhere the scene's own flow)."""
        if kind != "canonical_flow":
            if self._point_given and not self._field.exact:
                return getattr(self, kind)(H)       # a given point: no approximate test of XᵀX = I_r decides
            on_V = lambda: self.ON_V_SHORTCUTS and (self.X.T @ self.X - self.Ir).is_zero()      # noqa: E731
            if not self._approximates_point() and not self._cached("on V", on_V):
                return getattr(self, kind)(H)
        if kind == "multiplier_flow":
            return Flow(Xd, Pd, multipliers={"Lambda": Lam, "Pi": Pi})
        return Flow(Xd, Pd)

    def _tangent_vector(self, flow: Flow | Mapping[str, Mat], keys: tuple) -> dict[str, Mat]:
        """The components ``keys`` of a flow, checked as :meth:`tangent` checks a flow, each with the
        spaces of the primitive it moves (0 where the flow does not move it): what the graph's
        derivatives along the flow read (see :mod:`stiefelsym.ir.derivative`)."""
        tangent = flow.tangent() if isinstance(flow, Flow) else dict(flow)
        checked = _checked_tangent(self, tangent)
        out = {}
        for key in keys:
            prim = getattr(self, key)
            v = checked.get(key)
            if v is None:
                v = Mat.zeros(*prim._shape(), self._field, prim.tags, self.tracker)
            elif v.tags != prim.tags or v._coords != prim._coords:
                v = v._retyped(v._field, prim.tags, self.tracker)
            v._coords = prim._coords
            out[key] = v
        return out

    def d(self, F: Function, flow: Flow | Mapping[str, Mat]) -> Any:
        """The derivative of F (a function of the scene) along a flow."""
        tangent = flow.tangent() if isinstance(flow, Flow) else dict(flow)
        ts = self.tangent(tangent)
        value = _derivative_part(F(ts), self, getattr(ts, "under", self._field))
        return _opaque(self, value)


class CoordinateAccess(ValueError):
    """Raised when a chart cannot provide a coordinate object."""


class PointRead(Exception):
    """Raised when a graph evaluated on the diagonal chart (A = diag(a), O(n) spent on A) reads a point."""


class _LiftedScene(Scene):
    """The scene over a field built on the base scene's field (duals, reverse numbers): every
    primitive is the base scene's, lifted by :meth:`_lift_primitive`."""

    def _lift_primitive(self, M: Any, key: str | None) -> Any:
        raise NotImplementedError

    def _param(self, name: str) -> Scalar:
        return self._lift_primitive(self.base._param(name), None)

    def _point(self):
        def build():
            X, P = self.base._point()
            return self._lift_primitive(X, "X"), self._lift_primitive(P, "P")
        return self._cached("point", build)

    @property
    def P(self) -> Mat:
        self._momenta_read()
        return self._point()[1]

    @property
    def Y(self) -> Mat:
        return self._cached("Y", lambda: self._lift_primitive(self.base.Y, "Y"))

    @property
    def Q(self) -> Mat:
        return self._cached("Q", lambda: self._lift_primitive(self.base.Q, "Q"))

    @property
    def A(self) -> Mat:
        return self._cached("A", lambda: self._lift_primitive(self.base.A, None))

    @property
    def Zc(self) -> Mat:
        return self._cached("Zc", lambda: self._lift_primitive(self.base.Zc, "Zc"))

    @property
    def Zc_dot(self) -> Mat:
        return self._cached("Zc_dot", lambda: self._lift_primitive(self.base.Zc_dot, "Zc_dot"))

    @property
    def Ainv(self) -> Mat:
        return self._cached("Ainv", lambda: self._lift_primitive(self.base.Ainv, None))

    def _double_base(self) -> Mat:
        return self._cached("double base", lambda: self._lift_primitive(self.base._double_base(), None))

    @property
    def a(self):
        xs = self._cached("a", lambda: self._lift_primitive(self.base.a, None))
        return _opaque(self, xs)

    def _cached(self, key, build):
        return Scene._cached(self, key, build)

    def sym_operator(self, name: str = "AA"):
        """The base scene's operator (the same parameters), its coefficients lifted to this field;
        over reverse numbers, see :meth:`_reverse_operator_apply`.  On so(r) likewise."""
        def on(space: str):
            basis, coeffs = self.base._operator_coefficients(name, space)
            key = f"op:{name}" if space == "n" else f"op:{name}@so(r)"
            lifted = self._cached(key, lambda: self._lift_primitive(coeffs, None))
            generic = self._operator_apply(basis, lifted, space)
            if isinstance(self._field, RevField):
                return self._reverse_operator_apply(self.base._operator_apply(basis, coeffs, space), generic, space)
            return generic
        return _on_its_space(on("n"), lambda: on("r"))

    def _reverse_operator_apply(self, base_apply, generic, space: str = "n"):
        """The operator on the tape of reverse mode as one node: its value is the base scene's
        operator applied to the value, and its adjoint g -> AA(g), since AA is self-adjoint for the
        Frobenius pairing (<g, AA(xi)> = 2 c(g)ᵀ C c(xi) = <AA(g), xi>, c the skew coordinates and
        C the symmetric coefficient matrix).  A matrix of another field takes the generic path."""
        from stiefelsym.backends.reverse import linear as rev_linear

        def apply(xi: Mat) -> Mat:
            if not isinstance(xi, Mat) or xi._field is not self._field:
                return generic(xi)
            unify(xi.tags[0], space, f"the operator on so({space})", xi.tracker)
            unify(xi.tags[1], space, f"the operator on so({space})", xi.tracker)
            s = xi._nat()
            out = rev_linear(s, base_apply(s.v)._untyped(), lambda g: base_apply(g)._untyped())
            return Mat._wrap_native(out, self._field, (space, space), xi.tracker, xi._coords)
        return apply

    def generic(self, name, m, k, kind="general"):
        return self._cached(f"gen:{name}[{m}x{k}]{check_generic_kind(m, k, kind)}",
                            lambda: self._lift_primitive(self.base.generic(name, m, k, kind), None))

    def fresh(self, *args):
        if len(args) == 2:
            return self._lift_primitive(self.base.fresh(*args), None)
        return self._cached(f"{FRESH}{args}", lambda: self._lift_primitive(self.base.fresh(*args), None))

    def _skew_params(self, name, m, tag):
        return self._lift_primitive(self.base._skew_params(name, m, tag), None)

    def _sym_params(self, name, m, tag):
        return self._lift_primitive(self.base._sym_params(name, m, tag), None)

    def _general_params(self, name, m, k, tags):
        return self._lift_primitive(self.base._general_params(name, m, k, tags), None)

    def _engine_params(self, tag, m, k, tags=("?", "?")):
        return self._lift_primitive(self.base._engine_params(tag, m, k, tags), None)


class TangentScene(_LiftedScene):
    """The scene with primitives X, P (and any others in the flow) perturbed by ε·flow."""

    def __init__(self, base: Scene, flow: Mapping[str, Mat]) -> None:
        self.base = base
        flow = _checked_tangent(base, flow)
        #: the field the dual numbers of this scene are built over: the base scene's, or, for a flow made of
        #: values of a scene inside the base scene's function (t.d along u.X, u a scene of a function inside
        #: t's), that scene's field, so that this scene's ε is a level of its own above every level the flow
        #: carries (the flow's ε is never taken for this one's); the base scene's primitives are lifted to it
        #: as constants of the levels they lack
        self.under = _flow_field(base, flow)
        if self.under is not base._field:
            flow = {k: _lifted_to(v, self.under, base.tracker, f"the {k}-component of a tangent vector")
                    for k, v in flow.items()}
        self.flow = flow
        super().__init__(base.n, base.r, DualField(self.under), chart=base.chart, rng=base._rng,
                         component=base.component, realization=base.realization,
                         options=base._options, tracker=base.tracker)
        self._params, self._param_blocks = base._params, base._param_blocks

    def _lift_primitive(self, M: Any, key: str | None) -> Any:
        return self._lift(M, self.flow.get(key) if key is not None else None)

    @property
    def lam(self) -> Scalar:
        """The spectral parameter lambda, lifted once per tangent scene (a constant: derivative 0)."""
        x = self._cached("param:lambda", lambda: self._param("lambda"))
        return _number(self, x)

    @property
    def kappa(self) -> Scalar:
        """The parameter kappa, lifted once per tangent scene (a constant: derivative 0)."""
        x = self._cached("param:kappa", lambda: self._param("kappa"))
        return _number(self, x)

    @property
    def Phi(self) -> Mat:
        """Phi over the dual numbers of an exact field: the base scene's Phi (not recomputed) with
        the derivative B' - B'^T, B' = P' X^T + P X'^T (P', X' the flow's; a missing one is 0)."""
        b = self.base
        dX, dP = self.flow.get("X"), self.flow.get("P")
        if (not self._field.exact or self.under is not b._field
                or any(v is not None and v._field is not b._field for v in (dX, dP))):
            return PaperObjects.Phi.fget(self)

        def build():
            X, P = b.X, b.P
            parts = ([dP @ X.T] if dP is not None else []) + ([P @ dX.T] if dX is not None else [])
            dot = None
            if parts:
                Bd = parts[0] if len(parts) == 1 else parts[0] + parts[1]
                dot = Bd - Bd.T
            return b.Phi._dual(dot, self._field, self.tracker)
        return self._cached("Phi", build)

    def _lift(self, M: Any, dot: Mat | None = None) -> Any:
        under = self.under
        if isinstance(M, Mat):
            if M._field is not under:
                M = _lifted_to(M, under, self.tracker, "a primitive of the scene")
            return M._dual(dot, self._field, self.tracker)
        if isinstance(M, list):
            return [self._lift(x) for x in M]
        if isinstance(M, tuple):
            return tuple(self._lift(x) for x in M)
        if callable(M):
            return M
        if under is not self.base._field:
            M = under.lift(M)
        return Dual(M, under.const(0))


class ConstantScene(_LiftedScene):
    """The base scene's problem over a field built on the base scene's own (the numbers of a scene inside a
    function of it, some dual levels deeper): every primitive of the base scene a constant there, with a zero part
    at each level it lacks.  The problem at a point given by values of such a scene (twisted.at_point) is taken
    on it, so that the point's derivative parts stay in their levels and a derivative taken there gets a level
    of its own above them."""

    def __init__(self, base: Scene, field: Field) -> None:
        self.base = base
        super().__init__(base.n, base.r, field, chart=base.chart, rng=base._rng, component=base.component,
                         realization=base.realization, options=base._options, tracker=base.tracker)
        self._params, self._param_blocks = base._params, base._param_blocks

    def _lift_primitive(self, M: Any, key: str | None) -> Any:
        if isinstance(M, Mat):
            return M if M._field is self._field else _lifted_to(M, self._field, self.tracker, "a primitive of the scene")
        if isinstance(M, list):
            return [self._lift_primitive(x, None) for x in M]
        if isinstance(M, tuple):
            return tuple(self._lift_primitive(x, None) for x in M)
        if callable(M):
            return M
        return self._field.lift(M)


class ReverseScene(_LiftedScene):
    """The scene over reverse numbers: X and P are the independent variables of a tape, every
    other primitive a constant (used for gradients, see :mod:`.reverse`)."""

    def __init__(self, base: Scene) -> None:
        self.base = base
        super().__init__(base.n, base.r, RevField(base._field), chart=base.chart, rng=base._rng,
                         component=base.component, realization=base.realization,
                         options=base._options, tracker=base.tracker)
        self._params, self._param_blocks = base._params, base._param_blocks
        self.leaves: dict[str, RevMat] = {}

    def _lift_primitive(self, M: Any, key: str | None) -> Any:
        if isinstance(M, Mat):
            # the tape's values are untyped and unrecorded: the types are checked (and coordinate
            # reads recorded) on the matrices of this scene, which carry M's spaces
            v = M._untyped()
            if key in ("X", "P"):
                s = self.leaves.setdefault(key, rev_leaf(v))
            else:
                s = RevMat(v)
            return Mat._wrap_native(s, self._field, M.tags, self.tracker, M._coords)
        if isinstance(M, list):
            return [self._lift_primitive(x, None) for x in M]
        if isinstance(M, tuple):
            return tuple(self._lift_primitive(x, None) for x in M)
        if callable(M):
            return M
        return Rev(M)

    def tangent(self, flow):
        raise Unsupported("a derivative along a flow inside a gradient")


#: the primitives a flow or tangent vector may move, and the scene objects they perturb
TANGENT_KEYS = ("X", "P", "Y", "Q", "Zc", "Zc_dot")


def _checked_tangent(base: Scene, flow: Mapping[str, Any]) -> dict[str, Mat]:
    """A tangent vector: each component a matrix of the type of the primitive it moves.
    An untyped component meeting R^n is recorded, like any other untyped matrix."""
    out = {}
    for key, v in dict(flow).items():
        if key not in TANGENT_KEYS:
            raise TraceRefused(f"a tangent vector moves {', '.join(TANGENT_KEYS)}, not {key!r}")
        if not isinstance(v, Mat):
            raise TypeError(f"the {key}-component of a tangent vector must be a matrix")
        prim = getattr(base, key)
        if v._shape() != prim._shape():
            raise ValueError(f"the {key}-component of a tangent vector has shape {v._shape()}, "
                             f"{key} has {prim._shape()}")
        for t, p in zip(v.tags, prim.tags):
            if t != p:
                unify(t, p, f"the {key}-component of a tangent vector", base.tracker)
        if v._coords:
            base.tracker.touch("matrices built entrywise")
        out[key] = v if v._field is base._field else _at_level_of(v, base, key)
    return out


def _at_level_of(v: Mat, base: Scene, key: str) -> Mat:
    """A component ``v`` of a tangent vector of ``base`` that is a value of an enclosing scene (a function's scene
    of fewer dual levels: the outer point t.X handed to a derivative inside a function of u), as a matrix of
    ``base``'s numbers, with a zero part at each level it lacks.  Taken as it is, the parts of its own levels
    would be read as the parts of base's (t.X = X + ε₁U as X + ε₂U).  A value of a scene inside base's (a
    derivative on the claim's scene along a flow of a function's scene) is left as it is; one of neither (a
    sibling scene's) is refused."""
    if _built_over(v._field, base._field):
        return v        # a value of a scene inside base's (a flow that moves with an enclosing derivative): the
        #                 tangent scene is built over its field (see TangentScene.under)
    if not _built_over(base._field, v._field):
        raise TypeError(f"the {key}-component of a tangent vector is a value of a scene that does not enclose "
                        "the one it moves (a flow must be made of values of its own scene or of an enclosing one)")
    return _lifted_to(v, base._field, base.tracker, f"the {key}-component of a tangent vector")


def _built_over(f: Any, g: Any) -> bool:
    """Whether the field f is g or a field built over g (its base, or its base's base, ...)."""
    while f is not None:
        if f is g:
            return True
        f = getattr(f, "base", None)
    return False


def _lifted_to(v: Mat, field: Any, tracker: Any, what: str) -> Mat:
    """The matrix v of a field below ``field`` (``field`` is built over v's, through dual levels) as a matrix of
    ``field``'s numbers: a constant, with a zero part at each level v lacks."""
    chain = []
    f = field
    while f is not v._field:
        if not isinstance(f, DualField):
            raise TypeError(f"{what} is a value of another scene's numbers (not a derivative level below this one's)")
        chain.append(f)
        f = f.base
    for f in reversed(chain):
        v = v._dual(None, f, tracker)
    return v


def _flow_field(base: Scene, flow: Mapping[str, Mat]) -> Any:
    """The field a tangent scene of ``base`` along ``flow`` is built over: base's own, or the highest field among
    the flow's components that is built over base's (values of scenes inside base's function), which must then
    hold every other component's field (one chain of levels: components of two sibling scenes are refused)."""
    top = base._field
    for key, v in flow.items():
        f = v._field
        if f is top or _built_over(top, f):
            continue
        if _built_over(f, top):
            top = f
            continue
        raise TypeError(f"the {key}-component of a tangent vector is a value of a scene on another chain of derivative "
                        "levels than the other components' (a flow must be made of values of one scene and of "
                        "scenes enclosing it)")
    return top


def _on_its_space(on_n: Callable[[Mat], Mat], make_on_r: Callable[[], Callable[[Mat], Mat]]) -> Callable[[Mat], Mat]:
    """An operator named once, acting on so(n), and on so(r) for an r×r argument (both index spaces
    ℝʳ): the operator on so(r) is made on its first use."""
    on_r: list = []

    def apply(xi: Mat) -> Mat:
        if isinstance(xi, Mat) and xi.tags[0] == "r" and xi.tags[1] == "r":
            if not on_r:
                on_r.append(make_on_r())
            return on_r[0](xi)
        return on_n(xi)
    return apply


#: the number of engine checks in progress (:func:`engine_check`): the depth at which a check draws its symbols
ENGINE_CHECK_DEPTH = [0]


@contextlib.contextmanager
def engine_check() -> Iterator[None]:
    """While an engine step's check evaluates a claim's function at parameters of the engine's own (drawn
    before): a check nested in that function draws parameters of another depth (see
    :meth:`Scene._engine_params`, :meth:`.free.FreeScene._engine_letters`)."""
    ENGINE_CHECK_DEPTH[0] += 1
    try:
        yield
    finally:
        ENGINE_CHECK_DEPTH[0] -= 1


def so_basis(n: int) -> list[tuple[int, int]]:
    """Index pairs (i, j), i < j, of the orthonormal basis E_i ∧ E_j of so(n) for <,>."""
    return [(i, j) for i in range(n) for j in range(i + 1, n)]


def _flatten_value(v: Any, symmetric_lists: bool) -> list[Any]:
    if isinstance(v, Mat):
        if symmetric_lists:
            m = v._a.shape[0]
            return [v._a[i, j] for i in range(m) for j in range(i, m)]
        return list(v._a.flat)
    if isinstance(v, (list, tuple)):
        out = []
        for x in v:
            out.extend(_flatten_value(x, symmetric_lists))
        return out
    return [v]


def _derivative_part(v: Any, scene: Scene, field: Any = None) -> Any:
    """The ε-part of a value over the dual numbers built over ``field`` (the scene's own by default; see
    TangentScene.under) (a Mat, a scalar, or a dict/list/tuple of them): whole matrices natively where the dual
    backend holds them."""
    field = scene._field if field is None else field
    if isinstance(v, Mat) and v._n is not None and type(v._n) is tuple and getattr(v._field, "base", None) is field:
        return Mat._wrap_native(v._n[1], field, v.tags, scene.tracker, v._coords)
    if isinstance(v, dict):
        return {k: _derivative_part(x, scene, field) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return type(v)(_derivative_part(x, scene, field) for x in v)
    return map_entries(v, lambda x: x.b if isinstance(x, Dual) else field.const(0), scene, field)


def map_entries(v: Any, f, scene: Any, field: Any = None) -> Any:
    """Apply f to every entry of a value (a Mat, a scalar, or a dict/list/tuple of them); the matrices of the
    result are of ``field`` (the scene's by default)."""
    field = scene._field if field is None else field
    if isinstance(v, Mat):
        a = np.empty(v._a.shape, dtype=object)
        for idx, x in np.ndenumerate(v._a):
            a[idx] = f(x)
        return Mat._wrap(a, field, v.tags, scene.tracker, v._coords)
    if isinstance(v, dict):
        return {k: map_entries(x, f, scene, field) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return type(v)(map_entries(x, f, scene, field) for x in v)
    return f(v)


_UPPER_MASKS: dict[tuple[int, int], Any] = {}


def _upper_mask(m: int, k: int) -> Any:
    """The boolean mask of the entries (i, j) with j >= i + k of an m x m matrix (kept per size)."""
    mask = _UPPER_MASKS.get((m, k))
    if mask is None:
        if len(_UPPER_MASKS) > 64:
            _UPPER_MASKS.clear()
        mask = _UPPER_MASKS[(m, k)] = np.triu(np.ones((m, m), dtype=bool), k)
    return mask


def _diagonal(s: "Scene", values: list) -> Mat:
    r = len(values)
    return s.mat([[values[i] if i == j else s.q(0) for j in range(r)] for i in range(r)], ("r", "r"))


def double_point_of(s: "Scene") -> dict[str, Mat]:
    """The generic point of :func:`double_point` of a coordinate scene.

    X = X₀DU with X₀ a point of V(n, r) of its own (:meth:`Scene._double_base`), D diagonal and U unipotent upper triangular
    (every X of rank r, by the QR decomposition), Y = X₀D⁻¹U⁻ᵀ + (I − X₀X₀ᵀ)Z, Ẋ = V generic,
    Ẏ = −Y VᵀY + (I − YXᵀ)W: every point of a dense open subset of the constraint set."""
    r = s.r
    # parameters of the engine's names (s.scalar, s.general_params name the claim's own: a claim's
    # s.scalar("double_d1") was the D of this point)
    d = [_number(s, s._param(f"double_d{i + 1}")) for i in range(r)]
    N = [[_number(s, s._param(f"double_u{i + 1}_{j + 1}")) if j > i else s.q(0) for j in range(r)] for i in range(r)]
    U = s.mat([[s.q(1) if i == j else N[i][j] for j in range(r)] for i in range(r)], ("r", "r"))
    Nm = s.mat(N, ("r", "r"))
    Uinv, power = s.Ir, s.Ir
    for _ in range(r - 1):
        power = power @ (-Nm)
        Uinv = Uinv + power
    X0 = s._double_base()
    X = X0 @ _diagonal(s, d) @ U
    Y = (X0 @ _diagonal(s, [s.q(1) / x for x in d]) @ Uinv.T
         + (s.In - X0 @ X0.T) @ s._general_params("double_Z", s.n, r, ("n", "r")))
    V = s._general_params("double_V", s.n, r, ("n", "r"))
    W = s._general_params("double_W", s.n, r, ("n", "r"))
    return {"X": X, "Y": Y, "Xdot": V, "Ydot": -(Y @ V.T @ Y) + (s.In - Y @ X.T) @ W}
