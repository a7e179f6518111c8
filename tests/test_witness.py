"""Witnesses a reader checks by hand: a small point on T*V where the printed formula fails, and a
self-contained script that rebuilds it and evaluates the printed formula and the correction."""
import json
import re
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from stiefelsym.claims import load_catalog
from stiefelsym.methods.witness import decoded, encoded, small_witness
from stiefelsym.methods.witness_scripts import count_values, run_script, script_text, template, template_check

ROOT = Path(__file__).resolve().parents[1]
REPORTS = ROOT / "reports"
CID = "coupled-neumann-flow"


@pytest.fixture(scope="module")
def witness():
    claim = load_catalog().get(CID)
    return small_witness(claim, 1, 1, check=template_check(CID))


def test_the_small_witness_is_a_point_of_tstar_v_with_a_nonzero_entry(witness):
    assert witness["check"] == template_check(CID) and Fraction(witness["value"]) != 0
    assert witness["on T*V"] and all(witness["on T*V"].values())
    assert witness["height bits"] <= 4
    assert set(witness["letters"]) >= {"X", "P", "Y", "Q", "A", "κ"}


def test_the_small_witness_is_reproducible(witness):
    claim = load_catalog().get(CID)
    again = small_witness(claim, 1, 1, check=template_check(CID))
    assert encoded(again) == encoded(witness)
    assert decoded(json.loads(json.dumps(encoded(witness))))["letters"] == witness["letters"]


def test_the_correction_has_no_witness():
    claim = load_catalog().get(CID)
    fixed = claim.corrections[0].func
    assert small_witness(claim, 1, 1, fixed, check=template_check(CID)) is None


def test_the_script_confirms_the_report_and_a_wrong_one_does_not(witness):
    text = script_text(CID, "(C-eq)", 1, 1, encoded(witness))
    status, out = run_script(text)
    assert status == 0 and "the correction holds there" in out
    # negative controls: a stated value that is not the printed residual, a point off T*V
    wrong = dict(encoded(witness), value=str(Fraction(witness["value"]) + 1))
    assert run_script(script_text(CID, "", 1, 1, wrong))[0] == 1
    off = encoded(witness)
    off = dict(off, letters=dict(off["letters"], X=[["2"]]))
    status, out = run_script(script_text(CID, "", 1, 1, off))
    assert status == 1 and "X^T X = I: False" in out


def test_a_template_whose_correction_is_wrong_is_caught(witness, monkeypatch):
    import stiefelsym.methods.witness_scripts as ws
    body = template(CID).replace("+ Y * Pi", "- Y * Pi")
    monkeypatch.setattr(ws, "template", lambda cid: body)
    status, out = run_script(ws.script_text(CID, "", 1, 1, encoded(witness)))
    assert status == 1 and "(NOT zero)" in out


def _committed():
    return sorted((REPORTS / "witnesses").glob("*.py")) if (REPORTS / "witnesses").is_dir() else []


#: the committed scripts the default test run takes (every WITNESS_SAMPLE-th, in name order); every one of them
#: runs with the tests marked slow (each is a sympy computation of 2-4 s in an interpreter of its own)
WITNESS_SAMPLE = 4


@pytest.mark.parametrize("script", [pytest.param(p, marks=() if k % WITNESS_SAMPLE == 0 else pytest.mark.slow)
                                    for k, p in enumerate(_committed())], ids=lambda p: p.stem)
