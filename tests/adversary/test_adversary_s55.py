"""Adversarial review of stop 55.

Dimension claims (s55_dimension_probes.py): ranks and counts at every point and generic, engine-built constant
matrices on the equivariant chart (a reflection, an eigenspace projector, basis vectors of ℝʳ, in both
realizations), Jacobians of non-square symmetric statements and of the Dirac flow off T*V, ranks written with
sizes.  No wrong verdict: each false probe fails, is refused or stays undecided, under every method.

Inverse statements reading A⁻¹ (s55_inverse_ainv.py): x ↦ A⁻¹x is invertible only where A is, and the
standard realization's A is any symmetric matrix; the identities op(inv(y)) = y, inv(op(x)) = x hold as
rational functions of A's entries, so every method passed "invertible at every point".  Closed: A⁻¹ in op or
inv is a divisor that is not a constant (refused when the statement is traced: error at the fixed sizes,
undecided by free), except in the metric realization, whose A is positive definite."""
from __future__ import annotations

from adversary_cli import PASSING, verdicts_each

PROBES = "s55_dimension_probes.py"
#: false at (3,2) (the docstrings of the file say why)
FALSE_PROBES = ("adv-s55-t1-refl-res", "adv-s55-t1-refl-rank-every", "adv-s55-t1-proj-rank-every",
                "adv-s55-t1-basis-rank", "adv-s55-t2-jac-nonsquare-sym", "adv-s55-t5-std-basis", "adv-s55-t5-met-basis",
                "adv-s55-t5-met-mat", "adv-s55-t5-met-rank", "adv-s55-t6-rank-n", "adv-s55-t6-count-expr")
#: false at (3,1), and cheap there for the exact method (23 s each at (3,2))
FALSE_AT_31 = ("adv-s55-t4-jac-dirac-vs-closed", "adv-s55-t4-jac-diff-rank")


def test_false_dimension_probes_never_pass():
    got = verdicts_each(PROBES, ("exact", "modular"), size="3,2", ids=FALSE_PROBES + ("adv-s55-t2-jac-nonsquare-full",))
    for method, v in got.items():
        for cid in FALSE_PROBES:
            assert v[cid] not in PASSING, (method, cid, v[cid])
        assert v["adv-s55-t2-jac-nonsquare-full"] in PASSING, (method, v)
    got = verdicts_each(PROBES, ("exact", "modular", "float"), size="3,1", ids=FALSE_AT_31)
    for method, v in got.items():
        for cid in FALSE_AT_31:     # (float skips the rank: a dimension is not its to compute)
            if method != "float" or cid == FALSE_AT_31[0]:
                assert v[cid] == "fails", (method, cid, v[cid])


INVERSES = "s55_inverse_ainv.py"
A_INVERSE = ("adv-s55-inv-ainv", "adv-s55-inv-ainv-congruence", "adv-s55-rinv-ainv", "adv-s55-inv-ainv-hidden")


def test_an_inverse_statement_reading_a_inverse_is_refused_outside_the_metric_realization():
    got = verdicts_each(INVERSES, ("free", "exact", "modular", "float"), size="3,2")
    for method, v in got.items():
        for cid in A_INVERSE:
            assert v[cid] == ("undecided" if method == "free" else "error"), (method, cid, v[cid])
        for cid in ("adv-s55-inv-ainv-metric", "adv-s55-inv-constant"):
            assert v[cid] in PASSING, (method, cid, v[cid])
