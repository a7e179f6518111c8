"""Round 13 (tests/adversary/README.md, the "Round 13" table): the complex point of the exact method reduced by U(r)
acting on the right (S11 = 0; Z = I at r = n; `methods/complex_right`).  As before every run is the CLI in a fresh
process, and each test asserts the CORRECT outcome."""
from pathlib import Path

import pytest
from test_adversary_s38 import run_sizes, verdicts

from adversary_cli import PASSING
from stiefelsym.api import load
from stiefelsym.ir import compile_claim
from stiefelsym.methods import complex_right
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.scene import REALIZATIONS

SPLITS = "s40c_complex_right_splits.py"
SPLITS_FALSE = {"adv-s40c-re-z11-square": ((2, 2), (3, 3)), "adv-s40c-im-z11": ((3, 2), (4, 3)),
                "adv-s40c-im-z11-square": ((2, 2), (3, 3))}


def _graph(cid, n, r):
    c = load([Path(__file__).parent / SPLITS], catalog=False).get(cid)
    cons = REALIZATIONS["standard"]
    return compile_claim(c.func, n, r, (cons.name, cons.build))


@pytest.mark.parametrize("cid,size", [(c, sz) for c, sizes in SPLITS_FALSE.items() for sz in sizes])
def test_block_parts_of_other_sizes_are_refused_the_reduction(cid, size):
    """LA, the pass alone: a picker split (1, 4r − 1) (or (i, 1, ...)) joined to F's parts (2r, 2r) breaks
    covariance; the same blocks aligned (a picker split (2r, 2r)) keep the reduction."""
    n, r = size
    g = _graph(cid, n, r)
    assert complex_right.unitary_right_breaks(g, n, r) == ["block matrices joined across parts of different sizes"]
    assert not complex_right.applies(g, "standard", n, r)
    assert complex_right.applies(_graph("adv-s40c-aligned-true", n, r), "standard", n, r)


def test_an_entry_of_z_through_misaligned_blocks_fails_in_the_exact_method():
    """LA through `run_exact` at (2,2) (Z = I on the reduced chart): the statement fails, the reduction not stated."""
    c = load([Path(__file__).parent / SPLITS], catalog=False).get("adv-s40c-im-z11-square")
    res = run_exact(c, 2, 2, 0)
    assert res.verdict == "fails", (res.verdict, res.message)
    assert not any("reduced by U(r)" in x for x in res.reductions), res.reductions


@pytest.mark.slow
def test_an_entry_of_z_read_through_misaligned_blocks_is_refuted_exactly():
    """LA: F = [[Z, Z], [Z, Z], [Z, Z]] (columns split (2r, 2r)) times a column picker split (1, 4r − 1), and a row
    picker split (i, 1, ...), is one realified entry of Z; the pass joined the parts in order whatever their sizes,
    so it typed the entry as moving with R(h) and its square as a number.  Before: exact (and auto) took the chart
    reduced by U(r) and proved (Re z11)² = 1 at (2,2) (Z = I there) and (Im z11)² = 0 at (2,2), (3,2) (the top
    r × r block of Z is Hermitian at S11 = 0); modular and rational failed them.  Closed (`methods/complex_right`):
    a matrix's type carries the sizes of its parts, and block splittings are joined only where they agree."""
    got = run_sizes(SPLITS, methods=("exact", "modular", "rational"), free=False, sizes=("2,2", "3,2"))
    for c, sizes in SPLITS_FALSE.items():
        for size in sizes:
            if size in ((2, 2), (3, 2)):
                assert verdicts(got, c, size) == {"fails"}, (c, size, got)
    for size in ((2, 2), (3, 2)):
        seen = verdicts(got, "adv-s40c-aligned-true", size)
        assert seen and seen <= set(PASSING), (size, got)


def test_a_value_beyond_the_rings_parameters_is_decided_both_ways():
    """The exact zero test decides a polynomial over Q beyond the ring's parameters (two generic 9 x 9
    operators) by symengine's expansion: tr(GH) = tr(GHᵀ) fails, tr(GH) = tr(HG) and a cyclic trace with X
    are proved (exact), checked (modular)."""
    from test_adversary_s38 import run_sizes, verdicts
    got = run_sizes("s40_big_generic_zero_test.py", methods=("exact", "modular"), free=False)
    assert verdicts(got, "adv-s40-big-false", (9, 1)) == {"fails"}, got
    assert verdicts(got, "adv-s40-big-true", (9, 1)) == {"proved", "checked"}, got
