"""Poisson brackets as objects a claim can use.

Two kinds of brackets:

* brackets of functions of the scene (the phase space T*M_{n,r} or T*V_{n,r}):
  :data:`canonical` ({,}_0 on T*M_{n,r}), :data:`dirac` (the Dirac bracket
  (Dirac_bracket) of the scene's realization: (cond_XP), or (cond_XP2) in a claim
  declared with ``realization="metric"``) and :func:`dirac_bracket_for` (the Dirac
  bracket of any list of symmetric matrix constraints, built from the canonical
  bracket: the L_A bracket {,}_A of §3 is ``dirac_bracket_for(metric_constraints)``);
* Poisson tensors on a matrix space (so(m), Sym(m), gl(n)), given as a bilinear form
  ``form(x, a, b)`` = Λ(a, b)|_x in the covectors a, b, identified with the space by
  <a, b> = −½tr(ab): the Lie–Poisson brackets (±) on so(n) and so(r)
  (:func:`lie_poisson`), the pencil Λ1, Λ2 on gl(n) of (LAMBDA12) (:func:`lambda1`,
  :func:`lambda2`), their combinations ``c1 * T1 + c2 * T2``.

Functions on a matrix space are :class:`MatrixFunction` objects that carry their
gradient for <,> (:func:`linear`, :func:`quadratic`, :func:`trace_power`, sums,
products); ``f.pullback(moment)`` is the function f∘moment of the scene.

Checks (each returns a residual that must vanish): :func:`antisymmetry`,
:func:`jacobiator` (the Jacobi identity of a tensor, from its form alone: the
derivative in x is taken by exact interpolation of a polynomial of the declared
degree along x + t·e_k, over a basis e_k of the space), :func:`compatibility`,
:func:`casimir_residual`, :func:`poisson_map_residual` (a map of the phase space into
a matrix space is Poisson), :func:`phase_jacobiator` (the Jacobi identity of a
bracket of functions of the scene, through nested brackets).

:func:`poisson_checks` and :func:`compatibility` decide statements for every x, a, b, c: they evaluate
them at fresh elements of the space (``s.fresh``: numbered by the engine, new at every call, no name a
claim can spell), and the tensor as one engine step per evaluation (:func:`checked_tensor`), its form
traced as a function of (x, a, b): a tensor that keeps a point it was evaluated at keeps a parameter of
that function, never the test point.

For a tensor affine in x (every tensor of this module), the Jacobi identity for
linear functions with generic covectors a, b, c is the Jacobi identity (the
Jacobiator of coordinate functions is the Schouten bracket [Λ, Λ], a tensor).
"""
from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Any, Callable, Sequence

from stiefelsym.ir.trace import primitive, same_inline_function, same_scene_function, same_step_function
from stiefelsym.backends.matrix import Mat, comm
from stiefelsym.scene import engine_check

Scalar = Any
Function = Callable[[Any], Any]


# ---------------------------------------------------------------------------------
# brackets of functions of the scene

@dataclass(frozen=True)
class PhaseBracket:
    """A bracket of two scalar functions of the scene."""

    name: str
    evaluate: Callable[[Any, Function, Function], Scalar]

    def __call__(self, s: Any, F: Function, G: Function) -> Scalar:
        return self.evaluate(s, F, G)

    def flow_derivative(self, s: Any, F: Function, H: Function) -> Scalar:
        """dF/dt = {F, H} along the Hamiltonian flow of H."""
        return self.evaluate(s, F, H)


#: the canonical bracket {,}_0 on T*M_{n,r} = R^{2nr} (functions of the scene off T*V)
canonical = PhaseBracket("{,}_0 on T*M_{n,r}", lambda s, F, G: s.canonical_bracket(F, G))

#: the Dirac bracket (Dirac_bracket) of the scene's realization of T*V
dirac = PhaseBracket("Dirac bracket on T*V_{n,r}", lambda s, F, G: s.bracket(F, G))


def standard_constraints(t: Any) -> list[Mat]:
    """(cond_XP): XᵀX − I_r, XᵀP + PᵀX."""
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def metric_constraints(t: Any) -> list[Mat]:
    """(cond_XP2): XᵀX − I_r, XᵀA⁻¹P + PᵀA⁻¹X."""
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X]


def _scalar_constraints(constraints: Callable[[Any], Sequence[Mat]], s: Any, keys: dict) -> list[Function]:
    """The entries on and above the diagonal of every matrix of the list ``constraints(s)`` (each square), as
    scalar functions: for a symmetric matrix, each of its conditions once.  (Every matrix of the list: stop 79
    found the first two alone taken, whatever the list's length.)  The list is one function of the scene at
    every call, its length and each of its matrices (``keys``: the bracket's objects that stand for them)."""
    def held(t: Any, k: int | None) -> Any:
        mats = constraints(t)
        value = len(mats) if k is None else mats[k]
        return same_scene_function(keys.setdefault(k, object()), t, value, "the constraints of dirac_bracket_for")
    out = []
    count = held(s, None)
    for k in range(count if type(count) is int else len(constraints(s))):
        M = held(s, k)
        rows, cols = (int(x) for x in M.shape)
        if rows != cols:
            raise ValueError(f"dirac_bracket_for: constraint {k + 1} is a {rows}x{cols} matrix; the constraints are "
                             "symmetric (square) matrices, read by their entries on and above the diagonal")
        for i in range(rows):
            for j in range(i, rows):
                out.append(lambda t, k=k, i=i, j=j: held(t, k)[i, j])
    return out


