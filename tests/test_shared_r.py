"""A graph that involves no dimension r is run once per n: the pass that decides it, the records it gives
(every r's the same as a run of that size alone), and the claims it must leave alone."""
from __future__ import annotations

import os

import pytest

from stiefelsym.claims import Claim, Size, _mark_reviewed, admissible
from stiefelsym.ir import compile_claim
from stiefelsym.ir.passes import r_dependence
from stiefelsym.run import runner
from stiefelsym.scene import REALIZATIONS

needs_fork = pytest.mark.skipif(not hasattr(os, "fork"), reason="workers need os.fork")


def _claim(cid, func, n_max=3, reviewed=True, **kw) -> Claim:
    """A claim standing for one of the reviewed catalog (the only claims a plan traces in the parent)."""
    c = Claim(id=cid, paper=("t",), kind="id", section="9", func=func, sizes=admissible(n_max=n_max), **kw)
    return _mark_reviewed(c) if reviewed else c


def _commutator_symmetric(s):
    """[A, ξ] is symmetric for A symmetric and ξ skew (no point of T*V, no r)."""
    C = s.A @ s.xi - s.xi @ s.A
    return {"[A,xi]^T - [A,xi]": C.T - C}


def _commutator_skew(s):
    """A corrupted copy: [A, ξ] skew, false for every n >= 2 and every r."""
    C = s.A @ s.xi - s.xi @ s.A
    return {"[A,xi]^T + [A,xi]": C.T + C}


def _trace_of_ir(s):
    """tr(I_r) − 1 = 0: true at r = 1 only; the graph reads r through I_r."""
    return {"(tr I_r - 1) A": (s.tr(s.Ir) - 1) * s.A}


def _sized_by_r(s):
    """A generic n x r matrix G with G − G = 0: no point of T*V, but a leaf on ℝʳ."""
    G = s.generic("g", "n", "r")
    return {"G - G": G - G}


def _reads_a_point(s):
    """Φ is n x n, but built from X and P (of rank <= 2r): the value depends on r."""
    return {"Phi + Phi^T": s.Phi + s.Phi.T}


def _reads_r_as_a_number(s):
    """The number of r read by the claim (traced at fixed sizes only)."""
    return {"r A": s.A * int(s.r) - s.A * int(s.r)}


def _reads_n_as_a_number(s):
    """[A, ξ] symmetric, with a loop over n: traced at fixed sizes, the same graph at every r."""
    C = s.A @ s.xi - s.xi @ s.A
    for _ in range(int(s.n)):
        C = C + 0 * s.A
    return {"[A,xi]^T - [A,xi]": C.T - C}


def _graph(func, n=None, r=None):
    cons = REALIZATIONS["standard"]
    return compile_claim(func, n, r, (cons.name, cons.build))


def test_r_dependence_of_graphs():
    assert r_dependence(_graph(_commutator_symmetric)) == ""
    assert r_dependence(_graph(_commutator_skew)) == ""
    assert "Ir" in r_dependence(_graph(_trace_of_ir))
    assert "dimension r" in r_dependence(_graph(_sized_by_r))
    assert "Phi" in r_dependence(_graph(_reads_a_point))
    # traced at fixed sizes: r's number is a constant of the graph, which the pass cannot tell from an int;
    # the runner compares the graphs at (n, r) and (n, r0)
    assert r_dependence(_graph(_reads_r_as_a_number, 3, 2)) == ""
    assert _graph(_reads_r_as_a_number, 3, 2).digest() != _graph(_reads_r_as_a_number, 3, 1).digest()


def test_shared_size_is_a_function_of_the_claim_and_size():
    c = _claim("r-free", _commutator_symmetric)
    assert runner.shared_size(c, Size(3, 2)) == Size(3, 1)
    assert runner.shared_size(c, Size(3, 1)) == Size(3, 1)
    # the first attempt of auto decides r0: beyond the symbolic budget at r > 1, r0 is the least such r
    budget = _claim("r-free-budget", _commutator_symmetric, exact_max_n=2, exact_max_r=((3, 1),))
    assert runner.shared_size(budget, Size(3, 1)) == Size(3, 1)
    assert runner.shared_size(budget, Size(3, 3)) == Size(3, 2)
    for func in (_trace_of_ir, _sized_by_r, _reads_a_point, _reads_r_as_a_number):
        assert runner.shared_size(_claim("reads-r", func), Size(3, 2)) is None
    assert runner.shared_size(c, None) is None
    fixed = _claim("r-free-fixed", _reads_n_as_a_number)
    assert runner.shared_size(fixed, Size(3, 3)) == Size(3, 1)


def _records(results):
    """The records as a run writes them, without the seconds (the one field that differs between runs)."""
    out = {}
    for res in results:
        d = res.to_json()
        d.pop("seconds")
        out[(res.n, res.r, res.method)] = d
    return out


@needs_fork
@pytest.mark.parametrize("method,func", [("auto", _commutator_symmetric), ("modular", _commutator_symmetric),
                                         ("auto", _reads_n_as_a_number)])
