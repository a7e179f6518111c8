"""Stop 67: the review's files (tests/adversary/s67/review) and the stop's own attempt (s67/own_count_numbers.py).
See tests/adversary/README.md, Stop 67."""
import re
import shutil
import subprocess

import pytest

from adversary_cli import HERE, cli, verdicts_each

PASSING = ("proved", "checked", "numeric")


def test_a_count_compares_plain_ints_whatever_the_claim_hands_over():
    """The size errata of this stop are Counts: an int subclass that says it equals everything (as the value or
    as the printed number), a bool, a float near an integer, a numpy integer, a Fraction and a string are
    refused (`error`) under every method, never a pass; a true Count of plain ints is proved."""
    got = verdicts_each("s67/own_count_numbers.py", ("exact", "modular", "free"))
    false = ("oc-liar-int", "oc-liar-printed", "oc-bool", "oc-float", "oc-numpy", "oc-fraction", "oc-string")
    for method, by_claim in got.items():
        for cid in false:
            assert by_claim.get(cid) not in PASSING, (method, cid, by_claim.get(cid))
    assert got["exact"]["oc-liar-int"] == "error" and got["modular"]["oc-liar-printed"] == "error"
    # a count of plain ints is a constant, exact over Q: proved under modular too (since stop 88)
    assert got["exact"]["oc-true"] == "proved" and got["modular"]["oc-true"] == "proved"


def test_the_prose_idioms_of_the_reports_change_no_verdict_and_the_latex_compiles(tmp_path):
    """A claim whose statement, docstring, check names and erratum words are full of the idioms the reports now set
    in the paper's notation (L*_neum, r x r, !=, ->, 1<=i<=r, X0, Theta, nested and unclosed scripts): the verdicts
    are the claims' own, and the LaTeX report compiles."""
    out = tmp_path / "rep"
    run = cli("verify", "--claims", str(HERE / "s67" / "review" / "tex_idioms.py"), "--size", "3,2", "--method",
              "modular", "--jobs", "1", "--report-dir", str(out))
    assert "tx-idioms-false (3,2) modular: fails" in run.stdout, run.stdout[-2000:] + run.stderr[-2000:]
    assert "tx-idioms-true (3,2) modular: checked" in run.stdout
    tex = (out / "verification.tex").read_text()
    assert r"\ensuremath{\mathcal{L}^{*}_{neum}}" in tex     # the star a superscript, one formula
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed")
    build = tmp_path / "tex"
    build.mkdir()
    shutil.copy(out / "verification.tex", build)
    subprocess.run(["pdflatex", "-interaction=nonstopmode", "verification.tex"], cwd=build, capture_output=True,
                   timeout=300)
    log = (build / "verification.log").read_text(errors="replace")
    assert not re.search(r"^! ", log, re.M), log[-3000:]
    assert (build / "verification.pdf").exists()


def test_graphs_that_stress_the_evaluators_get_their_own_verdicts():
    """A residual nested 1500 deep, a claim that lowers the recursion limit of its tracing interpreter, a dict
    subclass that shows a true residual while it holds a false one, a generator claim: the false ones fail, the
    true one passes, the ill-formed ones are refused (`error`), under exact and modular."""
    ids = ("b1-deep-false", "b1-deep-true", "b1-recursion-limit", "b1-dict-subclass", "b1-generator")
    got = verdicts_each("s67/review/b1_eval.py", ("exact", "modular"), ids=ids)
    for method in ("exact", "modular"):
        v = got[method]
        assert v["b1-deep-false"] == "fails" and v["b1-recursion-limit"] == "fails", (method, v)
        assert v["b1-deep-true"] in PASSING, (method, v)
        assert v["b1-dict-subclass"] == "error" and v["b1-generator"] == "error", (method, v)
