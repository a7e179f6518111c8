"""The short cuts of a warm dimension-free proof compute what the general paths compute.

The native transpose of the free backend (it applies the involution, as the generic path of
``Mat.T`` does), the evaluator's scalar · matrix product (the matrix's reflected product at once
for a scalar type whose own product gives way), the checker's canonical forms kept across checks,
the memo of a lazy free field's arithmetic and the memo of normal forms of polynomials: each
against the general path; a corrupted certificate still rejected after a good one filled the shared
forms; the arithmetic memo off once the engine is sealed for a claims file.
"""
from __future__ import annotations

import copy
from fractions import Fraction

import numpy as np
import symengine as se

from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.free.scene import FreeScene
from stiefelsym.ir import evaluate as ev
from stiefelsym.backends.matrix import Mat
from stiefelsym.run.runner import run_one


def _scene() -> FreeScene:
    return FreeScene(realization="standard", lazy=True)


def _generic_T(M: Mat) -> Mat:
    a = M._view().T.copy()
    for idx, x in np.ndenumerate(a):
        a[idx] = M._field.star(x)
    return Mat._wrap(a, M._field, (M._tags[1], M._tags[0]), M._tracker)


def test_native_transpose_is_the_generic_one():
    s = _scene()
    for M in (s.X, s.P, s.X @ s.P.T, s.Phi, s.X.T @ s.A @ s.P):
        t = M.T
        assert t._n is not None and t._tags == (M._tags[1], M._tags[0])
        assert t._n == _generic_T(M)._view()[0, 0]
        assert (t.T)._n == M._n


def test_scalar_times_matrix_is_the_reflected_product():
    s = _scene()
    for c in (2, Fraction(1, 3), s.lam, s.lam * s.lam, 1 + 2 * s.kappa, -s.kappa, se.Integer(3)):
        for M in (s.X, s.Phi, s.P.T):
            got = ev._scale(c, M)
            assert type(got) is Mat and got._n == (c * M)._n and got._tags == M._tags
            if type(c) in ev._YIELDS_TO_MAT:   # only types whose own product gives way are short-cut
                assert type(c).__mul__(c, M) is NotImplemented
    assert ev._scale(2, 3) == 6 and ev._scale(s.lam, 2) == 2 * s.lam


def test_a_forged_certificate_is_rejected_after_good_ones_filled_the_shared_forms():
    claim = load_catalog().get("neumann-lax")
    res = run_one(claim, None, "free", 0)
    assert res.verdict == "proved"
    data = res.certificate_data
    assert check_certificate(data).accepted and check_certificate(data).accepted
    for forge in ("drop", "sign", "word"):
        bad = copy.deepcopy(data)
        entry = next(e for e in bad["entries"] if e["terms"])
        if forge == "drop":
            entry["terms"].pop()
        elif forge == "sign":
            t = entry["terms"][0]
            t["coef"] = f"-({t['coef']})"
        else:
            entry["residual"][0]["word"] = list(reversed(entry["residual"][0]["word"]))
        assert not check_certificate(bad).accepted, forge
    assert check_certificate(data).accepted


def _values_off():
    from stiefelsym.free import mat
    mat.VALUE_MEMO = 0
    mat.forget_values()


def test_the_memo_of_free_arithmetic_returns_what_is_computed_without_it():
    from stiefelsym.free import mat
    from stiefelsym.methods.fixed_size import call_claim
    claim = load_catalog().get("neumann-lax")
    warm = [call_claim(claim.func, _scene()) for _ in range(3)]
    assert len(mat._VALUES) > 0
    _values_off()
    cold = call_claim(claim.func, _scene())
    assert not mat._VALUES
    for k, v in cold.items():
        for w in warm:
            assert w[k]._n == v._n and w[k]._tags == v._tags


def test_the_memo_keys_polynomials_by_identity_and_scalars_by_type_and_value():
    from stiefelsym.free import mat
    s = _scene()
    be = mat.FreeBackend(s.field, values=True)
    a, b = s.X._n, s.P.T._n
    first = be.matmul(a, b)
    assert be.matmul(a, b) is first
    a2 = a * 1   # an equal polynomial, another object: computed again, the same value
    assert be.matmul(a2, b) is not first and be.matmul(a2, b) == first
    assert be.smul(a, 2) is be.smul(a, 2) and be.smul(a, Fraction(1, 2)) == a * Fraction(1, 2)
    assert be.neg(a) is be.neg(a) and be.neg(a) == -a
    # a field that is not lazy (its normalize applies the rules) is not memoized
    eager = FreeScene(realization="standard", lazy=False)
    assert not mat.FreeBackend(eager.field, values=True)._memo()


def test_sealing_switches_the_memo_off_and_the_seal_sees_it_switched_on():
    import pytest
    from stiefelsym.free import mat
    from stiefelsym.ir import seal
    seal.seal()
    assert mat.VALUE_MEMO == 0 and not mat._VALUES
    run_one(load_catalog().get("neumann-lax"), None, "free", 0)
    assert not mat._VALUES
    mat.VALUE_MEMO = 1
    with pytest.raises(seal.EngineChanged):
        seal.verify("test")


def test_the_normal_form_memo_gives_the_reduction_of_a_fresh_system():
    from stiefelsym.free.scene import standard_system
    from stiefelsym.methods.fixed_size import _entries, call_claim
    claim = load_catalog().get("neumann-lax")
    s = _scene()
    checks = call_claim(claim.func, s)
    for name, value in checks.items():
        for _pos, x in _entries(value, name):
            p = x._n if isinstance(x, Mat) else x
            first, again = s.system.reduce(p), standard_system().reduce(p)
            assert again.normal_form == first.normal_form and again.rules == first.rules
            assert _fresh_nf(p) == first.normal_form


def _fresh_nf(p):
    from stiefelsym.free.rewriting import RewritingSystem
    from stiefelsym.free.scene import standard_system
    shared = standard_system()
    own = RewritingSystem(shared.order.copy(), shared.rules)   # memos of its own, empty
    return own.reduce(p).normal_form


def test_the_certificate_memo_gives_the_certificate_of_a_fresh_system():
    from stiefelsym.free.rewriting import RewritingSystem
    from stiefelsym.free.scene import standard_system
    from stiefelsym.methods.fixed_size import _entries, call_claim
    claim = load_catalog().get("neumann-lax")
    s = _scene()
    for name, value in call_claim(claim.func, s).items():
        for _pos, x in _entries(value, name):
            p = x._n if isinstance(x, Mat) else x
            first, again = s.system.certify(p), standard_system().certify(p)
            shared = standard_system()
            fresh = RewritingSystem(shared.order.copy(), shared.rules).certify(p)
            assert [str(t) for t in again.terms] == [str(t) for t in first.terms] == [str(t) for t in fresh.terms]
            assert again.terms is not first.terms   # a list of its own
