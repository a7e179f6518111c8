"""The float64 backend's term scales in float32 and its Cayley path, against exact arithmetic: the
scales never exceed the exact term scales (so the resolution test is never easier than with them)
and stay within 10⁻⁵ of them; the Cayley X = 2Y − J lies within its bound of the exact
(I − S)(I + S)⁻¹ J; and both checks reject a corrupted backend (negative controls)."""
from __future__ import annotations

import random
from fractions import Fraction

import numpy as np
import pytest

from stiefelsym.backends import native
from stiefelsym.backends.fields import FloatField
from stiefelsym.backends.matrix import Mat

from float_replay import replay_field


def _q(x: float) -> Fraction:
    return Fraction(x)


def _mm(x, y):
    k = len(y)
    return [[sum((x[i][l] * y[l][j] for l in range(k)), Fraction(0)) for j in range(len(y[0]))]
            for i in range(len(x))]


def _ew(x, y, f):
    return [[f(a, b) for a, b in zip(r, t)] for r, t in zip(x, y)]


class _Pair:
    """A float64 backend matrix with its exact values and exact term scales (Fractions), built side
    by side."""

    def __init__(self, be, s, xs, ms):
        self.be, self.s, self.xs, self.ms = be, s, xs, ms

    def __add__(self, o):
        return _Pair(self.be, self.be.add(self.s, o.s), _ew(self.xs, o.xs, lambda a, b: a + b),
                     _ew(self.ms, o.ms, lambda a, b: a + b))

    def __sub__(self, o):
        return _Pair(self.be, self.be.sub(self.s, o.s), _ew(self.xs, o.xs, lambda a, b: a - b),
                     _ew(self.ms, o.ms, lambda a, b: a + b))

    def __matmul__(self, o):
        return _Pair(self.be, self.be.matmul(self.s, o.s), _mm(self.xs, o.xs), _mm(self.ms, o.ms))

    def scaled(self, c):
        cv, cm = _q(float(c.v)), _q(float(c.m))
        return _Pair(self.be, self.be.smul(self.s, c), [[cv * a for a in r] for r in self.xs],
                     [[cm * a for a in r] for r in self.ms])

    @property
    def T(self):
        return _Pair(self.be, self.be.T(self.s), [list(r) for r in zip(*self.xs)], [list(r) for r in zip(*self.ms)])

    def neg(self):
        return _Pair(self.be, self.be.neg(self.s), [[-a for a in r] for r in self.xs], self.ms)


def _chain(be, F, rng, n=6, r=3):
    """Sums, differences, products (general, with a diagonal, with a selection of columns, a
    product met again transposed), scalar multiples, transposes and negations, each result kept."""
    def general(m, k, scale=1.0):
        v = np.array([[rng.uniform(-1, 1) * scale for _ in range(k)] for _ in range(m)])
        return _Pair(be, be.from_array(v), [[_q(x) for x in row] for row in v], [[abs(_q(x)) for x in row] for row in v])
    A, B, C = general(n, n), general(n, r, 1e3), general(r, n, 1e-3)
    xs = [F.param("d", rng) for _ in range(n)]
    D = _Pair(be, be.diag(xs), [[_q(float(x.v)) if i == j else Fraction(0) for j, x in enumerate(xs)]
                                for i in range(n)],
              [[abs(_q(float(x.m))) if i == j else Fraction(0) for j, x in enumerate(xs)] for i in range(n)])
    J = np.zeros((n, r), dtype=np.int64)
    J[range(r), range(r)] = 1
    Js = _Pair(be, be.from_consts(J), [[Fraction(int(x)) for x in row] for row in J],
               [[Fraction(abs(int(x))) for x in row] for row in J])
    c = F.param("c", rng)
    out = []
    AB = A @ B
    out += [AB, AB @ C, (AB @ C) + A, A - AB @ C, (A @ B @ C).scaled(c), D @ A, A @ D, A @ Js]
    M = A + A.T
    L = B @ B.T + D
    out += [M @ L - L @ M, (M @ L).T, (AB @ C).neg() + D.scaled(c), (L - D) @ Js, (M.scaled(c) + L) @ AB]
    # the chains of a flow, reassociated: (X Pᵀ) X, (P Xᵀ) P, (X Pᵀ) P, (X Xᵀ) X
    X, P = general(n, 2), general(n, 2, 10.0)
    XPt = X @ P.T
    out += [XPt, XPt @ X, XPt.T @ P, XPt @ P, (X @ X.T) @ X, (XPt @ X) - (XPt.T @ P)]
    return out


