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


# --------------------------------------------------------------------------- the second review (s76/review2)

def test_a_change_whose_text_is_printed_where_nothing_changed_names_its_places(tmp_path):
    """Review 2, item 3: the check prints as XᵀP + (XᵀP)ᵀ − 2Iᵣ + XᵀPλ + (Pλ)ᵀX, and the correction changes the
    shared K = XᵀP only.  "XᵀP → XᵀX" read literally also rewrites XᵀPλ, a false statement (the claim
    s76r2-literal-reading fails); the change now names the places it is made at."""
    f = HERE / "review2" / "notation_partial.py"
    run = cli("verify", "--claims", str(f), "--method", "exact", "--jobs", "1", "--report-dir", str(tmp_path))
    md = (tmp_path / "verification.md").read_text(encoding="utf-8")
    assert "| in res, at the 1st and 2nd of its 3 places: XᵀP → XᵀX | K = XᵀX in place of K = XᵀP |" in md, \
        run.stdout[-2000:]
    verdicts = {line.split()[0] + line.split()[1]: line for line in run.stdout.splitlines() if " exact: " in line}
    assert "fails" in verdicts["s76r2-literal-reading(3,2)"] and "proved" in verdicts["s76r2-actual-correction(3,2)"]


def test_scripts_in_a_users_words_are_set_as_they_mean_and_the_report_compiles(tmp_path):
    """Review 2, item 4: f^(k) keeps its parentheses (an order of derivative, not a power), d^10X/dt^10 is set
    whole, and an accented letter after a caret stays text (pdflatex stopped on it)."""
    import shutil
    import subprocess
    f = HERE / "review2" / "words.py"
    cli("verify", "--claims", str(f), "--method", "exact", "--jobs", "1", "--report-dir", str(tmp_path))
    md = (tmp_path / "verification.md").read_text(encoding="utf-8")
    assert "d¹⁰X/dt¹⁰" in md and "f⁽ᵏ⁾" in md and "fᵏ" not in md
    if shutil.which("pdflatex"):
        for _ in range(2):
            proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "verification.tex"],
                                  cwd=tmp_path, capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
            assert proc.returncode == 0, proc.stdout[-2000:]


# --------------------------------------------------------------------------- the routes of issue 20 (s76/routes)

def test_a_claim_found_not_deterministic_with_symbolic_sizes_gets_no_verdict_at_a_size():
    """Routes D1 (class 4): the claim's first call gives XXᵀ − Iₙ, every later call XᵀX − Iᵣ.  Its two traces with
    symbolic sizes differ; it was then traced at (3,2) by its later calls, which agree, and exact said `proved`.
    A claim found not deterministic is now `error` under every method and at every size."""
    f = HERE / "routes" / "c4_counter_phase.py"
    for method in ("exact", "modular", "float", "free"):
        args = ["verify", "--claims", str(f), "--method", method, "--jobs", "1"]
        run = cli(*args, *([] if method == "free" else ["--size", "3,2"]))
        lines = [ln for ln in run.stdout.splitlines() if ln.startswith("c4-counter")]
        assert lines and all(": error " in ln and "NotDeterministic" in ln for ln in lines), run.stdout[-2000:]


def test_a_claims_file_class_named_as_an_engine_exception_is_not_replayed_as_one():
    """Routes D2 (class 3): a class of the file's own named MemoryError was taken for the method's memory budget
    (exact: inconclusive, "exceeded the memory budget"), and one named TraceRefused for the engine's refusal.  A
    recorded exception is replayed as the builtin or the engine's class only when it is that class."""
    f = HERE / "routes" / "c3_exceptions.py"
    run = cli("verify", "--claims", str(f), "c3-fake-memoryerror", "c3-fake-refusal-phase", "--method", "exact",
              "--method", "modular", "--size", "3,2", "--jobs", "1")
    lines = [ln for ln in run.stdout.splitlines() if ln.startswith("c3-")]
    assert len(lines) == 4 and all(": error " in ln and "a class of the claims file's own" in ln for ln in lines), \
        run.stdout[-2000:]
    assert "memory budget" not in run.stdout


def test_a_fraction_made_by_hand_is_refused_with_its_reason():
    """Routes D3, D4 (class 2): Fractions made by hand (a numerator that lies about being 0, a zero, negative or
    unreduced denominator) were refused with the wrong reason ("no graph at the sizes", "not deterministic")."""
    f = HERE / "routes" / "c2_disguised_constants.py"
    ids = ["c2-fraction-lying-zero", "c2-fraction-zero-den", "c2-fraction-unnormalised", "c2-fraction-negative-den"]
    run = cli("verify", "--claims", str(f), *ids, "--method", "exact", "--size", "3,2", "--jobs", "1")
    lines = [ln for ln in run.stdout.splitlines() if ln.startswith("c2-")]
    assert len(lines) == 4 and all(": error " in ln and "not in lowest terms" in ln for ln in lines), run.stdout[-2000:]


def test_each_check_names_its_own_places_of_a_change(tmp_path):
    """The own attempt after the review: one correction of the shared K = XᵀP in three checks, two of which also
    print XᵀP where nothing changes.  Each check says its own places (the collapsed list could carry one check's)."""
    own = HERE / "own" / "mixed_places.py"
    cli("verify", "--claims", str(own), "--method", "exact", "--jobs", "1", "--report-dir", str(tmp_path))
    md = (tmp_path / "verification.md").read_text(encoding="utf-8")
    assert ("| in a, at the 1st and 2nd of its 3 places; b, at the 1st and 2nd of its 3 places; c: XᵀP → XᵀX |"
            in md), md[-3000:]
