"""Brackets as objects: the canonical, Dirac and Lie–Poisson brackets and the pencil Λ1, Λ2 satisfy
the Jacobi identity and are antisymmetric; a bilinear form that is not Poisson is rejected; the
gradients of the matrix functions are exact; the Dirac bracket built from the canonical one agrees
with the scene's, for (cond_XP) and for (cond_XP2)."""
import random

import pytest

from stiefelsym import brackets as B
from stiefelsym.backends.fields import ModularField, RationalField
from stiefelsym.backends.matrix import comm
from stiefelsym.scene import Scene

SIZES = [(2, 1), (3, 2), (3, 3), (4, 2)]


def scene(n, r, seed=0, field=None, **kw):
    return Scene(n, r, field or ModularField(), rng=random.Random(f"brackets|{n}|{r}|{seed}"), **kw)


def all_zero(checks):
    return all(v == 0 for v in checks.values())


# -- Poisson tensors on matrix spaces --------------------------------------------------------------

TENSORS = {
    "Lie-Poisson (+) so(n)": lambda: B.lie_poisson(B.SO_N, 1),
    "Lie-Poisson (-) so(n)": lambda: B.lie_poisson(B.SO_N, -1),
    "Lie-Poisson (+) so(r)": lambda: B.lie_poisson(B.SO_R, 1),
    "Lie-Poisson (-) so(r)": lambda: B.lie_poisson(B.SO_R, -1),
    "Lie-Poisson gl(n)": lambda: B.lie_poisson(B.GL_N, 1),
    "Lambda1": B.lambda1,
    "Lambda2": B.lambda2,
}


@pytest.mark.parametrize("name", sorted(TENSORS))
@pytest.mark.parametrize("n, r", SIZES)
def test_tensor_is_antisymmetric_and_satisfies_jacobi(name, n, r):
    s = scene(n, r)
    checks = B.poisson_checks(s, TENSORS[name]())
    assert all_zero(checks), checks


@pytest.mark.parametrize("n", [2, 3, 4])
def test_pencil_is_compatible_for_every_coefficient(n):
    s = scene(n, 1)
    T1 = B.lambda1().scaled(lambda t: t.scalar("l1"))
    T2 = B.lambda2().scaled(lambda t: t.scalar("l2"))
    assert all_zero(B.poisson_checks(s, T1 + T2))
    assert all_zero(B.compatibility(s, B.lambda1(), B.lambda2()))


def doubled_action():
    """Not Poisson: the semi-direct product with the module action doubled (2ρ is no representation)."""
    def form(s, x, a, b):
        xi, eta, zeta, theta = B.skew(a), B.sym(a), B.skew(b), B.sym(b)
        return s.killing(x, comm(xi, zeta) + (comm(xi, theta) + comm(eta, zeta)) * 2)
    return B.PoissonTensor(B.GL_N, form, 1, "doubled")


def quadratic_so_bracket():
    """Not Poisson: <x, [a, b]> on gl(n) times <x, xᵀ>, which is not a Casimir (a multiple by a
    Casimir, or any multiple on so(3), would be Poisson)."""
    return B.PoissonTensor(B.GL_N, lambda s, x, a, b: s.killing(x, comm(a, b)) * s.killing(x, x.T), 3, "quadratic")


def symmetric_form():
    """Not antisymmetric: <x, ab + ba>."""
    return B.PoissonTensor(B.GL_N, lambda s, x, a, b: s.killing(x, a @ b + b @ a), 1, "symmetric")


@pytest.mark.parametrize("n", [3, 4])
@pytest.mark.parametrize("field", [ModularField, RationalField])
def test_a_non_poisson_bilinear_form_is_rejected(n, field):
    s = scene(n, 1, field=field())
    for T in (doubled_action(), quadratic_so_bracket()):
        checks = B.poisson_checks(s, T)
        assert checks[[k for k in checks if "Jacobi" in k][0]] != 0, T.name
    assert B.poisson_checks(s, symmetric_form())["Λ(a, b) + Λ(b, a)"] != 0


def test_the_declared_degree_is_checked():
    """A quadratic tensor declared affine: the finite difference of order 2 does not vanish."""
    s = scene(3, 1)
    T = quadratic_so_bracket()
    wrong = B.PoissonTensor(T.space, T.form, 1, "declared affine")
    assert B.poisson_checks(s, wrong)["degree in x <= 1"] != 0
    assert B.poisson_checks(s, T)["degree in x <= 3"] == 0


