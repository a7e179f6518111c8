"""Stop 73: the review's findings (tests/adversary/s73/review, FINDINGS.md).  See tests/adversary/README.md, Stop 73.
No wrong verdict was found; the replays keep the two defects that were fixed: a report that did not compile when a
claim's text had a long run of blanks (D1), and a correction dropped as vacuous because its left side vanishes at the
smallest size only (D2)."""
import shutil
import subprocess

from pathlib import Path

from adversary_cli import cli

REVIEW = Path(__file__).parent / "s73" / "review"


def test_a_long_run_of_blanks_in_a_claims_text_leaves_the_report_compilable(tmp_path):
    """D1: short_lines cut inside a run of 4,500 blanks of a statement, leaving a line of blanks (a paragraph break
    inside $\\displaystyle ...$): pdflatex stopped with "Missing $ inserted"."""
    out = tmp_path / "o"
    run = cli("verify", "--claims", str(REVIEW / "tex_spaces.py"), "--method", "exact", "--size", "2,1",
              "--jobs", "1", "--report-dir", str(out))
    assert run.returncode == 0, run.stderr[-2000:]
    for name in ("verification.tex", "verification-runs.tex"):
        lines = (out / name).read_text().split("\n")
        body = lines[lines.index(r"\begin{document}"):]
        # an empty line only where the document means a paragraph: never a line of blanks
        assert not any(ln and not ln.strip(" ") for ln in body)
    if shutil.which("pdflatex"):
        for name in ("verification.tex", "verification-runs.tex"):
            tex = subprocess.run(["pdflatex", "-halt-on-error", "-interaction=nonstopmode", name], cwd=out,
                                 capture_output=True, text=True, timeout=300)
            assert tex.returncode == 0, tex.stdout[-2000:]


def test_a_correction_whose_left_side_vanishes_at_the_smallest_size_only_is_offered():
    """D2: (tr Ψ²)² − 2 tr Ψ⁴ = 0 holds at r <= 3 (the claim's sizes) and is the one-step correction of the false
    (tr Ψ²)² − 2 tr Ψ⁴ = 1; its left side vanishes at (1,1) only (Ψ = 0), where the vacuity filter looked."""
    run = cli("mutate", "s73-psi-quartic", "--claims", str(REVIEW / "corrections_r.py"), "--corrections",
              "--jobs", "1")
    assert "1 of 15 candidates pass" in run.stdout + run.stderr, (run.stdout + run.stderr)[-2000:]
    assert "tr(ΨΨ)tr(ΨΨ) − 2tr(ΨΨΨΨ) − 1 → tr(ΨΨ)tr(ΨΨ) − 2tr(ΨΨΨΨ)" in run.stdout + run.stderr
