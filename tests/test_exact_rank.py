"""The exact method's rank certificates: a lower bound at an exact rational point, the
function-field rank by fraction-free elimination over flint polynomials, and the randomized
upper bound when the symbolic rank is out of reach."""
from __future__ import annotations

import random

import pytest
import sympy as sp

from stiefelsym import Rank, admissible
from stiefelsym.methods import fixed_size as methods
from stiefelsym.claims import Claim, _mark_reviewed
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import Mat
from stiefelsym.methods.fixed_size import ExactTimeout, _bareiss_rank, _flint_polynomials, run_exact


def _claim(func, cid="rank-trick"):
    return Claim(id=cid, paper=("2l",), kind="dim", section="t", func=func, sizes=admissible(4))


def ad_phi(s):
    """ad_Φ on so(n) in the basis E_ij: its rank is 2l (Lemma 2l)."""
    n = s.n
    basis = [(i, j) for i in range(n) for j in range(i + 1, n)]
    cols = []
    for i, j in basis:
        E = s.mat([[1 if (a, b) == (i, j) else -1 if (a, b) == (j, i) else 0 for b in range(n)]
                   for a in range(n)], ("n", "n"))
        cols.append(s.Phi @ E - E @ s.Phi)
    return [[c[a, b] for c in cols] for a, b in basis]


def rank_claim(expected):
    def f(s):
        return {"rank": Rank(s.mat(ad_phi(s), ("so", "so")), expected(s.n, s.r), generic=True)}
    return f


def two_l(n, r):
    return n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)


@pytest.mark.slow   # sympy's rank as the reference (10 s): run by `make verify-all`
def test_bareiss_rank_agrees_with_sympy():
    rng = random.Random(1)
    x = sp.symbols("x0:4")
    for _ in range(6):
        m, k = rng.randint(2, 5), rng.randint(2, 5)
        rows = [[sum(rng.randint(-2, 2) * xi for xi in x[:2]) + rng.randint(-1, 1) for _ in range(k)]
                for _ in range(m)]
        if rng.random() < 0.5:   # make a dependent row
            rows.append([a + 2 * b for a, b in zip(rows[0], rows[1])])
        import symengine as se
        M = Mat._rows([[se.sympify(str(v)) for v in row] for row in rows], SymbolicField())
        assert _bareiss_rank(_flint_polynomials(M)) == sp.Matrix(rows).rank()


def test_printed_rank_is_proved_two_sided():
    res = run_exact(_claim(rank_claim(two_l)), 3, 1, 0)
    assert res.verdict == "proved" and "two-sided" in res.certificate


@pytest.mark.parametrize("shift", [-1, 1])
def test_a_wrong_rank_fails(shift):
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) + shift)), 3, 1, 0)
    assert res.verdict == "fails"


def test_beyond_the_symbolic_budget_the_upper_bound_is_randomized(monkeypatch):
    def timeout(M):
        raise ExactTimeout("the function-field rank")
    monkeypatch.setattr(methods, "_function_field_rank", timeout)
    res = run_exact(_claim(rank_claim(two_l)), 3, 1, 0)
    assert res.verdict == "checked" and res.false_pass_bound is not None and res.false_pass_bound <= 1e-30
    assert "random points of prime fields" in res.certificate
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) - 1)), 3, 1, 0)
    assert res.verdict == "fails"       # a rank above the printed one is certain at a rational point
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) + 1)), 3, 1, 0)
    assert res.verdict == "inconclusive"   # below the printed rank at one point: not certain without the symbolic rank


# -- the upper bound from rational relations among rows or columns --------------------------------------

def _constraints(t):
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def constraint_jacobian(expected):
    """The Jacobian of XᵀX − I, XᵀP + PᵀX in the coordinates of X, P (each symmetric entry twice, so the rows
    repeat), read in coordinates: the Cayley chart, where the function-field elimination takes minutes."""
    def f(s):
        return {"rank": Rank(s.mat(s.jacobian(_constraints)), expected(s.r), generic=True)}
    return f


