"""The renderers, on hand-made Result records."""
from __future__ import annotations

import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

from stiefelsym.report import (case_name, render_junit, render_latex, render_markdown,
                               render_summary)
from stiefelsym.results import CheckOutcome, Result, dump_results, load_results

NASTY = r"50% of #cases & ~x^2 {b} \foo <a|b> under_score, Božidar Jovanović, dΦ/dt = [XXᵀ, A] ≤ ½"

STATEMENTS = {
    "prep": r"\frac{d}{dt}\Phi=[XX^T,A],\qquad \frac{d}{dt}(XX^T)=[\Phi,XX^T]",
    "casimirs": r"\tr(\Phi^{2k}),\ \diag(a_1,\dots,a_n),\ \ad_\xi,\ \Ad_g,\ \rank L=\ddim,"
                r"\ \pr_{\mathfrak{so}(n)},\ \Span\{\langle\xi,\eta\rangle\},\ \mathbb R,\ \mathcal O",
    "orbit": r"2l=\begin{cases}\tfrac{n(n-1)}2-\left[\tfrac n2\right],&n\le2r+1\\ 2r(n-r-1),&n>2r+1\end{cases}",
    "aligned": r"H &= \tfrac12\tr(P^TP) \\ &= \tfrac12\langle\Phi,\Phi\rangle",
    "lines": r"\dot X = P \\ \dot P = -XP^TP",
    "unbalanced": r"\frac{1}{2",
    "unicode": r"\dot Φ = [XXᵀ, A] + λ·𝔄",
}


def result(claim: str, n: int | None, r: int | None, method: str, verdict: str, *,
           section: str = "5", expected: bool | None = None, variant: str | None = None,
           **extra) -> Result:
    fields = dict(
        claim=claim, paper=[claim.replace("-", "_"), "extra_label"], section=section, kind="id",
        title=f"The claim {claim}: {NASTY}.", statement=STATEMENTS.get(claim, STATEMENTS["prep"]),
        n=n, r=r, method=method, verdict=verdict,
        expected=verdict in ("proved", "checked", "numeric") if expected is None else expected,
        seconds=0.25, seed=None if method in ("exact", "free") else 0,
        certificate="2 independent points over GF(2^61-1); numerator degree <= 39",
        false_pass_bound=2.9e-34 if verdict == "checked" else None,
        reductions=["rational parametrization X = (I - S)(I + S)^{-1}; dense in T*V_{n,r}"],
        rerun=f"stiefelsym verify {claim} --size {n},{r} --method {method} --seed 0",
        variant=variant)
    fields.update(extra)
    return Result(**fields)


WITNESS = {"seed": 0, "trial": 1, "field": "GF(2305843009213693951)", "check": "dPhi/dt",
           "entry": "(1, 2)", "value": "3/7", "point": {"a_1": "1/2", "S_12": "-3", "W#1": "x_1"}}


@pytest.fixture
def results() -> list[Result]:
    return [
        result("prep", 4, 2, "modular", "checked"),
        result("prep", None, None, "free", "proved", derivation=[
            "\\paragraph{dPhi/dt}\n\\[\\begin{aligned}R &= X^TX - 1 \\\\\n\\operatorname{nf}(R) &= 0"
            "\\end{aligned}\\]\nusing\n\\begin{itemize}\n  \\item $X^TX \\to 1$ (cond\\_XP)\n"
            "\\end{itemize}"]),
        result("casimirs", 3, 1, "exact", "proved", section="6"),
        result("orbit", 3, 2, "float", "numeric", section="2"),
        result("aligned", 2, 1, "rational", "inconclusive", section="3",
               message="every one of 8 sampled points was degenerate"),
        result("lines", 2, 2, "exact", "error", section="3", message="ZeroDivisionError: 1/0"),
        result("unbalanced", 3, 1, "modular", "checked", section=""),
        result("unicode", 3, 1, "modular", "checked", section="7"),
        # a printed formula that fails, with two candidate corrections
        result("neumann-lax", 3, 1, "rational", "fails", section="5", witness=WITNESS,
               residual="(1, 2) = 3/7",
               checks=[CheckOutcome("dL/dt", "nonzero", "entry (1, 2) = 3/7", 12),
                       CheckOutcome("trace", "zero")]),
        result("neumann-lax", 4, 2, "rational", "fails", section="5", witness=WITNESS),
        result("neumann-lax", 3, 1, "rational", "checked", section="5",
               variant=r"sign of $\lambda A$ flipped"),
        result("neumann-lax", 4, 2, "rational", "checked", section="5",
               variant=r"sign of $\lambda A$ flipped"),
        result("neumann-lax", 3, 1, "rational", "fails", section="5", expected=True,
               variant="M transposed"),
    ]


CLAIMS = ("prep", "casimirs", "orbit", "aligned", "lines", "unbalanced", "unicode", "neumann-lax")


