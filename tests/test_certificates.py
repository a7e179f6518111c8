"""Cofactor certificates of dimension-free proofs and their independent checker.

Every proof of the ``free`` method writes each residual entry as a combination
Σ c·T·a·h·b (and c·T·tr(a·h·b)·w) of the hypotheses; the checker re-expands it
without rewriting.  Accepted: every catalog proof, LA1, LA3/LA4, random
reductions through every rule.  Rejected: hand-made wrong certificates and
corrupted residuals.
"""
from __future__ import annotations

import ast
import copy
import json
import random
import sys
from fractions import Fraction
from pathlib import Path

import pytest
import symengine as se

from stiefelsym.certificate_check import FORMAT, check_certificate
from stiefelsym import admissible
from stiefelsym.claims import Claim, load_catalog
from stiefelsym.free.algebra import NCPoly, trace
from stiefelsym.free.certificates import CertificateWriter
from stiefelsym.free.rewriting import CertificateError, Hypothesis, Order, RewritingSystem
from stiefelsym.free.scene import AINV, A, FreeScene, P, Pt, X, Xt
from stiefelsym.run.runner import run_one

sys.path.insert(0, str(Path(__file__).parent))
from test_free_rewriting import random_poly  # noqa: E402
from test_free_scene import KAPPAS, la1_residual, la3_residual  # noqa: E402

lam, mu = se.Symbol("lambda"), se.Symbol("mu")


def certificate_of(scene: FreeScene, entries) -> dict:
    """Certify (position, polynomial) pairs of a scene; the JSON form, through a round trip."""
    writer = CertificateWriter(scene._resolvents)
    for pos, p in entries:
        writer.add(pos, scene.system.certify(p))
    return json.loads(json.dumps(writer.data()))


def matrix_entries(M):
    return [(f"[{i + 1},{j + 1}]", M._a[i, j]) for i in range(M._a.shape[0]) for j in range(M._a.shape[1])]


def accepted(data) -> bool:
    return check_certificate(data).accepted


def rejected_because(data, *words: str) -> str:
    rep = check_certificate(data)
    assert not rep.accepted
    for w in words:
        assert w in rep.message, rep.message
    return rep.message


# ---------------------------------------------------------------------------
@pytest.fixture(scope="module")
def catalog_free_results():
    return [(c, run_one(c, None, "free", 0)) for c in load_catalog()]


def test_every_free_proof_of_the_catalog_carries_an_accepted_certificate(catalog_free_results):
    proved = [(c, r) for c, r in catalog_free_results if r.verdict == "proved"]
    assert len(proved) >= 10
    assert not [c.id for c, r in catalog_free_results if r.verdict == "error"]
    for c, r in proved:
        data = json.loads(json.dumps(r.certificate_data))   # what results.json holds
        rep = check_certificate(data)
        assert rep.accepted, (c.id, rep.message)
        assert rep.terms == data["summary"]["terms"]
        assert "re-checked by the independent checker" in r.certificate
    assert any(r.certificate_data["summary"]["terms"] for _, r in proved)
    for c, r in catalog_free_results:
        if r.verdict != "proved":
            assert r.certificate_data is None, c.id


def test_certificates_survive_the_results_file(catalog_free_results):
    from stiefelsym.results import Result, dump_results

    proved = [r for _, r in catalog_free_results if r.verdict == "proved"]
    payload = json.loads(dump_results(proved, {}))
    again = [Result.from_json(d) for d in payload["results"]]
    assert all(accepted(r.certificate_data) for r in again)


@pytest.mark.parametrize("kappa", KAPPAS.values(), ids=KAPPAS.keys())
def test_neumann_LA1_gets_an_accepted_certificate(kappa):
    s = FreeScene(lazy=True)
    data = certificate_of(s, matrix_entries(la1_residual(s, kappa)))
    assert data["summary"]["terms"] > 0
    assert "XtX" in data["summary"]["hypotheses"]
    assert accepted(data)


