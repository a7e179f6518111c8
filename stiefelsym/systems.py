"""Phase spaces beyond T*V(n, r): Lagrangian systems with holonomic constraints, Hamiltonian
flows on products of cotangent bundles with several constraint sets, and the complex Stiefel
variety W(n, r) through its realification.

Everything here is *derived*, never typed in.  A system is given by functions of a scene ``t``
and of a point ``z`` (a dict of named matrices): a Lagrangian T(t, v) − U(t, q) or a Hamiltonian
H(t, z), and its holonomic constraints (scalar functions, independent).  The flow is computed
in coordinates along a basis of the ambient space of each matrix variable:

* :func:`euler_lagrange`: d/dt ∂L/∂q̇ = ∂L/∂q + Σ μ_j ∂g_j/∂q for L = T(q̇) − U(q), T a quadratic
  form in the velocities with constant coefficients (as for (D-Lag) and (W-Lag)), whose matrix
  is obtained by polarization, with the multipliers μ solved from the second derivative of the
  constraints, d²g/dt² = Dg·q̈ + D²g(q̇, q̇) = 0.
* :func:`hamiltonian_flow`: ż = Ω∇H + Σ μ_i Ω∇F_i on the product of the cotangent bundles of
  the named (position, momentum) pairs, the multipliers solved from dF_j/dt = 0: the Dirac flow
  of H for all the constraints together.

Derivatives are exact over every field of the scene, and the points are built by the caller
(generic points of the constraint set).  The gradients a flow needs (of H and of every scalar
constraint; of U, of the constraints, and of T at each basis vector) come from reverse mode over the
matrix operations (:mod:`.reverse`): one evaluation of the function over reverse numbers, the
point's variables being the leaves of the tape, and one backward sweep per scalar component.  Where
reverse mode has no adjoint for an operation (it raises ``Unsupported``), one forward pass (dual
numbers) per coordinate gives the same numbers.  In a claim's graph on a coordinate scene these
derivatives and gradients are graph nodes (:mod:`stiefelsym.ir.derivative` rewrites the steps into the
``graph_*`` steps below, which take them), and the constraints of a pair of Stiefel points have their
gradients in closed form.  The gradients are then stacked by rows, and the
linear algebra is whole-matrix: the constraint bracket matrix is one product G_x G_pᵀ − G_p G_xᵀ,
the multipliers one solve, the flow one product with the stacked gradients.

The coordinates are an orthogonal basis of each variable's space (the unit matrices E_ij, and
E_ij, iE_ij for a realified complex variable), the coordinates of a gradient are its inner
products with the basis (for the unit matrices, its entries), and a flow is reassembled in the
basis it was computed in, so the result does not depend on the basis: a flow derived from
O(n)-invariant data is O(n)-covariant, and these internal coordinates are not recorded as a look at
coordinates (like the scene's own gradients).  Only coordinate backends run these functions: the
dimension-free scene raises ``NeedsCoordinates``.

Engine internals used (an engine module may): ``Scene._unit_tangents`` (the unit matrices E_ij, not
recorded), ``TangentScene._lift`` (a matrix of the scene's field with a given derivative), so that
points of the caller's own move along tangent vectors of the caller's own, and ``ReverseScene``
with the tape of :mod:`.reverse`, whose leaves here are the variables of such a point (the
realification and the conjugate are operations of that tape, with their adjoints).

Complex matrices U + iV are realified as [[U, −V], [V, U]] (``Scene.realify``): sums, products
and the conjugate transpose (the transpose of the real form) are preserved; the plain transpose
Zᵀ is ``ctranspose``, the conjugate Z̄ is ``Scene.conj``.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable, Hashable, Mapping, Sequence

import numpy as np

from stiefelsym import scene as scene_module
from stiefelsym.ir.derivative import CONSTANT_ATTRS, NUMERIC_CALLS
from stiefelsym.ir.trace import PRIMITIVES, STEP_GRAPH_CHECKS, TraceRefused, TraceScene, primitive
from stiefelsym.backends.matrix import Mat, NeedsCoordinates, _coordinates, _refused, backend, block, definite
from stiefelsym.backends.reverse import Node, Rev, RevMat, Unsupported, gradient as rev_gradient, leaf as rev_leaf
from stiefelsym.scene import double_point_of, HermitianComponents, ReverseScene, Scene, _LiftedScene

Point = Mapping[Hashable, Mat]
Coordinates = Sequence[tuple[Hashable, Mat]]

__all__ = ["derivative", "entries", "symmetric_entries", "hermitian_entries", "real_coordinates",
           "complex_coordinates", "euler_lagrange", "hamiltonian_flow", "stiefel_pairs_flow", "double_point", "coupled_point",
           "complex_point", "real_complex_point", "ctranspose", "realify_real", "re_trace", "complex_diagonal"]


def _check_tangent(point: Mapping, tangent: Mapping) -> None:
    """A tangent vector at a point of the caller's own: it moves only the point's variables, each
    component a matrix of its variable's shape."""
    extra = set(tangent) - set(point)
    if extra:
        raise TraceRefused(f"a tangent vector moves the variables of the point, not {sorted(map(str, extra))}")
    for k, v in tangent.items():
        if not isinstance(v, Mat) or v.shape != point[k].shape:
            raise ValueError(f"the {k}-component of a tangent vector must be a matrix of the shape of {k}")


def _coordinate_scene(s: Any, what: str) -> None:
    if isinstance(s, TraceScene):
        if s._t.symbolic:
            s._t.refuse(f"{what} needs coordinates (fixed n, r)")
        return
    if not isinstance(s, Scene):
        raise _refused(getattr(s, "_tracker", None), what)   # recorded before it is raised


# -- derivatives at points of the caller's own --------------------------------------------------

def derivative(s: Scene, F: Callable[[Scene, dict], Any], point: Point, tangent: Mapping[Hashable, Mat]) -> Any:
    """d/dε F(t, point + ε·tangent) at ε = 0, exactly (components of ``tangent`` not given are 0).

    ``F`` is a function of a scene and of a point (a dict of matrices of the shapes of ``point``);
    its value is a scalar, a matrix, or a list/dict of them."""
    if not isinstance(s, (Scene, TraceScene)) and hasattr(s, "derivative_at_own_point"):
        return s.derivative_at_own_point(F, point, tangent)   # the dimension-free scene, at its own point
    _coordinate_scene(s, "a derivative at a point of a phase space other than T*V")
    _check_tangent(point, tangent)

    def lifted(t):
        z = {k: t._lift(M, tangent.get(k)) for k, M in point.items()}
        return F(t, z)
    return s.d(lifted, {})


def entries(M: Mat) -> list[Any]:
    """All entries of a matrix (independent scalar constraints), row by row."""
    m, k = M.shape
    return [M[i, j] for i in range(m) for j in range(k)]


def symmetric_entries(M: Mat) -> list[Any]:
    """The upper triangle of a symmetric matrix (its independent entries)."""
    m, _ = M.shape
    return [M[i, j] for i in range(m) for j in range(i, m)]


def hermitian_entries(M: Mat) -> list[Any]:
    """The independent real components of a realified Hermitian r×r matrix U + iV (U symmetric,
    V skew): the upper triangle of U and the strict upper triangle of V."""
    if isinstance(M, Mat) and not _coordinates(M._field):
        return HermitianComponents(M)   # type: ignore[return-value]
    m = M.shape[0] // 2
    return ([M[i, j] for i in range(m) for j in range(i, m)]
            + [M[m + i, j] for i in range(m) for j in range(i + 1, m)])