# --------------------------------------------------------------------------- Markdown

def test_markdown_has_every_claim_in_its_section(results):
    md = render_markdown(results, {"command": "stiefelsym verify --seed 0", "seed": 0})
    for cid in CLAIMS:
        assert f"### `{cid}`" in md
    headings = re.findall(r"^## (.*)$", md, re.M)
    assert headings == ["How to reproduce", "What the verdicts mean", "Summary", "§2", "§3", "§5",
                        "§6", "§7", "Claims outside the paper's sections", "Errata"]
    assert md.index("### `orbit`") < md.index("### `aligned`") < md.index("### `prep`")


def test_markdown_reproduce_and_vocabulary(results):
    meta = {"command": "stiefelsym verify --seed 3", "seed": 3, "date": "2026-11-21 10:00:00 UTC",
            "versions": {"python": "3.11.7", "sympy": "1.14.0"}, "commit": "abc123"}
    md = render_markdown(results, meta)
    assert "```sh\nstiefelsym verify --seed 3\n```" in md
    assert "Seed 3" in md and "sympy 1.14.0" in md and "abc123" in md
    for verdict in ("proved", "checked", "numeric", "fails", "inconclusive", "undecided", "error"):
        assert f"- **{verdict}**:" in md
    assert "Schwartz–Zippel" in md


def test_markdown_tables_hold_size_method_verdict_time_bound_seed(results):
    md = render_markdown(results)
    assert "| (4,2) | modular | checked | 0.25 s | 2 independent points over GF(2^61-1); " \
           "numerator degree \\<= 39 | 0 | 2.9e-34 |" in md
    assert "| all n, r | free | proved | 0.25 s |" in md
    assert "| (2,2) | exact | **error** (UNEXPECTED) |" in md
    assert "ZeroDivisionError: 1/0" in md


def test_markdown_summary_counts_verdicts_per_claim(results):
    md = render_markdown(results)
    summary = md[md.index("## Summary"):md.index("## §2")]
    header = "| claim | paper | § | kind | all n, r | proved | checked | numeric | fails | inconclusive | error | status |"
    assert header in summary
    assert "| `prep` | (prep), (extra\\_label) | 5 | id | proved |  | 1 |  |  |  |  | as expected |" in summary
    assert "| `neumann-lax` | (neumann\\_lax), (extra\\_label) | 5 | id | – |  |  |  | 2 |  |  | **2 unexpected** |" in summary


def test_markdown_statements_in_math_with_operators_expanded(results):
    md = render_markdown(results)
    assert r"$\frac{d}{dt}\Phi=[XX^T,A],\qquad \frac{d}{dt}(XX^T)=[\Phi,XX^T]$" in md
    assert r"\operatorname{tr}(\Phi^{2k})" in md and r"\operatorname{span}\{" in md
    assert "$$\n" + r"2l=\begin{cases}" in md


def test_errata_lists_failing_claim_with_witness_and_corrections(results):
    md = render_markdown(results)
    errata = md[md.index("## Errata"):]
    assert "### `neumann-lax`" in errata
    assert "Fails at: (3,1) rational, (4,2) rational." in errata
    assert "Witness at size (3,1), method rational, seed 0:" in errata
    assert "- entry: `(1, 2)`" in errata and "- value: `3/7`" in errata
    assert "- point: `a_1 = 1/2; S_12 = -3; W#1 = x_1`" in errata
    assert "- check dL/dt: nonzero, entry (1, 2) = 3/7" in errata
    assert "- rerun: `stiefelsym verify neumann-lax --size 3,1 --method rational --seed 0`" in errata
    assert r"| sign of $\lambda A$ flipped | **verified** | (3,1) rational: checked (p ≤ 2.9e-34), " \
           "(4,2) rational: checked (p ≤ 2.9e-34) |" in errata
    assert "| M transposed | rejected | (3,1) rational: fails |" in errata
    for cid in CLAIMS[:-1]:  # only the failing claim is an erratum
        assert f"### `{cid}`" not in errata


def test_no_errata_when_nothing_fails(results):
    md = render_markdown([r for r in results if r.claim != "neumann-lax"])
    assert md.rstrip().endswith("No statement failed as printed.")


def test_long_witness_is_cut_and_points_to_results_json():
    w = {"point": {f"p{i}": f"{i}/{i + 1}" for i in range(200)}}
    md = render_markdown([result("big", 5, 2, "rational", "fails", witness=w)])
    assert "(in full in results.json)" in md


def test_markdown_escapes_running_text(results):
    md = render_markdown(results)
    assert r"under\_score" in md and r"\<a|b\>" in md


def test_render_from_round_trip_json(results, tmp_path):
    meta = {"command": "stiefelsym verify", "seed": 0}
    (tmp_path / "results.json").write_text(dump_results(results, meta))
    meta2, back = load_results(tmp_path / "results.json")
    assert render_markdown(back, meta2) == render_markdown(results, meta)
    assert render_latex(back, meta2) == render_latex(results, meta)


