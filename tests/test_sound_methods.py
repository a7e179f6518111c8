"""Verdicts that cannot be fooled: each trick an adversarial claim could play on a method,
reproduced by a small claim, now fails, errs or is refused; the honest version still passes."""
import math
import random
from fractions import Fraction

import pytest

from stiefelsym import Count, Rank, admissible
from stiefelsym.claims import Claim, Size
from stiefelsym.backends.fields import (PRIME_HIGH, PRIME_LOW, PRIMES_IN_RANGE_LOWER, ConstantDegenerate, ErrNum,
                               FloatField, ModularField, primes_in_range_lower_bound,
                               random_prime)
from stiefelsym.methods.fixed_size import (POINTS_CAP, POINTS_TARGET, _per_point_bound, _points_needed, _prime_field,
                                degree_bound, draw_key, run_exact, run_float, run_points)
from stiefelsym.run.runner import run_one

PASSING = ("proved", "checked", "numeric")


def _claim(func, kind="id", expect="holds", cid="trick"):
    return Claim(id=cid, paper=("prep",), kind=kind, section="t", func=func, sizes=admissible(4), expect=expect)


from test_methods import resolvent_identity, resolvent_identity_sign  # noqa: E402  (shared test claims)


# -- 1. the modular method: a prime per point, a height bound, enough points -----------------

def test_the_prime_count_is_a_proven_lower_bound():
    assert primes_in_range_lower_bound() >= PRIMES_IN_RANGE_LOWER >= 7.6e16


def test_primes_are_drawn_by_the_seed_from_the_whole_range():
    import flint
    ps = [random_prime(random.Random(f"p{k}")) for k in range(20)]
    assert all(PRIME_LOW <= p < PRIME_HIGH and flint.fmpz(p).is_prime() for p in ps)
    assert len(set(ps)) == 20
    assert ps == [random_prime(random.Random(f"p{k}")) for k in range(20)]


def test_the_larger_primes_bring_the_target_with_fewer_points():
    """A point's bound over [2^62, 2^63) is about 4 times below the one over [2^60, 2^61): the degree
    and height of gen-chasles at (7,5) (d = 440, h = 3440.8) needed 3 points over [2^60, 2^61)
    (55 / 1.9e16 + 440 / 2^60 = 3.3e-15 a point); 2 points now, each with its own bound, and a
    false claim still fails at such points."""
    from stiefelsym.methods.fixed_size import DegreeBound, _per_point_bound, _points_needed
    deg = DegreeBound(440, 0, 3440.8, 0.0)
    eps = _per_point_bound("modular", deg)
    assert eps == 55 / PRIMES_IN_RANGE_LOWER + 440 / PRIME_LOW
    old = 57 / (19 * 10**15) + 440 / 2**60
    assert _points_needed(old) == 3 and _points_needed(eps) == 2 and eps ** 2 <= 1e-30 < eps
    res = run_points(_claim(mersenne_multiple), 4, 2, "modular", 0)
    assert res.verdict == "fails" and PRIME_LOW <= res.witness["prime"] < PRIME_HIGH


def test_a_constant_divisible_by_p_is_refused_not_reduced_to_zero():
    F = ModularField(2**61 - 1)
    for q in (2**61 - 1, 3 * (2**61 - 1), Fraction(1, 2**61 - 1)):
        with pytest.raises(ConstantDegenerate):
            F.const(q)
    assert F.const(5) * F.const(Fraction(1, 5)) == F.const(1)


def mersenne_multiple(s):
    """False: (2^61 - 1) X vanished mod the old fixed prime 2^61 - 1."""
    return {"pX": s.X * (2**61 - 1)}


def mersenne_multiple_raw(s):
    """False, the constant entering the field arithmetic directly (no const() to refuse it)."""
    return {"pX": s.X[0, 0] * (2**61 - 1)}


