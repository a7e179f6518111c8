"""Speed against error: no observed residual (nor the actual error against the exact value at the
same point) ever exceeds the error model's predicted bound; the hard cases never give a false
`fails` or a pass of a false claim; `stiefelsym speed --quick` writes its files."""
import json

import pytest

from stiefelsym.analyses import speed as sp


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


def test_small_r_series_and_every_precision_keep_the_bound(catalog):
    """Fresh data, small and fast: r = 2 against n (float64 entries read as whole arrays) and
    mpmath 30, 50, 100 digits and the exact evaluation against n, each compared with the exact
    residual at the same point."""
    c = catalog.get("neumann-lax")
    stops = []
    recs = sp.residual_against_n(c, [2, 3, 4, 8], cap=5, total=10, exact_n=8, r_of=sp.two, stops=stops)
    recs += sp.residual_against_precision(c, [3, 4], precisions=(30, 50, 100, "exact"), exact_n=4, stops=stops)
    assert {r["precision"] for r in recs} == {"float64", "mpmath30", "mpmath50", "mpmath100", "exact"}
    assert all(r.get("status") == "ok" for r in recs), recs
    assert sp.violations(recs) == []
    for r in recs:
        assert r["max_residual"] <= r["max_bound"], r
        if r["precision"] != "exact" and r["n"] <= 4:
            assert r["exceed_exact"] == 0 and r["max_actual_error"] <= r["max_bound"], r
    assert [r["max_residual"] for r in recs if r["precision"] == "exact"] == [0.0, 0.0]


def test_a_too_small_bound_is_caught():
    """Negative control of the check: the same residuals against bounds a million times too small
    are reported as entries over their bound (whole-array and entry-by-entry paths alike)."""
    import numpy as np
    v, m = np.array([1e-16, -3e-16, 0.0]), np.array([1.0, 2.0, 1.0])
    good = sp._stats(v, np.full(3, 1e-15), m, True)
    bad = sp._stats(v, np.full(3, 1e-21), m, True)
    assert good["exceed"] == 0 and bad["exceed"] == 2 and bad["worst_ratio"] > 1
    assert sp._stats(list(v), [1e-21] * 3, list(m), False)["exceed"] == 2
    assert sp.violations([dict(bad, precision="float64")]) != []


def test_prediction_stops_a_series_before_its_cap(monkeypatch):
    """The cost model's power law, fitted to the series so far, keeps a size predicted beyond the
    cap from being started, and says so."""
    series = [{"n": 2, "seconds": 0.01, "status": "ok"}, {"n": 4, "seconds": 0.08, "status": "ok"}]
    assert sp._predicted(series, 8) >= 0.64 * 0.999
    ran = []

    def fake(claim, n, r, dps=None, seed=0, exact=False, **kw):     # t = 0.01 n^3 seconds
        ran.append(n)
        return {"n": n, "r": r, "precision": "float64", "status": "ok", "seconds": 0.01 * n ** 3}
    monkeypatch.setattr(sp, "evaluate", fake)
    stops = []
    recs = sp.residual_against_n(None, [2, 3, 4, 200], cap=5.0, total=100, stops=stops)
    assert ran == [2, 3, 4] and [r["n"] for r in recs] == [2, 3, 4]
    assert stops and "stopped before n = 200" in stops[0] and "predicted" in stops[0]


def test_committed_report_has_no_residual_over_its_bound():
    """The committed data (reports/speed/speed.json): every observed residual within its predicted
    bound, and within e of the exact value wherever that was computed; the hard cases without a
    wrong verdict."""
    from pathlib import Path
    root = Path(__file__).resolve().parents[1] / "reports" / "speed"
    doc = json.loads((root / "speed.json").read_text())
    assert doc["violations"] == []
    seen = 0
    for fam, sec in doc["families"].items():
        for key in ("against_n", "against_n2", "against_precision"):
            for r in sec.get(key) or []:
                if r.get("status") != "ok":
                    continue
                seen += 1
                assert not r.get("exceed") and not r.get("exceed_exact"), (fam, r)
                if r["precision"] == "ball":      # an enclosure: no observed residual beside its bound
                    assert r["max_residual"] is None and r["resolved"], (fam, r)
                    continue
                assert float(r["max_residual"]) <= float(r["max_bound"]), (fam, r)
                if isinstance(r.get("max_actual_error"), float):
                    assert r["max_actual_error"] <= r["max_bound"], (fam, r)
    assert seen > 50
    n200 = [r for sec in doc["families"].values() for r in sec.get("against_n2") or [] if r["n"] == 200]
    assert len(n200) == 4 and all(r["status"] == "ok" for r in n200)
    rows = json.loads((root / "hard.json").read_text())
    assert rows and not [r for r in rows if r["judgement"].startswith("WRONG")]
    assert not [r for r in rows if r["truth"] == "true" and r["verdict"] == "fails"]
    assert not [r for r in rows if r["truth"] == "false" and r["verdict"] in ("numeric", "checked", "proved")]
    from stiefelsym.methods.hard import HARD_CASES
    at200 = {r["case"] for r in rows if r["n"] == 200}
    assert all(f"n = 200 + {case}" in at200 for case in HARD_CASES), sorted(at200)
    sizes = {(r["n"], r["r"]) for r in rows}
    assert {(200, 1), (200, 2)} <= sizes and any(n == r >= 8 for n, r in sizes) and any(r == n - 1 >= 7 for n, r in sizes)


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


