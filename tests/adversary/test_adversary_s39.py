"""Round 10 (tests/adversary/README.md, the "Round 10" table): the right-reduced Cayley chart (S11 = 0 for a graph
that reads nothing of R^r), the equivariant chart after a derivative step, the soundness rules of round 9 and the
Dirac bracket of a bracket that closes over the point.  As before every run is the CLI in a fresh process, and
each test asserts the CORRECT outcome."""
from test_adversary_s38 import run_sizes, verdicts

from adversary_cli import PASSING

SPLITS = "s39_right_chart_splits.py"
SPLITS_FALSE = ("adv-s39-block-columns", "adv-s39-rows-of-In", "adv-s39-rows-of-In-eta", "adv-s39-trace-given-columns",
                "adv-s39-killing-given-columns", "adv-s39-trace-method-slice", "adv-s39-two-splittings-identity",
                "adv-s39-two-splittings-symmetric", "adv-s39-two-splittings-p-skew",
                "adv-s39-two-splittings-first-columns")
SPLITS_TRUE = ("adv-s39-block-columns-true", "adv-s39-rows-of-In-true", "adv-s39-two-splittings-true")


def test_reads_of_r_the_right_chart_pass_missed_are_refuted_exactly():
    """RA-RC: X1 - X1ᵀ read through a block of 1 x 1 pieces of I and 0 used on ℝʳ (e₁ of ℝ²), through rows of
    I_n (a block of a matrix on ℝⁿ alone whose result meets ℝʳ), through tr(XᵀB) or ⟨Xᵀ, B⟩ with B of given entries
    (the trace did not join B's columns to ℝʳ).  Before: exact took S11 = 0 (X1 symmetric) and proved each false
    claim at (3, 2) and (4, 2).  Closed: a trace, a pairing, an inverse and a power join their matrix's sides; a
    block of an ℝⁿ matrix whose own sides meet ℝʳ, and ℝʳ joined to a direct sum (or two different splittings of
    a side on ℝʳ), leave the chart reduced by O(r) on the right."""
    got = run_sizes(SPLITS, methods=("exact", "modular", "float"), free=False)
    for c in SPLITS_FALSE:
        sizes = [k[1] for k in got if k[0] == c]
        assert sizes, (c, got)
        for size in sizes:
            assert verdicts(got, c, size) == {"fails"}, (c, size, got)
    for c in SPLITS_TRUE:
        for size in ((3, 2), (4, 2)):
            assert verdicts(got, c, size) and verdicts(got, c, size) <= set(PASSING), (c, size, got)


SQUARE = "s39_square_chart.py"


def test_statements_true_at_x_equal_i_only_are_not_passed_at_r_equal_n():
    """The chart X = I, P = W at r = n: P skew, tr X = n, X symmetric (through an untyped identity or zero) hold
    at the chart's point only.  No hole: each is refused when traced (ℝⁿ and ℝʳ are different spaces at r = n, and
    untyped pieces take the spaces they meet), under exact and modular alike; the true controls pass, near r = n
    (the Woodbury chart) too."""
    got = run_sizes(SQUARE, methods=("exact", "modular"), free=False)
    false = ("adv-s39-sq-p-skew", "adv-s39-sq-trace-x", "adv-s39-sq-x-sym-untyped-identity",
             "adv-s39-sq-x-sym-untyped-zero")
    for c in false:
        for size in ((3, 3), (4, 4)):
            seen = verdicts(got, c, size)
            assert seen and not seen & set(PASSING), (c, size, got)
    for c, sizes in (("adv-s39-sq-xxt-true", ((3, 3), (4, 4))), ("adv-s39-sq-untyped-true", ((3, 3), (4, 4))),
                     ("adv-s39-near-xtax-true", ((4, 3), (5, 4)))):
        for size in sizes:
            assert verdicts(got, c, size) == {"proved", "checked"}, (c, size, got)
