"""The renderers, on hand-made Result records."""
from __future__ import annotations

import json
from pathlib import Path
import re
from dataclasses import replace
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

from stiefelsym.reports.report import (_tex_change, case_name, grouped_reruns, quoted_value_words, render_junit, render_latex, render_markdown,
                               render_mutation_markdown, render_summary)
from stiefelsym.results import CheckOutcome, Result, dump_results, load_results

PAPER = Path(__file__).resolve().parents[2] / "shared" / "paper" / "fedorov-jovanovic-stiefel.tex"

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
    assert headings == ["What the verdicts mean", "Errata", "Summary", "§2", "§3", "§5", "§6", "§7",
                        "Claims outside the paper's sections", "How to reproduce"]
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
           "numerator degree \\<= 39 | 0 | 2.9·10⁻³⁴ |" in md
    assert "| all n, r | free | proved | 0.25 s |" in md
    assert "| (2,2) | exact | **error** (UNEXPECTED) |" in md
    assert "ZeroDivisionError: 1/0" in md


def test_markdown_summary_counts_verdicts_per_claim(results):
    md = render_markdown(results)
    summary = md[md.index("## Summary"):md.index("## §2")]
    header = "| claim | paper | § | kind | all n, r | proved | checked | numeric | fails | inconclusive | error | status |"
    assert header in summary
    assert "| `prep` | (6) §5 [prep], (extra\\_label) | 5 | id | proved |  | 1 |  |  |  |  | as expected |" in summary
    assert "| `neumann-lax` | (neumann\\_lax), (extra\\_label) | 5 | id | – |  |  |  | 2 |  |  | **2 unexpected** |" in summary


def test_markdown_statements_in_math_with_operators_expanded(results):
    md = render_markdown(results)
    assert r"$\frac{d}{dt}\Phi=[XX^T,A],\qquad \frac{d}{dt}(XX^T)=[\Phi,XX^T]$" in md
    assert r"\operatorname{tr}(\Phi^{2k})" in md and r"\operatorname{span}\{" in md
    assert "$$\n" + r"2l=\begin{cases}" in md


def test_errata_lists_failing_claim_with_witness_and_corrections(results):
    md = render_markdown(results)
    errata = md[md.index("## Errata"):md.index("## Summary")]
    assert "### `neumann-lax`" in errata
    assert "Failing runs: (3,1) rational, (4,2) rational." in errata
    assert "Witness at size (3,1), method rational, seed 0:" in errata
    assert "- entry: `(1, 2)`" in errata and "- value: `3/7`" in errata
    assert "- point: `a_1 = 1/2; S_12 = -3; W#1 = x_1`" in errata
    assert "- check dL/dt: residual nonzero, entry (1, 2) = 3/7" in errata
    assert "- rerun: `stiefelsym verify neumann-lax --size 3,1 --method rational --seed 0`" in errata
    assert "Candidate corrections: the claim as printed was run at 2 sizes (3,1), (4,2)" in errata
    assert r"| sign of $\lambda A$ flipped | **verified at the computed sizes** | verified at all 2 computed sizes by rational " \
           "(p ≤ 2.9·10⁻³⁴) |" in errata
    assert "| M transposed | rejected | fails at (3,1) by rational |" in errata
    for cid in CLAIMS[:-1]:  # only the failing claim is an erratum
        assert f"### `{cid}`" not in errata


def test_no_errata_when_nothing_fails(results):
    md = render_markdown([r for r in results if r.claim != "neumann-lax"])
    assert "## Errata\n\nNo statement failed as printed.\n\n## Summary" in md


def test_long_witness_is_cut_and_points_to_results_json():
    w = {"point": {f"p{i}": f"{i}/{i + 1}" for i in range(200)}}
    md = render_markdown([result("big", 5, 2, "rational", "fails", witness=w)])
    assert "(in full in results.json)" in md


def test_markdown_escapes_running_text(results):
    md = render_markdown(results)
    # (s74: words with a backslash that is not mathematics, \foo here, are shown verbatim as code, which no reader
    # takes for math or HTML; the words around them, and elsewhere the running text, are escaped text)
    assert "50% of #cases & ~x^2 {b} `\\foo` \\<a" in md
    outside = re.sub(r"`[^`]*`", "", md)
    assert "<a|b>" not in outside and "<a\\|b>" not in outside
    plain = render_markdown([replace(r, title=r.title.replace("\\foo", "foo")) for r in results])
    assert r"under\_score" in plain and r"\<a|b\>" in plain


def test_only_the_words_with_a_backslash_are_code_and_no_entity_closes_a_link():
    """A slip quoting the paper's source keeps its words as text, the source's token alone in a code span; a
    bracket before a parenthesis (which would close a link's text) is set apart by a space, not written as an
    entity that the raw file would show."""
    from stiefelsym.reports.report import _md_escape
    text = "Printed: in the source, “the Neumann flows ({\\ref{No}) are”, which prints (3). Meant: the brace closed."
    assert _md_escape(text) == ("Printed: in the source, “the Neumann flows `({\\ref{No})` are”, which prints (3). "
                                "Meant: the brace closed.")
    out = _md_escape("[Φ, Iₙ − XXᵀ](Iₙ − XXᵀ) and [a](b) and J[1][2]")
    assert out == "[Φ, Iₙ − XXᵀ] (Iₙ − XXᵀ) and [a] (b) and J[1][2]" and "&#" not in out


def test_render_from_round_trip_json(results, tmp_path):
    meta = {"command": "stiefelsym verify", "seed": 0}
    (tmp_path / "results.json").write_text(dump_results(results, meta))
    meta2, back = load_results(tmp_path / "results.json")
    assert render_markdown(back, meta2) == render_markdown(results, meta)
    assert render_latex(back, meta2) == render_latex(results, meta)


def test_verdicts_and_methods_are_explained_before_the_errata_use_them(results):
    """A referee meets "verified", "by modular", "p <= ..." in the first erratum: the vocabulary
    (verdicts, methods, the bound p, graphs and their digests) comes before it, in both documents."""
    md = render_markdown(results)
    vocabulary, errata = md.index("## What the verdicts mean"), md.index("## Errata")
    assert vocabulary < errata < md.index("### `neumann-lax`")
    for word in ("- **proved**:", "- **modular**:", "**The bound p.**", "**Graphs and digests.**"):
        assert vocabulary < md.index(word) < errata
    tex = render_latex(results)
    vocabulary, errata = tex.index(r"\section*{What the verdicts mean}"), tex.index(r"\section*{Errata}")
    assert tex.index(r"\tableofcontents") < vocabulary < errata
    for word in (r"\item[proved]", r"\item[modular]", r"\paragraph{The bound $p$.}", r"\paragraph{Graphs and digests.}"):
        assert vocabulary < tex.index(word) < errata
    assert tex.count(r"\section*{What the verdicts mean}") == md.count("## What the verdicts mean") == 1


def test_dimension_free_derivations_go_into_latex():
    good = "\\paragraph{dPhi}\n\\[R = X^TX - I\\]\nusing\n\\begin{itemize}\n\\item $X^TX \\to I$\n\\end{itemize}"
    bad = "\\paragraph{oops}\n\\[R = \\frac{1}{2\\]"
    r = result("prep", None, None, "free", "proved", derivation=[good, bad])
    tex = render_latex([r], detail=True)
    assert "Dimension-free proof (free)" in tex
    assert "\\paragraph{dPhi}" in tex and "R = X^TX - I" in tex and bad not in tex
    # the backslash and braces of the typewriter font itself (\textbackslash, \{ are OMS symbols: no cmtt shape)
    assert r"\texttt{\char92{}paragraph\char123{}oops\char125{}" in tex
    assert "derivation (residual, rules applied, normal form) is in `verification-runs.tex`" in \
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
    # an unexpected error is a JUnit <error> (counted under errors), any other unexpected verdict a <failure>
    failed = {c.get("name") for c in cases if c.find("failure") is not None}
    errored = {c.get("name") for c in cases if c.find("error") is not None}
    assert failed == {case_name(r) for r in results if not r.expected and r.verdict != "error"}
    assert errored == {case_name(r) for r in results if not r.expected and r.verdict == "error"}
    assert "prep[n=4,r=2]-modular" in {c.get("name") for c in cases}
    assert int(root.get("failures")) + int(root.get("errors")) == 4
    assert int(root.get("errors")) == len(errored)


def test_junit_survives_control_characters():
    r = result("prep", 3, 1, "modular", "error", message="bad \x00\x07 bytes")
    assert ET.fromstring(render_junit([r])).find(".//error") is not None


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
    from stiefelsym.run.runner import verify
    cat = load_catalog()
    from stiefelsym.methods.witness import attach_small_witnesses
    ids = ["euclidean-invariance", "normal-flow", "jensen-invariance", "invariant-metrics",
           "adjoint-orbit-regularity", "metric-flow", "double-neumann-dual-lax"]
    results = verify([cat.get(i) for i in ids], sizes=[Size(4, 1), Size(4, 2), Size(3, 2)],
                     methods=("auto", "free", "float"), seed=0)
    assert any(r.derivation for r in results) and any(r.verdict == "fails" for r in results)
    # the errata's witnesses to check by hand: a double-system point (X, Y, Ẋ, Ẏ) in display math
    assert attach_small_witnesses(results, {i: cat.get(i) for i in ids}) >= 1
    # with the list of the paper's typographical slips, as a report of the whole catalog has it
    (tmp_path / "verification.tex").write_text(render_latex(results, {"seed": 0, "whole_catalog": True}),
                                               encoding="utf-8")
    (tmp_path / "runs.tex").write_text(render_latex(results, {"seed": 0}, detail=True), encoding="utf-8")
    for name in ("verification", "runs"):
        for _ in range(2):
            proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                                   "-no-shell-escape", f"{name}.tex"], cwd=tmp_path,
                                  capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
            assert proc.returncode == 0, proc.stdout[-3000:]
        log = (tmp_path / f"{name}.log").read_text(errors="replace")
        assert "Undefined control sequence" not in log
        # no line wider than the page by more than 1 pt (displays shrink, numbers and names break)
        over = [float(x) for x in re.findall(r"Overfull \\hbox \(([0-9.]+)pt too wide\)", log)]
        assert not [x for x in over if x > 1], (name, over)


