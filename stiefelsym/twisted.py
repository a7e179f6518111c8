"""The twisted (magnetic) symplectic structure of Appendix 1: ω_ε = ω + ε π*ω_mag on T*V_{n,r}.

ω is the canonical form (the restriction of ω₀ = Σ dp_s^i ∧ de_s^i) and ω_mag = Σ_{j<k} F_jk de_j ∧ de_k
for a constant F ∈ so(r); the appendix takes r = 2 and F = E₁∧E₂, i.e. ω_mag = de₁∧de₂ = Σ_i de₁^i∧de₂^i.
Nothing of the paper's magnetic formulas is typed in here: the structure is built exactly as the
Dirac construction (Dirac_bracket) builds the canonical one.

* In the ambient space T*M_{n,r} = ℝ^{2nr}, ω_ε₀ = ω₀ + ε Σ F_jk de_j∧de_k has constant coefficients,
  so it is closed; as a matrix in the coordinates (X, P) it is W = [[εK, −I], [I, 0]] with
  K(V) = V Fᵀ, and it is nondegenerate (det W = 1).  Its Poisson tensor is W⁻¹ = [[0, I], [−I, εK]]:
  {f, g}_ε = {f, g}₀ − ε tr(f_Pᵀ g_P F), with the convention of the scene (i_{X_H} ω = −dH,
  Ẋ = ∂H/∂P, Ṗ = −∂H/∂X when ε = 0).
* T*V is cut out by the constraints (cond_XP); where the matrix {F_i, F_j}_ε is invertible, T*V is a
  symplectic submanifold of (ℝ^{2nr}, ω_ε₀), the Dirac bracket built from {,}_ε is the Poisson bracket of
  the restricted form ω_ε₀|_{T*V} = ω + ε π*ω_mag, and the Dirac flow of H is its Hamiltonian vector field.

The functions take a coordinate scene (a fixed n, r); the dimension-free backend has no so(r)-valued
constant F and refuses them (NeedsCoordinates), so its method answers ``undecided``.
"""
from __future__ import annotations

import copy
from typing import Any, Callable, Mapping

from stiefelsym.backends.fields import DegenerateError, Dual, DualField
from stiefelsym.backends.matrix import Mat, _refused
from stiefelsym.scene import ConstantScene, Flow, Scene, _LiftedScene, _built_over, _lifted_to
from stiefelsym.ir.trace import PRIMITIVES, TraceScene, primitive

Function = Callable[[Any], Any]


def _scene(s: Any, what: str) -> Scene:
    if isinstance(s, TraceScene):
        # a coordinate helper traced with the claim: it reads the sizes, so it needs fixed ones
        if s._t.symbolic:
            s._t.refuse(f"{what} needs coordinates (fixed n, r)")
        return s
    s = s
    if not isinstance(s, Scene):
        raise _refused(getattr(s, "_tracker", None), what)   # recorded before it is raised
    return s


def magnetic_matrix(s) -> Mat:
    """F = E₁∧E₂ ∈ so(2) (the r×r matrix [[0, 1], [−1, 0]]): ω_mag = Σ_{j<k} F_jk de_j∧de_k = de₁∧de₂.
    (Dimension-free, for a claim stated at r = 2 only: E₁E₂ᵀ − E₂E₁ᵀ in the column letters.)"""
    if _at_point(s):
        return s.lift(magnetic_matrix(s.inner))
    if _is_free(s):
        E1, E2 = s.column(0), s.column(1)
        return s._cached("twisted:F", lambda: E1 @ E2.T - E2 @ E1.T)
    s = _scene(s, "the magnetic form de_1 ∧ de_2 (a constant element of so(2))")
    if s.r != 2:
        raise ValueError(f"the magnetic form de_1 ∧ de_2 lives on V(n, 2), not on V({s.n}, {s.r})")
    return s._cached("twisted:F", lambda: s.mat([[0, 1], [-1, 0]], ("r", "r")))


def _field_strength(s, F: Mat | None) -> Mat:
    F = magnetic_matrix(s) if F is None else F
    if not isinstance(F, Mat):
        raise TypeError("the field strength F is an r x r skew matrix of the scene")
    return F


