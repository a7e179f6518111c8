"""Catalog integrity: ids, paper labels, coverage of CLAIMS.md, presence in the report."""
import re
from pathlib import Path

import pytest


ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
PAPER = SHARED / "paper" / "fedorov-jovanovic-stiefel.tex"
CLAIMS_MD = SHARED / "CLAIMS.md"
#: sections of CLAIMS.md the catalog covers (all of them)
COVERED = ("§2", "§3", "§4", "§5", "§6", "§7", "§8", "Appendix 1", "Appendix 2")
#: dimension statements checked by `stiefelsym tables` (formula against exact computation at every
#: 1 <= r <= n <= 12) rather than by a claim
TABLE_ONLY = {"NEUMANN2"}


def _paper_labels():
    return set(re.findall(r"\\label\s*\{([^}]*)\}", PAPER.read_text(encoding="utf-8")))


def _claims_md_labels(section_prefix):
    text = CLAIMS_MD.read_text(encoding="utf-8")
    out = set()
    for block in re.split(r"^## ", text, flags=re.M):
        if block.startswith(section_prefix):
            out |= set(re.findall(r"`([^`]+)`", block))
    return out


def test_ids_are_unique_and_kebab_case(catalog):
    ids = catalog.ids()
    assert len(ids) == len(set(ids))
    for cid in ids:
        assert re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)*", cid), cid


@pytest.mark.skipif(not PAPER.exists(), reason="the paper is not next to the repository")
def test_every_paper_label_exists_in_the_tex(catalog):
    labels = _paper_labels()
    for c in catalog:
        for lab in c.paper:
            assert lab in labels, f"{c.id}: no \\label{{{lab}}} in the paper"


@pytest.mark.skipif(not CLAIMS_MD.exists(), reason="CLAIMS.md is not next to the repository")
@pytest.mark.parametrize("section", COVERED)
def test_every_listed_label_is_covered(catalog, section):
    used = {lab for c in catalog for lab in c.paper}
    paper = _paper_labels()
    missing = sorted(lab for lab in _claims_md_labels(section)
                     if lab in paper and lab not in used and lab not in TABLE_ONLY)
    assert not missing, f"CLAIMS.md {section} items without a claim: {missing}"


def test_table_only_labels_are_in_the_tables():
    from stiefelsym.reports import tables
    source = Path(tables.__file__).read_text(encoding="utf-8")
    for lab in TABLE_ONLY:
        assert f'"{lab}"' in source, lab


def test_claims_are_documented(catalog):
    for c in catalog:
        assert c.title and c.statement, c.id
        assert c.kind in ("id", "lax", "pb", "dim", "not", "geo")
        from stiefelsym.proofs import SECTION_TITLES
        assert c.section in SECTION_TITLES, c.id


def test_every_claim_appears_in_the_report(catalog):
    from stiefelsym.reports.report import render_latex, render_markdown
    from stiefelsym.results import Result
    results = [Result(claim=c.id, paper=list(c.paper), section=c.section, kind=c.kind, title=c.title,
                      statement=c.statement, n=3, r=1, method="modular", verdict="checked", expected=True,
                      seconds=0.0, seed=0) for c in catalog]
    md, tex = render_markdown(results, {}), render_latex(results, {})
    for c in catalog:
        assert c.id in md and c.id in tex


def _run_catalog(catalog, n_max, methods):
    from stiefelsym.run.runner import verify
    sizes = sorted({s for c in catalog for s in c.sizes if s.n <= n_max}, key=lambda s: (s.n, s.r))
    return verify(list(catalog), sizes=sizes, methods=methods, seed=0)


def test_catalog_verdicts_are_as_expected_for_small_sizes(catalog):
    results = _run_catalog(catalog, 3, ("auto", "free"))
    bad = [r.line() for r in results if not r.expected]
    assert not bad, bad
    assert {r.claim for r in results} == set(catalog.ids())


@pytest.mark.slow
def test_catalog_verdicts_are_as_expected_with_every_method(catalog):
    """Every method at every size n <= 5; the exact method within each claim's symbolic budget
    (exact_max_n, as `auto` uses it: beyond it a forced exact run may spend its whole time limit)."""
    from stiefelsym.run.runner import verify
    results = _run_catalog(catalog, 5, ("modular", "rational", "float", "free"))
    for c in catalog:
        sizes = [z for z in c.sizes if z.n <= min(5, c.exact_max_n)]
        if sizes:
            results += verify([c], sizes=sizes, methods=("exact",), seed=0)
    bad = [r.line() for r in results if not r.expected and r.verdict != "inconclusive"]
    assert not bad, bad


def _printed_environments() -> set[str]:
    """The numbered theorem-like items of the paper as printed ("Theorem 7.1", "Remark 4.2"): theorems,
    propositions, lemmas and corollaries share one counter per section, remarks have their own."""
    names = {"thm": "Theorem", "prop": "Proposition", "lem": "Lemma", "cor": "Corollary", "remark": "Remark"}
    out, section, counts = set(), 0, {}
    for m in re.finditer(r"^\\section\{|\\begin\{(thm|prop|lem|cor|remark)\}", PAPER.read_text(encoding="utf-8"),
                         flags=re.M):
        if m.group(1) is None:
            section, counts = section + 1, {}
            continue
        counter = "remark" if m.group(1) == "remark" else "thm"
        counts[counter] = counts.get(counter, 0) + 1
        out.add(f"{names[m.group(1)]} {section}.{counts[counter]}")
    return out


