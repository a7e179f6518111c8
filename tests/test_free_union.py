"""The dimension-free method on claims stated at a union of one-r families (r = 1 and r = n, declared by
admissible(r_in=...)): each family proved on its own scene, with its own hypotheses and certificate; a
comparison of sizes answered on a family only where it has one truth value at all its sizes."""
import copy
import dataclasses
import json

import pytest

from stiefelsym import Size, SizeSpec, admissible
from stiefelsym.certificate_check import CASES, check_certificate
from stiefelsym.claims import load_catalog
from stiefelsym.methods.dimension_free import run_free
from stiefelsym.methods.families import size_families
from stiefelsym.ir import SizeFamily, TraceRefused, compile_at_size, compile_claim
from stiefelsym.ir.graph import Size as SizeExpr
from stiefelsym.reports.report import certificate_summary, free_scope
from stiefelsym.scene import REALIZATIONS

CATALOG = load_catalog()
GRAM = CATALOG.get("gram-commutes-with-psi-if-r-is-1-or-n")
UNION = dict(n_max=5, where=lambda n, r: r in (1, n), condition="r = 1 or r = n", r_in=(1, "n"))
CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
R_1, R_N = SizeFamily(1, 2), SizeFamily(None, 1)


def with_func(func, **kw):
    """The claim gram-commutes-with-psi-if-r-is-1-or-n with another function (and other sizes)."""
    return dataclasses.replace(GRAM, func=func, sizes=admissible(**{**UNION, **kw}))


def _proved(res):
    assert res.verdict == "proved", res.message
    report = check_certificate(res.certificate_data)
    assert report.accepted, report.message
    return res


def _psi_then_bracket(s):
    from stiefelsym.proofs.sec4_integrability import bracket_gram_psi
    return {"Psi": s.Psi, "bracket": bracket_gram_psi(s)}


# -- the claim of the paper ------------------------------------------------------------------------------------
def test_gram_commutes_with_psi_is_proved_for_every_n_at_r_1_and_at_r_n():
    res = _proved(run_free(GRAM))
    data = res.certificate_data
    assert data["format"] == CASES
    assert [c["sizes"] for c in data["cases"]] == [{"r": 1, "n_min": 2}, {"r": "n", "n_min": 1}]
    hyps = [set(c["certificate"]["summary"]["hypotheses"]) for c in data["cases"]]
    assert "E1E1t" in hyps[0] and "XXt" not in hyps[0]          # r = 1: E_1E_1^T = I_r, never X X^T = I_n
    assert "XXt" in hyps[1] and "E1E1t" not in hyps[1]          # r = n: X X^T = I_n, never E_1E_1^T = I_r
    assert [c.name for c in res.checks] == ["r = 1: Psi (r = 1)", "r = 1: {tr(G PᵀP), ⟨Ψ, Ψ⟩}",
                                            "r = n: P^T P + Psi^2/4", "r = n: {tr(G PᵀP), ⟨Ψ, Ψ⟩}"]
    assert free_scope(res) == "every n at r = 1 and at r = n"
    assert "r = 1 (n >= 2); r = n (n >= 1)" in res.reductions[0]
    assert any(x.startswith("at r = 1 (every n >= 2): the columns E_1") for x in res.reductions)
    assert any(x.startswith("at r = n (every n >= 1): the claim being stated at r = n") for x in res.reductions)
    assert "case r = 1" in certificate_summary(res) and "case r = n" in certificate_summary(res)
    rep = check_certificate(json.loads(json.dumps(data)))       # what results.json holds
    assert rep.accepted and "case r = 1, n >= 2" in rep.message and "case r = n, n >= 1" in rep.message


def test_the_families_of_the_claim():
    assert size_families(GRAM) == ([R_1, R_N], "")
    # (1,1) belongs to r = n; r = 1 starts where the statement first admits it
    assert size_families(with_func(GRAM.func, n_min=3)) == ([SizeFamily(1, 3), SizeFamily(None, 3)], "")
    # a claim stated at every r has no family; one declared r is one family
    assert size_families(CATALOG.get("magnetic-momentum-map-any-rank")) == ([None], "")
    assert size_families(CATALOG.get("rigid-body-euler-poisson"))[0] == [SizeFamily(None, 2)]