@pytest.mark.parametrize("kappa", [0, Fraction(-1, 2)], ids=["normal", "euclidean"])
def test_dual_lax_pair_LA3_LA4_gets_an_accepted_certificate_through_the_resolvent(kappa):
    s = FreeScene(lazy=True)
    data = certificate_of(s, matrix_entries(la3_residual(s, kappa)))
    assert any(h.startswith("res_") for h in data["summary"]["hypotheses"])
    assert data["letters"]["R[lambda]"] == {"kind": "resolvent", "parameter": "lambda_"}
    assert accepted(data)


def test_a_negative_control_has_no_certificate_of_zero():
    """LA1 with the commutator swapped: the certificate covers p − nf(p), not p."""
    s = FreeScene(lazy=True)
    entries = matrix_entries(la1_residual(s, None, swap=True))
    assert not all(s.system.certify(p).proves_zero for _, p in entries)
    rejected_because(certificate_of(s, entries), "does not expand to the residual")


def _every_rule_scene() -> FreeScene:
    s = FreeScene(lazy=True)
    s.resolvent(lam)
    s.resolvent(mu)
    s.resolvent(lam + 1)
    s.Ainv
    s.resolvent(0)   # R_0 -> -A^{-1}
    s.Y
    return s


@pytest.mark.parametrize("seed", range(4))
def test_random_reductions_through_every_rule_are_certified(seed):
    """p − nf(p) for random p (words and traces, resolvents, A^{-1}, a second point)."""
    rng = random.Random(seed)
    s = _every_rule_scene()
    letters = [X, Xt, P, Pt, A, AINV] + list(s._resolvents)
    entries = []
    for row, col in [("n", "r"), ("r", "r"), ("n", "n"), ("r", "n")]:
        p = random_poly(rng, letters, row, col)
        entries.append((f"{row}{col}", p - s.system.normal_form(p)))
    q, p2 = random_poly(rng, letters, "n", "r", 3, 5), random_poly(rng, letters, "r", "n", 3, 5)
    t = trace(q * p2) * trace(p2.star() * q.star()) + trace(q * p2) * NCPoly.scalar(lam)
    entries.append(("trace", t - s.system.normal_form(t)))
    y = s.Y._a[0, 0]
    t2 = trace(y.star() * q) * (y.star() * y)
    entries.append(("second point", t2 - s.system.normal_form(t2)))
    data = certificate_of(s, entries)
    rep = check_certificate(data)
    assert rep.accepted, rep.message
    used = set(data["summary"]["hypotheses"])
    assert {"XtP+PtX", "YtY", "AAinv", "AinvA"} <= used and any(h.startswith("res_") for h in used)


def test_a_reduction_by_a_rule_without_cofactors_is_not_certified():
    system = RewritingSystem(Order([X, Xt]))
    system.add_rule((Xt, X), NCPoly.identity("r"), "toy rule without cofactors")
    with pytest.raises(CertificateError, match="no cofactor expansion"):
        system.certify(NCPoly.word((Xt, X)))


def test_rules_whose_cofactors_do_not_sum_to_lhs_minus_rhs_are_refused():
    from stiefelsym.free.rewriting import Cofactor, RewritingError

    h = Hypothesis("XtX", NCPoly.word((Xt, X)) - NCPoly.identity("r"))
    system = RewritingSystem(Order([X, Xt]))
    with pytest.raises(RewritingError, match="cofactors do not sum"):
        system.add_rule((Xt, X), NCPoly.identity("r"), "wrong sign", cofactors=[Cofactor(se.Integer(-1), (), h, ())])


def test_traces_that_vanish_by_transposition_are_certified_with_one_half():
    """tr(XᵀP) = −tr(XᵀP) on T*V: the certificate is ½ tr(XᵀP + PᵀX)."""
    s = FreeScene(lazy=True)
    t = s.tr(s.X.T @ s.P)
    c = s.system.certify(t)
    assert c.proves_zero and [str(x.coef) for x in c.terms] == ["1/2"] and c.terms[0].in_trace
    assert accepted(certificate_of(s, [("tr", t)]))