@pytest.mark.parametrize("func", [mersenne_multiple, mersenne_multiple_raw], ids=lambda f: f.__name__)
def test_a_constant_multiple_of_the_old_prime_fails(func):
    res = run_points(_claim(func), 3, 2, "modular", 0)
    assert res.verdict == "fails" and PRIME_LOW <= res.witness["prime"] < PRIME_HIGH


def test_a_claim_aimed_at_the_seeds_primes_meets_other_primes():
    """A constant divisible by the primes seed 0 draws for another statement of the same id: the primes
    are drawn from the digest of the aimed claim's own graph (which holds the constant), so they are
    other primes, and the claim fails."""
    probe = _claim(mersenne_multiple)
    key = draw_key(probe, 3, 2, 0)
    c = 1
    for t in range(6):
        for attempt in range(3):
            c *= _prime_field(key, t, attempt).p

    def aimed(s):
        return {"cX": s.X * c}
    aimed_claim = _claim(aimed, cid=probe.id)
    assert draw_key(aimed_claim, 3, 2, 0) != key
    res = run_points(aimed_claim, 3, 2, "modular", 0)
    assert res.verdict == "fails" and c % res.witness["prime"] != 0


def test_the_draws_follow_the_seed_and_the_claims_graph():
    """Fiat-Shamir: the key of every draw is a function of the seed, the size and the traced graph (the
    same claim gives the same key; another constant, another seed or another size gives another)."""
    def times(c):
        def f(s):
            return {"cX": s.X * c}
        return f
    one, same, other = _claim(times(3)), _claim(times(3)), _claim(times(5))
    assert draw_key(one, 3, 2, 0) == draw_key(same, 3, 2, 0)
    assert len({draw_key(one, 3, 2, 0), draw_key(other, 3, 2, 0), draw_key(one, 3, 2, 1),
                draw_key(one, 4, 2, 0)}) == 4


def test_a_prime_dividing_a_constant_of_the_claim_is_redrawn(monkeypatch):
    """The redraw itself: when the first draw of every point is the prime 2^61 - 1, a claim with the
    constant 2^61 - 1 has that prime redrawn (the constant would vanish mod p) and fails."""
    import stiefelsym.methods.fixed_size as methods
    drawn = methods._prime_field

    def first_mersenne(key, t, attempt):
        return ModularField(2**61 - 1) if attempt == 0 else drawn(key, t, attempt)
    monkeypatch.setattr(methods, "_prime_field", first_mersenne)
    res = run_points(_claim(mersenne_multiple), 3, 2, "modular", 0)
    assert res.verdict == "fails" and res.witness["prime"] != 2**61 - 1
    assert "primes dividing a constant of the claim redrawn" in res.certificate + res.message


def test_the_height_bound_sees_big_constants():
    small = degree_bound(_claim(resolvent_identity), 3, 2)

    def big(s):
        R = s.resolvent(s.lam)
        return {"AR": s.A @ R - (s.lam * R - s.In) * s.q(3**400, 7**50)}
    large = degree_bound(_claim(big), 3, 2)
    # the term carrying the constant alone has height >= log2 3^400 (the other term may dominate `small`)
    assert large.height >= 400 * math.log2(3) and large.height > small.height
    assert large.constant_bits >= 400 * math.log2(3) + 50 * math.log2(7)


def fermat(s):
    """False, but x^p - x vanishes at every point of GF(p) for p = 2^61 - 1 (Fermat)."""
    x = s.X[0, 0]
    y, e = s.const(1), 2**61 - 1
    base = x
    while e:
        if e & 1:
            y = y * base
        base = base * base
        e >>= 1
    return {"x^p - x": y - x}


def test_fermat_trick_is_never_checked():
    res = run_points(_claim(fermat), 3, 1, "modular", 0)
    assert res.verdict in ("fails", "inconclusive")


