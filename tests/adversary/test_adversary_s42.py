"""Round 16 (tests/adversary/README.md, the "Round 16" table): forged and spliced results files under
`stiefelsym check` and `stiefelsym report`.  As before every run is the CLI in a fresh process, and each test
asserts the CORRECT outcome."""
import json
import os

from adversary_cli import HERE, cli

UNSTATED = "s42_unstated_size.py"


def _records(folder):
    return json.loads((folder / "results.json").read_text(encoding="utf-8"))


def _spliced(tmp_path, narrow, record, name):
    """The narrow run's results file with ``record`` (a genuine record of another run) added."""
    data = json.loads(json.dumps(narrow))
    data["results"].append(record)
    folder = tmp_path / name
    folder.mkdir()
    (folder / "results.json").write_text(json.dumps(data), encoding="utf-8")
    return folder


def test_a_record_at_a_size_the_claim_does_not_state_is_refused(tmp_path):
    """XXᵀ = I_n stated at r = n only: a genuine `fails` at (3,1) of the same claim id stated at every r (the same
    graph, the same digest, so running it again agrees) spliced into the results of its run at (3,3).  Before:
    `check` accepted the file (2 records checked, 0 rejected) and `report` wrote "the statement as printed fails at
    every computed size with r = 1" for a statement made at r = n only.  Now both refuse the record, as `verify`
    refuses the size; so are a true `proved` at a size the statement leaves out ((2,2) of a claim stated for
    n >= 3) and a record at a stated size its command did not plan ((4,2), the command asked for (3,3))."""
    narrow_dir, wide_dir = tmp_path / "narrow", tmp_path / "wide"
    run = cli("verify", "--claims", str(HERE / UNSTATED), "--size", "3,3", "--method", "exact", "--jobs", "1",
              "--report-dir", str(narrow_dir))
    assert run.returncode == 0, (run.stdout, run.stderr)
    assert "adv-s42-square-only (3,3) exact: proved" in run.stdout, run.stdout
    # outside its statement the size is refused by verify
    refused = cli("verify", "adv-s42-square-only", "--claims", str(HERE / UNSTATED), "--size", "3,1",
                  "--method", "exact", "--jobs", "1")
    assert refused.returncode != 0 and "outside" in refused.stderr, (refused.stdout, refused.stderr)
    wide = cli("verify", "--claims", str(HERE / UNSTATED), "--size", "3,1", "--size", "2,2", "--size", "4,2",
               "--method", "exact", "--jobs", "1", "--report-dir", str(wide_dir),
               env=dict(os.environ, STIEFELSYM_TEST_WIDE="1"))
    assert "adv-s42-square-only (3,1) exact: fails" in wide.stdout, (wide.stdout, wide.stderr)
    narrow = _records(narrow_dir)
    recs = {(r["claim"], r["n"], r["r"]): r for r in _records(wide_dir)["results"] if r["n"] is not None}
    control = cli("check", str(narrow_dir / "results.json"))
    assert control.returncode == 0, (control.stdout, control.stderr)
    for key, verdict, why in ((("adv-s42-square-only", 3, 1), "fails", "not stated for"),
                              (("adv-s42-from-three", 2, 2), "proved", "not stated for"),
                              (("adv-s42-from-three", 4, 2), "proved", "did not plan")):
        record = recs[key]
        assert record["verdict"] == verdict, record
        folder = _spliced(tmp_path, narrow, record, f"{key[0]}-{key[1]}{key[2]}")
        checked = cli("check", str(folder / "results.json"))
        assert checked.returncode == 1, (key, checked.stdout, checked.stderr)
        assert f"REJECTED {key[0]} ({key[1]},{key[2]}) exact: a record at a size" in checked.stdout, checked.stdout
        assert why in checked.stdout, checked.stdout
        report = cli("report", "--report-dir", str(folder))
        assert report.returncode != 0 and "refused" in report.stderr, (key, report.stdout, report.stderr)
        assert not (folder / "verification.md").exists()