def test_rational_relations_among_rows_bound_the_rank_from_above():
    from stiefelsym.methods.fixed_size import _coefficient_rank_bound
    import flint
    ctx = flint.fmpq_mpoly_ctx.get(("x", "y"), "degrevlex")
    x, y = ctx.gens()
    assert _coefficient_rank_bound([[x, y], [2 * x, 2 * y]])[0] == 1            # proportional rows
    assert _coefficient_rank_bound([[x, 2 * x, x + y], [y, 2 * y, x * y]])[0] == 2
    assert _coefficient_rank_bound([[x, 2 * x], [y, 2 * y], [x * y, 2 * x * y]])[0] == 1   # columns
    assert _coefficient_rank_bound([[x, y], [y, x]])[0] == 2       # rank 2: no rational relation, none found
    assert _coefficient_rank_bound([[x * 0, x * 0]])[0] == 0


def test_repeated_rows_prove_the_rank_of_the_constraints_in_the_cayley_chart():
    res = run_exact(_claim(constraint_jacobian(lambda r: r * (r + 1)), "constraints-rank"), 4, 2, 0)
    assert res.verdict == "proved", res.line()
    assert "span a space of dimension 6 over Q" in res.certificate and "two-sided" in res.certificate


@pytest.mark.parametrize("shift", [1, -1])
def test_a_wrong_rank_of_the_constraints_fails(shift):
    res = run_exact(_claim(constraint_jacobian(lambda r: r * (r + 1) + shift), "constraints-rank-wrong"), 4, 2, 0)
    assert res.verdict == "fails", res.line()


def test_the_zero_matrix_has_rank_zero_said_so():
    def zero(s):
        return {"rank": Rank(s.mat([[s.X[0, 0] - s.X[0, 0], s.P[0, 0] * 0]]), 0, generic=True)}
    res = run_exact(_claim(zero, "zero-rank"), 3, 2, 0)
    assert res.verdict == "proved" and "the zero matrix" in res.certificate, res.certificate
    wrong = run_exact(_claim(lambda s: {"rank": Rank(s.mat([[s.X[0, 0] * 0]]), 1, generic=True)}, "zero-rank-1"),
                      3, 2, 0)
    assert wrong.verdict == "fails", wrong.line()


def test_rows_dependent_over_the_function_field_only_are_not_a_rank_two():
    """(x, y) and (x², xy) are independent over Q as coefficient vectors (the bound says <= 2) but dependent over
    the function field: the printed rank 2 must fail, not be proved from the bound and a point."""
    def dependent(s):
        x, y = s.X[0, 0], s.X[1, 0]
        return {"rank": Rank(s.mat([[x, y], [x * x, x * y]]), 2, generic=True)}
    for method in ("exact", "modular"):
        from stiefelsym.claims import Size
        from stiefelsym.run.runner import run_one
        res = run_one(_claim(dependent, "dependent-rows"), Size(3, 2), method, 0)
        assert res.verdict in ("fails", "inconclusive"), res.line()
    assert run_exact(_claim(dependent, "dependent-rows"), 3, 2, 0).verdict == "fails"


def test_a_user_s_rank_is_quoted_as_claimed_and_the_catalog_s_as_the_paper_s():
    """The number a rank certificate quotes beside the computed one is the paper's only for the catalog's claims."""
    import dataclasses
    modular = lambda c, n, r, seed: methods.run_points(c, n, r, "modular", seed)    # noqa: E731
    for method, claimed in ((run_exact, 2), (modular, 3)):       # (the modular method quotes a rank it refutes)
        own = _claim(rank_claim(lambda n, r, k=claimed: k))
        for reviewed, word, other in ((False, "claimed", "paper"), (True, "paper", "claimed")):
            res = method(_mark_reviewed(dataclasses.replace(own)) if reviewed else dataclasses.replace(own), 3, 1, 0)
            said = " ".join([res.certificate] + [ch.detail or "" for ch in res.checks])
            assert f"{word}: {claimed}" in said and other not in said, said


def test_a_rank_above_the_truth_beyond_the_function_field_rank_says_what_random_points_show(monkeypatch):
    """Where the function-field rank is out of reach, a printed rank above the rank at an exact point stays
    inconclusive (a point can be special, and a refutation needs a witness), and the message says what random
    points of prime fields show, with the probability bound, and how kernel vectors would refute it."""
    def no_time(*args, **kwargs):
        raise methods.ExactTimeout("the function-field rank did not finish within 5 s")
    monkeypatch.setattr(methods, "_function_field_rank", no_time)
    monkeypatch.setattr(methods, "_coefficient_rank_bound", lambda polys: None)
    res = run_exact(_claim(rank_claim(lambda n, r: two_l(n, r) + 1)), 4, 1, 0)
    assert res.verdict == "inconclusive", res.line()
    assert "at 2 random points of prime fields the rank is" in res.message and "kernel=" in res.message, res.message