def test_derivative_weights_are_exact():
    from fractions import Fraction
    for d in range(1, 5):
        w = B._derivative_weights(d)
        for k in range(d + 1):      # p(t) = t^k: p'(0) = 1 if k == 1 else 0
            assert sum(wj * Fraction(j) ** k for j, wj in enumerate(w)) == (1 if k == 1 else 0)


# -- functions on matrix spaces ---------------------------------------------------------------------

def directional_derivative(s, f, x, e, degree):
    w = [s.q(q.numerator, q.denominator) for q in B._derivative_weights(degree)]
    acc = f(s, x) * w[0]
    for j in range(1, degree + 1):
        acc = acc + f(s, x + e * j) * w[j]
    return acc


@pytest.mark.parametrize("n", [2, 3])
def test_gradients_of_matrix_functions_are_exact(n):
    s = scene(n, 1)
    x, e = s.generic("x", "n", "n"), s.generic("e", "n", "n")
    lam = lambda t: t.scalar("lam")   # noqa: E731
    functions = [
        (B.linear(lambda t: t.generic("a", "n", "n")), 1),
        (B.quadratic(lambda t, y: B.skew(y)), 2),
        (B.trace_power(3, so_scale=lam, shift=lambda t: t.A), 3),
        (B.trace_power(2), 2),
        (B.trace_power(2) * B.linear(lambda t: t.generic("a", "n", "n")), 3),
    ]
    for f, degree in functions:
        assert s.killing(f.grad(s, x), e) - directional_derivative(s, f, x, e, degree) == 0, f.name


def test_casimirs_of_the_lie_poisson_bracket():
    s = scene(4, 1)
    T = B.lie_poisson(B.SO_N, 1)
    x, b = B.SO_N.generic(s, "x"), B.SO_N.generic(s, "b")
    for k in (2, 4):
        assert B.casimir_residual(s, T, B.trace_power(k), x, b) == 0
    assert B.casimir_residual(s, T, B.trace_power(2, shift=lambda t: t.zeta), x, b) != 0


def test_sharp_is_the_hamiltonian_vector_field():
    """For the (+) Lie–Poisson bracket, the Hamiltonian vector field of h = <μ, a> is ẋ = [a, x]."""
    s = scene(3, 1)
    T = B.lie_poisson(B.SO_N, 1)
    x, a = B.SO_N.generic(s, "x"), B.SO_N.generic(s, "a")
    assert (T.sharp(s, x, a) - comm(a, x)).is_zero()


# -- brackets of functions of the scene ----------------------------------------------------------

def F(t):
    return t.tr(t.generic("U", "n", "r").T @ t.X @ t.X.T @ t.P)


def G(t):
    return t.tr(t.P.T @ t.A @ t.P) + t.tr(t.X.T @ t.A @ t.A @ t.X)


def H(t):
    return t.killing(t.Phi, t.xi) * t.tr(t.X.T @ t.A @ t.X)


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (3, 3)])
def test_canonical_and_dirac_brackets_satisfy_jacobi(n, r):
    s = scene(n, r)
    for br in (B.canonical, B.dirac):
        assert B.phase_jacobiator(s, br, F, G, H) == 0, br.name
        assert br(s, F, G) + br(s, G, F) == 0


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2)])
def test_a_non_poisson_phase_bracket_is_rejected(n, r):
    """{,}_0 times a non-constant function of X is antisymmetric but not Poisson."""
    s = scene(n, r)
    bad = B.PhaseBracket("conformal", lambda t, F_, G_: t.canonical_bracket(F_, G_) * t.tr(t.X.T @ t.A @ t.X))
    assert bad(s, F, G) + bad(s, G, F) == 0
    assert B.phase_jacobiator(s, bad, F, G, H) != 0


