"""The mutation analysis evaluates a mutant at the points of the claim as printed and recomputes only
the nodes its change reaches (stiefelsym.methods.fixed_size.PointLoan): the same verdicts as fresh points, in
any order and any number of workers; a key that forgets part of a node is caught."""
from __future__ import annotations

import random
from fractions import Fraction

import pytest

from stiefelsym.claims import Size, load_catalog
from stiefelsym.backends.fields import RationalField
from stiefelsym.ir import evaluate as ev
from stiefelsym.analyses.mutate import run_mutation
from stiefelsym.backends.paired import PairField
from stiefelsym.scene import Scene

#: claims with flows, brackets, resolvents and an operator letter, a few mutants each
CLAIMS = ("neumann-lax", "euclidean-flow", "submersion-flow", "magnetic-normal-flow")


def outcomes(report):
    return {(c.claim, o.index): (o.classification, sorted(o.killed_by.items()), o.survived,
                                 [(x.n, x.r, x.method, x.verdict) for x in o.cells])
            for c in report.claims for o in c.mutants}


@pytest.fixture(scope="module")
def claims():
    reg = load_catalog()
    return [reg.get(c) for c in CLAIMS]


@pytest.fixture(scope="module")
def fresh(claims):
    return outcomes(run_mutation(claims, methods=("rational", "modular", "float"), limit=6, lend=False))


def test_lent_points_give_the_verdicts_of_fresh_points(claims, fresh):
    """The same verdict in every cell.  (A witness may differ: parameters the printed claim never
    drew are drawn in the mutant's own order, so its point is another random point.)"""
    lent = outcomes(run_mutation(claims, methods=("rational", "modular", "float"), limit=6))
    assert len(lent) >= 20
    assert lent == fresh


def messages(report):
    return {(c.claim, o.index, x.n, x.r, x.method): x.message for c in report.claims for o in c.mutants
            for x in o.cells}


def test_the_workers_and_their_order_do_not_matter(claims, fresh):
    """Verdicts, witnesses and bounds alike: every loan starts from the same snapshot of the point and
    of the fields' records (the denominators and constants the degree markers met)."""
    one = run_mutation(claims, methods=("rational", "modular", "float"), limit=6)
    two = run_mutation(claims, methods=("rational", "modular", "float"), limit=6, jobs=2)
    backwards = run_mutation(list(reversed(claims)), methods=("rational", "modular", "float"), limit=6)
    assert outcomes(two) == fresh
    assert messages(one) == messages(two) == messages(backwards)


def test_a_node_key_that_forgets_a_literal_is_caught(claims, fresh, monkeypatch):
    """Negative control: keys that drop the nodes' literal arguments (a coefficient, an attribute's
    name) let a mutant read the printed claim's values, and its verdicts change."""
    real = ev.node_keys

    def careless(g):
        keys = real(g)
        return [k if op in ("scene",) else op.encode() for k, op in zip(keys, g.ops)]
    monkeypatch.setattr(ev, "node_keys", careless)
    assert outcomes(run_mutation(claims, methods=("rational", "modular", "float"), limit=6)) != fresh


def test_a_lent_scene_draws_its_own_parameters_and_leaves_the_original_alone():
    s = Scene(4, 2, PairField(RationalField(2**20)), rng=random.Random(5))
    X = s.X
    copy = s._lent()
    assert copy.X is X                         # what was drawn is shared
    a_copy = copy.A                            # drawn after the loan, on the copy's own generator
    assert "A" not in s._cache and not any(k.startswith("a") for k in s._params if k not in copy._params)
    a_orig = s.A                               # the original draws the same values from its own
    assert (a_orig - a_copy).is_zero()
    copy.tracker.touch("matrix entries")
    assert "matrix entries" not in s.tracker.used


