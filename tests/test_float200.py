"""The float64 backend's cheaper paths for large matrices (deferred inverses, solves, reassociated
products), each replayed in ℚ: every entry lies within its bound of the exact value."""
from __future__ import annotations

import random
from fractions import Fraction

import numpy as np
import pytest

from stiefelsym.backends import native
from stiefelsym.backends.fields import FloatField
from stiefelsym.backends.matrix import Mat

from float_replay import assert_within_bounds, entries, replay_field


def skew(F, m, rng, scale=1):
    rows = [[F.const(0)] * m for _ in range(m)]
    for i in range(m):
        for j in range(i + 1, m):
            x = F.param("s", rng)
            if scale != 1:
                x = x * F.const(scale)
            rows[i][j], rows[j][i] = x, -x
    return Mat._rows(rows, F)


def general(F, m, k, rng):
    return Mat._rows([[F.param("g", rng) for _ in range(k)] for _ in range(m)], F)


def cayley_ops(F, m, r, rng):
    """The Cayley chart's X = (I − S)(I + S)⁻¹ [D; 0] and the other products with a deferred
    inverse: a solve with fewer columns, the inverse itself, a product met with the inverse on the
    right and then read, and an inverse of a matrix that carries an error."""
    S = skew(F, m, rng)
    G = general(F, m, r, rng)
    In = Mat.identity(m, F)
    D = np.zeros((m, r), dtype=np.int64)
    D[range(r), range(r)] = 1
    D[0, 0] = -1
    J = Mat._consts(D, F)
    Zi = (In + S).inv()
    X = (In - S) @ Zi @ J
    Y = Zi @ G                                  # a solve (r < m columns)
    S2 = skew(F, m, rng, scale=Fraction(1, 3))
    W = (In * F.const(2) + S2 - S2.T * F.const(0))  # 2I + S2: symmetric part 2I, carries a rounding bound
    V = W.inv() @ (G @ G.T)                     # as many columns as rows: the inverse is computed
    Q = (In - S) @ Zi                           # read in full
    return [X, Y, V, Q, Zi, (In + S2) @ (In + S2).inv() @ J]


@pytest.mark.parametrize("m,r,threshold", [(5, 2, 1), (6, 3, 1), pytest.param(40, 17, None, marks=pytest.mark.slow)])
def test_deferred_inverses_and_solves_keep_the_bound(monkeypatch, m, r, threshold):
    if threshold is not None:
        monkeypatch.setattr(native, "DEFERRED_INVERSE_MIN", threshold)
    for seed in range(2):
        F = FloatField()
        out = cayley_ops(F, m, r, random.Random(seed))
        assert_within_bounds(out, cayley_ops(replay_field(F), m, r, random.Random(seed)))
        assert all(M._n is not None for M in out)
        assert all(x.e < 1e-9 for M in out for row in entries(M) for x in row)


def test_the_cayley_inverse_is_deferred_and_never_computed(monkeypatch):
    """X = (I − S)(I + S)⁻¹ J is computed as (I − S)((I + S)⁻¹ J) by one solve: neither the inverse
    nor the product (I − S)(I + S)⁻¹ is formed."""
    monkeypatch.setattr(native, "DEFERRED_INVERSE_MIN", 1)
    F = FloatField()
    be = native.backend(F)
    rng = random.Random(0)
    S = skew(F, 6, rng)
    In = Mat.identity(6, F)
    Zi = (In + S).inv()
    Q = (In - S) @ Zi
    X = Q @ Mat._consts(np.eye(6, 2, dtype=np.int64), F)
    assert Zi._n.lazy is not None and Q._n.lazy is not None and X._n.lazy is None
    assert be.shape(Q._n) == (6, 6)


def test_an_inverse_without_the_structure_is_computed_at_once(monkeypatch):
    """A matrix whose symmetric part is not a positive diagonal takes the residual-checked inverse
    (and its refusals: a singular matrix raises at the inverse, not later)."""
    monkeypatch.setattr(native, "DEFERRED_INVERSE_MIN", 1)
    F = FloatField()
    rng = random.Random(1)
    A = general(F, 5, 5, rng)
    assert A.inv()._n.lazy is None
    S = skew(F, 5, rng)
    assert (Mat.identity(5, F) * F.const(-1) + S).inv()._n.lazy is None     # symmetric part −I
    from stiefelsym.backends.fields import DegenerateError
    with pytest.raises(DegenerateError):
        Mat.zeros(5, 5, F).inv()


def _reference_entries(s, name, u):
    """The float method's deciding entries as they were found before the fast path (every array
    in full)."""
    from stiefelsym.backends.fields import ErrNum
    from stiefelsym.methods.fixed_size import FLOAT_RESOLUTION
    v, m = s.v.ravel(), s.m.ravel()
    e = np.full(v.shape, float(s.e))
    with np.errstate(all="ignore"):
        finite = np.isfinite(v) & np.isfinite(e) & np.isfinite(m)
        clear = np.abs(v) > e
        resolves = finite & (e <= FLOAT_RESOLUTION * m)
        ratio = np.where(m != 0, e / np.where(m != 0, m, 1.0), np.where(e == 0, 0.0, np.inf))
    picks = {int(np.argmax(np.abs(v))), int(np.argmax(e)), int(np.argmax(ratio))}
    for mask in (~finite, clear, clear & resolves, ~resolves):
        hit = np.flatnonzero(mask)
        if hit.size:
            picks.add(int(hit[0]))
    cols = s.v.shape[1]
    return [(f"{name}[{i // cols + 1},{i % cols + 1}]", ErrNum(float(v[i]), float(e[i]), float(m[i]), u))
            for i in sorted(picks)]