# --------------------------------------------------------------------------- corrections across sizes

from stiefelsym.reports.report import correction_summary, dimension_checks, group_by_claim  # noqa: E402

ALL12 = [(n, r) for n in range(1, 6) for r in range(1, n + 1)][:12] + []


def _corr(n, r, method, verdict, variant="fix"):
    return result("claim", n, r, method, verdict, variant=variant, expected=verdict in ("proved", "checked"))


def test_correction_verified_at_every_planned_size_is_said_so():
    sizes = [(n, r) for n in range(1, 6) for r in range(1, n + 1) if (n, r) != (5, 1)][:12]
    rs = [_corr(n, r, "exact", "proved") for n, r in sizes]
    status, phrases = correction_summary(rs, sizes)
    assert status == "verified"
    assert phrases == ["verified at all 12 computed sizes by exact"]


def test_correction_verified_at_one_size_of_two_is_not_verified():
    status, phrases = correction_summary([_corr(3, 1, "rational", "checked")], [(3, 1), (4, 2)])
    assert status == "not verified"
    assert "passes at (3,1) by rational (p ≤ 2.9·10⁻³⁴)" in phrases
    assert "not verified at (4,2)" in phrases


def test_correction_failing_somewhere_is_rejected_with_the_sizes():
    rs = [_corr(3, 1, "exact", "proved"), _corr(4, 2, "exact", "fails"), _corr(4, 2, "modular", "checked")]
    status, phrases = correction_summary(rs, [(3, 1), (4, 2)])
    assert status == "rejected"
    assert "fails at (4,2) by exact" in phrases


def test_correction_at_the_claims_only_size():
    status, phrases = correction_summary([_corr(4, 2, "exact", "proved")], [(4, 2)])
    assert status == "verified" and phrases == ["verified at the claim's only size (4,2) by exact"]


def test_errata_table_aggregates_corrections_across_sizes():
    sizes = [(2, 1), (3, 1), (3, 2), (4, 2), (5, 2)]
    rs = [result("orbit", n, r, "exact", "fails", section="2") for n, r in sizes]
    rs += [_corr(n, r, "exact", "proved", variant="n <= 2r + 2") for n, r in sizes]
    rs += [_corr(n, r, "exact", "proved" if n < 4 else "fails", variant="n <= 2r") for n, r in sizes]
    for r in rs:
        r.claim, r.section = "orbit", "2"
    md = render_markdown(rs)
    # the registered words in Markdown: a spaced <= as ≤
    assert "| n ≤ 2r + 2 | **verified at the computed sizes** | verified at all 5 computed sizes by exact |" in md
    assert "| n ≤ 2r | rejected | passes at (2,1), (3,1), (3,2) by exact; fails at (4,2), (5,2) by exact |" in md
    tex = render_latex(rs, detail=True)
    assert r"\textbf{verified at the computed sizes} (verified at all 5 computed sizes by exact)." in tex


# --------------------------------------------------------------------------- rank and count statements

def _rank_results():
    checks = [CheckOutcome("rank ad_Phi", "rank", "rank over the function field Q(chart parameters) = 5 "
                                                  "(paper: 5); two-sided: exact rank of the generic matrix"),
              CheckOutcome("regular", "count-mismatch", "the generic orbit is regular (1) or singular (0): "
                                                        "1 (paper: 0)")]
    point = [CheckOutcome("rank ad_Phi", "rank", "rank 5 at this exact point: generic rank >= 5 (certain)"),
             CheckOutcome("rank ad_Phi", "rank", "rank 5 at this exact point (second trial)")]
    return [result("orbit", 4, 1, "exact", "fails", section="2", checks=checks, expected=True),
            result("orbit", 4, 1, "rational", "checked", section="2", checks=point),
            result("orbit", 3, 1, "rational", "checked", section="2", checks=point)]


def test_rank_and_count_details_are_shown_from_the_most_rigorous_method():
    c = group_by_claim(_rank_results())[0]
    rows = dimension_checks(c)
    assert [(name, size, m) for name, size, m, _, _ in rows] == [
        ("rank ad_Phi", "(3,1)", "rational"), ("rank ad_Phi", "(4,1)", "exact"), ("regular", "(4,1)", "exact")]
    md = render_markdown(_rank_results())
    assert "Rank and count statements" in md
    # the engine's ASCII in the paper's notation: ℚ for Q, ≥ for >=
    assert "| rank ad\\_Phi | (4,1) | exact | as printed | rank over the function field ℚ(chart parameters) = 5" in md
    assert "| regular | (4,1) | exact | **mismatch** | the generic orbit is regular (1) or singular (0): computed 1, printed 0 |" in md
    assert "rank 5 at this exact point: generic rank ≥ 5 (certain)" in md
    tex = render_latex(_rank_results(), detail=True)
    assert r"regular, (4,1) exact: \textbf{mismatch}. the generic orbit is regular (1) or singular (0)" in tex


def test_sizes_at_which_a_check_says_the_same_thing_share_a_row():
    """One row per (check, method, outcome, detail), naming its sizes; a detail that differs keeps its own row."""
    from stiefelsym.reports.report import grouped_dimension_checks
    same = [CheckOutcome("rank ad_Phi", "rank", "rank 0 at an exact rational point (rank >= 0 over the function "
                                                "field); so rank <= 0 (paper: 0)")]
    rs = [result("orbit", n, r, "exact", "proved", section="2", checks=same) for n, r in ((2, 1), (2, 2))] + \
         [result("orbit", 3, 1, "exact", "proved", section="2",
                 checks=[CheckOutcome("rank ad_Phi", "rank", "rank 2 (paper: 2)")])]
    rows = grouped_dimension_checks(group_by_claim(rs)[0])
    assert [(name, sizes) for name, sizes, *_ in rows] == [("rank ad_Phi", "(2,1), (2,2)"), ("rank ad_Phi", "(3,1)")]
    md = render_markdown(rs)
    assert "| rank ad\\_Phi | (2,1), (2,2) | exact | as printed | no lower bound (none is needed: no rank is below 0)" in md


def test_a_scalar_times_itself_is_read_back_as_a_power():
    from stiefelsym.reports.report import traced_words
    assert traced_words("d/dt(λΦ + XXᵀ − λλA) − [Φ − λA, λΦ + XXᵀ − λλA]") == \
        "d/dt(λΦ + XXᵀ − λ²A) − [Φ − λA, λΦ + XXᵀ − λ²A]"
    assert traced_words("tr(μμμA) + λ₁λ₁ + λλᵀ") == "tr(μ³A) + λ₁λ₁ + λλᵀ"


def test_a_meaning_carried_by_the_record_is_shown_in_front():
    r = result("orbit", 4, 1, "exact", "proved", section="2",
               checks=[CheckOutcome("rank ad_Phi", "rank", "rank ... = 5 (paper: 5)")])
    r.checks[0].meaning = "2l"   # a record that carries the Rank's meaning
    assert "| rank ad\\_Phi | (4,1) | exact | as printed | 2l: rank ... = 5 (printed: 5) |" in render_markdown([r])


# --------------------------------------------------------------------------- mutation analysis

def _mutation() -> dict:
    cell = lambda n, r, m, v, msg="": {"n": n, "r": r, "method": m, "verdict": v, "seconds": 0.1, "seed": 0,
                                       "message": msg}
    base = {"claim": "prep", "index": None, "description": "the claim as printed", "lineno": None,
            "operator": "", "source": "", "classification": "baseline", "killed_by": {}, "survived": [],
            "cells": [cell(4, 2, "rational", "checked"), cell(None, None, "free", "proved")]}
    killed = {"claim": "prep", "index": 0, "description": "line 12: swap the operands of @ in `s.X @ s.P.T`",
              "lineno": 12, "operator": "swap", "source": "s.P.T @ s.X", "classification": "killed",
              "killed_by": {"rational": "error", "free": "undecided"}, "survived": [],
              "cells": [cell(4, 2, "rational", "error", "TypeError: R^r x R^n @ R^n x R^r"),
                        cell(None, None, "free", "undecided")]}
    survivor = {"claim": "prep", "index": 1, "description": "line 13: flip the sign of the term `b_1` in `a*b | c`",
                "lineno": 13, "operator": "sign", "source": "a - b", "classification": "survivor",
                "killed_by": {"exact": "fails"}, "survived": ["float", "free"],
                "cells": [cell(4, 2, "exact", "fails", "entry (1,2) = 3/7 & 100% #"),
                          cell(4, 2, "float", "numeric"), cell(None, None, "free", "proved")]}
    equiv = {"claim": "prep", "index": 2, "description": "line 14: remove the transpose in `Lam.T` in `Lam - Lam.T`",
             "lineno": 14, "operator": "transpose", "source": "Lam", "classification": "equivalent",
             "killed_by": {}, "survived": [], "cells": [cell(4, 2, "rational", "checked")]}
    row = lambda m, **kw: {"claim": "prep", "method": m, "total": 3, "killed": 1, "fails": 0, "error": 1,
                           "inconclusive": 0, "undecided": 0, "survived": 1, "equivalent": 1, "unresolved": 0,
                           "missed": 0, "baseline": "checked", "baseline_passes": True, **kw}
    return {"schema": 1, "meta": {"command": "stiefelsym mutate prep --seed 0", "seed": 0, "seconds": 12.5,
                                  "operators": [{"name": "sign", "description": "flip a sign (a + b <-> a - b)"}]},
            "claims": [{"claim": "prep", "paper": ["prep"], "section": "5", "kind": "id", "sizes": [[4, 2]],
                        "methods": ["rational", "free"], "mutant_count": 3, "baseline": base,
                        "mutants": [killed, survivor, equiv], "skipped": "", "seconds": 1.0},
                       {"claim": "wrong", "paper": ["w"], "section": "5", "kind": "id", "sizes": [],
                        "methods": ["rational"], "mutant_count": 0, "baseline": None, "mutants": [],
                        "skipped": "the printed statement fails at every size", "seconds": 0.0}],
            "table": [row("rational"), row("free", baseline="undecided", baseline_passes=False, killed=0)],
            "totals": [dict(row("rational"), claim="all claims")]}


