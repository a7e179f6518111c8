"""Poisson tensors on so(n), gl(n) without a basis: the Hamiltonian vector field Λ_x(·, a)^♯ and the
gradient in x of Λ(b, c)|_x are one step of the IR (:func:`stiefelsym.brackets.form_gradient`), which a
coordinate scene takes in a basis and the dimension-free scene by cyclic differentiation of the form
at a fresh letter.  So the Lie–Poisson checks of (Euler-so(n)) and (LAMBDA12) are proved for every n,
with certificates, and corrupted tensors and flows are not."""
import random

import pytest

from stiefelsym import brackets as B
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.backends.fields import ModularField
from stiefelsym.free import FreeScene
from stiefelsym.free.mat import entry_of
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.backends.matrix import comm
from stiefelsym.scene import Scene

CATALOG = load_catalog()
BASE = CATALOG.get("lambda12-compatible")


def _proved(res):
    assert res.verdict == "proved", res.message
    assert check_certificate(res.certificate_data).accepted


@pytest.mark.parametrize("cid", ["euler-so-n", "lambda12-compatible"])
def test_lie_poisson_claims_are_proved_for_every_n(cid):
    _proved(run_free(CATALOG.get(cid)))


# -- the gradient of a form, on both kinds of scene -----------------------------------------------

def test_the_free_gradient_of_a_form_is_its_cyclic_derivative():
    """c ↦ <x, [c, a]> = <[a, x], c>: the gradient is [a, x], for x, a generic in gl(n)."""
    s = FreeScene(lazy=True)
    x, a = s.generic("x", "n", "n"), s.generic("a", "n", "n")
    G = s.form_gradient(lambda t, c: t.killing(x, comm(c, a)), "n")
    assert s.field.is_zero(entry_of(G - comm(a, x)))
    assert not s.field.is_zero(entry_of(G - comm(x, a)))


def test_a_form_that_is_not_affine_is_refused():
    s = FreeScene(lazy=True)
    with pytest.raises(Exception, match="not affine"):
        s.form_gradient(lambda t, c: t.killing(c, c), "n")


@pytest.mark.parametrize("space", [B.SO_N, B.GL_N, B.SO_R])
def test_the_step_is_the_basis_sum_at_a_fixed_size(space):
    """On a coordinate scene the step sums dual_k (form(e_k) − form(0)) over a basis: for the (+)
    Lie–Poisson bracket, Λ_x(·, a)^♯ = [a, x] projected onto the space."""
    s = Scene(4, 3, ModularField(), rng=random.Random("free-brackets"))
    T = B.lie_poisson(space, 1)
    x, a = space.generic(s, "x"), space.generic(s, "a")
    assert (T.sharp(s, x, a) - space.project(comm(a, x))).is_zero()


# -- size-free claims, and corrupted ones -----------------------------------------------------------

def sharp_of_lie_poisson(s):
    T = B.lie_poisson(B.SO_N, 1)
    x, a = B.SO_N.generic(s, "x"), B.SO_N.generic(s, "a")
    return {"sharp": T.sharp(s, x, a) - comm(a, x)}


def sharp_of_lie_poisson_wrong_sign(s):
    T = B.lie_poisson(B.SO_N, 1)
    x, a = B.SO_N.generic(s, "x"), B.SO_N.generic(s, "a")
    return {"sharp": T.sharp(s, x, a) - comm(x, a)}


def euler_wrong_order(s):
    """ξ̇ = [ξ, 𝔸ξ] instead of [𝔸ξ, ξ]."""
    T = B.lie_poisson(B.SO_N, 1)
    h = B.quadratic(lambda t, x: t.sym_operator("AA")(x))
    AA = s.sym_operator("AA")
    return {"flow": T.sharp(s, s.xi, h.grad(s, s.xi)) - comm(s.xi, AA(s.xi))}


def doubled_action(s):
    """Not Poisson: the semi-direct product with the module action doubled (2ρ is no representation)."""
    def form(t, x, a, b):
        xi, eta, zeta, theta = B.skew(a), B.sym(a), B.skew(b), B.sym(b)
        return t.killing(x, comm(xi, zeta) + (comm(xi, theta) + comm(eta, zeta)) * 2)
    return B.poisson_checks(s, B.PoissonTensor(B.GL_N, form, 1, "doubled"))


def lambda2_shifted_by_a_nonsymmetric_point(s):
    """Not Poisson: <x − AxA, [a, b]> (c ↦ c − AcA is not a morphism of Lie algebras)."""
    T = B.PoissonTensor(B.GL_N, lambda t, x, a, b: t.killing(x - t.A @ x @ t.A, comm(a, b)), 1, "AxA")
    return B.poisson_checks(s, T)


def pencil_with_a_foreign_tensor(s):
    """Λ1 + (the doubled action): each Jacobi identity but the sum's."""
    def form(t, x, a, b):
        xi, eta, zeta, theta = B.skew(a), B.sym(a), B.skew(b), B.sym(b)
        return t.killing(x, comm(xi, zeta) + (comm(xi, theta) + comm(eta, zeta)) * 2)
    return B.compatibility(s, B.lambda1(), B.PoissonTensor(B.GL_N, form, 1, "doubled"))


def test_the_sharp_of_the_lie_poisson_bracket_is_proved():
    _proved(run_free(BASE, sharp_of_lie_poisson))


@pytest.mark.parametrize("func", [sharp_of_lie_poisson_wrong_sign, euler_wrong_order, doubled_action,
                                  lambda2_shifted_by_a_nonsymmetric_point, pencil_with_a_foreign_tensor])
def test_a_corrupted_bracket_is_not_proved(func):
    res = run_free(BASE, func)
    assert res.verdict in ("undecided", "fails"), res.message
    assert "nonzero normal form" in res.message


def test_a_wrong_identity_fails_at_a_fixed_size_too():
    """The negative controls are wrong at fixed sizes as well (they are not artefacts of the free algebra)."""
    s = Scene(3, 1, ModularField(), rng=random.Random("free-brackets|fixed"))
    for func in (doubled_action, lambda2_shifted_by_a_nonsymmetric_point, pencil_with_a_foreign_tensor):
        assert any(v != 0 for v in func(s).values()), func.__name__
    for func in (sharp_of_lie_poisson_wrong_sign, euler_wrong_order):
        assert not all(v.is_zero() for v in func(s).values()), func.__name__
