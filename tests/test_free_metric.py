"""The metric realization in the free algebra: (cond_XP2) as rules, the Dirac flow of H_A = ½tr(PᵀA⁻¹P)
with Π = 0 by the uniqueness of a Sylvester solution and Λ a letter whose relation ρ joins the ideal,
the certificate of ``metric-flow`` (A_XP) and its re-check (ρ recomputed from the flow), and negative
controls: wrong flows and wrong Λ equations are not proved, forged certificates are rejected."""
from __future__ import annotations

import copy
import json

import pytest

from proofs.sec3_geodesic_flows import H_metric_A
from stiefelsym import admissible
from stiefelsym.certificate_check import check_certificate
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.free import FreeScene
from stiefelsym.free.algebra import NCPoly, NeedsCoordinates
from stiefelsym.free.mat import entry_of
from stiefelsym.free.metric import METRIC_HYP, metric_system
from stiefelsym.free.rewriting import critical_pairs, is_confluent
from stiefelsym.free.scene import AINV, P, Pt, X, Xt
from stiefelsym.run.runner import run_one


def _w(*letters):
    return NCPoly.word(letters)


def _metric_claim(func, cid="metric-trial"):
    return Claim(id=cid, paper=("A_XP",), kind="id", section="3", func=func, sizes=admissible(3),
                 realization="metric")


def _free(func):
    return run_one(_metric_claim(func), None, "free", 0)


@pytest.fixture(scope="module")
def metric_flow_result():
    claim = next(c for c in load_catalog() if c.id == "metric-flow")
    return run_one(claim, None, "free", 0)


def _certificate(result) -> dict:
    return json.loads(json.dumps(result.certificate_data))   # what results.json holds


# -- the rewriting system -----------------------------------------------------------------------------------
def test_the_rules_of_cond_XP2_decrease_and_every_critical_pair_resolves():
    system = metric_system()
    assert sorted(r.name for r in system.rules) == ["AAinv", "AinvA", "PtAinvX", "XtX"]
    for rule in system.rules:
        assert system.decreasing(rule), rule
        assert rule.cofactors
    pairs = critical_pairs(system)
    assert pairs and not [str(p) for p in pairs if not p.joinable]
    assert is_confluent(system)


def test_with_resolvents_every_critical_pair_of_the_metric_system_still_resolves():
    s = FreeScene(realization="metric", lazy=True)
    s.resolvent(s.lam)
    s.resolvent(0)          # R_0 -> -A^{-1}
    pairs = critical_pairs(s.system)
    assert len(pairs) > 4 and not [str(p) for p in pairs if not p.joinable]
    assert {"XtX", "PtAinvX", "AAinv", "AinvA"} <= {r.name for r in s.system.rules}


def test_the_metric_constraint_reduces_to_0_and_the_standard_one_does_not():
    system = metric_system()
    assert system.is_zero(_w(Xt, AINV, P) + _w(Pt, AINV, X))
    assert not system.is_zero(_w(Xt, P) + _w(Pt, X))
    assert system.is_zero(_w(Xt, X) - NCPoly.identity("r"))


# -- the flow ------------------------------------------------------------------------------------------------
def test_the_dirac_flow_of_H_A_has_Pi_0_and_Lambda_a_letter_with_its_sylvester_relation():
    s = FreeScene(realization="metric", lazy=True)
    flow = s.dirac_flow(H_metric_A)
    (L, m), = s._sylvester.items()
    assert entry_of(flow.Xdot) == _w(AINV, P)
    assert entry_of(flow.Pdot) == _w(X, L)
    # rho = Lambda M + M Lambda + 2 P^T A^-2 P, M = X^T A^-1 X
    assert m.relation == _w(L, Xt, AINV, X) + _w(Xt, AINV, X, L) + _w(Pt, AINV, AINV, P) * 2
    assert m.keeps_certificate.hypotheses() == [METRIC_HYP]
    assert s.dirac_flow(lambda t: t.tr(t.P.T @ t.Ainv @ t.P) * t.q(1, 3)) is not flow
    assert len(s._sylvester) == 2   # every flow its own multiplier


