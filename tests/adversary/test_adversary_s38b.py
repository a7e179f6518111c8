"""Round 9 (tests/adversary/README.md, the "Round 9" table): brackets of magnetic brackets as graph nodes, the
free algebra's brackets of brackets and derivatives at another point, the division probe before refutations,
discovery after the derivative pass.  As before every run is the CLI in a fresh process, and each test asserts
the CORRECT outcome."""
from test_adversary_s38 import run_sizes, verdicts

from adversary_cli import PASSING

CAPTURES = "s38b_nested_bracket_captures.py"


def test_a_bracket_of_a_bracket_that_closes_over_the_claims_point():
    """{f, G}_F with G(t) = {g, h}_F'(t) where g or F' closes over a value of the claim's point (a constant of G at
    fixed sizes).  Before: the free algebra's rule {f, G} = -dG(X_f) differentiated G's value with that value
    moving, and the scene's own twisted flow inside a function renamed the field strength's letters with the
    point: "{f, {g, h}_F}_F is the same for F frozen and F moving" and "{f, {g₀, h}_η}_η = 0" (g₀ = tr(X₀ᵀX)) were
    proved for every n, r and fail under every fixed-size method at (3, 2); the Jacobi identity for the frozen F
    (true) was undecided with a nonzero normal form.  Closed: the free rule refuses functions and field strengths
    that read the claim's point, the scene's flow inside a function refuses a field strength that closes over the
    base point as it refuses such a Hamiltonian."""
    got = run_sizes(CAPTURES, sizes=("3,2",))
    for c in ("adv-s38b-captured-F-is-moving-F", "adv-s38b-captured-g-zero"):
        assert verdicts(got, c, (3, 2)) == {"fails"}, (c, got)
        assert verdicts(got, c, None, free=True) == {"undecided"}, (c, got)
    for c in ("adv-s38b-jacobi-captured-F", "adv-s38b-jacobi-eta"):
        assert verdicts(got, c, (3, 2)) <= set(PASSING) and verdicts(got, c, (3, 2)), (c, got)
    assert verdicts(got, "adv-s38b-jacobi-captured-F", None, free=True) == {"undecided"}
    assert verdicts(got, "adv-s38b-jacobi-eta", None, free=True) == {"proved"}


DIRAC = "s38b_dirac_nested_capture.py"


def test_a_dirac_bracket_of_a_bracket_that_closes_over_the_claims_point_is_decided():
    """IB, closed in round 10: under every fixed-size method the true Jacobi identity passes and the false
    {f, {g₀, h}} = 0 fails (before: a TypeError of the degree-tracking values, or of the symbolic field's
    normalization, met inside the scene's dual and reverse numbers: the captured X₀ is a number of the point's
    field, the inner bracket's numbers are reverse numbers over dual numbers over it, and the lower operand
    took the higher one for a constant of its own field).  Free stays undecided (the claim does not run on
    the free algebra)."""
    got = run_sizes(DIRAC, sizes=("3,2",))
    for c in ("adv-s38b-dirac-jacobi-captured", "adv-s38b-dirac-captured-zero"):
        assert not verdicts(got, c, None, free=True) & set(PASSING), (c, got)
    assert verdicts(got, "adv-s38b-dirac-jacobi-captured", (3, 2)), got
    assert verdicts(got, "adv-s38b-dirac-jacobi-captured", (3, 2)) <= set(PASSING), got
    assert verdicts(got, "adv-s38b-dirac-captured-zero", (3, 2)) == {"fails"}, got
