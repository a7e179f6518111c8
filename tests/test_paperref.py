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
