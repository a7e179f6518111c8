"""Speed against error: no observed residual (nor the actual error against the exact value at the
same point) ever exceeds the error model's predicted bound; the hard cases never give a false
`fails` or a pass of a false claim; `stiefelsym speed --quick` writes its files."""
import json

import pytest

from stiefelsym import speed as sp


@pytest.mark.parametrize("cid", ["neumann-flow", "neumann-lax", "neumann-dual-lax-normal", "momentum-maps-poisson"])
def test_residual_never_exceeds_its_bound(catalog, cid):
    c = catalog.get(cid)
    recs = sp.residual_against_n(c, [2, 3, 4], cap=5, total=10, exact_n=4)
    recs += sp.residual_against_precision(c, 3, 2)
    assert recs and all(r.get("status") == "ok" for r in recs), recs
    assert all("exceed_exact" in r for r in recs if r["precision"] != "exact")
    assert sp.violations(recs) == []
    for r in recs:
        if r["precision"] != "exact":
            assert r["max_residual"] <= r["max_bound"]


def test_error_bound_holds_for_a_false_claim_too():
    """The bound is on |computed - exact|, whatever the claim: the corrupted Lax equation has a large
    residual, and its rounding error still stays within e."""
    c = sp.control_claim()
    rec = sp.evaluate(c, 4, 2, None, 0, exact=True)
    assert rec["max_exact_residual"] > 1e-3
    assert rec["exceed"] > 0             # the residual is visible ...
    assert rec["exceed_exact"] == 0      # ... and the computed value is within e of the exact one


@pytest.mark.parametrize("case", ["near-equal-a-1e-12", "near-pole-1e-8", "large-momenta", "manakov-0/0",
                                  "far-chart"])
def test_hard_points_keep_the_bound(catalog, case):
    for cid in ("neumann-lax", "manakov-lax"):
        rec = sp.evaluate(catalog.get(cid), 4, 2, None, 0, hard=case, exact=True)
        if rec.get("status") == "ok":
            assert rec["exceed_exact"] == 0 and rec["exceed"] == 0, rec


def test_corrupted_evaluation_is_a_violation():
    """The check itself can fail: a record whose residual exceeds its bound is reported."""
    assert sp.violations([{"exceed": 0, "exceed_exact": 1}, {"exceed": 0}]) == [{"exceed": 0, "exceed_exact": 1}]


def test_hard_table_has_no_wrong_verdict(catalog):
    rows = sp.hard_table(cases=["near-pole", "near-equal-a-1e-12"], sizes=((3, 1), (3, 3)), large=None,
                         timeout=60, claims=[catalog.get("neumann-lax"), sp.control_claim()])
    assert rows
    assert not [r for r in rows if r["judgement"].startswith("WRONG")], rows
    control = [r for r in rows if r["claim"] == "corrupted-LA1"]
    assert any(r["verdict"] == "fails" for r in control)
    assert all(r["verdict"] != "fails" for r in rows if r["truth"] == "true")
    assert "WRONG" in sp._judge("true", "fails", None)
    assert "WRONG" in sp._judge("false", "numeric", None)
    assert "WRONG" in sp._judge("false", "undecided", {"exceed_exact": 2})


def test_speed_quick_writes_its_files(run, tmp_path):
    out = run("speed", "--quick", "--report-dir", str(tmp_path / "speed"))
    assert out.exit_code == 0, out.output
    d = tmp_path / "speed"
    for name in ("speed.json", "speed.md", "hard.md", "hard.json", "costmodel.json", "costmodel.png",
                 "costmodel.pdf", "speed-lax.png", "speed-lax.pdf"):
        assert (d / name).is_file(), name
    doc = json.loads((d / "speed.json").read_text())
    assert doc["violations"] == [] and doc["hard_wrong"] == []


def test_overflow_escalates_and_keeps_the_bound(catalog):
    c = catalog.get("neumann-lax")
    assert sp.evaluate(c, 4, 2, None, 0, hard="huge-momenta")["status"] == "overflow"
    rec = sp.evaluate(c, 4, 2, 30, 0, hard="huge-momenta", exact=True)
    assert rec["status"] == "ok" and rec["exceed"] == 0 and rec["exceed_exact"] == 0
    rows = sp.hard_table(cases=["huge-momenta"], sizes=((3, 1),), large=None, methods=("float",),
                         claims=[c], timeout=60)
    assert rows[0]["verdict"] == "undecided" and rows[0]["precision"].startswith("mpmath")
    assert rows[0]["judgement"] == "ok"


def test_every_hard_case_rewrites_some_parameter(catalog):
    from stiefelsym.hard import HARD_CASES
    for case in HARD_CASES:
        touched = []
        for cid in ("neumann-lax", "manakov-lax"):
            rows = sp.hard_table(cases=[case], sizes=((3, 2),), large=None, methods=("modular",),
                                 claims=[catalog.get(cid)], timeout=60)
            touched += [r["touched"] for r in rows]
        assert any(touched), case
