"""The ball method (rigorous arb enclosures at the float method's exact points) and the float
method's error model checked against it.

* every catalog claim the float method finds ``numeric`` at a small size is passed by the ball
  method too (``numeric``, or ``proved`` for a claim that a residual is nonzero: an enclosure that
  excludes 0 proves it), and every claim the float method refutes is refuted;
* corrupted claims (negative controls) end ``fails`` with a certified witness, at n = 200 too;
* the ball backend's own shortcut (the Cayley chart's solve instead of an inverse) encloses the
  exact values, replayed over ℚ;
* the float64 bound of every residual entry of the catalog contains its true error (the distance
  from the float64 value to the ball of the exact value); a shrunk bound is caught.
"""
from __future__ import annotations

import random
from fractions import Fraction

import flint
import numpy as np
import pytest

from stiefelsym import admissible, comm
from stiefelsym.backends.ball import BallField, BallNum, working_precision
from stiefelsym.claims import Claim, Size
from stiefelsym.methods.hard import HARD_CASES
from stiefelsym.backends.matrix import Mat
from stiefelsym.results import PASSING
from stiefelsym.run.runner import run_one
from stiefelsym.analyses.speed import control_claim

from ball_replay import float_model_errors, optimistic

SEED = 0


def _catalog_sizes(catalog, n_max: int, which: str = "first"):
    out = []
    for c in catalog:
        if c.kind == "dim":
            continue
        sizes = [s for s in c.sizes if s.n <= n_max]
        if sizes:
            out.append((c.id, sizes[0] if which == "first" else sizes[-1]))
    return out


def _ids(pairs):
    return [f"{cid}[n={s.n},r={s.r}]" for cid, s in pairs]


def _load():
    from stiefelsym.claims import load_catalog
    return load_catalog()


SMALL = _catalog_sizes(_load(), 4)


# -- the ball method against the float method -------------------------------------------------------

@pytest.mark.parametrize("cid, size", SMALL, ids=_ids(SMALL))
def test_ball_agrees_with_float(catalog, cid, size):
    c = catalog.get(cid)
    f = run_one(c, size, "float", seed=SEED)
    b = run_one(c, size, "ball", seed=SEED)
    assert b.method == "ball" and b.verdict != "error", b.message
    if f.verdict == "numeric":
        assert b.verdict in PASSING, (b.verdict, b.message)
        assert b.verdict == ("proved" if c.expect == "nonzero" else "numeric")
    elif f.verdict == "fails":
        assert b.verdict == "fails", (b.verdict, b.message)
    else:
        assert b.verdict == f.verdict
    assert b.expected == f.expected


def test_a_numeric_ball_verdict_states_its_rigorous_bound(catalog):
    res = run_one(catalog.get("neumann-flow"), Size(4, 2), "ball", seed=SEED)
    assert res.verdict == "numeric"
    assert "contains its exact value" in res.certificate and "|exact residual| <=" in res.certificate
    assert res.false_pass_bound is None and res.witness is None


# -- negative controls --------------------------------------------------------------------------------

def _flow(s):
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    return {"X": P - k * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}


def _lax_along_a_wrong_flow(eps: Fraction):
    def residual(s):
        """LA1 along the flow with X' changed by eps X Pᵀ X."""
        L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
        flow = _flow(s)
        flow["X"] = flow["X"] - s.q(eps.numerator, eps.denominator) * (s.X @ s.P.T @ s.X)
        return {"LA1": s.d(L, flow) - comm(s.Phi - s.lam * s.A, L(s))}
    return residual


WRONG = Claim(id="wrong-LA1", paper=("LA1",), kind="lax", section="5",
              func=_lax_along_a_wrong_flow(Fraction(1, 10**6)), sizes=admissible(8),
              title="LA1 along a flow off by 1e-6 (negative control).")
SLIGHTLY_WRONG = Claim(id="slightly-wrong-LA1", paper=("LA1",), kind="lax", section="5",
                       func=_lax_along_a_wrong_flow(Fraction(1, 10**14)), sizes=admissible(8),
                       title="LA1 along a flow off by 1e-14.")


@pytest.mark.parametrize("claim, size", [(control_claim(), Size(4, 2)), (control_claim(), Size(3, 3)),
                                         (WRONG, Size(5, 2))],
                         ids=["corrupted-LA1[n=4,r=2]", "corrupted-LA1[n=3,r=3]", "wrong-LA1[n=5,r=2]"])
def test_a_corrupted_claim_fails_with_a_certified_witness(claim, size):
    res = run_one(claim, size, "ball", seed=SEED)
    assert res.verdict == "fails", res.message
    assert "excludes 0" in res.certificate and res.false_pass_bound is None
    assert res.witness["seed"] == SEED and res.witness["point"]
    assert "--method ball" in res.rerun and f"--seed {SEED}" in res.rerun
    # the witness point's coordinates are exact rationals
    assert all("/" in v or v.lstrip("-").isdigit() for v in res.witness["point"].values())