def test_mutation_section_in_markdown(results):
    md = render_markdown(results, {"seed": 0}, mutation=_mutation())
    assert re.findall(r"^## (.*)$", md, re.M)[-1] == "Mutation analysis"
    section = md[md.index("## Mutation analysis"):]
    # the summary: the totals per method, every survivor, the counts; the rest is in mutation.md, not repeated
    assert "| rational | 3 | 1 | 0 | 1 | 0 | 1 | 1 | 0 | 0 | 50.0% | 50.0% |" in section
    assert "3 mutants of 1 claim (1 more claim not mutated, each with its reason in `mutation.md`): " \
           "1 refuted, 1 equivalent; 1 survivor." in section
    assert "**1 survivor**" in section and "**survived float, free**" in section
    assert "`mutation.md` has the whole analysis" in section
    assert "Command: `stiefelsym mutate prep --seed 0`." in section
    whole = render_mutation_markdown(_mutation())
    for line in ("| `prep` | rational | checked | 3 | 1 | 0 | 1 | 0 | 1 | 1 | 0 | 0 | 50.0% | 50.0% |",
                 "| `prep` | free | undecided | 3 | 1 | 0 | 1 | 0 | 1 | 1 | 0 | 0 | – | – |",
                 "`prep#2` line 14: remove the transpose in `Lam.T` in `Lam - Lam.T`"):
        assert line in whole and line not in section
    assert "## Mutation analysis" not in render_markdown(results)


def test_mutation_markdown_document_lists_everything():
    md = render_mutation_markdown(_mutation())
    assert md.startswith("# Mutation analysis")
    assert "- sign: flip a sign (a + b \\<-\\> a - b)" in md
    assert "`prep#0`" not in md, "killed mutants are in mutation.json only"
    assert "- `prep#1` line 13: flip the sign of the term `b_1` in `a*b | c`: **survived float, free**" in md
    assert "`wrong`: the printed statement fails at every size" in md
    assert "entry (1,2) = 3/7 & 100% #" in md
    # its words are defined before it uses them, and "unresolved" is not said to be "killed" (refuted)
    terms = md.index("Terms used below:")
    for word in ("mutant", "refuted", "equivalent", "survivor", "unresolved", "missed"):
        assert md.index(f"- **{word}**") > terms
    assert terms < md.index("Each claim's source is corrupted") and "killed only by" not in md


def test_mutation_section_in_latex_compiles(results, tmp_path):
    tex = render_latex(results, {"seed": 0}, mutation=_mutation())
    assert r"\section*{Mutation analysis}" in tex and r"\textbf{survived float, free}" in tex
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed (Debian: texlive-latex-base texlive-latex-recommended)")
    (tmp_path / "verification.tex").write_text(tex, encoding="utf-8")
    for _ in range(2):
        proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                               "-no-shell-escape", "verification.tex"], cwd=tmp_path,
                              capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
        assert proc.returncode == 0, proc.stdout[-3000:]
    log = (tmp_path / "verification.log").read_text(errors="replace")
    assert "Undefined control sequence" not in log and "Missing character" not in log


def test_kill_rate_is_never_rounded_up_to_100_percent():
    from stiefelsym.reports.report import kill_rate
    assert kill_rate({"total": 1001, "fails": 999, "error": 1, "killed": 1000, "equivalent": 0}) == "99.9%"
    assert kill_rate({"total": 1001, "killed": 1000, "equivalent": 0}, decisive=False) == "99.9%"
    assert kill_rate({"total": 5, "fails": 2, "error": 2, "killed": 4, "equivalent": 1}) == "100%"
    assert kill_rate({"total": 5, "killed": 0, "equivalent": 5}) == "–"
    assert kill_rate({"total": 5, "fails": 5, "killed": 5, "equivalent": 0, "baseline_passes": False}) == "–"


def test_undecided_mutants_are_no_refutations():
    """A method that leaves every mutant undecided refutes none of them (stop 72's review, D1): its refuted % is 0
    and its not passed % 100."""
    from stiefelsym.reports.report import kill_rate
    row = {"total": 4, "killed": 3, "fails": 0, "error": 0, "inconclusive": 2, "undecided": 1, "equivalent": 1}
    assert (kill_rate(row), kill_rate(row, decisive=False)) == ("0.0%", "100%")



# --------------------------------------------------------------------------- words a referee reads

def test_the_dimension_free_method_is_named_not_by_its_identifier():
    """A correction's verdict for every n, r reads "by the dimension-free method", never "by free"."""
    rs = [_corr(3, 1, "exact", "proved"), result("claim", None, None, "free", "undecided", variant="fix",
                                                 expected=False)]
    _, phrases = correction_summary(rs, [(3, 1)])
    assert "undecided for all n, r by the dimension-free method" in phrases
    assert not any(p.endswith("by free") or "by free " in p for p in phrases)


def test_every_method_named_in_a_verdict_is_explained():
    from stiefelsym.reports.report import METHOD_MEANING
    rs = [result("prep", 4, 2, "modular", "checked"), result("prep", 3, 1, "exact", "proved")]
    md, tex = render_markdown(rs), render_latex(rs)
    for m in ("exact", "modular", "rational", "float", "ball", "free"):
        assert m in METHOD_MEANING
        assert f"- **{m}**: " in md and f"\\item[{m}] " in tex
    assert "primes near 2⁶²" in md


def test_a_statement_that_something_does_not_hold_found_identically_zero_says_so():
    """The witness of a "not" claim that fails is the exact proof that it vanishes identically: the report
    says so, instead of pointing at a computed value below that is not there."""
    rs = [result("not-claim", 2, 1, "exact", "fails", kind="not", expected=True,
                 certificate="the residual vanishes identically on the chart", erratum="It holds for r >= 2.")]
    md, tex = render_markdown(rs), render_latex(rs)
    for doc in (md, tex):
        assert "computed value below" not in doc
        assert "not identically zero, and exact computation finds it identically zero: the residual vanishes" in doc
    assert r"What is wrong: It holds for \ensuremath{r \ge  2}." in tex


def test_the_headline_counts_the_claims_proved_at_particular_r_by_their_r():
    """The headline's count of dimension-free proofs splits by scope, and the parts add up."""
    from stiefelsym.reports.report import headline
    cert = "cofactor certificate of 1 residual entry (for every n at r = n, the only r the claim is stated for: it uses X X^T = I_n)"
    union = "cofactor certificates of cases (for every n at r = 1 and at r = n, the sizes the claim is stated for: 2 cases)"
    rs = [result("a", None, None, "free", "proved"), result("b", None, None, "free", "proved", certificate=cert),
          result("c", None, None, "free", "proved", certificate=union), result("d", 3, 1, "exact", "proved")]
    text, _ = headline(group_by_claim(rs))
    assert ("3 of them proved for every size at once: 1 for every n and r, and, stated at particular r, "
            "for every n: 1 at r = n, 1 at r = 1 and at r = n)") in text


def test_a_proof_in_the_metric_realization_states_what_it_assumes_in_words():
    """The referee's verdict line and the certificate line of a proof in the metric realization say that A is
    positive definite, Π = 0 and Λ by Sylvester uniqueness, with Λ for the engine's name Lambda:1; a proof
    with no assumption says none."""
    from stiefelsym.reports.report import certificate_summary
    data = {"summary": {"entries": 1, "terms": 2, "hypotheses": ["XtX", "rho:Lambda:1"], "realization": "metric",
                        "assumes": ["A symmetric positive definite",
                                    "Lambda:1 is the solution of rho:Lambda:1 = 0, unique and symmetric "
                                    "(M = X^T A^-1 X positive definite)",
                                    "Pi = 0 by uniqueness: Pi M + M Pi = 0 (keeps: X^T X = I_r)"]},
            "entries": [{"terms": [1, 2]}]}
    proof = result("metric", None, None, "free", "proved", certificate_data=data)
    line = certificate_summary(proof)
    assert "it assumes (the metric realization): A symmetric positive definite; Λ is the solution of its " \
           "Sylvester equation" in line and "Π = 0 by uniqueness" in line and "Lambda:1" not in line.split("(XtX")[0]
    tex = render_latex([proof, result("metric", 3, 1, "exact", "proved")])
    assert r"proved, assuming \ensuremath{A} symmetric positive definite; \ensuremath{\Lambda} is the solution" in tex
    plain = dict(data, summary=dict(data["summary"], assumes=[]))
    assert "assum" not in certificate_summary(result("metric", None, None, "free", "proved", certificate_data=plain))


def test_a_failing_checks_status_is_in_words():
    from stiefelsym.reports.report import check_line
    assert check_line(CheckOutcome("regular iff n <= 2r+1", "count-mismatch", "1 (paper: 0)")) \
        == "check regular iff n <= 2r+1: count not as printed, computed 1, where the printed statement gives 0"
    assert check_line(CheckOutcome("rank ad_Phi", "rank", "= 4")) == "check rank ad_Φ: rank as printed, = 4"


def test_the_referees_verdict_line_gives_the_reason_for_undecided_in_words():
    from stiefelsym.reports.report import _brief_reason
    assert _brief_reason("needs coordinates (fixed n, r): a constant matrix on R^n (e.g. E_1); decided at "
                         "fixed sizes") == "needs fixed n, r: a constant matrix on R^n"
    assert _brief_reason("4 residual entries have a nonzero normal form; e.g. ...") \
        == "4 residual entries do not reduce to 0 by the rewriting rules"
    assert _brief_reason("1 residual entry has a nonzero normal form") \
        == "1 residual entry does not reduce to 0 by the rewriting rules"


