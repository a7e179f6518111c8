"""Stop 71: the review's findings (tests/adversary/s71/review).  See tests/adversary/README.md, Stop 71.  The pytest
plugin's are replayed in tests/test_pytest_plugin_collect.py."""
import json
import subprocess
import sys
from pathlib import Path

from adversary_cli import cli

REVIEW = Path(__file__).parent / "s71" / "review"


def test_report_check_refuses_a_fails_record_edited_into_checked(tmp_path):
    """Finding 3: the `fails` record of a false identity edited into `checked` with a true claim's evidence (its
    digest, words and rerun its own) is rendered as edited by `report`, which runs no record again (its help and the
    report say so); `report --check` and `check` run it again and refuse the file."""
    false, true = tmp_path / "F", tmp_path / "T"
    for name, out in (("flip_false.py", false), ("flip_true.py", true)):
        run = cli("verify", "--claims", str(REVIEW / name), "--method", "modular", "--size", "3,2", "--jobs", "1",
                  "--report-dir", str(out))
        assert run.returncode in (0, 1), run.stderr[-2000:]
    forged = false / "forged.json"
    subprocess.run([sys.executable, str(REVIEW / "report_flip.py"), str(false / "results.json"),
                    str(true / "results.json"), str(forged)], check=True)
    assert json.loads(forged.read_text())["results"][0]["verdict"] == "checked"
    for args in (("report", "--check", "--results", str(forged), "--report-dir", str(tmp_path / "rep")),
                 ("check", str(forged))):
        run = cli(*args)
        assert run.returncode == 1, run.stdout[-2000:] + run.stderr[-2000:]
        assert "a run again says 'fails'" in run.stdout + run.stderr
    assert not (tmp_path / "rep" / "verification.md").exists()
    # the honest file renders with --check
    run = cli("report", "--check", "--results", str(true / "results.json"), "--report-dir", str(tmp_path / "ok"))
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert (tmp_path / "ok" / "verification.md").is_file()
    assert "runs every record again" in cli("report", "--help").stdout


def test_the_review_calculus_and_mutation_probes_get_right_verdicts(tmp_path):
    """Tried, no hole: Dirac flows of Hamiltonians equal on T*V only, ambient derivatives and gradients, brackets
    with a function of the constraints, false twins; kept as a replay under the fixed-size methods."""
    run = cli("verify", "--claims", str(REVIEW / "batch_calculus.py"), "--method", "modular", "--size", "3,2",
              "--size", "2,1", "--jobs", "1", "--no-report")
    lines = [ln for ln in run.stdout.splitlines() if ln.startswith("s71-c-") and " modular: " in ln]
    assert len(lines) == 16, run.stdout[-3000:] + run.stderr[-3000:]
    for ln in lines:
        cid, verdict = ln.split()[0], ln.split(": ")[1].split()[0]
        assert verdict == ("fails" if cid.endswith("-false") else "checked"), ln


HIDDEN = Path(__file__).parent / "s71" / "hidden"


def test_further_statements_of_the_paper_get_the_verdicts_numpy_gives():
    """Stop 71's statements of the paper the catalog does not state, written with the public API (s71/hidden,
    FINDINGS.md): every verdict as a numpy check of its own says, the new erratum of §8's remark (N = l at r = 1)
    included."""
    run = cli("verify", "--claims", str(HIDDEN / "claims.py"), "--method", "modular", "--method", "exact",
              "--size", "3,2", "--size", "4,1", "--jobs", "2", "--no-report")
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    assert "h71-n-bigger-than-half (4,1) exact: fails" in run.stdout


def test_their_false_twins_fail_where_numpy_says():
    """Each statement with one change, failing where numpy says; the one rank printed too large that a random point
    cannot refute (rank 1 at a point is no upper bound on the generic rank) is inconclusive, never a pass."""
    run = cli("verify", "--claims", str(HIDDEN / "negatives.py"), "--method", "modular", "--method", "exact",
              "--size", "3,2", "--size", "4,1", "--jobs", "2", "--no-report")
    unexpected = [ln for ln in run.stdout.splitlines() if "UNEXPECTED" in ln and not ln.startswith("  ")]
    assert unexpected and all(ln.startswith("n71-jk-rank-r (3,2) modular: inconclusive") for ln in unexpected), \
        run.stdout[-3000:]


REVIEW2 = Path(__file__).parent / "s71" / "review2"


