"""§1 (the introduction): V_{n,n} is O(n), not SO(n) (an erratum with a witness, its correction holds), and V_{n,n−1}
is SO(n) by the cofactor column.  Negative controls: corrupted copies of the correction and of the completion fail."""
from stiefelsym.methods.fixed_size import run_exact, run_points
from stiefelsym.proofs.determinants import det
from stiefelsym.proofs.sec1_introduction import entries

SEED = 0


def test_the_printed_statement_fails_with_a_witness_and_its_correction_holds(catalog):
    c = catalog.get("stiefel-top-rank")
    assert c.erratum and c.expects_failure(3, 3)
    res = run_exact(c, 3, 3, SEED)
    assert res.verdict == "fails" and res.witness, res.line()
    (corr,) = c.corrections
    assert run_exact(c, 3, 3, SEED, func=corr.func).verdict == "proved"


def test_the_completion_to_so_n_holds(catalog):
    c = catalog.get("stiefel-corank-one")
    assert run_exact(c, 4, 3, SEED).verdict == "proved"


def det_squared_is_two(s):
    """Corrupted correction: (det X)² = 2."""
    d = det(s, entries(s.X, s.n, s.n))
    return {"det(X)^2 - 2": d * d - s.q(2)}


def completion_without_the_sign(s):
    """Corrupted completion: c_i = det of X without its i-th row, the sign (−1)^{n+i} dropped."""
    n, r = s.n, s.r
    rows = entries(s.X, n, r)
    c = [det(s, rows[:i] + rows[i + 1:]) for i in range(n)]
    return {"det(X c) - 1": det(s, [rows[i] + [c[i]] for i in range(n)]) - s.q(1)}


def test_corrupted_copies_fail(catalog):
    top, corank = catalog.get("stiefel-top-rank"), catalog.get("stiefel-corank-one")
    for method in ("exact", "modular"):
        run = run_exact if method == "exact" else (lambda c, n, r, seed, func: run_points(c, n, r, "modular", seed, func))
        assert run(top, 3, 3, SEED, func=det_squared_is_two).verdict == "fails"
        assert run(corank, 3, 2, SEED, func=completion_without_the_sign).verdict == "fails"


def test_the_correction_is_proved_exactly_at_the_raised_sizes_and_a_corrupted_copy_fails(catalog):
    c = catalog.get("stiefel-top-rank")
    (corr,) = c.corrections
    corrected = c.corrected(0)
    for n in (5, 6):
        assert corrected.exact_at(n, n) and not c.exact_at(n, n)
    assert run_exact(c, 5, 5, SEED, func=corr.func).verdict == "proved"
    assert run_exact(c, 5, 5, SEED, func=det_squared_is_two).verdict == "fails"


def test_the_completion_is_proved_exactly_at_6_5_and_a_corrupted_copy_fails_there(catalog):
    """At (6, 5) the chart's r × r inverse (I + S11 + KᵀK, 5 × 5 of degree 2) is taken within the work budget of a
    symbolic inverse (it was refused for its size): the completion is proved, the one without signs fails."""
    c = catalog.get("stiefel-corank-one")
    assert c.exact_at(6, 5) and not c.exact_at(7, 6)
    assert run_exact(c, 6, 5, SEED).verdict == "proved"
    assert run_exact(c, 6, 5, SEED, func=completion_without_the_sign).verdict == "fails"
