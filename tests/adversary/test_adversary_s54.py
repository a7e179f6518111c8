"""Adversarial review of stop 54.

The review found a false identity proved for every n, r by the dimension-free method: the twisted bracket of
Appendix 1 and the derivative along the twisted flow, for a field strength F that is not skew.  On the
fixed-size scenes the bracket is the Dirac bracket built from W⁻¹ = [[0, I], [−I, εK]], K(V) = VFᵀ, which is
the derivative along the flow only when W⁻¹ is antisymmetric (F skew); the dimension-free scene defines the
bracket as that derivative, so the identity was a tautology there (the fixed-size methods refuted it with
witnesses).  The engine steps of stiefelsym.twisted now refuse, while the claim is traced, a field strength
that is not skew by its construction (stiefelsym.ir.passes.skew_by_construction): the same refusal under
every method."""
from __future__ import annotations

from adversary_cli import PASSING, verdicts_each

FILE = "s54_twisted_nonskew_F.py"
REFUSED = ("nsf-sym", "nsf-general", "nsf-product-of-skew", "nsf-explicit-not-opposite")


def test_a_field_strength_that_is_not_skew_is_refused_by_every_method():
    got = verdicts_each(FILE, ("free", "exact", "modular", "float"), size="3,2")
    for method, v in got.items():
        for cid in REFUSED:
            assert v[cid] not in PASSING, (method, cid, v)
            if method != "free":
                assert v[cid] == "error", (method, cid, v)


def test_skew_field_strengths_built_in_the_recognised_ways_are_accepted():
    got = verdicts_each(FILE, ("free", "exact", "modular"), size="3,2")
    for method, v in got.items():
        assert v["nsf-control-skew"] in PASSING, (method, v)
        # the explicit matrix needs fixed sizes: the dimension-free method leaves that claim undecided
        allowed = PASSING + ("undecided",) if method == "free" else PASSING
        assert v["nsf-control-constructions"] in allowed, (method, v)


def test_routes_around_the_skew_check_are_refused_too():
    """The undecorated step (__wrapped__), the free algebra's private flow, F + Fᵀ − Fᵀ, a sum with a symmetric
    part, M − Nᵀ, η + λI: every method refuses or leaves them undecided, none passes them."""
    got = verdicts_each("s54_twisted_bypass.py", ("free", "exact", "modular"), size="3,2")
    for method, v in got.items():
        assert v and all(x not in PASSING for x in v.values()), (method, v)