def _stateful_fermat():
    """x^p − x, p the prime of the point the call is for (the claim counts its calls, and the
    primes follow from the seed): it vanishes at every point of GF(p).  Before the degree bound
    came from the sampled evaluation itself, the structural pass was a separate call that such a
    claim could show x − x."""
    calls = [0]

    def claim(s):
        calls[0] += 1
        x = s.X[0, 0]
        # (the key of the earlier draws, without the graph's digest: the claim cannot know its own)
        p = _prime_field(f"0|{c.id}|3|1", calls[0] - 1, 0).p
        return {"r": x ** p - x}
    c = _claim(claim)
    return c, calls


def test_a_claim_that_counts_its_calls_is_never_checked():
    """The degree bound comes from the sampled evaluation itself (values paired with degree
    markers), not only from a separate structural pass the claim could tell apart by counting."""
    c, calls = _stateful_fermat()
    res = run_one(c, Size(3, 1), "modular", 0)
    # traced twice, the two graphs differ (its constant follows the call count): never a verdict
    assert calls[0] >= 2 and res.verdict in ("fails", "inconclusive", "error")
    assert "degree <= d = 1" not in res.message


@pytest.mark.parametrize("kind", ["rational", "modular"])
def test_paired_markers_give_the_structural_bound_on_a_pure_claim(kind):
    """On a claim that computes the same thing on every call the sampled evaluations' own markers
    give the structural pass's bound at every point."""
    c = _claim(_huge_degree_identity(3))
    res = run_points(c, 3, 1, kind, 0)
    assert res.verdict == "checked" and "differ" not in res.certificate
    assert res.checks[0].degree == degree_bound(c, 3, 1).numerator


def _huge_degree_identity(k):
    def claim(s):
        """True: (x/x)^(2^k) = 1, but its degree bound 2^k exceeds what any sample set can bound."""
        y = s.X[0, 0] / s.X[0, 0]
        for _ in range(k):
            y = y * y
        return {"(x/x)^(2^k) - 1": y - 1}
    return claim


@pytest.mark.parametrize("kind,k", [("rational", 64), ("modular", 62)])
def test_a_residual_of_huge_degree_is_inconclusive_not_checked(kind, k):
    res = run_points(_claim(_huge_degree_identity(k)), 3, 1, kind, 0)
    assert res.verdict == "inconclusive" and "bound" in res.message
    honest = run_points(_claim(_huge_degree_identity(3)), 3, 1, kind, 0)
    assert honest.verdict == "checked" and honest.false_pass_bound <= POINTS_TARGET


def test_the_number_of_points_is_chosen_for_the_target():
    assert _points_needed(0.0) == 2 and _points_needed(1e-16) == 2
    assert _points_needed(1e-8) == 4
    assert _points_needed(0.05) == POINTS_CAP and _points_needed(0.1) is None and _points_needed(1.0) is None
    for eps in (1e-16, 3e-11, 1e-8, 2e-3, 0.05):
        k = _points_needed(eps)
        assert eps ** k <= POINTS_TARGET and (k == 2 or eps ** (k - 1) > POINTS_TARGET)


@pytest.mark.parametrize("kind", ["rational", "modular"])
def test_checked_means_a_bound_below_the_target_per_component(kind):
    for n, r in ((3, 2), (3, 3)):
        res = run_points(_claim(resolvent_identity), n, r, kind, 0)
        assert res.verdict == "checked" and 0 < res.false_pass_bound <= POINTS_TARGET
        assert ("each of the 2 components" in res.certificate) == (r == n)
    mod = run_points(_claim(resolvent_identity), 3, 2, "modular", 0)
    assert "Rosser-Schoenfeld" in mod.certificate and "primes:" in mod.certificate
    assert mod.certificate == run_points(_claim(resolvent_identity), 3, 2, "modular", 0).certificate
    eps = _per_point_bound("modular", degree_bound(_claim(resolvent_identity), 3, 2))
    assert 0 < eps < 1e-15


@pytest.mark.parametrize("kind", ["rational", "modular"])
def test_negative_control_sampled_methods(kind):
    res = run_points(_claim(resolvent_identity_sign), 3, 2, kind, 0)
    assert res.verdict == "fails" and res.witness["seed"] == 0