# -- coordinates ------------------------------------------------------------------------------

class _UnitCoordinates(list):
    """The coordinates of :func:`real_coordinates`: (name, E_ij) for each name, E_ij in row-major
    order, so that the coordinates of a matrix along them are its entries, row by row (no
    product with the basis is needed)."""

    def __init__(self, items, names: Sequence[Hashable], shape: tuple[int, int]) -> None:
        super().__init__(items)
        self.names, self.shape = list(names), shape
        self._made = [(name, id(E)) for name, E in items]

    def intact(self) -> bool:
        """Whether the list still holds the unit matrices it was made with (a list can be edited)."""
        return [(name, id(E)) for name, E in self] == self._made


class _ComplexCoordinates(list):
    """The coordinates of :func:`complex_coordinates`: (name, realify(E_ij, 0)) and (name, realify(0, E_ij))."""

    def __init__(self, items) -> None:
        super().__init__(items)
        self._made = [(name, id(E)) for name, E in items]

    def intact(self) -> bool:
        return [(name, id(E)) for name, E in self] == self._made


def _engine_coordinates(coords: Any, what: str) -> None:
    """Refuse coordinates other than the engine's own, unedited: the steps take them for a basis that spans the
    variables' space and is orthonormal (real) or of equal norms (complex), the same for positions and momenta,
    which a list of the claim's own need not be (one left out, one scaled: the solve of other equations)."""
    if not (isinstance(coords, (_UnitCoordinates, _ComplexCoordinates)) and coords.intact()):
        raise ValueError(f"{what}: the coordinates must be the engine's, systems.real_coordinates or "
                         "systems.complex_coordinates of the variables, as they were made (the step takes them for "
                         "a basis that spans, orthonormal, the same for positions and momenta)")


def _units(s: Scene) -> list[Mat]:
    """The unit n×r matrices E_ij (an orthonormal basis of M_{n,r}(ℝ))."""
    nr = s.n * s.r
    return [u["X"] for k, u in enumerate(s._unit_tangents()) if k < nr]


class _FreeCoordinates(tuple):
    """What the dimension-free scene has for the coordinates of matrix variables: none (the steps that
    take them solve in the free algebra or refuse).  A claim that reads one of them (``coords[0]``) needs
    coordinates: :class:`NeedsCoordinates` (``undecided``), as every other look at coordinates."""

    def __getitem__(self, index: Any) -> Any:
        raise NeedsCoordinates("a coordinate of a matrix variable (systems.real_coordinates)")


FREE_COORDINATES = _FreeCoordinates()
#: the same for realified complex matrix variables (the free scene's Euler–Lagrange equations on W(n, r))
FREE_COMPLEX_COORDINATES = _FreeCoordinates()


def real_coordinates(s: Scene, names: Sequence[Hashable]) -> list[tuple[Hashable, Mat]]:
    """The coordinates of n×r real matrix variables: (name, E_ij) for each name."""
    if not isinstance(s, (Scene, TraceScene)) and hasattr(s, "euler_lagrange_double"):
        return FREE_COORDINATES   # type: ignore[return-value]
    _coordinate_scene(s, "coordinates of matrix variables")
    units = _units(s)
    return _UnitCoordinates([(name, E) for name in names for E in units], names, (s.n, s.r))


def complex_coordinates(s: Scene, names: Sequence[Hashable]) -> list[tuple[Hashable, Mat]]:
    """The real coordinates of realified complex n×r variables: (name, E_ij) and (name, iE_ij)."""
    if not isinstance(s, (Scene, TraceScene)) and hasattr(s, "euler_lagrange_complex"):
        return FREE_COMPLEX_COORDINATES   # type: ignore[return-value]
    _coordinate_scene(s, "coordinates of matrix variables")
    units = _units(s)
    out = []
    for name in names:
        for E in units:
            Z = E - E
            out.append((name, s.realify(E, Z)))
            out.append((name, s.realify(Z, E)))
    return _ComplexCoordinates(out)


def _flat(value: Any) -> list[Any]:
    value = value
    if isinstance(value, Mat):
        return entries(value)
    if isinstance(value, (list, tuple)):
        out = []
        for v in value:
            out.extend(_flat(v))
        return out
    return [value]


def _matrix(s: Scene, a: np.ndarray) -> Mat:
    """An untyped, unrecorded matrix of the scene's field from an array of its numbers (engine
    internal: stacked gradients, coordinates)."""
    return Mat._wrap(a, s.field)


class _Algebra:
    """The linear algebra of the stacked gradients: whole-matrix products (the field's native
    backend) where the arithmetic is exact, so that the order of the operations cannot change a
    number; entry by entry (numpy arrays of the field's numbers) where the numbers carry error
    bounds, since entrywise propagation keeps the bound of every entry of a tall product to the
    terms of that entry, where a normwise bound would charge it with the whole matrix."""

    def __init__(self, s: Scene) -> None:
        self.s = s
        self.native = bool(s.field.exact)

    def of(self, a: np.ndarray) -> Any:
        """A matrix of this algebra from an array of numbers."""
        return _matrix(self.s, a) if self.native else a

    def array(self, M: Any) -> np.ndarray:
        """The numbers of a matrix of this algebra (read-only)."""
        return M._view() if self.native else M

    def mm(self, A: Any, B: Any) -> Any:
        """The product AB."""
        if self.native:
            return A @ B
        (m, inner), k = A.shape, B.shape[1]
        out = np.empty((m, k), dtype=object)
        if inner == 0:
            out.fill(self.s.const(0))
        elif m and k:
            normalize = self.s.field.normalize
            for idx, x in np.ndenumerate(np.dot(A, B)):
                out[idx] = normalize(x)
        return out

    def columns(self, M: Any, a: int, b: int) -> Any:
        """Columns a..b − 1 of M, a matrix of this algebra (cut in the backend where M is held there)."""
        return M[:, a:b] if self.native else M[:, a:b].copy()

    def solve(self, M: Any, B: Any, what: str) -> Any:
        """Y with M Y = B: M⁻¹B in the field's whole-matrix backend where it has one (the solution stays
        there: its entries are not carried to the field's scalars and back), else the field's solver (also
        where the backend's inverse is beyond the symbolic budget: the field's own budget decides)."""
        from stiefelsym.backends.fields import DegenerateError, SymbolicBudget
        be = backend(self.s.field) if self.native else None
        if be is not None and be.keeps_solutions and M._nat() is not None and B._nat() is not None:
            try:
                inverse = be.inv(M._nat())
            except (DegenerateError, ZeroDivisionError) as exc:
                raise DegenerateError(f"{what} is singular here") from exc
            except SymbolicBudget:
                inverse = None
            if inverse is not None:
                return Mat._wrap_native(be.matmul(inverse, B._nat()), self.s.field)
        try:
            sol = self.s.field.solve(self.array(M).tolist(), self.array(B).tolist())
        except DegenerateError as exc:
            raise DegenerateError(f"{what} is singular here") from exc
        if self.native:
            return Mat._rows(sol, self.s.field)
        out = np.empty((len(sol), len(sol[0]) if sol else 0), dtype=object)
        for i, row in enumerate(sol):
            for j, x in enumerate(row):
                out[i, j] = x
        return out