def test_numeric_is_not_a_proof_of_the_identity():
    """A residual of 10⁻¹⁴ of its terms is nonzero, but below the resolution 10⁻⁸ of the term scale: the
    ball enclosure alone says ``numeric`` with a rigorous bound on it at this point, which is all it
    claims; the confirmation at exact points mod p, which runs at every size, refutes it, as the exact
    methods do."""
    from stiefelsym.methods.fixed_size import _run_ball
    n = 14
    alone = _run_ball(SLIGHTLY_WRONG, n, 2, SEED, SLIGHTLY_WRONG.func, None)
    assert alone.verdict == "numeric"
    bound = float(alone.certificate.rsplit("|exact residual| <= ", 1)[1].split()[0])
    assert 0 < bound < 1e-8
    for size in (Size(n, 2), Size(5, 2)):
        res = run_one(SLIGHTLY_WRONG, size, "ball", seed=SEED)
        assert res.verdict == "fails" and "exact points mod p" in res.message
    assert run_one(SLIGHTLY_WRONG, Size(5, 2), "modular", seed=SEED).verdict == "fails"


@pytest.mark.parametrize("method", ["float", "ball"])
def test_numeric_without_an_exact_point_is_not_a_pass(monkeypatch, method):
    """Where the confirmation cannot evaluate the claim at one exact point mod p, float's or ball's
    `numeric` is not reported as a pass: `inconclusive`, with the reason."""
    import stiefelsym.methods.fixed_size as methods
    real = methods.run_points

    def no_point(*args, **kw):
        res = real(*args, **kw)
        res.verdict, res.message, res.checks = "error", "no exact point", []
        return res
    monkeypatch.setattr(methods, "run_points", no_point)
    true = Claim(id="true-LA1", paper=("LA1",), kind="lax", section="5",
                 func=_lax_along_a_wrong_flow(Fraction(0)), sizes=admissible(8))
    res = run_one(true, Size(4, 2), method, seed=SEED)
    assert res.verdict == "inconclusive" and "could not decide (error: no exact point)" in res.message


def test_a_corrupted_claim_fails_at_n_200():
    res = run_one(control_claim(), Size(200, 2), "ball", seed=SEED)
    assert res.verdict == "fails", res.message
    assert res.witness["seed"] == SEED


# -- the backend against exact arithmetic ---------------------------------------------------------------

def _cayley(F, m, r, rng):
    S = [[F.const(0)] * m for _ in range(m)]
    for i in range(m):
        for j in range(i + 1, m):
            x = F.param("s", rng)
            S[i][j], S[j][i] = x, -x
    S = Mat._rows(S, F)
    In = Mat.identity(m, F)
    J = Mat._consts(np.eye(m, r, dtype=np.int64), F)
    G = Mat._rows([[F.param("g", rng) for _ in range(r)] for _ in range(m)], F)
    Zi = (In + S).inv()
    return [(In - S) @ Zi @ J, Zi @ G, (In - S) @ Zi]


@pytest.mark.parametrize("bits", [53, 212])
@pytest.mark.parametrize("m, r", [(5, 2), (30, 7)])
def test_ball_matrices_enclose_the_exact_values(bits, m, r):
    """The deferred Cayley inverse (a solve with a residual bound) and arb's own products and
    inverses contain the exact rational values at the same exact parameters."""
    from stiefelsym.backends.fields import RationalField

    class Replay(RationalField):
        def param(self, name, rng):
            x = BallField().param(name, rng)
            return flint.fmpq(*Fraction(float(x.b.mid())).as_integer_ratio())
    with working_precision(bits):
        out = _cayley(BallField(bits), m, r, random.Random(1))
        exact = _cayley(Replay(), m, r, random.Random(1))
        for B, Q in zip(out, exact):
            for i in range(Q._shape()[0]):
                for j in range(Q._shape()[1]):
                    b, q = B._view()[i, j], Q._view()[i, j]
                    assert isinstance(b, BallNum) and b.b.contains(q)
                    assert float(b.b.rad()) < 2.0 ** (20 - bits) * m * m


# -- the float64 error model against balls ---------------------------------------------------------------

MODEL = _catalog_sizes(_load(), 4, which="last")


@pytest.mark.parametrize("cid, size", MODEL, ids=_ids(MODEL))
def test_the_float64_bound_contains_the_true_error(catalog, cid, size):
    errors = float_model_errors(catalog.get(cid), size.n, size.r, SEED)
    assert errors
    bad = optimistic(errors)
    assert not bad, f"optimistic float64 bounds: {bad[:3]}"


MODEL6 = _catalog_sizes(_load(), 6, which="last")


@pytest.mark.slow
@pytest.mark.parametrize("cid, size", MODEL6, ids=_ids(MODEL6))
def test_the_float64_bound_contains_the_true_error_to_n_6(catalog, cid, size):
    assert not optimistic(float_model_errors(catalog.get(cid), size.n, size.r, SEED))


HARD_CLAIMS = ("neumann-lax", "manakov-lax", "neumann-flow")