Pair = tuple  # (d/dX, d/dP): a covector or a vector of the ambient space, as two n x r matrices


def _pair_dot(s: Scene, u: Pair, v: Pair) -> Any:
    """⟨u, v⟩ = tr(u_Xᵀ v_X) + tr(u_Pᵀ v_P) (the scene's pairing: the sums of the entrywise products,
    not the whole products u_Xᵀ v_X)."""
    return s._pair_dot(u, v)


def _stack(s: Scene, pairs: list[Pair]) -> Mat:
    """The pairs (u_X, u_P) as the rows (entries of u_X, then of u_P) of one matrix, so that the
    products ⟨u_i, v_j⟩ of two lists are one matrix product."""
    return Mat._rows([list(u[0]._view().flat) + list(u[1]._view().flat) for u in pairs], s.field)


def _pair_dots(s: Scene, us: list[Pair], vs: list[Pair]) -> list[list[Any]]:
    """The matrix ⟨u_i, v_j⟩ (one product of the stacked pairs)."""
    if not us or not vs:
        return [[] for _ in us]
    C = (_stack(s, us) @ _stack(s, vs).T)._view()
    return [[C[i, j] for j in range(len(vs))] for i in range(len(us))]


def _pi(s: Scene, v: Pair, F: Mat) -> Pair:
    """W⁻¹ v: the ambient twisted Poisson tensor applied to a covector v = (v_X, v_P)."""
    return (v[1], -v[0] - s.eps * (v[1] @ F))


def _constraint_gradients(s: Scene) -> list[Pair]:
    """The gradients of the scalar constraints (scalar) as pairs of n x r matrices (the scene's own)."""
    grads = getattr(s, "_constraint_gradients", None)
    if grads is not None:
        return grads()
    out = []
    for row in s._constraint_jacobian():
        f = s._split(row)
        out.append((f.Xdot, f.Pdot))
    return out


def _key(F: Mat | None) -> str:
    return "default" if F is None else str(id(F))


def ambient_bracket(s, f: Function, g: Function, F: Mat | None = None) -> Any:
    """{f, g}_ε = {f, g}₀ − ε tr(f_Pᵀ g_P F): the Poisson bracket of ω₀ + ε Σ F_jk de_j∧de_k on ℝ^{2nr}."""
    s = _scene(s, "the ambient twisted bracket")
    F = _field_strength(s, F)
    return _pair_dot(s, s.gradient(f), _pi(s, s.gradient(g), F))


def constraint_bracket_matrix(s, F: Mat | None = None) -> list[list[Any]]:
    """The matrix {F_i, F_j}_ε of the scalar constraints (scalar) for the twisted ambient bracket."""
    s = _scene(s, "the twisted constraint bracket matrix")
    Fm = _field_strength(s, F)

    def build():
        G = _constraint_gradients(s)
        return _pair_dots(s, G, [_pi(s, gj, Fm) for gj in G])   # ⟨∇F_i, W⁻¹∇F_j⟩
    return s._cached_for("twisted:C0:" + _key(F), Fm, build)


def _inverse(s: Scene, F: Mat | None) -> list[list[Any]]:
    Fm = _field_strength(s, F)

    def build():
        C0 = constraint_bracket_matrix(s, F)
        base = _dual_base(s, F)
        if base is not None:
            return _dual_inverse(s, _inverse(base, None), C0)
        m = len(C0)
        I = [[s.const(1 if i == j else 0) for j in range(m)] for i in range(m)]
        try:
            return s.field.solve(C0, I)
        except DegenerateError as exc:
            raise DegenerateError("the twisted constraint bracket matrix {F_i, F_j}_eps is singular here") from exc
    return s._cached_for("twisted:C:" + _key(F), Fm, build)


def _dual_base(s: Scene, F: Mat | None) -> Scene | None:
    """For a scene over dual numbers a + bε lifted from a base scene (a derivative along a tangent
    vector), that base scene (whose values are the a parts of this one's), else None."""
    from stiefelsym.scene import TangentScene
    s = s
    if F is not None or not isinstance(s, TangentScene) or not isinstance(s.field, DualField):
        return None
    base = s.base
    return base if isinstance(base, Scene) and base.field is s.field.base else None