class _Layout:
    """Where the coordinates of a tangent vector at a point sit among the entries of its matrices:
    the variables of the point one after the other, each row by row (the *ambient* vector), and
    the coordinates as the ambient vector times Bᵀ, B the rows of the coordinate basis (or, for
    :func:`real_coordinates`, the entries of the named variables themselves)."""

    def __init__(self, s: Scene, coords: Coordinates, point: Point) -> None:
        self.s = s
        self.names = list(point)
        self.shapes = {k: point[k]._shape() for k in self.names}
        self.offsets, at = {}, 0
        for k in self.names:
            self.offsets[k] = at
            at += self.shapes[k][0] * self.shapes[k][1]
        self.size = at
        for name, B in coords:
            if name not in self.shapes:
                raise KeyError(f"a coordinate of {name!r}, which is not a variable of the point")
            if not isinstance(B, Mat) or B._shape() != self.shapes[name]:
                raise ValueError(f"the coordinates of {name!r} must be matrices of its shape")
        self.coords = list(coords)
        self.unit = (isinstance(coords, _UnitCoordinates) and coords.intact()
                     and all(self.shapes[k] == coords.shape for k in coords.names))
        self.unit_names = list(coords.names) if self.unit else None
        self.alg = _Algebra(s)
        self._basis = None

    def basis(self) -> Any:
        """B: one row per coordinate, its basis matrix as an ambient vector (a matrix of the
        layout's algebra)."""
        if self._basis is None:
            zero = self.s.const(0)
            rows = np.empty((len(self.coords), self.size), dtype=object)
            rows.fill(zero)
            for a, (name, B) in enumerate(self.coords):
                o = self.offsets[name]
                rows[a, o:o + B._shape()[0] * B._shape()[1]] = B._view().reshape(-1)
            self._basis = self.alg.of(rows)
        return self._basis

    def ambient(self, grads: Sequence[Mapping[Hashable, Mat | None]]) -> np.ndarray:
        """The ambient vectors (rows) of gradients given as matrices per variable (None: zero)."""
        out = np.empty((len(grads), self.size), dtype=object)
        out.fill(self.s.const(0))
        for i, g in enumerate(grads):
            for k, M in g.items():
                if M is not None and k in self.offsets:
                    o = self.offsets[k]
                    out[i, o:o + M._shape()[0] * M._shape()[1]] = M._view().reshape(-1)
        return out

    def project(self, grads: Sequence[Mapping[Hashable, Mat | None]]) -> np.ndarray:
        """The coordinates (rows, an array) of gradients given as matrices per variable: their
        derivatives along the coordinate basis, ⟨∇F, B_a⟩."""
        amb = self.ambient(grads)
        if self.unit:
            cols = [amb[:, self.offsets[k]:self.offsets[k] + self.shapes[k][0] * self.shapes[k][1]]
                    for k in self.unit_names]
            return np.concatenate(cols, axis=1) if cols else amb[:, :0].copy()
        alg = self.alg
        return alg.array(alg.mm(alg.of(amb), self.basis().T))

    def assemble(self, c: np.ndarray | Mat, like: Point) -> dict[Hashable, Mat]:
        """The tangent vector Σ c_a B_a (c a column of coordinates: an array, or a matrix of the layout's
        algebra), as matrices of the variables of ``like`` (one without coordinates gets 0), each with the
        spaces of its basis.  A matrix held in its field's whole-matrix backend is cut there (its entries
        never leave the backend: a symbolic solution of thousands of terms per entry is not carried to
        symengine and back)."""
        s = self.s
        parts = self._native_parts(c) if isinstance(c, Mat) else None
        if parts is None:
            parts = self._entry_parts(c._view() if isinstance(c, Mat) else c)
        tags = {}
        for name, B in self.coords:
            tags.setdefault(name, B.tags)
        out = {}
        for name, M in like.items():
            if name in parts:
                part = parts[name]
                out[name] = (Mat._wrap(part.copy(), s.field, tags[name], s.tracker) if isinstance(part, np.ndarray)
                             else Mat._wrap_native(part, s.field, tags[name], s.tracker))
            else:
                out[name] = M - M
        return out

    def _entry_parts(self, c: np.ndarray) -> dict[Hashable, np.ndarray]:
        """:meth:`assemble`'s matrices of the variables as arrays of entries, cut from the column ``c``."""
        if self.unit:
            vec = c.reshape(-1)
            m, k = self.shapes[self.unit_names[0]] if self.unit_names else (0, 0)
            return {name: vec[i * m * k:(i + 1) * m * k].reshape(m, k) for i, name in enumerate(self.unit_names)}
        alg = self.alg
        vec = alg.array(alg.mm(alg.of(c.T.copy()), self.basis())).reshape(-1)
        parts = {}
        for name, _B in self.coords:
            if name not in parts:
                o, (m, k) = self.offsets[name], self.shapes[name]
                parts[name] = vec[o:o + m * k].reshape(m, k)
        return parts

    def _native_parts(self, c: Mat) -> dict[Hashable, Any] | None:
        """:meth:`assemble`'s matrices of the variables cut from the column ``c`` in its field's backend (the
        m x k matrix of a variable from its m rows of k entries one after the other), or None where the
        backend cannot cut them (the caller reads the entries)."""
        be = backend(self.s.field)
        if be is None or not be.keeps_solutions or c._field is not self.s.field or c._nat() is None:
            return None
        if self.unit:
            row = be.T(c._nat())          # the coordinates are the entries, variable after variable
            m, k = self.shapes[self.unit_names[0]] if self.unit_names else (0, 0)
            spans = [(name, i * m * k, m, k) for i, name in enumerate(self.unit_names)]
        else:
            row = self.alg.mm(c.T, self.basis())._nat()      # the ambient vector Σ c_a B_a
            spans = [(name, self.offsets[name]) + tuple(self.shapes[name]) for name in dict(self.coords)]
        first = np.arange(1)
        parts = {}
        for name, o, m, k in spans:
            if not (m and k):
                return None
            rows = [[be.take(row, first, np.arange(o + a * k, o + (a + 1) * k))] for a in range(m)]
            if any(r[0] is NotImplemented for r in rows):
                return None
            parts[name] = be.block(rows)
        return parts


# -- gradients at points of the caller's own ----------------------------------------------------

