"""Stop 61: the review's files (tests/adversary/s61/review) and the user trial's statements (s61/hidden).  See
tests/adversary/README.md, Stop 61."""
import json

import pytest

from adversary_cli import assert_hold_and_fail, cli, verdicts, HERE

REVIEW = "s61/review"
HIDDEN = "s61/hidden"


@pytest.mark.parametrize("method", ["exact", "auto"])
def test_false_claims_refuted_on_every_chart_fail_under_exact(method):
    """The exact method first tries a rational point of T*V before the symbolic Cayley chart (a refutation there
    needs no symbolic residual).  While that change was being written the review found that a claim refuted on
    the equivariant or diagonal chart read the pre-check's result unset: A = 0, tr PᵀP = 0, XXᵀ = I_n at r < n and
    the complex point's ZᵀZ = I got `error`.  Every one of them is false and fails."""
    for name in ("unbound_refuted2.py", "unbound_refuted.py"):
        got = verdicts(f"{REVIEW}/{name}", method)
        assert got and set(got.values()) == {"fails"}, (name, got)


def test_a_size_times_zero_or_a_negative_int_is_a_number():
    """s.n * 0 and s.n * -1 were sizes k·n with k <= 0, which the replay refused as "claim code changed the graph"
    (a true claim got `error`).  A size times a positive int is a size; times 0 or a negative int it is a number,
    through the door (a fixed size's number)."""
    for method in ("exact", "modular"):
        got = verdicts(f"{REVIEW}/dim_mult.py", method)
        assert set(got) == {"dm-n", "dm-2n", "dm-minus-n", "dm-zero-n"}, got
        assert set(got.values()) <= {"proved", "checked"}, (method, got)


def _record(*args):
    run = cli("verify", *args, "--no-report", "--format", "json", "--timeout", "60")
    return json.loads(run.stdout)["results"][0]


def test_a_false_determinant_identity_is_refuted_by_exact_without_its_symbolic_residual():
    """The user trial's twin of the (VV) minors with a sign dropped: the true statement is proved at (4,3) in
    0.07 s, but the exact method spent its whole 120 s budget on the false one (its symbolic residual on the
    Cayley chart, a 6x6 determinant of rational functions, ran out of memory) and answered `inconclusive`.  Now a
    rational point of T*V refutes it first, the symbolic residual is tried within a cap of term products, and the
    verdict is `fails` with the exact witness.  The true statement is still proved."""
    false = _record("hn-plucker-V-unsigned", "--claims", str(HERE / HIDDEN / "negatives.py"), "--size", "4,3",
                    "--method", "exact")
    assert false["verdict"] == "fails", false
    assert false["witness"]["field"] == "rational" and "not written out" in false["certificate"], false
    true = _record("h-plucker-V", "--claims", str(HERE / HIDDEN / "claims.py"), "--size", "4,3", "--method", "exact")
    assert true["verdict"] == "proved", true


def test_where_the_symbolic_residual_is_within_the_cap_it_is_still_written_out():
    """The same twin at (3,2): refuted at the rational point, and the symbolic residual on the Cayley chart is
    small: the record states it (as before), with the witness of the point."""
    rec = _record("hn-plucker-V-unsigned", "--claims", str(HERE / HIDDEN / "negatives.py"), "--size", "3,2",
                  "--method", "exact")
    assert rec["verdict"] == "fails" and "nonzero function on the chart" in rec["certificate"], rec
    assert "K_" in rec["residual"] and rec["witness"]["field"] == "rational", rec


REVIEW2 = "s61/review2"


def test_a_false_claim_beyond_the_equivariant_charts_budget_fails_under_exact():
    """The second review: the realified complex point's column of norm 2 (false: 1) at (3,3) is beyond the
    equivariant chart's symbolic budget, so the rational pre-check placed before the Cayley chart was never reached:
    `inconclusive`.  Every symbolic budget now hands a claim of residuals to that point: `fails` with the witness."""
    got = verdicts(f"{REVIEW2}/points2.py", "exact", size="3,3", ids=("p2-zc-false",))
    assert got == {"p2-zc-false": "fails"}, got


@pytest.mark.parametrize("method", ["exact", "auto", "modular"])
def test_sym_coordinates_of_an_image_that_is_not_symmetric_do_not_hide_its_rank(method):
    """The second review: `matrix_of(s, lambda v: s.X.T @ v, matrix_units(s, "n", "r"), kind="sym")` took the upper
    triangle of a non-symmetric image, and the false rank r(r+1)/2 (the map has rank r²) was `proved`.  The "sym"
    and "skew" coordinates now end with the combinations that vanish on such an image, so they determine the
    matrix whatever it is: the rank is the map's, and the statement fails."""
    got = verdicts(f"{REVIEW2}/dims_bases.py", method, size="3,2", ids=("b-sym-on-general-false",))
    assert got == {"b-sym-on-general-false": "fails"}, got


#: the user trial's statements, each at one size where it is stated, and its false twin at a size where the twin is
#: false (numpy: tests/adversary/s61/hidden/indep.py)
TRUE_AT = {"h-submersion-gradient": (3, 2), "h-isotropy-invariance": (3, 2), "h-pencil-isomorphism": (3, 2),
           "h-lema1-eta3": (3, 2), "h-lema2-kernel": (3, 2), "h-plucker-V": (3, 2), "h-double-xydot": (3, 2),
           "h-submersion-not-left-invariant": (3, 2), "h-proof-counts": (3, 2)}
FALSE_AT = {"hn-submersion-gradient-sign": (3, 2), "hn-isotropy-no-transpose": (3, 2),
            "hn-pencil-isomorphism-no-square": (3, 2), "hn-lema1-eta3-sign": (3, 2), "hn-lema2-kernel-sign": (3, 2),
            "hn-plucker-V-unsigned": (3, 2), "hn-double-xdot-ydot": (3, 2), "hn-proof-counts-no-rank": (3, 2)}


@pytest.fixture(scope="module")
def hidden():
    from stiefelsym.claims import load_claims_file
    return {c.id: c for f in ("claims.py", "negatives.py") for c in load_claims_file(HERE / HIDDEN / f)}


@pytest.mark.parametrize("method", ["exact", "modular"])
def test_the_user_trials_statements_hold_and_their_twins_fail(hidden, method):
    """Nine statements of the paper the catalog does not state, written by a user (the user trial of this stop):
    each holds where it is stated, and each false twin (a sign, a square, a transpose dropped) fails."""
    assert_hold_and_fail(hidden, TRUE_AT, FALSE_AT, method)
