"""A claim of a claims file that takes the id of a catalog claim (it shadows it in the run): its records carry the
file's claim's identity, and the reports show it as the file's claim, under a section of its own file, never with
the catalog's labels, section, erratum, place of the misprint, slips or witness script of that id."""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

SHADOWED = "2r-integrals-general-line"      # a catalog erratum with labels, §8, a place, slips and a witness script
LABELLED = "euclidean-flow"                 # a catalog claim of §3, shadowed by a claim that cites a label of §3
OWN = "my-own-id"
CATALOG_CLAIM = "euclidean-multipliers"     # a catalog claim run beside them (§3)

CLAIMS = f'''
from stiefelsym import admissible, claim


@claim("{SHADOWED}", kind="id", sizes=admissible(n_max=2), fails_at=lambda n, r: r >= 2,
       erratum="The file's own statement fails where r >= 2 (a test of shadowing).")
def mine(s):
    """The file's own statement: the block X^T P vanishes."""
    return {{"w": s.X.T @ s.P}}


@claim("{LABELLED}", paper=("Euclidean",), kind="id", sizes=admissible(n_max=2))
def labelled(s):
    """The file's own identity, citing a label of the paper."""
    return {{"w": s.X.T @ s.X - s.Ir}}


@claim("{OWN}", kind="id", sizes=admissible(n_max=2))
def own(s):
    """A claim with an id of its own."""
    return {{"w": s.X.T @ s.X - s.Ir}}
'''


def _invoke(cwd: Path, *args: str):
    from click.testing import CliRunner
    from stiefelsym import cli
    old = os.getcwd()
    os.chdir(cwd)
    try:
        return CliRunner().invoke(cli.main, list(args), prog_name="stiefelsym")
    finally:
        os.chdir(old)


@pytest.fixture(scope="module")
def shadow_run(tmp_path_factory):
    d = tmp_path_factory.mktemp("shadow")
    (d / "shadow.py").write_text(CLAIMS, encoding="utf-8")
    out = _invoke(d, "verify", SHADOWED, LABELLED, OWN, CATALOG_CLAIM, "--claims", "shadow.py",
                  "--size", "1,1", "--size", "2,1", "--size", "2,2", "--report-dir", "rep", "--jobs", "1")
    assert out.exit_code == 0, out.output
    assert "has the id of a catalog claim" in out.output
    return d


@pytest.fixture(scope="module")
def catalog_claims():
    from stiefelsym.claims import load_catalog
    cat = load_catalog()
    return {cid: cat.get(cid) for cid in (SHADOWED, LABELLED, CATALOG_CLAIM)}


def _records(d: Path) -> list[dict]:
    return json.loads((d / "rep" / "results.json").read_text(encoding="utf-8"))["results"]


def _catalog_words(c) -> list[str]:
    """What of a catalog claim's identity must not be attached to a claims file's claim of its id."""
    words = [c.title, c.erratum, c.place, *c.slips]
    return [w for w in words if w and len(w) > 12]


def _section(md: str, heading: str) -> str:
    """The text of one ``## `` section of the Markdown report."""
    m = re.search(rf"^## {re.escape(heading)}\n(.*?)(?=^## |\Z)", md, re.M | re.S)
    assert m, f"no section {heading!r}"
    return m.group(1)


def test_records_carry_the_files_claim(shadow_run, catalog_claims):
    recs = _records(shadow_run)
    by = {}
    for r in recs:
        by.setdefault(r["claim"], []).append(r)
    cat = catalog_claims[SHADOWED]
    for r in by[SHADOWED]:
        assert r["shadows"] is True
        assert r["paper"] == [] and r["section"] == "" and r["place"] == "" and r["slips"] == []
        assert r["title"] != cat.title and r["erratum"] in ("", "The file's own statement fails where r >= 2 "
                                                                 "(a test of shadowing).")
        assert "--claims shadow.py" in r["rerun"]
    assert any(r["verdict"] == "fails" and r["erratum"] for r in by[SHADOWED])
    for r in by[LABELLED]:
        assert r["shadows"] is True and r["paper"] == ["Euclidean"]
        assert r["title"] != catalog_claims[LABELLED].title
    # a claim of the file with an id of its own, and the catalog's claim: no such key
    assert all("shadows" not in r for r in by[OWN] + by[CATALOG_CLAIM])
    text = (shadow_run / "rep" / "results.json").read_text(encoding="utf-8")
    for w in _catalog_words(cat):
        assert json.dumps(w)[1:-1] not in text
    # no witness script of the catalog's erratum is written for the file's claim
    assert not (shadow_run / "rep" / "witnesses" / f"{SHADOWED}.py").exists()


