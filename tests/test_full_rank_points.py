"""A generic rank equal to its matrix's full size, proved at one point of each component.

The point methods (modular, rational) evaluate a rank at random points; a rank there is a lower bound on
the generic rank (a nonzero minor at a point is a nonzero rational function; mod p, its numerator's
reduction is not 0), and no rank exceeds the matrix's full size.  So when every check of a claim is a
generic rank equal to its matrix's full size at a point of each component, the claim is proved (both
sides, no probability).  Anything less stays a randomized check, or fails, as before."""
from __future__ import annotations

import pytest

from stiefelsym import Rank, admissible
from stiefelsym.claims import Claim, Size, load_catalog
from stiefelsym.run.runner import run_one

POINTS = ("modular", "rational")


def _claim(func):
    return Claim(id=func.__name__.replace("_", "-"), paper=("prep",), kind="dim", section="t", func=func,
                 sizes=admissible(6), exact_max_n=1)


def full_column_rank(s):
    """X Xᵀ A X has full column rank r (n x r)."""
    return {"rank": Rank(s.X @ s.X.T @ s.A @ s.X, 2, generic=True)}


def one_more_than_full(s):
    """False: rank 3 for an n x 2 matrix at r = 2."""
    return {"rank": Rank(s.X @ s.X.T @ s.A @ s.X, 3, generic=True)}


def full_size_but_singular(s):
    """False: XᵀX - I (= 0 on V) of full rank 2."""
    return {"rank": Rank(s.X.T @ s.X - s.Ir + s.X.T @ s.P + s.P.T @ s.X, 2, generic=True)}


def below_full(s):
    """True: X Xᵀ (n x n) has rank r < n: not full, a randomized check."""
    return {"rank": Rank(s.X @ s.X.T, 2, generic=True)}


def full_with_a_residual(s):
    """True, with a residual beside the rank: the residual is a randomized check."""
    return {"rank": Rank(s.X @ s.X.T @ s.A @ s.X, 2, generic=True), "XtX": s.X.T @ s.X - s.Ir}


def full_at_every_point(s):
    """Full rank at EVERY point: one point proves nothing of every point."""
    return {"rank": Rank(s.X @ s.X.T @ s.A @ s.X, 2, generic=False)}


@pytest.mark.parametrize("method", POINTS)
@pytest.mark.parametrize("n,r", [(4, 2), (2, 2)])
def test_a_full_generic_rank_is_proved_at_a_point_of_each_component(method, n, r):
    res = run_one(_claim(full_column_rank), Size(n, r), method, 0)
    assert res.verdict == "proved" and res.false_pass_bound is None, (res.verdict, res.message)
    assert "full size" in res.certificate
    if r == n:
        assert "each of the 2 components" in res.certificate


@pytest.mark.parametrize("method", POINTS)
@pytest.mark.parametrize("func,verdicts", [(one_more_than_full, ("inconclusive", "fails")),
                                           (full_size_but_singular, ("inconclusive", "fails")),
                                           (below_full, ("checked",)),
                                           (full_with_a_residual, ("checked",)),
                                           (full_at_every_point, ("undecided",))])
def test_anything_less_is_not_proved(method, func, verdicts):
    res = run_one(_claim(func), Size(4, 2), method, 0)
    assert res.verdict in verdicts, (func.__name__, res.verdict, res.message)


def test_the_catalog_claim_of_full_rank_is_proved_at_n_7():
    c = load_catalog().get("dual-lax-determines-the-point")
    assert not c.exact_at(6, 3)
    res = run_one(c, Size(6, 3), "auto", 0)
    assert res.verdict == "proved" and res.method == "modular", (res.verdict, res.message)


def skew_claimed_full(s):
    """False at odd r: XᵀP is skew on T*V (XᵀP + PᵀX = 0), so its rank is at most r − 1 when r is odd."""
    return {"rank": Rank(s.X.T @ s.P, 3, generic=True)}


@pytest.mark.parametrize("method", POINTS + ("auto",))
def test_an_odd_skew_matrix_claimed_of_full_rank_is_not_proved(method):
    """A careful-looking full-rank claim that the constraints make false: every point of T*V refutes the
    full size (the rank there is r − 1), so no point proves it."""
    res = run_one(_claim(skew_claimed_full), Size(4, 3), method, 0)
    assert res.verdict not in ("proved", "checked", "numeric"), (method, res.verdict, res.certificate)