def test_r_free_records_are_the_records_of_one_size_runs(method, func):
    c = _claim("r-free", func)
    results = runner.verify([c], methods=(method,), jobs=2, seed=3)
    sized = [res for res in results if res.n is not None]
    assert [(res.n, res.r) for res in sized] == [(s.n, s.r) for s in c.sizes]
    assert all(res.verdict in ("proved", "checked") and res.expected for res in sized)
    note = runner.shared_note(Size(3, 1))
    assert all(note in res.reductions for res in sized if res.n == 3)
    # one computation per n: its record (seconds included) at every r
    by_n = {}
    for res in sized:
        by_n.setdefault(res.n, set()).add(res.seconds)
    assert all(len(s) == 1 for s in by_n.values())
    # a run of one size alone gives the same record
    catalog = _records(results)
    for s in c.sizes:
        alone = runner.verify([c], sizes=[s], methods=(method,), jobs=1, seed=3)
        assert _records(alone)[(s.n, s.r, alone[0].method)] == catalog[(s.n, s.r, alone[0].method)]
        single = runner.run_one(c, s, method, 3)
        assert _records([single])[(s.n, s.r, single.method)] == catalog[(s.n, s.r, single.method)]


@needs_fork
def test_a_corrupted_r_free_claim_fails_at_every_r():
    c = _claim("r-free-corrupted", _commutator_skew)
    results = runner.verify([c], methods=("auto",), jobs=2, seed=0)
    sized = [res for res in results if res.n is not None and res.n >= 2]
    assert sized and all(res.verdict == "fails" and not res.expected for res in sized)
    assert {res.r for res in sized if res.n == 3} == {1, 2, 3}
    assert all(f"--size {res.n},{res.r} " in res.rerun for res in sized)
    for s in (Size(2, 2), Size(3, 3)):
        alone = runner.run_one(c, s, "auto", 0)
        assert alone.verdict == "fails" and (alone.n, alone.r) == (s.n, s.r)


@needs_fork
def test_a_claim_that_reads_r_is_not_shared():
    c = _claim("reads-r", _trace_of_ir, n_max=2)
    results = runner.verify([c], methods=("auto",), jobs=2, seed=0)
    verdicts = {(res.n, res.r): res.verdict for res in results if res.n is not None}
    assert verdicts == {(1, 1): "proved", (2, 1): "proved", (2, 2): "fails"}
    assert not any("involves no dimension r" in h for res in results for h in res.reductions)


def test_a_users_claim_is_not_traced_in_the_parent_to_plan():
    """Sharing across r is planned in the parent for the reviewed catalog only: a user's claim (not reviewed)
    runs as one task per size, traced in budgeted workers only (a claim that sleeps while traced once hung
    the parent's plan)."""
    calls = []

    def counted(s):
        calls.append(1)
        return {"A - A^T": s.A - s.A.T}

    from stiefelsym.run.runner import _run_shared
    c = _claim("user", counted, reviewed=False)
    tasks = [(0, 3, r, "modular", -1) for r in (1, 2, 3)]
    seen = []

    def run(ts):
        seen.append(list(ts))
        return iter([])

    list(_run_shared(run, tasks, [c]))
    assert seen == [tasks] and calls == []


@needs_fork
def test_the_copies_of_a_shared_run_are_marked_and_the_run_log_counts_its_seconds_once(tmp_path):
    """Each record copied from the one run at n (results.COPY_OF: not a field, never in results.json) names the
    record it copies, the record at the size the run was made at; the run log gives the seconds there only, and
    `stiefelsym speed` reads them once (the copies keep no seconds)."""
    import json
    from stiefelsym.cli import _run_log
    from stiefelsym.cli.speed import timed
    from stiefelsym.results import COPY_OF
    c = _claim("r-free", _commutator_symmetric)
    results = runner.verify([c], methods=("auto",), jobs=2, seed=3)
    sized = [res for res in results if res.n is not None]
    by_n: dict = {}
    for res in sized:
        by_n.setdefault(res.n, []).append(res)
    for n, group in by_n.items():
        owners = [res for res in group if not hasattr(res, COPY_OF)]
        assert len(owners) == 1
        assert all(getattr(res, COPY_OF) == (n, owners[0].r) for res in group if res is not owners[0])
    assert all(COPY_OF not in res.to_json() for res in results)
    rows = json.loads(_run_log(results, {}))["seconds"]
    assert [row[:5] for row in rows] == [[r.claim, r.n, r.r, r.method, r.variant] for r in results]
    assert sum(1 for row in rows if row[5] is not None) == len(results) - sum(len(g) - 1 for g in by_n.values())
    assert all(row[6] == {"copy of": list(getattr(r, COPY_OF))} for row, r in zip(rows, results) if len(row) > 6)
    counted = sum(1 for r in results if r.n is not None and not hasattr(r, COPY_OF))
    records = [{"claim": r.claim, "n": r.n, "r": r.r, "method": r.method, "variant": r.variant} for r in results]
    log = tmp_path / "run-log.json"
    log.write_text(_run_log(results, {}))
    assert sum(1 for r in timed(records, log) if r["n"] is not None and r["seconds"] is not None) == counted

