"""A proof at one size from the dimension-free proof of the same graph (stiefelsym.methods.specialise).

Beyond a claim's symbolic budget the exact method (and ``auto``) proves a claim at (n, r) when the
graph the run evaluates there is the graph the dimension-free method proved for every n, r, and the
modular method's points at (n, r) agree.  A false statement is never proved this way; a dimension-free
"proof" that the modular points contradict is an ``error``, not a verdict; within the budget the
exact method's own chart still proves the claim."""
from __future__ import annotations

import dataclasses

import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, Size, load_catalog
from stiefelsym.methods import specialise
from stiefelsym.methods.fixed_size import mutation_analysis
from stiefelsym.results import Result
from stiefelsym.run.runner import run_one

SPECIALISED = "the dimension-free proof, specialised"


def _claim(func, cid=None, exact_max_n=2, sizes=None, **kw):
    return Claim(id=cid or func.__name__.replace("_", "-"), paper=("prep",), kind="id", section="t", func=func,
                 sizes=sizes or admissible(7), exact_max_n=exact_max_n, **kw)


def dual_gram(s):
    """True: Xᵀ(XXᵀ)P + PᵀX = 0 on T*V (XᵀX = I, XᵀP + PᵀX = 0)."""
    return {"XtXXtP + PtX": s.X.T @ (s.X @ s.X.T) @ s.P + s.P.T @ s.X}


def dual_gram_flipped(s):
    """False: one sign flipped."""
    return {"XtXXtP - PtX": s.X.T @ (s.X @ s.X.T) @ s.P - s.P.T @ s.X}


def dual_gram_dropped(s):
    """False: a term dropped (XᵀP alone)."""
    return {"XtP": s.X.T @ s.P}


#: the dimension-free results of the process forgotten before and after each test
pytestmark = pytest.mark.usefixtures("fresh_specialise")


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_beyond_the_budget_the_dimension_free_proof_is_specialised(method):
    c = _claim(dual_gram)
    for n, r in ((3, 2), (7, 3), (6, 6)):
        res = run_one(c, Size(n, r), method, 0)
        assert res.verdict == "proved" and res.method == "exact", (n, r, res.verdict, res.message)
        assert res.reductions[0].startswith(SPECIALISED) and (res.n, res.r) == (n, r)
        assert "cross-check" in res.reductions[-1] and res.seed == 0
        assert "independent checker" in res.certificate


def test_within_the_budget_the_exact_method_uses_its_own_chart():
    c = _claim(dual_gram, exact_max_n=7)
    res = run_one(c, Size(4, 2), "exact", 0)
    assert res.verdict == "proved"
    assert not any(x.startswith(SPECIALISED) for x in res.reductions)


@pytest.mark.parametrize("func", [dual_gram_flipped, dual_gram_dropped])
@pytest.mark.parametrize("method", ["exact", "auto"])
def test_a_corrupted_claim_is_not_proved(func, method):
    c = _claim(func)
    res = run_one(c, Size(5, 2), method, 0)
    assert res.verdict not in ("proved", "checked", "numeric"), (res.verdict, res.reductions)


def test_a_dimension_free_proof_contradicted_by_the_points_is_an_error(monkeypatch):
    """An unsound dimension-free method (simulated: it 'proves' a false statement) is caught by the
    cross-check at the size: error, never proved or fails."""
    c = _claim(dual_gram_dropped)
    borrowed = specialise.run_free(_claim(dual_gram)).certificate_data   # a valid certificate, of another claim

    def unsound(claim, func=None):
        res = Result(claim=claim.id, paper=[], section="", kind="id", title="", statement="", n=None, r=None,
                     method="free", verdict="proved", expected=True, seconds=0.0, seed=None)
        res.certificate_data, res.certificate = borrowed, "forged"
        return res
    monkeypatch.setattr(specialise, "run_free", unsound)
    res = run_one(c, Size(5, 2), "exact", 0)
    assert res.verdict == "error" and "disagree" in res.message


