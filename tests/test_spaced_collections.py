"""The garbage collector runs less often while a claim is traced or evaluated at points, and as before
everywhere else; the verdicts are the same (negative controls)."""
import gc

import pytest

from stiefelsym import comm
from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.methods import fixed_size
from stiefelsym.methods.fixed_size import SPACED_COLLECTIONS, run_points, spaced_collections
from stiefelsym.run import runner


@pytest.fixture
def default_thresholds():
    old = gc.get_threshold()
    gc.set_threshold(700, 10, 10)
    yield (700, 10, 10)
    gc.set_threshold(*old)


def test_spaced_collections_raise_the_thresholds_and_restore_them(default_thresholds):
    with spaced_collections():
        assert gc.get_threshold() == SPACED_COLLECTIONS
        with spaced_collections():
            assert gc.get_threshold() == SPACED_COLLECTIONS
        assert gc.get_threshold() == SPACED_COLLECTIONS
    assert gc.get_threshold() == default_thresholds
    with pytest.raises(RuntimeError):
        with spaced_collections():
            raise RuntimeError("a run that raises")
    assert gc.get_threshold() == default_thresholds


def test_spaced_collections_never_lower_a_threshold_nor_switch_a_collector_on(default_thresholds):
    gc.set_threshold(50000, 5, 100)
    with spaced_collections():
        assert gc.get_threshold() == (50000, 20, 100)
    assert gc.get_threshold() == (50000, 5, 100)
    gc.set_threshold(0)
    with spaced_collections():
        assert gc.get_threshold()[0] == 0
    assert gc.get_threshold()[0] == 0


def projector_evolves(s):
    flow = s.dirac_flow(lambda t: t.killing(t.Phi, t.Phi) / 2)
    return {"d(XX^T)/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(s.Phi, s.X @ s.X.T)}


def projector_evolves_swapped(s):
    """Corrupted: the commutator in the wrong order."""
    flow = s.dirac_flow(lambda t: t.killing(t.Phi, t.Phi) / 2)
    return {"d(XX^T)/dt": s.d(lambda t: t.X @ t.X.T, flow) - comm(s.X @ s.X.T, s.Phi)}


def _claim(func):
    return Claim(id="test", paper=("prep",), kind="id", section="t", func=func, sizes=admissible(4))


def test_points_are_evaluated_and_claims_traced_with_spaced_collections(default_thresholds, monkeypatch):
    seen = {}
    real_points, real_digest = fixed_size._run_points, runner.graph_digest

    def points(*a, **k):
        seen["points"] = gc.get_threshold()
        return real_points(*a, **k)

    def digest(*a, **k):
        seen.setdefault("trace", gc.get_threshold())
        return real_digest(*a, **k)

    monkeypatch.setattr(fixed_size, "_run_points", points)
    monkeypatch.setattr(runner, "graph_digest", digest)
    good = runner.run_one(_claim(projector_evolves), Size(4, 2), "modular", 0)
    assert seen == {"points": SPACED_COLLECTIONS, "trace": SPACED_COLLECTIONS}
    assert good.verdict == "checked"
    assert gc.get_threshold() == default_thresholds


@pytest.mark.parametrize("kind", ["modular", "rational"])
def test_a_corrupted_claim_still_fails_at_points(default_thresholds, kind):
    assert run_points(_claim(projector_evolves_swapped), 4, 2, kind, 0).verdict == "fails"
    assert run_points(_claim(projector_evolves), 4, 2, kind, 0).verdict == "checked"
    assert gc.get_threshold() == default_thresholds
