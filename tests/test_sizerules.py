"""Statements about sizes: the rule separating failing from holding sizes is tested against every
size it speaks of, and a list is never shortened to an ellipsis."""
import pytest

from stiefelsym.reports.report import format_sizes
from stiefelsym.sizerules import _atoms, fails_holds_text, rule

SIZES = [(n, r) for n in range(1, 7) for r in range(1, n + 1)]


def _check(cond: str, bad, good):
    """Evaluate the printed rule as Python over every size: true on ``bad``, false on ``good``."""
    expr = (cond.replace("≥", ">=").replace("≤", "<=").replace("≠", "!=").replace("−", "-").replace(" = ", " == ")
            .replace("2r", "2*r"))
    for n, r in bad:
        assert eval(expr, {}, {"n": n, "r": r}), (cond, n, r)
    for n, r in good:
        assert not eval(expr, {}, {"n": n, "r": r}), (cond, n, r)


@pytest.mark.parametrize("pred, text", [
    (lambda n, r: r >= 2, "r ≥ 2"),
    (lambda n, r: n == 2 * r + 2, "n = 2r + 2"),
    (lambda n, r: 2 * r > n, "2r > n"),
    (lambda n, r: r == n, "r = n"),
    (lambda n, r: r == 1 or r == n, "r = 1 or r = n"),
    (lambda n, r: r == 1 and n <= 2, "r = 1 and n ≤ 2"),
    (lambda n, r: n != 2 * r, "n ≠ 2r"),      # not "2r > n or 2r < n" (the referee of stop 67)
    (lambda n, r: r != 2, "r ≠ 2"),
])
def test_the_rule_is_found_and_holds_at_every_computed_size(pred, text):
    bad = [s for s in SIZES if pred(*s)]
    good = [s for s in SIZES if not pred(*s)]
    found = rule(bad, good)
    assert found == text
    _check(found, bad, good)


def test_every_atom_reads_as_its_test():
    for a in _atoms(SIZES):
        _check(a.text, [s for s in SIZES if a.test(*s)], [s for s in SIZES if not a.test(*s)])


def test_no_rule_lists_both_sets_in_full():
    bad = [(4, 2), (4, 3), (4, 4), (5, 4), (6, 4)]
    good = [s for s in SIZES if s not in bad]
    assert rule(bad, good) is None
    text = fails_holds_text(bad, good)
    assert "…" not in text and all(f"({n},{r})" in text for n, r in SIZES)


def test_format_sizes_never_uses_an_ellipsis():
    scattered = [(1, 1), (3, 2), (4, 4), (5, 1), (6, 3), (6, 6), (2, 2)]
    assert "…" not in format_sizes(scattered, 4)
    assert format_sizes([s for s in SIZES if s[1] >= 2], 4, SIZES) == "every computed size with r ≥ 2 (15 sizes)"
    assert format_sizes(SIZES, 4, SIZES) == "every computed size (21)"