@pytest.mark.slow      # the whole quick speed run (about 30 s): with the slow tests (`make verify-all`)
def test_speed_quick_writes_its_files(run, tmp_path):
    pytest.importorskip("matplotlib")
    out = run("speed", "--quick", "--report-dir", str(tmp_path / "speed"))
    assert out.exit_code == 0, out.output
    d = tmp_path / "speed"
    for name in ("speed.json", "speed.md", "hard.md", "hard.json", "costmodel.json", "costmodel.png",
                 "costmodel.pdf", "speed-lax.png", "speed-lax.pdf"):
        assert (d / name).is_file(), name
    doc = json.loads((d / "speed.json").read_text())
    assert doc["violations"] == [] and doc["hard_wrong"] == []
    precs = {r["precision"] for r in doc["families"]["lax"]["against_precision"]}
    assert precs == {"float64", "mpmath30", "mpmath50", "mpmath100", "ball", "exact"}
    assert doc["tradeoffs"] and "Hard sizes" in (d / "hard.md").read_text()


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
    from stiefelsym.methods.hard import HARD_CASES
    for case in HARD_CASES:
        touched = []
        for cid in ("neumann-lax", "manakov-lax"):
            rows = sp.hard_table(cases=[case], sizes=((3, 2),), large=None, methods=("modular",),
                                 claims=[catalog.get(cid)], timeout=60)
            touched += [r["touched"] for r in rows]
        assert any(touched), case


def test_cost_model_refit_from_its_records_is_byte_for_byte(run, tmp_path):
    """stiefelsym speed --cost-only --records refits the stored measurements: the same cost model file and the
    same plot of predicted against measured as committed.  The control: one measurement changed gives
    another fit; a file without measurements is refused (exit 2, one line, no traceback)."""
    pytest.importorskip("matplotlib")
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    stored = root / "stiefelsym" / "methods" / "costmodel.json"
    for f in ("all/results.json", "results.json"):           # the catalog runs the claims are calibrated on
        (tmp_path / "reports" / f).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "reports" / f).write_bytes((root / "reports" / f).read_bytes())
    out = run("speed", "--cost-only", "--records", str(stored), "--report-dir", str(tmp_path / "a"),
              "--model-file", str(tmp_path / "model.json"))
    assert out.exit_code == 0, out.output
    assert (tmp_path / "model.json").read_bytes() == stored.read_bytes()
    for name in ("costmodel.json", "costmodel-accuracy.png", "costmodel.png"):
        assert (tmp_path / "a" / name).read_bytes() == (root / "reports" / "speed" / name).read_bytes(), name
    doc = json.loads(stored.read_text())
    rec = next(r for r in doc["records"] if r["method"] == "float" and r["n"] >= 64)
    rec["seconds"] *= 10
    (tmp_path / "changed.json").write_text(json.dumps(doc))
    out = run("speed", "--cost-only", "--records", str(tmp_path / "changed.json"), "--report-dir", str(tmp_path / "b"),
              "--model-file", str(tmp_path / "model2.json"))
    assert out.exit_code == 0, out.output
    assert (tmp_path / "model2.json").read_bytes() != stored.read_bytes()
    (tmp_path / "empty.json").write_text("{}")
    out = run("speed", "--cost-only", "--records", str(tmp_path / "empty.json"), "--report-dir", str(tmp_path / "c"))
    assert out.exit_code == 2 and "holds no cost model measurements" in out.output
    assert "Traceback" not in out.output
    for bad in (["--cost-only", "--hard-only"], ["--cost-only", "--records", str(stored), "--cap", "5"]):
        out = run("speed", *bad, "--report-dir", str(tmp_path / "d"))
        assert out.exit_code == 2 and "Traceback" not in out.output and "--" in out.output, bad


def test_ball_evaluation_bounds_a_true_claim_and_not_a_corrupted_one(catalog):
    """The ball column of the speed-against-error plots: a rigorous bound for a true claim at the float
    method's point (below float64's error-model bound there); the control, the corrupted LA1, gets an
    enclosure that excludes 0, never a bound."""
    c = catalog.get("neumann-lax")
    rec = sp.evaluate_ball(c, 8, 2)
    assert rec["status"] == "ok" and rec["bits"] == "arb53" and 0 < rec["max_bound"] < 1e-9
    assert rec["max_bound"] <= sp.evaluate(c, 8, 2)["max_bound"]
    bad = sp.evaluate_ball(sp.control_claim(), 8, 2)
    assert bad["status"] == "bad" and not bad["resolved"]


def test_the_cost_model_reads_the_seconds_from_the_run_log_beside_results(tmp_path):
    """A committed results.json leaves the timings out; `stiefelsym speed` takes them from the run log of the
    same run (run-log.json, not committed), record by record, and only where it lists the same runs."""
    from stiefelsym.cli.speed import timed
    records = [{"claim": "LA1", "n": 3, "r": 1, "method": "exact", "variant": None},
               {"claim": "LA1", "n": 3, "r": 2, "method": "exact", "variant": None, "seconds": 0.5}]
    log = tmp_path / "run-log.json"
    assert timed(records, log) == records                               # no log: as they are
    log.write_text(json.dumps({"seconds": [["LA1", 3, 1, "exact", None, 0.25], ["LA1", 3, 2, "exact", None, 9.0]]}))
    assert [r.get("seconds") for r in timed(records, log)] == [0.25, 0.5]  # a record's own seconds are kept
    log.write_text(json.dumps({"seconds": [["LA1", 3, 2, "exact", None, 0.25], ["LA1", 3, 1, "exact", None, 9.0]]}))
    assert timed(records, log) == records                               # another run's log: not read