def dirac_bracket_for(constraints: Callable[[Any], Sequence[Mat]], name: str = "") -> PhaseBracket:
    """The Dirac bracket {f, g} = {f, g}_0 + Σ {F_i, f}_0 C_ij {F_j, g}_0 (Dirac_bracket) for the
    scalar constraints F_i (the entries on and above the diagonal of each matrix of the list ``constraints``,
    symmetric square matrices: a lower triangle is not read), C the inverse of ({F_i, F_j}_0); only the
    canonical bracket of the scene is used."""
    keys: dict = {}

    def evaluate(s: Any, F: Function, G: Function) -> Scalar:
        Fs = _scalar_constraints(constraints, s, keys)
        m = len(Fs)
        if m == 0:
            return s.canonical_bracket(F, G)      # no constraint (an empty list, or 0×0 matrices): {,}_0 itself
        C0 = s.mat([[s.canonical_bracket(Fi, Fj) for Fj in Fs] for Fi in Fs], ("cond", "cond"))
        C = C0.inv()
        FiF = [s.canonical_bracket(Fi, F) for Fi in Fs]
        FjG = [s.canonical_bracket(Fj, G) for Fj in Fs]
        acc = s.canonical_bracket(F, G)
        for i in range(m):
            for j in range(m):
                acc = acc + FiF[i] * C[i, j] * FjG[j]
        return acc
    return PhaseBracket(name or "Dirac bracket of the given constraints", evaluate)


#: the Dirac bracket {,}_A of the constraints (cond_XP2) of the SO(r)-invariant metric L_A (§3)
metric_dirac = dirac_bracket_for(metric_constraints, "Dirac bracket {,}_A of (cond_XP2)")


def phase_jacobiator(s: Any, bracket: PhaseBracket, F: Function, G: Function, H: Function) -> Scalar:
    """{F, {G, H}} + {G, {H, F}} + {H, {F, G}} (nested brackets: the inner bracket is a function of
    the scene, differentiated like any other)."""
    def inner(P: Function, Q: Function) -> Function:
        return lambda t: bracket(t, P, Q)
    return (bracket(s, F, inner(G, H)) + bracket(s, G, inner(H, F)) + bracket(s, H, inner(F, G)))


# ---------------------------------------------------------------------------------
# matrix spaces

def skew(M: Mat) -> Mat:
    """The so-part (M − Mᵀ)/2."""
    return (M - M.T) / 2


def sym(M: Mat) -> Mat:
    """The Sym-part (M + Mᵀ)/2."""
    return (M + M.T) / 2


@dataclass(frozen=True)
class Space:
    """A matrix space so(m), Sym(m) or gl(m) (m = n or r), paired with itself by <a, b> = −½tr(ab)."""

    kind: str   # "so", "sym" or "gl"
    index: str  # "n" or "r"

    def __post_init__(self) -> None:
        if self.kind not in ("so", "sym", "gl") or self.index not in ("n", "r"):
            raise ValueError(f"a matrix space is so, sym or gl over n or r, not {self.kind}({self.index})")

    @property
    def name(self) -> str:
        return f"{self.kind}({self.index})"

    def size(self, s: Any) -> int:
        return s.n if self.index == "n" else s.r

    def project(self, M: Mat) -> Mat:
        """The orthogonal projection of a matrix onto the space (for <,>, so(m) ⊥ Sym(m))."""
        if self.kind == "so":
            return skew(M)
        if self.kind == "sym":
            return sym(M)
        return M

    def generic(self, s: Any, name: str) -> Mat:
        """A generic element (parameters of the claim's own)."""
        return self.project(s.generic(name, self.index, self.index) * 2)

    def fresh(self, s: Any) -> Mat:
        """A fresh generic element (``s.fresh``: parameters no claim can name, new at every call), for a
        statement about every element of the space."""
        return self.project(s.fresh(self.index, self.index) * 2)

    def zero(self, s: Any) -> Mat:
        """The zero of the space."""
        m = self.size(s)
        return s.zeros(m, m, (self.index, self.index))

    def basis(self, s: Any) -> list[tuple[Mat, Mat]]:
        """Pairs (e_k, e_k*) of a basis and its dual basis for <,> (<e_k, e_l*> = δ_kl)."""
        m = self.size(s)
        tags = (self.index, self.index)

        def unit(i, j):
            return s.mat([[s.q(1) if (a, b) == (i, j) else s.q(0) for b in range(m)] for a in range(m)], tags)
        out = []
        if self.kind == "so":
            for i in range(m):
                for j in range(i + 1, m):
                    e = unit(i, j) - unit(j, i)            # <e, e> = 1
                    out.append((e, e))
        elif self.kind == "sym":
            for i in range(m):
                e = unit(i, i)                              # <e, e> = -1/2
                out.append((e, e * (-2)))
                for j in range(i + 1, m):
                    e = unit(i, j) + unit(j, i)            # <e, e> = -1
                    out.append((e, -e))
        else:
            for i in range(m):
                for j in range(m):
                    out.append((unit(i, j), unit(j, i) * (-2)))   # <E_ij, E_kl> = -1/2 δ_jk δ_il
        return out


SO_N, SO_R, GL_N, SYM_N = Space("so", "n"), Space("so", "r"), Space("gl", "n"), Space("sym", "n")


def pairing(s: Any, a: Mat, b: Mat) -> Scalar:
    """<a, b> = −½tr(ab)."""
    return s.killing(a, b)


# ---------------------------------------------------------------------------------
# functions on a matrix space, with their gradients