def test_markdown_shows_the_files_claim_under_its_file(shadow_run, catalog_claims):
    md = (shadow_run / "rep" / "verification.md").read_text(encoding="utf-8")
    mine = _section(md, "Claims of shadow.py with the ids of catalog claims")
    assert f"### `{SHADOWED}`" in mine and f"### `{LABELLED}`" in mine
    assert mine.count("it has the id of a catalog claim, which it replaced in this run") == 2
    assert "not the paper's statement of that id" in mine
    # the paper's sections hold the catalog's claim only
    geodesic = _section(md, "§3 Geodesic flows")
    assert f"### `{CATALOG_CLAIM}`" in geodesic and f"`{LABELLED}`" not in geodesic
    assert "## §8" not in md
    # the headline says it, and the list of failures names whose claim fails
    head = md.split("## What the verdicts mean")[0]
    said = re.search(r"2 of the claims verified \(([^)]*)\) are claims of a claims file with the id of a catalog "
                     r"claim, which they replaced in this run", head)
    assert said and set(said.group(1).split(", ")) == {SHADOWED, LABELLED}
    assert f"`{SHADOWED}` (the claim of shadow.py, not the catalog's)" in head
    # the summary files them under their file, with no section of the paper
    assert "| Claims of shadow.py with the ids of catalog claims | 2 |" in md
    row = next(line for line in md.splitlines() if line.startswith(f"| `{LABELLED}` |"))
    assert row.split(" | ")[2] == "–"
    # nothing of the catalog's claim of that id: its words, its witness script, a note for the paper's authors
    for w in _catalog_words(catalog_claims[SHADOWED]) + _catalog_words(catalog_claims[LABELLED]):
        assert w not in md
    assert f"witnesses/{SHADOWED}.py" not in md
    errata = _section(md, "Errata")
    assert "Note for the authors" not in errata and "In §" not in errata


def test_latex_shows_the_files_claim_under_its_file(shadow_run, catalog_claims):
    for name in ("verification.tex", "verification-runs.tex"):
        tex = (shadow_run / "rep" / name).read_text(encoding="utf-8")
        assert r"\section*{Claims of shadow.py with the ids of catalog claims}" in tex
        mine = tex.split(r"\section*{Claims of shadow.py with the ids of catalog claims}")[1]
        assert r"\texttt{" + SHADOWED + "}" in mine and r"\texttt{" + LABELLED + "}" in mine
        assert "which it replaced in this run" in tex
        assert f"witnesses/{SHADOWED}.py" not in tex
        assert r"\section*{\ensuremath{\S}8" not in tex and "§8" not in tex
        for w in _catalog_words(catalog_claims[SHADOWED]):
            assert w not in tex


def test_latex_report_compiles(shadow_run, tmp_path):
    if shutil.which("pdflatex") is None:
        pytest.skip("pdflatex is not installed (Debian: texlive-latex-base texlive-latex-recommended)")
    for name in ("verification", "verification-runs"):
        shutil.copy(shadow_run / "rep" / f"{name}.tex", tmp_path / f"{name}.tex")
        for _ in range(2):
            proc = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape",
                                   f"{name}.tex"], cwd=tmp_path, capture_output=True, text=True, timeout=120,
                                  stdin=subprocess.DEVNULL)
            assert proc.returncode == 0, proc.stdout[-3000:]
        log = (tmp_path / f"{name}.log").read_text(errors="replace")
        assert "Undefined control sequence" not in log


def test_junit_files_no_shadowing_record_under_the_papers_section(shadow_run):
    import xml.etree.ElementTree as ET
    from stiefelsym.reports.report import render_junit
    from stiefelsym.results import load_results
    _, results = load_results(shadow_run / "rep" / "results.json")
    root = ET.fromstring(render_junit(results))      # (results.json keeps no timings: 0.000 s each)
    for suite in root.iter("testsuite"):
        names = [case.get("name") for case in suite.iter("testcase")]
        if suite.get("name") == "section 3":
            assert names and not any(n.startswith(LABELLED) for n in names)


