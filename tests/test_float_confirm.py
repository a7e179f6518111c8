"""The exact confirmation of a float or ball `numeric` (methods._confirm_numeric): at random points mod p,
as many per component as bring the chance of missing a residual that is not identically 0 to at most
CONFIRM_TARGET (one point for the catalog's claims), with that bound printed; and the exact Cayley point
it evaluates (scene._stiefel_point over an exact field) is on T*V."""
from __future__ import annotations

import random
import re

import pytest

from stiefelsym import admissible, comm
from stiefelsym.claims import Claim, Size
from stiefelsym.backends.fields import ModularField, RationalField
from stiefelsym.run.runner import run_one
from stiefelsym.scene import Scene

SEED = 11
C = 10 ** 20


def _la1(s):
    """LA1 along the printed Neumann flow (No)."""
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    flow = {"X": P - k * (X @ P.T @ X), "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    return {"LA1": s.d(L, flow) - comm(s.Phi - s.lam * s.A, L(s))}


def _absorbed(s):
    """False: (c[XXᵀ, A] + XXᵀ) - c[XXᵀ, A] = XXᵀ, hidden below float64's resolution of the terms."""
    M = s.X @ s.X.T
    K = M @ s.A - s.A @ M
    return {"r": (K * C + M) - K * C}


LA1 = Claim(id="confirm-LA1", paper=("LA1",), kind="lax", section="5", func=_la1, sizes=admissible(8))
ABSORBED = Claim(id="confirm-absorbed", paper=("LA1",), kind="id", section="5", func=_absorbed, sizes=admissible(8))


def _confirmation(res) -> tuple[int, bool, float]:
    m = re.search(r"confirmed exactly: every residual is 0 at (\d+) random points? mod p( per component)?.*?"
                  r"probability <= ([0-9.e+-]+) <= 2\^-40", res.certificate)
    assert m, res.certificate
    return int(m.group(1)), bool(m.group(2)), float(m.group(3))


@pytest.mark.parametrize("method", ["float", "ball"])
@pytest.mark.parametrize("n,r", [(5, 2), (3, 3)])
def test_numeric_is_confirmed_at_one_point_per_component_with_its_bound(method, n, r):
    res = run_one(LA1, Size(n, r), method, seed=SEED)
    assert res.verdict == "numeric", res.message
    points, per_component, bound = _confirmation(res)
    assert points == 1 and per_component == (r == n)
    assert 0 < bound <= 2.0 ** -40


def test_a_stricter_target_takes_more_points(monkeypatch):
    """The number of points follows the bound: at a target one point cannot reach, two are taken."""
    import stiefelsym.methods.fixed_size as methods
    monkeypatch.setattr(methods, "CONFIRM_TARGET", 1e-20)
    monkeypatch.setattr(methods, "_confirm_text", lambda exact: exact.certificate)
    res = run_one(LA1, Size(5, 2), "float", seed=SEED)
    assert res.verdict == "numeric" and "2 independent points" in res.certificate, res.certificate


@pytest.mark.parametrize("method", ["float", "ball"])
def test_a_residual_below_float64s_resolution_fails_at_the_one_point(method):
    """The negative control: the float evaluation passes (the residual is 1e-20 of the terms), the single
    exact point refutes it."""
    res = run_one(ABSORBED, Size(5, 2), method, seed=SEED)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert "not 0 at exact points mod p" in res.message and res.witness is not None


@pytest.mark.parametrize("field", [RationalField(2 ** 62), ModularField(2 ** 61 - 1)])
@pytest.mark.parametrize("n,r,component", [(5, 2, 0), (4, 4, 0), (4, 4, 1)])
def test_the_exact_cayley_point_is_on_the_cotangent_bundle(field, n, r, component):
    """X = 2(I + S)^-1 J - J and P = XW + Z - X(XᵀZ): XᵀX = I and XᵀP + PᵀX = 0 exactly, det-sign of the
    component as asked (the first column negated on the second)."""
    s = Scene(n, r, field, chart="cayley", rng=random.Random(SEED), component=component)
    X, P = s.X, s.P
    eye = s.identity(r, "r")
    assert (X.T @ X - eye).is_zero()
    assert (X.T @ P + P.T @ X).is_zero()
    assert not (X.T @ P).is_zero()


def test_a_confirmation_whose_bound_is_too_weak_is_no_pass(monkeypatch):
    """Outside hard cases `numeric` stands only on a `checked` (or `proved`) confirmation: an exact run at
    random points whose residuals vanished but whose false-pass bound is above the target (`inconclusive`)
    leaves the float verdict `inconclusive`, with the reason."""
    from stiefelsym.methods import fixed_size as methods
    from stiefelsym.results import Result

    real = methods.run_points

    def weak(*args, **kw):
        res = real(*args, **kw)
        assert res.verdict == "checked" and res.checks
        res.verdict, res.false_pass_bound = "inconclusive", None
        res.message = "every residual vanishes at 1 point, but the false-pass bound is too weak"
        return res

    monkeypatch.setattr(methods, "run_points", weak)
    res = run_one(LA1, Size(4, 2), "float", seed=SEED)
    assert res.verdict == "inconclusive" and "too weak" in res.message, (res.verdict, res.message)
    assert isinstance(res, Result)