def _worst_excess(out):
    """The largest m / exact − 1 (positive: a scale above the exact one) and the largest
    1 − m / exact (the loss) over every entry of every result."""
    up, loss = -1.0, 0.0
    for P in out:
        m = P.s.m
        for i, row in enumerate(P.ms):
            for j, x in enumerate(row):
                if x == 0:
                    assert m[i, j] == 0.0
                    continue
                ratio = float(_q(float(m[i, j])) / x)
                up, loss = max(up, ratio - 1.0), max(loss, 1.0 - ratio)
    return up, loss


def _outside(out):
    """Whether some computed entry lies outside its bound of the exact value."""
    for P in out:
        v, e = P.s.v, Fraction(P.s.e)
        for i, row in enumerate(P.xs):
            for j, x in enumerate(row):
                if abs(_q(float(v[i, j])) - x) > e:
                    return True
    return False


@pytest.mark.parametrize("seed", range(3))
def test_float32_scales_never_exceed_the_exact_scales(seed, monkeypatch):
    reassociated = []
    real = native.Float64Backend._reassociated

    def spy(self, a, b):
        out = real(self, a, b)
        reassociated.append(out is not None)
        return out
    monkeypatch.setattr(native.Float64Backend, "_reassociated", spy)
    F = FloatField()
    out = _chain(native.backend(F), F, random.Random(seed))
    assert any(P.s._m is None or P.s.msrc is not None for P in out)       # the float32 form is used
    assert sum(reassociated) >= 3                                          # the chains are thin products
    up, loss = _worst_excess(out)
    assert up <= 0.0 and loss < 1e-5
    assert not _outside(out)


def test_a_wrongly_reassociated_chain_is_caught(monkeypatch):
    """Negative control: (P Xᵀ) P reassociated from the factors of X Pᵀ without transposing them,
    X (Pᵀ P), lies outside its bound of the exact value."""
    real = native.Float64Backend._reassociated

    def wrong(self, a, b):
        if a.fac is None:
            c, d = a.t.fac
            return self.matmul(c, self.matmul(d, b))
        return real(self, a, b)
    monkeypatch.setattr(native.Float64Backend, "_reassociated", wrong)
    F = FloatField()
    assert _outside(_chain(native.backend(F), F, random.Random(0)))


def test_a_scale_factor_that_overstates_is_caught(monkeypatch):
    """Negative control: with the factor of a float32 operation above 1 (rounding not covered) the
    same check finds scales above the exact ones."""
    monkeypatch.setattr(native, "_R32", 1.0 + 2.0**-12)
    F = FloatField()
    up, _loss = _worst_excess(_chain(native.backend(F), F, random.Random(0)))
    assert up > 0.0


def test_scales_too_large_for_float32_take_float64():
    F = FloatField()
    be = native.backend(F)
    a = be.from_array(np.full((3, 3), 2.0**20))
    p = be.matmul(be.matmul(a, a), a)          # scales 9·2^60, in float32: above 2^56 for a product
    assert p._m is None
    q = be.matmul(p, a)
    assert q.m32 is None and q._m is not None
    exact = 27.0 * 2.0**80
    assert np.all(q.m <= exact) and np.all(q.m >= exact * (1 - 1e-5))


def _cayley(F, m, r, rng):
    S = [[F.const(0)] * m for _ in range(m)]
    for i in range(m):
        for j in range(i + 1, m):
            x = F.param("s", rng)
            S[i][j], S[j][i] = x, -x
    S = Mat._rows(S, F)
    In = Mat.identity(m, F)
    D = np.zeros((m, r), dtype=np.int64)
    D[range(r), range(r)] = 1
    D[0, 0] = -1
    return (In - S) @ (In + S).inv() @ Mat._consts(D, F)


