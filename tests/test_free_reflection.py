"""An orthogonal symmetry S of ℝⁿ commuting with A as a letter of the free algebra (S = Sᵀ, S² = I_n, SA = AS,
and SR = RS for every resolvent R, derived from SA = AS and the resolvent's definition): the reflection claims of
§4 and §8 are proved for every n, r and every such S (every element of ℤ₂ⁿ when A is diagonal; at fixed sizes
S = S₁); what holds for S₁ only is not proved, a corrupted claim is not, and the checker rejects a forged
certificate."""

import pytest

from stiefelsym import twisted
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.fixed_size import run_exact
from stiefelsym.proofs import sec4_integrability as sec4
from stiefelsym.proofs import sec8_dual_lax_pair as sec8
from free_words import forged

CATALOG = load_catalog()


def _proved(res):
    assert res.verdict == "proved", res.message
    report = check_certificate(res.certificate_data)
    assert report.accepted, report.message
    return res


@pytest.mark.parametrize("cid", ["manakov-reflections", "dual-lax-reflections"])
def test_the_reflection_claims_are_proved_for_every_symmetry(cid):
    res = _proved(run_free(CATALOG.get(cid)))
    used = {t["hyp"] for e in res.certificate_data["entries"] for t in e["terms"]}
    assert used & {"SrefSref", "SrefA"}


def trace_of_the_first_reflection(s):
    """tr S₁ = n − 2 holds for S₁ (at fixed sizes) but not for every symmetry S: not proved dimension-free."""
    return {"tr S - n + 2": s.tr(twisted.reflection(s)) - s.tr(s.In) + 2}


def resolvent_at_the_reflected_point_shifted(s):
    """Corrupted: 𝓛*(SX, SP) with the resolvent at −λ in place of λ."""
    S = twisted.reflection(s)
    R = s.resolvent(-s.lam)
    X, P = S @ s.X, S @ s.P
    return {"L*": sec8.block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, P.T @ R @ X]]) - sec8.L_dual(s)}


def dual_a_of_sx_only(s):
    """Corrupted: 𝓐*_neum(λ) at (SX, P) (only X reflected) is 𝓐*_neum(λ) (its block XᵀP is not)."""
    S = twisted.reflection(s)
    return {"A*": sec8.A_dual_normal_at(s, S @ s.X, s.P) - sec8.A_dual_normal(s)}


def manakov_flow_of_sx_only(s):
    """Corrupted: the Manakov flow at (SX, P) is S times the flow (only X reflected)."""
    S = twisted.reflection(s)
    return {"dX/dt": sec4.flow_XP3_at(s, S @ s.X, s.P)["X"] - S @ sec4.flow_XP3(s)["X"]}


CORRUPTED = [("dual-lax-reflections", resolvent_at_the_reflected_point_shifted), ("dual-lax-reflections", dual_a_of_sx_only),
             ("manakov-reflections", manakov_flow_of_sx_only)]


@pytest.mark.parametrize("cid, func", CORRUPTED, ids=[f.__name__ for _, f in CORRUPTED])
def test_a_corrupted_reflection_claim_is_not_proved_and_fails_at_a_fixed_size(cid, func):
    assert run_free(CATALOG.get(cid), func).verdict == "undecided"
    assert run_exact(CATALOG.get(cid), 2, 1, 0, func=func).verdict == "fails"


def test_what_holds_for_the_first_reflection_only_is_not_proved():
    c = CATALOG.get("dual-lax-reflections")
    assert run_free(c, trace_of_the_first_reflection).verdict == "undecided"
    assert run_exact(c, 3, 2, 0, func=trace_of_the_first_reflection).verdict == "proved"


def test_the_checker_rejects_a_forged_reflection_hypothesis():
    data, changed = forged(_proved(run_free(CATALOG.get("dual-lax-reflections"))).certificate_data,
                           {"SrefA": "SrefSref"})
    assert changed
    assert not check_certificate(data).accepted