# -- 2. ranks at every point ---------------------------------------------------------------

def every_point_rank_false(s):
    """False: [x] has rank 1 generically, not at every point (x = 0)."""
    return {"rank": Rank(s.mat([[s.X[0, 0]]]), 1, generic=False)}


def every_point_rank_true(s):
    """True: X^T X = I_r has rank r at every point."""
    return {"rank": Rank(s.X.T @ s.X, s.r, generic=False), "X^T X": s.X.T @ s.X - s.Ir}


def every_point_rank_exceeded(s):
    return {"rank": Rank(s.mat([[s.X[0, 0]]]), 0, generic=False)}


def every_point_rank_too_low(s):
    """False: X X^T (r < n) has rank r < n everywhere."""
    return {"rank": Rank(s.X @ s.X.T, s.n, generic=False)}


@pytest.mark.parametrize("kind", ["rational", "modular"])
def test_every_point_ranks_are_not_checked_by_sampling(kind):
    for func in (every_point_rank_false, every_point_rank_true):
        res = run_points(_claim(func, "dim"), 3, 2, kind, 0)
        assert res.verdict == "undecided" and res.message.startswith("not applicable:")
        assert "exact method" in res.message and "generic rank >= " in res.checks[0].detail
    # rank 1 over the function field and no constant nonzero 1x1 minor: where it drops (x = 0) is not
    # found by the exact method, so the false statement is undecided (never proved; `fails` needs a point)
    assert run_exact(_claim(every_point_rank_false, "dim"), 3, 2, 0).verdict == "undecided"
    assert run_exact(_claim(every_point_rank_true, "dim"), 3, 2, 0).verdict == "proved"
    assert run_one(_claim(every_point_rank_true, "dim"), Size(3, 2), kind, 0).expected


@pytest.mark.parametrize("kind", ["rational", "modular"])
def test_a_sampled_rank_above_the_printed_one_still_fails(kind):
    assert run_points(_claim(every_point_rank_exceeded, "dim"), 3, 2, kind, 0).verdict == "fails"


def test_a_rank_below_the_printed_one_at_an_exact_point_fails():
    assert run_points(_claim(every_point_rank_too_low, "dim"), 3, 2, "rational", 0).verdict == "fails"
    assert run_points(_claim(every_point_rank_too_low, "dim"), 3, 2, "modular", 0).verdict not in PASSING


def test_float_never_passes_a_rank():
    res = run_float(_claim(every_point_rank_true, "id"), 3, 2, 0)
    assert res.verdict == "undecided" and res.message.startswith("not applicable:")


def count_wrong_beside_a_true_residual(s):
    return {"X^T X": s.X.T @ s.X - s.Ir, "count": Count(s.n, s.n + 1)}


@pytest.mark.parametrize("method", ["float", "rational", "modular"])
def test_a_wrong_count_next_to_a_true_residual_fails(method):
    assert run_one(_claim(count_wrong_beside_a_true_residual), Size(3, 2), method, 0).verdict == "fails"


# -- 3. the float method -------------------------------------------------------------------

def identically_zero(s):
    return {"X^T X - I": s.X.T @ s.X - s.Ir}


def rounding_sized_zero(s):
    """Identically zero, but only after a cancellation that float64 cannot see: (a + q) - a - q."""
    a, q = s.a[0], s.q(1, 10**20)
    return {"cancel": (a + q) - a - q}


def rounding_sized_nonzero(s):
    """Not zero: (a + q) - a = q = 10^-20, which float64 rounds away."""
    a, q = s.a[0], s.q(1, 10**20)
    return {"tiny": (a + q) - a}


def clearly_nonzero(s):
    return {"X^T X": s.X.T @ s.X}