@dataclass(frozen=True)
class MatrixFunction:
    """A scalar function h on a matrix space with its gradient ∇h (dh(δ) = <∇h, δ>, taken in the space of all
    matrices of the point's shape: for an m×k point, ∇h is k×m)."""

    value: Callable[[Any, Mat], Scalar]
    gradient: Callable[[Any, Mat], Mat]
    name: str = "h"

    def __call__(self, s: Any, x: Mat) -> Scalar:
        f = self.value
        v = f(s, x)
        # the value the claim computes with is the one the gradient's check takes (a value that tests its point would
        # have the check pass for another function).  Held under the function object itself, whatever its field
        # holds at this call (a value swapped after the gradient was checked, object.__setattr__ on the frozen
        # dataclass or a subclass's attribute lookup, is another function at one of the calls: stop 81's sweep), and
        # under the value's function too (copies of one function object share it: stop 81's third review)
        for o in (self, f):
            same_inline_function(v, o, s, (x,), f"the value of {self.name}")
        return v

    def grad(self, s: Any, x: Mat) -> Mat:
        """∇h(x), checked: the step :func:`gradient_check` refuses a gradient that is not the value's (a function
        built with a gradient of another, MatrixFunction(lambda s, x: 0, lambda s, x: s.A), had the brackets of a
        function it is not).  The value is one function of the point wherever the claim evaluates it."""
        G = self.gradient(s, x)
        f = self.value
        zero = gradient_check(s, f, x, G)
        for o in (self, f):
            same_step_function(zero, o, f"the value of {self.name}", inline=True)
        return G + zero

    def pullback(self, moment: Callable[[Any], Mat]) -> Function:
        """h∘moment, a function of the scene (its value through the held call, never a subclass's own __call__: the
        function whose gradient is checked, stop 81's third review)."""
        return lambda t: MatrixFunction.__call__(self, t, moment(t))

    # (the values of a sum, a product or a multiple are its parts' values through their held calls, f(s, x): a part
    # whose value tests its point is one function there and in the claim, stop 80's second review)
    def __add__(self, o: "MatrixFunction") -> "MatrixFunction":
        return MatrixFunction(lambda s, x: MatrixFunction.__call__(self, s, x) + MatrixFunction.__call__(o, s, x),
                              lambda s, x: self.gradient(s, x) + o.gradient(s, x), f"({self.name} + {o.name})")

    def __mul__(self, o: "MatrixFunction") -> "MatrixFunction":
        """The product (Leibniz rule for the gradient)."""
        def value(s: Any, x: Mat, f: "MatrixFunction") -> Scalar:
            return MatrixFunction.__call__(f, s, x)
        return MatrixFunction(lambda s, x: value(s, x, self) * value(s, x, o),
                              lambda s, x: self.gradient(s, x) * value(s, x, o) + o.gradient(s, x) * value(s, x, self),
                              f"{self.name}·{o.name}")

    def scaled(self, c: Callable[[Any], Scalar]) -> "MatrixFunction":
        """c·h for a scalar c(s) of the scene (one function of it: its value and its gradient read the same c)."""
        def c_(s: Any) -> Scalar:
            return same_scene_function(c, s, c(s), "the scalar of MatrixFunction.scaled")
        return MatrixFunction(lambda s, x: MatrixFunction.__call__(self, s, x) * c_(s),
                              lambda s, x: self.gradient(s, x) * c_(s), f"c·{self.name}")


def _gradient(f: Any, s: Any, x: Mat) -> Mat:
    """∇f(x), checked (:meth:`MatrixFunction.grad`, never a subclass's own grad: an override would hand the engine a
    gradient no check saw, stop 80's second review)."""
    if not isinstance(f, MatrixFunction):
        raise TypeError(f"a MatrixFunction (a function with its gradient) is expected, not a {type(f).__name__}")
    return MatrixFunction.grad(f, s, x)


def linear(a: Callable[[Any], Mat], name: str = "<x, a>") -> MatrixFunction:
    """h(x) = <x, a(s)>, ∇h = a (one function of the scene: the value and the gradient read the same a; a
    callable whose state, or a test of its scene, makes it another at some call is refused, stop 79)."""
    def a_(s: Any) -> Mat:
        return same_scene_function(a, s, a(s), "the covector of brackets.linear")
    return MatrixFunction(lambda s, x: s.killing(x, a_(s)), lambda s, x: a_(s), name)


def quadratic(op: Callable[[Any, Mat], Mat] | None = None, name: str = "½<x, 𝔸x>") -> MatrixFunction:
    """h(x) = ½<x, op(x)> with op linear and symmetric for <,> (default: the identity), ∇h = op(x).  Every
    evaluation of the gradient checks both (:func:`_check_symmetric`): for another op the gradient is not
    op(x) (for a skew op, h = 0), and the step would hand on the gradient of another function."""
    if op is None:
        return MatrixFunction(lambda s, x: s.killing(x, x) / 2, lambda s, x: x, name)
    op_ = op

    def gradient(s: Any, x: Mat) -> Mat:
        v = op_(s, x)
        zero = symmetric_operator_check(s, op_, x, v)
        # every check of op in the claim is of one function, and its value at x is the gradient's (a stateful
        # op, or one that tests its argument, would have the check pass for another function than the one the
        # gradient uses)
        same_step_function(zero, op_, "the operator of brackets.quadratic", inline=True)
        return v + zero

    def value(s: Any, x: Mat) -> Scalar:
        v = op_(s, x)
        # the op the claim's value computes with is the one the gradient's step checks (stop 79: an op that is
        # B·u at the claim's own point y and u elsewhere made h(y) = ½<y, By> and ∇h = x both hold)
        same_inline_function(v, op_, s, (x,), "the operator of brackets.quadratic")
        return s.killing(x, v) / 2

    return MatrixFunction(value, gradient, name)


def symmetric_operator_check(s: Any, op: Callable[[Any, Mat], Mat], x: Mat, value: Mat) -> Mat:
    """The zero matrix of x's shape, once op is checked linear and symmetric for <,> (:func:`_check_symmetric`)
    and its value at x is the claim's ``value`` (the same function where the claim evaluates it): one step of
    the IR, so that every method makes the check when it evaluates the graph (a check made at the point: inside a
    derivative or a gradient whose variables move its arguments, the scene makes it, see :func:`gradient_check`)."""
    _refuse_on_tape(s, "quadratic's operator")
    _refuse_foreign_numbers(s, (x, value), "quadratic's operator")
    if not _vanishes(s, op(s, x) - value):
        raise ValueError(NOT_SYMMETRIC + " (and one function: its value at x differs between two evaluations)"
                         + _along_flow(s))
    _check_symmetric(s, op, x)
    return x - x


