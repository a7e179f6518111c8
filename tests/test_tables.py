"""stiefelsym tables: the paper's dimensions against the computation (known cases, a wrong formula
is flagged, the known disagreements as closed forms), the three files, bad input, and the LaTeX
compiling on its own."""
import json
import shutil
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import pytest

from stiefelsym.reports import tables
from stiefelsym.methods.dimensions import exact

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def small():
    """The tables for n <= 4 (a few seconds)."""
    return tables.compute_tables(4, seed=0)


def _row(T, n, r, key):
    return next(row for row in T.rows[(n, r)] if row.key == key)


def test_known_values(small):
    assert _row(small, 4, 2, "dimV").cert.value == 5
    assert _row(small, 4, 2, "dimV").cert.proved
    assert _row(small, 3, 1, "2l").cert.value == 2
    assert _row(small, 4, 1, "2l").cert.value == 4          # n > 2r + 1: 2r(n − r − 1)
    assert _row(small, 4, 2, "KER").cert.value == 8 and _row(small, 4, 2, "KER").cert.proved
    assert _row(small, 4, 4, "A2").cert.value == 4
    assert _row(small, 4, 3, "torus").cert.value == tables.torus_printed(4, 3)


def test_proved_upper_sides_from_polynomial_kernels(small):
    """(dimension): the solutions of (L1), (L2) lie in ker Λ1 identically over ℤ[P]; 2l where the orbit is
    regular: the odd powers of Φ."""
    for (n, r) in small.rows:
        assert _row(small, n, r, "leaf").cert.proved, (n, r)
    assert _row(small, 4, 2, "2l").cert.proved and not _row(small, 4, 1, "2l").cert.proved


def test_every_printed_dimension_formula_agrees_except_the_errata(small):
    allowed = {"regular", "invariant_forms", "N_vs_l", "N_dependent", "leaf_singular", "L5L6"}
    for (n, r), rows in small.rows.items():
        for row in rows:
            if row.key not in allowed:
                assert row.agree is not False, (n, r, row.key, row.printed, row.cert.describe())


def test_every_checked_value_has_a_small_false_pass_bound(small):
    for rows in small.rows.values():
        for row in rows:
            assert row.cert.value is not None
            assert row.cert.false_probability <= 1e-30   # a difference of ranks adds the bounds of both
            assert row.cert.kind in ("proved", "checked")


def test_the_disagreements_are_the_closed_forms(small):
    checks = small.formula_check()
    assert checks["regular"]["sizes"] == [(4, 1)]
    assert checks["leaf_singular"]["sizes"] == [(1, 1), (2, 1)]
    assert checks["L5L6"]["sizes"] == [(3, 3), (4, 3), (4, 4)]
    assert checks["invariant_forms"]["sizes"] == [(4, 2), (4, 3), (4, 4)]
    assert checks["N_dependent"]["sizes"] == [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (4, 1), (4, 2)]
    assert all(c["matches_formula"] for c in checks.values())


def test_the_dual_lax_integrals_are_independent_only_for_r_at_most_2():
    for (n, r), dependent in (((4, 2), 0), ((5, 3), 1)):
        rows = {x.key: x for x in tables.compute_size(n, r, include={"N_rank", "N_dependent", "torus"})}
        assert rows["N_dependent"].cert.value == dependent
        assert rows["N_rank"].cert.value == rows["torus"].cert.value     # = l + [r/2]


def test_a_wrong_formula_is_flagged():
    cert = exact("2l", 4, "count")
    assert tables._cmp(4, cert) is True
    assert tables._cmp(5, cert) is False
    assert tables._cmp(Fraction(9, 2), cert) is False
    assert tables._cmp(None, cert) is None


def test_a_closed_form_that_misses_a_size_is_reported(small, monkeypatch):
    monkeypatch.setitem(tables.KNOWN_DISAGREEMENTS, "regular", ("n = 2r + 3", lambda n, r: n == 2 * r + 3))
    check = small.formula_check()["regular"]
    assert not check["matches_formula"] and check["mismatch"] == [(4, 1)]


def test_the_invariant_metrics_erratum_occurs_for_every_n_at_r_4():
    for n in (5, 6):
        row = next(x for x in tables.compute_size(n, 4, include={"invariant_forms"}) if x.key == "invariant_forms")
        assert (row.printed, row.cert.value, row.agree) == (2, 3, False)