def _dual_inverse(s: Scene, Ca: list[list[Any]], C0: list[list[Any]]) -> list[list[Any]]:
    """(C_a + C_b ε)⁻¹ = C_a⁻¹ − C_a⁻¹ C_b C_a⁻¹ ε from the inverse of the a part (Ca = C_a⁻¹, taken once
    on the base scene): the same solution as the dual-number solve, with no elimination."""
    bf = s.field.base
    C1 = Mat._rows([[s.field.lift(x).b for x in row] for row in C0], bf)
    Cm = Mat._rows(Ca, bf)
    Y1 = (-(Cm @ C1 @ Cm))._view()
    m = len(Ca)
    return [[Dual(Ca[i][j], Y1[i, j]) for j in range(m)] for i in range(m)]


def _at_point(s: Any) -> bool:
    from stiefelsym.free.scene import FreePointScene
    return isinstance(s, FreePointScene)


def bracket(s, f: Function, g: Function, F: Mat | None = None) -> Any:
    """The Dirac bracket (Dirac_bracket) built from {,}_ε: the Poisson bracket of ω + ε π*ω_mag on T*V.
    (Dimension-free: the derivative of f along the twisted flow of g, for a field strength F of so(r).)"""
    if _at_point(s):
        return s.lift(bracket(s.inner, s._lower(f), s._lower(g), s._lower(F)))   # functions checked for captures
    if _is_free(s):
        return s.d(f, _free_flow(s, g, F))
    s = _scene(s, "the twisted Dirac bracket")
    return _bracket(s, F, lambda: (s.gradient(f), s.gradient(g)))


def _bracket(s: Scene, F: Mat | None, gradients: Callable[[], tuple[Pair, Pair]]) -> Any:
    """The twisted Dirac bracket of two functions on a coordinate scene, from their gradients
    (``gradients``, taken after the constraint bracket matrix is built, as the scene draws ε first)."""
    Fm = _field_strength(s, F)
    G = _constraint_gradients(s)
    C = _inverse(s, F)
    gf, gg = gradients()
    pig = _pi(s, gg, Fm)                                     # W⁻¹∇g
    acc = _pair_dot(s, gf, pig)
    if not G:
        return acc
    SG = _stack(s, G)
    Fif = SG @ _stack(s, [_pi(s, gf, Fm)]).T                 # {F_i, f}_ε, a column
    Fjg = SG @ _stack(s, [pig]).T                            # {F_j, g}_ε, a column
    corr = (Fif.T @ Mat._rows(C, s.field) @ Fjg)._view()[0, 0]   # Σ_ij {F_i, f}_ε C_ij {F_j, g}_ε
    return s.field.normalize(acc + corr)


def ambient_flow(s, H: Function, F: Mat | None = None) -> Flow:
    """The Hamiltonian vector field of H for ω₀ + ε Σ F_jk de_j∧de_k on ℝ^{2nr}: Ẋ = H_P, Ṗ = −H_X − εH_P F."""
    s = _scene(s, "the ambient twisted flow")
    Fm = _field_strength(s, F)
    HX, HP = s.gradient(H)
    return Flow(HP, -HX - s.eps * (HP @ Fm))


def flow(s, H: Function, F: Mat | None = None) -> Flow:
    """dz/dt = {z, H} for the twisted Dirac bracket, z = entries of X, P: the Hamiltonian vector field of
    H for ω_ε = ω + ε π*ω_mag on T*V.  On the dimension-free scene (for a field strength F given as a
    letter of so(r), e.g. s.eta) it is the Lagrange form of :func:`multiplier_flow` with Λ, Π solved in
    the free algebra."""
    if _at_point(s):
        return s.lift(flow(s.inner, s._lower(H), s._lower(F)))   # H checked for captures of the point
    if _is_free(s):
        return _free_flow(s, H, F)
    s = _scene(s, "the Hamiltonian flow of the twisted form")
    return _flow(s, H, F, lambda: s.gradient(H))


