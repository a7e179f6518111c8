"""The paper's own numbers: every label the catalog cites is numbered as the paper prints it, and
the committed table is what compiling the paper gives."""
import shutil
from pathlib import Path

import pytest

from stiefelsym import paperref
from stiefelsym.claims import load_catalog

PAPER = Path(__file__).resolve().parents[2] / "shared" / "paper" / "fedorov-jovanovic-stiefel.tex"


def test_every_catalog_label_has_the_papers_number():
    table = paperref.table()
    missing = sorted({p for c in load_catalog() for p in c.paper} - set(table))
    assert not missing


def test_references_print_as_the_paper_prints_them():
    assert paperref.printed("cond_XP") == "(4) §2"
    assert paperref.printed("NEUMANN2") == "Theorem 7.1"
    assert paperref.printed("tangency") == "Proposition 8.4"
    assert paperref.printed("not-a-label") == "(not-a-label)"


def test_an_unnumbered_display_is_named_by_its_section_not_its_page():
    """A display has no number of its own, and its page depends on the paper's build: it is named by the
    section it stands in, counted in the source (the appendices are §9 and §10)."""
    assert paperref.printed("VVB") == "unnumbered display in §8"
    assert paperref.printed("P_p") == "unnumbered display in §8"
    assert paperref.printed("LA4*C") == "unnumbered display in §10"
    assert paperref._source_sections("\\section{A} \\label{a} \\section*{B} \\label{b} \\section{C} \\label{c}") \
        == {"a": "1", "b": "1", "c": "2"}


@pytest.mark.skipif(not PAPER.exists() or shutil.which("pdflatex") is None,
                    reason="the paper's source or pdflatex is not here")
def test_the_committed_table_is_what_the_paper_compiles_to():
    assert paperref.build(PAPER) == paperref.table()


def test_prose_cites_the_printed_numbers():
    """The reports' words cite the paper as it prints its numbers: an equation's key in parentheses becomes
    "(5) §4" ("(5) of Section 4" in a statement, LaTeX, where an underscore is written \\_), a theorem-like
    label after its kind becomes the theorem's number; keys the table does not know, equations named after
    a theorem's word, and words that only begin like a key stay as they are."""
    from stiefelsym.paperref import readable
    assert readable("the Manakov flow (dot_XP3*) (B = A²)") == "the Manakov flow (5) §4 (B = A²)"
    assert readable(r"\text{along (dot\_XP3*)}", statement=True) == r"\text{along (5) of Section 4}"
    assert readable("Theorem man-dual: the flow") == "Theorem 4.4: the flow"
    assert readable("by (DUAL)") == "by (Theorem 8.1)"
    assert readable("(foo) and Theorem man and (NEUMANN2x) and Lemma 2lx") == \
        "(foo) and Theorem man and (NEUMANN2x) and Lemma 2lx"
    # plurals with a list of labels, each a theorem of that kind (else the words stay as they are)
    assert readable("Theorems DUAL and man-dual say") == "Theorems 8.1 and 4.4 say"
    assert readable("Lemmas LEMA1, LEMA2 and 2l") == "Lemmas 6.2, 6.3 and 2.5"
    assert readable("Theorems DUAL and LEMA1") == "Theorems DUAL and LEMA1"
    assert readable("Theorems DUAL and man-dualx") == "Theorems DUAL and man-dualx"


def test_the_conditions_the_paper_names_keep_their_names():
    """(A1), (A2) are the names the proof of Lemma 6.3 gives its two conditions; the label A2 is also the
    equation (11) §6 that states the second.  With the keep-list they stay as printed, while (L5), a label of an
    equation the paper prints as (16), becomes its number."""
    from stiefelsym.paperref import CONDITION_NAMES, readable
    assert readable("(A2) and (L5)") == "(11) §6 and (16) §6"
    assert readable("(A1), (A2) and (L5)", keep=CONDITION_NAMES) == "(A1), (A2) and (16) §6"