def test_report_again_and_check(shadow_run, tmp_path):
    rep = shadow_run / "rep"
    out = _invoke(shadow_run, "report", "--results", str(rep / "results.json"), "--report-dir", str(tmp_path / "again"))
    assert out.exit_code == 0, out.output
    for name in ("verification.md", "verification.tex", "verification-runs.tex"):
        assert (tmp_path / "again" / name).read_bytes() == (rep / name).read_bytes(), name
    out = _invoke(shadow_run, "check", str(rep / "results.json"))
    assert out.exit_code == 0 and "0 rejected" in out.output, out.output


def _rewritten(shadow_run: Path, tmp_path: Path, edit) -> Path:
    payload = json.loads((shadow_run / "rep" / "results.json").read_text(encoding="utf-8"))
    for r in payload["results"]:
        edit(r)
    f = tmp_path / "results.json"
    f.write_text(json.dumps(payload, indent=1), encoding="utf-8")
    return f


def test_a_record_without_the_flag_gets_it_from_the_claims(shadow_run, tmp_path):
    # a results file written before records carried the flag is rendered as the claims loaded now say
    f = _rewritten(shadow_run, tmp_path, lambda r: r.pop("shadows", None))
    out = _invoke(shadow_run, "report", "--results", str(f), "--report-dir", str(tmp_path / "old"))
    assert out.exit_code == 0, out.output
    assert (tmp_path / "old" / "verification.md").read_bytes() == (shadow_run / "rep" / "verification.md").read_bytes()


@pytest.mark.parametrize("who,value", [(SHADOWED, False), (CATALOG_CLAIM, True), (OWN, True)])
def test_an_edited_flag_is_refused(shadow_run, tmp_path, who, value):
    def edit(r):
        if r["claim"] == who:
            r["shadows"] = value
    f = _rewritten(shadow_run, tmp_path, edit)
    out = _invoke(shadow_run, "report", "--results", str(f), "--report-dir", str(tmp_path / "edited"))
    if value:
        # a record of the catalog, or of a claim with an id of its own, said to be a shadowing claim's
        assert out.exit_code == 2 and "refused" in out.output and "catalog claim" in out.output, out.output
    else:
        # a flag taken off (read as a record written before records carried it): rendered as the claims say
        assert out.exit_code == 0, out.output
        assert (tmp_path / "edited" / "verification.md").read_bytes() == \
            (shadow_run / "rep" / "verification.md").read_bytes()
    out = _invoke(shadow_run, "check", str(f), "--no-rerun")
    assert out.exit_code == 1 and "REJECTED" in out.output and "catalog claim" in out.output, out.output


def test_a_catalog_run_has_no_flag_and_renders_as_before():
    """A record of the catalog carries no key ``shadows``: a catalog run's results file, and its reports, are
    what they were before records could carry it."""
    from stiefelsym.results import Result, dump_results
    r = Result(claim="x", paper=["Euclidean"], section="3", kind="id", title="t", statement="", n=2, r=1,
               method="exact", verdict="proved", expected=True, seconds=0.0, seed=None)
    assert "shadows" not in r.to_json() and '"shadows"' not in dump_results([r], {})
    r.shadows = True
    assert r.to_json()["shadows"] is True and '"shadows": true' in dump_results([r], {})


def test_a_files_claim_keeps_its_own_slips(tmp_path):
    """The identity a file's decorator gives a claim reaches its records whole: its slips too (they were lost on
    the way from the file's interpreter)."""
    from stiefelsym.run.userfile import load_claims_isolated
    f = tmp_path / "slips.py"
    f.write_text('from stiefelsym import admissible, claim\n\n\n'
                 '@claim("my-slip", kind="id", sizes=admissible(n_max=2), fails_at=lambda n, r: r >= 2,\n'
                 '       erratum="mine fails", slips=("my own slip of a passage",))\n'
                 'def mine(s):\n    """Mine."""\n    return {"w": s.X.T @ s.P}\n', encoding="utf-8")
    (c,) = list(load_claims_isolated(f, []))
    assert c.slips == ("my own slip of a passage",) and not c.reviewed
