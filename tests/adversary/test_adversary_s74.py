"""Stop 74: the own attempt on the momenta hard cases (s74/own/momenta.py) and replays of the new-user review's
defects of the command line (s74/newuser/FINDINGS.md): each an exit status and a one-line message."""
import json
from pathlib import Path

from adversary_cli import cli

HERE = Path(__file__).parent
UNTOUCHED = "changed no parameter of this claim"


def test_own_attempt_momenta_count_once_p_is_read():
    """A claim that reads P only through Φ or through a flow is evaluated at the hard point (it is touched); one that
    reads X alone is verified at random points as without the case; no false claim passes, the true one is not
    refuted, under every sampled method."""
    for case in ("large-momenta", "huge-momenta"):
        run = cli("verify", "--claims", str(HERE / "s74" / "own" / "momenta.py"), "--size", "3,2",
                  "--method", "rational", "--method", "modular", "--method", "float", "--method", "ball",
                  "--hard", case, "--jobs", "1", "--format", "json", "--no-report")
        recs = json.loads(run.stdout)["results"]
        assert len(recs) == 16, run.stderr[-2000:]
        for r in recs:
            touched = UNTOUCHED not in (r["message"] or "")
            if r["claim"] in ("s74-own-phi-false", "s74-own-flow-false"):
                assert touched, r
                assert r["verdict"] in ("fails", "inconclusive", "undecided"), r
            else:
                assert not touched, r
                expect = ("proved", "checked", "numeric") if r["claim"] == "s74-own-x-true" else ("fails",)
                assert r["verdict"] in expect, r


def test_flows_refuses_a_results_file_that_is_not_one(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"results": [')
    for results in (bad, tmp_path / "none.json", tmp_path):
        run = cli("flows", "--report-dir", str(tmp_path / "out"), "--results", str(results), "--quick")
        assert run.returncode == 2 and "Traceback" not in run.stderr, run.stderr
        assert not (tmp_path / "out" / "flows.md").exists()


def test_flows_checks_its_report_folder_before_integrating():
    run = cli("flows", "--report-dir", "/proc/stiefelsym-nowhere", "--quick")
    assert run.returncode == 2 and "cannot write the flows report" in run.stderr and "integrat" not in run.stderr.lower()


def test_check_names_what_a_json_object_lacks(tmp_path):
    empty = tmp_path / "empty.json"
    empty.write_text("{}")
    run = cli("check", str(empty))
    assert run.returncode == 2 and "no results and no meta at its top level" in run.stderr, run.stderr
    assert "KeyError" not in run.stderr


def test_memory_refusal_and_size_condition_read_as_sentences():
    run = cli("verify", "neumann-lax", "--size", "2,1", "--memory", "0.001")
    assert run.returncode == 2 and "; or a larger" not in run.stderr and "a larger --memory" in run.stderr, run.stderr
    run = cli("verify", "--claims", str(HERE / "s74" / "newuser" / "true_claims.py"), "nu-action-rank", "--size", "1,1")
    assert run.returncode == 2 and "n >= 2 (n >= 2)" not in run.stderr and "n >= 2" in run.stderr, run.stderr


def test_every_seed_option_takes_random_and_refuses_negatives():
    run = cli("mutate", "neumann-lax", "--size", "2,1", "--seed", "random", "--limit", "1", "--method", "modular")
    assert run.returncode in (0, 1) and "seed: " in run.stderr and "Traceback" not in run.stderr, run.stderr[-2000:]
    run = cli("tables", "--size", "2,1", "--seed", "-5")
    assert run.returncode == 2 and "non-negative integer or 'random'" in run.stderr, run.stderr


def test_texts_of_a_hand_edited_record_are_parsed_never_evaluated():
    """The class of the second review's D1 (a residual's text run as code through sympy's parser): no text of a
    results file is evaluated as Python, and none that would take for ever is expanded.  The notebook's residual
    parser and the certificate checker's coefficients refuse power towers, huge expansions, attribute calls and
    nesting beyond the stack, at once."""
    import time

    import pytest

    from stiefelsym.certificate_check import Rejected, coefficient
    from stiefelsym.reports.notebook import _sympy_text
    t0 = time.perf_counter()
    for text in ("9**9**9**9", "(9**9999)**9999", "(7).equals('1')", "__import__('os').getcwd()", "x**y",
                 "(" * 50_000 + "1" + ")" * 50_000, "lambda: 0", "1/0"):
        with pytest.raises(ValueError):
            _sympy_text(text)
    for text in ("9**9**9**9", "(kappa + lam + n + r + 1)**1000", "kappa lam", "sin(kappa)"):
        with pytest.raises(Rejected):
            coefficient(text)
    assert time.perf_counter() - t0 < 60
    assert str(_sympy_text("3/4*Z_2,1**2 - lambda*a_1 + 1")) == "3*Z_2,1**2/4 - a_1*lambda + 1"
    assert str(coefficient("(kappa + 1)**2/(n - r)")) == "(1 + kappa)**2/(n - r)"