def _flow(s: Scene, H: Function, F: Mat | None, gradient: Callable[[], Pair]) -> Flow:
    """The twisted flow of H on a coordinate scene from H's gradient (``gradient``, taken after the
    constraint bracket matrix is built, as the scene draws ε first)."""
    Fm = _field_strength(s, F)

    def build():
        G = _constraint_gradients(s)
        C = _inverse(s, F)
        zX, zP = _pi(s, gradient(), Fm)                     # W⁻¹∇H
        FjH = [_pair_dot(s, g, (zX, zP)) for g in G]        # {F_j, H}_ε
        w = [s.field.normalize(sum((c * x for c, x in zip(Ci, FjH)), s.const(0))) for Ci in C]
        for wi, g in zip(w, G):                             # {z, F_i}_ε = W⁻¹∇F_i
            gX, gP = _pi(s, g, Fm)
            zX = zX - gX * wi
            zP = zP - gP * wi
        return Flow(zX, zP)
    return s._cached_for("twisted:flow", H, build) if F is None else build()


def _is_free(s: Any) -> bool:
    from stiefelsym.free import FreeScene
    return isinstance(s, FreeScene)


def _free_flow(s, H: Function, F: Mat | None) -> Flow:
    """The twisted flow in the free algebra: Ẋ = H_P − XΠ, Ṗ = −H_X − εẊF + XΛ + PΠ, with Π, Λ solved
    from d/dt(XᵀX) = 0 and d/dt(XᵀP + PᵀX) = 0 (the same construction as the scene's Dirac flows)."""
    from stiefelsym.free.scene import LAMBDA, PI, P as LP, X as LX, FreeTangentScene, FunctionScene, _w, \
        solve_multipliers
    if isinstance(s, FreeTangentScene):
        # a flow built inside a derivative (the scene of entries a + bε): refused as the Dirac flows are
        # there (dirac_flow of the tangent scene records the refusal and raises)
        return s.dirac_flow(H)
    own = isinstance(s, FunctionScene)  # inside a function: solved at X, P, renamed to its fresh letters
    if own:
        s.refuse_ambient_flow()
    if F is None:
        F = magnetic_matrix(s)   # the columns E_1, E_2 of a claim at r = 2 (refused otherwise)
    from stiefelsym.free.algebra import substitute

    def build():
        f = F._a[0, 0]
        HX, HP = (m._a[0, 0] for m in s._gradient(H))
        if own:     # a field strength that closes over a value of the base point is refused as H is
            HX, HP, f = s.to_point(HX, HP, f)
        nf = s.system.normal_form
        x, p = _w(LX), _w(LP)
        Pi, Lam = _w(PI), _w(LAMBDA)
        Xd = HP - x * Pi
        Pd = -HX - s.eps * (Xd * f) + x * Lam + p * Pi
        eq_XX = nf(Xd.star() * x + x.star() * Xd)
        eq_XP = nf(Xd.star() * p + x.star() * Pd + Pd.star() * x + p.star() * Xd)
        solved = solve_multipliers([eq_XX, eq_XP], [PI, LAMBDA], s.system)
        Xd, Pd = (nf(substitute(v, solved)) for v in (Xd, Pd))
        if own:
            Xd, Pd = s.from_point(Xd, Pd)
        return Flow(s._const_mat(Xd), s._const_mat(Pd))
    return s._cached_for("twisted:flow:" + str(f_key(F)), H, build)


def f_key(F: Mat) -> str:
    """A cache key of a field strength of the free scene (its polynomial)."""
    return str(F._a[0, 0])


def multiplier_flow(s, H: Function, F: Mat | None = None) -> Flow:
    """The Lagrange form of the twisted flow: Ẋ = H_P − XΠ, Ṗ = −H_X − εẊF + XΛ + PΠ (the Lorentz force
    −εẊF), with symmetric Λ, Π solved from the condition that (cond_XP) is preserved.  An independent
    derivation of :func:`flow` (the constraints' gradients moved by W⁻¹)."""
    s = _scene(s, "the Lagrange form of the twisted flow")
    Fm = _field_strength(s, F)

    def build():
        HX, HP = s.gradient(H)
        base = (HP, -HX - s.eps * (HP @ Fm))

        def direction(name, XE, PE):
            if name == "Lambda":
                return (s.zeros(s.n, s.r, ("n", "r")), XE)
            return (-XE, PE + s.eps * (XE @ Fm))
        Lam, Pi = s._solve_multipliers(base, direction, "the multipliers Lambda, Pi of the twisted flow")
        Xd = HP - s.X @ Pi
        Pd = -HX - s.eps * (Xd @ Fm) + s.X @ Lam + s.P @ Pi
        return Flow(Xd, Pd, multipliers={"Lambda": Lam, "Pi": Pi})
    return s._cached_for("twisted:mflow", H, build) if F is None else build()