def test_the_summary_table_says_where_a_proof_at_particular_r_holds():
    cert = "cofactor certificate of 1 residual entry (for every n at r = n, the only r the claim is stated for: it uses X X^T = I_n)"
    md = render_markdown([result("b", None, None, "free", "proved", certificate=cert), result("b", 2, 2, "exact", "proved")])
    assert "| proved, every n at r = n |" in md


def test_the_headline_and_the_summary_table_count_the_same_claims_as_holding():
    """A claim that no method decided at one computed size is not said to hold at every size computed: the
    headline names it, and its count agrees with the summary table's column."""
    from stiefelsym.reports.report import headline, section_counts
    rs = [result("a", 3, 1, "exact", "proved"), result("a", 6, 1, "modular", "undecided", expected=True),
          result("b", 3, 1, "exact", "proved"), result("b", 6, 1, "modular", "checked")]
    claims = group_by_claim(rs)
    text, _ = headline(claims)
    assert text.startswith("Of the catalog's 2 claims (the paper's checkable statements, and some forms of them: corrected, more general, or lemmas of a proof), 1 holds as printed at every size computed")
    assert "1 holds where decided but was left undecided at some size (a)" in text
    assert section_counts(claims)["hold at every size"] == 1


def test_the_headline_and_the_summary_table_tell_proofs_from_random_checks():
    """A claim that holds at every size computed but is only checked (at random points) at one of them is not
    counted as proved there: the headline says how many rest on checks, with their false-pass bound; a proof
    for every n at one r is counted apart from one for every n and r."""
    from stiefelsym.reports.report import headline, section_counts
    cert = "cofactor certificate of 1 residual entry (for every n at r = n, the only r the claim is stated for: it uses X X^T = I_n)"
    rs = [result("a", 3, 1, "exact", "proved"), result("a", 6, 1, "modular", "checked", false_pass_bound=2.5e-31),
          result("b", 3, 1, "exact", "proved"), result("c", None, None, "free", "proved", certificate=cert),
          result("c", 3, 3, "modular", "checked")]
    claims = group_by_claim(rs)
    text, _ = headline(claims)
    assert ("3 hold as printed at every size computed (2 proved at every size computed; 1 of them proved for every "
            "size at once: 0 for every n and r, and, stated at particular r, for every n: 1 at r = n; 1 rests at some "
            "size on a check at random points (false-pass probability at most 2.5·10⁻³¹ per check) alone, no method "
            "proving it there)") in text
    counts = section_counts(claims)
    assert (counts["proved for all n, r"], counts["proved for every n at one r"], counts["hold at every size"],
            counts["proved at every size"]) == (0, 1, 3, 2)
    # a numerical check has no false-pass probability: the bound is said of the randomized checks only
    text, _ = headline(group_by_claim(rs + [result("d", 3, 1, "float", "numeric")]))
    assert ("2 rest at some size on a check at random points (false-pass probability at most 2.5·10⁻³¹ per check) "
            "or numerically (within a floating-point error bound; no probability attaches to such a check) alone, "
            "no method proving them there)") in text


def test_the_report_of_a_claims_file_counts_its_statements_not_the_papers():
    """A run of a user's claims file is not the paper's catalog: its headline counts the statements verified,
    and every verdict is compared with its own claim's expectation."""
    rs = [result("a", 3, 1, "exact", "proved"), result("b", 3, 1, "exact", "proved")]
    md = render_markdown(rs, {"claims_files": ["mine.py"], "title": "Verification of the claims of mine.py"})
    assert "Of the 2 statements verified, 2 hold as printed" in md and "the paper's" not in md.split("##")[0]
    assert "every verdict is the one its claim expects" in md
    assert "Of the catalog's 2 claims" in render_markdown(rs)


def test_how_obtained_names_the_sizes_of_each_reduction():
    """A method whose runs used different charts lists each chart with the sizes it proved; a method with one
    chart for every run is named alone."""
    runs = [result("prep", 3, 2, "exact", "proved", reductions=["the Cayley chart"]),
            result("prep", 4, 4, "exact", "proved", reductions=["the chart X = I"]),
            result("prep", 5, 5, "exact", "proved", reductions=["the chart X = I"]),
            result("prep", 6, 2, "modular", "checked", reductions=["points of the Cayley chart"]),
            result("prep", 7, 2, "modular", "checked", reductions=["points of the Cayley chart"])]
    (c,) = group_by_claim(runs)
    assert c.how_obtained() == [("exact at (3,2)", "the Cayley chart"), ("exact at (4,4), (5,5)", "the chart X = I"),
                                ("modular", "points of the Cayley chart")]
    md = render_markdown(runs)
    assert "- exact at (4,4), (5,5): the chart X = I" in md
    assert "- modular: points of the Cayley chart" in md


def test_a_changed_formula_with_left_right_never_overflows_the_line():
    """A mutant's change set in ``\\left … \\right`` (which TeX cannot break) is shrunk to 0.9 of the
    line and may begin a line; a formula TeX can break stays plain inline mathematics."""
    wide = r"\mathrm{tr}\left(I_r \left(\tfrac{1}{2} (\Psi - \Psi^T)\right)\right)"
    tex = _tex_change([{"where": "H", "old": "a", "new": "b", "old_tex": wide, "new_tex": "X^T P"}])
    assert (r"\nobreak\hfil\penalty0\hfilneg\relax\resizebox{\ifdim\width>0.9\linewidth 0.9\linewidth\else"
            r"\width\fi}{!}{$" + wide + "$}") in tex
    assert tex.endswith(r"$\to$ $X^T P$")


def test_a_count_witness_to_check_by_hand_sets_its_scripts_in_the_pdf():
    """The hand witness of a count names the printed formula in the paper's notation: diag(I_{n-r},
    B^{-1}) is set with scripts in the PDF, never as the characters _{ and ^{."""
    small = {"kind": "count", "check": "rows of V", "value": 2, "paper": 1,
             "meaning": "the rows of V; printed: the size of diag(I_{n-r}, B^{-1})"}
    rs = [result("neumann-lax", 1, 1, "exact", "fails", expected=False, witness={"small": small})]
    tex = render_latex(rs)
    line = next(x for x in tex.splitlines() if x.startswith(r"\textbf{A witness to check by hand:}"))
    assert r"\ensuremath{\mathop{\mathrm{diag}}\nolimits (I_{n-r}, B^{-1})}: computed 2" in line
    assert r"\_\{" not in line and r"\^{}" not in line
    md = render_markdown(rs)
    assert "**A witness to check by hand:** at (n, r) = (1,1), the rows of V; printed: the size of" in md


def test_a_rank_witness_to_check_by_hand_states_the_quantity_the_paper_prints():
    """Where the paper states the dimension of a kernel (the number of invariant forms of Proposition 4.6, the
    dimension of the solutions of (16), (17) §6), the hand witness states that quantity, the unknowns minus the rank,
    with the two ranks of the check beside it; the template declares the quantity and the unknowns."""
    from stiefelsym.reports.report import count_kernel
    assert count_kernel("invariant-metrics")[1] == 15 and count_kernel("pencil-l5-l6")[1] == 7
    assert count_kernel("neumann2-h-size") is None and count_kernel("no-such-claim") is None
    for cid, check, size, value, paper, says in (
            ("invariant-metrics", "invariant forms", (4, 2), 12, 13,
             "the number of independent invariant quadratic forms on the fibre: computed 3, where the printed "
             "statement gives 2; that is 15 − 12 against 15 − 13, where 12 is the computed rank of the invariance "
             "conditions"),
            ("pencil-l5-l6", "rank of (16), (17) §6", (3, 3), 5, 4,
             "of (16), (17) §6: computed 2, where the printed statement gives 3; that is 7 − 5 against 7 − 4")):
        small = {"kind": "count", "check": check, "value": value, "paper": paper, "meaning": ""}
        rs = [result(cid, *size, "exact", "fails", expected=True, erratum="wrong", witness={"small": small})]
        md = render_markdown(rs)
        line = next(x for x in md.splitlines() if x.startswith("**A witness to check by hand:**"))
        assert says in line, line
        assert "A witness to check by hand" in render_latex(rs)


def test_what_is_wrong_spells_the_greek_letters_as_letters():
    """The catalog writes what is wrong in ASCII (Psi, L(nu), Q(lambda*)); a referee reads Ψ, L(ν), Q(λ*)
    in both documents, and a word that merely contains a letter's name (beta, Pit) is left alone."""
    text = "with <Psi, Psi> and L(nu), Q(lambda*); beta and Pit stay"
    rs = [result("neumann-lax", 3, 1, "exact", "fails", expected=False, erratum=text)]
    md, tex = render_markdown(rs), render_latex(rs)
    assert "What is wrong: with \\<Ψ, Ψ\\> and L(ν), Q(λ\\*); beta and Pit stay" in md
    line = next(x for x in tex.splitlines() if x.startswith("What is wrong: "))
    assert r"\ensuremath{\Psi}" in line and r"\ensuremath{L(\nu )}" in line and "beta and Pit stay" in line
    assert "Psi" not in line.replace(r"\Psi", "")


def test_the_summary_by_section_is_the_same_in_both_documents(results):
    """The Markdown's summary opens with the PDF's table by section, the same numbers and a total that
    is the sum of its rows (and equals the headline's counts)."""
    md, tex = render_markdown(results), render_latex(results)
    summary = md[md.index("## Summary"):md.index("## §2")]
    md_rows = [[c.strip().strip("*") for c in line.split("|")[1:-1]]
               for line in summary.splitlines() if line.startswith("| ") and not line.startswith("| ---")]
    assert md_rows[0] == ["section", "claims", "proved for all n, r", "proved for every n at one r",
                          "hold at every size", "proved at every size", "fail as printed", "unexpected"]
    table = tex[tex.index(r"\begin{tabular}{@{}P{5.6cm}rrrrrrr@{}}"):]
    table = table[:table.index(r"\end{tabular}")]
    tex_rows = [[c.strip() for c in line.removesuffix(r"\\").split("&")] for line in table.splitlines()
                if line.endswith(r"\\") and not line.startswith("section")]
    numbers = [row[1:] for row in md_rows[1:md_rows.index(next(r for r in md_rows if r[0] == "claim"))]]
    assert numbers == [row[1:] for row in tex_rows]
    *rows, total = numbers
    assert total == [str(sum(int(r[i]) for r in rows)) for i in range(7)]