def test_dimension_free_derivations_go_into_latex():
    good = "\\paragraph{dPhi}\n\\[R = X^TX - I\\]\nusing\n\\begin{itemize}\n\\item $X^TX \\to I$\n\\end{itemize}"
    bad = "\\paragraph{oops}\n\\[R = \\frac{1}{2\\]"
    r = result("prep", None, None, "free", "proved", derivation=[good, bad])
    tex = render_latex([r])
    assert "Dimension-free proof (free)" in tex
    assert good in tex and bad not in tex
    assert r"\texttt{\textbackslash{}paragraph\{oops\}" in tex
    assert "derivation (residual, rules applied, normal form) is in `verification.tex`" in \
        render_markdown([r])


def test_empty_results_render():
    assert "No statement failed as printed." in render_markdown([])
    assert r"\end{document}" in render_latex([])
    assert render_summary([]) == "summary: no runs\n"


# --------------------------------------------------------------------------- terminal, JUnit

def test_summary_counts_verdicts_by_method(results):
    text = render_summary(results)
    lines = text.splitlines()
    assert lines[0] == "summary: 8 claims, 13 runs: 9 as expected, 4 unexpected"
    assert lines[1].split() == ["method", "proved", "checked", "numeric", "fails", "inconclusive",
                                "undecided", "error", "total"]
    assert lines[2].split() == ["modular", "-", "3", "-", "-", "-", "-", "-", "3"]
    assert "    rerun: stiefelsym verify lines --size 2,2 --method exact --seed 0" in lines


def test_junit_one_testcase_per_result_failures_for_unexpected(results):
    root = ET.fromstring(render_junit(results))
    cases = root.findall(".//testcase")
    assert len(cases) == len(results)
    failed = {c.get("name") for c in cases if c.find("failure") is not None}
    assert failed == {case_name(r) for r in results if not r.expected}
    assert "prep[n=4,r=2]-modular" in {c.get("name") for c in cases}
    assert root.get("failures") == "4"


def test_junit_survives_control_characters():
    r = result("prep", 3, 1, "modular", "error", message="bad \x00\x07 bytes")
    assert ET.fromstring(render_junit([r])).find(".//failure") is not None


# --------------------------------------------------------------------------- pdflatex

def test_latex_report_compiles_with_pdflatex(results, tmp_path):
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed (Debian: texlive-latex-base texlive-latex-recommended)")
    meta = {"title": "Verification of claims_file #1 & 100% of {them}",
            "command": "stiefelsym verify --claims my_claims.py --seed 0 --report-dir out_dir",
            "seed": 0, "date": "2026-11-21 10:00:00 UTC", "platform": "Linux-6.1-x86_64",
            "versions": {"python": "3.11.7", "python-flint": "0.9.0"},
            "sections": {"5": "Neumann systems & friends"}}
    (tmp_path / "verification.tex").write_text(render_latex(results, meta), encoding="utf-8")
    for _ in range(2):  # longtable settles its column widths on the second pass
        proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                               "-no-shell-escape", "verification.tex"], cwd=tmp_path,
                              capture_output=True, text=True, timeout=120,
                              stdin=subprocess.DEVNULL)
        assert proc.returncode == 0, proc.stdout[-3000:]
    log = (tmp_path / "verification.log").read_text(errors="replace")
    assert "Undefined control sequence" not in log
    assert "Missing character" not in log
    assert ".600pk" not in log, "a bitmap font was generated: some glyph is not in a Type 1 font"
    assert (tmp_path / "verification.pdf").stat().st_size > 10_000


def test_latex_report_of_real_catalog_runs_compiles(tmp_path):
    """The catalog's own results (statements, certificates, dimension-free derivations, errata)."""
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed (Debian: texlive-latex-base texlive-latex-recommended)")
    from stiefelsym.claims import Size, load_catalog
    from stiefelsym.runner import verify
    cat = load_catalog()
    ids = ["euclidean-invariance", "normal-flow", "jensen-invariance", "invariant-metrics",
           "adjoint-orbit-regularity", "metric-flow"]
    results = verify([cat.get(i) for i in ids], sizes=[Size(4, 1), Size(4, 2), Size(3, 2)],
                     methods=("auto", "free", "float"), seed=0)
    assert any(r.derivation for r in results) and any(r.verdict == "fails" for r in results)
    (tmp_path / "verification.tex").write_text(render_latex(results, {"seed": 0}), encoding="utf-8")
    for _ in range(2):
        proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                               "-no-shell-escape", "verification.tex"], cwd=tmp_path,
                              capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
        assert proc.returncode == 0, proc.stdout[-3000:]
    assert "Undefined control sequence" not in (tmp_path / "verification.log").read_text(errors="replace")