def test_a_graph_other_than_the_proved_one_is_not_specialised(monkeypatch):
    """The proof is used only for the graph it is about: a digest that differs at the size (simulated)
    leaves the run to the modular method."""
    c = _claim(dual_gram)
    real = specialise.compile_claim

    class Other:
        def __init__(self, g):
            self.g = g

        def digest(self):
            return "0" * 64
    monkeypatch.setattr(specialise, "compile_claim",
                        lambda f, n, r, cons, family=None: Other(real(f, n, r, cons)) if n is not None
                        else real(f, n, r, cons, family=family))
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "checked" and res.method == "modular"


def test_a_changed_claim_is_proved_again():
    """The dimension-free result is kept per claim and function while what it reads of the claim is
    unchanged: a claim object changed in place (its expectation) is not given the old proof."""
    c = _claim(dual_gram)
    assert run_one(c, Size(5, 2), "exact", 0).verdict == "proved"
    object.__setattr__(c, "expect", "nonzero")
    res = run_one(c, Size(5, 2), "exact", 0)
    assert not any(x.startswith(SPECIALISED) for x in res.reductions)
    other = dataclasses.replace(c, func=dual_gram_flipped, expect="holds")
    assert run_one(other, Size(5, 2), "exact", 0).verdict != "proved"


def test_the_mutation_analysis_does_not_lend_the_proof():
    c = _claim(dual_gram)
    with mutation_analysis():
        res = run_one(c, Size(5, 2), "auto", 0)
    assert res.method == "modular" and res.verdict == "checked"


@pytest.mark.parametrize("cid,n,r", [("coupled-dual-lax", 7, 5), ("dual-lax-spectral-invariants", 6, 3),
                                     ("manakov-reflections", 7, 2)])
def test_catalog_claims_with_a_dimension_free_proof_are_proved_at_n_7(cid, n, r):
    c = load_catalog().get(cid)
    assert not c.exact_at(n, r)
    res = run_one(c, Size(n, r), "auto", 0)
    assert res.verdict == "proved" and res.reductions[0].startswith(SPECIALISED), (res.verdict, res.message)


def test_a_catalog_erratum_is_still_refuted():
    """A claim the dimension-free method does not prove (an erratum as printed) fails at sizes beyond its
    budget as before."""
    c = load_catalog().get("coupled-perturbed-big-lax")
    res = run_one(c, Size(5, 2), "auto", 0)
    assert res.verdict == "fails"


def test_a_correction_rebuilt_for_each_run_shares_one_dimension_free_attempt(monkeypatch):
    """A correction's claim is a new object at each run: its dimension-free result is found by the claim's id,
    its function and what the method reads of it; a claim that reads differently is attempted again."""
    from unittest import mock
    import stiefelsym.run.isolate as isolate
    spy = mock.Mock(wraps=isolate.run_isolated)
    monkeypatch.setattr(isolate, "run_isolated", spy)
    c = _claim(dual_gram)
    for n, r in ((4, 2), (5, 3), (6, 2)):
        fresh = dataclasses.replace(c)
        assert fresh is not c and run_one(fresh, Size(n, r), "exact", 0).verdict == "proved"
    assert spy.call_count == 1
    other = dataclasses.replace(c, realization="metric")
    run_one(other, Size(4, 2), "exact", 0)
    assert spy.call_count >= 2      # attempted again (the exact chart that follows may fork too)