def form(s, u: Mapping[str, Mat], v: Mapping[str, Mat], F: Mat | None = None) -> Any:
    """ω_ε(u, v) = (u_P, v_X) − (u_X, v_P) + ε Σ F_jk (u_j, v_k) for tangent vectors u, v (dicts with
    components "X", "P"); the canonical part is ω₀ = Σ dp∧de, the magnetic part ε Σ_{j<k} F_jk de_j∧de_k."""
    if not _is_free(s):
        s = _scene(s, "the twisted symplectic form")
    Fm = _field_strength(s, F)
    uX, uP, vX, vP = u["X"], u["P"], v["X"], v["P"]
    return s.field.normalize(s.tr(uP.T @ vX) - s.tr(uX.T @ vP) + s.eps * s.tr(uX @ Fm @ vX.T))


def basis_vector(s, i: int) -> Mat:
    """E_{i+1} ∈ ℝʳ as a column (index space ("r", "?")), so that XE_{i+1} = e_{i+1}: the appendix writes
    its flows column by column.  The dimension-free backend has the columns E₁, E₂ as letters for a
    claim stated at r = 2 only (NeedsCoordinates otherwise)."""
    if _at_point(s):
        return s.lift(basis_vector(s.inner, i))
    if _is_free(s):
        return s.column(i)
    s = _scene(s, f"the column e_{i + 1} = X E_{i + 1} (a basis vector of R^r)")
    if not 0 <= i < s.r:
        raise ValueError(f"E_{i + 1} is not a basis vector of R^{s.r}")
    return s.mat([[1 if j == i else 0] for j in range(s.r)], ("r", "?"))


def coordinate_projector(s, k: int) -> Mat:
    """D_k = diag(1, ..., 1, 0, ..., 0) (k ones) on ℝʳ: the splitting ℝʳ = ℝᵏ ⊕ ℝʳ⁻ᵏ of the first k columns
    (NeedsCoordinates on the dimension-free backend)."""
    s = _scene(s, f"the first {k} columns of X (the splitting of R^r)")
    return s.mat([[1 if i == j and i < k else 0 for j in range(s.r)] for i in range(s.r)], ("r", "r"))


def first_basis_vectors(s, k: int) -> Mat:
    """The r × k matrix (E_1, ..., E_k) (column space untyped): X(E_1, ..., E_k) = (e_1, ..., e_k)."""
    s = _scene(s, f"the first {k} columns of X")
    return s.mat([[1 if i == j else 0 for j in range(k)] for i in range(s.r)], ("r", "?"))


def last_basis_vector(s) -> Mat:
    """E_r ∈ ℝʳ: X E_r is the last column (e_n of 𝒳 ∈ SO(n) when r = n); a letter of the dimension-free
    backend (E_rᵀE_r = 1)."""
    if _at_point(s):
        return s.lift(last_basis_vector(s.inner))
    if _is_free(s):
        return s.last_column()
    s = _scene(s, "the last column e_n = X E_n of X in SO(n)")
    return basis_vector(s, s.r - 1)