def test_float_respects_expect_nonzero():
    for func in (identically_zero, rounding_sized_zero):
        res = run_float(_claim(func, expect="nonzero"), 3, 2, 0)
        assert res.verdict == "fails"
    res = run_float(_claim(clearly_nonzero, expect="nonzero"), 3, 2, 0)
    assert res.verdict == "numeric" and "error bound" in res.certificate
    res = run_float(_claim(rounding_sized_nonzero, expect="nonzero"), 3, 2, 0)
    assert res.verdict == "numeric" and res.witness["field"] == "rational"


def only_on_the_identity_component(s):
    X = s.X
    det = (X[0, 0] * (X[1, 1] * X[2, 2] - X[1, 2] * X[2, 1]) - X[0, 1] * (X[1, 0] * X[2, 2] - X[1, 2] * X[2, 0])
           + X[0, 2] * (X[1, 0] * X[2, 1] - X[1, 1] * X[2, 0]))
    return {"det X - 1": det - 1}


def test_float_samples_both_components_when_r_equals_n():
    res = run_float(_claim(only_on_the_identity_component), 3, 3, 0)
    assert res.verdict == "fails" and res.witness["component"] == 1
    assert run_float(_claim(identically_zero), 3, 3, 0).verdict == "numeric"


def overflowing_scale_hides_a_false_entry(s):
    """False.  "scale": 0 with a term scale beyond float64 (it overflowed to inf and switched the
    resolution test off for every entry); "false": a cancellation float64 cannot resolve, off by 10^-6."""
    a = s.a[0]
    w = (a + s.q(1000)) - s.q(1000)
    for _ in range(8):
        w = w * w
    q = s.q(1, 10**12)
    return {"scale": w - w, "false": 1 / ((a + q) - a) - 1 / (q * (1 + s.q(1, 10**6)))}


def overflowing_scale_true(s):
    a = s.a[0]
    w = (a + s.q(1000)) - s.q(1000)
    for _ in range(8):
        w = w * w
    q = s.q(1, 10**12)
    return {"scale": w - w, "true": 1 / ((a + q) - a) - 1 / q}


def test_a_non_finite_scale_never_passes():
    res = run_float(_claim(overflowing_scale_hides_a_false_entry), 3, 1, 0)
    assert res.verdict == "fails" and (res.witness["field"] == "rational" or res.witness["field"].startswith("arb"))
    assert "float64: unresolved" in res.message
    res = run_float(_claim(overflowing_scale_true), 3, 1, 0)
    assert res.verdict == "numeric" and "mpmath" in res.certificate


def test_non_finite_float64_poisons_every_number_computed_from_it():
    F = FloatField()
    big, one, zero = F.const(10**300), F.const(1), F.const(0)
    assert (big * big).poisoned and F.const(10**400).poisoned and (ErrNum(float("nan")) + one).poisoned
    overflow = big * big
    # nothing computed from a poisoned number becomes finite again: not 1/inf, not 0 * inf, not x - x
    for x in (one / overflow, zero * overflow, overflow - overflow, one / (one + overflow * zero), -overflow):
        assert x.poisoned
    tiny = F.const(Fraction(1, 10**200))
    z = tiny * tiny                     # underflows to 0: the bound must still contain 10^-400
    assert z.v == 0 and z.e > 0 and not z.poisoned


def test_float_solve_accounts_for_entries_that_are_zero_only_within_their_bound():
    """(1 + 10^-20) - 1 is 0 in float64 with a bound of ~1e-16: an elimination that skipped it would
    claim x_2 = 0 exactly; the true x_2 is -10^-20, and the bound must contain it."""
    F = FloatField()
    one = F.const(1)
    f = (one + F.const(Fraction(1, 10**20))) - one
    assert f.v == 0 and f.e > 0
    for M, B, i in (([[one, F.const(0)], [f, one]], [[one], [F.const(0)]], 1),
                    ([[F.const(2), F.const(1)], [f, one]], [[one], [F.const(3)]], 1)):
        x = F.solve(M, B)
        Mq = [[Fraction(1), Fraction(0)], [Fraction(1, 10**20), Fraction(1)]] if M[0][0].v == 1 else \
             [[Fraction(2), Fraction(1)], [Fraction(1, 10**20), Fraction(1)]]
        Bq = [Fraction(1), Fraction(0)] if M[0][0].v == 1 else [Fraction(1), Fraction(3)]
        det = Mq[0][0] * Mq[1][1] - Mq[0][1] * Mq[1][0]
        exact = [(Bq[0] * Mq[1][1] - Mq[0][1] * Bq[1]) / det, (Mq[0][0] * Bq[1] - Mq[1][0] * Bq[0]) / det]
        for k in range(2):
            assert abs(Fraction(x[k][0].v) - exact[k]) <= Fraction(x[k][0].e)


