"""Stop 96, h4 (an adversary of issue 20's routes and of the stop's new mechanisms): the degree guard of the exact
and rational methods reads the degree of every value computed on the way to the residuals, not only theirs."""
from __future__ import annotations

from pathlib import Path

import pytest

import stiefelsym

FILES = Path(__file__).with_name("s96") / "h4"


@pytest.mark.parametrize("cid, truth", [("h4t-pow0-true", "holds"), ("h4t-times-zero-true", "holds"),
                                        ("h4t-recip-pow0-true", "holds"), ("h4t-pow0-false", "fails")])
def test_a_value_beyond_expansion_on_the_way_is_inconclusive_at_once(cid, truth):
    """(u^(2^40))^0 − 1 = 0, 0 · u^(2^40) = 0, ((1/u)^(2^40))^0 − 1 = 0: the residuals' structural degree is 0 (or
    none), below EXPANDABLE_DEGREE, so the degree guard let the exact and rational methods evaluate them, and both
    wrote u^(2^40) out until flint failed to allocate (213 s, then `inconclusive` / `error`: the child process died
    by SIGABRT).  The guard reads the largest degree of a numerator or a denominator of every value the degree
    markers stood for: both answer `inconclusive` at once, and the modular method still decides."""
    from stiefelsym.methods import fixed_size as fs
    claims = stiefelsym.load(files=[FILES / "c2_degree.py"], catalog=False)
    c = next(x for x in claims if x.id == cid)
    for res in (fs.run_exact(c, 2, 1, 0), fs.run_points(c, 2, 1, "rational", 0)):
        assert res.verdict == "inconclusive", res.message
        assert "a value it computes" in res.message and str(fs.EXPANDABLE_DEGREE) in res.message
    assert fs.run_points(c, 2, 1, "modular", 0).verdict == ("checked" if truth == "holds" else "fails")
    bound = fs.degree_bound(c, 2, 1)
    assert bound.peak >= 2 ** 40 > fs.EXPANDABLE_DEGREE >= bound.numerator


SCALE = [1]


@pytest.mark.xfail(strict=True, reason="open by design: a function's graph is cached per process, keyed by its "
                   "identity (docs/architecture.md, 'Trace twice'): a claim of the caller's own process changed "
                   "after a run keeps its first graph; binding the cache to what the function computes with "
                   "(ir.seal.reach) closed it but let another claim's in-place change of a shared Fraction reach "
                   "a later trace (test_ir_routes, s59): a refusal of the changed function is the fix left")
def test_a_function_changed_after_a_run_in_the_callers_process_is_traced_again():
    """A claim of the caller's own process (``claim(...)(f).claim``), proved at (3, 2), then its function's
    ``__code__`` swapped for X^T P = 0's, one of its defaults set to 0, or a global it reads rebound: the graph
    cache (keyed by the function's identity) handed back the first graph, and exact, modular and float said
    `proved`, `checked`, `numeric` of a false statement (a fresh process: `fails`).  The cache keeps what the
    function computes with beside its graph (its code, defaults, closure and the globals it and its helpers read,
    as the review of the catalog's functions does) and traces a function changed since again."""
    from stiefelsym import admissible, claim
    from stiefelsym.methods import fixed_size as fs

    def body(s):
        return {"r": s.X.T @ s.P + s.P.T @ s.X}

    def false_body(s):
        return {"r": s.X.T @ s.P}

    def by_default(s, k=1):
        return {"r": s.X.T @ s.P + s.P.T @ s.X * k}

    def by_global(s):
        return {"r": s.X.T @ s.P + s.P.T @ s.X * SCALE[0]}

    sz = admissible(n_min=2, n_max=3)
    c1 = claim("h4s-code", kind="id", sizes=sz)(body).claim
    c2 = claim("h4s-default", kind="id", sizes=sz)(by_default).claim
    c3 = claim("h4s-global", kind="id", sizes=sz)(by_global).claim
    for c in (c1, c2, c3):
        assert fs.run_exact(c, 3, 2, 0).verdict == "proved"
        assert fs.run_points(c, 3, 2, "modular", 0).verdict == "checked"
    body.__code__ = false_body.__code__
    by_default.__defaults__ = (0,)
    SCALE[0] = 0
    try:
        for c in (c1, c2, c3):
            assert fs.run_exact(c, 3, 2, 0).verdict == "fails", c.id
            assert fs.run_points(c, 3, 2, "modular", 0).verdict == "fails", c.id
            assert [r.verdict for r in stiefelsym.verify([c], sizes=[(3, 2)], methods=["float"], jobs=1)] == ["fails"]
    finally:
        SCALE[0] = 1


def test_the_float_methods_confirmation_goes_modulo_a_prime_where_the_rational_point_is_beyond_expansion():
    """(u^(2^40))^0 − 1 + tr(XᵀX) = 0 (false: it is r): float64's residual 1 exceeds its error bound, and the
    confirmation at an exact rational point is `inconclusive` (a value of degree 2^40 on the way, beyond what it
    writes out); the float method said "the exact check passed (inconclusive): the bound is too optimistic here"
    and answered `inconclusive`.  A point modulo a prime evaluates any degree: its nonzero residual refutes."""
    from stiefelsym.methods import fixed_size as fs
    claims = stiefelsym.load(files=[FILES / "c2_degree.py"], catalog=False)
    c = next(x for x in claims if x.id == "h4t-pow0-false")
    res = fs.run_float(c, 2, 1, 0)
    assert res.verdict == "fails" and "confirmed by an exact modular witness" in res.certificate, res.message
    true = next(x for x in claims if x.id == "h4t-pow0-true")
    assert fs.run_float(true, 2, 1, 0).verdict == "numeric"


def test_a_divisor_below_float64s_range_is_no_error_of_the_ball_backend():
    """w^(−2^21) · w^(2^21) − 1 = 0 (true; w = (u + 1)/(u + 2) < 1): the arb ball of w^(2^21) excludes 0, but the
    float64 of its lower bound is 0.0, and the term scale's division raised ZeroDivisionError: `error` under ball
    and under float (whose ladder reaches ball arithmetic).  The term scale overflows float64 there, which the
    resolution test already treats as unresolved: ball is `inconclusive`, float `numeric` (mpmath's range holds
    w^(2^21)), and the false twin still fails under both."""
    from stiefelsym.methods import fixed_size as fs
    claims = stiefelsym.load(files=[FILES / "c2_degree.py"], catalog=False)
    true = next(x for x in claims if x.id == "h4t-negpow-true")
    false = next(x for x in claims if x.id == "h4t-negpow-false")
    assert fs.run_ball(true, 2, 1, 0).verdict == "inconclusive"
    assert fs.run_float(true, 2, 1, 0).verdict == "numeric"
    assert fs.run_ball(false, 2, 1, 0).verdict == "fails"
    assert fs.run_float(false, 2, 1, 0).verdict == "fails"