@pytest.mark.parametrize("n, r", SIZES)
def test_dirac_bracket_from_the_constraints_is_the_scenes(n, r):
    s = scene(n, r)
    assert B.dirac(s, F, G) - B.dirac_bracket_for(B.standard_constraints)(s, F, G) == 0


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (3, 3)])
def test_metric_dirac_bracket_of_cond_XP2(n, r):
    """On (cond_XP2) the bracket {,}_A built from the constraints is the scene's, satisfies Jacobi,
    and the right SO(r) action is generated by Ψ_η (ds²_A is right SO(r)-invariant)."""
    s = scene(n, r, realization="metric")
    assert all(C.is_zero() for C in B.metric_constraints(s))
    assert B.metric_dirac(s, F, G) - B.dirac(s, F, G) == 0
    assert B.phase_jacobiator(s, B.dirac, F, G, H) == 0
    H_A = lambda t: t.tr(t.P.T @ t.Ainv @ t.P) / 2                   # noqa: E731
    Psi_eta = lambda t: t.killing(t.X.T @ t.P - t.P.T @ t.X, t.eta)  # noqa: E731
    assert B.dirac(s, Psi_eta, H_A) == 0
    flow = s.dirac_flow(Psi_eta)
    assert (flow.Xdot - s.X @ s.eta).is_zero() and (flow.Pdot - s.P @ s.eta).is_zero()


def test_poisson_map_residual_detects_a_non_poisson_map():
    s = scene(3, 2)
    a, b = (lambda t: t.generic("a", "n", "n")), (lambda t: t.generic("b", "n", "n"))
    Theta = lambda t: t.Phi + t.X @ t.X.T          # noqa: E731
    wrong = lambda t: -t.Phi + t.X @ t.X.T         # noqa: E731
    assert B.poisson_map_residual(s, B.dirac, Theta, B.lambda1(), a, b) == 0
    assert B.poisson_map_residual(s, B.dirac, wrong, B.lambda1(), a, b) != 0


# -- the fast paths agree with the definitions --------------------------------------------------

def _symbolic_scene(n, r):
    from stiefelsym.backends.polyfield import SymbolicField
    return Scene(n, r, SymbolicField(), chart="equivariant")


FAST_TENSORS = dict(TENSORS, **{
    "pencil": lambda: B.pencil(lambda t: t.scalar("l1"), lambda t: t.scalar("l2")),
    "quadratic": quadratic_so_bracket,
    "doubled": doubled_action,
    "Lie-Poisson sym(n)": lambda: B.PoissonTensor(B.SYM_N, lambda s, x, a, b: s.killing(x, a @ b - b @ a), 1, "sym"),
})


@pytest.mark.parametrize("name", sorted(FAST_TENSORS))
@pytest.mark.parametrize("make", [lambda n, r: scene(n, r), lambda n, r: scene(n, r, field=RationalField()),
                                  _symbolic_scene], ids=["modular", "rational", "symbolic"])
def test_gradient_in_x_is_the_basis_gradient(name, make):
    """The gradient in x (the engine step polynomial_gradient) equals the one from the values along a basis, for
    Poisson tensors and for forms that are not Poisson (at a generic x: for a tensor of degree > 1 the
    derivative at x, which the basis gradient takes by exact interpolation)."""
    for n, r in ((2, 1), (3, 2)):
        s = make(n, r)
        T = FAST_TENSORS[name]()
        x, b, c = (T.space.generic(s, nm) for nm in ("Tx", "Tb", "Tc"))
        assert (B.gradient_in_x(s, T, x, b, c) - _basis_gradient_in_x(s, T, x, b, c)).is_zero(), (name, n, r)


def _basis_gradient_in_x(s, T, x, b, c):
    """The gradient at x of y ↦ Λ(b, c)|_y from the values of the form along a basis of the space (the
    derivative at x by exact interpolation of degree T.degree)."""
    acc = T.space.zero(s)
    w = [s.q(q.numerator, q.denominator) for q in B._derivative_weights(T.degree)]
    values0 = T(s, x, b, c)
    for e, dual in T.space.basis(s):
        deriv = values0 * w[0]
        for j in range(1, T.degree + 1):
            deriv = deriv + T(s, x + e * j, b, c) * w[j]
        acc = acc + dual * deriv
    return acc


def test_gradient_in_x_over_floats_is_the_basis_gradient():
    """On a scene over another number system (float) the gradient in x has the basis gradient's value."""
    from stiefelsym.backends.fields import FloatField
    s = scene(3, 2, field=FloatField())
    T = B.lambda1()
    x, b, c = (T.space.generic(s, nm) for nm in ("Tx", "Tb", "Tc"))
    assert (B.gradient_in_x(s, T, x, b, c) - _basis_gradient_in_x(s, T, x, b, c)).is_zero()


