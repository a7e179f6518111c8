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


def _pooled_residuals(claim, n, r, monkeypatch, pool: bool, min_bytes: int) -> list:
    """The claim's residual matrices at one float64 point with the backend's array pool on (every
    array from min_bytes) or off."""
    from stiefelsym import native
    with monkeypatch.context() as mp:
        mp.setattr(native, "POOL", pool)
        mp.setattr(native, "POOL_MIN_BYTES", min_bytes)
        out, _peak = _residuals(claim, n, r, False, monkeypatch)
    return out


@pytest.mark.parametrize("cid, n, r, min_bytes", [
    ("neumann-lax", 6, 3, 0), ("neumann-flow", 7, 3, 0), ("coupled-dual-lax-along-corrected-flow", 4, 3, 0),
    ("neumann-lax", 40, 20, 0), ("neumann-lax", 120, 60, 1 << 16)])
def test_pooled_arrays_change_no_residual(monkeypatch, cid, n, r, min_bytes):
    """Results written into the float backend's pooled arrays (reused once nothing refers to them,
    across evaluations) are those numpy allocates, bit for bit: values, bounds and term scales, on
    a second evaluation too (the pool then hands out arrays holding the first one's numbers)."""
    claim = load_catalog().get(cid)
    plain = _pooled_residuals(claim, n, r, monkeypatch, False, min_bytes)
    for _ in range(2):
        pooled = _pooled_residuals(claim, n, r, monkeypatch, True, min_bytes)
        assert [x[0] for x in plain] == [x[0] for x in pooled]
        for (name, v0, e0, m0), (_name, v1, e1, m1) in zip(plain, pooled):
            assert np.array_equal(v0, v1) and np.array_equal(np.signbit(v0), np.signbit(v1)), name
            assert e0 == e1, name
            assert np.array_equal(m0, m1), name


def test_a_pooled_array_is_reused_only_when_nothing_refers_to_it(monkeypatch):
    """The pool hands an array out again only once every view of it (a transpose, a slice) is gone."""
    from stiefelsym import native
    monkeypatch.setattr(native, "POOL", True)
    monkeypatch.setattr(native, "_POOL", native._Pool())
    a = native._buf((300, 300))
    a[...] = 1.0
    t = a.T
    del a
    b = native._buf((300, 300))
    b[...] = 2.0
    assert np.all(t == 1.0)                        # t's array was not handed out again
    s = b[10:20]
    del b
    c = native._buf((300, 300))
    assert not np.shares_memory(c, s) and not np.shares_memory(c, t)
    del t, s, c
    d = native._buf((300, 300))
    assert np.shares_memory(d, native._POOL.bufs[((300, 300), np.dtype(np.float64))][0])
    # the layouts numpy gives its own results
    x = np.ones((300, 200))
    for y in (x, x.T):
        assert native._binop(np.add, y, y).strides == (y + y).strides
        assert native._matmul(y, y.T).strides == (y @ y.T).strides
        assert native._down32(y).strides == y.astype(np.float32).strides
