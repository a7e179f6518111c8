"""The normal part of a tangent vector on the exact method's charts: P = XW + (I − XXᵀ)Z with
Z = [0; Z2] (its first r rows 0).  Where the top r x r block of X is invertible (a dense open set
of the chart) Z2 ↦ (I − XXᵀ)[0; Z2] is onto the normal space, so the chart stays dense in T*V with
r² fewer parameters; for r = n the normal space is 0 and P = XW.

Negative controls: the top rows of the normal part vanish at X = X0 = [I; 0] but not at a generic
X, so a claim that they vanish (false on T*V) is refused on the reduced Cayley chart, on the second
point of the equivariant chart and on the complex point; a false 'XᵀP = 0' is refused at r = n."""
from __future__ import annotations

import pytest

from stiefelsym import admissible
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.claims import Claim
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.scene import Scene


def _claim(func, cid="t-normal"):
    return Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7))


def _top_normal_X(s):
    """Entry (1, 1) of (I − XXᵀ)P: 0 at X0 = [I; 0], not at a generic point (reads an entry: the
    Cayley chart)."""
    N = (s.In - s.X @ s.X.T) @ s.P
    return {"((I - XX^T)P)[0,0]": N[0, 0]}


def _cotangent_X(s):
    """XᵀP + PᵀX = 0 and XᵀX = I, read entrywise (the Cayley chart)."""
    M, G = s.X.T @ s.P + s.P.T @ s.X, s.X.T @ s.X - s.Ir
    return {"(X^T P + P^T X)[0,0]": M[0, 0], "(X^T X - I)[0,0]": G[0, 0], "X^T P + P^T X": M}


def _top_normal_Y(s):
    """Xᵀ(I − YYᵀ)Q: covariant (the equivariant chart), and at X = X0 the top rows of the normal part
    of Q; not 0 on T*V × T*V."""
    return {"X^T (I - YY^T) Q": s.X.T @ (s.In - s.Y @ s.Y.T) @ s.Q}


def _XtP_vanishes(s):
    return {"(X^T P)[0,1]": (s.X.T @ s.P)[0, 1]}


def _top_rows_of_normal(s, X, P):
    """The first r rows of (I − XXᵀ)P as symbolic entries."""
    return ((s.identity(s.n, "n") - X @ X.T) @ P)._view()[:s.r, :]


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_the_reduced_cayley_chart_has_r_squared_fewer_normal_parameters_and_stays_on_T_V(n, r):
    s = Scene(n, r, SymbolicField(), chart="cayley")
    X, P = s.X, s.P
    assert (X.T @ X - s.Ir).is_zero() and (X.T @ P + P.T @ X).is_zero()
    names = [k for k in s.params if k.startswith("Z")]
    assert len(names) == (n - r) * r
    # the normal part is not confined to the rows of Z2: its top rows are nonzero functions
    assert any(not s._field.is_zero(x) for x in _top_rows_of_normal(s, X, P).ravel())


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2), (5, 2)])
def test_a_false_top_normal_rows_claim_fails_on_the_reduced_cayley_chart(n, r):
    res = run_exact(_claim(_top_normal_X), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert any("Z = [0; Z2]" in d for d in res.reductions), res.reductions


@pytest.mark.parametrize("n,r", [(3, 2), (4, 2), (3, 3)])
def test_the_cotangent_conditions_are_proved_on_the_cayley_chart(n, r):
    res = run_exact(_claim(_cotangent_X), n, r, 0)
    assert res.verdict == "proved", (res.verdict, res.message)


@pytest.mark.parametrize("n", [2, 3])
def test_r_equals_n_keeps_P_generic_in_the_tangent_space(n):
    s = Scene(n, n, SymbolicField(), chart="cayley")
    assert not [k for k in s.params if k.startswith("Z")]
    X, P = s.X, s.P
    assert (X.T @ P + P.T @ X).is_zero()
    assert not (X.T @ P).is_zero()
    res = run_exact(_claim(_XtP_vanishes), n, n, 0)
    assert res.verdict == "fails", (res.verdict, res.message)


@pytest.mark.parametrize("n,r", [(3, 1), (4, 2)])
def test_a_false_top_normal_rows_claim_fails_on_the_second_point(n, r):
    res = run_exact(_claim(_top_normal_Y), n, r, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert any("Z' generic with its first r rows 0" in d for d in res.reductions), res.reductions


def test_the_complex_point_keeps_a_generic_normal_part():
    s = Scene(3, 1, SymbolicField(), chart="equivariant")
    Z, V = s.Zc, s.Zc_dot
    # Z^* V + V^* Z = 0 (realified: Zᵀ V + Vᵀ Z = 0) and Z^* Z = I identically
    assert (Z.T @ V + V.T @ Z).is_zero() and (Z.T @ Z - s.identity(2, "r+r")).is_zero()
    top = ((s.identity(6, "n+n") - Z @ Z.T) @ V)._view()
    assert any(not s._field.is_zero(top[i, j]) for i in (0, 3) for j in range(2))
