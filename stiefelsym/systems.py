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

Derivatives are exact (forward mode, dual numbers) over every field of the scene, and the
points are built by the caller (generic points of the constraint set).  The coordinates are
orthonormal (the unit matrices E_ij, and E_ij, iE_ij for a realified complex variable) and a
flow is reassembled in the basis it was computed in, so the result does not depend on the basis:
a flow derived from O(n)-invariant data is O(n)-covariant, and these internal coordinates are not
recorded as a look at coordinates (like the scene's own gradients).  Only coordinate backends run
these functions: the dimension-free scene raises ``NeedsCoordinates``.

Engine internals used (an engine module may): ``Scene._unit_tangents`` (the unit matrices E_ij, not
recorded) and ``TangentScene._lift`` (a matrix of the scene's field with a given derivative), so that
points of the caller's own move along tangent vectors of the caller's own.

Complex matrices U + iV are realified as [[U, −V], [V, U]] (``Scene.realify``): sums, products
and the conjugate transpose (the transpose of the real form) are preserved; the plain transpose
Zᵀ is ``ctranspose``, the conjugate Z̄ is ``Scene.conj``.
"""
from __future__ import annotations

from typing import Any, Callable, Hashable, Mapping, Sequence

from .matrix import Mat, NeedsCoordinates
from .scene import Scene

Point = Mapping[Hashable, Mat]
Coordinates = Sequence[tuple[Hashable, Mat]]

__all__ = ["derivative", "entries", "symmetric_entries", "hermitian_entries", "real_coordinates",
           "complex_coordinates", "euler_lagrange", "hamiltonian_flow", "double_point", "coupled_point",
           "complex_point", "real_complex_point", "ctranspose", "realify_real", "re_trace", "complex_diagonal"]


def _coordinate_scene(s: Any, what: str) -> None:
    if not isinstance(s, Scene):
        raise NeedsCoordinates(what)


# -- derivatives at points of the caller's own --------------------------------------------------

def derivative(s: Scene, F: Callable[[Scene, dict], Any], point: Point, tangent: Mapping[Hashable, Mat]) -> Any:
    """d/dε F(t, point + ε·tangent) at ε = 0, exactly (components of ``tangent`` not given are 0).

    ``F`` is a function of a scene and of a point (a dict of matrices of the shapes of ``point``);
    its value is a scalar, a matrix, or a list/dict of them."""
    _coordinate_scene(s, "a derivative at a point of a phase space other than T*V")
    extra = set(tangent) - set(point)
    if extra:
        raise KeyError(f"a tangent vector moves the variables of the point, not {sorted(map(str, extra))}")
    for k, v in tangent.items():
        if not isinstance(v, Mat) or v.shape != point[k].shape:
            raise ValueError(f"the {k}-component of a tangent vector must be a matrix of the shape of {k}")

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
    m = M.shape[0] // 2
    return ([M[i, j] for i in range(m) for j in range(i, m)]
            + [M[m + i, j] for i in range(m) for j in range(i + 1, m)])


# -- coordinates ------------------------------------------------------------------------------

def _units(s: Scene) -> list[Mat]:
    """The unit n×r matrices E_ij (an orthonormal basis of M_{n,r}(ℝ))."""
    nr = s.n * s.r
    return [u["X"] for k, u in enumerate(s._unit_tangents()) if k < nr]


def real_coordinates(s: Scene, names: Sequence[Hashable]) -> list[tuple[Hashable, Mat]]:
    """The coordinates of n×r real matrix variables: (name, E_ij) for each name."""
    _coordinate_scene(s, "coordinates of matrix variables")
    units = _units(s)
    return [(name, E) for name in names for E in units]


def complex_coordinates(s: Scene, names: Sequence[Hashable]) -> list[tuple[Hashable, Mat]]:
    """The real coordinates of realified complex n×r variables: (name, E_ij) and (name, iE_ij)."""
    _coordinate_scene(s, "coordinates of matrix variables")
    units = _units(s)
    out = []
    for name in names:
        for E in units:
            Z = E - E
            out.append((name, s.realify(E, Z)))
            out.append((name, s.realify(Z, E)))
    return out


def _combine(s: Scene, coords: Coordinates, c: Sequence[Any], like: Point) -> dict[Hashable, Mat]:
    out: dict[Hashable, Mat] = {}
    for (name, B), x in zip(coords, c):
        term = x * B
        out[name] = out[name] + term if name in out else term
    for name, M in like.items():
        if name not in out:
            out[name] = M - M
    return out


def _flat(value: Any) -> list[Any]:
    if isinstance(value, Mat):
        return entries(value)
    if isinstance(value, (list, tuple)):
        out = []
        for v in value:
            out.extend(_flat(v))
        return out
    return [value]


def _dot(s: Scene, u: Sequence[Any], v: Sequence[Any]) -> Any:
    acc = s.q(0)
    for x, y in zip(u, v):
        acc = acc + x * y
    return acc


def _solve(s: Scene, M: list[list[Any]], B: list[list[Any]], what: str) -> list[list[Any]]:
    from .fields import DegenerateError
    try:
        return s.field.solve(M, B)
    except DegenerateError as exc:
        raise DegenerateError(f"{what} is singular here") from exc


# -- Lagrangian systems with holonomic constraints -----------------------------------------------

def euler_lagrange(s: Scene, T: Callable[[Scene, dict], Any], U: Callable[[Scene, dict], Any],
                   constraints: Callable[[Scene, dict], Any], position: Point, velocity: Point,
                   coords: Coordinates) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The accelerations q̈ (a dict like ``position``) and the multipliers μ of the Euler–Lagrange
    equations of the Lagrangian L = T(q̇) − U(q), T(t, v) a quadratic form in the velocities with
    constant coefficients and U(t, q) the potential, with the holonomic constraints g(t, q) = 0 (a
    list of independent scalar functions, or matrices whose entries are), at the point (q, q̇):

        d/dt ∂T/∂q̇ = −∂U/∂q + Σ_j μ_j ∂g_j/∂q,    Dg·q̈ + D²g(q̇, q̇) = 0.

    The matrix of T is obtained by polarization, T(b_k + b_l) − T(b_k) − T(b_l)."""
    _coordinate_scene(s, "the Euler-Lagrange equations in coordinates")
    names = list(position)
    if set(velocity) != set(names):
        raise KeyError("the velocity must have the variables of the position")
    point = {("q", k): position[k] for k in names}
    point.update({("v", k): velocity[k] for k in names})

    def g(t, z):
        return _flat(constraints(t, {k: z[("q", k)] for k in names}))

    zero_v = {k: M - M for k, M in velocity.items()}
    T0 = T(s, zero_v)

    def kinetic(w):
        return T(s, w) - T0

    def direction(name, B, base=zero_v):
        return {k: (base[k] + B if k == name else base[k]) for k in names}

    N = len(coords)
    T1 = [kinetic(direction(name, B)) for name, B in coords]
    K = [[None] * N for _ in range(N)]
    for a in range(N):
        na, Ba = coords[a]
        da = direction(na, Ba)
        for b in range(a, N):
            nb, Bb = coords[b]
            K[a][b] = K[b][a] = kinetic(direction(nb, Bb, da)) - T1[a] - T1[b]
    grad = [-derivative(s, lambda t, z: U(t, {k: z[("q", k)] for k in names}), point, {("q", name): B})
            for name, B in coords]
    J = [derivative(s, g, point, {("q", name): B}) for name, B in coords]    # rows: ∂g/∂c_a
    m = len(J[0]) if J else 0
    # D²g(q̇, q̇) = d/dε [Dg(q + εq̇)·q̇]
    along = {("q", k): velocity[k] for k in names}
    hess = derivative(s, lambda t, z: derivative(t, g, z, {("q", k): z[("v", k)] for k in names}),
                      point, along)
    rhs = [[grad[a]] + [J[a][j] for j in range(m)] for a in range(N)]
    Y = _solve(s, K, rhs, "the kinetic energy's quadratic form")
    S = [[_dot(s, [J[a][i] for a in range(N)], [Y[a][1 + j] for a in range(N)]) for j in range(m)]
         for i in range(m)]
    b = [[-hess[i] - _dot(s, [J[a][i] for a in range(N)], [Y[a][0] for a in range(N)])] for i in range(m)]
    mu = [row[0] for row in _solve(s, S, b, "the matrix of the constraints' second derivatives")]
    acc = [Y[a][0] + _dot(s, [Y[a][1 + j] for j in range(m)], mu) for a in range(N)]
    return _combine(s, coords, acc, position), mu


# -- Hamiltonian flows on products of cotangent bundles ----------------------------------------

def hamiltonian_flow(s: Scene, H: Callable[[Scene, dict], Any], constraints: Callable[[Scene, dict], Any],
                     point: Point, pairs: Sequence[tuple[Hashable, Hashable]],
                     coords: Callable[[Scene, Sequence[Hashable]], list] = real_coordinates
                     ) -> tuple[dict[Hashable, Mat], list[Any]]:
    """The flow of H(t, z) on the product of the cotangent bundles of the (position, momentum)
    pairs, restricted by the constraints F(t, z) = 0 (independent scalar functions, or matrices
    whose entries are): ż = Ω∇H + Σ_i μ_i Ω∇F_i with the multipliers μ solved from dF/dt = 0 (the
    Dirac flow of H for all constraints together).  Returns the tangent vector (a dict like
    ``point``) and μ."""
    _coordinate_scene(s, "a Hamiltonian flow in coordinates")
    positions = coords(s, [p for p, _ in pairs])
    momenta = coords(s, [m for _, m in pairs])
    cx = [derivative(s, H, point, {name: B}) for name, B in positions]
    cp = [derivative(s, H, point, {name: B}) for name, B in momenta]
    Fx = [_flat(derivative(s, constraints, point, {name: B})) for name, B in positions]
    Fp = [_flat(derivative(s, constraints, point, {name: B})) for name, B in momenta]
    N, m = len(positions), len(Fx[0])
    # Ω∇f = (∂f/∂p, −∂f/∂x);  ∇F_j·Ω∇G = Σ ∂F_j/∂x ∂G/∂p − ∂F_j/∂p ∂G/∂x
    def pair(fx, fp, gx, gp):
        return _dot(s, fx, gp) - _dot(s, fp, gx)
    col = lambda rows, j: [rows[a][j] for a in range(N)]
    C = [[pair(col(Fx, j), col(Fp, j), col(Fx, i), col(Fp, i)) for i in range(m)] for j in range(m)]
    b = [[-pair(col(Fx, j), col(Fp, j), cx, cp)] for j in range(m)]
    mu = [row[0] for row in _solve(s, C, b, "the constraint bracket matrix {F_i, F_j}_0")]
    xdot = [cp[a] + _dot(s, Fp[a], mu) for a in range(N)]
    pdot = [-(cx[a] + _dot(s, Fx[a], mu)) for a in range(N)]
    out = _combine(s, positions, xdot, {p: point[p] for p, _ in pairs})
    out.update(_combine(s, momenta, pdot, {q: point[q] for _, q in pairs}))
    return out, mu


# -- generic points of the appendix's phase spaces ------------------------------------------------

def _diag(s: Scene, values: Sequence[Any]) -> Mat:
    r = len(values)
    return s.mat([[values[i] if i == j else s.q(0) for j in range(r)] for i in range(r)], ("r", "r"))


def double_point(s: Scene) -> dict[str, Mat]:
    """A generic point (X, Y, Ẋ, Ẏ) of the rank r double Neumann system: XᵀY = I_r,
    ẊᵀY + XᵀẎ = 0 (keys "X", "Y", "Xdot", "Ydot").

    X = X₀DU with X₀ the scene's point of V(n, r), D diagonal and U unipotent upper triangular
    (every X of rank r, by the QR decomposition), Y = X₀D⁻¹U⁻ᵀ + (I − X₀X₀ᵀ)Z, Ẋ = V generic,
    Ẏ = −Y VᵀY + (I − YXᵀ)W: every point of a dense open subset of the constraint set."""
    _coordinate_scene(s, "a generic point of the double Neumann system")
    r = s.r
    d = [s.scalar(f"double_d{i + 1}") for i in range(r)]
    N = [[s.scalar(f"double_u{i + 1}_{j + 1}") if j > i else s.q(0) for j in range(r)] for i in range(r)]
    U = s.mat([[s.q(1) if i == j else N[i][j] for j in range(r)] for i in range(r)], ("r", "r"))
    Nm = s.mat(N, ("r", "r"))
    Uinv, power = s.Ir, s.Ir
    for _ in range(r - 1):
        power = power @ (-Nm)
        Uinv = Uinv + power
    X0 = s.X
    X = X0 @ _diag(s, d) @ U
    Y = (X0 @ _diag(s, [s.q(1) / x for x in d]) @ Uinv.T
         + (s.In - X0 @ X0.T) @ s.general_params("double_Z", s.n, r, ("n", "r")))
    V = s.general_params("double_V", s.n, r, ("n", "r"))
    W = s.general_params("double_W", s.n, r, ("n", "r"))
    return {"X": X, "Y": Y, "Xdot": V, "Ydot": -(Y @ V.T @ Y) + (s.In - Y @ X.T) @ W}


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