def test_markdown_math_sets_the_underscore_of_a_name_in_text_as_math():
    """\\text{along (dot\\_XP3*)} is plain text to a Markdown viewer's MathJax, which would show the
    backslash: the underscore is set in math between two pieces of text; the PDF keeps the source."""
    from stiefelsym.reports.report import _md_math
    assert _md_math(r"\dot X=P\ \text{along (dot\_XP3*)},\ x_1\ \text{for every }\kappa") == \
        r"\dot X=P\ \text{along (dot}\_\text{XP3*)},\ x_1\ \text{for every }\kappa"


def test_the_characters_left_out_of_junit_are_those_xml_does_not_allow():
    """_XML_BAD is written as the class of what XML 1.0 leaves out (it compiles in a twentieth of the time of the
    class of what it allows): over every code point, the two classes replace the same characters."""
    import re
    from stiefelsym.reports.report import _XML_BAD
    allowed = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
    text = "".join(map(chr, range(0x110000)))
    assert _XML_BAD.sub("?", text) == allowed.sub("?", text)


def test_a_witness_bullet_says_which_value_the_printed_statement_gives():
    """The referee of stop 67: "printed: 2r: 3 (paper: 2)" read as if the paper gave 2; the bullet says it as the
    witness to check by hand does."""
    from stiefelsym.reports.report import check_line, printed_value_words
    line = check_line(CheckOutcome("rows of V", "count-mismatch", "the rows of V (VV); printed: 2r: 3 (paper: 2)"))
    assert line.endswith("the rows of V (VV); printed: 2r: computed 3, where the printed statement gives 2")
    assert "(paper:" not in line
    assert printed_value_words("rank 5 at an exact rational point (paper: 4)") \
        == "rank 5 at an exact rational point; the printed statement gives 4"
    assert printed_value_words("exact rank 12 over Q, so rank 12 at every point; paper: 13") \
        == "exact rank 12 over Q, so rank 12 at every point; the printed statement gives 13"
    assert printed_value_words("the sizes: 2 (claimed: 1)") == "the sizes: computed 2, where the claim states 1"
    assert printed_value_words("= 4") == "= 4"
    # an agreeing count is not said as a contrast (the referee of stop 75: "computed 0, where ... gives 0")
    assert printed_value_words("nontrivial integrals: 0 (paper: 0)") == \
        "nontrivial integrals: computed 0, as the printed statement gives"


def _misprinted(place: str = "") -> list[Result]:
    return [result("neumann2-h", n, r, "exact", "fails", section="7", paper=["NEUMANN2"], erratum="h is r x r.",
                   place=place, checks=[CheckOutcome("size of h", "count-mismatch", "the rows of h: 1 (paper: 2)")],
                   rerun=f"stiefelsym verify neumann2-h --size {n},{r} --method exact")
            for n, r in ((2, 1), (3, 1), (3, 2))]


def test_an_erratum_names_the_place_of_its_misprint_before_the_statements_it_involves():
    """A misprint in a proof beside a correct theorem is located there ("In the proof of Theorem 7.1 (involves:
    Theorem 7.1 [NEUMANN2])"), in the list after the headline and in the note for the authors, in both documents;
    without a place the note reads as before."""
    placed = _misprinted("the proof of Theorem 7.1")
    md, tex = render_markdown(placed), render_latex(placed)
    assert "- `neumann2-h` in the proof of Theorem 7.1 (involves: Theorem 7.1 [NEUMANN2])" in md
    assert "**Note for the authors.** In the proof of Theorem 7.1 (involves: Theorem 7.1 [NEUMANN2]), the " \
           "statement as printed fails" in md
    assert r"\texttt{neumann2-h} in the proof of Theorem 7.1 (involves: Theorem~7.1 " in tex
    assert r"\textbf{Note for the authors.} In the proof of Theorem 7.1 (involves: Theorem 7.1 [NEUMANN2]), the " \
           "statement as printed fails" in tex
    plain = render_markdown(_misprinted())
    assert "- `neumann2-h` Theorem 7.1 [NEUMANN2]" in plain and "involves" not in plain
    assert "**Note for the authors.** In Theorem 7.1 [NEUMANN2], the statement as printed fails" in plain
    # a place in the paper's notation is set as such
    tex = render_latex(_misprinted("the general line 𝓘₂ₗ(λ) of (5) §8"))
    assert r"in the general line \ensuremath{\mathcal{I}_{2l}(\lambda )} of (5) " in tex


def test_a_list_of_reruns_shows_its_last_item_rather_than_one_more():
    """"… and 1 more (in results.json)" takes the room of the one rerun command it hides (the referee of stop 67)."""
    from stiefelsym.reports.report import _shown
    assert [_shown(range(k), 2) for k in (0, 2, 3, 4)] == [0, 2, 3, 2]
    four = [result("neumann-lax", n, 1, "exact", "fails", witness=WITNESS, residual="(1, 2) = 3/7",
                   rerun=f"stiefelsym verify neumann-lax --size {n},1 --method exact") for n in (2, 3, 4, 5)]
    tex = render_latex(four)          # the referee's document lists two more failing runs: here all three
    assert "more (in results" not in tex and r"--size\nobreakspace{}5,1" in tex
    # commands that are not joined (here each at a hard point) are listed one by one, up to the limit
    hard = [result("neumann-lax", n, 1, "exact", "fails", witness=WITNESS,
                   rerun=f"stiefelsym verify neumann-lax --size {n},1 --hard far-chart") for n in (2, 3, 4, 5, 6)]
    assert "and 2 more (in results.json)" in render_latex(hard)
    md = render_markdown([result("neumann-lax", n, 1, "exact", "fails", witness=WITNESS,
                                 rerun=f"stiefelsym verify neumann-lax --size {n},1") for n in range(1, 11)])
    assert "more (in results" not in md and "--size 10,1" in md


def test_the_meaning_of_fails_names_both_kinds_of_witness():
    from stiefelsym.reports.report import VERDICT_MEANING
    text = VERDICT_MEANING["fails"]
    assert "a point and a nonzero residual entry" in text and "dimension, rank or count" in text


# --------------------------------------------------------------------------- stop 69: the referee's reading

def _erratum_pair(claim: str, paper: list[str], fix: str = "one fix", place: str = "") -> list[Result]:
    """A claim that fails as printed at (2,1) and (3,1) and whose correction ``fix`` is proved at both."""
    rs = [result(claim, n, 1, "exact", "fails", expected=True, erratum="wrong", paper=paper, place=place)
          for n in (2, 3)]
    rs += [result(claim, n, 1, "exact", "proved", variant=fix, paper=paper) for n in (2, 3)]
    return rs


def test_one_misprint_repaired_by_one_correction_in_two_statements_is_counted_once():
    """Two errata of the catalog that declare one place of their misprint and are repaired by the same verified
    correction fail through one misprint (the headline counts it once, the list says which); the same correction at
    another place is another misprint (the review of stop 69: never inferred from shared words and a shared label
    alone), and a claims file's report counts nothing together."""
    rs = (_erratum_pair("theorem", ["LA3D", "D-eq"], place="the blocks of (5) §10")
          + _erratum_pair("extends", ["LA3D", "LA3"], place="the blocks of (5) §10")
          + _erratum_pair("elsewhere", ["LA3D"], place="the display before (4) §8"))
    md = render_markdown(rs)
    assert ("3 fail as printed (from 2 distinct places of the paper, each a false statement, a misprinted size or "
            "index, or a statement taken literally where a hypothesis is tacit or a formula schematic: theorem and "
            "extends fail through one place") in md
    assert "correction: one fix (the same place of the paper as theorem)" in md
    assert "(involves: (LA3D)); correction: one fix\n" in md
    tex = render_latex(rs)
    assert "from 2 distinct places" in tex and "the same place of the paper as theorem" in tex
    # shared words and a shared label without a declared place: two misprints, nothing said
    rs2 = _erratum_pair("a", ["x"]) + _erratum_pair("b", ["x"])
    assert "distinct places" not in render_markdown(rs2) and "the same place" not in render_markdown(rs2)
    # a claims file's report (its claims may copy the catalog's place and words): nothing is counted together
    meta = {"claims_files": ["mine.py"]}
    for doc in (render_markdown(rs, meta), render_latex(rs, meta)):
        assert "distinct places" not in doc and "the same place" not in doc


def test_the_headline_counts_the_places_of_each_nature():
    """The referee's C1: the headline counts the places of the paper the errata fail through by their nature, as the
    catalog declares it of each erratum (``@claim(nature=...)``): two statements that fail through one misprint in a
    printed formula count one such place; a claims file's report counts none."""
    rs = (_erratum_pair("double-neumann-dual-lax", ["dual-D"], place="the blocks of (5) §10")
          + _erratum_pair("double-neumann-dual-lax-extends-la3", ["dual-D"], place="the blocks of (5) §10")
          + _erratum_pair("spectral-curve-identity-size", ["2r-integrals"], place="the display before (4) §8"))
    md = render_markdown(rs)
    assert ("3 fail as printed (from 2 distinct places of the paper: 1 misprint in a printed formula (a sign, an "
            "inverse, a letter or a term) and 1 misprinted size or index range (Iₙ for I₂ᵣ, GL(n) for GL(r)); "
            "double-neumann-dual-lax and double-neumann-dual-lax-extends-la3 fail through one place") in md
    assert "[2r-integrals]); correction: one fix; nature: a misprinted size or index range\n" in md
    tex = render_latex(rs)
    assert "1 misprint in a printed formula" in tex and r"\ensuremath{I_{n}} for \ensuremath{I_{2r}}" in tex
    assert "; nature: a misprint in a printed formula" in tex
    one = _erratum_pair("spectral-curve-identity-size", ["2r-integrals"])
    assert "1 fails as printed (through 1 misprinted size or index range (Iₙ for I₂ᵣ" in render_markdown(one)
    two = one + _erratum_pair("manakov-dual-lax", ["man-dual"])
    assert ("2 fail as printed (each through a place of the paper of its own: 1 misprint in a printed formula "
            "(a sign, an inverse, a letter or a term) and 1 misprinted size") in render_markdown(two)
    for doc in (render_markdown(rs, {"claims_files": ["mine.py"]}), render_latex(rs, {"claims_files": ["mine.py"]})):
        assert "misprint in a printed formula" not in doc