def gradient_check(s: Any, value: Callable[[Any, Mat], Scalar], x: Mat, G: Mat) -> Mat:
    """The zero matrix of G's shape (x's transpose's: <a, b> = −½ tr(ab) pairs an m×k point with a k×m gradient), once ``G`` is the gradient at x of y ↦ value(s, y) for <,> (taken in the space of
    all matrices of x's shape): one step of the IR, so that every method makes the check when it evaluates the
    graph.  A check made at the point: where its arguments move with a derivative along a flow, the scene's dual
    numbers make it in both parts; on a reverse tape it is not taken (:func:`_refuse_on_tape`).  A coordinate scene takes the value's gradient at x by
    reverse mode (over a field without it, or for an operation it does not differentiate, by a basis:
    :func:`polynomial_gradient`); the dimension-free scene by cyclic differentiation at a letter of the engine's
    own, put x in its place (:meth:`~stiefelsym.free.FreeScene.declared_gradient_holds`)."""
    if hasattr(type(s), "_engine_letters"):            # the dimension-free scene
        if not s.declared_gradient_holds(value, x, G):
            raise ValueError(NOT_GRADIENT)
        return G - G
    _refuse_on_tape(s, "MatrixFunction.grad")
    _refuse_foreign_numbers(s, (x, G), "MatrixFunction.grad")
    if not _field_in(s, _AFFINE_CHECKED):
        return G - G
    if not (_value_gradient(s, value, x) - G).is_zero():
        raise ValueError(NOT_GRADIENT + _along_flow(s))
    return G - G


def _numbers(x: Any) -> str:
    """The name of a scene's (or a matrix's) number system: "dual(...)" on a derivative's dual numbers, "reverse(...)"
    on a gradient's tape, "" for anything without one."""
    return getattr(getattr(x, "_field", None), "name", "")


def _along_flow(s: Any) -> str:
    """What a check's refusal adds on the dual numbers of a derivative along a flow (the check compares both parts:
    what holds at the point must hold to first order along the flow)."""
    if "dual(" in _numbers(s):
        return " (inside a derivative along a flow: it holds at the point, not to first order along the flow)"
    return ""


def _refuse_foreign_numbers(s: Any, mats: tuple, what: str) -> None:
    """Refuse a check on a scene whose numbers are not those of its matrices' derivatives: a point (or gradient) that
    moves with a derivative or a gradient taken on another scene (dual numbers, a reverse tape) handed with the
    claim's own scene, f.grad(s, x_t) inside s.d(lambda t: ...).  The check on s would see the value only."""
    name = _numbers(s)
    for M in mats:
        m = _numbers(M) if isinstance(M, Mat) else ""
        # M's numbers wrap the scene's (dual or reverse numbers over them): a derivative or gradient deeper than s
        if m != name and m.startswith(("dual(", "reverse(")) and name in m:
            raise ValueError(f"{what}: taken on a scene at a point (or with a gradient) that moves with a derivative "
                             "or gradient of another scene: take it on the scene of the function being "
                             "differentiated (f.grad(t, x) inside s.d(lambda t: ...))")


def _refuse_on_tape(s: Any, what: str) -> None:
    """Refuse a check step evaluated on a reverse tape (inside the function of a gradient, at arguments that move
    with the gradient's variables): the check holds at the point, which says nothing of the adjoints handed
    through it (a gradient right on V(n, r) and not off it would have its wrong derivative taken).  Refused as an
    operation reverse mode does not differentiate: the caller takes the gradient by forward passes (the scene's
    dual numbers, where the check is made in both parts) or from a basis (:func:`_value_gradient`)."""
    if "reverse(" in _numbers(s):
        from stiefelsym.backends.reverse import Unsupported
        raise Unsupported(f"{what}: a gradient through a check made at the point (its derivative is not checked "
                          "on a reverse tape)")


#: the refusal of a MatrixFunction whose gradient is not its value's
NOT_GRADIENT = ("MatrixFunction: the gradient is not the gradient of the value (dh(δ) = <∇h, δ> for every δ): a "
                "bracket or a flow of h would be taken with another function's gradient")


def _value_gradient(s: Any, value: Callable[[Any, Mat], Scalar], x: Mat) -> Mat:
    """The gradient at x of y ↦ value(s, y) for <,>, in the space of all matrices of x's shape: by reverse mode
    over the scene's numbers where it applies, else from a basis (:func:`polynomial_gradient`)."""
    from stiefelsym.backends.reverse import Unsupported, gradient, leaf
    from stiefelsym.scene import REVERSE_GRADIENTS, ReverseScene, Scene
    if type(s) is Scene and REVERSE_GRADIENTS and _field_in(s, _REVERSE_FIELDS):
        try:
            rs = ReverseScene(s)
            lx = leaf(x._untyped())
            v = value(rs, Mat._wrap_native(lx, rs.field, x.tags, rs.tracker, x._coords))
            D = gradient(v, [lx], s.const(1))[0]
        except (Unsupported, TypeError):
            pass                        # an operation reverse mode does not take (a conjugate, an entry write)
        else:
            if D is None:
                return x * 0
            # dh = Σ ∂h/∂y_ij δ_ij = tr(Dᵀδ) = <−2Dᵀ, δ>
            return D._retyped(s.field, x.tags, s.tracker).T * (-2)
    m, k = x.tags
    if m != k or m not in ("n", "r"):
        raise ValueError("MatrixFunction: the gradient of a function of a matrix that is not n×n or r×r, where the "
                         "scene takes no reverse gradient (inside a derivative along a flow, or over floats or balls)")
    return _polynomial_gradient(s, value, x, "gl", m)


def _vanishes(s: Any, M: Mat) -> bool:
    """Whether a matrix is zero, where the scene's field decides it (else taken as zero: the symmetric check is
    not made there either)."""
    if not hasattr(type(s), "_engine_letters") and not _field_in(s, _AFFINE_CHECKED):
        return True
    return M.is_zero()


#: the refusal of an operator that is not linear and symmetric for <,> (see :func:`quadratic`)
NOT_SYMMETRIC = ("quadratic: the operator must be linear and symmetric for <,> (<y, op(z)> = <z, op(y)>, "
                 "op(y + z) = op(y) + op(z)): the gradient of ½<x, op(x)> is op(x) for such an operator only")