@pytest.mark.skipif(not PAPER.exists(), reason="the paper is not next to the repository")
def test_every_place_of_a_misprint_names_what_the_paper_prints(catalog):
    """A place of a misprint ("the proof of Theorem 7.1") names numbered items the paper prints, equations by their
    printed number and section ("(17) §6", as the labels are printed), and paragraphs by their printed title."""
    from stiefelsym import paperref
    printed = _printed_environments()
    table = paperref.table()
    for label, ref in table.items():       # the count agrees with the paper's own numbers where a label gives them
        if ref["kind"] in ("Theorem", "Proposition", "Lemma", "Corollary"):
            assert f"{ref['kind']} {ref['number']}" in printed, label
    equations = {f"({ref['number']}) §{ref['section']}" for ref in table.values() if ref["kind"] == "equation"}
    titles = {" ".join(t.split()) for t in re.findall(r"\\paragraph\{([^}]*)\}", PAPER.read_text(encoding="utf-8"))}
    placed = [c for c in catalog if c.place]
    assert len(placed) >= 9
    for c in placed:
        for item in re.findall(r"(?:Theorem|Proposition|Lemma|Corollary|Remark) \d+\.\d+", c.place):
            assert item in printed, f"{c.id}: the paper has no {item}"
        for eq in re.findall(r"\(\d+\) §\d+", c.place):
            assert eq in equations, f"{c.id}: the paper numbers no equation {eq}"
        for title in re.findall(r"“([^”]*)”", c.place):
            if "…" not in title:
                assert any(t.rstrip(".").replace("--", "–") == title for t in titles), f"{c.id}: no paragraph {title!r}"
        assert not re.search(r"\bp\.\s*\d", c.place), c.id


def test_a_label_in_an_unnumbered_row_is_named_by_its_displays_number():
    """The paper's \\label{so(n,n)} sits in a \\notag row of its gather, and amsmath gives it the next equation's
    number (10), that of (LA3*C); the display carries (9), which the reports name (the referee of stop 69)."""
    from stiefelsym import paperref
    tex = ("\\section{A}\\begin{equation}a\\label{one}\\end{equation}\n\\begin{gather}\\label{pair}\n"
           "\\dot L = [L, A], \\notag \\\\\n L = \\begin{pmatrix} a & b \\\\ c & d \\end{pmatrix}, \\\\\n"
           " A = L_+ \\notag\n\\end{gather}\n\\begin{equation}b\\label{next}\\end{equation}\n")
    moved = paperref._labels_on_numbered_rows(tex)
    rows = paperref._rows(moved[moved.index("\\begin{gather}") + len("\\begin{gather}"):moved.index("\\end{gather}")])
    assert len(rows) == 3 and "\\label{pair}" not in rows[0] and rows[1].endswith("\\label{pair}")
    assert paperref._labels_on_numbered_rows(tex.replace("\\notag", "")) == tex.replace("\\notag", "")
    assert paperref.table()["so(n,n)"]["number"] == "9" and paperref.table()["LA3*C"]["number"] == "10"


def _without_typewriter(tex: str) -> str:
    """LaTeX with every \\texttt{...} group taken out (code and labels set in typewriter type)."""
    out, i = [], 0
    while i < len(tex):
        if tex.startswith(r"\texttt{", i):
            i, depth = i + len(r"\texttt{"), 1
            while i < len(tex) and depth:
                depth += {"{": 1, "}": -1}.get(tex[i], 0) if tex[i - 1] != "\\" else 0
                i += 1
            out.append(" ")
        else:
            out.append(tex[i])
            i += 1
    return "".join(out)


@pytest.mark.skipif(not PAPER.exists(), reason="the paper is not next to the repository")
def test_no_title_leaves_a_script_in_the_text_font(catalog):
    """A title's scripts are set in math (tex_words): an underscore left in the text is only the paper's name of a
    label (dot_XP2, Gen_Chasles), and no letter of the text carries a script set in math (X_rX_r once printed
    X\\_r X$_r$: a script glued to the next letter is not read as one; E_jE_j, α_iF_i, F_Ωė, R_λU the same)."""
    from stiefelsym.latex import tex_words
    labels = _paper_labels()
    bad = []
    for c in catalog:
        tex = _without_typewriter(tex_words(c.title))
        for m in re.finditer(r"[\w*]*\\_[\w*]*", tex):
            if m.group(0).replace("\\_", "_") not in labels:
                bad.append((c.id, tex[max(0, m.start() - 30):m.end() + 30]))
        bad += [(c.id, m.group(0)) for m in re.finditer(r"[A-Za-z]\\ensuremath\{_\{[^}]*\}\}", tex)]
    assert not bad, bad


def test_every_statement_is_set_as_mathematics(catalog):
    """A statement the report cannot set as a display (math_ok: balanced, the vocabulary of mathematics, a
    grammatical formula; H_\\mathbb A is not, H_{\\mathbb A} is) would be printed as plain text."""
    from stiefelsym.latex import math_ok
    assert [c.id for c in catalog if not math_ok(c.statement)] == []