def test_the_headline_counts_a_correction_shared_by_two_statements_once():
    """Two statements repaired by one correction at one place (one error of the paper) count one correction proved
    for every n and r, and the headline says how many statements the corrections repair."""
    rs = []
    for cid, place in (("theorem", "the blocks of (5) §10"), ("extends", "the blocks of (5) §10"),
                       ("other", "the display before (4) §8")):
        rs += _erratum_pair(cid, ["LA3D"], place=place)
        rs.append(result(cid, None, None, "free", "proved", variant="one fix", paper=["LA3D"]))
    md = render_markdown(rs)
    assert "(2 distinct corrections proved for every n and r, which repair 3 of the statements that fail)" in md
    # a claims file's report counts nothing together
    assert "(3 corrections proved for every n and r)" in render_markdown(rs, {"claims_files": ["mine.py"]})


def test_the_reruns_of_an_erratum_are_one_command_per_method_and_seed():
    cmds = [f"stiefelsym verify c --size {n},1 --method exact --seed 0" for n in (2, 3, 4)]
    cmds += ["stiefelsym verify c --size 5,1 --method modular --seed 0", "stiefelsym verify c --size 6,1 --method exact",
             "stiefelsym verify c --size 7,1 --method exact",
             "stiefelsym verify c --size 6,2 --method exact --seed 0", "stiefelsym verify c --claims f.py --size 1,1"]
    assert grouped_reruns(cmds) == [
        "stiefelsym verify c --method exact --seed 0 --size 2,1 --size 3,1 --size 4,1 --size 6,2",
        "stiefelsym verify c --size 5,1 --method modular --seed 0",   # alone: as it is
        "stiefelsym verify c --method exact --size 6,1 --size 7,1",     # a run that draws nothing has no seed
        "stiefelsym verify c --claims f.py --size 1,1"]       # any other command as it is


def test_a_grouped_rerun_reproduces_each_of_its_runs(tmp_path):
    """The command that joins the sizes gives, at each size, the verdict of the command of that size alone."""
    from click.testing import CliRunner
    from stiefelsym.cli import main
    one = [CliRunner().invoke(main, ["verify", "spectral-curve-identity-size", "--size", s, "--method", "exact",
                                     "--seed", "0", "--format", "json", "--no-report"]) for s in ("3,1", "4,1")]
    both = CliRunner().invoke(main, ["verify", "spectral-curve-identity-size", "--method", "exact", "--seed", "0",
                                     "--size", "3,1", "--size", "4,1", "--format", "json", "--no-report"])
    def records(out):
        data = json.loads(out.stdout)
        return [(r["n"], r["r"], r["verdict"], r["certificate"], r.get("witness")) for r in data["results"]
                if not r.get("variant")]
    assert records(both) == records(one[0]) + records(one[1])


def test_the_note_for_the_authors_quotes_the_registered_correction_not_the_computed_change():
    """The note quotes the paper's place and the registered correction's words; the change of the formula as the graphs
    give it (the engine's normal form, at a check's name), long or short, is left to the list of candidates."""
    rs = _erratum_pair("big", ["so(n,n)"], fix="the sign of the last term")
    # the change of the catalog's coupled-big-lax-normal: two block matrices and a commutator of them
    J, M, K = "(0, A; A, 0)ν", "(PXᵀ − XPᵀ, 0; 0, QYᵀ − YQᵀ)", "(0, XYᵀ; YXᵀ, 0)ν⁻¹"
    tJ, tM = r"\begin{pmatrix}0 & A\\ A & 0\end{pmatrix} \nu", \
        r"\begin{pmatrix}P X^T - X P^T & 0\\ 0 & Q Y^T - Y Q^T\end{pmatrix}"
    tK = r"\begin{pmatrix}0 & X Y^T\\ Y X^T & 0\end{pmatrix} \nu^{-1}"
    long_change = [{"where": "so(n,n)", "old": K, "new": "−" + K, "old_tex": tK, "new_tex": "-" + tK},
                   {"where": "so(n,n)", "old": f"[{J} + {M} + {K}, {J} + {M}]", "new": f"[{J} + {M}, {J} + {M} − {K}]",
                    "old_tex": f"[{tJ} + {tM} + {tK}, {tJ} + {tM}]", "new_tex": f"[{tJ} + {tM}, {tJ} + {tM} - {tK}]"}]
    for change in (long_change, long_change[:1]):
        for r in rs:
            if r.variant:
                r.change = change
        for doc in (render_markdown(rs), render_latex(rs)):
            note = doc.split("Note for the authors")[1].split("\n\n")[0]
            assert "the sign of the last term (the change of the formula as computed is in the candidate " \
                   "corrections below)" in note
            assert "XYᵀ" not in note and "X Y^T" not in note and "in so(n,n)" not in note
        # the list of candidates has it
        assert "−(0, XYᵀ; YXᵀ, 0)ν⁻¹" in render_markdown(rs).split("Candidate corrections")[1]


def test_the_value_the_paper_prints_reads_as_printed_in_every_table():
    assert quoted_value_words("regular (1) or singular (0): 1 (paper: 0)") == \
        "regular (1) or singular (0): computed 1, printed 0"
    assert quoted_value_words("rank = 30 (paper: 30); two-sided") == "rank = 30 (printed: 30); two-sided"
    assert quoted_value_words("exact rank 4 over Q; paper: 4") == "exact rank 4 over Q; printed: 4"
    assert quoted_value_words("rank 3 (claimed: 3)") == "rank 3 (claimed: 3)"


def test_a_claims_files_own_words_are_never_reworded_as_the_papers():
    """"(paper: 5)" in the words of a claims file's claim stays as written (the review of stop 69): only the
    catalog's records have their quoted values said as printed."""
    detail = "mm-count: 3 (paper: 5); claimed: 3"
    mine = result("mm-count", 3, 1, "exact", "proved", checks=[CheckOutcome("c", "count", detail)], certificate=detail,
                  rerun="stiefelsym verify mm-count --size 3,1 --method exact --claims mine.py")
    md = render_markdown([mine], {"claims_files": ["mine.py"]})
    assert "(paper: 5)" in md and "printed: 5" not in md
    ours = result("mm-count", 3, 1, "exact", "proved", checks=[CheckOutcome("c", "count", detail)], certificate=detail)
    assert "computed 3, printed 5" in render_markdown([ours])


@pytest.mark.parametrize("forge", ["value", "letter", "constraint"])
def test_report_refuses_a_witness_to_check_by_hand_that_is_not_the_engines(tmp_path, forge):
    """The witness a reader checks by hand is rendered only as the engine finds it again (the review of stop 69: a
    results file whose X or residual value was edited rendered "a point of T*V ... the residual is ..."); `check`
    refused it already, `report` now does too."""
    from click.testing import CliRunner
    from stiefelsym.cli import main
    run = CliRunner().invoke(main, ["verify", "manakov-dual-lax", "--size", "2,1", "--method", "exact",
                                    "--report-dir", str(tmp_path)])
    assert run.exit_code == 0, run.output
    path = tmp_path / "results.json"
    data = json.loads(path.read_text())
    record = next(r for r in data["results"] if "small" in (r.get("witness") or {}))
    small = record["witness"]["small"]
    assert CliRunner().invoke(main, ["report", "--results", str(path)]).exit_code == 0
    if forge == "value":
        small["value"] = "-5/2"
    elif forge == "letter":
        small["letters"]["X"] = [["2"], ["0"]]
    else:
        small["on T*V"] = {k: True for k in small["on T*V"]} | {"XᵀX = 2I": True}
    path.write_text(json.dumps(data))
    out = CliRunner().invoke(main, ["report", "--results", str(path)])
    assert out.exit_code == 2
    assert "its witness to check by hand is not the one the engine finds" in out.output


def test_report_refuses_a_count_witness_edited_together_with_its_check(tmp_path):
    """A results file that edits a count erratum's check and its witness to check by hand together (both say 1 where
    the engine computes 2) is refused: the two numbers are recomputed by the claim's own count template."""
    from click.testing import CliRunner
    from stiefelsym.cli import main
    run = CliRunner().invoke(main, ["verify", "neumann2-h-size", "--size", "3,2", "--method", "exact",
                                    "--report-dir", str(tmp_path)])
    assert run.exit_code == 0, run.output
    path = tmp_path / "results.json"
    data = json.loads(path.read_text())
    record = next(r for r in data["results"] if "small" in (r.get("witness") or {}))
    small = record["witness"]["small"]
    assert (small["value"], small["paper"]) == (2, 3)
    small["value"] = 1
    for ch in record["checks"]:
        if ch["name"] == small["check"]:
            ch["detail"] = ch["detail"].replace(": 2 (paper: 3)", ": 1 (paper: 3)")
    path.write_text(json.dumps(data))
    out = CliRunner().invoke(main, ["report", "--results", str(path)])
    assert out.exit_code == 2 and "its witness to check by hand is not the one the engine finds" in out.output