def _replay(m, r, seed):
    """The float Cayley X at (m, r) and the exact one at the same point (flint, over ℚ)."""
    F = FloatField()
    X = _cayley(F, m, r, random.Random(seed))
    Xq = _cayley(replay_field(F), m, r, random.Random(seed))
    return X, Xq


def _max_miss(X, Xq):
    """The largest |computed − exact| − bound over the entries (<= 0: every entry within its bound)."""
    v, e = X._n.v, Fraction(X._n.e)
    worst = None
    for i in range(v.shape[0]):
        for j in range(v.shape[1]):
            q = Xq._view()[i, j]
            miss = abs(Fraction(float(v[i, j])) - Fraction(int(q.p), int(q.q))) - e
            worst = miss if worst is None else max(worst, miss)
    return worst


@pytest.mark.parametrize("m,r", [(40, 17), (36, 36)])
def test_the_cayley_x_from_the_solve_keeps_its_bound(monkeypatch, m, r):
    calls = []
    real = native.Float64Backend._cayley

    def spy(self, *args):
        out = real(self, *args)
        calls.append(out is not None)
        return out
    monkeypatch.setattr(native.Float64Backend, "_cayley", spy)
    X, Xq = _replay(m, r, 0)
    assert calls == [True]
    assert _max_miss(X, Xq) <= 0 and X._n.e < 1e-10
    # the term scales are those of the product (I − S)((I + S)⁻¹ J), as without the path
    monkeypatch.setattr(native, "CAYLEY_BY_SOLVE", False)
    X2, _ = _replay(m, r, 0)
    assert np.array_equal(X._n.m, X2._n.m)
    assert X._n.e <= X2._n.e
    assert np.max(np.abs(X._n.v - X2._n.v)) <= X._n.e + X2._n.e


def test_a_corrupted_cayley_x_is_caught(monkeypatch):
    """Negative control: 2Y + J instead of 2Y − J lies outside the bound of the exact value."""
    real = native.Float64Backend._cayley

    def wrong(self, c, src, y, j):
        out = real(self, c, src, y, j)
        rows, signs = j.sel
        v = out.v.copy()
        v[rows, np.arange(v.shape[1])] += 2.0 * signs
        return native.F64(v, out.e, out.m, None)
    monkeypatch.setattr(native.Float64Backend, "_cayley", wrong)
    X, Xq = _replay(40, 5, 1)
    assert _max_miss(X, Xq) > 0


def test_the_cayley_path_needs_c_plus_a_to_be_twice_the_identity(monkeypatch):
    """(I − S + E)(I + S)⁻¹ J with E ≠ 0 is the product, not 2Y − J."""
    F = FloatField()
    be = native.backend(F)
    rng = random.Random(2)
    m = 40
    S = np.zeros((m, m))
    for i in range(m):
        for j in range(i + 1, m):
            S[i, j] = rng.randint(-2**20, 2**20) / 2**20
            S[j, i] = -S[i, j]
    plus, minus = be.from_array(np.eye(m) + S), np.eye(m) - S
    minus[3, 5] += 0.5
    y = be.matmul(be.inv(plus), be.from_consts(np.eye(m, 4, dtype=np.int64)))
    assert be._cayley(be.from_array(minus), plus, y, be.from_consts(np.eye(m, 4, dtype=np.int64))) is None


def test_exact_zeros_in_sums_and_multiples():
    F = FloatField()
    be = native.backend(F)
    a = be.from_array(np.arange(6.0).reshape(2, 3))
    z = be.zeros(2, 3)
    assert be.add(a, z) is a and be.sub(a, z) is a and be.add(z, a) is a
    nz = be.sub(z, a)
    assert np.array_equal(nz.v, -a.v) and nz.e == a.e
    c = F.param("c", random.Random(0))
    zc = be.smul(z, c)
    assert not np.any(zc.v) and zc.e == 0.0 and not np.any(zc.m)


