"""Stop 76: the review (s76/review, FINDINGS.md) found no wrong verdict and one misleading description, D1, closed
here; the stop's own attempt (s76/own) pushes D1's class to a registered correction.

D1: the tracer keeps one node for the P read twice inside a function, as XᵀP and, transposed, as PᵀX.  The letter
mutant P → X changes both places (XᵀX + XᵀX, a true statement: rightly "equivalent"), and `mutate` described it as
"XᵀP → XᵀX", which reads as d/dt(XᵀX + PᵀX) = 0, false for that flow.  A change made at several places of a small
expression, where a place does not print the changed part as it is, is now described by the whole expression."""
import json
from pathlib import Path

from adversary_cli import cli

HERE = Path(__file__).parent / "s76"


def test_a_change_at_a_transposed_read_is_described_at_every_place():
    run = cli("mutate", "--claims", str(HERE / "review" / "mutate_notation.py"), "s76-tangent", "--method", "modular",
              "--jobs", "1")
    lines = {ln.split(" ", 1)[0]: ln for ln in run.stdout.splitlines() if ln.startswith("s76-tangent#")}
    assert "in sym: XᵀP + PᵀX → XᵀX + XᵀX" in lines["s76-tangent#17"], run.stdout[-3000:]
    assert "equivalent" in lines["s76-tangent#17"]
    assert "in sym: XᵀP + PᵀX → PᵀP + PᵀP" in lines["s76-tangent#16"]
    # the statement the old words described is false, the one made is true
    for cid, verdict in (("s76-described-mutant", "fails"), ("s76-actual-mutant", "proved")):
        out = cli("verify", "--claims", str(HERE / "review" / "mutate_notation.py"), cid, "--method", "exact",
                  "--jobs", "1", "--format", "json", "--no-report")
        recs = json.loads(out.stdout)["results"]
        assert {r["verdict"] for r in recs} == {verdict}, out.stdout[-2000:]


def test_a_correction_through_a_product_read_twice_names_what_the_printed_form_shows(tmp_path):
    """K + Kᵀ = 2Iᵣ with K = XᵀP (false), corrected to K = XᵀX (true).  The printed form of the residual is
    XᵀP + (XᵀP)ᵀ − 2Iᵣ, where XᵀP shows at both places, so "XᵀP → XᵀX" describes the correction faithfully."""
    own = HERE / "own" / "shared_read_correction.py"
    run = cli("verify", "--claims", str(own), "--method", "exact", "--jobs", "1", "--report-dir", str(tmp_path))
    assert run.returncode == 0, run.stdout + run.stderr[-2000:]
    md = (tmp_path / "verification.md").read_text(encoding="utf-8")
    assert "| in K + K^T - 2I: XᵀP → XᵀX | K = XᵀX in place of XᵀP | **verified at the computed sizes** |" in md
