"""Adversarial review of stop 56: the numeric methods (s56_numeric_steps.py).

Two engine steps computed on floats and balls what the exact fields compute otherwise, so that a certified
enclosure bounded another value and ball arithmetic said `fails` of true statements and `proved` of false ones
said not to vanish (float was caught by its exact confirmations, or stayed inconclusive):

1. the closed-form multipliers of the Dirac flow at a point a claim gives (twisted.at_point) off V, taken on
   trust because "the chart's point is on V by construction".  Closed: at a given point floats and balls solve
   the multiplier system, as the exact fields do wherever XᵀX = I_r does not hold exactly (Scene._point_given);
2. the degree of polynomial_gradient's form decided by "0 lies in the enclosure", which hides a term of higher
   degree under the radius of a large one.  Closed: the degree is decided in exact fields only; floats and balls
   interpolate at the highest degree, exact for every lower one (brackets._DEGREE_DECIDED).

And, whatever the step: a ball `fails` (or `proved` of a claim said not to vanish) stands only where an exact
point agrees, modulo a large prime (fixed_size._exact_agrees), as a float `fails` and every `numeric` already did."""
from __future__ import annotations


from adversary_cli import PASSING, verdicts_each

PROBES = "s56_numeric_steps.py"
TRUE = ("adv-s56-offv-tangent", "adv-s56-offv-bracket", "adv-s56-offv-mult", "adv-s56-offv-shifted",
        "adv-s56-onv-closed", "adv-s56-polygrad-zero", "adv-s56-polygrad-additive")
FALSE = ("adv-s56-offv-tangent-nonzero", "adv-s56-offv-closed", "adv-s56-polygrad-nonzero")


def test_numeric_steps_agree_with_the_exact_evaluation():
    got = verdicts_each(PROBES, ("exact", "modular", "float", "ball"), size="3,2")
    for method, v in got.items():
        for cid in TRUE:
            assert v[cid] != "fails", (method, cid, v[cid])
            if method != "exact":       # (exact: a 6 x 6 symbolic solve of offv-shifted is beyond its budget)
                assert v[cid] in PASSING, (method, cid, v[cid])
        for cid in FALSE:
            assert v[cid] not in PASSING, (method, cid, v[cid])
            assert v[cid] == "fails", (method, cid, v[cid])
        # a degree beyond the highest, hidden under a large term: refused alike by every method
        assert v["adv-s56-polygrad-seventh-nonzero"] == "error", (method, v)


def _false_claim():
    """XᵀX = 0, false (a claim of the engine's own making: loading a file would seal the engine, and the test
    replaces one of its functions)."""
    from stiefelsym import admissible
    from stiefelsym.claims import Claim

    def gram(s):
        return {"XtX": s.X.T @ s.X}
    return Claim(id="ball-refutation", paper=(), kind="id", section="t", func=gram, sizes=admissible(4))


def test_a_ball_refutation_stands_only_where_an_exact_point_agrees(monkeypatch):
    from stiefelsym.methods import fixed_size
    claim = _false_claim()
    res = fixed_size.run_ball(claim, 3, 2, 0)
    assert res.verdict == "fails" and "confirmed by an exact point mod p" in res.certificate, res
    real = fixed_size.run_points

    def exact_says(verdict: str):
        def run_points(c, n, r, kind, seed, func=None, *a, **k):
            if kind != "modular":
                return real(c, n, r, kind, seed, func, *a, **k)
            out = fixed_size._base_result(c, n, r, "rational", seed)
            out.verdict, out.message = verdict, "stand-in"
            return out
        return run_points
    monkeypatch.setattr(fixed_size, "run_points", exact_says("checked"))
    res = fixed_size.run_ball(claim, 3, 2, 0)
    assert res.verdict == "inconclusive" and "does not confirm" in res.message, res
    assert res.witness is None and not res.certificate
    monkeypatch.setattr(fixed_size, "run_points", exact_says("error"))
    res = fixed_size.run_ball(claim, 3, 2, 0)
    assert res.verdict == "error" and "refuses" in res.message, res