def _check_symmetric(s: Any, op: Callable[[Any, Mat], Mat], x: Mat) -> None:
    """Refuse an op that is not additive and symmetric for <,> at two generic elements y, z of x's space whose
    parameters are the engine's own (on the dimension-free scene, letters no claim can name): additivity makes
    a polynomial op linear over ℚ, and then symmetry makes op(x) the gradient of ½<x, op(x)>.  Decided where the
    field's test of zero decides it; the dimension-free scene tests normal forms."""
    if hasattr(type(s), "_engine_letters"):            # the dimension-free scene
        y, z = s._engine_letters("quadratic", x)
    elif hasattr(type(s), "_engine_params"):
        if not _field_in(s, _AFFINE_CHECKED):
            return
        m, k = x._shape()
        y, z = (s._engine_params(f"quadratic:{t}", m, k, x.tags) for t in ("y", "z"))
    else:
        raise TypeError(f"quadratic: a gradient on a {type(s).__name__}")
    field = s._field
    with engine_check():
        sym = s.killing(y, op(s, z)) - s.killing(z, op(s, y))
        add = op(s, y + z) - op(s, y) - op(s, z)
    if not field.is_zero(sym) or not add.is_zero():
        raise ValueError(NOT_SYMMETRIC + _along_flow(s))


def _power(M: Mat, k: int, one: Mat) -> Mat:
    acc = one
    for _ in range(k):
        acc = acc @ M
    return acc


def trace_power(k: int, *, so_scale: Callable[[Any], Scalar] | None = None,
                sym_scale: Callable[[Any], Scalar] | None = None,
                shift: Callable[[Any], Mat] | None = None, name: str = "") -> MatrixFunction:
    """h(x) = tr(M^k) with M = c₁·(x − xᵀ)/2 + c₂·(x + xᵀ)/2 + B (c₁ = so_scale, c₂ = sym_scale,
    default 1; B = shift, default 0), ∇h = −2k(c₁·skew(M^{k−1}) + c₂·sym(M^{k−1}))."""
    if k < 1:
        raise ValueError("trace_power: k >= 1")

    def one(f: Callable[[Any], Any], what: str) -> Callable[[Any], Any]:
        # the value and the gradient read the same function of the scene (stop 79)
        return lambda s: same_scene_function(f, s, f(s), f"the {what} of brackets.trace_power")
    so_scale = None if so_scale is None else one(so_scale, "so_scale")
    sym_scale = None if sym_scale is None else one(sym_scale, "sym_scale")
    shift = None if shift is None else one(shift, "shift")

    def M_of(s, x):
        h, v = skew(x), sym(x)
        M = (h * so_scale(s) if so_scale is not None else h) + (v * sym_scale(s) if sym_scale is not None else v)
        return M + shift(s) if shift is not None else M

    def identity_like(s, x):
        return s.Ir if x.tags[0] == "r" else s.In

    def value(s, x):
        return _power(M_of(s, x), k, identity_like(s, x)).trace()

    def gradient(s, x):
        Mk = _power(M_of(s, x), k - 1, identity_like(s, x))
        g_so, g_sym = skew(Mk), sym(Mk)
        g_so = g_so * so_scale(s) if so_scale is not None else g_so
        g_sym = g_sym * sym_scale(s) if sym_scale is not None else g_sym
        return (g_so + g_sym) * (-2 * k)
    return MatrixFunction(value, gradient, name or f"tr M^{k}")


# ---------------------------------------------------------------------------------
# Poisson tensors on a matrix space

#: weights w_j with p'(0) = Σ_j w_j p(j) for every polynomial p of degree <= d (j = 0..d)
def _derivative_weights(d: int) -> list[Fraction]:
    pts = list(range(d + 1))
    weights = []
    for j in pts:
        den = Fraction(1)
        for m in pts:
            if m != j:
                den *= (j - m)
        num = Fraction(0)
        for l in pts:
            if l == j:
                continue
            prod = Fraction(1)
            for m in pts:
                if m not in (j, l):
                    prod *= (0 - m)
            num += prod
        weights.append(num / den)
    return weights


@dataclass(frozen=True)
class PoissonTensor:
    """Λ(a, b)|_x = form(s, x, a, b), bilinear in the covectors a, b of the space (identified with
    the space by <,>), polynomial of degree <= ``degree`` in x."""

    space: Space
    form: Callable[[Any, Mat, Mat, Mat], Scalar]
    degree: int = 1
    name: str = "Λ"

    def __call__(self, s: Any, x: Mat, a: Mat, b: Mat) -> Scalar:
        return self._evaluate(s, x, self.space.project(a), self.space.project(b))

    def _evaluate(self, s: Any, x: Mat, a: Mat, b: Mat) -> Scalar:
        """form(s, x, a, b), held to one function: every evaluation of the tensor in the claim (inline, through
        checked_tensor's steps, or as a part of a sum or a multiple) is one function of (x, a, b) (a form that
        tests its point made casimir_residual and checked_tensor two tensors, stop 79)."""
        value = self.form(s, x, a, b)
        same_inline_function(value, self, s, (x, a, b), f"the tensor {self.name}")
        return value

    def bracket(self, s: Any, f: MatrixFunction, g: MatrixFunction, x: Mat) -> Scalar:
        """{f, g}(x) = Λ(∇f, ∇g)|_x (gradients projected onto the space)."""
        return self(s, x, _gradient(f, s, x), _gradient(g, s, x))

    def sharp(self, s: Any, x: Mat, a: Mat) -> Mat:
        """The vector Λ_x(·, a)^♯: <Λ_x(·, a)^♯, c> = Λ_x(c, a) for every c (the Hamiltonian vector
        field of a function with gradient a at x: ẋ = sharp(x, ∇H))."""
        return form_gradient(s, lambda t, c: self(t, x, c, a), x, self.space.kind, self.space.index)

    def __add__(self, o: "PoissonTensor") -> "PoissonTensor":
        if o.space != self.space:
            raise TypeError(f"a sum of tensors on {self.space.name} and {o.space.name}")
        out = PoissonTensor(self.space, lambda s, x, a, b: self._evaluate(s, x, a, b) + o._evaluate(s, x, a, b),
                            max(self.degree, o.degree), f"{self.name} + {o.name}")
        object.__setattr__(out, "_parts", ("add", (self, o)))    # held to the parts' own evaluations (checked_tensor)
        return out

    def scaled(self, c: Callable[[Any], Scalar]) -> "PoissonTensor":
        """c(s)·Λ for a scalar of the scene (a pencil λ1Λ1 + λ2Λ2 is ``T1.scaled(l1) + T2.scaled(l2)``)."""
        def c_(s: Any) -> Scalar:
            return same_scene_function(c, s, c(s), "the scalar of PoissonTensor.scaled")
        out = PoissonTensor(self.space, lambda s, x, a, b: self._evaluate(s, x, a, b) * c_(s), self.degree,
                            f"c·{self.name}")
        object.__setattr__(out, "_parts", ("mul", (self,)))      # held to its part's own evaluations
        return out


