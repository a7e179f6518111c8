"""The relation ρ of a metric flow's multiplier is the derivative of XᵀA⁻¹P + PᵀA⁻¹X along the flow reduced by
the rules (XᵀA⁻¹AX → I_r, ...): its certificate carries the difference of the two, in the ideal of the
constraints (``derived``), which the independent checker re-checks; without it, or with it corrupted, the
relation is rejected."""
from __future__ import annotations

import copy
import json

import pytest

from stiefelsym import admissible
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import Claim
from stiefelsym.run.runner import run_one


def H_neumann(t):
    """½ tr(PᵀA⁻¹P) + tr(XᵀAX): its gradient in X makes the derivative of the constraint reduce."""
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X)


def energy(s):
    return {"dH/dt": s.d(H_neumann, s.dirac_flow(H_neumann))}


def relation(s):
    L = s.multiplier_flow(H_neumann).multipliers["Lambda"]
    M = s.X.T @ s.Ainv @ s.X
    return {"rho": L @ M + M @ L + 2 * (s.P.T @ s.Ainv @ s.Ainv @ s.P) - 4 * s.Ir}


def _claim(func):
    return Claim(id="metric-derived-trial", paper=("A_XP",), kind="id", section="3", func=func,
                 sizes=admissible(3), realization="metric")


@pytest.fixture(scope="module", params=[energy, relation], ids=["energy", "relation"])
def proved(request):
    res = run_one(_claim(request.param), None, "free", 0)
    assert res.verdict == "proved", res.message
    return json.loads(json.dumps(res.certificate_data))


def _decl(data):
    return next((k, v) for k, v in data["letters"].items() if v.get("kind") == "sylvester")


def _rejected(data, why):
    rep = check_certificate(data)
    assert not rep.accepted and why in rep.message, rep.message


def test_a_reduced_relation_is_accepted_with_its_link_to_the_derivative(proved):
    name, decl = _decl(proved)
    assert decl["derived"]["terms"] and {"coef": "-4", "traces": [], "word": []} in decl["relation"]
    assert check_certificate(copy.deepcopy(proved)).accepted


def test_without_the_link_the_reduced_relation_is_rejected(proved):
    data = copy.deepcopy(proved)
    del _decl(data)[1]["derived"]
    _rejected(data, "is not d/dt")


def test_a_forged_relation_and_its_link_edited_to_match_are_rejected(proved):
    data = copy.deepcopy(proved)
    name, decl = _decl(data)
    for t in decl["relation"]:
        if t["word"] == []:
            t["coef"] = "-3"                         # -3 I_r instead of -4 I_r
    _rejected(copy.deepcopy(data), "is not d/dt")
    decl["derived"]["residual"].append({"coef": "-1", "traces": [], "word": []})   # derived - rho, edited to match
    _rejected(data, "as d/dt (X^T A^-1 P + P^T A^-1 X) along its flow:")


def test_a_link_that_uses_a_relation_or_does_not_expand_is_rejected(proved):
    data = copy.deepcopy(proved)
    name, decl = _decl(data)
    decl["derived"]["terms"][0]["hyp"] = f"rho:{name}"
    _rejected(data, "is not d/dt")
    data = copy.deepcopy(proved)
    decl = _decl(data)[1]
    decl["derived"]["terms"][0]["coef"] = "7"
    _rejected(data, "as d/dt (X^T A^-1 P + P^T A^-1 X) along its flow:")