def test_a_hamiltonian_whose_Pi_equation_is_not_homogeneous_is_refused():
    s = FreeScene(realization="metric", lazy=True)
    with pytest.raises(NeedsCoordinates, match="Pi M \\+ M Pi = S"):
        s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2)   # H_P = P: P^T X + X^T P is not 0 on (cond_XP2)


def test_the_multiplier_is_not_differentiated_as_a_constant():
    s = FreeScene(realization="metric", lazy=True)
    flow = s.dirac_flow(H_metric_A)
    Lam = s.X.T @ flow.Pdot + 0 * (s.P.T @ s.X)   # (the scene's letters X, P read)
    with pytest.raises(NeedsCoordinates, match="moves with the point"):
        s.d(s.tr(Lam), flow)
    with pytest.raises(NeedsCoordinates, match="moves with the point"):
        s.gradient(lambda t: t.tr(Lam @ t.X.T @ t.X))


def test_values_along_the_metric_flow_keep_cond_XP2():
    s = FreeScene(realization="metric", lazy=True)
    flow = s.dirac_flow(H_metric_A)
    cond = s.d(lambda t: t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X, flow)
    assert s.reduce(entry_of(cond)).is_zero          # through rho
    assert s.reduce(s.d(H_metric_A, flow)).is_zero   # (a trace form: tr(P^T A^-1 X Lambda), skew times symmetric)


# -- the proof of (A_XP) -------------------------------------------------------------------------------------
def test_metric_flow_is_proved_for_every_n_r_with_an_accepted_certificate(metric_flow_result):
    r = metric_flow_result
    assert r.verdict == "proved", r.message
    data = _certificate(r)
    rep = check_certificate(data)
    assert rep.accepted, rep.message
    assert data["realization"] == "metric"
    (name, decl), = data["letters"].items()
    assert name.startswith("Lambda:") and decl["kind"] == "sylvester"
    used = set(data["summary"]["hypotheses"])
    assert {f"rho:{name}", "XtX", METRIC_HYP} <= used     # (the metric constraint: in the flow keeping X^T X)
    assert not used & {"XtP+PtX"}
    assumes = " ".join(data["summary"]["assumes"])
    assert "positive definite" in assumes and "Pi = 0 by uniqueness" in assumes and f"solution of rho:{name}" in assumes
    assert "Pi = 0 by uniqueness" in r.certificate and "Pi = 0 by uniqueness" in rep.message
    text = " ".join(r.reductions)
    assert "positive definite" in text and "Pi = 0 by uniqueness" in text and "rho" in text


def _flow_claim(xdot=None, pdot=None, coef=2):
    def func(s):
        flow = s.dirac_flow(H_metric_A)
        Lam = s.X.T @ flow.Pdot
        M = s.X.T @ s.Ainv @ s.X
        return {
            "dX/dt": flow.Xdot - (xdot(s) if xdot else s.Ainv @ s.P),
            "dP/dt": flow.Pdot - (pdot(s, Lam) if pdot else s.X @ Lam),
            "Lambda equation": Lam @ M + M @ Lam + coef * (s.P.T @ s.Ainv @ s.Ainv @ s.P),
        }
    return func


def test_the_correct_flow_written_as_a_claim_is_proved():
    assert _free(_flow_claim()).verdict == "proved"


@pytest.mark.parametrize("corruption", [
    dict(pdot=lambda s, Lam: -(s.X @ Lam)),
    dict(xdot=lambda s: s.Ainv @ s.P + s.X),
    dict(xdot=lambda s: s.P),
    dict(coef=3),
    dict(coef=-2),
], ids=["Pdot=-X Lambda", "Xdot=A^-1 P + X", "Xdot=P", "Lambda equation 3", "Lambda equation -2"])
def test_a_corrupted_flow_or_Lambda_equation_is_not_proved(corruption):
    r = _free(_flow_claim(**corruption))
    assert r.verdict == "undecided", r.verdict
    assert "nonzero normal form" in r.message


def test_a_trick_that_swallows_the_refusal_of_a_multiplier_is_not_proved():
    def func(s):
        try:
            s.dirac_flow(lambda t: t.tr(t.P.T @ t.P) / 2)
        except Exception:   # noqa: BLE001 - the trick
            return {"r": s.X - s.X}
        return {"r": s.X}
    assert _free(func).verdict == "undecided"