def lie_poisson(space: Space, sign: int = 1) -> PoissonTensor:
    """The (±) Lie–Poisson bracket {h1, h2}^±(μ) = ±<μ, [∇h1, ∇h2]> on so(m) or gl(m)."""
    if sign not in (1, -1):
        raise ValueError("sign is +1 or -1")
    return PoissonTensor(space, lambda s, x, a, b: s.killing(x, comm(a, b)) * sign, 1,
                         f"({'+' if sign > 0 else '-'}) Lie-Poisson on {space.name}")


def lambda1() -> PoissonTensor:
    """(LAMBDA12): Λ1(ξ+η, ζ+θ)|_x = <x, [ξ,ζ] + [ξ,θ] + [η,ζ]> on gl(n) = so(n) + Sym(n), the
    Lie–Poisson bracket of the semi-direct product so(n) ⊕_ad Sym(n)."""
    def form(s, x, a, b):
        xi, eta, zeta, theta = skew(a), sym(a), skew(b), sym(b)
        return s.killing(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))
    return PoissonTensor(GL_N, form, 1, "Λ1")


def lambda2() -> PoissonTensor:
    """(LAMBDA12): Λ2(ξ+η, ζ+θ)|_x = <x − A, [ξ+η, ζ+θ]> on gl(n)."""
    return PoissonTensor(GL_N, lambda s, x, a, b: s.killing(x - s.A, comm(a, b)), 1, "Λ2")


def pencil(l1: Callable[[Any], Scalar], l2: Callable[[Any], Scalar]) -> PoissonTensor:
    """Λ_{λ1,λ2} = λ1Λ1 + λ2Λ2."""
    return lambda1().scaled(l1) + lambda2().scaled(l2)


# ---------------------------------------------------------------------------------
# checks

def antisymmetry(s: Any, T: PoissonTensor, x: Mat, a: Mat, b: Mat) -> Scalar:
    """Λ(a, b) + Λ(b, a) at x."""
    return T(s, x, a, b) + T(s, x, b, a)


def form_gradient(s: Any, form: Callable[[Any, Mat], Scalar], point: Mat, kind: str, index: str) -> Mat:
    """The gradient G in the space kind(index) of an affine form y ↦ form(s, y) on it, for <,>:
    form(y) − form(0) = <G, y> for every y of the space (``point`` only gives the shape of y).

    One step of the IR, so that a claim's graph holds no basis and is the same at every size.  A
    coordinate scene sums dual_k·(form(e_k) − form(0)) over a basis e_k of the space; the
    dimension-free scene differentiates the form, evaluated at a fresh letter, cyclically
    (:meth:`~stiefelsym.free.FreeScene.form_gradient`), and projects onto the space (the forms of
    this module project their arguments, so the projection changes nothing there)."""
    space = Space(kind, index)
    own = getattr(type(s), "form_gradient", None)
    if own is not None:
        return space.project(own(s, form, index))
    zero = space.zero(s)
    base = form(s, zero)
    acc = zero
    for e, dual in space.basis(s):
        acc = acc + dual * (form(s, e) - base)
    _check_affine(s, form, space, base, acc)
    return acc


#: fields whose test of zero decides the affinity check of :func:`form_gradient` (exact, or an error bound)
_AFFINE_CHECKED = ("symbolic", "rational", "modular", "float64", "mpmath", "arb")


def _check_affine(s: Any, form: Callable[[Any, Mat], Scalar], space: Space, base: Any, G: Mat) -> None:
    """Refuse a form that is not affine on the space, as the dimension-free scene refuses it: the sum
    over a basis is the gradient only of an affine form (for any other it is a secant through the basis
    vectors).  form(w) − form(0) − <G, w> must vanish at a generic element w of the space, whose
    parameters are the engine's own (Scene._engine_params: independent of the claim's draws, which they do not
    change).  Its homogeneous parts of degree k >= 2 in w vanish with it, so the form is affine."""
    field = getattr(s, "_field", None)
    if not _field_in(s, _AFFINE_CHECKED):
        return
    w = _engine_element(s, space, "form_gradient")
    with engine_check():
        residual = form(s, w) - base - pairing(s, G, w)
    if not field.is_zero(residual):
        raise ValueError("form_gradient: the form is not affine on "
                         f"{space.name} (its gradient is not the sum over a basis; refused, as the "
                         "dimension-free scene refuses it)")


def _field_in(s: Any, fields: tuple[str, ...]) -> bool:
    """Whether the scene's number system (under the dual numbers of a flow, or on a reverse tape: the
    field of the values) is one of ``fields`` (names or their prefixes)."""
    name = _numbers(s)
    while name.endswith(")") and name.startswith(("dual(", "reverse(")):
        name = name[name.index("(") + 1:-1]
    return any(name == f or name.startswith(f) for f in fields)


def _engine_element(s: Any, space: Space, tag: str) -> Mat:
    """A generic element of the space whose parameters are the engine's own (``Scene._engine_params``: independent
    of the claim's draws, which they do not change)."""
    m = space.size(s)
    return space.project(s._engine_params(f"{tag}:w:{space.name}", m, m, (space.index, space.index)))


_affine_form_gradient = form_gradient
form_gradient = primitive(form_gradient, like={"form": "point"}, returns=("like", "point"))
symmetric_operator_check = primitive(symmetric_operator_check, like={"op": "x"}, returns=("like", "x"), zero=True)
gradient_check = primitive(gradient_check, like={"value": "x"}, returns=("like", "G"), zero=True)


