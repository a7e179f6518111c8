"""Stop 96, h4 (an adversary of issue 20's routes and of the stop's new mechanisms): the degree guard of the exact
and rational methods reads the degree of every value computed on the way to the residuals, not only theirs."""
from __future__ import annotations

from pathlib import Path

import pytest

import stiefelsym

FILES = Path(__file__).with_name("s96") / "h4"


@pytest.mark.parametrize("cid, truth", [("h4t-pow0-true", "holds"), ("h4t-times-zero-true", "holds"),
                                        ("h4t-recip-pow0-true", "holds"), ("h4t-pow0-false", "fails")])
def test_a_value_beyond_expansion_on_the_way_is_inconclusive_at_once(cid, truth):
    """(u^(2^40))^0 − 1 = 0, 0 · u^(2^40) = 0, ((1/u)^(2^40))^0 − 1 = 0: the residuals' structural degree is 0 (or
    none), below EXPANDABLE_DEGREE, so the degree guard let the exact and rational methods evaluate them, and both
    wrote u^(2^40) out until flint failed to allocate (213 s, then `inconclusive` / `error`: the child process died
    by SIGABRT).  The guard reads the largest degree of a numerator or a denominator of every value the degree
    markers stood for: both answer `inconclusive` at once, and the modular method still decides."""
    from stiefelsym.methods import fixed_size as fs
    claims = stiefelsym.load(files=[FILES / "c2_degree.py"], catalog=False)
    c = next(x for x in claims if x.id == cid)
    for res in (fs.run_exact(c, 2, 1, 0), fs.run_points(c, 2, 1, "rational", 0)):
        assert res.verdict == "inconclusive", res.message
        assert "a value it computes" in res.message and str(fs.EXPANDABLE_DEGREE) in res.message
    assert fs.run_points(c, 2, 1, "modular", 0).verdict == ("checked" if truth == "holds" else "fails")
    bound = fs.degree_bound(c, 2, 1)
    assert bound.peak >= 2 ** 40 > fs.EXPANDABLE_DEGREE >= bound.numerator