# -- forged certificates -------------------------------------------------------------------------------------
def _rejected(data, *words) -> str:
    rep = check_certificate(data)
    assert not rep.accepted
    for w in words:
        assert w in rep.message, rep.message
    return rep.message


def _decl(data):
    (name, decl), = data["letters"].items()
    return name, decl


def test_a_forged_relation_is_rejected(metric_flow_result):
    data = _certificate(metric_flow_result)
    name, decl = _decl(data)
    for t in decl["relation"]:
        if name not in t["word"]:
            t["coef"] = "3"          # 3 P^T A^-2 P instead of 2: not what the flow's preservation gives
    _rejected(data, "is not d/dt")


def test_an_empty_relation_or_an_empty_residual_of_the_flow_is_rejected(metric_flow_result):
    data = _certificate(metric_flow_result)
    _decl(data)[1]["relation"] = []
    _rejected(data, "is not d/dt")
    data = _certificate(metric_flow_result)
    keeps = _decl(data)[1]["keeps"]["XtX"]
    keeps["residual"], keeps["terms"] = [], []
    _rejected(data, "not the derivative along its flow")


def test_a_forged_flow_is_rejected(metric_flow_result):
    data = _certificate(metric_flow_result)
    name, decl = _decl(data)
    decl["flow"]["P"][0]["coef"] = "-1"         # P' = -X Lambda
    _rejected(data, "is not X Lambda")
    data = _certificate(metric_flow_result)
    name, decl = _decl(data)
    decl["flow"]["P"].append({"coef": "1", "traces": [], "word": ["X"]})   # P' = X Lambda + X
    _rejected(data, "is not d/dt")
    data = _certificate(metric_flow_result)
    name, decl = _decl(data)
    decl["flow"]["X"].append({"coef": "1", "traces": [], "word": ["X", name]})
    _rejected(data, "holds a multiplier")


def test_hypotheses_of_the_other_realization_are_rejected(metric_flow_result):
    data = _certificate(metric_flow_result)
    entry = next(e for e in data["entries"] if e["terms"])
    entry["terms"][0]["hyp"] = "XtP+PtX"
    _rejected(data, "not one of the metric realization")
    data = _certificate(metric_flow_result)
    data["realization"] = "standard"     # rho and the multiplier's letter belong to the metric realization
    _rejected(data, "standard realization")
    data = _certificate(metric_flow_result)
    data["letters"] = {}
    _rejected(data)


def test_a_standard_certificate_may_not_use_the_metric_constraint():
    from stiefelsym.free.certificates import CertificateWriter
    s = FreeScene()
    writer = CertificateWriter(s._resolvents)
    writer.add("[1,1]", s.system.certify(_w(Xt, X) - NCPoly.identity("r")))
    data = json.loads(json.dumps(writer.data()))
    assert check_certificate(copy.deepcopy(data)).accepted
    data["entries"][0]["terms"][0]["hyp"] = METRIC_HYP
    _rejected(data, "not one of the standard realization")


@pytest.mark.parametrize("touch", [
    lambda s: s.Y,
    lambda s: s.at_point(s.X, s.P),
    lambda s: s.pairs_dirac_flow(lambda t, z: t.tr(z["P"].T @ z["P"]), {"X": s.X, "P": s.P}, [("X", "P")]),
    lambda s: s.d(lambda t: t.dirac_flow(H_metric_A).Xdot, s.dirac_flow(H_metric_A)),
], ids=["a second point", "another point", "a flow on pairs", "a flow along a tangent"])
def test_what_the_free_scene_offers_for_cond_XP_only_is_refused_in_the_metric_realization(touch):
    s = FreeScene(realization="metric", lazy=True)
    with pytest.raises((NeedsCoordinates, TypeError)):
        touch(s)


def test_a_flow_inside_a_function_of_the_metric_scene_is_refused():
    s = FreeScene(realization="metric", lazy=True)
    with pytest.raises(NeedsCoordinates, match="inside a function"):
        s.gradient(lambda t: t.tr(t.X.T @ t.dirac_flow(H_metric_A).Pdot))
