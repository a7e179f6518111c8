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


HIDDEN = Path(__file__).parent / "s73" / "hidden"


def test_a_false_claim_of_a_claims_file_is_refuted_at_a_point_before_the_symbolic_charts():
    """The hidden round's usability defect 1: a false claim on the complex point of W(3, 2) (Λ(ZU) = UΛU*) ran the
    exact method's equivariant chart out of memory after 74 s (`inconclusive`), where the rational method refutes it
    in a fraction of a second.  A claims file's claim is now evaluated at the seed's first exact rational point of T*V
    before any symbolic chart."""
    run = cli("verify", "--claims", str(HIDDEN / "negatives.py"), "n73-complex-lambda-order", "--size", "3,2",
              "--method", "exact", "--jobs", "1", "--no-report", "--timeout", "60")
    line = next(ln for ln in run.stdout.splitlines() if ln.startswith("n73-complex-lambda-order"))
    assert "exact: fails" in line and "witness" in line, run.stdout + run.stderr[-2000:]


def test_an_exact_attempt_that_runs_out_is_followed_by_the_point(tmp_path):
    """A symbolic attempt that ran out of its time or memory before the point was tried (a chart that does not try
    it first) is followed by the point, in a process of its own: `fails` with an exact witness for a false claim,
    nothing for a true one (the attempt's verdict stands)."""
    import time

    from stiefelsym import load_claims_file
    from stiefelsym.methods.fixed_size import _refuted_after_the_attempt
    reg = load_claims_file(str(HIDDEN / "negatives.py"))
    false = reg.get("n73-complex-lambda-order")
    res = _refuted_after_the_attempt(false, 3, 2, 0, None, time.perf_counter(), 120.0)
    assert res is not None and res.verdict == "fails" and res.method == "exact" and res.witness
    # (its certificate names no budget: a record checked again under another budget says the same)
    assert "ran out of its time or memory" in res.certificate and " s" not in res.certificate.split("(")[-1]
    true = load_claims_file(str(HIDDEN / "claims.py")).get("h73-complex-u-r-symmetry")
    assert _refuted_after_the_attempt(true, 3, 2, 0, None, time.perf_counter(), 120.0) is None
    # no time left (the attempt used 4/3 of its budget already): the point is not tried
    assert _refuted_after_the_attempt(false, 3, 2, 0, None, time.perf_counter() - 200.0, 120.0) is None


def test_the_exact_method_gets_the_runs_budget_and_autos_attempt_is_capped(monkeypatch):
    """`--method exact` gets 0.7 of `--timeout` (the guide: only auto's attempt is capped at 120 s); it had
    min(120 s, timeout), so a true claim needing 150 s was `inconclusive` under `--timeout 300`.  The point tried
    after an attempt that ran out ends by 4/3 of the attempt's budget: inside the run's."""
    from stiefelsym.methods import fixed_size
    from stiefelsym.run import runner
    seen = []
    monkeypatch.setattr(fixed_size, "run_exact_isolated", lambda c, n, r, seed, func, limit, in_worker: seen.append(limit))
    runner._exact_runner(True, 300.0, capped=False)(None, 3, 2, 0)
    runner._exact_runner(True, 150.0)(None, 3, 2, 0)
    runner._exact_runner(True, 60.0)(None, 3, 2, 0)
    assert seen == [210.0, fixed_size.EXACT_TIME_LIMIT, 60.0]
    assert runner.EXACT_SHARE * fixed_size.AFTER_ATTEMPT_END < 1


REVIEW2 = Path(__file__).parent / "s73" / "review2"


def test_a_claim_decided_in_groups_of_checks_is_refuted_at_the_point_first():
    """The second review (D1): a claims file's claim whose checks are proved group by group skipped the point
    tried first, so the false Λ(ZU) = UΛU* beside checks that read coordinates was `inconclusive` after 49 s."""
    run = cli("verify", "--claims", str(REVIEW2 / "groups.py"), "rv2-complex-lambda-order-grouped", "--size", "3,2",
              "--method", "exact", "--jobs", "1", "--no-report", "--timeout", "60")
    line = next(ln for ln in run.stdout.splitlines() if ln.startswith("rv2-complex-lambda-order-grouped"))
    assert "exact: fails" in line and "witness" in line, run.stdout + run.stderr[-2000:]


def test_an_attempt_stopped_by_its_own_deadline_is_followed_by_the_point(tmp_path):
    """The second review (D2, D3): the catalog's manakov-dual-lax at (8,8) under --timeout 10: the symbolic attempt
    reached its own deadline (no child was stopped), and no point followed: `inconclusive` where the rational method
    refutes it in 0.4 s.  Now `fails` with the point's witness, within the run's budget; and `check` runs the record
    again under the file's budget and accepts it (it ran it under 120 s and rejected the certificate)."""
    out = tmp_path / "o"
    run = cli("verify", "manakov-dual-lax", "--size", "8,8", "--method", "exact", "--jobs", "1", "--timeout", "10",
              "--report-dir", str(out))
    line = next(ln for ln in run.stdout.splitlines() if ln.startswith("manakov-dual-lax (8,8)"))
    assert "exact: fails" in line, run.stdout + run.stderr[-2000:]
    check = cli("check", str(out / "results.json"))
    assert check.returncode == 0 and "0 rejected" in check.stdout, check.stdout + check.stderr[-2000:]


def test_own_attempt_on_the_exact_methods_order():
    """Stop 73's own attempt (s73/own/exact_order.py): a residual that vanishes at the chart's origin only (X₁₁ = 1),
    a nonvanishing claim whose residual vanishes on V, and a true twin, under exact and auto with the run's budget
    and with a budget of 1 s: no false claim passes, the true one is never refuted."""
    for budget in ("300", "1"):
        run = cli("verify", "--claims", str(Path(__file__).parent / "s73" / "own" / "exact_order.py"),
                  "--size", "3,2", "--size", "4,4", "--method", "exact", "--method", "auto", "--jobs", "1",
                  "--no-report", "--timeout", budget)
        lines = [ln for ln in run.stdout.splitlines() if ln.startswith("s73-own-")]
        assert len(lines) == 12, run.stdout + run.stderr[-2000:]
        for ln in lines:
            verdict = ln.split(": ")[1].split()[0]
            if ln.startswith("s73-own-true"):
                assert verdict in ("proved", "checked", "inconclusive"), ln
            else:
                assert verdict in ("fails", "inconclusive", "undecided"), ln