def block_projector(s, i: int) -> Mat:
    """The orthogonal projector of ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂} (r₁ = ⌈r/2⌉, r₂ = ⌊r/2⌋) onto its first (i = 0:
    diag(I_{r₁}, 0)) or second (i = 1: diag(0, I_{r₂})) block.  Letters D, C of the dimension-free backend
    with D = Dᵀ = D², C = Cᵀ = C², DC = CD = 0 and nothing else, so what is proved there holds for every
    pair of orthogonal blocks of ℝʳ."""
    if _at_point(s):
        return s.lift(block_projector(s.inner, i))
    if _is_free(s):
        return s.split_projector(i)
    s = _scene(s, "the splitting of R^r into its first ceil(r/2) and last floor(r/2) coordinates")
    if i not in (0, 1):
        raise ValueError(f"a splitting of R^r into two blocks has no block {i + 1}")
    r1 = (s.r + 1) // 2
    return s.mat([[1 if j == k and (j < r1) == (i == 0) else 0 for k in range(s.r)] for j in range(s.r)],
                 ("r", "r"))


def reflection(s) -> Mat:
    """S₁ = diag(−1, 1, ..., 1), the reflection of ℝⁿ in the first coordinate hyperplane (it commutes with A
    diagonal; every S_i is S₁ up to a relabelling of the coordinates).  A letter S of the dimension-free
    backend with S = Sᵀ, S² = I_n, SA = AS and nothing else, so what is proved there holds for every orthogonal
    symmetry that commutes with A (every S_i and every product of them)."""
    if _at_point(s):
        return s.lift(reflection(s.inner))
    if _is_free(s):
        return s.reflection()
    s = _scene(s, "the reflection S_1 of R^n in the first coordinate hyperplane")
    return s.mat([[(-1 if i == 0 else 1) if i == j else 0 for j in range(s.n)] for i in range(s.n)], ("n", "n"))


def eigenspace_projector(s) -> Mat:
    """D = diag(I_2, 0) on ℝⁿ (n ≥ 2; I_2 at n = 2): the projector onto the span of the first two coordinate
    vectors, an eigenspace of the matrices A = αD + (I − D)B(I − D) a claim builds with it.  A letter D of the
    dimension-free backend with D = Dᵀ = D² and nothing else, so what is proved there holds for every
    orthogonal projector of ℝⁿ (every eigenspace of every symmetric A)."""
    if _at_point(s):
        return s.lift(eigenspace_projector(s.inner))
    if _is_free(s):
        return s.projector_n()
    s = _scene(s, "the projector of R^n onto its first two coordinates")
    return s.mat([[1 if i == j and i < 2 else 0 for j in range(s.n)] for i in range(s.n)], ("n", "n"))


def kernel_frame(s) -> Mat:
    """W, a generic constant n×r matrix (parameters of the engine's at fixed sizes, W_ij, which no claim can
    name: a claim's s.generic("W", "n", "r") is a matrix of its own, as on the dimension-free backend): the
    frame whose orthogonal complement ker Wᵀ is the subspace :func:`kernel_annihilator` annihilates.  A letter W
    of the dimension-free backend (with its transpose), tied to that annihilator."""
    if _at_point(s):
        return s.lift(kernel_frame(s.inner))
    if _is_free(s):
        return s.kernel_frame()
    s = _scene(s, "a generic constant n x r matrix W")
    return s._cached("kernel frame", lambda: s._general_params("kernel_W", s.n, s.r, ("n", "r")))


def _det(rows: list) -> Any:
    """det of a square list of lists of scalars (first-row expansion; 1 for the empty matrix)."""
    if not rows:
        return 1
    acc = 0
    for j in range(len(rows)):
        minor = _det([row[:j] + row[j + 1:] for row in rows[1:]])
        acc = acc + rows[0][j] * minor if j % 2 == 0 else acc - rows[0][j] * minor
    return acc


def kernel_annihilator(s) -> Mat:
    """K = det(WᵀW)·I_n − W adj(WᵀW) Wᵀ for W = :func:`kernel_frame`: det(WᵀW) times the orthogonal projector
    onto ker Wᵀ, a polynomial in W (symmetric, KW = 0).  A symmetric letter K of the dimension-free backend
    with KW = 0 (and WᵀK = 0) and nothing else, so what is proved there holds for every symmetric K with
    KW = 0 (the projector onto ker Wᵀ and its multiples among them)."""
    if _at_point(s):
        return s.lift(kernel_annihilator(s.inner))
    if _is_free(s):
        return s.kernel_annihilator()
    s = _scene(s, "the projector onto ker W^T, W a generic n x r matrix")
    W = kernel_frame(s)
    G = W.T @ W
    g = [[G[i, j] for j in range(s.r)] for i in range(s.r)]
    idx = range(s.r)
    adj = s.mat([[_det([[g[a][b] for b in idx if b != i] for a in idx if a != j]) * (1 if (i + j) % 2 == 0 else -1)
                  for j in idx] for i in idx], ("r", "r"))
    return s.scalar_matrix(_det(g), s.n, "n") - W @ adj @ W.T