#: the fields whose test of zero decides the degree in x that :func:`polynomial_gradient` derives (exact); on
#: the others it interpolates at the highest degree it takes, which is exact for every lower one: a float's or a
#: ball's test of zero only says that 0 lies within the error bound, and a term of higher degree hidden there
#: (K tr(yᵀy) + y₁₁³ with K = 2⁵²) would be taken for absent.  Floats and balls still refuse a form whose
#: difference of order MAX_FORM_DEGREE + 1 is clearly not zero (the exact fields refuse every form beyond it)
_DEGREE_DECIDED = ("symbolic", "rational", "modular")
_DEGREE_BOUNDED = _AFFINE_CHECKED + ("midrad",)
#: the highest degree in x of a form :func:`polynomial_gradient` takes (one evaluation per degree and basis vector)
MAX_FORM_DEGREE = 6


def polynomial_gradient(s: Any, form: Callable[[Any, Mat], Scalar], point: Mat, kind: str, index: str) -> Mat:
    """The gradient G at ``point`` in the space kind(index) of a polynomial form y ↦ form(s, y), for
    <,>: d/dt form(point + t·e)|_{t=0} = <G, e> for every e of the space.

    One step of the IR whose degree is the engine's, never a claim's: the degree d of the form in y is
    derived here, as the least d <= MAX_FORM_DEGREE whose (d+1)-th finite difference
    Δ_w^{d+1} form(point) vanishes along a generic element w of the space (parameters of the engine's
    own, Scene._engine_params: independent of the claim's draws); for a polynomial of degree D > d its part of
    degree D in w is a nonzero multiple of the top part of the form at w, so it does not vanish, and a
    form that is not a polynomial has no such d and is refused.  The derivative along each basis vector
    is then the exact interpolation of t ↦ form(point + t·e) at t = 0, ..., d (for d <= 1:
    :func:`form_gradient`, the affine case).  The dimension-free scene differentiates the form
    cyclically (:meth:`~stiefelsym.free.FreeScene.form_gradient`), which takes affine forms only."""
    space = Space(kind, index)
    own = getattr(type(s), "form_gradient", None)
    if own is not None:
        return space.project(own(s, form, index))
    d = _form_degree(s, form, space, point)
    if d <= 1:
        return _affine_form_gradient(s, form, point, kind, index)
    w = [s.q(q.numerator, q.denominator) for q in _derivative_weights(d)]
    values0 = form(s, point)
    acc = space.zero(s)
    for e, dual in space.basis(s):
        deriv = values0 * w[0]
        for j in range(1, d + 1):
            deriv = deriv + form(s, point + e * j) * w[j]
        acc = acc + dual * deriv
    return acc


def _form_degree(s: Any, form: Callable[[Any, Mat], Scalar], space: Space, point: Mat) -> int:
    """The degree in y of the polynomial form (see :func:`polynomial_gradient`): the least d whose
    (d+1)-th finite difference along a generic element of the space vanishes at ``point``."""
    from math import comb
    decided = _field_in(s, _DEGREE_DECIDED)
    if not decided and not _field_in(s, _DEGREE_BOUNDED):
        return MAX_FORM_DEGREE          # markers: the highest degree's interpolation bounds the others'
    field = s._field
    w = _engine_element(s, space, "polynomial_gradient")
    values = [form(s, point)]
    for d in range(MAX_FORM_DEGREE + 1):
        with engine_check():
            values.append(form(s, point + w * (d + 1)))
        k = d + 1                       # the k-th difference of the values at t = 0, ..., k
        if not decided and d < MAX_FORM_DEGREE:
            continue                    # floats, balls: only the last difference is tested (see _DEGREE_DECIDED)
        diff = None
        for j in range(k + 1):
            term = values[j] * ((-1) ** (k - j) * comb(k, j))
            diff = term if diff is None else diff + term
        if field.is_zero(diff):
            return d
    raise ValueError(f"polynomial_gradient: the form is not a polynomial of degree <= {MAX_FORM_DEGREE} in "
                     f"the point of {space.name} (refused: its gradient is not an interpolation)")


_polynomial_gradient = polynomial_gradient
polynomial_gradient = primitive(polynomial_gradient, like={"form": "point"}, returns=("like", "point"))


def gradient_in_x(s: Any, T: PoissonTensor, x: Mat, b: Mat, c: Mat) -> Mat:
    """The gradient at x of the function y ↦ Λ(b, c)|_y: one engine step :func:`polynomial_gradient`,
    which derives the form's degree in x itself (T.degree, the tensor's declaration, is not read here:
    :func:`degree_residual` checks it as a claim).  A claim's graph holds the step and the form's body
    (no basis: the same graph at every size, which the dimension-free method evaluates by cyclic
    differentiation)."""
    return polynomial_gradient(s, lambda t, y: T(t, y, b, c), x, T.space.kind, T.space.index)


#: the fields whose scenes take the gradient in x by reverse mode (the others by a basis)
_REVERSE_FIELDS = ("symbolic", "rational", "modular")


def jacobiator(s: Any, T: PoissonTensor, x: Mat, a: Mat, b: Mat, c: Mat) -> Scalar:
    """{f_a, {f_b, f_c}} + {f_b, {f_c, f_a}} + {f_c, {f_a, f_b}} at x for the linear functions
    f_a = <·, a>: the Schouten bracket [Λ, Λ](a, b, c) at x."""
    return (T(s, x, a, gradient_in_x(s, T, x, b, c)) + T(s, x, b, gradient_in_x(s, T, x, c, a))
            + T(s, x, c, gradient_in_x(s, T, x, a, b)))


def degree_residual(s: Any, T: PoissonTensor, x: Mat, e: Mat, b: Mat, c: Mat) -> Scalar:
    """The (degree+1)-th finite difference of t ↦ Λ(b, c)|_{x + t e}: zero iff the form is a
    polynomial of degree <= T.degree along the line (which the exact derivative needs)."""
    from math import comb
    d = T.degree + 1
    acc = None
    for j in range(d + 1):
        term = T(s, x + e * j, b, c) * ((-1) ** (d - j) * comb(d, j))
        acc = term if acc is None else acc + term
    return acc


