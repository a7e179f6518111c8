"""The short cuts of a warm dimension-free proof compute what the general paths compute.

The native transpose of the free backend (it applies the involution, as the generic path of
``Mat.T`` does), the evaluator's scalar · matrix product (the matrix's reflected product at once
for a scalar type whose own product gives way), and the checker's canonical forms kept across
checks: each against the general path, and a corrupted certificate still rejected after a good
one filled the shared forms.
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
from stiefelsym.matrix import Mat
from stiefelsym.runner import run_one


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