def leading_basis_vectors(s) -> Mat:
    """(E_1, ..., E_{r−1}): X(E_1, ..., E_{r−1}) = (e_1, ..., e_{n−1}) when r = n (iden1); a letter of the
    dimension-free backend (its columns and E_r are those of I_r)."""
    if _at_point(s):
        return s.lift(leading_basis_vectors(s.inner))
    if _is_free(s):
        return s.leading_columns()
    s = _scene(s, "the columns e_1, ..., e_(n-1) of X in SO(n)")
    return first_basis_vectors(s, s.r - 1)


def column_splittings(s) -> list[int]:
    """k = 1, ..., r − 1: the splittings of the columns into the first k and the last r − k."""
    s = _scene(s, "the splittings of the columns of X into the first k and the last r - k")
    return list(range(1, s.r))


def at_point(s, X: Mat, P: Mat) -> Scene:
    """The scene's problem at another point (X, P) of T*V (same field, parameters and record): its
    gradients, brackets and flows, the twisted ones included, are taken at (X, P).  (X, P) must lie on
    T*V (a claim checks the constraints it relies on)."""
    if _is_free(s):
        return s.at_point(X, P)
    s = _scene(s, "the flows at another point (X, P) of T*V, given by matrices")
    if s.realization != "standard":
        raise ValueError("a scene at another point is offered for the realization (cond_XP) only")
    for M, name in ((X, "X"), (P, "P")):
        if not isinstance(M, Mat) or M._a.shape != (s.n, s.r):
            raise TypeError(f"{name} must be an n x r matrix of the scene")
    # the field of the point: s's, or that of a scene inside s's function whose values X or P are (their
    # derivative parts kept in their levels: the problem is then taken over that field, s's primitives constants)
    top = s.field
    for M, name in ((X, "X"), (P, "P")):
        if M._field is top or _built_over(top, M._field):
            continue
        if not _built_over(M._field, top):
            raise TypeError(f"{name} is a value of a scene on another chain of derivative levels than the "
                            "scene's and the other component's")
        top = M._field
    if top is not s.field or isinstance(s, _LiftedScene):
        # over a field built on s's, or from a derivative's or a gradient's scene, whose primitives are its
        # base's lifted and some of whose values have closed forms in its base's point (a tangent scene's Φ,
        # Ψ): a scene of its own, every primitive a constant of it and every value computed from the point
        s = ConstantScene(s, top)
    point = []
    for M, name in ((X, "X"), (P, "P")):
        if M._field is not top:
            M = _lifted_to(M, top, s.tracker, name)     # a value of an enclosing scene: a constant here
        point.append(Mat._wrap(M._a.copy(), top, ("n", "r"), s.tracker, M._coords))
    other = copy.copy(s)            # the same problem: field, chart, parameters, record, options
    other._cache = {}
    other._point_given = True       # on V only if the claim made it so: no closed form is taken on trust
    other._cache["point"] = tuple(point)
    return other


__all__ = ["magnetic_matrix", "ambient_bracket", "constraint_bracket_matrix", "bracket", "ambient_flow",
           "flow", "multiplier_flow", "form", "basis_vector", "coordinate_projector", "first_basis_vectors",
           "last_basis_vector", "leading_basis_vectors", "block_projector", "reflection", "eigenspace_projector",
           "kernel_frame", "kernel_annihilator", "column_splittings", "at_point"]