def test_a_metric_proof_reads_the_same_whatever_ran_before_it_in_the_process():
    """The multipliers Λ of the metric flows are numbered from 1 in each dimension-free run: a specialised proof
    of metric-flow at (5, 2) read Λ:1 or Λ:2 by the worker it ran in (the numbers went on from run to run), so a
    catalog run was not reproduced byte for byte (stop 88)."""
    from stiefelsym.methods.dimension_free import run_free
    from stiefelsym.run import runner
    cat = load_catalog()
    first, _ = runner._specialised(cat.get("metric-flow"), Size(5, 2), 0, None, 0.0, None)
    for c in [c for c in cat if c.realization == "metric"][:3]:
        run_free(c)
    specialise._FREE.clear()
    again, _ = runner._specialised(cat.get("metric-flow"), Size(5, 2), 0, None, 0.0, None)
    assert first.verdict == again.verdict == "proved"
    assert "Lambda:1" in first.certificate and first.certificate == again.certificate
    assert first.reductions == again.reductions


def _false_at_five(s):
    """False at n = 5 only (the claim reads n as a number: its graph at (5, r) is not its graph at other sizes)."""
    bump = s.q(1) if int(s.n) == 5 else s.q(0)
    return {"r": s.X.T @ s.X - s.Ir + s.Ir * bump}


def test_auto_from_n_5_takes_no_dimension_free_proof_of_another_graph():
    """auto takes the dimension-free proof first from n = 5 on (runner.FREE_FIRST_N) only for the graph it proves:
    a claim false at n = 5 alone fails there, and holds at (6, 2)."""
    c = Claim(id="t88-false-at-5", paper=("t",), kind="id", section="t", func=_false_at_five,
              sizes=admissible(n_max=6))
    assert run_one(c, Size(5, 2), "auto", 0).verdict == "fails"
    assert run_one(c, Size(6, 2), "auto", 0).verdict == "proved"


def test_a_dimension_free_result_kept_in_one_process_is_taken_in_another_without_a_new_attempt(monkeypatch):
    """What one worker kept of a claim's dimension-free run (its record with no size, the proofs of its attempts)
    is handed over once (take_kept) and adopted by another worker, whose run at a size then makes no attempt of
    its own and gives the record it would have given; a claim that reads differently adopts nothing."""
    from unittest import mock
    from stiefelsym.methods.dimension_free import run_free
    import stiefelsym.run.isolate as isolate
    c = _claim(dual_gram)
    expected = run_one(c, Size(5, 2), "auto", 0)
    assert SPECIALISED in expected.reductions[0]
    specialise._FREE.clear()
    specialise.remember(c, None, run_free(c))
    entries = specialise.take_kept(c, None)
    assert len(entries) == 1 and entries[0][0] is None and entries[0][3].verdict == "proved"
    assert specialise.take_kept(c, None) == []          # handed over once
    specialise._FREE.clear()
    other = dataclasses.replace(c, realization="metric")
    specialise.adopt(other, None, entries)
    assert not specialise._FREE
    specialise.adopt(c, None, entries)
    assert specialise.take_kept(c, None) == []          # an adopted result is not handed over again
    spy = mock.Mock(wraps=isolate.run_isolated)
    monkeypatch.setattr(isolate, "run_isolated", spy)
    got = run_one(c, Size(5, 2), "auto", 0)
    assert spy.call_count == 0
    assert dataclasses.replace(got, seconds=0.0) == dataclasses.replace(expected, seconds=0.0)


def test_two_workers_give_the_records_one_worker_gives():
    """With two workers the claim's dimension-free results are handed from the worker that kept them to the other
    (runner.FREE_KEPT): the records are those of one worker (timings aside), and none carries what was handed."""
    from stiefelsym.run import runner
    c = _claim(dual_gram)
    sizes = [Size(5, 2), Size(6, 2), Size(6, 3), Size(7, 2), Size(7, 3)]
    one = runner.verify([c], sizes=sizes, methods=("free", "auto"), jobs=1)
    two = runner.verify([c], sizes=sizes, methods=("free", "auto"), jobs=2)
    assert [dataclasses.replace(x, seconds=0.0) for x in one] == [dataclasses.replace(x, seconds=0.0) for x in two]
    assert all(SPECIALISED in x.reductions[0] for x in two if x.n is not None)
    assert not any(hasattr(x, runner.FREE_KEPT) for x in one + two)
