"""Matrices of the exact backend whose entries carry their own denominators (stiefelsym.backends.ratmat)
against the same operations on symengine entries: sums over the lcm of two denominators, products,
scalar multiples, traces, pairings, blocks; the exact zero test; corrupted results rejected."""
from __future__ import annotations

import numpy as np
import pytest
import symengine as se

from stiefelsym.backends import native
from stiefelsym.backends import ratmat as rm
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.polyfield import PolyMat
from stiefelsym.backends.ratmat import RatMat

a, b, c, x, y = se.symbols("a b c x y")


def setup():
    F = SymbolicField()
    be = native.backend(F)
    return F, be


def ratmat(be, rows):
    """A RatMat of symengine entries, each over its own reduced denominator."""
    R = be.ring
    A = np.array(rows, dtype=object)
    n, d = np.empty(A.shape, dtype=object), np.empty(A.shape, dtype=object)
    for idx, e in np.ndenumerate(A):
        n[idx], d[idx] = R.from_se(se.sympify(e))
    out = RatMat(n, d, R.ctx)
    return rm.fix(be, out)


def objs(rows):
    return np.array([[se.sympify(e) for e in row] for row in rows], dtype=object)


def equal(F, be, M, E) -> bool:
    """Entry by entry, exactly (the field's own zero test, through symengine expressions)."""
    got = be.to_obj(M) if type(M) is not RatMat else rm.to_obj(be, M)
    E = np.asarray(E, dtype=object)
    return got.shape == E.shape and all(F.is_zero(F.normalize(g - e)) for g, e in zip(got.flat, E.flat))


A_ROWS = [[x / (a + b), 1 / (a + c)], [y / (b + c) + 1, 0]]
B_ROWS = [[1 / (a + b), x], [a / (a + c), y / (a + b) ** 2]]


def test_operations_agree_with_symengine_entries():
    F, be = setup()
    A, B = ratmat(be, A_ROWS), ratmat(be, B_ROWS)
    EA, EB = objs(A_ROWS), objs(B_ROWS)
    assert equal(F, be, rm.add(be, A, B), EA + EB)
    assert equal(F, be, rm.sub(be, A, B), EA - EB)
    assert equal(F, be, rm.matmul(be, A, B), np.dot(EA, EB))
    assert equal(F, be, rm.matmul(be, B, A), np.dot(EB, EA))
    assert equal(F, be, rm.neg(be, A), -EA)
    assert equal(F, be, rm.T(be, A), EA.T)
    n, d = be.ring.from_se(se.sympify(x / (b + c)))
    assert equal(F, be, rm.smul(be, A, n, d), EA * (x / (b + c)))
    assert F.is_zero(F.normalize(rm.trace(be, A) - (EA[0, 0] + EA[1, 1])))
    assert F.is_zero(F.normalize(rm.inner(be, A, B) - sum(p * q for p, q in zip(EA.flat, EB.flat))))
    blk = rm.block(be, [[A, B], [B, A]])
    assert equal(F, be, blk, np.block([[EA, EB], [EB, EA]]))


def test_mixed_with_the_common_denominator_representation():
    F, be = setup()
    A = ratmat(be, A_ROWS)
    P = be.from_obj(objs(B_ROWS))
    assert type(P) is PolyMat
    EA, EB = objs(A_ROWS), objs(B_ROWS)
    assert equal(F, be, rm.add(be, A, P), EA + EB)
    assert equal(F, be, rm.add(be, P, A), EB + EA)
    assert equal(F, be, rm.matmul(be, P, A), np.dot(EB, EA))
    assert equal(F, be, rm.common(be, A), EA)


def test_exact_zero_and_back_to_one_denominator():
    F, be = setup()
    A = ratmat(be, A_ROWS)
    Z = rm.sub(be, A, A)
    assert rm.is_zero(be, Z) if type(Z) is RatMat else be.is_zero(Z)
    # entries over one denominator go back to the common-denominator representation
    S = ratmat(be, [[x / (a + b), 1 / (a + b)], [0, y / (a + b)]])
    out = rm.add(be, S, S)
    assert type(out) is PolyMat
    assert equal(F, be, out, 2 * objs([[x / (a + b), 1 / (a + b)], [0, y / (a + b)]]))
    # x/(a+b) + y/(a+c) - (x(a+c) + y(a+b))/((a+b)(a+c)) = 0 over the lcm
    U = ratmat(be, [[x / (a + b)]])
    V = ratmat(be, [[y / (a + c)]])
    W = ratmat(be, [[(x * (a + c) + y * (a + b)) / ((a + b) * (a + c))]])
    out = rm.sub(be, rm.add(be, U, V), W)
    assert be.is_zero(out) if type(out) is PolyMat else rm.is_zero(be, out)


