"""Scenes: charts land on T*V, flows keep it, the Dirac and Lagrange forms agree."""
import random

import pytest

from stiefelsym.fields import ModularField, RationalField, SymbolicField
from stiefelsym.scene import Scene, SizeError

SIZES = [(2, 1), (3, 2), (4, 2), (3, 3)]


def H_test(s):
    """A Hamiltonian with no symmetry: a generic linear part plus a potential."""
    U, V = s.generic("U", "n", "r"), s.generic("V", "n", "r")
    return s.tr(U.T @ s.X) + s.tr(V.T @ s.P) + s.tr(s.X.T @ s.A @ s.X) / 2


@pytest.mark.parametrize("n,r", SIZES)
def test_cayley_point_is_on_the_cotangent_bundle(n, r):
    for comp in (0, 1):
        s = Scene(n, r, RationalField(), rng=random.Random(n * 10 + r), component=comp)
        assert (s.X.T @ s.X - s.Ir).is_zero()
        assert (s.X.T @ s.P + s.P.T @ s.X).is_zero()


def test_second_component_when_r_equals_n():
    import sympy
    dets = set()
    for comp in (0, 1):
        s = Scene(3, 3, RationalField(), rng=random.Random(4), component=comp)
        M = sympy.Matrix([[sympy.Rational(int(x.p), int(x.q)) for x in row] for row in s.X._a.tolist()])
        dets.add(M.det())
    assert dets == {1, -1}


@pytest.mark.parametrize("n,r", SIZES)
def test_dirac_flow_is_tangent_and_equals_the_multiplier_form(n, r):
    s = Scene(n, r, ModularField(), rng=random.Random(7))
    flow = s.dirac_flow(H_test)
    for C in s.d(s.constraints.build, flow):
        assert C.is_zero()
    mult = s.multiplier_flow(H_test)
    assert (mult.Xdot - flow.Xdot).is_zero() and (mult.Pdot - flow.Pdot).is_zero()


def test_equivariant_chart_is_symbolic_and_polynomial():
    s = Scene(4, 2, SymbolicField(), chart="equivariant")
    assert (s.X.T @ s.X - s.Ir).is_zero()
    assert (s.X.T @ s.P + s.P.T @ s.X).is_zero()
    assert not s.tracker.used


def test_reading_coordinates_is_recorded():
    s = Scene(3, 1, RationalField(), rng=random.Random(1))
    _ = s.Psi[0, 0]
    assert not s.tracker.used          # Psi is r x r: no coordinate of R^n
    _ = s.Phi[0, 1]
    assert s.tracker.used


@pytest.mark.parametrize("n,r", [(2, 3), (3, 0), (3, -1)])
def test_inadmissible_sizes(n, r):
    with pytest.raises(SizeError):
        Scene(n, r, RationalField())


def test_same_seed_same_point_different_seed_different_point():
    a = Scene(3, 2, RationalField(), rng=random.Random("s|1"))
    b = Scene(3, 2, RationalField(), rng=random.Random("s|1"))
    c = Scene(3, 2, RationalField(), rng=random.Random("s|2"))
    assert a.P._a.tolist() == b.P._a.tolist() != c.P._a.tolist()


@pytest.mark.parametrize("n,r", [(2, 1), (3, 2), (3, 3)])
def test_complex_stiefel_point_is_unitary_and_complex_linear(n, r):
    s = Scene(n, r, RationalField(), rng=random.Random(3))
    Z, V = s.Zc, s.Zc_dot
    assert (Z.T @ Z - s.identity(2 * r)).is_zero()
    assert (Z.T @ V + V.T @ Z).is_zero()
    # complex linearity: Z is of the form [[U, -W], [W, U]], i.e. conj(conj(Z)) = Z and J Z = Z J
    assert (s.conj(s.conj(Z)) - Z).is_zero()
    Jn = s.realify(s.zeros(n, n), s.identity(n))
    Jr = s.realify(s.zeros(r, r), s.identity(r))
    assert (Jn @ Z - Z @ Jr).is_zero()
