"""Scenes: charts land on T*V, flows keep it, the Dirac and Lagrange forms agree."""
import random

import pytest

from stiefelsym.backends.fields import ModularField, RationalField
from stiefelsym.backends.polyfield import SymbolicField
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


# -- the equivariant chart of the metric realization -------------------------------------------

def _metric_scene(n, r, field, seed=0):
    return Scene(n, r, field, chart="equivariant", realization="metric", rng=random.Random(seed))


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (4, 2), (4, 4), (5, 3)])
def test_metric_equivariant_point_is_on_cond_xp2_with_diagonal_blocks(n, r):
    """X = X0, XᵀA⁻¹P skew, and the diagonal blocks of A⁻¹ diagonal (the O(n) × O(r) reduction)."""
    s = _metric_scene(n, r, ModularField(2**61 - 1))
    X, P, B = s.X, s.P, s.Ainv
    assert (X.T @ X - s.Ir).is_zero()
    assert (X.T @ B @ P + P.T @ B @ X).is_zero()
    assert (B - B.T).is_zero()
    b = B._a
    assert all(b[i, j] == 0 for i in range(n) for j in range(n)
               if i != j and (max(i, j) < r or min(i, j) >= r))
    assert (s.A @ B - s.identity(n, "n")).is_zero()


def _metric_hamiltonians(s):
    return [lambda t: t.tr(t.P.T @ t.Ainv @ t.P) * t.q(1, 2),
            lambda t: t.tr(t.P.T @ t.P) * t.q(1, 3) + t.tr(t.X.T @ t.A @ t.X),
            lambda t: t.tr(t.X.T @ t.P @ t.X.T @ t.A @ t.P)]


@pytest.mark.parametrize("n, r", [(2, 1), (3, 2), (4, 3), (4, 4), (5, 2)])
@pytest.mark.parametrize("field", [ModularField(2**61 - 1), RationalField()], ids=["GF(p)", "Q"])
def test_metric_closed_form_dirac_flow_is_the_solved_one(n, r, field, monkeypatch):
    """The Dirac flow on (cond_XP2) by two diagonal Lyapunov equations equals the flow with the
    r(r+1) multipliers solved from the constraint bracket matrix."""
    import stiefelsym.scene as scene_mod
    for k, H in enumerate(_metric_hamiltonians(None)):
        fast = _metric_scene(n, r, field, seed=k)
        assert fast._metric_closed_form_flow(*fast.gradient(H)) is not None
        F = fast.dirac_flow(H)
        monkeypatch.setattr(scene_mod, "CLOSED_FORM_MULTIPLIERS", False)
        slow = _metric_scene(n, r, field, seed=k)
        G = slow.dirac_flow(H)
        monkeypatch.setattr(scene_mod, "CLOSED_FORM_MULTIPLIERS", True)
        assert (F.Xdot - G.Xdot).is_zero() and (F.Pdot - G.Pdot).is_zero(), (n, r, k)


def test_metric_flow_is_proved_in_the_reduced_chart_and_a_corrupted_one_fails():
    from stiefelsym import admissible
    from stiefelsym.claims import Claim, Size
    from stiefelsym.run.runner import run_one

    def flow(s, sign):
        H = lambda t: t.tr(t.P.T @ t.Ainv @ t.P) * t.q(1, 2)  # noqa: E731
        F = s.dirac_flow(H)
        return {"dX/dt": F.Xdot - s.Ainv @ s.P * s.q(sign)}
    good = Claim(id="m", paper=("A_XP",), kind="id", section="t", func=lambda s: flow(s, 1),
                 sizes=admissible(5), realization="metric")
    bad = Claim(id="m-bad", paper=("A_XP",), kind="id", section="t", func=lambda s: flow(s, -1),
                sizes=admissible(5), realization="metric")
    for n, r in [(3, 1), (4, 2), (5, 5)]:
        res = run_one(good, Size(n, r), "exact", 0)
        assert res.verdict == "proved", (n, r, res.message)
        assert run_one(bad, Size(n, r), "exact", 0).verdict == "fails"
