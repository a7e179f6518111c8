"""The float evaluation frees each value after its last use (:func:`stiefelsym.ir.evaluate.release_plan`,
:meth:`stiefelsym.native.Float64Backend.forget`): what it frees is only what the backend remembers,
so the residuals, their bounds and their term scales are those of an evaluation that keeps every
value to the end, bit for bit, and the peak memory is lower."""
from __future__ import annotations

import random
import tracemalloc

import numpy as np
import pytest

from stiefelsym.claims import load_catalog
from stiefelsym.fields import FloatField
from stiefelsym.ir import evaluate as ev
from stiefelsym.methods import call_claim, quiet_numpy
from stiefelsym.native import backend
from stiefelsym.scene import Scene


def _residuals(claim, n, r, keep: bool, monkeypatch) -> tuple[list, int]:
    """The claim's residual matrices (values, bound, scales) at one float64 point, and the peak of
    the memory traced during the evaluation; keep: every value kept to the end."""
    with monkeypatch.context() as mp:
        if keep:
            mp.setattr(ev, "_forgets", lambda scene: False)
        field = FloatField(None)
        scene = Scene(n, r, field, chart="cayley", rng=random.Random(f"release|{claim.id}|{n}|{r}"),
                      realization=claim.realization)
        with quiet_numpy():
            tracemalloc.start()
            try:
                checks = call_claim(claim.func, scene)
                peak = tracemalloc.get_traced_memory()[1]
            finally:
                tracemalloc.stop()
        out = []
        for name in sorted(checks):
            s = checks[name]._n
            out.append((name, s.v.copy(), float(s.e), np.array(s.m)))
        backend(field).release()
    return out, peak


@pytest.mark.parametrize("cid, n, r", [("neumann-lax", 40, 20), ("neumann-flow", 12, 5),
                                       ("coupled-dual-lax-along-corrected-flow", 4, 3)])
def test_freeing_values_changes_no_residual(monkeypatch, cid, n, r):
    claim = load_catalog().get(cid)
    kept, peak_kept = _residuals(claim, n, r, True, monkeypatch)
    freed, peak_freed = _residuals(claim, n, r, False, monkeypatch)
    assert [x[0] for x in kept] == [x[0] for x in freed]
    for (name, v0, e0, m0), (_name, v1, e1, m1) in zip(kept, freed):
        assert np.array_equal(v0, v1), name
        assert e0 == e1, name
        assert np.array_equal(m0, m1), name
    if n >= 40:
        assert peak_freed < peak_kept
