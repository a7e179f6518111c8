"""The exact method proves a claim's checks in groups, each on the chart its own slice of the graph allows:
a claim whose checks read coordinates of R^n goes whole to the unconstrained or the Cayley chart, while its
checks that read none go to the equivariant chart.  Each reduction is stated with the checks it is used for;
a corrupted check fails in either group, with its witness; a claim said not to vanish is proved whole; the
slice of a graph is the nodes its checks read and nothing else."""
from __future__ import annotations

import pytest

from stiefelsym import admissible
from stiefelsym.claims import Claim, _mark_reviewed
from stiefelsym.ir import compile_claim
from stiefelsym.methods import fixed_size
from stiefelsym.methods.fixed_size import _check_groups, run_exact
from stiefelsym.scene import REALIZATIONS


def _claim(func, cid="t-groups", expect="holds"):
    # as the catalog's (reviewed): a claims file's claim is evaluated at a rational point before any symbolic
    # chart and refuted there, so its groups of checks would not be what is tested here (test_adversary_s73)
    return _mark_reviewed(Claim(id=cid, paper=("prep",), kind="id", section="t", func=func, sizes=admissible(7),
                                expect=expect))


def _graph(func, n, r):
    cons = REALIZATIONS["standard"]
    return compile_claim(func, n, r, (cons.name, cons.build))


def _sum_of_squares(s):
    """Σ X_ij² written entry by entry (reads coordinates of R^n)."""
    acc = s.q(0)
    for i in range(s.n):
        for j in range(s.r):
            acc = acc + s.X[i, j] * s.X[i, j]
    return acc


def _mixed(s):
    return {"X^T X - I": s.X.T @ s.X - s.Ir,
            "sum of squares - tr(X^T X)": _sum_of_squares(s) - s.tr(s.X.T @ s.X),
            "tr(X^T P) + tr(P^T X)": s.tr(s.X.T @ s.P) + s.tr(s.P.T @ s.X)}


def _mixed_wrong_unread(s):
    out = _mixed(s)
    out["X^T X - I"] = s.X.T @ s.X - 2 * s.Ir
    return out


def _mixed_wrong_read(s):
    out = _mixed(s)
    out["sum of squares - tr(X^T X)"] = _sum_of_squares(s) - s.tr(s.X.T @ s.X) + s.X[0, 0]
    return out


def _mixed_needs_constraints_where_read(s):
    """Every check true on V; the one that reads entries needs the constraints (Σ X_ij² = r on V)."""
    return {"X^T X - I": s.X.T @ s.X - s.Ir, "sum of squares - r": _sum_of_squares(s) - s.q(s.r)}


def test_a_slice_holds_the_nodes_its_checks_read_and_nothing_else():
    g = _graph(_mixed, 3, 2)
    assert g.output_keys() == ("X^T X - I", "sum of squares - tr(X^T X)", "tr(X^T P) + tr(P^T X)")
    unread = g.checks_slice(frozenset({"X^T X - I", "tr(X^T P) + tr(P^T X)"}))
    read = g.checks_slice(frozenset({"sum of squares - tr(X^T X)"}))
    assert "entry" in g.ops and "entry" in read.ops and "entry" not in unread.ops
    assert unread.output_keys() == ("X^T X - I", "tr(X^T P) + tr(P^T X)")       # in the claim's order
    assert len(unread) + len(read) <= len(g) + 8 and len(unread) < len(g) and len(read) < len(g)
    assert unread.digest() != g.digest() != read.digest()
    again = g.checks_slice(frozenset({"X^T X - I", "tr(X^T P) + tr(P^T X)"}))
    assert again.digest() == unread.digest()
    for bad in (frozenset(), frozenset({"no such check"})):
        with pytest.raises(ValueError):
            g.checks_slice(bad)


def test_the_checks_that_read_no_coordinates_are_proved_on_the_equivariant_chart():
    c = _claim(_mixed)
    assert _check_groups(c, 3, 2, c.func) is not None
    res = run_exact(c, 3, 2, 0)
    assert res.verdict == "proved", res.message
    assert [o.name for o in res.checks] == ["X^T X - I", "sum of squares - tr(X^T X)", "tr(X^T P) + tr(P^T X)"]
    assert len(res.reductions) == 2
    unread, read = res.reductions
    assert unread.startswith("for the checks 'X^T X - I', 'tr(X^T P) + tr(P^T X)': equivariance") and "these checks read no coordinates of R^n" in unread
    assert read.startswith("for the checks 'sum of squares - tr(X^T X)': no constraint used")