def lax_false(s):
    """A false Lax-type equation at a larger size: [Phi, Phi^2] = Phi (it is 0)."""
    Phi = s.Phi
    return {"lax": (Phi @ (Phi @ Phi) - (Phi @ Phi) @ Phi) - s.q(1, 10**6) * Phi}


def lax_true(s):
    Phi = s.Phi
    return {"lax": Phi @ (Phi @ Phi) - (Phi @ Phi) @ Phi}


def lax_true_huge(s):
    """The same true identity with entries near 1e200: float64 overflows (inf - inf)."""
    Phi = s.Phi * s.q(10**200)
    return {"lax": Phi @ (Phi @ Phi) - (Phi @ Phi) @ Phi}


def test_float_decides_at_n_12_in_float64():
    res = run_float(_claim(lax_true), 12, 1, 0)
    assert res.verdict == "numeric" and "float64: max |residual|" in res.message
    res = run_float(_claim(lax_false), 12, 1, 0)
    assert res.verdict == "fails" and (res.witness["field"] == "rational" or res.witness["field"].startswith("arb"))


def test_float64_overflow_escalates_to_mpmath():
    res = run_float(_claim(lax_true_huge), 6, 1, 0)
    assert res.verdict == "numeric" and "float64: unresolved" in res.message and "mpmath" in res.certificate


def test_negative_control_float():
    assert run_float(_claim(resolvent_identity_sign), 3, 2, 0).verdict == "fails"
    assert run_float(_claim(resolvent_identity), 3, 2, 0).verdict == "numeric"


# -- 4. vacuous checks ---------------------------------------------------------------------

def empty_list(s):
    return {"nothing": []}


def empty_dict(s):
    return {"nothing": {}, "nested": {"also": []}}


def empty_matrix(s):
    return {"nothing": s.zeros(0, 0)}


@pytest.mark.parametrize("func", [empty_list, empty_dict, empty_matrix], ids=lambda f: f.__name__)
@pytest.mark.parametrize("method", ["exact", "rational", "modular", "float", "auto"])
def test_a_vacuous_check_is_an_error(func, method):
    res = run_one(_claim(func), Size(3, 2), method, 0)
    assert res.verdict == "error" and "vacuous" in res.message


@pytest.mark.parametrize("func", [empty_list, empty_dict], ids=lambda f: f.__name__)
def test_a_vacuous_check_is_an_error_dimension_free(func):
    res = run_one(_claim(func), None, "free", 0)
    assert res.verdict == "error" and "vacuous" in res.message


def test_an_empty_claim_is_still_an_error():
    for method in ("modular", "float"):
        assert run_one(_claim(lambda s: {}), Size(3, 2), method, 0).verdict == "error"


# -- 5. hard cases that change nothing -----------------------------------------------------

@pytest.mark.parametrize("method", ["rational", "modular", "float"])
def test_a_hard_case_that_changes_no_parameter_says_so(method):
    res = run_one(_claim(identically_zero), Size(3, 2), method, 0, hard="near-pole")
    assert "the hard case near-pole changed no parameter of this claim" in res.message
    res = run_one(_claim(resolvent_identity), Size(3, 2), method, 0, hard="near-pole")
    assert "changed no parameter" not in res.message