# -- negative controls: corrupted claims ---------------------------------------------------------------------
def gram_square_sign(s):
    """P^T P - Psi^2/4 at r = n (the sign of the paper's identity flipped): false."""
    from stiefelsym.proofs.sec4_integrability import bracket_gram_psi
    checks = {"P^T P - Psi^2/4": s.P.T @ s.P - s.Psi @ s.Psi / 4} if s.r == s.n else {"Psi (r = 1)": s.Psi}
    checks["bracket"] = bracket_gram_psi(s)
    return checks


def gram_psi_plus_gram(s):
    """Psi + X^T X at r = 1 (= X^T X = I_1 there): false."""
    from stiefelsym.proofs.sec4_integrability import bracket_gram_psi
    checks = ({"P^T P + Psi^2/4": s.P.T @ s.P + s.Psi @ s.Psi / 4} if s.r == s.n
              else {"Psi + X^T X": s.Psi + s.X.T @ s.X})
    checks["bracket"] = bracket_gram_psi(s)
    return checks


def gram_swapped_branches(s):
    """The two cases swapped (Psi = 0 at r = n, P^T P = -Psi^2/4 at r = 1): false in both."""
    return {"P^T P + Psi^2/4": s.P.T @ s.P + s.Psi @ s.Psi / 4} if s.r != s.n else {"Psi": s.Psi}


@pytest.mark.parametrize("func, case", [(gram_square_sign, "at r = n"), (gram_psi_plus_gram, "at r = 1"),
                                        (gram_swapped_branches, "at r = 1")])
def test_a_corrupted_claim_at_r_1_or_r_n_is_not_proved(func, case):
    res = run_free(with_func(func))
    assert res.verdict == "undecided", res.message
    assert res.message.startswith(case) and "nonzero normal form" in res.message


def test_each_case_alone_is_what_the_proof_of_the_union_needs():
    """The r = 1 case of the claim is false at r = n (Psi = 0 fails at (2,2)): stated at r = 1 and r = n, it is
    not proved; stated at r = 1 alone it is."""
    assert run_free(with_func(_psi_then_bracket)).verdict == "undecided"
    _proved(run_free(dataclasses.replace(GRAM, func=_psi_then_bracket, sizes=admissible(5, r_max=1))))


# -- negative controls: sizes that are not a union of one-r families -----------------------------------------
def test_a_condition_without_the_declaration_is_not_a_union():
    """r in (1, n) read from a condition, not declared: no hypothesis of one r is used, r == n is refused."""
    res = run_free(dataclasses.replace(GRAM, sizes=admissible(5, where=lambda n, r: r in (1, n))))
    assert res.verdict == "undecided" and "a size (r) used as a number" in res.message


class AdmitsEveryR(SizeSpec):
    """Declares r in (1, n), but its admits() takes every size."""

    def admits(self, n, r):
        return 1 <= r <= n


@pytest.mark.parametrize("spec", [
    SizeSpec((Size(3, 1), Size(3, 2), Size(3, 3)), r_in=(1, "n")),                 # lists (3,2)
    dataclasses.replace(admissible(4), r_in=(1, "n")),                              # lists every r <= n
])
def test_a_claim_whose_sizes_admit_another_r_is_not_a_union(spec):
    res = run_free(dataclasses.replace(GRAM, sizes=spec))
    assert res.verdict == "undecided"
    assert "declares r = 1 or r = n but admits" in res.message and ",2)" in res.message


def test_a_union_declared_with_an_admits_of_its_own_is_not_believed():
    """A subclass's admits() may admit another r at any n (here every r): the declaration is not believed."""
    res = run_free(dataclasses.replace(GRAM, sizes=AdmitsEveryR((Size(3, 1), Size(3, 3)), r_in=(1, "n"))))
    assert res.verdict == "undecided" and "declares r = 1 or r = n but its admits() is its own code" in res.message


