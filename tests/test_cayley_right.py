"""The symbolic Cayley chart reduced by O(r) acting on the right (S11 = 0) for graphs that read
coordinates of R^n and nothing of R^r: the reduction is stated, it is refused to every graph that
reads R^r (an entry of an R^r-sided matrix, a matrix of given entries on R^r), and a corrupted claim
is refuted exactly on it; a statement true on the reduced chart only (X1 symmetric) fails."""
from __future__ import annotations

import pytest

import stiefelsym.proofs.sec4_integrability as m
import stiefelsym.proofs.sec8_dual_lax_pair as d
from stiefelsym import admissible, twisted
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.ir import compile_claim
from stiefelsym.ir.passes import right_action_breaks
from stiefelsym.methods import cayley_right
from test_sec8 import cones_of_a_plus_pp  # noqa: E402 - the corrupted cones of the section's tests
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.scene import REALIZATIONS, Scene

RIGHT = "reduced by O(r) acting on the right"


def _claim(func, cid="t-right"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _graph(func, n, r):
    cons = REALIZATIONS["standard"]
    return compile_claim(func, n, r, (cons.name, cons.build))


def _reflections_forget_S_on_P(s):
    """The reflection S₁ applied to X alone in the image of the flow (dot_XP3*): a wrong statement."""
    V = m.flow_XP3(s)
    S = twisted.reflection(s)
    W = m.flow_XP3_at(s, S @ s.X, S @ s.P)
    return {"S: dP/dt": W["P"] - V["P"]}


def _x1_symmetric(s):
    """X1 = X1ᵀ for the top r × r block of X: true on the reduced chart only (an entry read on R^r)."""
    X1 = s.X[0:s.r, 0:s.r]
    return {"X1 - X1^T": X1 - X1.T + (s.A[0, 0] - s.A[0, 0]) * s.Ir}


def _x1_symmetric_by_given_entries(s):
    """The same statement through matrices of given entries on R^r, E_i (columns of I_r): E_1ᵀXᵀE E_2
    against E_2ᵀXᵀE E_1, E the n × r matrix of the first r coordinate vectors (read on R^n too)."""
    n, r = s.n, s.r
    e1 = s.mat([[s.q(1)] if i == 0 else [s.q(0)] for i in range(r)], ("r", "?"))
    e2 = s.mat([[s.q(1)] if i == 1 else [s.q(0)] for i in range(r)], ("r", "?"))
    E = s.mat([[s.q(1) if i == j else s.q(0) for j in range(r)] for i in range(n)], ("n", "r"))
    M = E.T @ s.X
    return {"(X1)_12 - (X1)_21": e1.T @ M @ e2 - e2.T @ M @ e1}


def test_the_chart_is_refused_outside_the_standard_cayley_chart_with_2_le_r_le_n():
    for bad in ({"n": 4, "r": 1}, {"n": 3, "r": 1}, {"n": 4, "r": 2, "chart": "equivariant"},
                {"n": 4, "r": 2, "realization": "metric"}):
        args = dict(chart="cayley", realization="standard")
        args.update(bad)
        n, r = args.pop("n"), args.pop("r")
        with pytest.raises(ValueError):
            Scene(n, r, SymbolicField(), cayley_right=True, **args)
    s = Scene(4, 2, SymbolicField(), chart="cayley", cayley_right=True)
    X = s.X._a
    assert X[0, 1] == X[1, 0] and X[0, 1] != 0          # X1 symmetric, not diagonal


@pytest.mark.parametrize("func", [_x1_symmetric, _x1_symmetric_by_given_entries])
def test_a_graph_that_reads_r_is_refused_the_reduction_and_its_statement_fails(func):
    g = _graph(func, 4, 2)
    assert right_action_breaks(g)
    assert not cayley_right.applies(g, "standard", 4, 2)
    res = run_exact(_claim(func), 4, 2, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert not any(RIGHT in x for x in res.reductions), res.reductions


@pytest.mark.parametrize("n,r", [(4, 2), (4, 3)])
def test_the_manakov_reflections_are_proved_on_the_reduced_chart_and_a_forgotten_reflection_refuted(n, r):
    c = load_catalog().get("manakov-reflections")
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any(RIGHT in x for x in res.reductions), res.reductions
    bad = run_exact(_claim(_reflections_forget_S_on_P), n, r, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)
    assert any(RIGHT in x for x in bad.reductions), bad.reductions


def test_r_one_keeps_its_chart_and_r_n_takes_the_identity():
    g = _graph(_reflections_forget_S_on_P, 4, 1)
    assert not right_action_breaks(g)
    assert not cayley_right.applies(g, "standard", 4, 1)
    assert cayley_right.applies(_graph(_reflections_forget_S_on_P, 3, 3), "standard", 3, 3)


def _cones_by_entries(s):
    """(chasles-cones-real) with its determinant expanded by entries (which reads coordinates of R^n; the
    catalog's claim computes it from traces of powers and is proved on the equivariant chart)."""
    Q = s.In - s.X @ s.X.T
    M = Q @ (s.A - s.P @ s.P.T) @ Q
    integrals, _ = d.spectral_integrals(s, s.lam)
    lam_r = s.q(1)
    for _ in range(s.r):
        lam_r = lam_r * s.lam
    return {"char": lam_r * integrals[s.r] - d.det_matrix(s, s.scalar_matrix(s.lam, s.n, "n") - M)}


def test_the_chasles_cones_are_proved_at_3_2_on_the_reduced_chart_and_a_wrong_sign_refuted():
    c = load_catalog().get("chasles-cones-real")
    assert c.exact_at(3, 2)
    res = run_exact(c, 3, 2, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert res.reductions[0].startswith("equivariance"), res.reductions
    res = run_exact(_claim(_cones_by_entries), 3, 2, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any(RIGHT in x for x in res.reductions), res.reductions
    bad = run_exact(_claim(cones_of_a_plus_pp), 3, 2, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)
    assert any(RIGHT in x for x in bad.reductions), bad.reductions


def test_the_woodbury_inverse_gives_the_chart_s_own_rational_functions():
    """For n - r < r the right-reduced chart inverts I + KKᵀ ((n - r) × (n - r)) in place of I + KᵀK
    (r × r): X is the same matrix of rational functions as with the r × r inverse."""
    from stiefelsym.scene import param_name
    s = Scene(5, 3, SymbolicField(), chart="cayley", cayley_right=True)
    X = s.X
    K = s.zeros(5, 3, ("n", "r"))
    for i in range(3, 5):
        for j in range(3):
            K._a[i, j] = s._param(param_name("K", i, j))
    KtK = K.T @ K
    E = s.mat([[s.q(1) if i == j else s.q(0) for j in range(3)] for i in range(5)], ("n", "r"))
    direct = (E @ (s.Ir - KtK) - K * s.const(2)) @ (s.Ir + KtK).inv()
    assert all(X._a[i, j] == direct._a[i, j] for i in range(5) for j in range(3))
    XtX = (X.T @ X)._a
    assert all(XtX[i, j] == (1 if i == j else 0) for i in range(3) for j in range(3))


def test_the_square_chart_is_the_identity_with_a_generic_skew_momentum():
    s = Scene(4, 4, SymbolicField(), chart="cayley", cayley_right=True)
    X, P = s.X._a, s.P._a
    assert all(X[i, j] == (1 if i == j else 0) for i in range(4) for j in range(4))
    assert all(P[i, j] == -P[j, i] for i in range(4) for j in range(4)) and P[0, 1] != 0


@pytest.mark.parametrize("n,r", [(5, 4), (5, 5), (6, 6)])
def test_the_manakov_reflections_at_r_close_to_n_and_a_forgotten_reflection(n, r):
    """Beyond the equivariant chart's budget (a symbolic inverse of A + λI), the right-reduced chart:
    the Woodbury inverse at (5, 4), X = I at r = n; the corrupted claim is refuted there."""
    c = load_catalog().get("manakov-reflections")
    res = run_exact(c, n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any("acting on the right" in x for x in res.reductions), res.reductions
    bad = run_exact(_claim(_reflections_forget_S_on_P), n, r, 0)
    assert bad.verdict == "fails", (bad.verdict, bad.message)
    assert any("acting on the right" in x for x in bad.reductions), bad.reductions


@pytest.mark.parametrize("n,r", [(4, 4), (5, 4)])
def test_a_graph_that_reads_r_gets_no_right_reduced_chart_at_r_close_to_n(n, r):
    """X1 symmetric holds on X = I (r = n) and on the S11 = 0 chart: read on R^r, it is refused both
    reductions (and fails on the full chart)."""
    res = run_exact(_claim(_x1_symmetric), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert not any("acting on the right" in x for x in res.reductions), res.reductions


def _manakov_conserves_a_linear_function(s):
    """tr(CX) (C a generic r × n matrix) conserved along the Manakov flow (dot_XP2): a wrong statement."""
    flow = s.dirac_flow(m.H_manakov)
    return {"d tr(C X)/dt": s.d(lambda t: t.tr(t.generic("C", "r", "n") @ t.X), flow)}


def _cones_with_lambda_to_r_minus_1(s):
    """(chasles-cones-real) with λ^(r−1) in place of λ^r (at r = n, Q = 0 and the sign of PPᵀ is not
    seen: this corruption is): a wrong statement."""
    Q = s.In - s.X @ s.X.T
    M = Q @ (s.A - s.P @ s.P.T) @ Q
    integrals, _ = d.spectral_integrals(s, s.lam)
    lam_r = s.q(1)
    for _ in range(s.r - 1):
        lam_r = lam_r * s.lam
    return {"lambda^(r-1) I_2r(lambda) - det(lambda I - Q(A - PP^T)Q)":
            lam_r * integrals[s.r] - d.det_matrix(s, s.scalar_matrix(s.lam, s.n, "n") - M)}


@pytest.mark.parametrize("cid,bad,chart", [
    # (its characteristic polynomial from traces of powers reads no coordinate: the equivariant chart; the
    # corruption expands it by entries, and goes to the chart X = I)
    ("chasles-cones-real", _cones_with_lambda_to_r_minus_1, "equivariance: X = X0"),
    # its Manakov flows are those of B = A^j (products only): the equivariant chart, whose X is X0 = I at r = n
    ("dual-invariants-manakov-r-n", _manakov_conserves_a_linear_function, "equivariance: X = X0")])
def test_claims_raised_to_3_3_are_proved_on_the_chart_x_i_and_a_corruption_refuted(cid, bad, chart):
    c = load_catalog().get(cid)
    assert c.exact_at(3, 3)
    res = run_exact(c, 3, 3, 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    assert any(chart in x for x in res.reductions), res.reductions
    wrong = run_exact(_claim(bad), 3, 3, 0)
    assert wrong.verdict == "fails", (wrong.verdict, wrong.message)
    assert any("X = I, P = W" in x for x in wrong.reductions), wrong.reductions