def test_a_claim_left_out_whole_is_refused(tmp_path):
    """The other half of "a results file is the whole run of its command": a claim the command selected whose
    records are all taken out (its `fails` with them) left the file acceptable to `check` and `report` (the
    planned runs were listed only for the claims the file has records of); now both refuse it.  The command's
    claims are the ids it names, else every claim of its claims files."""
    folder = tmp_path / "run"
    run = cli("verify", "--claims", str(HERE / UNSTATED), "--size", "3,3", "--size", "3,1", "--method", "exact",
              "--jobs", "1", "--report-dir", str(folder))
    assert "adv-s42-from-three (3,1) exact: proved" in run.stdout, (run.stdout, run.stderr)
    data = _records(folder)
    assert {r["claim"] for r in data["results"]} == {"adv-s42-square-only", "adv-s42-from-three"}
    assert cli("check", str(folder / "results.json"), "--no-rerun").returncode == 0
    data["results"] = [r for r in data["results"] if r["claim"] != "adv-s42-square-only"]
    forged = tmp_path / "forged"
    forged.mkdir()
    (forged / "results.json").write_text(json.dumps(data), encoding="utf-8")
    checked = cli("check", str(forged / "results.json"), "--no-rerun")
    assert checked.returncode == 1, (checked.stdout, checked.stderr)
    assert "REJECTED adv-s42-square-only: no record of any of the 1 runs its command planned" in checked.stdout, \
        checked.stdout
    report = cli("report", "--report-dir", str(forged))
    assert report.returncode != 0 and "refused" in report.stderr, (report.stdout, report.stderr)
    # a command that names its claims plans those only
    named = tmp_path / "named"
    run = cli("verify", "adv-s42-from-three", "--claims", str(HERE / UNSTATED), "--size", "3,3", "--method", "exact",
              "--jobs", "1", "--report-dir", str(named))
    assert run.returncode == 0, (run.stdout, run.stderr)
    assert cli("check", str(named / "results.json"), "--no-rerun").returncode == 0


NONZERO = "s42_nonzero_statements.py"
WRONG_BESIDE = ("adv-s42-nonzero-wrong-count", "adv-s42-nonzero-rank-above-full", "adv-s42-nonzero-wrong-generic-rank")
#: a kind="dim" claim: float and ball do not run it
ALONE = "adv-s42-nonzero-rank-alone"


def test_a_rank_or_count_beside_a_nonvanishing_residual_is_not_passed():
    """expect="nonzero" with a rank or a count: before, exact, modular, rational, auto (and ball for the rank)
    said `proved` from the nonzero residual alone, whatever the rank or count.  Now every fixed-size method
    refuses the claim (error), at every size, and the residual-only controls keep their verdicts."""
    got: dict = {}
    for methods in (("--method", "exact", "--method", "modular", "--method", "rational"),
                    ("--method", "float", "--method", "ball"), ("--method", "auto")):
        run = cli("verify", "--claims", str(HERE / NONZERO), "--size", "2,2", "--size", "3,2", "--jobs", "1", *methods)
        for line in run.stdout.splitlines():
            parts = line.split()
            if len(parts) >= 4 and parts[0].startswith("adv-s42-") and parts[1].startswith("("):
                got.setdefault(parts[0], {})[(parts[1], parts[2].rstrip(":"))] = parts[3]
    for cid in WRONG_BESIDE:
        assert len(got.get(cid, {})) == 10, (cid, got.get(cid))     # auto takes exact here
        assert set(got[cid].values()) == {"error"}, (cid, got[cid])
    assert len(got.get(ALONE, {})) == 6 and set(got[ALONE].values()) == {"error"}, got.get(ALONE)
    only = got["adv-s42-nonzero-only-residuals"]
    assert set(only.values()) == {"proved", "numeric"} and only[("(3,2)", "modular")] == "proved", only
    vanishing = got["adv-s42-nonzero-vanishing"]
    assert set(vanishing.values()) == {"fails"}, vanishing


def test_the_runs_of_a_correction_taken_out_are_refused(tmp_path):
    """A correction runs at every size its claim was run at by a method under which the claim failed (and for
    every n, r where the dimension-free method did not prove it): its failing records taken out, `check` accepted
    the file (the report, to its credit, said "not verified" there); now `check` and `report` refuse it."""
    folder = tmp_path / "run"
    run = cli("verify", "--claims", str(HERE / "s42_correction_runs.py"), "--method", "exact", "--jobs", "1",
              "--report-dir", str(folder))
    assert "adv-s42-corrected [constant dropped] (3,2) exact: fails" in run.stdout, (run.stdout, run.stderr)
    assert cli("check", str(folder / "results.json"), "--no-rerun").returncode == 0
    data = _records(folder)
    data["results"] = [r for r in data["results"] if not (r.get("variant") and r["verdict"] == "fails")]
    forged = tmp_path / "forged"
    forged.mkdir()
    (forged / "results.json").write_text(json.dumps(data), encoding="utf-8")
    checked = cli("check", str(forged / "results.json"), "--no-rerun")
    assert checked.returncode == 1, (checked.stdout, checked.stderr)
    assert "REJECTED adv-s42-corrected [constant dropped] (3,2) exact: no record of the run" in checked.stdout
    report = cli("report", "--report-dir", str(forged))
    assert report.returncode != 0 and "refused" in report.stderr, (report.stdout, report.stderr)