@pytest.mark.parametrize("corrupt", ["numerator", "denominator"])
def test_a_corrupted_entry_is_rejected(corrupt):
    """Negative control: one entry's numerator doubled, or its denominator's exponent raised, gives
    a nonzero difference with the true result, and is_zero says so."""
    F, be = setup()
    A, B = ratmat(be, A_ROWS), ratmat(be, B_ROWS)
    good = rm.matmul(be, A, B)
    good = good if type(good) is RatMat else rm.of(be, good)
    bad = RatMat(good.a.copy(), good.d.copy(), good.ctx)
    if corrupt == "numerator":
        bad.a[0, 1] = bad.a[0, 1] * 2
    else:
        k = be.ring.factor(be.ring.from_se(a + b)[0])[1][0][0]
        exps = dict(bad.d[0, 1])
        exps[k] = exps.get(k, 0) + 1
        bad.d[0, 1] = tuple(sorted(exps.items()))
    diff = rm.sub(be, bad, good)
    assert not (be.is_zero(diff) if type(diff) is PolyMat else rm.is_zero(be, diff))
    assert not equal(F, be, bad, np.dot(objs(A_ROWS), objs(B_ROWS)))


def test_a_product_cancels_the_factors_of_each_denominator():
    """(a+c)/(a+b) times (a+b)/(a+c): both atoms cancel in the factors, the product is 1 over no
    denominator (back to the common-denominator representation)."""
    F, be = setup()
    U = ratmat(be, [[(a + c) / (a + b), x / (a + b)]])
    V = ratmat(be, [[(a + b) / (a + c)], [0]])
    out = rm.matmul(be, U, V)
    assert type(out) is PolyMat and out.den == () and equal(F, be, out, objs([[1]]))
    W = ratmat(be, [[(a + b) / (a + c)], [y / (b + c)]])
    assert equal(F, be, rm.matmul(be, U, W), objs([[1 + x * y / ((a + b) * (b + c))]]))


def test_the_backend_dispatches_entrywise_matrices():
    """PolyBackend's operations on a RatMat: entrywise in flint, generic (symengine) beside a
    generic operand or a constant flint cannot hold, the inverse over one denominator."""
    from stiefelsym.backends.polyfield import ObjMat
    F, be = setup()
    A, B = ratmat(be, A_ROWS), ratmat(be, B_ROWS)
    EA, EB = objs(A_ROWS), objs(B_ROWS)
    assert type(be.add(A, B)) is RatMat and equal(F, be, be.add(A, B), EA + EB)
    assert equal(F, be, be.matmul(A, be.T(B)), np.dot(EA, EB.T))
    assert equal(F, be, be.neg(be.sub(A, B)), EB - EA)
    assert F.is_zero(F.normalize(be.trace(A) - (EA[0, 0] + EA[1, 1])))
    assert F.is_zero(F.normalize(be.inner(A, B) - sum(p * q for p, q in zip(EA.flat, EB.flat))))
    assert not be.is_zero(A) and be.is_zero(be.sub(A, A))
    G = ObjMat(objs([[se.sqrt(2), 0], [0, 1]]))
    out = be.add(A, G)
    assert type(out) is ObjMat and equal(F, be, out, EA + objs([[se.sqrt(2), 0], [0, 1]]))
    out = be.smul(A, se.sqrt(2))
    assert type(out) is ObjMat and equal(F, be, out, EA * se.sqrt(2))
    out = be.smul(A, x / (a + b))
    assert equal(F, be, out, EA * x / (a + b))
    inv = be.inv(B)
    assert be.is_zero(be.sub(be.matmul(B, inv), be.identity(2)))
    assert equal(F, be, be.block([[A, be.from_obj(EB)]]), np.block([[EA, EB]]))
    assert all(F.is_zero(F.normalize(g - e)) for g, e in zip(be.to_obj(A).flat, EA.flat))