def test_the_second_case_of_lemma_2l_at_r_2():
    rows = {x.key: x for x in tables.compute_size(7, 2, include={"2l", "regular"})}   # n = 2r + 3
    assert rows["2l"].printed == 2 * 2 * (7 - 2 - 1) and rows["2l"].agree


def _write(run, *args):
    return run("tables", *args)


def test_the_command_writes_the_files(run, tmp_path):
    res = _write(run, "--report-dir", "out", "--n-max", "3", "--extended-n-max", "3")
    assert res.exit_code == 0, res.output
    out = tmp_path / "out"
    for name in ("tables.md", "tables.tex", "tables.json", "tables-standalone.tex"):
        assert (out / name).is_file()
    data = json.loads((out / "tables.json").read_text())
    assert data["n_max"] == 3 and len(data["sizes"]) == 6
    assert "Disagreements" in (out / "tables.md").read_text()
    assert r"\toprule" in (out / "tables.tex").read_text()


def test_the_verdict_matrix_is_read_from_a_results_file(run, tmp_path):
    results = tmp_path / "r.json"
    results.write_text(json.dumps({"meta": {}, "results": [
        {"claim": "c1", "n": 2, "r": 1, "method": "exact", "verdict": "proved", "expected": True, "variant": None},
        {"claim": "c1", "n": None, "r": None, "method": "free", "verdict": "undecided", "expected": True},
        {"claim": "c2", "n": 2, "r": 1, "method": "modular", "verdict": "fails", "expected": False}]}))
    res = _write(run, "--report-dir", "out", "--size", "2,1", "--results", str(results))
    assert res.exit_code == 0, res.output
    md = (tmp_path / "out" / "tables.md").read_text()
    assert "| `c1` |" in md and "F!" in md


def test_every_verdict_matrix_names_its_run_and_another_runs_matrix_says_so():
    """Above each matrix: the commit, command, claims and records of its run; a matrix of another commit or
    catalog than the first (the main results file) says so, and which one the report is rendered from."""
    def rec(claim, statement="S"):
        return {"claim": claim, "statement": statement, "n": 2, "r": 1, "method": "exact", "verdict": "proved",
                "expected": True}
    main = tables.verdict_matrix([rec("c1"), rec("c2"), dict(rec("c2"), variant="v")],
                                 {"commit": "aaaa", "command": "stiefelsym verify --max-n 2"})
    same = tables.verdict_matrix([rec("c1"), rec("c2")], {"commit": "aaaa"})
    older = tables.verdict_matrix([rec("c1", "T")], {"commit": "bbbb+dirty"})
    md = "\n".join(tables.verdict_markdown({"reports/results.json": main, "same.json": same, "old.json": older}))
    assert ("From the run of commit aaaa (`stiefelsym verify --max-n 2`): 2 claims, 3 records." in md
            and "From the run of commit aaaa: 2 claims, 2 records." in md)
    assert md.count("This is another run") == 1
    assert ("**This is another run than that of reports/results.json**: it is of commit bbbb+dirty, not aaaa, and of "
            "another catalog (1 claim against 2; 1 claim of reports/results.json is not in it).") in md
    assert "the report (verification.md) is rendered from reports/results.json" in md


@pytest.mark.parametrize("args, message", [
    (("--size", "2,3"), "needs r <= n"),
    (("--size", "3,0"), "needs r >= 1"),
    (("--size", "x"), "is not a size"),
    (("--n-max", "0"), "--n-max"),
    (("--results", "missing.json"), "not found"),
])
def test_bad_input_exits_2_with_one_line(run, args, message):
    res = _write(run, "--report-dir", "out", *args)
    assert res.exit_code == 2
    lines = [x for x in res.output.splitlines() if x.strip()]
    assert len(lines) == 1 and message in lines[0], res.output


def test_an_unreadable_results_file_exits_2(run, tmp_path):
    (tmp_path / "bad.json").write_text("{not json")
    res = _write(run, "--report-dir", "out", "--size", "2,1", "--results", "bad.json")
    assert res.exit_code == 2 and "not a stiefelsym results file" in res.output