# ---------------------------------------------------------------------------
# hand-made certificates: the checker's view only
def entry(row, col, residual, terms, position="e"):
    return {"position": position, "type": [row, col], "hypotheses": [],
            "residual": [{"coef": c, "traces": tr, "word": w} for c, tr, w in residual],
            "terms": [dict({"traces": [], "word": [], "in_trace": False, "left": [], "right": []}, **t)
                      for t in terms]}


def cert(*entries, letters=None) -> dict:
    return {"format": FORMAT, "symbols": {}, "letters": letters or {}, "entries": list(entries)}


def xtp_skew():
    """tr(XᵀP) = ½ tr(XᵀP + PᵀX) = 0 on T*V."""
    return cert(entry("1", "1", [("1", [["Xt", "P"]], [])],
                      [{"coef": "1/2", "hyp": "XtP+PtX", "in_trace": True}]))


W1 = ["Xt", "A", "X", "Pt", "A", "P"]   # a closed path at R^r
W2 = ["Xt", "A", "P", "Pt", "A", "X"]   # the same letters, another cyclic word


def cyclic_example(left, right, transposed=False):
    """tr(W1·XᵀX) − tr(W1) = tr(W1·(XᵀX − I)), certified by one trace term."""
    term = {"coef": "1", "hyp": "XtX", "left": left, "right": right, "in_trace": True}
    if transposed:
        term["transposed"] = True
    return cert(entry("1", "1", [("1", [W1 + ["Xt", "X"]], []), ("-1", [W1], [])], [term]))


def test_hand_made_certificates_are_accepted():
    assert accepted(xtp_skew())
    assert accepted(cyclic_example(W1, []))
    assert accepted(cyclic_example([], W1))                                  # rotated
    star_w1 = ["Pt", "A", "P", "Xt", "A", "X"]                              # W1ᵀ
    assert accepted(cyclic_example([], star_w1))                             # transposed: tr(w) = tr(wᵀ)
    assert accepted(cyclic_example([], star_w1, transposed=True))


def test_a_trace_term_that_is_not_cyclically_equal_is_rejected():
    rejected_because(cyclic_example(W2, []), "does not expand to the residual")


def resolvent_example(hyp, transposed=False, coef="1", parameter="lambda_"):
    """R(λI − A) − I written out, certified by one hypothesis."""
    R = "R[lambda]"
    term = {"coef": coef, "hyp": f"{hyp}:{R}", "transposed": transposed}
    return cert(entry("n", "n", [("lambda_", [], [R]), ("-1", [], [R, "A"]), ("-1", [], [])], [term]),
                letters={R: {"kind": "resolvent", "parameter": parameter}})


def test_transposed_hypotheses_and_resolvents():
    assert accepted(resolvent_example("res_right"))
    assert accepted(resolvent_example("res_left", transposed=True))
    rejected_because(resolvent_example("res_left"), "does not expand")           # a hypothesis swapped
    rejected_because(resolvent_example("res_right", parameter="mu"), "does not expand")


@pytest.fixture(scope="module")
def la1_certificate():
    s = FreeScene(lazy=True)
    data = certificate_of(s, matrix_entries(la1_residual(s, None)))
    assert accepted(data)
    return data


def test_a_dropped_term_is_rejected(la1_certificate):
    data = copy.deepcopy(la1_certificate)
    data["entries"][0]["terms"].pop()
    rejected_because(data, "does not expand to the residual")


def test_a_wrong_coefficient_is_rejected(la1_certificate):
    data = copy.deepcopy(la1_certificate)
    t = data["entries"][0]["terms"][0]
    t["coef"] = f"({t['coef']})*(1 + kappa)"
    rejected_because(data, "does not expand to the residual")


def test_a_hypothesis_swapped_for_another_is_rejected(la1_certificate):
    data = copy.deepcopy(la1_certificate)
    t = next(t for t in data["entries"][0]["terms"] if t["hyp"] == "XtX")
    t["hyp"] = "XtP+PtX"
    rejected_because(data)
    t["hyp"] = "no such hypothesis"
    rejected_because(data, "unknown hypothesis")