def test_counts_of_integers_run_at_any_size_whatever_the_cost_model_predicts():
    """The second review: `dual-integrals-exceed-half-leaf` at (200,2) was refused up front ("predicted 2.04e+09
    days ... try --method ball", a method that does not run on dimensions).  Counts of plain integers are evaluated
    exactly at any size."""
    run = cli("verify", "dual-integrals-exceed-half-leaf", "--size", "200,2", "--size", "200,1", "--method", "exact",
              "--method", "auto", "--jobs", "1", "--no-report")
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert "dual-integrals-exceed-half-leaf (200,1) exact: fails" in run.stdout
    run = cli("verify", "pencil-rank-a1", "--size", "400,2", "--method", "exact", "--memory", "1000000",
              "--no-report")
    assert run.returncode == 2 and "--method ball" not in run.stderr and "--method float" not in run.stderr


def test_an_empty_block_at_n_equals_r_gets_one_verdict_in_a_process():
    """The second review: a check on the empty (n − r) × (n − r) block at n = r was proved by a first exact run and an
    error (IndexError) by the next one in the same process (the straight-line program of the first)."""
    run = subprocess.run([sys.executable, str(REVIEW2 / "empty_trace.py")], capture_output=True, text=True,
                         timeout=600)
    assert run.returncode == 0, run.stderr[-2000:]
    rows = dict(line.split(" ", 1) for line in run.stdout.splitlines() if line.strip())
    assert len(rows) == 6
    for name, verdicts in rows.items():
        words = verdicts.split()[-8:]
        want = ("fails",) if name.startswith("f-") else ("proved", "checked", "numeric")
        assert all(w.split(":")[1] in want for w in words), (name, verdicts)


HIDDEN2 = Path(__file__).parent / "s71" / "hidden2"


def test_auto_tries_the_exact_method_where_the_points_cannot_decide():
    """The second round of further statements: a rank printed one too large for a small linear matrix (the isotropy
    in the proof of (ddim)) at (6,2), beyond the default symbolic budget: the modular method is inconclusive (a
    lower rank at points is no witness), and `auto` gave up, where the exact method refutes it at once.  `auto` now
    tries the exact method after an undecided or inconclusive modular run, within the run's budgets."""
    run = cli("verify", "--claims", str(HIDDEN2 / "negatives.py"), "n71b-ddim-isotropy-trivial", "--size", "6,2",
              "--method", "auto", "--jobs", "1", "--no-report")
    assert run.returncode == 0, run.stdout[-2000:] + run.stderr[-2000:]
    assert "n71b-ddim-isotropy-trivial (6,2) exact: fails" in run.stdout
    assert "the modular method could not decide beyond the symbolic budget (inconclusive" in run.stdout


def test_the_second_round_of_statements_and_twins_get_the_verdicts_numpy_gives():
    run = cli("verify", "--claims", str(HIDDEN2 / "claims.py"), "--method", "modular", "--size", "3,2", "--size",
              "4,2", "--jobs", "2", "--no-report")
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    run = cli("verify", "--claims", str(HIDDEN2 / "negatives.py"), "--method", "auto", "--size", "3,2", "--size",
              "4,1", "--size", "4,2", "--jobs", "2", "--no-report")
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]


REVIEW3 = Path(__file__).parent / "s71" / "review3"


def test_check_accepts_the_records_of_auto_running_exact_after_all(tmp_path):
    """The third review: records written where auto ran the exact method beyond the budget after the modular method
    could not decide were refused by `check` and `report --check` (their messages were compared with the record's
    method run alone).  Their messages are compared with auto run again, whole; an edited one is still refused."""
    out = tmp_path / "o"
    run = cli("verify", "--claims", str(REVIEW3 / "late_exact.py"), "r3-late-every-point", "r3-late-rank-low",
              "r3-late-every-point-false", "--size", "4,2", "--method", "auto", "--jobs", "1", "--report-dir", str(out))
    assert "the modular method could not decide beyond the symbolic budget" in run.stdout, run.stdout[-3000:]
    assert "so the exact method ran after all" in run.stdout
    run = cli("check", str(out / "results.json"))
    assert run.returncode == 0 and "0 rejected" in run.stdout + run.stderr, run.stdout[-2000:] + run.stderr[-2000:]
    data = json.loads((out / "results.json").read_text())
    late = next(r for r in data["results"] if (r["message"] or "").startswith("the modular method could not"))
    late["message"] = late["message"].replace("could not decide", "did decide")
    (out / "edited.json").write_text(json.dumps(data, indent=1))
    run = cli("check", str(out / "edited.json"))
    assert run.returncode == 1 and "(message)" in run.stdout + run.stderr


def test_a_count_of_thousands_of_digits_is_refused_at_once():
    """The third review: a Count of 7^(10^6) (845,099 digits) cost 331 s, a third of it in the main process (every
    decimal rendering of the number is quadratic).  A count of more than 3,900 digits is refused when traced."""
    run = cli("verify", "--claims", str(REVIEW3 / "count_digits.py"), "--size", "4,2", "--method", "auto", "--jobs", "1",
              "--no-report")
    assert run.returncode == 1 and "a count of more than 3,900 digits" in run.stdout, run.stdout[-2000:]
