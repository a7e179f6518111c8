"""The exact method's rank certificates: a lower bound at an exact rational point, the
function-field rank by fraction-free elimination over flint polynomials, and the randomized
upper bound when the symbolic rank is out of reach."""
from __future__ import annotations

import random

import pytest
import sympy as sp

from stiefelsym import Rank, admissible
from stiefelsym.methods import fixed_size as methods
from stiefelsym.claims import Claim
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import Mat
from stiefelsym.methods.fixed_size import ExactTimeout, _bareiss_rank, _flint_polynomials, run_exact


def _claim(func, cid="rank-trick"):
    return Claim(id=cid, paper=("2l",), kind="dim", section="t", func=func, sizes=admissible(4))


def ad_phi(s):
    """ad_Φ on so(n) in the basis E_ij: its rank is 2l (Lemma 2l)."""
    n = s.n
    basis = [(i, j) for i in range(n) for j in range(i + 1, n)]
    cols = []
    for i, j in basis:
        E = s.mat([[1 if (a, b) == (i, j) else -1 if (a, b) == (j, i) else 0 for b in range(n)]
                   for a in range(n)], ("n", "n"))
        cols.append(s.Phi @ E - E @ s.Phi)
    return [[c[a, b] for c in cols] for a, b in basis]


def rank_claim(expected):
    def f(s):
        return {"rank": Rank(s.mat(ad_phi(s), ("so", "so")), expected(s.n, s.r), generic=True)}
    return f


def two_l(n, r):
    return n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)


@pytest.mark.slow   # sympy's rank as the reference (10 s): run by `make verify-all`
def test_bareiss_rank_agrees_with_sympy():
    rng = random.Random(1)
    x = sp.symbols("x0:4")
    for _ in range(6):
        m, k = rng.randint(2, 5), rng.randint(2, 5)
        rows = [[sum(rng.randint(-2, 2) * xi for xi in x[:2]) + rng.randint(-1, 1) for _ in range(k)]
                for _ in range(m)]
        if rng.random() < 0.5:   # make a dependent row
            rows.append([a + 2 * b for a, b in zip(rows[0], rows[1])])
        import symengine as se
        M = Mat._rows([[se.sympify(str(v)) for v in row] for row in rows], SymbolicField())
        assert _bareiss_rank(_flint_polynomials(M)) == sp.Matrix(rows).rank()


def test_printed_rank_is_proved_two_sided():
    res = run_exact(_claim(rank_claim(two_l)), 3, 1, 0)
    assert res.verdict == "proved" and "two-sided" in res.certificate


@pytest.mark.parametrize("shift", [-1, 1])
def test_a_wrong_rank_fails(shift):
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) + shift)), 3, 1, 0)
    assert res.verdict == "fails"


def test_beyond_the_symbolic_budget_the_upper_bound_is_randomized(monkeypatch):
    def timeout(M):
        raise ExactTimeout("the function-field rank")
    monkeypatch.setattr(methods, "_function_field_rank", timeout)
    res = run_exact(_claim(rank_claim(two_l)), 3, 1, 0)
    assert res.verdict == "checked" and res.false_pass_bound is not None and res.false_pass_bound <= 1e-30
    assert "random points of prime fields" in res.certificate
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) - 1)), 3, 1, 0)
    assert res.verdict == "fails"       # a rank above the printed one is certain at a rational point
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) + 1)), 3, 1, 0)
    assert res.verdict == "inconclusive"   # below the printed rank at one point: not certain without the symbolic rank