def _hides_from_the_division_probe():
    """True in the free algebra (X^T X = I), but raises on its first call, which is the division
    probe's at a fixed size (a claim can no longer tell a fixed size from the free scene by the
    class of its scene; it can count its calls): the probe, which guards the dimension-free proof
    against divisions by identically zero expressions, must not be skipped by a claim that raises
    there."""
    calls = []

    def claim(s):
        calls.append(1)
        if len(calls) == 1:
            raise RuntimeError("not at a fixed size")
        return {"XtX": s.X.T @ s.X - s.Ir}
    return claim


def test_a_claim_that_raises_at_the_probe_is_not_proved_for_all_sizes():
    res = run_one(_claim(_hides_from_the_division_probe()), None, "free", 0)
    assert res.verdict == "error", (res.verdict, res.message)


def _power_or_zero(s):
    """False (x^2 = x): unless a power raises, in which case the claim returns 0.  A power that one
    number type lacks (float64 with error bounds, degree markers) used to raise there only."""
    x = s.X[0, 0]
    try:
        y = x ** 2
    except TypeError:
        return {"x^2 - x": x - x}
    return {"x^2 - x": y - x}


@pytest.mark.parametrize("method", ["exact", "rational", "modular", "float"])
def test_powers_are_the_same_on_every_method(method):
    """Scalar powers are products (square and multiply) on every number system, so a claim cannot
    catch a power that raises on one method only and return zero there."""
    res = run_one(_claim(_power_or_zero), Size(3, 1), method, seed=0)
    assert res.verdict == "fails", (method, res.verdict, res.message)
    true = run_one(_claim(lambda s: {"r": s.X[0, 0] ** 3 * s.X[0, 0] ** -2 - s.X[0, 0]}), Size(3, 1), method, seed=0)
    assert true.verdict in ("proved", "checked", "numeric"), (method, true.verdict, true.message)


# -- the shortcuts of the whole-matrix backends: zero entries skipped, outer products by one,
# reassociated chains, the Cayley X from a solve, the block solve (n >= 32 in float) -----------

def _reassociated_wrongly(s):
    return {"c": (s.X @ s.P.T) @ s.X - s.X @ (s.X.T @ s.P)}          # PᵀX is not XᵀP


def _zeros_around_a_small_term(s):
    Z = s.zeros(s.n, s.r, ("n", "r"))
    return {"c": Z + s.X @ (s.X.T @ s.X) - Z - s.X + s.q(0) * s.P + s.q(1, 10**6) * (s.P @ s.X.T @ s.X)}


def _outer_product_is_not_the_identity(s):
    return {"c": s.X @ s.X.T - s.identity(s.n, "n")}                 # false for r < n


def _cayley_without_its_j(s):
    I, K = s.identity(s.n, "n"), s.xi
    return {"c": (I - K) @ (I + K).inv() @ s.X - s.q(2) * ((I + K).inv() @ s.X)}


@pytest.mark.parametrize("func", [_reassociated_wrongly, _zeros_around_a_small_term,
                                  _outer_product_is_not_the_identity, _cayley_without_its_j])
@pytest.mark.parametrize("method,size", [("exact", (3, 1)), ("exact", (3, 2)), ("modular", (4, 2)),
                                         ("rational", (4, 2)), ("float", (4, 2)), ("float", (40, 20)),
                                         ("modular", (40, 20))])
def test_false_claims_through_the_backends_shortcuts_fail(func, method, size):
    """False statements written to run through the backends' shortcuts: every method refutes them
    (at (3,1) PᵀX = XᵀP = 0, so the reassociation claim is true there and is not run)."""
    if func is _reassociated_wrongly and size[1] == 1:
        pytest.skip("true at r = 1")
    claim = Claim(id="trick", paper=("prep",), kind="id", section="t", func=func, sizes=admissible(40))
    res = run_one(claim, Size(*size), method, seed=0)
    assert res.verdict == "fails", (res.verdict, res.message)