def test_the_deciding_entries_are_those_of_the_full_arrays():
    """The float method's entry picks (largest |v|, e and e/m, first non-finite, clear, clear and
    resolving, not resolving) are the same with the fast path, on matrices with zero scales, zero
    bounds, entries above the bound, unresolved entries, infinities and nan."""
    from stiefelsym.methods.fixed_size import _float_entries
    F = FloatField()
    rng = np.random.default_rng(3)
    for trial in range(60):
        v = rng.standard_normal((5, 4)) * 10.0 ** rng.integers(-20, 3)
        m = np.abs(rng.standard_normal((5, 4))) * 10.0 ** rng.integers(-3, 12)
        e = [0.0, 1e-12, 1e-3, 1.0, float("inf"), float("nan")][trial % 6]
        if trial % 5 == 1:
            m[rng.integers(5), rng.integers(4)] = 0.0
        if trial % 7 == 2:
            v[rng.integers(5), rng.integers(4)] = [np.inf, -np.inf, np.nan][trial % 3]
        if trial % 11 == 3:
            m[rng.integers(5), rng.integers(4)] = [np.inf, np.nan][trial % 2]
        if trial % 13 == 4:
            m[:, :] = m[0, 0]
        s = native.F64(v, e, m)
        M = Mat._wrap_native(s, F)
        got = _float_entries(M, "R", F.u)
        want = _reference_entries(s, "R", F.u)
        assert [p for p, _ in got] == [p for p, _ in want]
        for (_, x), (_, y) in zip(got, want):
            assert repr((x.v, x.e, x.m)) == repr((y.v, y.e, y.m))


def commutator_ops(F, rng):
    """A commutator of two matrices whose term scales are symmetric (B + Bᵀ, C Cᵀ + c·I): its
    second product takes the first one's scales transposed; sums, differences and multiples by a
    scalar met again are the stored ones."""
    B, C = general(F, 5, 5, rng), general(F, 5, 3, rng)
    c = F.param("c", rng)
    M = B + B.T
    L = C @ C.T + Mat.identity(5, F) * c
    out = [M @ L - L @ M, L @ M, M @ L]
    out += [B + B.T, (C @ C.T + Mat.identity(5, F) * c) - B, B * c, B - C @ C.T]
    return out


def test_symmetric_scales_and_repeated_sums_keep_the_bound():
    for seed in range(4):
        F = FloatField()
        be = native.backend(F)
        out = commutator_ops(F, random.Random(seed))
        assert_within_bounds(out, commutator_ops(replay_field(F), random.Random(seed)), scales=True)
        LM, ML = out[1]._n, out[2]._n
        # the scales of L M are those of M L, transposed (not a new product)
        assert np.shares_memory(LM.m, ML.m) and np.array_equal(LM.m, ML.m.T)
        assert be is native.backend(F)


def test_a_sum_or_multiple_met_again_is_the_stored_one():
    F = FloatField()
    rng = random.Random(0)
    B, C = general(F, 4, 4, rng), general(F, 4, 4, rng)
    c = F.param("c", rng)
    assert (B + C)._n is (B + C)._n and (B - C)._n is (B - C)._n
    assert (B * c)._n is (B * ErrNumLike(c))._n
    assert (B * c)._n is not (B * (c + F.const(1)))._n


def ErrNumLike(c):
    from stiefelsym.backends.fields import ErrNum
    return ErrNum(c.v, c.e, c.m, c.u)


def diagonal_ops(F, rng):
    """A diagonal matrix (the scene's A) and its scalar multiples, kept without their full arrays:
    sums and differences with full matrices on either side and with each other, products on either
    side, a transpose; the results are read in full."""
    be = native.backend(F)
    xs = [F.param("a", rng) for _ in range(5)]
    if be is not None:
        D = Mat._wrap_native(be.diag(xs), F)
    else:
        D = Mat._rows([[xs[i] if i == j else F.const(0) for j in range(5)] for i in range(5)], F)
    B = general(F, 5, 5, rng)
    c, d = F.param("c", rng), F.param("d", rng)
    cD, dD = D * c, D * (c * d)
    return [B - cD, cD - B, B + dD, dD + B, cD - dD, cD + dD, cD @ B, B @ dD, cD.T @ B,
            (B - cD) - dD * F.const(3), cD]


def test_diagonals_without_full_arrays_keep_the_bound():
    for seed in range(4):
        F = FloatField()
        out = diagonal_ops(F, random.Random(seed))
        assert_within_bounds(out, diagonal_ops(replay_field(F), random.Random(seed)), scales=True)


def test_a_diagonal_times_a_scalar_stays_diagonal_and_equals_the_full_multiple():
    """Values and scales are those of the full arrays; a scalar that is not finite takes the full
    arrays (its nan off the diagonal voids the error model as before)."""
    F = FloatField()
    be = native.backend(F)
    rng = random.Random(2)
    xs = [F.param("a", rng) for _ in range(4)]
    d = be.diag(xs)
    c = F.param("c", rng)
    s = be.smul(d, c)
    assert s.lazy is not None and s.diag is not None
    full = be.smul(native.F64(d.v.copy(), d.e, d.m.copy()), c)
    assert np.array_equal(s.v, full.v) and np.array_equal(s.m, full.m)
    assert abs(s.e - full.e) <= 1e-12 * full.e
    from stiefelsym.backends.fields import ErrNum
    bad = be.smul(be.diag(xs), ErrNum(float("inf"), 0.0, float("inf"), F.u))
    assert not np.all(np.isfinite(bad.v))