def test_a_check_that_needs_the_constraints_where_it_reads_goes_to_the_cayley_chart():
    c = _claim(_mixed_needs_constraints_where_read)
    res = run_exact(c, 3, 2, 0)
    assert res.verdict == "proved", res.message
    assert res.reductions[0].startswith("for the checks 'X^T X - I': equivariance")
    assert res.reductions[1].startswith("for the checks 'sum of squares - r': rational parametrization")


@pytest.mark.parametrize("func, wrong", [(_mixed_wrong_unread, "X^T X - I"),
                                         (_mixed_wrong_read, "sum of squares - tr(X^T X)")])
def test_a_corrupted_check_fails_in_either_group_with_its_witness(func, wrong):
    c = _claim(func)
    res = run_exact(c, 3, 2, 0)
    assert res.verdict == "fails"
    assert res.residual.startswith(wrong)
    assert res.witness
    if wrong == "X^T X - I":        # the first group fails: the second is not run, and the record says so
        assert "'sum of squares - tr(X^T X)' were not evaluated" in res.message
        assert [o.name for o in res.checks] == ["X^T X - I", "tr(X^T P) + tr(P^T X)"]
    # the modular method agrees (a witness of the whole claim)
    from stiefelsym.run.runner import Size, run_one
    assert run_one(c, Size(3, 2), "modular", 0).verdict == "fails"


def test_the_groups_give_the_verdict_of_the_whole_claim():
    """Proved in groups and proved whole (the unconstrained and Cayley charts for every check) agree."""
    c = _claim(_mixed)
    grouped = run_exact(c, 3, 2, 0)
    # the groups of another function are current: this claim is proved whole (no engine function replaced,
    # which the engine's seal would refuse once a claims file has been loaded in the process)
    token = fixed_size._CHECKS.set((object(), frozenset()))
    try:
        whole = run_exact(_claim(_mixed, "t-groups-whole"), 3, 2, 0)
    finally:
        fixed_size._CHECKS.reset(token)
    assert grouped.verdict == whole.verdict == "proved"
    assert not any(d.startswith("for the checks") for d in whole.reductions)
    assert [o.name for o in grouped.checks] == [o.name for o in whole.checks]


def test_no_groups_for_a_claim_said_not_to_vanish_one_check_or_no_coordinate_read():
    assert _check_groups(_claim(_mixed, expect="nonzero"), 3, 2, _mixed) is None
    assert _check_groups(_claim(_mixed), 3, 2, lambda s: {"one": _sum_of_squares(s) - s.tr(s.X.T @ s.X)}) is None

    def unread(s):
        return {"a": s.X.T @ s.X - s.Ir, "b": s.tr(s.X.T @ s.P) + s.tr(s.P.T @ s.X)}
    assert _check_groups(_claim(unread), 3, 2, unread) is None


def test_a_check_that_shares_a_reading_node_is_not_in_the_unread_group():
    def shared(s):
        m = s.mat([[s.X[0, 0]]], ("?", "?"))
        return {"reads": m - m, "also reads": (m @ m) - (m @ m), "none": s.X.T @ s.X - s.Ir}
    c = _claim(shared)
    names, groups = _check_groups(c, 3, 2, shared)
    assert groups[0] == frozenset({"none"}) and groups[1] == frozenset({"reads", "also reads"})


def test_the_review_tricks_that_read_through_an_engine_step_still_fail():
    """Stop 57's review (tests/adversary/s57): a check the static analysis puts in the unread group but whose
    evaluation reads coordinates (the rank of a Jacobian, the eigenvalues a_i) leaves the equivariant chart by
    its own run's record, and the false statement fails, grouped as whole."""
    from pathlib import Path
    from stiefelsym.claims import load_claims_file
    from stiefelsym.run.runner import Size, run_one
    reg = load_claims_file(str(Path(__file__).parent / "adversary" / "s57" / "batch1.py"))
    for cid in ("b2-jacobian-rank", "b6-eigs"):
        c = reg.get(cid)
        assert _check_groups(c, 3, 2, c.func) is not None, cid
        assert run_one(c, Size(3, 2), "exact", 0).verdict == "fails", cid
        assert run_one(c, Size(3, 2), "modular", 0).verdict == "fails", cid


