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


@pytest.mark.skipif(not PAPER.exists() or shutil.which("pdflatex") is None,
                    reason="the paper's source or pdflatex is not here")
def test_the_committed_table_is_what_the_paper_compiles_to():
    assert paperref.build(PAPER) == paperref.table()
