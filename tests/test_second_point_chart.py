"""The second point (Y, Q) on the exact method's equivariant chart, and the closed-form multipliers
of the Dirac flow on a product of cotangent bundles of Stiefel varieties.

The equivariant chart moves the first point to X0 and keeps the second generic: Y is the first r
columns of a Cayley transform with one r x r inverse (times diag(-1, 1, .., 1) on the second
component of O(n) when r = n).  Negative controls: a claim true only when X and Y lie on the same
component of O(n), a false 'Y = X', and a corrupted coupled flow, each rejected; the closed-form
flow equals the general solve of the multipliers at random exact points."""
from __future__ import annotations

import random

import pytest

import stiefelsym.proofs.app2_double_coupled_complex as a
from stiefelsym import admissible
from stiefelsym.claims import Claim
from stiefelsym.backends.fields import ModularField
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.scene import Scene
from stiefelsym.systems import (_closed_form_pairs_flow, coupled_point, hamiltonian_flow, stiefel_pairs_flow,
                                symmetric_entries)


def _claim(func, cid="t-second"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _on_V(s):
    Y, Q = s.Y, s.Q
    return {"Y^T Y - I": Y.T @ Y - s.Ir, "Y^T Q + Q^T Y": Y.T @ Q + Q.T @ Y}


def _det2(M):
    return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]


def _same_component(s):
    """det(XᵀY) = 1 (r = n = 2): O(n)-invariant, true only when X and Y lie on one component."""
    return {"det(X^T Y) - 1": _det2(s.X.T @ s.Y) - s.q(1)}


def _y_is_x(s):
    return {"Y - X": s.Y - s.X}


def test_the_second_point_is_on_V_identically_and_stated():
    s = Scene(6, 2, SymbolicField(), chart="equivariant")
    Y, Q = s.Y, s.Q
    assert (Y.T @ Y - s.Ir).is_zero() and (Y.T @ Q + Q.T @ Y).is_zero()
    assert "second point (Y, Q)" in s.second_point_text()
    res = run_exact(_claim(_on_V), 6, 2, 0)
    assert res.verdict == "proved", res.message
    assert any("second point (Y, Q)" in d and "X = X0" in d for d in res.reductions), res.reductions


@pytest.mark.parametrize("n,r", [(5, 2), (4, 1)])
def test_a_false_Y_equals_X_fails_on_the_equivariant_chart(n, r):
    res = run_exact(_claim(_y_is_x), n, r, 0)
    assert res.verdict == "fails"
    assert any("second point (Y, Q)" in d for d in res.reductions), res.reductions


def test_r_equals_n_evaluates_both_components_of_the_second_point():
    res = run_exact(_claim(_same_component), 2, 2, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert any("component 2 of O(n) for Y" in d for d in res.reductions), res.reductions
    # on the first component alone it vanishes identically
    f = SymbolicField()
    s = Scene(2, 2, f, chart="equivariant")
    M = (s.X.T @ s.Y)._view()
    assert f.is_zero(M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0] - f.const(1))


def _coupled_constraints(t, z):
    out = []
    for x, p in (("X", "P"), ("Y", "Q")):
        X, P = z[x], z[p]
        out += symmetric_entries(X.T @ X - t.Ir) + symmetric_entries(X.T @ P + P.T @ X)
    return out


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2), (3, 3)])
@pytest.mark.parametrize("kappa", [a.NORMAL, a.FREE_KAPPA])
def test_closed_form_pairs_flow_equals_the_general_solve(n, r, kappa):
    s = Scene(n, r, ModularField(2**61 - 1), chart="cayley", rng=random.Random(n * 10 + r))
    z = coupled_point(s)
    H = a.H_coupled(kappa)
    closed = _closed_form_pairs_flow(s, H, z, (("X", "P"), ("Y", "Q")))
    assert closed is not None
    general, _ = hamiltonian_flow(s, H, _coupled_constraints, z, (("X", "P"), ("Y", "Q")))
    for k in ("X", "P", "Y", "Q"):
        assert (closed[k] - general[k]).is_zero(), k
    assert set(stiefel_pairs_flow(s, H, z, (("X", "P"), ("Y", "Q")))) == {"X", "P", "Y", "Q"}