def _charpoly_of_xxt_minus(s, shift):
    """charpoly(XXᵀ) − λ^(n−r)(λ − 1)^r − shift: 0 on V when shift is 0 (XXᵀ a projector of rank r)."""
    from stiefelsym.proofs.determinants import charpoly
    out = s.q(1)
    for _ in range(s.n - s.r):
        out = out * s.lam
    for _ in range(s.r):
        out = out * (s.lam - s.q(1))
    return charpoly(s, s.X @ s.X.T, s.lam) - out - shift


@pytest.mark.parametrize("method", ["exact", "modular", "float"])
def test_the_stop_s_own_attempt_with_charpoly_in_the_unread_group(method):
    """A check of the characteristic polynomial (no coordinate read) beside one that reads entries: the true
    claim is grouped and holds; shifting either check by a term that vanishes nowhere on V fails it."""
    from stiefelsym.run.runner import Size, run_one

    def true(s):
        return {"entries": _sum_of_squares(s) - s.q(s.r), "charpoly": _charpoly_of_xxt_minus(s, s.q(0))}

    def shifted_unread(s):
        return {"entries": _sum_of_squares(s) - s.q(s.r),
                "charpoly": _charpoly_of_xxt_minus(s, s.lam * s.tr(s.P.T @ s.P))}

    def shifted_read(s):
        return {"entries": _sum_of_squares(s) - s.q(s.r) + s.X[0, 0] * s.P[0, 0],
                "charpoly": _charpoly_of_xxt_minus(s, s.q(0))}
    assert _check_groups(_claim(true), 3, 2, true) is not None
    good = run_one(_claim(true, "t-cp-true"), Size(3, 2), method, 0)
    assert good.verdict in ("proved", "checked", "numeric"), good.message
    for f, wrong in ((shifted_unread, "charpoly"), (shifted_read, "entries")):
        res = run_one(_claim(f, f"t-cp-{wrong}"), Size(3, 2), method, 0)
        assert res.verdict == "fails" and res.residual.startswith(wrong), (method, wrong, res.verdict, res.message)


def test_a_refuted_mutant_is_proved_in_groups_from_the_group_its_witness_names():
    """In the mutation analysis a mutant the rational method has refuted is proved in groups from the group of
    the check its witness names: that group fails, and the group that holds is not proved in full first (it
    was, at stop 58, until the order was taken from the witness: mum-geod's analysis took 2.5 times longer)."""
    from stiefelsym.analyses.mutate import run_mutation
    from stiefelsym.claims import Size
    rep = run_mutation([_claim(_mixed, "t-groups-mutated")], sizes=[Size(3, 2)], methods=("rational", "exact"),
                       seed=0)
    first = 0
    for o in rep.claims[0].mutants:
        cells = {x.method: x for x in o.cells}
        if cells["rational"].verdict != "fails" or cells["exact"].verdict != "fails":
            continue
        if cells["rational"].message.startswith("sum of squares") and "not evaluated" in cells["exact"].message:
            # the read group first: the unread checks are left, and the record says so (a mutant whose
            # checks no longer read coordinates is proved whole)
            assert "'X^T X - I', 'tr(X^T P) + tr(P^T X)' were not evaluated" in cells["exact"].message, o
            first += 1
    assert first >= 1


def test_a_shared_slice_never_carries_one_claims_verdict_to_another(monkeypatch):
    """Stop 69's own attempt on the slices shared by content (fixed_size._interned): in one process, the true claim
    first, then a claim that corrupts its check of the group that reads no coordinate, then one that corrupts the
    group that reads entries.  Each corrupted claim shares the other group's slice with the true one, and still
    fails, in the group it corrupted; the true one is proved again after them."""
    monkeypatch.setattr(fixed_size, "_SLICES", fixed_size.OrderedDict())
    runs = [(f, run_exact(_claim(f, cid=f"t-share-{k}"), 3, 2, 0))
            for k, f in enumerate((_mixed, _mixed_wrong_unread, _mixed_wrong_read, _mixed))]
    assert [res.verdict for _f, res in runs] == ["proved", "fails", "fails", "proved"]
