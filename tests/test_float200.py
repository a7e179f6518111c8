"""The float64 backend's cheaper paths for large matrices (deferred inverses, solves, reassociated
products), each replayed in ℚ: every entry lies within its bound of the exact value."""
from __future__ import annotations

import random
from fractions import Fraction

import flint
import numpy as np
import pytest

from stiefelsym import native
from stiefelsym.fields import FloatField, RationalField
from stiefelsym.matrix import Mat


def entries(M):
    return [[M._view()[i, j] for j in range(M._shape()[1])] for i in range(M._shape()[0])]


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


@pytest.mark.parametrize("m,r,threshold", [(5, 2, 1), (6, 3, 1), (40, 17, None)])
def test_deferred_inverses_and_solves_keep_the_bound(monkeypatch, m, r, threshold):
    if threshold is not None:
        monkeypatch.setattr(native, "DEFERRED_INVERSE_MIN", threshold)
    for seed in range(2):
        F = FloatField()
        out = cayley_ops(F, m, r, random.Random(seed))

        class Replay(RationalField):
            def param(self, name, rr):
                x = F.param(name, rr)
                return flint.fmpq(*Fraction(x.v).as_integer_ratio())
        exact = cayley_ops(Replay(), m, r, random.Random(seed))
        for M, Mq in zip(out, exact):
            assert M._n is not None
            for row, rowq in zip(entries(M), entries(Mq)):
                for x, q in zip(row, rowq):
                    assert abs(Fraction(x.v) - Fraction(int(q.p), int(q.q))) <= Fraction(x.e)
                    assert x.e < 1e-9


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
    from stiefelsym.fields import DegenerateError
    with pytest.raises(DegenerateError):
        Mat.zeros(5, 5, F).inv()