@pytest.mark.parametrize("restore", [True, False])
def test_every_loan_starts_from_the_baselines_record_of_denominators(monkeypatch, restore):
    """What a mutant's degree markers meet (a new denominator, a new constant) is not seen by the next
    mutant; the negative control (no restore) shows that it would be."""
    from stiefelsym.methods import fixed_size as methods
    if not restore:
        monkeypatch.setattr(methods, "_restore_field", lambda f, state: None)
    loan = methods.PointLoan()

    def build():
        f = PairField(RationalField(2**20))
        return f, Scene(3, 1, f, rng=random.Random(1))
    loan.recording = True
    f, s = loan.scene(("k",), build)
    s.X                                             # the baseline draws its point
    loan.recording = False
    f1, s1 = loan.scene(("k",), build)
    before = dict(f1.degrees.factor_degree)
    f1.degrees.new_factor(3)                        # a mutant meets a denominator the baseline did not
    f1.degrees.const(7919)
    f1.const(Fraction(1, 7919))                     # and makes a constant over it
    f2, s2 = loan.scene(("k",), build)
    assert f2 is f1 is f and s2 is not s1
    assert (f2.degrees.factor_degree == before) == restore
    assert (7919 not in f2.degrees.constants) == restore
    assert (Fraction(1, 7919) not in f2._consts) == restore


def test_two_mutants_that_make_the_same_new_constant():
    """jensen-hamiltonian #21 and #50 both change a coefficient 1/2 to 1/3: the second must not read
    the first one's constant, whose denominator the loan forgot (it ended in a KeyError)."""
    claim = load_catalog().get("jensen-hamiltonian")
    kw = dict(methods=("rational", "float"), sizes=[Size(4, 2)], only=[21, 50])
    lent, fresh = run_mutation([claim], **kw), run_mutation([claim], lend=False, **kw)
    assert outcomes(lent) == outcomes(fresh)
    assert all("KeyError" not in x.message for c in lent.claims for o in c.mutants for x in o.cells)


@pytest.mark.parametrize("guard", [True, False])
def test_a_scene_of_its_own_is_not_shared(monkeypatch, guard):
    """magnetic-grassmannian-flow evaluates at another point of T*V, a scene of its own that builds
    its objects lazily: shared between mutants, #132's A⁻¹ built there would be read by the next run
    over a denominator the loan forgot.  Such values are not shared; the negative control shares
    them, and the runs break."""
    from stiefelsym.ir import evaluate
    if not guard:
        monkeypatch.setattr(evaluate, "shareable", lambda v: True)
    claim = load_catalog().get("magnetic-grassmannian-flow")
    kw = dict(methods=("rational", "float"), sizes=[Size(3, 2)], only=[132])
    lent = run_mutation([claim], **kw)
    broken = any("KeyError" in x.message for c in lent.claims for o in c.mutants for x in o.cells)
    assert broken != guard
    if guard:
        assert outcomes(lent) == outcomes(run_mutation([claim], lend=False, **kw))


def test_the_exact_witness_taken_from_the_rational_run_is_that_of_a_one_point_run(monkeypatch):
    """A refutation by the exact method attaches the witness of a one-point rational run; on lent points
    it is taken from the rational run of the same mutant at the same size (PointLoan.witnesses): the
    very witness the one-point run computes (compared here run by run), taken for most refutations."""
    from stiefelsym.methods import fixed_size as M
    real = M._rational_witness
    seen = {"memo": 0, "runs": 0}

    def compared(claim, n, r, seed, func):
        loan = M._LOAN
        hit = loan.witnesses.get((claim.id, claim.realization, n, r, seed, id(func))) if loan else None
        got = real(claim, n, r, seed, func)
        direct = M.run_points(claim, n, r, "rational", seed, func, trials=1).witness
        assert got == direct
        seen["memo" if hit is not None and hit[0] is func and not loan.recording else "runs"] += 1
        return got
    monkeypatch.setattr(M, "_rational_witness", compared)
    reg = load_catalog()
    run_mutation([reg.get("neumann-lax"), reg.get("euclidean-flow"), reg.get("normal-momentum-of-velocity")],
                 methods=("exact", "rational"), limit=8)
    assert seen["memo"] >= 5 and seen["memo"] > seen["runs"]


def test_a_witness_kept_for_another_function_is_not_taken():
    """Negative control: a kept witness is taken only for the function it was computed for (by identity)."""
    from stiefelsym.methods import fixed_size as M
    reg = load_catalog()
    claim = reg.get("neumann-lax")
    loan = M.PointLoan()

    def other(s):
        return claim.func(s)
    loan.witnesses[(claim.id, claim.realization, 4, 2, 0, id(other))] = (claim.func, {"forged": True})
    with M.lending_points(loan):
        assert M._rational_witness(claim, 4, 2, 0, other) != {"forged": True}