def test_the_reports_keep_the_keys_in_their_records():
    """Only the rendering reads the numbers: the records keep the claims' own words."""
    from stiefelsym.reports.report import readable_results
    from stiefelsym.results import Result
    r = Result(claim="c", paper=["man"], section="4", kind="id", title="along (dot_XP3*)", statement="", n=2, r=1,
               method="exact", verdict="proved", seed=0, seconds=0.0, expected=True)
    assert readable_results([r])[0].title == "along (5) §4"
    assert r.title == "along (dot_XP3*)"
    mine = Result(claim="c", paper=["man"], section="4", kind="id", title="along (BB)", statement="", n=2, r=1,
                  method="exact", verdict="proved", seed=0, seconds=0.0, expected=True,
                  rerun="stiefelsym verify c --claims mine.py")      # a user's claim: its words are its own
    assert readable_results([mine])[0].title == "along (BB)"


@pytest.mark.skipif(not PAPER.exists(), reason="the paper is not next to the repository")
def test_a_statement_without_a_label_is_named_by_its_printed_number():
    """Theorem 4.3 has no label, and Theorem 4.2 only that of its equation (man): a reader finds them by their
    numbers.  An equation inside such a statement is printed with it ("(3) §4 in Theorem 4.2"); a claim names the
    ones with no labelled equation inside by their printed names, each a statement of the paper without a label."""
    from stiefelsym.reports.report import labels
    unlabelled = paperref.unlabelled_statements(PAPER.read_text(encoding="utf-8"))
    assert unlabelled["Theorem 4.3"] == [] and unlabelled["Theorem 4.2"] == ["man"]
    assert "Theorem 4.4" not in unlabelled and "Proposition 4.6" in unlabelled
    assert paperref.printed("man") == "(3) §4 in Theorem 4.2"
    assert labels(["man"], ["Theorem 4.3"]) == "(3) §4 in Theorem 4.2 [man], Theorem 4.3"
    declared = {name for c in load_catalog() for name in c.unlabelled}
    assert "Theorem 4.3" in declared and declared <= {k for k, v in unlabelled.items() if not v}


@pytest.mark.skipif(not PAPER.exists(), reason="the paper is not next to the repository")
def test_every_unlabelled_statement_a_claim_checks_is_named_by_it():
    """The paper's statements without a label are numbered by its \\newtheorem counters (Theorem, Proposition, Lemma
    and Corollary share one per section, a Remark has its own; the appendices are sections 9 and 10): Remarks 3.1,
    4.1, 4.2, 8.1 and 8.2, Corollary 8.7, Theorems 4.3, 9.2 and 9.5, Proposition 4.6.  Each that a claim checks is
    named by that claim (Remark 3.1, at r = n (5) §3 is the right-invariant geodesic flow on SO(n), by
    right-invariant-geodesic-flow)."""
    unlabelled = paperref.unlabelled_statements(PAPER.read_text(encoding="utf-8"))
    bare = {k for k, v in unlabelled.items() if not v}
    assert bare == {"Remark 3.1", "Remark 4.1", "Theorem 4.3", "Remark 4.2", "Proposition 4.6", "Remark 8.1",
                    "Remark 8.2", "Corollary 8.7", "Theorem 9.2", "Theorem 9.5"}
    naming: dict[str, set[str]] = {}
    for c in load_catalog():
        for name in c.unlabelled:
            naming.setdefault(name, set()).add(c.id)
    assert naming == {
        "Remark 3.1": {"right-invariant-geodesic-flow"},
        "Remark 4.1": {"manakov-integrals", "noether-normal-metric"},
        "Theorem 4.3": {"manakov-lax"},
        "Remark 4.2": {"gram-not-in-involution-with-psi"},
        "Proposition 4.6": {"invariant-metrics"},
        "Remark 8.1": {"dual-invariants-manakov-r-n"},
        "Remark 8.2": {"gen-chasles2"},
        "Corollary 8.7": {"poisson-sphere-chasles"},
        "Theorem 9.2": {"ym-reduced-neumann", "ym-charge"},
        "Theorem 9.5": {"magnetic-spectral-invariants", "magnetic-spectral-invariants-any-rank"},
    }