def tensor_value(s: Any, form: Callable[[Any, tuple], Scalar], args: tuple) -> Scalar:
    """form(s, (x, a, b)): one step of the IR whose function ``form`` is traced as a function of its
    argument (x, a, b) alone, at each use (see :func:`checked_tensor`)."""
    return form(s, args)


tensor_value = primitive(tensor_value, like={"form": "args"}, returns=("like", "form"))


def checked_tensor(T: PoissonTensor) -> PoissonTensor:
    """T with each evaluation Λ(a, b)|_x one step :func:`tensor_value`: in a claim's graph the tensor is a
    function of its arguments x, a, b, traced at each evaluation with parameters of its own, so a tensor
    that keeps a point it was evaluated at (state kept between evaluations) keeps a parameter of another
    function, never the point of a check (the graph is then not evaluable: an error, never a verdict)."""
    def form(s: Any, x: Mat, a: Mat, b: Mat) -> Scalar:
        value = tensor_value(s, lambda t, v: T(t, v[0], v[1], v[2]), (x, a, b))
        # every evaluation of the tensor object in the claim is of one form: a form with state (or a test of
        # its arguments) that is another form on some evaluations (Λ for the antisymmetry and degree,
        # Lie–Poisson for the Jacobi identity; Λ in its poisson_checks, another in a compatibility check of
        # T + T2, whose form is the sum of the parts' forms) would have each check pass for no one tensor
        # (the step's function evaluates T through T.__call__, whose every evaluation is a held call: the
        # inline ones of the claim are held to it there)
        same_step_function(value, T, f"the tensor {T.name}", lambda o: getattr(o, "_parts", ("", ())))
        return value
    return PoissonTensor(T.space, form, T.degree, T.name)


def poisson_checks(s: Any, T: PoissonTensor, prefix: str = "") -> dict[str, Scalar]:
    """Additivity in a covector, antisymmetry, polynomial degree and the Jacobi identity of T at a generic point x
    with generic covectors a, b, c and a direction e: fresh elements of the space (:meth:`Space.fresh`), new at
    every call, which the claim can neither name nor keep from another call (the checks say "for every
    x, a, b, c": a tensor built on the test point would be wrong only away from it).  The Jacobi identity of
    linear functions is the Schouten bracket [Λ, Λ] of a bivector only: additive in a (hence linear, the form
    being rational) and antisymmetric, the form is bilinear."""
    sp = T.space
    x, a, b, c, e = (sp.fresh(s) for _ in range(5))
    T = checked_tensor(T)
    p = f"{prefix}: " if prefix else ""
    return {
        f"{p}Λ(a + c, b) − Λ(a, b) − Λ(c, b)": T(s, x, a + c, b) - T(s, x, a, b) - T(s, x, c, b),
        f"{p}Λ(a, b) + Λ(b, a)": antisymmetry(s, T, x, a, b),
        f"{p}degree in x <= {T.degree}": degree_residual(s, T, x, e, b, c),
        f"{p}Jacobi identity": jacobiator(s, T, x, a, b, c),
    }


def compatibility(s: Any, T1: PoissonTensor, T2: PoissonTensor, prefix: str = "") -> dict[str, Scalar]:
    """Jacobi identity of T1 + T2 (compatibility, given that T1 and T2 are Poisson) at a generic
    point with generic covectors (fresh elements, new at every call, as in :func:`poisson_checks`)."""
    sp = T1.space
    # the sum as PoissonTensor makes it (a subclass's own __add__ would build a sum whose parts are not held to
    # the parts' own evaluations)
    T = checked_tensor(PoissonTensor.__add__(T1, T2))
    x, a, b, c = (sp.fresh(s) for _ in range(4))
    p = f"{prefix}: " if prefix else ""
    return {f"{p}Jacobi identity of {T1.name} + {T2.name}": jacobiator(s, T, x, a, b, c)}


def casimir_residual(s: Any, T: PoissonTensor, f: MatrixFunction, x: Mat, b: Mat) -> Scalar:
    """Λ(∇f, b)|_x: zero for every b iff f is a Casimir of Λ at x."""
    return T(s, x, _gradient(f, s, x), b)


def poisson_map_residual(s: Any, bracket: PhaseBracket, moment: Callable[[Any], Mat], T: PoissonTensor,
                         a: Callable[[Any], Mat], b: Callable[[Any], Mat]) -> Scalar:
    """{<moment, a>, <moment, b>} − Λ(a, b)|_{moment}: the map ``moment`` of the phase space into
    T's space is Poisson (linear functions suffice: both sides are biderivations).  The covectors
    a, b are functions of the scene (e.g. ``lambda t: t.generic("a", "n", "n")``), so that they
    are constants of every derived scene.  Each of moment, a, b is called on the scenes of Fa, Fb and on
    the claim's: it must be one function of its scene at every call (a covector that is G in the bracket
    and 2G on the right would have 2Φ "Poisson")."""
    def one(f: Callable[[Any], Mat], what: str) -> Callable[[Any], Mat]:
        return lambda t: same_scene_function(f, t, f(t), what)
    moment, a, b = one(moment, "the map"), one(a, "the covector a"), one(b, "the covector b")
    Fa = lambda t: t.killing(moment(t), a(t))   # noqa: E731
    Fb = lambda t: t.killing(moment(t), b(t))   # noqa: E731
    return bracket(s, Fa, Fb) - T(s, moment(s), a(s), b(s))


__all__ = ["PhaseBracket", "canonical", "dirac", "metric_dirac", "dirac_bracket_for", "standard_constraints",
           "metric_constraints", "phase_jacobiator", "skew", "sym", "Space", "SO_N", "SO_R", "GL_N", "SYM_N",
           "pairing", "MatrixFunction", "form_gradient", "linear", "quadratic", "trace_power", "PoissonTensor", "lie_poisson",
           "lambda1", "lambda2", "pencil", "antisymmetry", "polynomial_gradient", "gradient_in_x", "jacobiator", "degree_residual",
           "poisson_checks", "compatibility", "checked_tensor", "tensor_value", "casimir_residual", "poisson_map_residual"]