def test_every_committed_witness_script_runs_alone_and_prints_what_the_report_states(script, tmp_path):
    """Each script runs from an empty folder with python -I (no stiefelsym on its path), prints
    exactly its committed output, and the value it confirms is the one in results.json (a sample of them in the
    default run, all with the tests marked slow)."""
    out = subprocess.run([sys.executable, "-I", str(script)], cwd=tmp_path, capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stdout + out.stderr
    assert out.stdout == script.with_suffix(".out").read_text(encoding="utf-8")
    results = json.loads((REPORTS / "results.json").read_text(encoding="utf-8"))["results"]
    small = [r["witness"]["small"] for r in results if r["claim"] == script.stem and not r.get("variant")
             and isinstance(r.get("witness"), dict) and "small" in r["witness"]]
    assert small and f"(the report states {Fraction(small[0]['value'])})" in out.stdout
    assert f"`witnesses/{script.stem}.py`" in (REPORTS / "verification.md").read_text(encoding="utf-8")


def test_the_integrity_check_recomputes_the_small_witness():
    """A hand-edited small witness (another point, another value) is caught by `stiefelsym check`;
    the honest record passes."""
    from stiefelsym.claims import Size
    from stiefelsym.run.integrity import check_results
    from stiefelsym.run.runner import verify
    from stiefelsym.methods.witness import attach_small_witnesses
    cat = load_catalog()
    claim = cat.get(CID)
    res = [r for r in verify([claim], sizes=[Size(1, 1)], methods=("exact",), seed=0) if not r.variant]
    assert attach_small_witnesses(res, {CID: claim}) == 1
    honest = json.loads(json.dumps(res[0].to_json(), default=str))
    assert check_results([honest], cat, echo=lambda _: None) == 0
    forged = json.loads(json.dumps(honest))
    forged["witness"]["small"]["value"] = "3"
    lines: list[str] = []
    assert check_results([forged], cat, echo=lines.append) == 1 and "small witness" in lines[0]


@pytest.mark.parametrize("script", _committed(), ids=lambda p: p.stem)
def test_every_witness_script_rejects_a_value_the_report_does_not_state(script):
    """Negative control of every committed script: the stated value changed by one, it exits 1."""
    text = script.read_text(encoding="utf-8")
    m = re.search(r'^STATED = (?:sp\.Rational\("([^"]+)"\)|(-?\d+))$', text, re.M)
    assert m, "no STATED line"
    wrong = Fraction(m.group(1) or m.group(2)) + 1
    new = f'STATED = sp.Rational("{wrong}")' if m.group(1) else f"STATED = {wrong}"
    status, out = run_script(text[:m.start()] + new + text[m.end():])
    assert status == 1 and "MISMATCH" in out


@pytest.mark.parametrize("detail, want", [
    ("kernel = invariant forms: a constant nonzero 12x12 minor (rank >= 12 at every point) and rank 12 over the "
     "function field; paper: 13", (12, 13)),
    ("kernel = invariant forms: a matrix of rational numbers (15x15, the same at every point of the chart): exact "
     "rank 12 over Q, so rank 12 at every point; paper: 13", (12, 13)),
    ("the generic orbit is regular (1) or singular (0): 1 (paper: 0)", (1, 0)),
    ("rank 12 over Qx; paper: 13", None),
])
def test_the_computed_and_printed_values_are_read_from_every_rank_certificate(detail, want):
    """A rank's certificate names the computed rank in each of its forms (over the function field, over Q for a
    matrix of rational numbers), so an erratum about a number keeps its hand-checkable witness script."""
    assert count_values(detail) == want


def test_the_integrity_check_accepts_a_count_whose_witness_is_only_the_small_one():
    """A refuted count (an erratum about a number) has no witness point: its record's witness is the small
    witness alone, which `stiefelsym check` recomputes; the honest record passes, a forged value is caught."""
    from stiefelsym.claims import Size
    from stiefelsym.run.integrity import check_results
    from stiefelsym.run.runner import verify
    from stiefelsym.methods.witness import attach_small_witnesses
    cat = load_catalog()
    cid = "adjoint-orbit-regularity"
    res = [r for r in verify([cat.get(cid)], sizes=[Size(4, 1)], methods=("exact",), seed=0) if not r.variant]
    assert res[0].verdict == "fails" and attach_small_witnesses(res, {cid: cat.get(cid)}) == 1
    honest = json.loads(json.dumps(res[0].to_json(), default=str))
    assert set(honest["witness"]) == {"small"}
    assert check_results([honest], cat, echo=lambda _: None) == 0
    forged = json.loads(json.dumps(honest))
    forged["witness"]["small"]["value"] = 0
    lines: list[str] = []
    assert check_results([forged], cat, echo=lines.append) == 1 and "small witness" in lines[0]