def test_the_declaration_restricts_the_statement():
    spec = admissible(5, r_in=(1, "n"))
    assert [(z.n, z.r) for z in spec] == [(n, r) for n in range(1, 6) for r in range(1, n + 1) if r in (1, n)]
    assert not spec.admits(7, 3) and spec.admits(7, 1) and spec.admits(7, 7)
    for bad in [(0,), ("m",), (1, 1), (True,)]:
        with pytest.raises(ValueError):
            admissible(5, r_in=bad)


# -- comparisons of sizes: decided on a family only where it has one truth value -----------------------------
def branch_on_n(s):
    """Branches on n == 2, which neither family decides."""
    return {"Psi": s.Psi} if s.n == 2 else {"Psi": s.Psi - s.Psi}


def branch_on_r_is_1(s):
    """Branches on r == 1: true on the family r = 1, undecided on r = n (true at (1,1) only)."""
    return {"Psi": s.Psi} if s.r == 1 else {"P^T P + Psi^2/4": s.P.T @ s.P + s.Psi @ s.Psi / 4}


def branch_on_r_below_n(s):
    """Branches on r < n: true on the family r = 1 (n >= 2), false on r = n."""
    return {"Psi": s.Psi} if s.r < s.n else {"P^T P + Psi^2/4": s.P.T @ s.P + s.Psi @ s.Psi / 4}


@pytest.mark.parametrize("func, refused", [(branch_on_n, "n == 2"), (branch_on_r_is_1, "r == 1")])
def test_a_comparison_a_family_does_not_decide_is_undecided(func, refused):
    res = run_free(with_func(func))
    assert res.verdict == "undecided"
    assert f"a comparison of sizes ({refused})" in res.message and "that is not the same at every size" in res.message


def test_a_comparison_each_family_decides_is_proved():
    _proved(run_free(with_func(branch_on_r_below_n)))


def test_the_graph_on_a_family_is_the_graph_at_its_sizes():
    for family, sizes in ((R_1, [(2, 1), (3, 1), (7, 1)]), (R_N, [(1, 1), (3, 3), (7, 7)])):
        g = compile_claim(GRAM.func, None, None, CONS, family=family).digest()
        assert all(compile_at_size(GRAM.func, n, r, CONS).digest() == g for n, r in sizes)
    # with symbolic sizes on no family, the comparison is refused (as before)
    with pytest.raises(TraceRefused, match=r"a size \(r\) used as a number"):
        compile_claim(GRAM.func, None, None, CONS)


@pytest.mark.parametrize("family, a, op, b, expected", [
    (R_N, "r", "__eq__", "n", True), (R_N, "r", "__lt__", "n", False), (R_N, "r", "__le__", "n", True),
    (R_N, "n", "__eq__", 1, None), (R_N, "n", "__ge__", 1, True), (R_N, "r", "__gt__", 1, None),
    (R_N, "n", "__ne__", 0, True), (SizeFamily(None, 3), "n", "__gt__", 2, True),
    (R_1, "r", "__eq__", "n", False), (R_1, "r", "__lt__", "n", True), (R_1, "r", "__eq__", 1, True),
    (R_1, "n", "__eq__", 1, False), (R_1, "n", "__eq__", 2, None), (R_1, "n", "__ge__", 2, True),
    (R_1, "n", "__gt__", 2, None), (SizeFamily(1, 1), "r", "__eq__", "n", None),
    (SizeFamily(2, 3), "r", "__lt__", "n", True), (R_N, "2r", "__eq__", "n", False), (R_N, "2r", "__gt__", "n", True),
])
def test_what_a_family_decides(family, a, op, b, expected):
    size = lambda x: x if type(x) is int else SizeExpr(int(x[:-1] or 1), x[-1], None)    # noqa: E731
    assert family.decide(size(a), op, size(b)) is expected


def test_a_family_gives_the_numbers_it_fixes():
    assert R_1.number(SizeExpr(2, "r", None)) == 2 and R_1.number(SizeExpr(1, "n", None)) is None
    assert R_N.number(SizeExpr(1, "r", None)) is None
    for bad in [(None, 0), (0, 3), (3, 2), ("n", 2)]:
        with pytest.raises(ValueError):
            SizeFamily(*bad)


# -- the certificate of cases --------------------------------------------------------------------------------
def _cases():
    return copy.deepcopy(_proved(run_free(GRAM)).certificate_data)