def test_an_ill_typed_path_is_rejected(la1_certificate):
    data = copy.deepcopy(la1_certificate)
    data["entries"][0]["terms"][0]["left"] = ["X", "X"]
    rejected_because(data, "term 1", "ill-typed word X*X")
    data = copy.deepcopy(la1_certificate)      # a path, but from the wrong object
    data["entries"][0]["terms"][0]["left"] = ["Xt"]
    rejected_because(data, "term 1", "left cofactor")


def test_a_corrupted_residual_is_rejected_with_the_original_certificate(la1_certificate):
    data = copy.deepcopy(la1_certificate)
    res = data["entries"][0]["residual"]
    res[0]["coef"] = f"2*({res[0]['coef']})"
    rejected_because(data, "does not expand to the residual")
    data = copy.deepcopy(la1_certificate)
    data["entries"][0]["residual"].pop()
    rejected_because(data, "does not expand to the residual")
    data = copy.deepcopy(la1_certificate)       # the same residual claimed for other sizes of blocks
    data["entries"][0]["type"] = ["r", "r"]
    rejected_because(data)


def test_the_quiver_is_the_checkers_own():
    data = xtp_skew()
    data["letters"] = {"X": {"kind": "generic", "row": "n", "col": "n", "transpose": "Xt"}}
    rejected_because(data, "redeclares")
    g = {"gen:G": {"kind": "generic", "row": "n", "col": "r", "transpose": "gen:G^T"}}
    ok = cert(entry("r", "r", [("1", [], ["gen:G^T", "gen:G"]), ("-1", [], ["gen:G^T", "gen:G"])], []),
              letters=g)
    assert accepted(ok)
    bad = copy.deepcopy(ok)
    bad["entries"][0]["residual"][0]["word"] = ["gen:G", "gen:G"]
    rejected_because(bad, "ill-typed")
    data = cert(entry("1", "1", [("1", [["Xt", "A"]], [])], []))           # tr of a path that does not close
    rejected_because(data, "closed path")
    data = cert(entry("n", "n", [], [{"coef": "1", "hyp": "XtX"}]))          # an r×r hypothesis in an n×n entry
    rejected_because(data, "left cofactor")
    rejected_because({"format": "something else"}, "format")
    rejected_because(cert(entry("n", "n", [("1", [], ["A"]), ("-1", [], ["no-letter"])], [])), "unknown letter")


def test_skew_letters_have_vanishing_traces_and_dimensions_come_from_the_identity():
    data = cert(entry("1", "1", [("1", [["xi"]], [])], []))                  # tr ξ = 0 (ξᵀ = −ξ)
    assert accepted(data)
    # tr(XᵀX − I_r) = tr(X Xᵀ) − r: the empty word in a trace is the dimension
    data = cert(entry("1", "1", [("1", [["X", "Xt"]], []), ("-r", [], [])],
                      [{"coef": "1", "hyp": "XtX", "in_trace": True}]))
    assert accepted(data)
    data["entries"][0]["residual"][1]["coef"] = "-n"
    rejected_because(data, "does not expand")


# ---------------------------------------------------------------------------
def test_the_free_method_refuses_a_proof_whose_certificate_is_rejected(monkeypatch):
    import stiefelsym.methods.dimension_free as fm

    claim = load_catalog().get("neumann-lax")
    assert run_one(claim, None, "free", 0).verdict == "proved"
    real = fm.certify_entries

    def drop_a_term(scene, entries):
        data = real(scene, entries)
        next(e for e in data["entries"] if e["terms"])["terms"].pop()
        return data
    monkeypatch.setattr(fm, "certify_entries", drop_a_term)
    res = run_one(claim, None, "free", 0)
    assert res.verdict == "error" and "certificate rejected" in res.message