def test_closed_form_pairs_flow_declines_off_V():
    s = Scene(3, 1, ModularField(2**61 - 1), chart="cayley", rng=random.Random(3))
    z = coupled_point(s)
    off = dict(z, Y=z["Y"] * s.const(2))
    assert _closed_form_pairs_flow(s, a.H_coupled(a.NORMAL), off, (("X", "P"), ("Y", "Q"))) is None


@pytest.mark.parametrize("n,r", [(5, 1), pytest.param(4, 2, marks=pytest.mark.slow)])
def test_coupled_flow_proved_beyond_the_cayley_chart_and_the_printed_one_fails(n, r):
    good = run_exact(_claim(lambda s: a.coupled_flow_checks(s, Q_Pi=False)), n, r, 0)
    assert good.verdict == "proved", good.message
    bad = run_exact(_claim(lambda s: a.coupled_flow_checks(s, Q_Pi=True)), n, r, 0)
    assert bad.verdict == "fails", bad.message


def _complex_on_W(s):
    Z, V = s.Zc, s.Zc_dot
    return {"Z*Z - I": Z.T @ Z - s.identity(2 * s.r, "r+r"), "Z*V + V*Z": Z.T @ V + V.T @ Z}


def _complex_false(s):
    """Z Z* = I_n: false for r < n."""
    return {"ZZ* - I": s.Zc @ s.Zc.T - s.identity(2 * s.n, "n+n")}


def test_the_complex_point_of_the_equivariant_chart_is_on_W_and_a_false_claim_fails():
    res = run_exact(_claim(_complex_on_W), 4, 1, 0)
    assert res.verdict == "proved", res.message
    assert any("(Z, Zdot) of TW(n, r)" in d for d in res.reductions), res.reductions
    assert run_exact(_claim(_complex_false), 3, 1, 0).verdict == "fails"
    good = run_exact(a.complex_neumann_flow.claim, 4, 1, 0)
    assert good.verdict == "proved", good.message


def _complex_flow_corrupted(s):
    """(W-eq) with Λ replaced by its conjugate transpose's negative: Z'' = −AZ − ZΛ."""
    z = a.complex_point(s)
    acc = a.complex_acceleration(s, z)
    A = a.realify_real(s, s.A)
    return {"Z'' - corrupted (W-eq)": acc - (-(A @ z["Z"]) - z["Z"] @ a.Lambda_complex(s, z))}


def test_a_corrupted_complex_flow_fails_on_the_equivariant_chart():
    res = run_exact(_claim(_complex_flow_corrupted), 3, 1, 0)
    assert res.verdict == "fails", res.message
    assert any("(Z, Zdot) of TW(n, r)" in d for d in res.reductions), res.reductions


def _rows_weighted(s, corrupt=False):
    """tr(XᵀAX)·(XᵀX)₁₁ = Σ_i a_i |row_i X|² with A = diag(a) (reads entries and the a_i; the factor (XᵀX)₁₁ = 1
    holds on V only, so the unconstrained chart does not take it); ``corrupt``: the last weight a_n replaced by
    a_1."""
    X, a_ = s.X, s.a
    acc = s.q(0)
    for i in range(s.n):
        w = a_[0] if corrupt and i == s.n - 1 else a_[i]
        for j in range(s.r):
            acc = acc + w * X[i, j] * X[i, j]
    return {"tr(X^T A X) (X^T X)_11 - sum": s.tr(X.T @ s.A @ X) * (X.T @ X)[0, 0] - acc}


@pytest.mark.parametrize("n,r", [(6, 2), (5, 3)])
def test_the_reduced_cayley_chart_proves_a_coordinate_claim_and_rejects_its_corruption(n, r):
    res = run_exact(_claim(_rows_weighted), n, r, 0)
    assert res.verdict == "proved", res.message
    assert "S = [[S11, -K^T], [K, 0]]" in res.reductions[0]
    assert run_exact(_claim(lambda s: _rows_weighted(s, corrupt=True)), n, r, 0).verdict == "fails"