def test_the_headline_counts_slips_reported_in_passing_and_the_errata_with_a_correction():
    """The slips an erratum reports in passing are said after the count of errors; where not every erratum has a
    registered correction, the headline says how many have one ("23 of the 24")."""
    from stiefelsym.reports.report import group_by_claim, headline
    rs = [result("neumann-lax", 2, 1, "exact", "fails", witness=WITNESS, residual="(1, 2) = 3/7", expected=True,
                 erratum="x", slips=["the subscript Iᵣ₊₁ for Iₗ₊₁ in (5) §8"]),
          result("neumann-lax", 2, 1, "exact", "proved", variant="(5) §8: I₂ in place of I₁"),
          result("prep", 2, 1, "exact", "fails", witness=WITNESS, residual="(1, 2) = 3/7", expected=True,
                 erratum="y")]
    text, errata = headline(group_by_claim(rs))
    assert len(errata) == 2 and "where a correction is registered (1 of the 2) it was verified" in text
    assert text.endswith("Besides these failures, 1 slip of the paper that makes no statement fail is reported in "
                         "passing: the subscript Iᵣ₊₁ for Iₗ₊₁ in (5) §8 (see neumann-lax).")


def test_a_witness_on_the_complex_stiefel_variety_is_said_in_the_papers_notation():
    """A point of TW_{n,r} is said as the paper writes it (Z̄ᵀZ = Iᵣ, V = Ż), and its residual as realified."""
    from stiefelsym.reports.report import _realified, _witness_place
    w = {"letters": {"Re Z": [[1]], "Im Z": [[0]], "Re V": [[0]], "Im V": [[1]]}}
    md = _witness_place(w, ["Z*Z = I", "Z*V + V*Z = 0"], False)
    assert "TW\\_{n,r}, V = Ż" in md and "(Z̄ᵀZ = Iᵣ, Z̄ᵀV + V̄ᵀZ = 0 hold exactly)" in md and "Z*" not in md
    assert r"$\bar Z^TZ=I_r$" in _witness_place(w, ["Z*Z = I"], True)
    assert _realified(w).startswith(" realified") and _realified({"letters": {"X": [[1]]}}) == ""


def test_no_line_of_a_latex_report_outgrows_texs_buffer():
    """verification-runs.tex printed a derivation's source whole in one \\texttt, a line of 211,394 characters:
    Debian's pdflatex (buf_size 200000) stopped there ("Unable to read an entire line").  Lines are broken at spaces
    (a space to TeX), and a line with a comment is left whole."""
    from stiefelsym.reports.report import TEX_LINE_MAX, short_lines
    words = " ".join(f"w{i}" for i in range(20000))
    out = short_lines("a\n" + words + "\nb")
    assert max(len(x) for x in out.split("\n")) <= TEX_LINE_MAX
    assert " ".join(out.split("\n")) == "a " + words + " b"
    assert short_lines("% " + words) == "% " + words
    assert short_lines(r"100\% " + words).count("\n") > 0


def test_a_derivation_writes_no_term_of_coefficient_zero():
    """The per-run document showed R = 0 tr(PᵀAξXGᵀ) + 0 tr(…) + … for twisted-form-closed: terms whose coefficient
    expands to 0 are no terms of R."""
    import re
    import subprocess
    import sys
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "derive", "twisted-form-closed"], capture_output=True,
                         text=True, timeout=600)
    assert out.returncode == 0 and r"R &= " in out.stdout, out.stderr[-2000:]
    assert not re.search(r"(&= |[+-] )0 \\operatorname", out.stdout), out.stdout[:2000]


def test_breaking_long_lines_makes_no_empty_line_and_no_control_space():
    """Stop 73's review (D1): a statement with a run of 4,500 blanks was cut inside the run, leaving a line of blanks
    (an empty line, a new paragraph: "Missing $ inserted" inside the display).  A break is made only between two
    pieces of text, never after a backslash (a control space), and a line of blanks alone is left empty."""
    from stiefelsym.reports.report import TEX_LINE_MAX, short_lines
    blanks = " " * 4500
    for tex in (r"$\displaystyle x" + blanks + "= y$", "a" + blanks + "b " + "w " * 3000 + blanks,
                r"\ " * 1500 + "x " * 1500, "x" + " " * (TEX_LINE_MAX - 1) + "y z"):
        out = short_lines(tex).split("\n")
        assert all(ln.strip(" ") for ln in out), [ln[:20] for ln in out]
        assert " ".join(out).split() == tex.split()
        assert not any(ln.endswith("\\") for ln in out)
    assert short_lines(blanks) == ""
    words = " ".join(f"w{i}" for i in range(20000))
    assert max(len(x) for x in short_lines(words).split("\n")) <= TEX_LINE_MAX


# --------------------------------------------------------------------------- typographical slips

def test_the_typographical_slips_are_listed_in_a_report_of_the_whole_catalog_only():
    """A report of a run of the whole catalog lists the paper's typographical slips after the errata (both
    documents, the headline counting them); a report of some claims, of a claims file, or the per-run
    document does not."""
    from stiefelsym.proofs.slips import SLIPS
    r = result("prep", 3, 1, "exact", "proved")
    md = render_markdown([r], {"whole_catalog": True})
    assert "## Typographical slips" in md and f"lists {len(SLIPS)} more slips" in md
    assert md.index("## Errata") < md.index("## Typographical slips") < md.index("## Summary")
    # the slip of (5) §8's neighbour, a dropped "= n", with its place and the claim that computes it
    assert "(source line 1432).** Printed: “Therefore, dim ker Λ" in md and "computed by pencil-rank-a1" in md
    tex = render_latex([r], {"whole_catalog": True})
    assert r"\section*{Typographical slips}" in tex and "Printed:" in tex
    for meta in ({}, {"whole_catalog": True, "claims_files": ["mine.py"]}):
        assert "Typographical slips" not in render_markdown([r], meta) + render_latex([r], meta)
        assert "Spelling and punctuation" not in render_markdown([r], meta) + render_latex([r], meta)
    assert "Typographical slips" not in render_latex([r], {"whole_catalog": True}, detail=True)
    assert "Spelling and punctuation" not in render_latex([r], {"whole_catalog": True}, detail=True)


def test_the_slips_of_spelling_and_punctuation_follow_the_typographical_slips():
    """A report of the whole catalog lists the paper's slips of spelling and punctuation after its typographical
    slips, each with its place, the source's text and the text meant (monospace in the LaTeX, escaped); the
    headline counts them after the slips."""
    from stiefelsym.proofs.slips import SLIPS, SPELLING
    r = result("prep", 3, 1, "exact", "proved")
    md = render_markdown([r], {"whole_catalog": True})
    assert md.index("## Typographical slips") < md.index("## Spelling and punctuation") < md.index("## Summary")
    assert (f"lists {len(SLIPS)} more slips, in passages whose mathematics holds; the section Spelling and "
            f"punctuation lists {len(SPELLING)} slips without mathematical content.") in md
    assert ("- **The references, [44] (source line 3007).** Printed `Semonov-Tian-Shanski`, meant "
            "`Semenov-Tian-Shanski`: ") in md
    assert "Printed `\\{i_1,\\ldots i_k\\}`, meant `\\{i_1,\\ldots, i_k\\}`" in md
    tex = render_latex([r], {"whole_catalog": True})
    assert tex.index(r"\section*{Typographical slips}") < tex.index(r"\section*{Spelling and punctuation}")
    assert (r"Printed \texttt{\char92{}\char123{}i\_1,\allowbreak{}\char92{}ldots i\_k\char92{}\char125{}}"
            in tex)
    assert r"\texttt{Semonov-\allowbreak{}Tian-\allowbreak{}Shanski}" in tex


@pytest.mark.skipif(not PAPER.exists(), reason="the paper is not next to the repository")
def test_every_spelling_slip_is_printed_at_its_lines_of_the_paper():
    """The text a slip of spelling or punctuation quotes stands in the paper's source on each of its lines (a
    range "a–b" read as one text, spaces as one), its correction differs from it, and its place is a section of
    the catalog or outside them (the abstract, the references)."""
    from stiefelsym.proofs import SECTION_TITLES
    from stiefelsym.proofs.slips import SPELLING
    source = PAPER.read_text(encoding="utf-8").split("\n")
    assert len(SPELLING) == 17
    for slip in SPELLING:
        assert slip.printed != slip.meant and slip.where, slip
        assert slip.section in SECTION_TITLES or (not slip.section and slip.where.startswith(("the abstract",
                                                                                               "the references"))), slip
        for part in slip.lines.split(", "):
            first, _, last = part.partition("–")
            text = " ".join(" ".join(source[int(first) - 1:int(last or first)]).split())
            assert " ".join(slip.printed.split()) in text, (slip.lines, part, slip.printed)
    assert len({(s.lines, s.printed) for s in SPELLING}) == len(SPELLING)


def test_every_slip_names_a_section_and_claims_of_the_catalog():
    from stiefelsym.claims import load_catalog
    from stiefelsym.proofs import SECTION_TITLES
    from stiefelsym.proofs.slips import SLIPS
    ids = set(load_catalog().ids())
    for slip in SLIPS:
        assert slip.section in SECTION_TITLES and slip.lines and slip.printed and slip.meant and slip.why
        assert set(slip.claims) <= ids, slip
    assert len({(s.lines, s.printed) for s in SLIPS}) == len(SLIPS)


def test_a_verdict_line_says_where_the_exact_records_are_the_dimension_free_proof_specialised():
    """At the sizes where auto took the dimension-free proof specialised to the size, the record of exact is no
    computation of its own: the one-line verdict says at which sizes it is which."""
    from stiefelsym.reports.report import correction_summary
    spec = ["the dimension-free proof, specialised: the claim's graph at this size is its graph with symbolic sizes "
            "(digest 0123456789ab), whose residual rewriting modulo the constraints reduces to 0 for every n and r",
            "cross-check at this size: the residual vanishes at the modular method's random points"]
    sizes = [(3, 1), (4, 1), (5, 1), (6, 1)]
    rs = [result("a", n, r, "exact", "proved", reductions=spec if n >= 5 else []) for n, r in sizes]
    status, phrases = correction_summary(rs, sizes)
    assert status == "verified"
    assert phrases == ["verified at all 4 computed sizes by exact: its own computation at (3,1), (4,1), the "
                       "dimension-free proof specialised to the size (cross-checked at random points) at (5,1), (6,1)"]
    _, phrases = correction_summary([result("a", n, r, "exact", "proved") for n, r in sizes], sizes)
    assert phrases == ["verified at all 4 computed sizes by exact"]