class _PointReverseScene(ReverseScene):
    """The scene over reverse numbers, for gradients at a point of the caller's own: the complex
    conjugate and the realification of the scene are operations of the tape here (the conjugate as
    the product J M J, J = diag(I, −I), its own adjoint; the realification a block matrix, whose
    adjoint gathers the blocks of the adjoint), not entry writes."""

    def conj(self, M: Mat) -> Mat:
        for tag in M.tags:
            atoms = definite(tag)
            if atoms is None or len(atoms) != 2 or atoms[0] != atoms[1]:
                raise TypeError(f"conj acts on realified matrices, indexed by n+n or r+r, not by {tag!r}")
        R = M._nat()
        m, k = M._shape()
        Jm, Jk = self._signs(m), self._signs(k)
        conj = lambda v: Jm @ v @ Jk
        node = None if R.node is None else Node(lambda g, parent=R.node: [(parent, conj(g))])
        return Mat._wrap_native(RevMat(conj(R.v), node), self.field, M.tags, M.tracker, M._coords)

    def _signs(self, m: int) -> Mat:
        """J = diag(I, −I) (m × m, untyped, over the base field): the conjugate of a realified
        matrix M is J M J, and the adjoint of M ↦ J M J is itself."""
        def build():
            d = np.ones(m, dtype=np.int64)
            d[m // 2:] = -1
            return Mat._consts(np.diag(d), self.base.field)
        return self.base._cached(f"systems: diag(I, -I) {m}x{m}", build)

    def realify(self, U: Mat, V: Mat) -> Mat:
        base = self.base.field
        shadow = lambda M: Mat.zeros(*M._shape(), base, M.tags, M.tracker)
        Us, Vs = shadow(U), shadow(V)
        tags = block([[Us, -Vs], [Vs, Us]]).tags      # the spaces (and records) of the block matrix
        RU, RV = U._nat(), V._nat()
        v = block([[RU.v, -RV.v], [RV.v, RU.v]])
        m, k = U._shape()
        live = [(R.node, part) for R, part in ((RU, lambda g: g[0] + g[1]), (RV, lambda g: g[2] - g[3]))
                if R.node is not None]
        node = None
        if live:
            def backward(g):
                a = g._view()
                q = [Mat._wrap(x.copy(), base) for x in (a[:m, :k], a[m:, k:], a[m:, :k], a[:m, k:])]
                return [(parent, part(q)) for parent, part in live]
            node = Node(backward)
        return Mat._wrap_native(RevMat(v, node), self.field, tags, self.tracker, U._coords or V._coords)


def _reverse_applies(s: Scene) -> bool:
    return scene_module.REVERSE_GRADIENTS and not isinstance(s, _LiftedScene)


def _reverse_gradients(s: Scene, F: Callable[[Scene, dict], Any], point: Point,
                       wrt: Sequence[Hashable]) -> list[dict[Hashable, Mat | None]]:
    """The gradients, with respect to the variables ``wrt`` of the point, of the scalar components
    of F (as :func:`_flat` lists them) at the point: one evaluation of F over reverse numbers and
    one backward sweep per component.  Raises :class:`Unsupported` where reverse mode cannot."""
    rs = _PointReverseScene(s)
    z, leaves = {}, []
    for k, M in point.items():
        if k in wrt:
            lf = rev_leaf(M._untyped())
            leaves.append(lf)
            z[k] = Mat._wrap_native(lf, rs.field, M.tags, rs.tracker, M._coords)
        else:
            z[k] = rs._lift_primitive(M, None)
    one = s.const(1)
    out = []
    for x in _flat(F(rs, z)):
        if isinstance(x, Rev) and x.node is not None:
            gs = rev_gradient(x, leaves, one)
        else:
            gs = [None] * len(leaves)
        out.append(dict(zip(wrt, gs)))
    return out


def _difference(a: Mat | None, b: Mat | None) -> Mat | None:
    """a − b for gradients (None: zero)."""
    if b is None:
        return a
    return -b if a is None else a - b


def _jacobian(s: Scene, F: Callable[[Scene, dict], Any], point: Point, layout: _Layout) -> np.ndarray:
    """Rows: the scalar components of F; columns: their derivatives along the coordinates of the
    layout at the point.  Reverse mode (one evaluation, one sweep per component, one product with
    the coordinate basis), or one forward pass per coordinate where reverse mode cannot."""
    if _reverse_applies(s):
        try:
            wrt = list(dict.fromkeys(name for name, _ in layout.coords))
            return layout.project(_reverse_gradients(s, F, point, wrt))
        except Unsupported:
            pass
    cols = [_flat(derivative(s, F, point, {name: B})) for name, B in layout.coords]
    a = np.empty((len(cols[0]) if cols else 0, len(cols)), dtype=object)
    for j, col in enumerate(cols):
        for i, x in enumerate(col):
            a[i, j] = x
    return a


def _kinetic_matrix(s: Scene, T: Callable[[Scene, dict], Any], velocity: Point, layout: _Layout) -> np.ndarray:
    """The matrix K_ab = T(b_a + b_b) − T(b_a) − T(b_b) + T(0) of a quadratic form T in the velocities
    with constant coefficients, in the coordinates b_a of the layout.  Its columns are the gradients
    ∇T(b_b) − ∇T(0) = K b_b (reverse mode: one evaluation each), or, where reverse mode cannot, its
    entries come from polarization."""
    zero_v = {k: M - M for k, M in velocity.items()}
    names = list(velocity)

    def direction(name, B, base=zero_v):
        return {k: (base[k] + B if k == name else base[k]) for k in names}

    if _reverse_applies(s):
        try:
            wrt = list(dict.fromkeys(name for name, _ in layout.coords))

            def grad(v):
                out = _reverse_gradients(s, T, v, wrt)
                if len(out) != 1:
                    raise TypeError("the kinetic energy must be a scalar function")
                return out[0]

            g0 = grad(zero_v)
            cols = []
            for name, B in layout.coords:
                g = grad(direction(name, B))
                cols.append({k: _difference(g[k], g0[k]) for k in wrt})
            return layout.project(cols).T.copy()    # column b: ∇T(b_b) − ∇T(0) = K b_b
        except Unsupported:
            pass
    T0 = (T(s, zero_v))

    def kinetic(w):
        return (T(s, w)) - T0

    coords = layout.coords
    N = len(coords)
    T1 = [kinetic(direction(name, B)) for name, B in coords]
    K = np.empty((N, N), dtype=object)
    for a in range(N):
        na, Ba = coords[a]
        da = direction(na, Ba)
        for b in range(a, N):
            nb, Bb = coords[b]
            K[a, b] = K[b, a] = kinetic(direction(nb, Bb, da)) - T1[a] - T1[b]
    return K


# -- Lagrangian systems with holonomic constraints -----------------------------------------------

def euler_lagrange(s: Scene, T: Callable[[Scene, dict], Any], U: Callable[[Scene, dict], Any],
                   constraints: Callable[[Scene, dict], Any], position: Point, velocity: Point,
                   coords: Coordinates) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The accelerations q̈ (a dict like ``position``) and the multipliers μ of the Euler–Lagrange
    equations of the Lagrangian L = T(q̇) − U(q), T(t, v) a quadratic form in the velocities with
    constant coefficients and U(t, q) the potential, with the holonomic constraints g(t, q) = 0 (a
    list of independent scalar functions, or matrices whose entries are), at the point (q, q̇):

        d/dt ∂T/∂q̇ = −∂U/∂q + Σ_j μ_j ∂g_j/∂q,    Dg·q̈ + D²g(q̇, q̇) = 0.

    The matrix K of T is that of its polarization, T(b_k + b_l) − T(b_k) − T(b_l) + T(0), taken as
    the gradients of T at the basis vectors; with J = Dg, Y = K⁻¹[−∇U | Jᵀ], the multipliers solve
    (J Y₁) μ = −D²g(q̇, q̇) − J Y₀ and q̈ = Y₀ + Y₁ μ (whole-matrix products)."""
    if coords is FREE_COORDINATES and hasattr(s, "euler_lagrange_double"):
        return s.euler_lagrange_double(T, U, constraints, position, velocity)   # the dimension-free scene
    if coords is FREE_COMPLEX_COORDINATES and hasattr(s, "euler_lagrange_complex"):
        return s.euler_lagrange_complex(T, U, constraints, position, velocity)  # the dimension-free scene
    _coordinate_scene(s, "the Euler-Lagrange equations in coordinates")
    names = list(position)
    if set(velocity) != set(names):
        raise KeyError("the velocity must have the variables of the position")
    point = {("q", k): position[k] for k in names}
    point.update({("v", k): velocity[k] for k in names})

    def g(t, z):
        return _flat(constraints(t, {k: z[("q", k)] for k in names}))

    _engine_coordinates(coords, "euler_lagrange")
    layout = _Layout(s, coords, position)
    _every_variable_moved(layout, position, "euler_lagrange: the position")
    K = _kinetic_matrix(s, T, velocity, layout)
    _check_quadratic(s, lambda v: T(s, v), velocity, layout)
    gradU = _jacobian(s, U, position, layout)                                      # 1 × N
    Ja = _jacobian(s, lambda t, q: _flat(constraints(t, q)), position, layout)    # m × N
    # D²g(q̇, q̇) = d/dε [Dg(q + εq̇)·q̇]
    along = {("q", k): velocity[k] for k in names}
    hess = _flat(derivative(s, lambda t, z: derivative(t, g, z, {("q", k): z[("v", k)] for k in names}),
                            point, along))
    return _solve_euler_lagrange(layout, K, gradU, Ja, hess, position)


def _every_variable_moved(layout: _Layout, point: Point, what: str) -> None:
    """Refuse a variable of the point no coordinate moves: the step differentiates its functions along the
    coordinates only, so such a variable would be a constant of theirs riding in their argument (a velocity
    handed to the potential as q["C"]), and the result that of other functions."""
    moved = {name for name, _ in layout.coords}
    extra = [k for k in point if k not in moved]
    if extra:
        raise ValueError(f"{what} has variables no coordinate moves ({', '.join(map(repr, extra))}): every variable "
                         "of the point must be a coordinate's (a constant is closed over, not passed in the point)")


def _pairs_cover(point: Point, pairs: Sequence[tuple[Hashable, Hashable]], what: str) -> None:
    """Refuse a variable of the point that is in no (position, momentum) pair (see :func:`_every_variable_moved`)."""
    named = {k for pair in pairs for k in pair}
    extra = [k for k in point if k not in named]
    if extra:
        raise ValueError(f"{what}: the point has variables in no (position, momentum) pair "
                         f"({', '.join(map(repr, extra))}): every variable of the point must be in a pair (a constant "
                         "is closed over, not passed in the point)")


#: what the Euler-Lagrange equations refuse of a kinetic energy (every method: see the dimension-free scene's)
NOT_QUADRATIC = ("a kinetic energy that is not a quadratic form in the velocities (plus a linear and a constant "
                 "term): the equations are solved for one")


def _check_quadratic(s: Scene, value: Callable[[Point], Any], velocity: Point, layout: _Layout) -> None:
    """Refuse a kinetic energy that is not of degree at most 2 in the velocities: its third difference
    T(3w) − 3T(2w) + 3T(w) − T(0) = Σ_k (3ᵏ − 3·2ᵏ + 3 − 0ᵏ) T_k(w), whose coefficient is 0 for k <= 2 and
    positive for k >= 3, must vanish at a generic velocity w = Σ c_b b_b (the coefficients c the engine's own
    parameters, Scene._engine_params: independent of the claim's draws).  K is read from the
    gradients at the basis vectors, which see the quadratic part only: a cubic term (a product of entries no
    basis vector makes nonzero together) would otherwise be dropped without a word, and the equations solved
    for another Lagrangian.  (A linear term with constant coefficients changes nothing: d/dt of a constant
    covector is 0, and K does not see it.)  Decided where the field's test of zero decides it (exact fields,
    error bounds)."""
    from stiefelsym.brackets import _AFFINE_CHECKED, _field_in
    if not _field_in(s, _AFFINE_CHECKED) or not layout.coords:
        return
    N = len(layout.coords)
    c = s._engine_params("euler_lagrange:w", N, 1)._view()[:, 0]
    zero_v = {k: M - M for k, M in velocity.items()}

    def at(m: int) -> Any:
        w = dict(zero_v)
        for (name, B), cb in zip(layout.coords, c):
            w[name] = w[name] + B * (cb * m)
        return value(w)
    with scene_module.engine_check():
        third = at(3) - at(2) * 3 + at(1) * 3 - value(zero_v)
    if not s._field.is_zero(third):
        raise ValueError(f"euler_lagrange: {NOT_QUADRATIC}")


def _solve_euler_lagrange(layout: _Layout, K: np.ndarray, gradU: np.ndarray, Ja: np.ndarray, hess: list,
                          position: Point) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The solve of :func:`euler_lagrange` from K, ∇U, Dg and D²g(q̇, q̇) in the layout's coordinates."""
    alg = layout.alg
    N = len(layout.coords)
    m = Ja.shape[0]
    rhs = np.empty((N, m + 1), dtype=object)
    rhs[:, :1] = (-gradU).T
    rhs[:, 1:] = Ja.T
    Y = alg.solve(alg.of(K), alg.of(rhs), "the kinetic energy's quadratic form")
    Y0 = alg.columns(Y, 0, 1)
    if m:
        Y1 = alg.columns(Y, 1, m + 1)
        h = np.empty((m, 1), dtype=object)
        for i, x in enumerate(hess):
            h[i, 0] = -x
        J = alg.of(Ja.copy())
        S = alg.mm(J, Y1)
        b = alg.of(h) - alg.mm(J, Y0)
        mu = alg.solve(S, b, "the matrix of the constraints' second derivatives")
        acc = Y0 + alg.mm(Y1, mu)
        mu_list = list(alg.array(mu)[:, 0])
    else:
        acc, mu_list = Y0, []
    return layout.assemble(acc, position), mu_list


# -- Hamiltonian flows on products of cotangent bundles ----------------------------------------

def hamiltonian_flow(s: Scene, H: Callable[[Scene, dict], Any], constraints: Callable[[Scene, dict], Any],
                     point: Point, pairs: Sequence[tuple[Hashable, Hashable]],
                     coords: Callable[[Scene, Sequence[Hashable]], list] = real_coordinates
                     ) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The flow of H(t, z) on the product of the cotangent bundles of the (position, momentum)
    pairs, restricted by the constraints F(t, z) = 0 (independent scalar functions, or matrices
    whose entries are): ż = Ω∇H + Σ_i μ_i Ω∇F_i with the multipliers μ solved from dF/dt = 0 (the
    Dirac flow of H for all constraints together).  Returns the tangent vector (a dict like
    ``point``) and μ.

    With the gradients stacked by rows, H_x, H_p (1 × N) and G_x, G_p (one row per constraint), the
    bracket matrix is C = {F_i, F_j}_0 = G_x G_pᵀ − G_p G_xᵀ, C μ = −(G_x H_pᵀ − G_p H_xᵀ), and
    ẋ = H_pᵀ + G_pᵀ μ, ṗ = −(H_xᵀ + G_xᵀ μ)."""
    _coordinate_scene(s, "a Hamiltonian flow in coordinates")
    _pairs_cover(point, pairs, "hamiltonian_flow")
    positions = coords(s, [p for p, _ in pairs])
    momenta = coords(s, [m for _, m in pairs])
    _engine_coordinates(positions, "hamiltonian_flow")
    _engine_coordinates(momenta, "hamiltonian_flow")
    xs = _Layout(s, positions, {p: point[p] for p, _ in pairs})
    ps = _Layout(s, momenta, {q: point[q] for _, q in pairs})
    N = len(positions)
    if len(momenta) != N:
        raise ValueError("the positions and the momenta need as many coordinates")

    def scalar_H(t, z):
        value = (H(t, z))
        if isinstance(value, (Mat, list, tuple, dict)):
            raise TypeError("a Hamiltonian must be a scalar function, not a " + type(value).__name__)
        return value

    both = lambda t, z: [scalar_H(t, z)] + _flat(constraints(t, z))
    grads = None
    if _reverse_applies(s):
        try:
            grads = _reverse_gradients(s, both, point, list(point))
        except Unsupported:
            pass
    if grads is not None:
        Jx, Jp = xs.project(grads), ps.project(grads)
    else:
        Jx = _jacobian(s, both, point, _Layout(s, positions, point))
        Jp = _jacobian(s, both, point, _Layout(s, momenta, point))
    return _dirac_flow(xs, ps, Jx, Jp, point, pairs)


def _dirac_flow(xs: _Layout, ps: _Layout, Jx: np.ndarray, Jp: np.ndarray, point: Point,
                pairs: Sequence[tuple[Hashable, Hashable]]) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The flow of :func:`hamiltonian_flow` from the coordinates of the gradients (rows: H, then the
    constraints; Jx along the positions' coordinates, Jp along the momenta's)."""
    alg = xs.alg
    m = Jx.shape[0] - 1
    hx, hp = alg.of(Jx[:1].copy()), alg.of(Jp[:1].copy())
    Gx, Gp = alg.of(Jx[1:].copy()), alg.of(Jp[1:].copy())
    if m:
        C = alg.mm(Gx, Gp.T) - alg.mm(Gp, Gx.T)
        b = -(alg.mm(Gx, hp.T) - alg.mm(Gp, hx.T))
        mu = alg.solve(C, b, "the constraint bracket matrix {F_i, F_j}_0")
        xdot = hp.T + alg.mm(Gp.T, mu)
        pdot = -(hx.T + alg.mm(Gx.T, mu))
        mu_list = list(alg.array(mu)[:, 0])
    else:
        xdot, pdot, mu_list = hp.T, -hx.T, []
    out = xs.assemble(xdot, {p: point[p] for p, _ in pairs})
    out.update(ps.assemble(pdot, {q: point[q] for _, q in pairs}))
    return out, mu_list


def stiefel_pairs_flow(s: Scene, H: Callable[[Scene, dict], Any], point: Point,
                       pairs: Sequence[tuple[Hashable, Hashable]]) -> dict[Hashable, Mat]:
    """The Dirac flow of H(t, z) on the product of copies of T*V(n, r), one for each (position,
    momentum) pair of ``point``, each with its constraints (cond_XP): xᵀx = I_r, xᵀp + pᵀx = 0.
    On a coordinate scene it is :func:`hamiltonian_flow` with these constraints; on the
    dimension-free scene, at the scene's own points (X, P), (Y, Q), each pair has its own
    multipliers (its constraints involve only its letters): ẋ = H_p − xΠ, ṗ = −H_x + xΛ + pΠ."""
    _pairs_cover(point, pairs, "stiefel_pairs_flow")
    if not isinstance(s, (Scene, TraceScene)) and hasattr(s, "pairs_dirac_flow"):
        return s.pairs_dirac_flow(H, point, pairs)

    closed = _closed_form_pairs_flow(s, H, point, pairs)
    if closed is not None:
        return closed

    def constraints(t, z):
        out: list = []
        for x, p in pairs:
            X, P = z[x], z[p]
            out += symmetric_entries(X.T @ X - t.Ir) + symmetric_entries(X.T @ P + P.T @ X)
        return out
    return hamiltonian_flow(s, H, constraints, point, pairs)[0]


def _closed_form_pairs_flow(s: Scene, H: Callable[[Scene, dict], Any], point: Point,
                            pairs: Sequence[tuple[Hashable, Hashable]]) -> dict[Hashable, Mat] | None:
    """The flow of :func:`stiefel_pairs_flow` by the closed forms of its multipliers, where they
    hold: over an exact field, at a point whose every position x is n x r with xᵀx = I_r exactly.
    The constraints of a pair involve only its own letters, so the bracket matrix {F_i, F_j}_0 is
    block diagonal and each pair has its own multipliers, the unique symmetric Π, Λ that keep
    xᵀx = I_r and xᵀp + pᵀx = 0 (d/dt of each, with xᵀx = I_r): ẋ = H_p − xΠ, ṗ = −H_x + xΛ + pΠ,
    Π = sym(xᵀH_p), Λ = sym(xᵀH_x − H_pᵀp + ΠK − KΠ), K = xᵀp, sym M = ½(M + Mᵀ) (the forms of
    the Dirac flow of a single point, :meth:`Scene._closed_form_multipliers`).  The gradient of H
    is the reverse sweep of :func:`hamiltonian_flow`.  None where any condition fails (then the
    general solve of :func:`hamiltonian_flow`)."""
    if not _closed_form_applies(s, point, pairs):
        return None

    def scalar_H(t, z):
        value = H(t, z)
        if isinstance(value, (Mat, list, tuple, dict)):
            raise TypeError("a Hamiltonian must be a scalar function, not a " + type(value).__name__)
        return [value]
    try:
        grads = _reverse_gradients(s, scalar_H, point, list(point))[0]
    except Unsupported:
        return None
    return _closed_form_from_gradients(s, point, pairs, grads)


def _closed_form_applies(s: Scene, point: Point, pairs: Sequence[tuple[Hashable, Hashable]]) -> bool:
    """Whether the closed forms of :func:`_closed_form_pairs_flow` hold at the point (the conditions
    on the scene and the point, XᵀX = I_r checked exactly)."""
    if type(s) is not Scene or not s.field.exact or not _reverse_applies(s):
        return False
    names = [k for pair in pairs for k in pair]
    if len(set(names)) != len(names) or set(names) != set(point):
        return False
    n, r = s.n, s.r
    I = Mat.identity(r, s.field)
    for x, p in pairs:
        X, P = point[x], point[p]
        if not (isinstance(X, Mat) and isinstance(P, Mat)) or X._shape() != (n, r) or P._shape() != (n, r):
            return False
        Xu = X._untyped()
        if not (Xu.T @ Xu - I).is_zero():
            return False
    return True


def _closed_form_from_gradients(s: Scene, point: Point, pairs: Sequence[tuple[Hashable, Hashable]],
                                grads: Mapping[Hashable, Mat | None]) -> dict[Hashable, Mat]:
    """The flow of :func:`_closed_form_pairs_flow` from the gradients of H (None: zero)."""
    n, r = s.n, s.r
    f = s.field
    half = s.const(Fraction(1, 2))
    sym = lambda M: (M + M.T) * half          # noqa: E731
    out: dict[Hashable, Mat] = {}
    for x, p in pairs:
        X, P = point[x]._untyped(), point[p]._untyped()
        zero = Mat.zeros(n, r, f)
        Hx = grads[x]._untyped() if grads.get(x) is not None else zero
        Hp = grads[p]._untyped() if grads.get(p) is not None else zero
        K = X.T @ P
        Pi = sym(X.T @ Hp)
        Lam = sym(X.T @ Hx - Hp.T @ P + Pi @ K - K @ Pi)
        out[x] = (Hp - X @ Pi)._retyped(f, point[x].tags, s.tracker)
        out[p] = (-Hx + X @ Lam + P @ Pi)._retyped(f, point[p].tags, s.tracker)
    return out


# -- generic points of the appendix's phase spaces ------------------------------------------------



def double_point(s: Scene) -> dict[str, Mat]:
    """A generic point (X, Y, Ẋ, Ẏ) of the rank r double Neumann system: XᵀY = I_r,
    ẊᵀY + XᵀẎ = 0 (keys "X", "Y", "Xdot", "Ydot"): the scene's matrices DX, DY, DXdot, DYdot
    (built by :func:`double_point_of` on a coordinate scene, letters on the dimension-free one)."""
    return {"X": s.DX, "Y": s.DY, "Xdot": s.DXdot, "Ydot": s.DYdot}


#: the points of the appendix's phase spaces built from scalar parameters of their own, for a
#: witness (stiefelsym.methods.witness) to state: (the prefix of their parameters' names, the builder, the
#: keys of the point and the letters a report names them by); such a point replaces the chart's X, P
WITNESS_POINTS = (("double_", double_point_of, (("X", "X"), ("Y", "Y"), ("Xdot", "Ẋ"), ("Ydot", "Ẏ"))),)


def coupled_point(s: Scene) -> dict[str, Mat]:
    """The scene's two points (X, P), (Y, Q) of T*V(n, r): a point of T*V × T*V."""
    return {"X": s.X, "P": s.P, "Y": s.Y, "Q": s.Q}


def complex_point(s: Scene) -> dict[str, Mat]:
    """The scene's point of the tangent bundle of W(n, r), realified: Z*Z = I_r, Z*Ż + Ż*Z = 0
    (keys "Z", "Zdot")."""
    return {"Z": s.Zc, "Zdot": s.Zc_dot}


def real_complex_point(s: Scene) -> dict[str, Mat]:
    """The scene's point (X, P) of T*V(n, r) as real data Z = X, Ż = P on W(n, r), realified."""
    return {"Z": realify_real(s, s.X), "Zdot": realify_real(s, s.P)}


# -- complex matrices, realified -----------------------------------------------------------------

def realify_real(s: Scene, M: Mat) -> Mat:
    """A real matrix as a complex one, realified: [[M, 0], [0, M]]."""
    return s.realify(M, M - M)


def ctranspose(s: Scene, M: Mat) -> Mat:
    """The plain (not conjugate) transpose Mᵀ of a realified complex matrix: the conjugate of M*."""
    return s.conj(M.T)


def re_trace(s: Scene, M: Mat) -> Any:
    """The real part of the trace of a realified complex matrix (half the trace of its real form)."""
    return s.q(1, 2) * M.trace()      # (a product: a constant divisor would be a new factor of a degree bound)


def complex_diagonal(M: Mat) -> list[tuple[Any, Any]]:
    """The diagonal entries (real part, imaginary part) of a realified complex square matrix."""
    m = M.shape[0] // 2
    return [(M[j, j], M[m + j, j]) for j in range(m)]

# -- the engine steps of the transformed graphs (stiefelsym.ir.derivative) ---------------------------

def _matrix_variable(M: Any, k: Hashable) -> None:
    """Refuse a variable of a point that is not a matrix (the graph's derivatives and gradients at a point
    take its variables as matrices)."""
    if not isinstance(M, Mat):
        raise TypeError(f"the variable {k!r} of a point must be a matrix here, not a {type(M).__name__}")


def graph_tangent(s: Scene, point: Point, tangent: Mapping[Hashable, Mat], keys: tuple) -> dict[Hashable, Mat]:
    """The components ``keys`` of a tangent vector at a point of the caller's own, checked as
    :func:`derivative` checks them, each with the spaces of the point's matrix (0 where the tangent does
    not move it): what the graph's derivative of a function at the point reads."""
    if not isinstance(s, Scene):
        raise TypeError(f"a derivative at a point on a {type(s).__name__} (not a coordinate scene)")
    _coordinate_scene(s, "a derivative at a point of a phase space other than T*V")
    _check_tangent(point, tangent)
    out = {}
    for k in keys:
        M = point[k]
        _matrix_variable(M, k)
        v = tangent.get(k)
        if v is None:
            v = Mat.zeros(*M._shape(), s.field, M.tags, s.tracker)
        elif v.tags != M.tags or v._coords != M._coords:
            v = v._retyped(v._field, M.tags, s.tracker)
        v._coords = M._coords
        out[k] = v
    return out


def _pairs_constraint_gradients(s: Scene, point: Point, pairs: Sequence[tuple[Hashable, Hashable]]
                                ) -> list[dict[Hashable, Mat | None]]:
    """The gradients of the constraints of :func:`stiefel_pairs_flow` in closed form, in their order
    (for each pair, the upper triangle of xᵀx − I_r, then of xᵀp + pᵀx): with S_ij = E_ij + E_ji
    (2E_ii on the diagonal), the (i, j) entry of xᵀx has the x-gradient xS_ij, the (i, j) entry of
    xᵀp + pᵀx the x-gradient pS_ij and the p-gradient xS_ij (untyped, unrecorded: engine internals)."""
    f = s.field
    out: list[dict[Hashable, Mat | None]] = []
    for x, p in pairs:
        X, P = point[x]._untyped(), point[p]._untyped()
        r = X._shape()[1]
        if P._shape() != X._shape():
            raise ValueError("the position and the momentum of a pair must have the same shape")
        units = []
        for i in range(r):
            for j in range(i, r):
                S = np.empty((r, r), dtype=object)
                S.fill(f.const(0))
                S[i, j] = S[i, j] + f.const(1)
                S[j, i] = S[j, i] + f.const(1)
                units.append(Mat._wrap(S, f))
        out += [{x: X @ S} for S in units]
        out += [{x: P @ S, p: X @ S} for S in units]
    return out


def graph_pairs_flow(s: Scene, H: Callable[[Scene, dict], Any], point: Point,
                     pairs: Sequence[tuple[Hashable, Hashable]], value: Any, keys: tuple, *grads: Any
                     ) -> dict[Hashable, Mat]:
    """The flow of :func:`stiefel_pairs_flow` from the gradients of H the graph computed (``grads``, one
    per key of ``keys``, None: zero; ``value``: H's value, evaluated as the reverse tape evaluated it):
    the closed forms of the multipliers where they hold, else the constraints' gradients in closed form
    and the solve of :func:`hamiltonian_flow`."""
    if not isinstance(s, Scene):
        raise TypeError(f"a flow of pairs of Stiefel points on a {type(s).__name__} (not a coordinate scene)")
    _pairs_cover(point, pairs, "stiefel_pairs_flow")
    for k, M in point.items():
        _matrix_variable(M, k)
    gH = dict(zip(keys, grads))
    if _closed_form_applies(s, point, pairs):
        return _closed_form_from_gradients(s, point, pairs, gH)
    _coordinate_scene(s, "a Hamiltonian flow in coordinates")
    positions = real_coordinates(s, [x for x, _ in pairs])
    momenta = real_coordinates(s, [q for _, q in pairs])
    xs = _Layout(s, positions, {x: point[x] for x, _ in pairs})
    ps = _Layout(s, momenta, {q: point[q] for _, q in pairs})
    if len(momenta) != len(positions):
        raise ValueError("the positions and the momenta need as many coordinates")
    rows = [gH] + _pairs_constraint_gradients(s, point, pairs)
    return _dirac_flow(xs, ps, xs.project(rows), ps.project(rows), point, pairs)[0]


def graph_euler_lagrange(s: Scene, position: Point, velocity: Point, coords: Coordinates, wrt: tuple,
                         kinetic: Callable[[Scene, Point], tuple], potential: tuple,
                         column: Callable[[Scene, Point], Any], hess: Any) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The accelerations and multipliers of :func:`euler_lagrange` from what the graph computed:
    ``kinetic(s, v)``, the gradient of T at the velocity v (one value per variable of ``wrt``, then T's
    value), taken at 0 and at each basis vector b_b of the coordinates (K b_b = ∇T(b_b) − ∇T(0)); the
    gradient of U at the position (``potential``, likewise); ``column(s, u)``, the derivative of the
    constraints at the position along the tangent vector u, taken along each basis vector (the columns
    of Dg); and D²g(q̇, q̇) (``hess``).  The step's checks made as the step makes them."""
    if not isinstance(s, Scene):
        raise TypeError(f"Euler-Lagrange equations on a {type(s).__name__} (not a coordinate scene)")
    _coordinate_scene(s, "the Euler-Lagrange equations in coordinates")
    if set(velocity) != set(position):
        raise KeyError("the velocity must have the variables of the position")
    for k, M in list(position.items()) + list(velocity.items()):
        _matrix_variable(M, k)
    _engine_coordinates(coords, "euler_lagrange")
    layout = _Layout(s, coords, position)
    _every_variable_moved(layout, position, "euler_lagrange: the position")
    n = len(wrt)
    zero_v = {k: M - M for k, M in velocity.items()}
    g0 = dict(zip(wrt, kinetic(s, zero_v)[:n]))
    cols = []
    for name, B in layout.coords:
        g = dict(zip(wrt, kinetic(s, {k: (zero_v[k] + B if k == name else zero_v[k]) for k in velocity})[:n]))
        cols.append({k: _difference(g[k], g0[k]) for k in wrt})
    K = layout.project(cols).T.copy()                  # column b: ∇T(b_b) − ∇T(0) = K b_b
    _check_quadratic(s, lambda v: kinetic(s, v)[n], velocity, layout)
    gradU = layout.project([dict(zip(wrt, potential[:n]))])
    flat = [_flat(column(s, {name: B})) for name, B in layout.coords]
    Ja = np.empty((len(flat[0]) if flat else 0, len(flat)), dtype=object)
    for j, col in enumerate(flat):
        for i, x in enumerate(col):
            Ja[i, j] = x
    return _solve_euler_lagrange(layout, K, gradU, Ja, _flat(hess), position)


PRIMITIVES[f"{__name__}.derivative:tangent"] = graph_tangent
PRIMITIVES[f"{__name__}.euler_lagrange:graph"] = graph_euler_lagrange
PRIMITIVES[f"{__name__}.stiefel_pairs_flow:graph"] = graph_pairs_flow

# the functions that need the engine's scene (coordinates, derivatives at points of other phase
# spaces) are single steps of a claim's graph; the points and the complex helpers are traced with it
derivative = primitive(derivative, like={"F": "point"}, returns=("like", "F"))
#: what a step's function may read of its scene besides its variable: the problem's constants (the derivative
#: pass's constant attributes, and A's eigenvalues) and the calls that compute from their arguments and constants
#: (the pass's numeric calls, and the scene's symmetric operator); the point, flows and brackets are refused
KINETIC_CONSTANT_ATTRS = CONSTANT_ATTRS | {"a"}
KINETIC_CONSTANT_CALLS = NUMERIC_CALLS | {"sym_operator"}
KINETIC_CONSTANT_STEPS = frozenset(f"stiefelsym.{x}" for x in (
    "systems.real_coordinates", "systems.complex_coordinates", "systems.hermitian_entries", "twisted.basis_vector",
    "twisted.block_projector", "twisted.reflection", "twisted.last_basis_vector", "twisted.leading_basis_vectors",
    "twisted.first_basis_vectors", "twisted.coordinate_projector", "twisted.kernel_frame",
    "twisted.kernel_annihilator", "twisted.magnetic_matrix"))


def _reads_beyond_own_variable(g: Any, fn: int) -> str | None:
    """What the body of the traced function ``fn`` (the kinetic energy T(t, v), the potential U(t, q) or the
    constraints g(t, q)) reads that may move with the point other than its own variable, directly or through a
    value of the claim it closes over (the position z["X"], t.X, a flow, a bracket, a variable of a function
    enclosing it), or None: its own variable, those of functions inside it, constants, the scene's constant
    parameters and steps of constants only."""
    own = {g.args[fn][0]}
    seen: set = set()
    stack = [fn]
    while stack:
        j = stack.pop()
        if j in seen:
            continue
        seen.add(j)
        op, a = g.ops[j], g.args[j]
        if op == "fn":
            own.add(a[0])       # a function inside it: its variables are bound there
        if op == "param":
            if a[0] not in own:
                return "a variable of a function enclosing it"
            continue            # its own variable (its last argument only gives its shape)
        if op == "attr" and a[1] not in KINETIC_CONSTANT_ATTRS:
            return f"the scene's {a[1]}"
        if op == "call" and a[1] not in KINETIC_CONSTANT_CALLS:
            return f"the scene's {a[1]}(...)"
        if op == "prim" and a[0].qualname not in KINETIC_CONSTANT_STEPS:
            return f"the engine step {a[0].qualname.rsplit('.', 1)[-1]}"
        stack.extend(g.refs(j))
    return None


def _own_variable_only(what: str, functions: tuple[tuple[int, str, str], ...]) -> Callable[[Any, Any], None]:
    """The trace-time check of an engine step's functions (argument index, name, what it must be): each must
    depend on the point through its own variable only, decided from the graph (the same refusal for every
    method), since the step differentiates it in its variable: a dependence on the point by another road (a
    value closed over, the scene's point, a flow, a variable of an enclosing function) would be a constant
    there, and the step's result that of another function."""
    def check(t: Any, ref: Any) -> None:
        a = t.g.args[ref.i]
        for i, who, must in functions:
            f = a[i] if len(a) > i else None
            if type(f) is not type(ref) or t.g.ops[f.i] != "fn":
                continue
            reads = _reads_beyond_own_variable(t.g, f.i)
            if reads is not None:
                t.refuse(f"{who} that may depend on the point other than through its variable (it reads {reads}): "
                         f"{must} ({what})")
    return check


#: Euler-Lagrange: K is read from T's gradients at the point, and d/dt ∂T/∂q̇ = K q̈ and ∂T/∂q = 0 hold only where T
#: does not move with the position; ∇U and Dg are taken in their variable q
_traced_kinetic = _own_variable_only("the Euler-Lagrange equations", (
    (2, "a kinetic energy", "T(t, v) is a quadratic form in the velocities v with constant coefficients"),
    (3, "a potential", "U(t, q) depends on the position q only, through q"),
    (4, "constraints", "g(t, q) depend on the position q only, through q")))


euler_lagrange = primitive(euler_lagrange, returns=2, like={"T": "velocity", "U": "position",
                                                            "constraints": "position"})
STEP_GRAPH_CHECKS["stiefelsym.systems.euler_lagrange"] = _traced_kinetic
STEP_GRAPH_CHECKS["stiefelsym.systems.hamiltonian_flow"] = _own_variable_only("a Hamiltonian flow", (
    (2, "a Hamiltonian", "H(t, z) depends on the point z only, through z"),
    (3, "constraints", "F(t, z) depend on the point z only, through z")))
STEP_GRAPH_CHECKS["stiefelsym.systems.stiefel_pairs_flow"] = _own_variable_only("a flow of pairs of Stiefel points", (
    (2, "a Hamiltonian", "H(t, z) depends on the point z only, through z"),))
hamiltonian_flow = primitive(hamiltonian_flow, returns=2, like={"H": "point", "constraints": "point"})
stiefel_pairs_flow = primitive(stiefel_pairs_flow, like={"H": "point"})
real_coordinates = primitive(real_coordinates)
complex_coordinates = primitive(complex_coordinates)
# the components of a Hermitian constraint: a list of entries at a fixed size, the matrix itself on the
# dimension-free scene (whose Euler–Lagrange solver reads it as the constraint)
hermitian_entries = primitive(hermitian_entries)