def _rejected(data, why):
    rep = check_certificate(data)
    assert not rep.accepted and why in rep.message, rep.message


def test_a_certificate_of_cases_with_a_dropped_term_is_rejected():
    data = _cases()
    next(e for e in data["cases"][1]["certificate"]["entries"] if e["terms"])["terms"].pop()
    _rejected(data, "the case r = n")


def test_a_case_that_uses_a_hypothesis_of_another_r_is_rejected():
    data = _cases()
    data["cases"][0]["sizes"]["r"], data["cases"][1]["sizes"]["r"] = "n", 1     # each case under the other's r
    _rejected(data, "a hypothesis of another r")


@pytest.mark.parametrize("edit", [
    lambda d: d["cases"].pop(),                                       # one case is no union
    lambda d: d["cases"].append(copy.deepcopy(d["cases"][0])),        # a family twice
    lambda d: d["cases"][0]["sizes"].update(n_min=0),                 # n >= 0
    lambda d: d["cases"][0]["sizes"].update(r="m"),                   # not a family
    lambda d: d["cases"][0].update(certificate=copy.deepcopy(d)),     # a case of cases
])
def test_a_malformed_certificate_of_cases_is_rejected(edit):
    data = _cases()
    edit(data)
    assert not check_certificate(data).accepted


# -- the results file ------------------------------------------------------------------------------------------
def _cli(*args):
    from click.testing import CliRunner
    from stiefelsym.cli import main
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def test_the_proof_of_the_union_survives_the_results_file(tmp_path):
    """The record of the union's proof carries the digest of its graphs on its families (it has no graph on every
    size); `stiefelsym check` accepts it, and rejects it with a case's certificate cut or its digest edited."""
    out = tmp_path / "rep"
    r = _cli("verify", GRAM.id, "--method", "free", "--report-dir", str(out))
    assert r.exit_code == 0, r.output
    path = out / "results.json"
    payload = json.loads(path.read_text())
    record, = payload["results"]
    assert record["verdict"] == "proved" and len(record["digest"]) == 64
    # (the PDF keeps a short relation on one line: its spaces are ties)
    tex = (out / "verification.tex").read_text().replace(r"\nobreakspace{}", " ")
    assert "every n at r = 1 and at r = n (dimension-free): proved" in tex
    assert _cli("check", str(path)).exit_code == 0
    for edit in (lambda x: next(e for e in x["certificate_data"]["cases"][0]["certificate"]["entries"]
                                if e["terms"])["terms"].pop(),
                 lambda x: x.update(digest="0" * 64)):
        bad = copy.deepcopy(payload)
        edit(bad["results"][0])
        path.write_text(json.dumps(bad))
        r = _cli("check", str(path))
        assert r.exit_code == 1 and "REJECTED" in r.output, r.output


# -- one declared r is one family: the same answers ------------------------------------------------------------
def orthogonal_if_square(s):
    """X X^T = I_n where r == n (the only branch at r = n), X^T X = I_r otherwise."""
    return {"XX^T": s.X @ s.X.T - s.In} if s.r == s.n else {"X^TX": s.X.T @ s.X - s.Ir}


def test_a_claim_stated_at_r_n_alone_may_ask_whether_r_is_n():
    square = dataclasses.replace(GRAM, func=orthogonal_if_square, sizes=admissible(4, r_is_n=True))
    res = _proved(run_free(square))
    assert "XXt" in res.certificate_data["summary"]["hypotheses"] and free_scope(res) == "every n at r = n"


def test_r_1_with_n_1_does_not_decide_whether_r_is_n():
    """Stated at r = 1 for every n >= 1: r == n holds at (1,1) only, so the comparison is refused; from n = 2 on
    it is false and the claim (X^T X = I_r there) is proved."""
    res = run_free(dataclasses.replace(GRAM, func=orthogonal_if_square, sizes=admissible(4, r_max=1)))
    assert res.verdict == "undecided" and "a comparison of sizes (r == n)" in res.message
    _proved(run_free(dataclasses.replace(GRAM, func=orthogonal_if_square, sizes=admissible(4, n_min=2, r_max=1))))
