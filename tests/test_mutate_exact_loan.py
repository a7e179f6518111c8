"""The symbolic method evaluates a mutant on the chart of the claim as printed and takes the values of
the subgraphs the change does not reach (stiefelsym.methods.fixed_size.PointLoan.chart): every result the same as
on a chart of its own, the chart decided from the mutant's own looks at coordinates; a shared value
that does not record again what its computation looked at is caught."""
from __future__ import annotations

import pytest

from stiefelsym.methods import fixed_size as M
from stiefelsym.claims import Size, load_catalog
from stiefelsym.backends.matrix import CoordinateTracker
from stiefelsym.analyses.mutate import run_mutation

#: claims on the equivariant chart (with and without a stated reason, a rank) and on the Cayley chart
#: (eigenvalues a_i of A, entries), a few mutants each
CLAIMS = ("euclidean-flow", "neumann-lax", "euler-so-n", "mum-geod", "adjoint-orbit-dimension")


def symbolic_runs(claims, monkeypatch, lend=True, **kw):
    """Every result of the symbolic method in the order of the runs: verdict, chart(s), message,
    residual, certificate and the checks."""
    seen = []
    real = M.run_exact

    def recorded(claim, n, r, seed, func=None, time_budget=None):
        res = real(claim, n, r, seed, func, time_budget)
        seen.append((claim.id, n, r, res.verdict, tuple(res.reductions), res.message, res.residual,
                     res.certificate, [(o.name, o.status, o.detail) for o in res.checks]))
        return res
    monkeypatch.setattr(M, "run_exact", recorded)
    monkeypatch.setattr(M, "isolates", lambda *a, **k: False)     # every run in this process
    run_mutation(claims, methods=("exact", "rational"), lend=lend, **kw)
    return seen


@pytest.fixture(scope="module")
def claims():
    reg = load_catalog()
    return [reg.get(c) for c in CLAIMS]


@pytest.fixture(scope="module")
def fresh(claims):
    with pytest.MonkeyPatch.context() as mp:
        return symbolic_runs(claims, mp, lend=False, limit=8)


def test_a_lent_chart_gives_the_results_of_a_chart_of_its_own(claims, fresh, monkeypatch):
    lent = symbolic_runs(claims, monkeypatch, limit=8)
    assert len(lent) >= 60
    assert {x[4] for x in lent if x[4]} >= {x[4] for x in fresh if x[4]}     # both charts, both ways
    assert any("equivariance" in c for x in lent for c in x[4]) and any("rational param" in c for x in lent for c in x[4])
    assert lent == fresh


def test_the_lent_chart_shares_the_values(claims, monkeypatch):
    """The mutants' runs take most of their symbolic products from the printed claim's run."""
    from stiefelsym.backends.polyfield import PolyBackend
    count = [0]
    real = PolyBackend.matmul

    def counted(self, a, b):
        count[0] += 1
        return real(self, a, b)
    monkeypatch.setattr(PolyBackend, "matmul", counted)
    monkeypatch.setattr(M, "isolates", lambda *a, **k: False)
    run_mutation(claims[:2], methods=("exact",), limit=8)
    lent, count[0] = count[0], 0
    run_mutation(claims[:2], methods=("exact",), limit=8, lend=False)
    assert 0 < 3 * lent < count[0]


def test_a_shared_value_that_does_not_record_its_looks_again_is_caught(claims, fresh, monkeypatch):
    """Negative control: shared values that leave out what their computation recorded (entries read,
    a_i asked for) give a mutant the printed claim's chart decisions no more, and results change."""
    monkeypatch.setattr(CoordinateTracker, "replay", lambda self, log: None)
    assert symbolic_runs(claims, monkeypatch, limit=8) != fresh


def test_the_record_of_a_lent_chart_starts_empty():
    """A lent chart's record is the kept scene's record object (the shared matrices record into it),
    emptied: what the printed claim or an earlier mutant looked at is not seen."""
    from stiefelsym.backends.polyfield import SymbolicField
    from stiefelsym.scene import Scene
    loan = M.PointLoan()

    def build():
        f = SymbolicField()
        return f, Scene(Size(4, 2).n, 2, f, chart="equivariant")
    loan.recording = True
    f, s = loan.chart(("k",), build)
    X = s.X
    X[0, 0]
    assert s.tracker.used == ("matrix entries",)
    loan.recording = False
    f1, s1 = loan.chart(("k",), build)
    assert f1 is f and s1 is not s and s1.tracker is s.tracker and s1.tracker.used == ()
    assert "X" not in s1._cache and s1._params == s._params
    assert (s1.X - X).is_zero()                    # built again, from the same symbols
    X[1, 1]                                        # a matrix of the printed claim's run records here
    assert s1.tracker.used == ("matrix entries",)
    f2, s2 = loan.chart(("k",), build)
    assert s2.tracker.used == ()