def test_twisted_constraint_brackets_are_the_pairings():
    """The twisted constraint bracket matrix (one product of the stacked gradients) is the matrix of the
    pairings ⟨∇F_i, W⁻¹∇F_j⟩, and the twisted Dirac bracket is the sum of its definition."""
    from stiefelsym import twisted
    for n in (2, 3, 4):
        s = scene(n, 2)
        F = twisted.magnetic_matrix(s)
        G = twisted._constraint_gradients(s)
        C0 = twisted.constraint_bracket_matrix(s)
        for i, gi in enumerate(G):
            for j, gj in enumerate(G):
                assert C0[i][j] == twisted._pair_dot(s, gi, twisted._pi(s, gj, F))
        f = lambda t: t.killing(t.Phi, t.xi)                                   # noqa: E731
        g = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P)   # noqa: E731
        C = twisted._inverse(s, None)
        gf, gg = s.gradient(f), s.gradient(g)
        acc = twisted._pair_dot(s, gf, twisted._pi(s, gg, F))
        for i, gi in enumerate(G):
            for j, gj in enumerate(G):
                acc = acc + (twisted._pair_dot(s, gi, twisted._pi(s, gf, F)) * C[i][j]
                             * twisted._pair_dot(s, gj, twisted._pi(s, gg, F)))
        assert twisted.bracket(s, f, g) == s.field.normalize(acc)


def test_twisted_inverse_on_a_tangent_scene_is_the_dual_solve():
    """Along a tangent vector, the inverse of the twisted constraint bracket matrix taken from the base
    inverse (C_a⁻¹ − C_a⁻¹C_bC_a⁻¹ε) is the dual-number solve of the matrix."""
    from stiefelsym import twisted
    for n in (2, 3):
        s = scene(n, 2)
        t = s.tangent({"X": s.generic("dX", "n", "r"), "P": s.generic("dP", "n", "r")})
        assert twisted._dual_base(t, None) is s
        C0 = twisted.constraint_bracket_matrix(t)
        m = len(C0)
        I = [[t.const(1 if i == j else 0) for j in range(m)] for i in range(m)]
        solved = t.field.solve(C0, I)
        fast = twisted._inverse(t, None)
        for i in range(m):
            for j in range(m):
                assert t.field.is_zero(fast[i][j] - solved[i][j]), (n, i, j)


def test_twisted_jacobi_identity_fails_for_a_wrong_field_strength_term():
    """Negative control of the fast twisted bracket: with the magnetic term of W⁻¹ doubled on one side
    (no Poisson tensor), the Jacobiator of three generic functions does not vanish."""
    from stiefelsym import twisted
    s = scene(3, 2)
    f = lambda t: t.killing(t.Phi, t.xi)                                   # noqa: E731
    g = lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P)             # noqa: E731
    h = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2 + t.tr(t.generic("U", "n", "r").T @ t.P)   # noqa: E731
    good = B.PhaseBracket("twisted", lambda t, F, G: twisted.bracket(t, F, G))
    assert B.phase_jacobiator(s, good, f, g, h) == 0
    bad = B.PhaseBracket("twisted + eps{,}", lambda t, F, G: twisted.bracket(t, F, G) + t.eps * t.canonical_bracket(F, G) * t.eps)
    assert B.phase_jacobiator(s, bad, f, g, h) != 0


# -- form_gradient refuses a form that is not affine (the sum over a basis would be a secant) -------------

@pytest.mark.parametrize("field", [ModularField, RationalField])
def test_form_gradient_refuses_a_form_that_is_not_affine(field):
    s = scene(3, 2, field=field())
    with pytest.raises(ValueError, match="not affine"):
        B.form_gradient(s, lambda t, y: t.killing(y, y) + t.killing(y, t.Psi), s.Psi, "so", "r")
    # affine on so(r) (tr y = 0 there), though not on gl(r): accepted, the gradient is Psi
    G = B.form_gradient(s, lambda t, y: t.tr(y) * t.tr(y) + t.killing(y, t.Psi), s.Psi, "so", "r")
    assert (G - s.Psi).is_zero()


def test_form_gradient_check_leaves_the_draws_that_follow_unchanged():
    a, b = scene(3, 2), scene(3, 2)
    a.Psi, b.Psi
    B.form_gradient(a, lambda t, y: t.killing(y, t.Psi), a.Psi, "so", "r")
    assert (a.generic("G", "n", "r") - b.generic("G", "n", "r")).is_zero()