def test_bad_input_as_a_subprocess(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "stiefelsym", "tables", "--size", "2,3",
                           "--report-dir", str(tmp_path)], capture_output=True, text=True, cwd=ROOT)
    assert proc.returncode == 2 and proc.stdout == ""
    assert len(proc.stderr.strip().splitlines()) == 1


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_the_latex_compiles_on_its_own(run, tmp_path):
    assert _write(run, "--report-dir", "out", "--n-max", "3", "--extended-n-max", "3").exit_code == 0
    out = tmp_path / "out"
    proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "tables-standalone.tex"],
                          cwd=out, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout[-2000:]
    assert (out / "tables-standalone.pdf").is_file()


def test_tables_text_prints_inequalities_and_squares_in_the_default_font():
    """In the default (OT1) text font a bare < prints as ¡ and ² needs a bitmap font: the tables' words set
    them in math; the standalone wrapper asks for no font package whose glyphs are bitmaps here."""
    from stiefelsym.reports.tables import STANDALONE, _tex, _tex_title
    assert _tex("r = 1 and n <= 2 (2l = n² - n), r >= 3, a < b") == \
        r"r = 1 and n $\le$ 2 (2l = n$^2$ - n), r $\ge$ 3, a $<$ b"
    assert _tex_title("§2–§4") == r"\ensuremath{\S}2--\ensuremath{\S}4"
    assert "fontenc" not in STANDALONE and r"\labelitemi" in STANDALONE


def test_the_latex_states_the_range_of_the_rows_as_the_markdown_does(small):
    """Rows beyond n_max (to the extended n_max, without the completeness checks) are announced in the
    PDF's heading as in the Markdown's title: never "n <= 9" above rows at n = 12."""
    import copy
    T = copy.copy(small)
    T.extended_n_max = 6
    tex, md = tables.render_latex(T, {}), tables.render_markdown(T, {})
    assert r"\paragraph{Dimensions, printed against computed ($n\le 4$; $n\le 6$ without the completeness checks).}" in tex
    assert r"For $4 < n\le 6$ the columns of completeness checks" in tex
    assert "(n ≤ 4; n ≤ 6 without the completeness checks)" in md.splitlines()[0]
    T.extended_n_max = 4
    assert r"\paragraph{Dimensions, printed against computed ($n\le 4$).}" in tables.render_latex(T, {})


def test_the_columns_cite_the_places_of_the_paper_they_compute():
    """(A1) is the first condition in the proof of Lemma 6.3 (not the label A2, the equation (11) §6 of the
    second condition); the invariant metrics are Proposition 4.6 in §4; the Lax matrix whose integrals N
    indep. counts is the display (2) §8, not (3) §8 (LA4), which holds the matrices 𝓐*_neum."""
    labels = json.loads((ROOT / "proofs" / "paper_labels.json").read_text(encoding="utf-8"))
    assert tables.QUANTITIES["A1"][0] == tables.QUANTITIES["A1_t"][0] == "LEMA2"
    assert (labels["LEMA2"]["kind"], labels["LEMA2"]["number"]) == ("Lemma", "6.3")
    assert "(LA4)" not in tables.QUANTITIES["N_rank"][1] and "(2) §8" in tables.QUANTITIES["N_rank"][1]
    assert (labels["LA4"]["number"], labels["LA4"]["section"]) == ("3", "8")
    assert any(title.startswith("§4, §7, §8: invariant metrics") for title, _ in tables.GROUPS)


def test_the_prose_prints_the_papers_numbers_not_its_label_keys(small):
    """The tables' words cite the paper by its printed numbers (Lemma 2.5, (16), (17) §6, Theorem 7.1), and keep
    the names of the conditions (A1), (A2) of the proof of Lemma 6.3; the rows of numbers are untouched."""
    md = tables.render_markdown(small, {})
    prose = "\n".join(line for line in md.splitlines() if not line.startswith("| ("))
    for key in ("Lemma 2l", "LEMA1", "LEMA2", "(dim_fol)", "(dimension)", "NEUMANN2", "(L5)", "(L6)", "KER"):
        assert key not in prose, key
    assert "Lemma 2.5" in prose and "(16), (17) §6" in prose and "Theorem 7.1" in prose
    assert "**(A2)** (A2):" in md and "(A1) t=−1" in md
    tex = tables.render_latex(small, {})
    assert "LEMA2" not in tex and "(16), (17) c." in tex