@pytest.mark.parametrize("case", sorted(HARD_CASES))
@pytest.mark.parametrize("cid", HARD_CLAIMS)
def test_the_float64_bound_contains_the_true_error_at_hard_cases(catalog, cid, case):
    """At a hard point (the float method's own: its hard values are the float64 numbers it took as
    exact inputs, given to the ball scene coordinate by coordinate)."""
    errors = float_model_errors(catalog.get(cid), 4, 2, SEED, hard=case)
    assert not optimistic(errors), optimistic(errors)[:3]
    if case != "huge-momenta":           # there float64 overflows: no finite value to compare
        assert errors and optimistic(errors, shrink=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("case", sorted(HARD_CASES))
@pytest.mark.parametrize("cid, size", MODEL6, ids=_ids(MODEL6))
def test_the_float64_bound_contains_the_true_error_at_every_hard_case(catalog, cid, size, case):
    assert not optimistic(float_model_errors(catalog.get(cid), size.n, size.r, SEED, hard=case))


@pytest.mark.parametrize("cid, size", [("neumann-lax", Size(4, 2)), ("neumann-flow", Size(6, 3)),
                                       ("momentum-maps-poisson", Size(4, 2))])
def test_a_shrunk_float64_bound_is_caught(catalog, cid, size):
    """Negative control: the same comparison with every bound divided by 10⁹ finds entries whose
    true error exceeds it (the float64 bounds are sound, not vacuous)."""
    errors = float_model_errors(catalog.get(cid), size.n, size.r, SEED)
    assert not optimistic(errors)
    assert optimistic(errors, shrink=1e-9)


def test_a_float_value_off_by_more_than_its_bound_is_caught(catalog):
    """Negative control of the comparison itself: a value moved by twice its bound (and at least
    10⁻³⁰⁰) is certainly outside it."""
    errors = float_model_errors(catalog.get("neumann-flow"), 4, 2, SEED)
    from ball_replay import Violation
    moved = [Violation(x.entry, x.value, x.bound, x.distance + 2 * x.bound + 1e-300) for x in errors]
    assert len(optimistic(moved)) == len(moved)


# -- the command line and the Python API ------------------------------------------------------------------

def test_the_command_line_runs_the_ball_method(run):
    out = run("verify", "neumann-flow", "--size", "4,2", "--method", "ball", "--no-report")
    assert out.exit_code == 0, out.output
    assert "numeric" in out.output and "ball" in out.output


def test_the_python_api_runs_the_ball_method():
    from stiefelsym.api import verify
    results = verify("neumann-lax", sizes=[(5, 2)], methods="ball", memory=None)
    assert [r.verdict for r in results] == ["numeric"] and results.ok


def test_the_ball_method_is_refused_on_dimension_claims(catalog):
    from stiefelsym.run.runner import plan
    dims = [c for c in catalog if c.kind == "dim"][:1]
    assert dims and plan(dims, None, ["ball"]) == []


# -- hard cases ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("method", ["float", "ball", "rational"])
def test_a_claim_the_hard_case_does_not_touch_is_verified_at_random_points(catalog, method):
    """near-pole rewrites λ only: a claim without λ is verified as without the case (here an erratum
    at r = 1, which must fail as documented, instead of ending inconclusive)."""
    c = catalog.get("gram-not-in-involution-with-psi")
    res = run_one(c, Size(2, 1), method, SEED, hard="near-pole")
    assert res.verdict == "fails" and res.expected, res.message
    assert "changed no parameter of this claim: verified at random points" in res.message
    assert "--hard near-pole" in res.rerun


@pytest.mark.parametrize("case", ["near-pole", "near-equal-a", "large-momenta", "huge-momenta", "far-chart"])
def test_ball_at_hard_cases(catalog, case):
    """At a hard point the ball method certifies a corrupted claim's failure, and says nothing of a
    true statement (the point is chosen): undecided, or verified at random points if untouched."""
    bad = run_one(control_claim(), Size(4, 2), "ball", SEED, hard=case)
    if case == "huge-momenta":
        # terms near 1e480 whose difference is near 1e160: 424 bits do not reach it, and the term
        # scales overflow float64: inconclusive, never a pass
        assert bad.verdict == "inconclusive", bad.message
    else:
        assert bad.verdict == "fails", bad.message
    good = run_one(catalog.get("neumann-lax"), Size(4, 2), "ball", SEED, hard=case)
    if case == "huge-momenta":
        # a known limit: the term scales (float64) overflow, so no resolution test, never a pass
        assert good.verdict == "inconclusive" and "overflows float64" in good.message
    else:
        assert good.verdict in ("undecided", "numeric") and good.expected, good.message


def test_a_ball_run_beyond_the_memory_budget_is_refused(run):
    """A ball matrix entry takes 48 bytes of arb and 8 of its term scale: n = 10000 needs more than
    4 n x n matrices' 20 GiB, refused up front (exit 2) instead of dying of memory."""
    out = run("verify", "neumann-lax", "--size", "10000,2", "--method", "ball", "--memory", "4", "--no-report")
    assert out.exit_code == 2 and "memory budget" in out.output