def test_the_rank_modulo_a_prime_never_certifies_more_than_the_rank_over_q():
    """rational_rank takes the rank modulo a prime first and accepts it only when it is the full size: a matrix of
    rank 2 over Q (third row the sum of the others) is rank 2, never 3 (the fallback to flint's exact rank refuses
    the full size); a matrix of full rank 3 whose determinant RANK_PRIME divides has rank 2 modulo p, and the
    fallback still finds rank 3 over Q."""
    import flint
    from stiefelsym.methods.fixed_size import RANK_PRIME, rational_rank
    q = flint.fmpq
    low = [[q(1, 3), q(2), q(5, 7)], [q(4), q(-1, 2), q(3)], [q(13, 3), q(3, 2), q(26, 7)]]
    assert flint.fmpq_mat(low).rank() == 2 and rational_rank(low) == 2
    p = RANK_PRIME
    special = [[q(1), q(0), q(0)], [q(0), q(1), q(0)], [q(0), q(0), q(p, 5)]]       # det = p/5: 0 modulo p
    assert flint.nmod_mat(flint.fmpq_mat(special).numer_denom()[0], p).rank() == 2
    assert rational_rank(special) == 3
    assert rational_rank([[q(2), q(1)], [q(0), q(3)], [q(1), q(1)]]) == 2          # full rank found modulo p


def test_a_kernel_of_full_rank_at_a_small_point_gives_the_rank_and_a_special_one_falls_back():
    """_full_rank_at_point: a full rank at the small point is the rank (certified by a nonzero full-size minor), a
    rank below the full size there (a matrix of generic rank below full size, or a minor vanishing at the small
    point) sends the rank to the usual point of the run's generator, whose draws it then makes as before."""
    import random
    from stiefelsym.methods import fixed_size
    calls = []

    def fake(M, rng, modulus=None, height=2**62):
        calls.append(height)
        return M.ranks[height]

    class Fake:
        def __init__(self, shape, ranks):
            self.shape, self.ranks = shape, ranks

        def _shape(self):
            return self.shape

    real = fixed_size._rank_at_point
    fixed_size._rank_at_point = fake
    try:
        assert fixed_size._full_rank_at_point(Fake((5, 3), {fixed_size.SMALL_HEIGHT: 3, 2**62: 3}),
                                              random.Random(0)) == 3
        assert calls == [fixed_size.SMALL_HEIGHT]
        calls.clear()
        assert fixed_size._full_rank_at_point(Fake((5, 3), {fixed_size.SMALL_HEIGHT: 2, 2**62: 3}),
                                              random.Random(0)) == 3
        assert calls == [fixed_size.SMALL_HEIGHT, 2**62]
        calls.clear()
        assert fixed_size._full_rank_at_point(Fake((5, 3), {fixed_size.SMALL_HEIGHT: 2, 2**62: 2}),
                                              random.Random(0)) == 2
    finally:
        fixed_size._rank_at_point = real


def test_the_cheapest_rows_of_a_tall_kernel_give_its_full_rank_and_a_deficient_one_is_not_full():
    """_cheapest_rows_rank evaluates the 2c rows with the fewest terms of a matrix with more than 2c rows (c its
    columns): full rank there is full rank of the matrix; a matrix of rank below c is never found full (rows of a
    matrix have at most its rank), and a matrix with at most 2c rows is left to the whole evaluation (None)."""
    import symengine as se
    from stiefelsym.methods.fixed_size import _cheapest_rows_rank, _full_rank_at_point
    F = SymbolicField()
    x, y = se.symbols("x y")
    rows = [[x, 1], [y, x * y], [x + y, 2], [x * x, y], [1, 0], [0, 1], [(x + y) ** 3, y ** 4], [x ** 5, 1 + y ** 5]]

    def mat(rows):
        return Mat._rows([[se.sympify(e) for e in row] for row in rows], F)
    rng = random.Random(0)
    assert _cheapest_rows_rank(mat(rows), rng) == 2 and _full_rank_at_point(mat(rows), rng) == 2
    deficient = mat([[row[0], 2 * row[0]] for row in rows])
    assert _cheapest_rows_rank(deficient, rng) in (None, 1) and _full_rank_at_point(deficient, rng) == 1
    assert _cheapest_rows_rank(mat(rows[:4]), rng) is None