def test_the_block_solve_is_used_and_its_errors_are_bounded_by_the_residual(monkeypatch):
    """The solve with B = [D; 0] goes by blocks; its bound comes from the residual, so even a Y
    perturbed on purpose stays within its (larger) bound of the exact value."""
    used = []
    real = native._solve_top

    def spy(v, sel):
        out = real(v, sel)
        used.append(out is not None)
        return out
    monkeypatch.setattr(native, "_solve_top", spy)
    X, Xq = _replay(40, 17, 3)
    assert used == [True] and _max_miss(X, Xq) <= 0
    e_good = X._n.e

    def perturbed(v, sel):
        out = real(v, sel)
        out[5, 2] += 1e-7
        return out
    monkeypatch.setattr(native, "_solve_top", perturbed)
    X, Xq = _replay(40, 17, 3)
    assert _max_miss(X, Xq) <= 0 and X._n.e > 1e3 * e_good


def test_a_sum_met_again_transposed_is_the_transpose_of_the_stored_one():
    """aᵀ + bᵀ, bᵀ + aᵀ and aᵀ − bᵀ after a + b and a − b: the transposes of the stored results,
    with the values, bound, norm and scales the same sum computed afresh has."""
    def operands(seed):
        rng = np.random.default_rng(seed)
        be = native.backend(FloatField())
        a, b = (be.matmul(be.from_array(rng.standard_normal((6, 3))), be.from_array(rng.standard_normal((3, 6))))
                for _ in range(2))
        return be, a, b

    for name, swap in (("add", False), ("add", True), ("sub", False)):
        be, a, b = operands(7)
        stored = getattr(be, name)(a, b)
        again = (be.T(b), be.T(a)) if swap else (be.T(a), be.T(b))
        hit = getattr(be, name)(*again)
        assert hit is be.T(stored)
        be2, a2, b2 = operands(7)
        fresh = getattr(be2, name)(*((be2.T(b2), be2.T(a2)) if swap else (be2.T(a2), be2.T(b2))))
        assert np.array_equal(hit.v, fresh.v) and hit.e == fresh.e and hit.nv == fresh.nv
        assert np.array_equal(hit.m, fresh.m)


def test_the_block_inverse_inverts_matrices_with_a_positive_definite_symmetric_part():
    """I + S (S skew) at sizes that split into leaves of every shape, and a Schur complement of
    such a matrix: the block inverse is an inverse to rounding; a singular leading block raises."""
    rng = np.random.default_rng(5)
    for m in (1, 7, native.BLOCK_INVERSE_LEAF, native.BLOCK_INVERSE_LEAF + 1, 77, 100, 150):
        S = np.triu(rng.standard_normal((m, m)), 1)
        v = np.eye(m) + S - S.T
        Z = native._block_inverse(v)
        assert np.linalg.norm(np.eye(m) - v @ Z) <= 1e-12 * m
    a = np.ones((80, 80))
    with pytest.raises(np.linalg.LinAlgError):
        native._block_inverse(a)


def test_down32_is_nextafter_towards_zero_bit_for_bit():
    """The float32 term scales are rounded down by one unit in the bits (faster than np.nextafter): the
    same float32 as nextafter(x in float32, 0) for every nonnegative x, normal, subnormal, beyond
    float32's range and 0; never above x.  The control: the cast alone (rounded to nearest) is above x
    somewhere."""
    import numpy as np
    from stiefelsym.backends.native import _down32
    rng = np.random.default_rng(3)
    x = np.concatenate([np.abs(rng.standard_normal(20000)) * 10.0 ** rng.integers(-50, 40, 20000),
                        [0.0, np.inf, 1e-45, 1e-46, 3e38, 3.5e38, 1e-40, 2.0**-149, 2.0**-126]])
    with np.errstate(over="ignore"):
        ref = np.nextafter(x.astype(np.float32), np.float32(0.0))
        got = _down32(x)
        near = x.astype(np.float32)
    assert np.array_equal(ref.view(np.int32), got.view(np.int32))
    assert np.all(got.astype(float) <= x)
    assert np.any(near.astype(float) > x)