def test_a_rule_that_names_the_largest_r_computed_says_so():
    """"fails at every computed size with r = 3" where no size with r > 3 was computed would read as "only at
    r = 3": the note says that 3 is the largest r computed; a value inside the range is left as it is."""
    from stiefelsym.reports.report import _fails_holds_text, format_sizes
    sizes = [(n, r) for n in range(1, 7) for r in range(1, min(n, 3) + 1)]
    assert _fails_holds_text([s for s in sizes if s[1] == 3], [s for s in sizes if s[1] != 3]).startswith(
        "fails at every computed size with r = 3 (the largest r computed): (3,3), (4,3), (5,3), (6,3); holds")
    assert _fails_holds_text([s for s in sizes if s[1] == 2], [s for s in sizes if s[1] != 2]).startswith(
        "fails at every computed size with r = 2: (2,2)")
    assert format_sizes([s for s in sizes if s[0] == 6], 2, sizes) == \
        "every computed size with n = 6 (the largest n computed; 3 sizes)"
    assert format_sizes([s for s in sizes if s[0] - 2 * s[1] == 2], 1, sizes) == "every computed size with n = 2r + 2 (2 sizes)"


def test_the_references_say_that_the_appendices_are_sections_9_and_10(results):
    """The report cites the appendices as §9 and §10, as the paper numbers them (Proposition 9.1 is in Appendix 1,
    Theorem 10.1 in Appendix 2): the explanation of the references says so once."""
    import json
    from pathlib import Path
    labels = json.loads((Path(__file__).resolve().parents[1] / "proofs" / "paper_labels.json").read_text("utf-8"))
    assert (labels["YM"]["kind"], labels["YM"]["number"]) == ("Proposition", "9.1")
    assert (labels["dual-D"]["kind"], labels["dual-D"]["number"]) == ("Theorem", "10.1")
    md = render_markdown(results)
    assert "Appendix 1 (magnetic Neumann systems) is Section 9 and Appendix 2 (double, coupled and complex " \
           "systems) is Section 10" in md


def test_the_heading_of_an_erratum_leads_with_the_place_of_its_statement():
    """A statement that is an unlabelled environment (Proposition 4.6) is named in the claim's heading, before the
    labels of the equations it involves, in both documents; a claim without a place keeps its labels alone."""
    rs = [result("metrics", 3, 1, "exact", "fails", expected=True, place="Proposition 4.6 and its proof",
                 erratum="The invariant forms are not only these two."),
          result("prep", 3, 1, "exact", "proved")]
    md, tex = render_markdown(rs), render_latex(rs)
    assert "### `metrics` in Proposition 4.6 and its proof (involves: " in md
    assert re.search(r"^### `prep` \S", md, re.M) and "### `prep` in " not in md
    assert r"\subsection*{\texttt{metrics} in Proposition 4.6 and its proof (involves: " in tex


def test_a_rank_of_zero_is_not_given_a_lower_bound_as_evidence():
    """"rank 0 at a point (rank >= 0 over the function field)" is true of every matrix: the report says there is no
    lower bound instead, and keeps the lower bound of a positive rank."""
    from stiefelsym.reports.report import engine_words
    zero = ("2l: rank 0 at an exact rational point (rank >= 0 over the function field) and 1 kernel vector of the "
            "claim, so rank <= 1 - 1 = 0 over the function field")
    assert engine_words(zero).startswith("2l: no lower bound (none is needed: no rank is below 0) and 1 kernel vector")
    two = "rank 2 at an exact rational point (rank >= 2 over the function field) and 1 kernel vector"
    assert "rank ≥ 2" in __import__("stiefelsym.latex", fromlist=["unicode_words"]).unicode_words(engine_words(two))


def test_an_encoding_of_words_of_the_paper_is_not_headed_as_printed():
    """A display that is the tool's encoding of a sentence of the paper (det X = 1 for "diffeomorphic to SO(n)", a
    size check) is headed as the encoding, with the words the paper prints; a printed formula stays "As printed"."""
    rs = [result("stiefel-top-rank", 1, 1, "exact", "fails", expected=True),
          result("prep", 3, 1, "exact", "fails", expected=True)]
    md = render_markdown(rs)
    assert ("Checked as (the tool's encoding of the printed words “both V\\_{n,n} and V\\_{n,n−1} are diffeomorphic "
            "to SO(n)”, not a formula of the paper):") in md
    assert "As printed:" in md
    tex = render_latex(rs)
    assert r"Checked as (the tool's encoding of the printed words ``both \ensuremath{V_{n,n}}" in tex


def test_one_notation_for_probabilities():
    """Every probability the report prints is m·10⁻ᵏ: the bounds it computes and those in the engine's words."""
    from stiefelsym.reports.report import format_bound, probability_words
    assert format_bound(2.5e-31) == "2.5·10⁻³¹" and format_bound(0) == "0" and format_bound(None) == "–"
    assert probability_words("2 points (chosen so that the bound is <= 1e-30); p 2.5e-31, GF(2^61-1)") == \
        "2 points (chosen so that the bound is ≤ 10⁻³⁰); p 2.5·10⁻³¹, GF(2^61-1)"
    r = result("prep", 4, 2, "modular", "checked", certificate="2 points (chosen so that the bound is <= 1e-30)")
    md = render_markdown([r])
    assert "bound is ≤ 10⁻³⁰) | 0 | 2.9·10⁻³⁴ |" in md and "e-3" not in md


def test_the_encoding_of_printed_words_is_declared_at_the_claim():
    """The words a display encodes (det X = 1 for "diffeomorphic to SO(n)", the size checks) are metadata of the
    claim, declared at it in proofs/ (``@claim(..., encodes=...)``), and the report reads them from there: every
    claim that declares them is headed as their encoding, and no claim without them is."""
    from stiefelsym.claims import load_catalog
    from stiefelsym.reports import report
    catalog = load_catalog()
    declared = {c.id: c.encodes for c in catalog if c.encodes}
    assert declared["stiefel-top-rank"] == "both V_{n,n} and V_{n,n−1} are diffeomorphic to SO(n)"
    assert len(declared) == 8 and all(catalog.get(cid).erratum for cid in declared)
    assert report.encoded_statements() == declared and not hasattr(report, "ENCODED_STATEMENTS")


def test_the_relations_of_a_certificate_are_named_in_the_paper_s_notation():
    """A dimension-free certificate names the relations of its ideal by the engine's names (XtP+PtX, XtX, as the
    results file keeps them); the report prints them as the paper writes them."""
    from stiefelsym.reports.report import certificate_words, hypothesis_words
    assert hypothesis_words("XtP+PtX") == "XᵀP + PᵀX = 0" and hypothesis_words("XtX") == "XᵀX = Iᵣ"
    assert hypothesis_words("UtV-VtU") == "UᵀV = VᵀU" and hypothesis_words("XtAinvP+PtAinvX") == "XᵀA⁻¹P + PᵀA⁻¹X = 0"
    assert hypothesis_words("UdtU+UtUd+VdtV+VtVd") == "U̇ᵀU + UᵀU̇ + V̇ᵀV + VᵀV̇ = 0"
    assert hypothesis_words("res_left:R[lambda]") == "(λIₙ − A)(λIₙ − A)⁻¹ = Iₙ"
    assert hypothesis_words("EleadtElead") == "EleadᵀElead = Iᵣ₋₁"
    assert hypothesis_words("rho:Lambda:1") == "the Sylvester equation of Λ"
    text = certificate_words("cofactor certificate of 6 residual entries (26 terms in the hypotheses XtP+PtX, XtX), "
                             "re-checked")
    assert text == ("cofactor certificate of 6 residual entries (26 terms in the hypotheses XᵀP + PᵀX = 0, XᵀX = Iᵣ), "
                    "re-checked")
    assert certificate_words("hypotheses XtX; re-checked") == "hypotheses XᵀX = Iᵣ; re-checked"
    assert certificate_words("(1 term in the hypotheses (none)), re-checked") == "(1 term in the hypotheses (none)), re-checked"
    rs = [result("prep", None, None, "free", "proved", expected=True,
                 certificate="cofactor certificate of 6 residual entries (26 terms in the hypotheses XtP+PtX, XtX)")]
    assert "hypotheses XᵀP + PᵀX = 0" in render_markdown(rs) and "XtP+PtX" not in render_latex(rs, detail=True)


def test_the_real_form_of_a_complex_chart_is_named_in_the_paper_s_notation():
    """The chart of a complex Stiefel variety is described by the engine as acting by realify(g) Z realify(h)^T on
    (Z, Zdot): the report writes g_ℝ Z h_ℝᵀ on (Z, Ż), and says what g_ℝ is."""
    from stiefelsym.reports.report import engine_words
    from stiefelsym.latex import unicode_words
    text = unicode_words(engine_words("the point (Z, Zdot) of TW(n, r), realified, generic: real (g, h) act on it as "
                                      "realify(g) Z realify(h)^T and leave it anywhere"))
    assert "realify" not in text and "Zdot" not in text
    assert "(Z, Z\u0307)" in text and "g_ℝ Z h_ℝᵀ (g_ℝ: the complex matrix g written as a real one)" in text


def test_a_statement_without_a_label_is_named_once_beside_an_erratum():
    """The place of a misprint that names the statement ("in Proposition 4.6 and its proof") is not followed by
    the same name among the labels it involves; a claim that holds lists it with its labels."""
    tex = render_markdown([result("invariant-metrics", 4, 2, "exact", "fails", expected=True,
                                  place="Proposition 4.6 and its proof"),
                           result("manakov-lax", 3, 1, "exact", "proved")])
    assert "Proposition 4.6)" not in tex and "in Proposition 4.6 and its proof" in tex
    assert any(line.startswith("### `manakov-lax`") and line.endswith(", Theorem 4.3") for line in tex.splitlines())
