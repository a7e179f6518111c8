"""Stop 96, h5: degrees made by products in a row, where the power gate of the degree pass sees no power."""
from __future__ import annotations

from pathlib import Path

import pytest

import stiefelsym

FILES = Path(__file__).with_name("s96") / "h5"


def _claims():
    return {c.id: c for c in stiefelsym.load(files=[FILES / "c1_powers.py"], catalog=False)}


@pytest.mark.parametrize("cid, truth", [("h5p-mono-squarings-true", "checked"), ("h5p-mono-squarings-false", "fails"),
                                        ("h5p-matpow-false", "fails"), ("h5p-ratio-squarings-false", "fails"),
                                        ("h5p-trace-squarings-false", "fails"),
                                        ("h5p-squarings-then-power-false", "fails")])
def test_a_degree_made_by_products_in_a_row_is_inconclusive_at_once(cid, truth):
    """u^(2^40) made by forty products x = x * x (no power node, so the power gate let it through): the exact method
    evaluated u at a rational point and squared the integer for 207 s of CPU (budget 120 s), its command-line child
    died out of memory, and the free method rewrote it for minutes.  The products' degree (passes.product_degree,
    read through the tuples of a call's arguments: squarings through s.tr count; at most 80 in the catalog) sends
    it to the degree bound: exact and rational inconclusive at once, free undecided, modular decides."""
    from stiefelsym.methods import fixed_size as fs
    from stiefelsym.methods.dimension_free import run_free
    c = _claims()[cid]
    for res in (fs.run_exact(c, 2, 1, 0), fs.run_points(c, 2, 1, "rational", 0)):
        assert res.verdict == "inconclusive", res.message
        assert "structural degree bound" in res.message
    assert fs.run_points(c, 2, 1, "modular", 0).verdict == truth
    assert run_free(c).verdict == "undecided"