# the functions that need the engine's scene (its number system, its gradients and multipliers) are
# single steps of a claim's graph; the coordinate helpers above are traced with the claim
def _traced_field_strength(t: Any, bound: dict) -> None:
    """While a claim is traced: a field strength F given to a step of this module must be skew by its
    construction (:func:`stiefelsym.ir.passes.skew_by_construction`): the twisted form ω₀ + ε Σ F_jk de_j∧de_k
    and its Poisson tensor are defined for F ∈ so(r) only, and a matrix that is not skew would make the
    Dirac bracket of the fixed sizes and the derivative along the flow of the dimension-free algebra two
    different things.  The refusal is decided from the graph: the same for every method."""
    from stiefelsym.ir.passes import skew_by_construction
    from stiefelsym.ir.trace import MAT, Tracer
    F = bound.get("F")
    if F is None:
        return
    if type(F) is not Tracer or F._kind != MAT:
        t.refuse("the field strength F is an r x r skew matrix of the scene")
        return
    if not skew_by_construction(t.g, F._r):
        t.refuse("the field strength F must be skew by its construction: a generic skew matrix "
                 "(s.generic(name, 'r', 'r', 'skew')), s.eta, the magnetic F, M - M.T, an explicit matrix with "
                 "opposite entries across a zero diagonal, or sums and multiples by numbers of these")


for _name in ("ambient_bracket", "constraint_bracket_matrix", "bracket", "ambient_flow", "flow",
              "multiplier_flow", "form"):
    globals()[_name] = primitive(globals()[_name], check=_traced_field_strength)
magnetic_matrix = primitive(magnetic_matrix, returns=("mat", ("r", "r")))
# the basis vectors of R^r do not move with the point: their derivative along a flow is 0
for _name in ("basis_vector", "last_basis_vector", "leading_basis_vectors", "block_projector", "reflection",
              "eigenspace_projector", "kernel_frame", "kernel_annihilator"):
    globals()[_name] = primitive(globals()[_name], constant=True)
at_point = primitive(at_point, returns="scene")


# the flow and the bracket with the gradients the graph computed (see :mod:`stiefelsym.ir.derivative`,
# which rewrites ``flow(s, H)`` and ``bracket(s, f, g)`` into these on a coordinate scene)
def graph_flow(s: Scene, H: Function, F: Mat | None, eps: Any, pair: Pair) -> Flow:
    """:func:`flow` of H for the field strength F with H's gradient ``pair`` computed by the graph
    (``eps``: the scene's ε, drawn before H is evaluated, as :func:`flow` draws it).  Engine step of the
    transformed graphs."""
    s = _scene(s, "the Hamiltonian flow of the twisted form")
    return _flow(s, H, F, lambda: pair)


def graph_bracket(s: Scene, f: Function, g: Function, F: Mat | None, eps: Any, pf: Pair, pg: Pair) -> Any:
    """:func:`bracket` of f and g for the field strength F with their gradients ``pf``, ``pg`` computed
    by the graph.  Engine step of the transformed graphs."""
    s = _scene(s, "the twisted Dirac bracket")
    return _bracket(s, F, lambda: (pf, pg))


def graph_solve(s: Scene, C: Mat, b: Mat, F: Mat) -> Mat:
    """x with C x = b for C the constraint bracket matrix {F_i, F_j}_ε of the field strength F at the scene's
    point, as the graph computed it (the XᵀX constraints, then the XᵀP + PᵀX ones): x = C⁻¹b with the
    scene's own inverse, the one its flows and brackets use (over an exact field, C is checked to be the
    scene's matrix).  Engine step of the transformed graphs (a magnetic bracket as graph nodes)."""
    s = _scene(s, "the twisted Dirac bracket")
    key = None if F is s._cache.get("twisted:F") else F
    if s.field.exact and not (C - Mat._rows(constraint_bracket_matrix(s, key), s.field, C.tags)).is_zero():
        raise AssertionError("the graph's constraint bracket matrix is not the scene's")
    Cinv = Mat._rows(_inverse(s, key), s.field, (C.tags[1], C.tags[0]), b.tracker)
    return Cinv @ b


PRIMITIVES[f"{__name__}.flow:graph"] = graph_flow
PRIMITIVES[f"{__name__}.bracket:graph"] = graph_bracket
PRIMITIVES[f"{__name__}.solve:graph"] = graph_solve
