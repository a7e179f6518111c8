"""The float evaluation frees each value after its last use (:func:`stiefelsym.ir.evaluate.release_plan`,
:meth:`stiefelsym.backends.native.Float64Backend.forget`): what it frees is only what the backend remembers,
so the residuals, their bounds and their term scales are those of an evaluation that keeps every
value to the end, bit for bit, and the peak memory is lower."""
from __future__ import annotations

import random
import tracemalloc

import numpy as np
import pytest

from stiefelsym.claims import load_catalog
from stiefelsym.backends.fields import FloatField
from stiefelsym.ir import evaluate as ev
from stiefelsym.methods.fixed_size import call_claim, quiet_numpy
from stiefelsym.backends.native import backend
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


def _pooled_residuals(claim, n, r, monkeypatch, pool, min_bytes: int) -> list:
    """The claim's residual matrices at one float64 point with the backend's array pool ``pool``
    (every array from min_bytes), or with none (pool None)."""
    from stiefelsym.backends import native
    with monkeypatch.context() as mp:
        mp.setattr(native, "POOL", pool is not None)
        mp.setattr(native, "POOL_MIN_BYTES", min_bytes)
        if pool is not None:
            mp.setattr(native, "_POOL", pool)
        out, _peak = _residuals(claim, n, r, False, monkeypatch)
    return out


@pytest.mark.parametrize("cid, n, r, min_bytes", [
    ("neumann-lax", 6, 3, 0), ("neumann-flow", 7, 3, 0), ("coupled-dual-lax-along-corrected-flow", 4, 3, 0),
    ("neumann-lax", 40, 20, 0), ("neumann-lax", 120, 60, 1 << 16)])
def test_pooled_arrays_change_no_residual(monkeypatch, cid, n, r, min_bytes):
    """Results written into the float backend's pooled arrays (reused once nothing refers to them,
    across evaluations) are those numpy allocates, bit for bit: values, bounds and term scales, on
    a second evaluation too (the pool then hands out arrays holding the first one's numbers)."""
    from stiefelsym.backends import native
    claim = load_catalog().get(cid)
    plain = _pooled_residuals(claim, n, r, monkeypatch, None, min_bytes)
    pool = native._Pool()
    for k in range(2):
        pooled = _pooled_residuals(claim, n, r, monkeypatch, pool, min_bytes)
        assert pool.total > 0
        assert [x[0] for x in plain] == [x[0] for x in pooled]
        for (name, v0, e0, m0), (_name, v1, e1, m1) in zip(plain, pooled):
            assert np.array_equal(v0, v1) and np.array_equal(np.signbit(v0), np.signbit(v1)), name
            assert e0 == e1, name
            assert np.array_equal(m0, m1), name


def test_a_pooled_array_is_reused_only_when_nothing_refers_to_it(monkeypatch):
    """The pool hands an array out again only once every view of it (a transpose, a slice) is gone."""
    from stiefelsym.backends import native
    monkeypatch.setattr(native, "POOL", True)
    monkeypatch.setattr(native, "_POOL", native._Pool())
    assert native._buf((10, 10)).base is None       # below the pool's range: numpy's own
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
    assert np.shares_memory(d, native._POOL.bufs[((300, 300), np.float64)][0])
    # the layouts numpy gives its own results
    x = np.ones((300, 200))
    for y in (x, x.T):
        assert native._binop(np.add, y, y).strides == (y + y).strides
    z = np.ones((200, 300)).T
    for y, w in ((x, z), (z, x), (x, x[:, ::-1]), (x[::2], x[1::2])):
        assert native._binop(np.subtract, y, w).strides == (y - w).strides
        assert np.array_equal(native._binop(np.subtract, y, w), y - w)
    for y in (x, x.T):
        assert native._matmul(y, y.T).strides == (y @ y.T).strides
        assert native._down32(y).strides == y.astype(np.float32).strides
    d = np.arange(300.0)
    be = native.Float64Backend(None)
    for y in (x, x.T):
        k0, k1 = y.shape
        right = be._product(native.F64(y, 0.0, y), be._diagonal(d[:k1], d[:k1], 0.0, None)).v
        left = be._product(be._diagonal(d[:k0], d[:k0], 0.0, None), native.F64(y, 0.0, y)).v
        assert right.strides == (y * d[:k1]).strides and np.array_equal(right, y * d[:k1])
        assert left.strides == (d[:k0, None] * y).strides and np.array_equal(left, d[:k0, None] * y)
    i = native._eye(300)
    assert np.array_equal(i, np.eye(300)) and native._eye(300) is i
    with pytest.raises(ValueError):
        i[0, 1] = 1.0                              # shared: never written into


