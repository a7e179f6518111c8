"""The checks of a mutant's run that no parameter entered are evaluated over Q once per function, size
and seed, for its rational and its modular run alike (stiefelsym.methods.fixed_size.PointLoan.constants): the
report of evaluating them every time; an evaluation kept for another function is caught."""
from __future__ import annotations

import pytest

from stiefelsym.methods import fixed_size as M
from stiefelsym.claims import Size, load_catalog
from stiefelsym.analyses.mutate import run_mutation


def cells(report):
    return {(c.claim, o.index, x.n, x.r, x.method): (o.classification, x.verdict, x.message)
            for c in report.claims for o in c.mutants for x in o.cells}


CONSTANT = dict(methods=("rational", "modular"), sizes=[Size(4, 1)], only=[0, 2, 3])


@pytest.fixture(scope="module")
def constant_claim():
    """invariant-metrics is a constant at (4, 1) as printed and in its mutants (a rank of a matrix of numbers);
    #0 and #3 change the rank (refuted), #2 changes nothing the checks read (equivalent).  (It was
    dual-lax-determines-the-point, whose rank of full size 2nr had no (k+1)-minor, so its lent points' degree
    bound was 0 and its mutants were taken for constants, though parameters enter them: see `_lent_constant`.)"""
    return load_catalog().get("invariant-metrics")


def test_a_constant_run_is_evaluated_once_for_both_point_methods(constant_claim, monkeypatch):
    real, scenes = M._constant_evaluations, []

    def forgetful(claim, n, r, seed, func, options, field):
        if M._LOAN is not None:
            M._LOAN.constants.clear()      # nothing kept: every run evaluates afresh
        return real(claim, n, r, seed, func, options, field)

    def counted(*args, **kw):
        if type(args[2]) is M.RationalField:
            scenes.append(args[:2])
        return scene(*args, **kw)
    scene = M.Scene
    monkeypatch.setattr(M, "Scene", counted)
    monkeypatch.setattr(M, "_constant_evaluations", forgetful)
    fresh = cells(run_mutation([constant_claim], **CONSTANT))
    afresh = len(scenes)
    monkeypatch.setattr(M, "_constant_evaluations", real)
    scenes.clear()
    got = cells(run_mutation([constant_claim], **CONSTANT))
    assert got == fresh
    assert {v[1] for v in got.values()} == {"proved", "fails"}
    # the claim as printed and three mutants: one evaluation each, not one per method
    assert afresh == 8 and len(scenes) == 4


def test_a_constant_evaluation_kept_for_another_function_is_caught(constant_claim, monkeypatch):
    """Negative control: keyed without the function, every mutant reads the printed claim's evaluation
    and the refuted mutants pass."""
    real = M._constant_evaluations

    def careless(claim, n, r, seed, func, options, field):
        return real(claim, n, r, seed, claim.func if M._LOAN is not None and not M._LOAN.recording else func,
                    options, field)
    fresh = cells(run_mutation([constant_claim], **CONSTANT))
    monkeypatch.setattr(M, "_constant_evaluations", careless)
    assert cells(run_mutation([constant_claim], **CONSTANT)) != fresh
