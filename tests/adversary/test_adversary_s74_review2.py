"""Stop 74 second review (tests/adversary/s74/review2, FINDINGS.md): replays of the defects found, all closed (a
residual's text is now read by a parser of the notebook's own, nothing evaluated as code; an entity-like & and any
text with a backslash or a $ that is not mathematics are escaped or shown as code; a float or ball pass at a hard
point is looked at at the hard case's exact points mod p).  No wrong verdict was found.  D1: Result.residual_sympy() runs code (and hangs) on a hand-edited record:
fullwidth attribute names pass notebook._sympy_text's renaming of ASCII names, and Expr.equals sympifies a string.
D2: HTML character references (&#36;, &#92;) in a claim's words reach the Markdown report and the Jupyter display
unescaped: the rendered text holds $\\href{...}{...}$ for MathJax.  D3: under --hard large-momenta the float method
leaves a false claim `undecided` that rational, modular and ball refute at the same hard case (the exact confirmation
of a float pass at the hard point, which the guide promises, never runs)."""
import os
import subprocess
import sys


from pathlib import Path

from adversary_cli import cli

REVIEW2 = Path(__file__).parent / "s74" / "review2"
MARK = "/tmp/hE_residual_sympy_pwned"


def test_residual_sympy_of_a_hand_edited_record_runs_no_code():
    if os.path.exists(MARK):
        os.remove(MARK)
    run = subprocess.run([sys.executable, str(REVIEW2 / "residual_exec.py.in")], capture_output=True, text=True,
                         timeout=120)
    assert "Traceback" not in run.stderr, run.stderr[-2000:]
    assert not os.path.exists(MARK), run.stdout


def test_residual_sympy_of_a_hand_edited_record_returns():
    run = subprocess.run([sys.executable, str(REVIEW2 / "residual_hang.py.in")], capture_output=True, text=True,
                         timeout=120)
    assert "HANG" not in run.stdout, run.stdout


def test_character_references_of_a_claims_words_make_no_mathjax_command(tmp_path):
    out = tmp_path / "o"
    run = cli("verify", "r2-h-entities", "--claims", str(REVIEW2 / "hostile_words.py"), "--method", "rational",
              "--size", "2,1", "--jobs", "1", "--report-dir", str(out))
    assert run.returncode == 0, run.stderr[-2000:]
    md = (out / "verification.md").read_text()
    assert "&#92;href" not in md and "&#36;&#92;" not in md, "a character reference of a claim's words"


def test_float_refutes_at_large_momenta_what_modular_refutes_there():
    verdicts = {}
    for method in ("modular", "float"):
        run = cli("verify", "r2-m-flow-false", "--claims", str(REVIEW2 / "momenta_paths.py"), "--size", "3,2",
                  "--method", method, "--hard", "large-momenta", "--jobs", "1", "--no-report")
        line = next(ln for ln in run.stdout.splitlines() if ln.startswith("r2-m-flow-false"))
        verdicts[method] = line.split(": ", 1)[1].split()[0]
    assert verdicts["modular"] == "fails"
    assert verdicts["float"] == "fails", verdicts
