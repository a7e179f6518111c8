"""Round 11 (tests/adversary/README.md, the "Round 11" table): the chart X = I, P = W at r = n and the chart reduced
by O(r) on the right below it, the number-type tower, the claims file's confined loading, the exact method's residual
text and the modular bound.  As before every run is the CLI in a fresh process, and each test asserts the CORRECT
outcome."""
from test_adversary_s38 import run_sizes, verdicts

from adversary_cli import PASSING

JOINS = "s40_right_chart_joins.py"
JOINS_FALSE = {"adv-s40-sq-int-identity-sym": ((3, 3),), "adv-s40-sq-int-identity-trace": ((3, 3),),
               "adv-s40-sq-int-identity-p-skew": ((3, 3),), "adv-s40-sq-int-generic-commutes": ((3, 3),),
               "adv-s40-sq-d-scalar-sym": ((3, 3),),
               "adv-s40-d-scalar-two-splittings-sym": ((3, 2), (4, 2)),
               "adv-s40-d-scalar-two-splittings-p": ((3, 2), (4, 2)),
               "adv-s40-eigenvalue-two-splittings-sym": ((3, 2), (4, 2))}
JOINS_TRUE = {"adv-s40-sq-int-identity-true": ((3, 3),), "adv-s40-d-scalar-true": ((3, 2), (4, 2)),
              "adv-s40-d-scalar-two-splittings-true": ((3, 2), (4, 2))}


def test_reads_of_r_through_int_sized_pieces_and_engine_numbers_are_refuted_exactly():
    """JA: at r = n an untyped identity of an int size used on ℝʳ and on ℝⁿ (X·I₃ − (X·I₃)ᵀ) makes X a matrix on ℝⁿ;
    JB: a number made by s.d gave c·M an engine value's sides in the pass, hiding M's joins (c·I₃ at r = n, and
    round 10's ℝⁿ ⊕ ℝʳ taken for ℝʳ ⊕ ℝⁿ with blocks c·I_r, c·0 at (3,2), (4,2)).  Before: exact (and auto) took
    the chart reduced by O(r) on the right and proved X symmetric, tr X = 3, P skew, the top block of X symmetric
    and of P skew; every other method failed them.  Closed (`ir/passes`): a join of ℝⁿ and ℝʳ breaks the right
    action, and a product by a number or a sum keeps the sides the pass knows."""
    got = run_sizes(JOINS, methods=("exact", "modular", "float"), free=False)
    for c, sizes in JOINS_FALSE.items():
        for size in sizes:
            assert verdicts(got, c, size) == {"fails"}, (c, size, got)
    for c, sizes in JOINS_TRUE.items():
        for size in sizes:
            seen = verdicts(got, c, size)
            assert seen and seen <= set(PASSING), (c, size, got)


SHARED = "s40_shared_parameter_name.py"


def test_a_parameter_name_on_r_n_and_on_r_r_names_two_matrices():
    """JC: s.general_params("G", n, n, ("n", "n")) and s.general_params("G", r, r, ("r", "r")) were one matrix at r = n
    (keyed by the name and the numbers of the size), two at r < n.  The equivariant chart moves the first with
    O(n) and the second with O(r): XG₂ = G₁X and XᵀG₁X = G₂ were proved exactly at (3,3), (4,4) (X = X₀ = I), every
    other method failed them.  Closed (`Scene.general_params`): the spaces are part of the name, as the size is.
    Since stop 88 (h1 I1: two parameters of one name printed alike) one name names one parameter of a claim: every
    claim of the file draws both and is refused when traced, under every method."""
    got = run_sizes(SHARED, methods=("exact", "modular", "float"), free=False)
    for c, sizes in (("adv-s40-shared-name-commutes", ((3, 3), (4, 4))),
                     ("adv-s40-shared-name-conjugate", ((3, 3), (4, 4))),
                     ("adv-s40-shared-name-true", ((3, 3), (4, 4))),
                     ("adv-s40-shared-name-one-space-true", ((3, 2), (3, 3)))):
        for size in sizes:
            assert verdicts(got, c, size) == {"error"}, (c, size, got)


TOWER = "s40_number_tower.py"


def test_the_number_tower_mixed_in_any_order_against_truths_by_hand():
    """(No hole) derivatives inside derivatives (left to the scene's dual numbers by the graph's pass), gradients and
    brackets in any order, with values captured from every enclosing scene (the claim's X₀ in an inner flow, a number
    of the middle layer, a captured number in the diagonal blocks of an inner inverse beside a resolvent at a moving
    μ): every true statement passes and every false one fails under exact, modular and float (rational and ball
    alike when run by hand; free leaves them undecided)."""
    got = run_sizes(TOWER, methods=("exact", "modular", "float"), free=False)
    claims = {c for c, _ in got}
    assert len(claims) == 10, got
    for c in claims:
        seen = verdicts(got, c, (3, 2))
        if c.endswith("-false"):
            assert seen == {"fails"}, (c, got)
        else:
            assert seen and seen <= set(PASSING), (c, got)