def test_the_checker_does_not_import_the_rewriting_system():
    path = Path(__file__).parent.parent / "stiefelsym" / "certificate_check.py"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    imported = {a.name.split(".")[0] for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    imported |= {n.module.split(".")[0] for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.module}
    assert not any(isinstance(n, ast.ImportFrom) and n.level for n in ast.walk(tree))   # no relative imports
    assert imported <= {"__future__", "time", "dataclasses", "typing", "symengine", "sympy", "json", "sys", "math",
                        "hashlib"}   # hashlib: the key of a certificate a results file holds once
    # small enough to read in one sitting (with the table of the double and complex points, and the
    # re-derivation of the Sylvester relations of the metric realization's multipliers: about 110 lines, and
    # the certificates of cases of a claim stated at a union of one-r families: about 25 lines; what a certificate
    # proves and which record it belongs to: about 45 lines; the joint scope of hypotheses of one r: about 15 lines;
    # the bound on a coefficient's expansion before it is expanded: about 20 lines; no denominator that may vanish
    # at a size: about 20 lines; the memos of the denominators and of that test: about 20 lines; the note on a
    # certificate that uses no hypothesis: about 10 lines; a certificate a results file holds once: about 10 lines;
    # REJECTED, not a traceback, for a file that is not a results file, and a line for a file with no certificate:
    # about 8 lines)
    assert len(path.read_text(encoding="utf-8").splitlines()) < 775


ZERO = "((kappa + 1)**2 - kappa**2 - 2*kappa - 1)"   # the zero polynomial, not written as 0


@pytest.mark.parametrize("coef", ["oo", "zoo", "nan", "1/0", "sin(kappa)", "2**(1/2)", "kappa**(1/2)",
                                  f"1/{ZERO}", f"{ZERO}/{ZERO}"])
def test_coefficients_are_rational_functions_with_a_nonzero_denominator(coef):
    data = xtp_skew()
    data["entries"][0]["terms"][0]["coef"] = f"1/2 + {coef}"
    rejected_because(data, "coefficient")


def test_a_coefficient_the_checker_has_parsed_before_is_checked_the_same_way(la1_certificate):
    """The checker parses each coefficient text once: a text it accepted stays a term of its own
    certificate (a wrong one is still rejected), a text it rejected is rejected again."""
    assert accepted(la1_certificate) and accepted(copy.deepcopy(la1_certificate))
    data = copy.deepcopy(la1_certificate)
    data["entries"][0]["terms"][0]["coef"] = data["entries"][0]["terms"][1]["coef"] + " + 1"
    for _ in range(2):
        rejected_because(data, "does not expand to the residual")
        bad = xtp_skew()
        bad["entries"][0]["terms"][0]["coef"] = f"1/{ZERO}"
        rejected_because(bad, "zero denominator")


def test_the_checker_runs_on_a_results_file(tmp_path, catalog_free_results, capsys):
    from stiefelsym.certificate_check import main
    from stiefelsym.results import dump_results

    proved = [r for _, r in catalog_free_results if r.verdict == "proved"]
    path = tmp_path / "results.json"
    path.write_text(dump_results(proved, {}), encoding="utf-8")
    assert main([str(path)]) == 0
    assert capsys.readouterr().out.count("accepted") == len(proved)
    payload = json.loads(path.read_text(encoding="utf-8"))
    victim = next(r for r in payload["results"] if r["certificate_data"]["summary"]["terms"])
    next(e for e in victim["certificate_data"]["entries"] if e["terms"])["terms"].pop()
    path.write_text(json.dumps(payload), encoding="utf-8")
    assert main([str(path)]) == 1
    assert "REJECTED" in capsys.readouterr().out


def test_coefficients_parse_in_sympy_with_one_name_per_symbol(catalog_free_results):
    """Another system can read the certificates: sympy parses every coefficient."""
    import sympy

    s = FreeScene(lazy=True)
    datas = [certificate_of(s, matrix_entries(la3_residual(s, 0)))]
    datas += [d for _, r in catalog_free_results if r.verdict == "proved"    # (a certificate of cases: each case)
              for d in ([c["certificate"] for c in r.certificate_data["cases"]] if "cases" in r.certificate_data
                        else [r.certificate_data])]
    for data in datas:
        for e in data["entries"]:
            for t in e["residual"] + e["terms"]:
                names = {str(x) for x in sympy.sympify(t["coef"]).free_symbols}
                assert names <= set(data["symbols"]), (names, data["symbols"])
    assert "lambda_" in datas[0]["symbols"]


def test_a_claims_own_scalar_that_prints_like_a_chart_symbol_gets_its_own_name():
    s = FreeScene(lazy=True)
    own = se.Dummy("lambda")
    x = (s.X.T @ s.X)._a[0, 0] * own - NCPoly.identity("r") * s.lam
    writer = CertificateWriter(s._resolvents)
    coefs = {writer.coef(c) for c in x.terms.values()}
    # symengine >= 0.15 prints the dummy as "lambda" (then it becomes lambda__2), older ones as "_lambda"
    names = {c.lstrip("-") for c in coefs}
    assert len(names) == 2 and "lambda_" in names, coefs
    assert names - {"lambda_"} <= {"lambda__2", "s_lambda"}, coefs


# ---------------------------------------------------------------------------
# A^{-1} and the resolvent at 0 (0·I − A)^{-1} = −A^{-1}: true identities that need the rule
# R_0 -> -A^{-1} (completion of the pairs A^{-1}·A·R_0, R_0·A·A^{-1}, A^{-1}·R_lambda·R_0, ...)
def _claim(func, cid):
    return Claim(id=cid, paper=("cond_XP",), kind="id", section="t", func=func, sizes=admissible(4))


def ainv_plus_resolvent_at_0(s):
    """True: A^{-1} + (0·I − A)^{-1} = 0."""
    return {"Ainv + R_0": s.Ainv + s.resolvent(0)}


def resolvent_at_0_then_ainv(s):
    """True: (0·I − A)^{-1} A^{-1} = −A^{-2}, the resolvent at 0 built before A^{-1}."""
    R0 = s.resolvent(0)
    Ai = s.Ainv
    return {"R_0 Ainv + Ainv Ainv": R0 @ Ai + Ai @ Ai}


def ainv_resolvent_two_ways(s):
    """True: λ Xᵀ A^{-1} R_λ X = Xᵀ (R_λ − R_0) X (the resolvent identity at 0 and λ)."""
    X, R = s.X, s.resolvent(s.lam)
    return {"XtAinvRX": s.lam * (X.T @ s.Ainv @ R @ X) - X.T @ (R - s.resolvent(0)) @ X}


def ainv_minus_resolvent_at_0(s):
    """False: A^{-1} = (0·I − A)^{-1}."""
    return {"Ainv - R_0": s.Ainv - s.resolvent(0)}


@pytest.mark.parametrize("func", [ainv_plus_resolvent_at_0, resolvent_at_0_then_ainv, ainv_resolvent_two_ways])
def test_identities_through_the_resolvent_at_0_are_proved_with_an_accepted_certificate(func):
    res = run_one(_claim(func, func.__name__), None, "free", 0)
    assert res.verdict == "proved", (res.verdict, res.message)
    data = json.loads(json.dumps(res.certificate_data))
    rep = check_certificate(data)
    assert rep.accepted, rep.message
    assert "res_left:R[0]" in data["summary"]["hypotheses"]
    assert data["letters"]["R[0]"] == {"kind": "resolvent", "parameter": "0"}


def test_a_false_identity_with_the_resolvent_at_0_is_not_proved():
    res = run_one(_claim(ainv_minus_resolvent_at_0, "ainv_minus_R0"), None, "free", 0)
    assert res.verdict not in ("proved", "checked", "numeric"), res.verdict
    assert res.certificate_data is None


@pytest.mark.parametrize("den, vanishes", [("n - r", True), ("n - r + 1", False), ("2*n - r", False),
                                            ("kappa", False), ("(n - 2)*kappa", True), ("(n - 2)*kappa + 1", False), ("n + r", False)])
def test_a_remembered_denominator_is_judged_as_the_first_time(den, vanishes):
    """The checker remembers denominators by their coefficient's text and whether each may vanish at a size (pure
    functions): asked again, in either order, it answers as it did the first time."""
    from stiefelsym.certificate_check import denominator, may_vanish_at_a_size
    for _ in range(2):
        assert may_vanish_at_a_size(denominator(f"1/({den})")) is vanishes
        assert may_vanish_at_a_size(denominator(f"3/({den})")) is vanishes
    with pytest.raises(Exception, match="must be a string"):
        denominator(["1/(n - r)"])