@pytest.mark.parametrize("n", [60, 200])
def test_eigenvalues_drawn_at_once_give_the_diagonal_of_their_parameters(n):
    """A from the eigenvalues' array (Float64Backend.diag_from_raw) is diag of the parameters a_i
    themselves, bit for bit: values, scales, bound and norm; the parameters are entered in order."""
    field = FloatField(None)
    scene = Scene(n, 3, field, chart="cayley", rng=random.Random(f"eig|{n}"))
    with quiet_numpy():
        got = scene.A._n
        xs = scene._cache["a"]
        want = backend(field).diag(xs)
    assert [scene.params[f"a_{i + 1}"] for i in range(n)] == xs
    assert all(type(x.v) is float and x.e == 0 and x.m == abs(x.v) for x in xs)
    for g, w in ((got.diag[0], want.diag[0]), (got.diag[1], want.diag[1]), (got.v, want.v), (got.m, want.m)):
        assert g.dtype == w.dtype and np.array_equal(g, w) and np.array_equal(np.signbit(g), np.signbit(w))
    assert (got.e, got.nv) == (want.e, want.nv)


def test_float32_rounding_down_is_one_step_towards_zero():
    """_down32 (one unit less in the bits of every positive float32, by subtracting the mask of the
    positive ones) is the rounding to nearest moved one step towards 0 where positive: the numbers
    of the masked subtraction, and of np.nextafter, entry by entry (0, -0, subnormals, float32's
    overflow to inf, inf, nan of either sign)."""
    from stiefelsym.backends.native import _down32
    rng = np.random.default_rng(3)
    x = np.abs(rng.standard_normal((70, 90))) * 10.0 ** rng.integers(-50, 50, size=(70, 90))
    x.flat[:9] = [0.0, -0.0, 1e-45, 1e-40, 3.5e38, 1e300, np.inf, np.nan, -np.nan]
    for a in (x, x.T, x[::2]):
        want = a.astype(np.float32)
        bits = want.view(np.int32)
        np.subtract(bits, 1, out=bits, where=bits > 0)
        got = _down32(a)
        assert got.dtype == np.float32 and got.strides == want.strides
        assert np.array_equal(got.view(np.int32), want.view(np.int32))
        pos = a.astype(np.float32) > 0
        assert np.array_equal(got[pos], np.nextafter(a.astype(np.float32), np.float32(0))[pos])


def test_constants_take_the_same_path_and_storage():
    """from_consts reads the largest |entry| without the array of |a|: the same storage, bound,
    scales and signed selection as before, and the generic path from 2^53 on."""
    from stiefelsym.backends import native
    F = FloatField(None)
    be = backend(F)
    D = np.zeros((7, 4), dtype=np.int64)
    D[range(4), range(4)] = 1
    D[0, 0] = -1
    cases = [D, D * 3, -D, np.zeros((3, 2), dtype=np.int64), np.array([[2**53, 1]]), np.array([[-2**53, 0]]),
             np.array([[2**53 - 1, -5]]), np.array([[1, 1], [0, 1]])]
    for a in cases:
        top = np.max(np.abs(a), initial=0)
        got = be.from_consts(a)
        if top >= 2**53:
            assert type(got) is not native.F64 or got.e != 0.0 or not np.array_equal(got.v, a)
            continue
        assert np.array_equal(got.v, a.astype(float)) and np.array_equal(got.m, np.abs(a).astype(float))
        assert got.e == 0.0
        sel = got.sel
        if a.size and top <= 1 and np.all(np.count_nonzero(a, axis=0) <= 1):
            assert sel is not None and np.array_equal(sel[1], a[sel[0], np.arange(a.shape[1])])
        else:
            assert sel is None


def test_float64_scales_from_float32_in_a_pooled_array():
    """F64.m from float32 scales (one product, into a pooled array of numpy's layout) is numpy's own
    mixed-type product, bit for bit."""
    from stiefelsym.backends.native import _f32
    rng = np.random.default_rng(2)
    m32 = np.abs(rng.standard_normal((300, 250))).astype(np.float32)
    m32[0, 0] = np.float32(1e-42)
    for a in (m32, m32.T):
        got = _f32(np.zeros(a.shape), 0.0, a, 0.9999997, 10.0).m
        want = np.multiply(a, 0.9999997 * (1.0 - 2.0**-40), dtype=np.float64)
        assert np.array_equal(got, want) and got.strides == want.strides


def test_pooled_arrays_are_not_shared_with_a_forked_process(monkeypatch):
    """A pooled array is a private mapping: a process forked while it is pooled (the worker pool)
    writes into its own copy, never into the parent's."""
    import os
    from stiefelsym.backends import native
    if not hasattr(os, "fork"):
        pytest.skip("no fork")
    monkeypatch.setattr(native, "POOL", True)
    monkeypatch.setattr(native, "_POOL", native._Pool())
    a = native._buf((300, 300))
    a[...] = 1.0
    pid = os.fork()
    if pid == 0:                                   # the child writes into its copy and leaves
        a[...] = 2.0
        os._exit(0)
    os.waitpid(pid, 0)
    assert np.all(a == 1.0)
