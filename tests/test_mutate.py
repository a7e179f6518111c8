"""The mutation harness: the mutant generator, the classification, the errata search,
the records, the command line, and (slow) the whole catalog."""
from __future__ import annotations

import dataclasses

import json
import linecache
import re
from fractions import Fraction
from types import SimpleNamespace

import numpy as np
import pytest
from click.testing import CliRunner

from stiefelsym import comm
from stiefelsym.claims import Claim, Size, admissible, load_catalog
from stiefelsym.cli.mutate import mutate as mutate_command
from stiefelsym.analyses.mutate import (LETTER_SWAPS, OPERATORS, SEARCH_EXTRAS, Cell, MutantOutcome, MutationReport,
                               classify, correction_candidates, helper_functions, mutants, mutation_sizes,
                               notation_text, run_mutation, search_corrections)
from stiefelsym.reports.report import render_mutation_markdown, render_mutation_summary
from stiefelsym.run.runner import run_one


# --------------------------------------------------------------------------- a hand-written claim

def toy_identities(s):
    """Identities on T*V that exercise every operator class."""
    X, P = s.X, s.P
    pair = {"Lambda": s.eta, "Pi": s.theta}
    return {
        "constraint": s.X.T @ s.P + s.P.T @ s.X,
        "antisymmetry": comm(s.xi, s.zeta) + comm(s.zeta, s.xi),
        "half": s.tr(s.P.T @ s.P) / 2 - s.q(1, 2) * s.tr(P.T @ P),
        "unit": -(X.T @ X) + s.Ir,
        "pick": pair["Lambda"] - s.eta,
    }


def toy_claim(func=toy_identities, cid: str = "toy") -> Claim:
    return Claim(id=cid, paper=("toy",), kind="id", section="", func=func, sizes=admissible(n_max=3))


def _numeric_scene(seed: int = 1) -> SimpleNamespace:
    """Plain numpy matrices (no constraints): enough to see that a mutant computes something else."""
    rng = np.random.default_rng(seed)
    n, r = 4, 2
    skew = lambda m: (lambda a: a - a.T)(rng.integers(-5, 6, (m, m)).astype(float))
    return SimpleNamespace(X=rng.integers(-5, 6, (n, r)).astype(float), P=rng.integers(-5, 6, (n, r)).astype(float),
                           xi=skew(n), zeta=skew(n), eta=skew(r), theta=skew(r), Ir=np.eye(r), In=np.eye(n),
                           tr=np.trace, q=lambda a, b=1: float(Fraction(a, b)))


def _value(func, scene) -> dict:
    return {k: np.asarray(v, dtype=float) for k, v in func(scene).items()}


def resolvent_identities(s):
    """The resolvent identity AR − λR + I = 0 and an explicit inverse: the operators on matrix
    functions of A and the spectral parameter."""
    R = s.resolvent(s.lam)
    M = s.A + s.lam * s.In
    return {"resolvent": s.A @ R - s.lam * R + s.In, "inverse": M.inv() @ M - s.In}


def test_every_operator_class_generates_its_mutants():
    ms = mutants(toy_claim())
    by_op = {m.operator for m in ms} | {m.operator for m in mutants(toy_claim(resolvent_identities))}
    assert by_op == {name for name, _, _ in OPERATORS}
    texts = [m.description.split(": ", 1)[1] for m in ms]
    for expected in [
        "flip the sign of the term `s.P.T @ s.X` in `s.X.T @ s.P + s.P.T @ s.X`",
        "negate the term `s.X.T @ s.P` in `s.X.T @ s.P + s.P.T @ s.X`",
        "remove the unary minus in `-(X.T @ X)`",
        "swap the operands of @ in `s.X.T @ s.P`",
        "swap the operands of comm in `comm(s.xi, s.zeta)`",
        "transpose the factor `s.P` in `s.X.T @ s.P`",
        "remove the transpose in `s.X.T` in `s.X.T @ s.P`",
        "drop the term `s.P.T @ s.X` from `s.X.T @ s.P + s.P.T @ s.X`",
        "drop the term `s.X.T @ s.P` from `s.X.T @ s.P + s.P.T @ s.X`",
        "replace `s.X` by `s.P` in `s.X.T`",
        "replace `s.xi` by `s.zeta` in `comm(s.xi, s.zeta)`",
        "replace `s.eta` by `s.theta` in `pair['Lambda'] - s.eta`",
        "replace `X` by `P` in `X.T`",
        "replace `pair['Lambda']` by `pair['Pi']` in `pair['Lambda'] - s.eta`",
        "change the coefficient 2 to 3 in `s.tr(s.P.T @ s.P) / 2`",
        "change the coefficient 1 to 2 in `s.q(1, 2)`",
        "change the coefficient 2 to 3 in `s.q(1, 2)`",
        "swap the letters X and P in the term `s.X.T @ s.P`",
    ]:
        assert expected in texts, expected
    assert len({m.description for m in ms}) == len(ms), "descriptions identify mutants"
    assert [m.index for m in ms] == list(range(len(ms)))


def test_mutants_name_their_source_line():
    for m in mutants(toy_claim()):
        line = linecache.getline(__file__, m.lineno)
        snippet = m.description.split("`")[1]
        first_name = re.search(r"[A-Za-z_]\w*", snippet).group(0)
        assert first_name in line, (m.description, line)


def test_a_mutant_really_changes_the_value():
    ms = mutants(toy_claim())
    scene = _numeric_scene()
    base = _value(toy_identities, scene)
    changed = 0
    for m in ms:
        try:
            val = _value(m.func, scene)
        except (ValueError, TypeError):   # ill-shaped: changed as well
            changed += 1
            continue
        assert set(val) == set(base), "check names are not mutated"
        if any(val[k].shape != base[k].shape or not np.allclose(val[k], base[k]) for k in base):
            changed += 1
    # on unconstrained matrices only a handful can coincide (e.g. comm swapped inside a symmetric sum)
    assert changed >= len(ms) - 4
    flip = next(m for m in ms if m.description.endswith("flip the sign of the term `s.P.T @ s.X` in "
                                                        "`s.X.T @ s.P + s.P.T @ s.X`"))
    got = _value(flip.func, scene)["constraint"]
    assert np.allclose(got, scene.X.T @ scene.P - scene.P.T @ scene.X)
    assert toy_identities(scene)["constraint"].shape == got.shape


def named_checks(s):
    return {f"order {2 * 1 + 1}": s.q(3) - s.q(2 + 1)}


def test_f_strings_are_names_not_mathematics():
    texts = [m.description for m in mutants(toy_claim(named_checks))]
    assert texts and not any("2 * 1" in t for t in texts)
    assert any("change the coefficient 3 to 4 in `s.q(3)`" in t for t in texts)


def test_mutants_keep_the_original_function_intact():
    before = _value(toy_identities, _numeric_scene())
    mutants(toy_claim())
    after = _value(toy_identities, _numeric_scene())
    assert all(np.allclose(before[k], after[k]) for k in before)


def test_a_mutated_definition_is_the_deep_copy_with_the_site_replaced():
    """Each mutant copies only the path to its site: the same tree as a deep copy with the node replaced
    (every field and position), and the definition it came from is never changed."""
    import ast
    import copy
    from stiefelsym.analyses.mutate import _bound_names, _function_ast, _function_sites, _mutated

    defn, _ = _function_ast(toy_identities)
    before = ast.dump(defn, include_attributes=True)
    sites = list(_function_sites(defn, _bound_names(defn)))
    assert sites
    for site in sites:
        memo: dict = {}
        deep = copy.deepcopy(defn, memo)
        target = memo[id(site.node)]

        class Put(ast.NodeTransformer):
            def visit(self, node):
                if node is target:
                    return ast.copy_location(copy.deepcopy(site.replacement), node)
                return self.generic_visit(node)
        expected = ast.dump(Put().visit(deep), include_attributes=True)
        assert ast.dump(_mutated(defn, site), include_attributes=True) == expected
        assert expected != before
    assert ast.dump(defn, include_attributes=True) == before


def test_mutants_of_a_closure():
    offset = 2

    def shifted(s):
        return {"v": s.q(offset, 4) - s.q(1, 2)}

    ms = mutants(toy_claim(shifted))
    assert ms and all(m.func(SimpleNamespace(q=lambda a, b=1: Fraction(a, b)))["v"] is not None for m in ms)
    flip = next(m for m in ms if "flip the sign" in m.description)
    assert flip.func(SimpleNamespace(q=lambda a, b=1: Fraction(a, b)))["v"] == 1


def test_letter_swaps_are_symmetric_where_declared():
    for a, alts in LETTER_SWAPS.items():
        for b in alts:
            assert a in LETTER_SWAPS[b], (a, b)


def test_a_mutant_is_refuted_by_the_engine():
    c = toy_claim()
    flip = next(m for m in mutants(c) if "flip the sign of the term `s.P.T @ s.X`" in m.description)
    assert run_one(c, Size(3, 2), "rational", 0).verdict == "checked"
    res = run_one(c, Size(3, 2), "rational", 0, func=flip.func, variant=flip.description)
    assert res.verdict == "fails" and res.variant == flip.description and not res.expected


# --------------------------------------------------------------------------- sizes

def test_mutation_sizes_prefer_a_generic_size_and_distinct_r():
    c = toy_claim()
    c = dataclasses.replace(c, sizes=admissible(n_max=5))
    sizes = mutation_sizes(c)
    assert sizes[0] == Size(4, 2)
    assert len(sizes) == 3 and len({s.r for s in sizes}) == 3 and all(s.n <= 4 for s in sizes)
    c = dataclasses.replace(c, fails_at=lambda n, r: (n, r) == (4, 2), erratum="a test erratum")
    assert Size(4, 2) not in mutation_sizes(c)


# --------------------------------------------------------------------------- classification

def _cells(spec: dict) -> list[Cell]:
    out = []
    for (size, method), verdict in spec.items():
        n, r = size if size else (None, None)
        out.append(Cell(n, r, method, verdict))
    return out


BASE = {((3, 2), "exact"): "proved", ((3, 2), "rational"): "checked", ((3, 1), "rational"): "checked",
        (None, "free"): "proved"}


def _classify(spec: dict, base: dict = BASE) -> MutantOutcome:
    baseline = MutantOutcome("c", None, "as printed", None, "", "", _cells(base), "baseline")
    return classify(MutantOutcome("c", 0, "m", 1, "sign", "", _cells(spec)), baseline)


def test_classification_killed_equivalent_survivor_unresolved():
    killed = _classify({((3, 2), "exact"): "fails", ((3, 2), "rational"): "fails",
                        ((3, 1), "rational"): "checked", (None, "free"): "undecided"})
    assert killed.classification == "killed" and not killed.survived
    assert killed.killed_by == {"exact": "fails", "rational": "fails", "free": "undecided"}

    equiv = _classify({((3, 2), "exact"): "proved", ((3, 2), "rational"): "checked",
                       ((3, 1), "rational"): "checked", (None, "free"): "undecided"})
    assert equiv.classification == "equivalent" and not equiv.killed_by

    survivor = _classify({((3, 2), "exact"): "fails", ((3, 2), "rational"): "checked",
                          ((3, 1), "rational"): "checked", (None, "free"): "undecided"})
    assert survivor.classification == "survivor" and survivor.survived == ["rational"]

    unsound_free = _classify({((3, 2), "exact"): "error", ((3, 2), "rational"): "error",
                              ((3, 1), "rational"): "error", (None, "free"): "proved"})
    assert unsound_free.classification == "survivor" and unsound_free.survived == ["free"]

    unresolved = _classify({((3, 2), "exact"): "inconclusive", ((3, 2), "rational"): "checked",
                            ((3, 1), "rational"): "checked", (None, "free"): "undecided"})
    assert unresolved.classification == "unresolved" and not unresolved.survived


def test_cells_where_the_printed_claim_does_not_pass_are_not_counted():
    base = dict(BASE)
    base[((3, 2), "exact")] = "inconclusive"
    o = _classify({((3, 2), "exact"): "inconclusive", ((3, 2), "rational"): "checked",
                   ((3, 1), "rational"): "checked", (None, "free"): "proved"}, base)
    assert o.classification == "equivalent"


# --------------------------------------------------------------------------- errata search

def sign_error(s):
    """X^T P - P^T X vanishes on T*V (a deliberate sign error: it is X^T P + P^T X)."""
    return {"constraint": s.X.T @ s.P - s.P.T @ s.X}


def test_search_corrections_finds_the_sign_error():
    c = toy_claim(sign_error, "sign-error")
    assert run_one(c, Size(3, 2), "rational", 0).verdict == "fails"
    found = search_corrections(c, [Size(3, 2), Size(3, 3)], ["rational"])
    texts = [m.description.split(": ", 1)[1] for m in found]
    assert "flip the sign of the term `s.P.T @ s.X` in `s.X.T @ s.P - s.P.T @ s.X`" in texts
    # the only other one-step correction is the same identity times -1
    assert set(texts) <= {"flip the sign of the term `s.P.T @ s.X` in `s.X.T @ s.P - s.P.T @ s.X`",
                          "negate the term `s.X.T @ s.P` in `s.X.T @ s.P - s.P.T @ s.X`"}
    for m in found:
        assert run_one(c, Size(4, 2), "modular", 3, func=m.func, variant=m.description).verdict == "checked"


def test_search_corrections_at_r_1_cannot_see_the_sign():
    """At r = 1 the printed X^T P - P^T X vanishes anyway: every size matters."""
    c = toy_claim(sign_error, "sign-error")
    assert run_one(c, Size(3, 1), "rational", 0).verdict == "checked"


def test_search_corrections_finds_the_catalogs_registered_erratum_fix():
    """The remark before Lemma 2l: "regular iff n <= 2r + 1" fails at (4, 1); one mutation away is
    the registered correction n <= 2r + 2 (and, at n <= 5, the indistinguishable n <= 3r + 1)."""
    c = load_catalog().get("adjoint-orbit-regularity")
    sizes = [s for s in c.sizes if s.n <= 5]
    assert run_one(c, Size(4, 1), "rational", 0).verdict == "fails"
    texts = {m.description.split(": ", 1)[1] for m in search_corrections(c, sizes, ["rational"])}
    assert "change the coefficient 1 to 2 in `2 * r + 1`" in texts
    assert texts <= {"change the coefficient 1 to 2 in `2 * r + 1`", "change the coefficient 2 to 3 in `2 * r`"}


# --------------------------------------------------------------------------- the operators on resolvents

def test_resolvent_operators_name_what_they_do():
    texts = [m.description.split(": ", 1)[1] for m in mutants(toy_claim(resolvent_identities))]
    for expected in [
        "invert the resolvent `s.resolvent(s.lam)` (μI − A in place of (μI − A)⁻¹)",
        "drop the inverse in `M.inv()` in `M.inv() @ M`",
        "invert the matrix `s.A + s.lam * s.In`",
        "(A − μI)⁻¹ in place of `s.resolvent(s.lam)`",
        "(−μI − A)⁻¹: `s.resolvent(-s.lam)` in place of `s.resolvent(s.lam)`",
        "(A + μI)⁻¹: `-s.resolvent(-s.lam)` in place of `s.resolvent(s.lam)`",
        "(I − A/μ)⁻¹: `s.lam * s.resolvent(s.lam)` in place of `s.resolvent(s.lam)`",
    ]:
        assert expected in texts, expected


@pytest.mark.parametrize("operator", ["invert", "normalize", "letters"])
def test_each_new_operator_is_refuted_on_a_real_claim(operator):
    """Every mutant of the new operators in the dual Lax matrix (LA3), a helper of the claim, is refuted
    by the rational method at (3, 2), and the exact method agrees on the first.  (Elsewhere a swap can be
    a true statement: XᵀP -> PᵀX in tr((XᵀP)²) of the Hamiltonian changes nothing on T*V.)"""
    c = load_catalog().get("neumann-dual-lax-euclidean")
    ms = [m for m in mutants(c, helpers=True) if m.operator == operator and m.description.startswith("in L_dual_at()")]
    assert ms, operator
    for m in ms:
        res = run_one(c, Size(3, 2), "rational", 0, func=m.func, variant=m.description)
        assert res.verdict in ("fails", "error"), (m.description, res.verdict, res.message)
    assert run_one(c, Size(2, 2), "exact", 0, func=ms[0].func, variant=ms[0].description).verdict in ("fails", "error")


def test_helpers_are_the_claims_own_formulas():
    c = load_catalog().get("manakov-dual-lax")
    names = [name for name, _ in helper_functions(c.func)]
    assert "inverse_of_A_plus_lambda" in names and "A_man_dual_at" in names
    assert not any(name in ("block", "comm", "claim") for name in names)


def test_a_helper_mutant_leaves_the_helper_intact():
    c = load_catalog().get("manakov-dual-lax")
    m = next(m for m in correction_candidates(c) if m.operator == "invert"
             and m.description.startswith("in inverse_of_A_plus_lambda()"))
    assert run_one(c, Size(3, 2), "rational", 0, func=m.func, variant=m.description).verdict == "checked"
    assert run_one(c, Size(3, 2), "rational", 0).verdict == "fails"   # the module is restored


# --------------------------------------------------------------------------- planted corrections

def planted_inverse(s):
    """The resolvent identity with μI − A in place of the resolvent (planted)."""
    R = s.resolvent(s.lam).inv()
    return {"resolvent": s.A @ R - s.lam * R + s.In}


def planted_normalization(s):
    """The resolvent identity with (−λI − A)⁻¹ (planted)."""
    R = s.resolvent(-s.lam)
    return {"resolvent": s.A @ R - s.lam * R + s.In}


def planted_letters(s):
    """XᵀP + XᵀP vanishes (planted: the letters of the second term swapped)."""
    return {"constraint": s.X.T @ s.P + s.X.T @ s.P}


def planted_two_signs(s):
    """XᵀX − I_r + PᵀX + XᵀP = 0 with the signs of I_r and XᵀP wrong (planted)."""
    return {"constraints": s.X.T @ s.X + s.Ir + s.P.T @ s.X - s.X.T @ s.P}


def planted_nonzero(s):
    """XᵀP + PᵀX does not vanish (planted: the paper's "does not hold" is wrong)."""
    return {"constraint": s.X.T @ s.P + s.P.T @ s.X}


@pytest.mark.parametrize("func, expected", [
    (planted_inverse, "drop the inverse in `s.resolvent(s.lam).inv()`"),
    (planted_normalization, "(−μI − A)⁻¹: `s.resolvent(s.lam)` in place of `s.resolvent(-s.lam)`"),
    (planted_letters, "swap the letters X and P in the term `s.X.T @ s.P` (occurrence 2)"),
    (planted_two_signs, "flip the sign of the term `s.Ir`"),
], ids=lambda v: getattr(v, "__name__", "")[:30])
def test_search_recovers_a_planted_correction(func, expected):
    c = toy_claim(func, func.__name__)
    assert run_one(c, Size(3, 2), "rational", 0).verdict == "fails"
    found = search_corrections(c, [Size(3, 2), Size(3, 1)], ["rational"])
    texts = [m.description for m in found]
    assert any(expected in t for t in texts), texts
    for m in found:   # verified by another method too, and none reads 0 = 0
        assert run_one(c, Size(4, 2), "modular", 5, func=m.func, variant=m.description).verdict == "checked"
    if func is planted_two_signs:
        assert {m.operator for m in found} == {"sign2"}
        assert any("flip the sign of the term `s.X.T @ s.P`" in t for t in texts)


def test_search_corrects_a_wrong_does_not_hold():
    c = Claim(id="planted-nonzero", paper=("toy",), kind="not", section="", func=planted_nonzero,
              sizes=admissible(n_max=3), expect="nonzero")
    assert run_one(c, Size(3, 2), "rational", 0).verdict == "fails"
    found = search_corrections(c, [Size(3, 2)], ["rational"])
    assert [m.operator for m in found] == ["expect"] and found[0].expect == "holds"


def test_search_space_is_declared():
    names = {name for name, _, _ in OPERATORS} | {name for name, _ in SEARCH_EXTRAS}
    assert {"sign", "sign2", "swap", "transpose", "invert", "normalize", "letters", "helper", "expect"} <= names


def test_vacuous_candidates_are_left_out():
    """Swapping the letters of XᵀP − PᵀX in one term makes the residual E − E: no correction."""
    c = toy_claim(sign_error, "sign-error")
    texts = [m.description for m in correction_candidates(c)]
    assert not any("swap the letters X and P in the term `s.X.T @ s.P`" in t for t in texts)


def _resolvent_line() -> int:
    """The line of `-s.resolvent(-s.lam)` in the catalog's helper inverse_of_A_plus_lambda."""
    import inspect
    from stiefelsym.proofs import sec4_integrability as sec4
    lines, start = inspect.getsourcelines(sec4.inverse_of_A_plus_lambda)
    return start + next(i for i, t in enumerate(lines) if "s.resolvent(-s.lam)" in t)


#: the residual of manakov-dual-lax, (7) §4
MANAKOV_RESIDUAL = "d𝓛*_man/dt − [𝓛*_man, 𝓐*_man]"


def test_search_recovers_the_catalogs_resolvent_erratum():
    """Theorem man-dual: the search over the claim and its helpers finds exactly the registered
    correction, (A + λI) in place of (A + λI)⁻¹, and nothing else."""
    c = load_catalog().get("manakov-dual-lax")
    found = search_corrections(c, [Size(2, 1), Size(3, 2)], ["rational"])
    assert [m.description for m in found] == [
        f"in inverse_of_A_plus_lambda(), line {_resolvent_line()}: invert the resolvent `s.resolvent(-s.lam)` "
        "(μI − A in place of (μI − A)⁻¹) in `-s.resolvent(-s.lam)`"]
    # and in the paper's notation: the inverse dropped in every block of 𝓐*_man(λ)
    assert notation_text(found[0].notation) == (f"in {MANAKOV_RESIDUAL}, blocks (1,1), (1,2), (2,1), (2,2): "
                                                "(A + λIₙ)⁻¹ → λIₙ + A")


def test_cli_corrections(tmp_path):
    res = CliRunner().invoke(mutate_command, ["manakov-dual-lax", "--corrections", "--size", "3,2",
                                              "--method", "rational"])
    assert res.exit_code == 0, res.output
    assert (f"manakov-dual-lax: correction passes: in {MANAKOV_RESIDUAL}, blocks (1,1), (1,2), (2,1), (2,2): (A + λIₙ)⁻¹ → "
            f"λIₙ + A (source: in inverse_of_A_plus_lambda(), line {_resolvent_line()}") in res.output
    assert "1 of " in res.output
    res = CliRunner().invoke(mutate_command, ["--corrections"])
    assert res.exit_code == 2


def test_cli_corrections_on_graphs():
    """The same search on the claim's graphs: one change at one site at a time finds the same correction,
    alone, at the site of the printed resolvent."""
    res = CliRunner().invoke(mutate_command, ["manakov-dual-lax", "--corrections", "--size", "3,2",
                                              "--method", "rational", "--on", "graphs", "--format", "json"])
    assert res.exit_code == 0, res.output
    import json
    data = json.loads(res.stdout)
    (c,) = data["claims"]
    assert c["on"] == "graphs" and c["candidates"] > 10 and len(c["corrections"]) == 1
    (fix,) = c["corrections"]
    assert fix["notation"] == f"in {MANAKOV_RESIDUAL}, blocks (1,1), (1,2), (2,1), (2,2): (A + λIₙ)⁻¹ → λIₙ + A"
    assert fix["source"] == "s.resolvent(-s.lam)" and "in inverse_of_A_plus_lambda()" in fix["description"]


# --------------------------------------------------------------------------- end to end

SMALL = ("euclidean-invariance", "normal-hamiltonian", "invariants-so-n")


@pytest.fixture(scope="module")
def small_report() -> MutationReport:
    cat = load_catalog()
    return run_mutation([cat.get(i) for i in SMALL], sizes=[Size(3, 2)], methods=("rational", "free"), seed=0)


def test_small_catalog_run_kills_every_mutant_that_is_not_equivalent(small_report):
    rep = small_report
    assert [c.claim for c in rep.claims] == list(SMALL)
    for c in rep.claims:
        assert c.baseline is not None and not c.skipped and c.sizes == [(3, 2)]
        assert {(x.n, x.r, x.method) for x in c.baseline.cells} == {(3, 2, "rational"), (None, None, "free")}
        assert len(c.mutants) == c.mutant_count > 10
        for o in c.mutants:
            assert {(x.n, x.method) for x in o.cells} == {(3, "rational"), (None, "free")}
            assert o.classification in ("killed", "equivalent")
    assert rep.ok() and not rep.survivors()
    rows = {(r["claim"], r["method"]): r for r in rep.table()}
    for cid in SMALL:
        row = rows[(cid, "rational")]
        assert row["killed"] + row["equivalent"] == row["total"] > 10
        assert row["killed"] == row["fails"] + row["error"]
    assert sum(r["fails"] for r in rep.table()) > 0 and sum(r["error"] for r in rep.table()) > 0
    free = rows[("euclidean-invariance", "free")]
    assert free["baseline"] == "proved" and free["survived"] == 0


def test_mutation_report_round_trips_through_json(small_report):
    text = small_report.dumps()
    back = MutationReport.from_json(json.loads(text))
    assert back.dumps() == text
    assert back.table() == small_report.table()
    md = render_mutation_markdown(json.loads(text))
    assert "# Mutation analysis" in md and "`euclidean-invariance`" in md
    assert "No survivor" in md
    summary = render_mutation_summary(json.loads(text))
    assert summary.startswith("mutation: ") and "refuted %" in summary and "not passed %" in summary


def test_limit_and_only_select_mutants():
    c = load_catalog().get("normal-hamiltonian")
    rep = run_mutation([c], sizes=[Size(3, 2)], methods=("rational",), limit=3)
    assert len(rep.claims[0].mutants) == 3
    idx = [o.index for o in rep.claims[0].mutants]
    assert idx[0] == 0 and idx == sorted(idx) and idx[-1] > 3
    rep = run_mutation([c], sizes=[Size(3, 2)], methods=("rational",), only=[5])
    assert [o.index for o in rep.claims[0].mutants] == [5]


def test_parallel_run_gives_the_same_records():
    c = load_catalog().get("normal-hamiltonian")
    one = run_mutation([c], sizes=[Size(3, 2)], methods=("rational",), limit=4, jobs=1)
    two = run_mutation([c], sizes=[Size(3, 2)], methods=("rational",), limit=4, jobs=2)
    strip = lambda rep: [(o.index, o.classification, [(x.n, x.method, x.verdict) for x in o.cells])
                         for o in rep.outcomes()]
    assert strip(one) == strip(two)


def test_unknown_method_is_refused():
    with pytest.raises(ValueError, match="unknown mutation method"):
        run_mutation([toy_claim()], methods=("auto",))


# --------------------------------------------------------------------------- command line

def _invoke(args):
    return CliRunner().invoke(mutate_command, args)


def test_cli_small_run_writes_reports(tmp_path):
    out = tmp_path / "rep"
    res = _invoke(["normal-hamiltonian", "--size", "3,2", "--method", "rational", "--method", "free",
                   "--limit", "4", "--report-dir", str(out), "--jobs", "1"])
    assert res.exit_code == 0, res.output + res.stderr
    lines = res.stdout.splitlines()
    assert lines[0].startswith("normal-hamiltonian (as printed) baseline:")
    assert sum(1 for l in lines if l.startswith("normal-hamiltonian#")) == 4
    assert any(l.startswith("mutation: 4 mutants of 1 claims") for l in lines)
    data = json.loads((out / "mutation.json").read_text())
    assert data["meta"]["command"].startswith("stiefelsym mutate normal-hamiltonian --size 3,2")
    assert [o["name"] for o in data["meta"]["operators"]] == [n for n, _, _ in OPERATORS]
    md = (out / "mutation.md").read_text()
    assert "| `normal-hamiltonian` | rational |" in md


def test_cli_reports_carry_no_timing_and_the_log_keeps_them(tmp_path, monkeypatch):
    """mutation.json is the same file at every run of the same command (no per-claim or per-run seconds);
    the timings go to mutation-log.json, which is not one of the reproducible reports."""
    monkeypatch.chdir(tmp_path)
    files = []
    for _ in range(2):
        res = _invoke(["normal-hamiltonian", "--size", "3,2", "--method", "rational", "--limit", "3",
                       "--report-dir", "rep", "--jobs", "1"])
        assert res.exit_code == 0, res.output + res.stderr
        files.append(((tmp_path / "rep" / "mutation.json").read_bytes(),
                      json.loads((tmp_path / "rep" / "mutation-log.json").read_text())))
    assert files[0][0] == files[1][0]
    stable = json.loads(files[0][0])
    cells = [c for m in stable["claims"][0]["mutants"] for c in m["cells"]]
    assert cells and all(c["seconds"] is None for c in cells) and stable["claims"][0]["seconds"] is None
    logged = [c for m in files[0][1]["claims"][0]["mutants"] for c in m["cells"]]
    assert all(isinstance(c["seconds"], float) for c in logged) and "seconds" in files[0][1]["meta"]


def test_cli_json_format_and_partial_run_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    res = _invoke(["normal-hamiltonian", "--size", "3,2", "--method", "rational", "--limit", "2",
                   "--format", "json", "--jobs", "1"])
    assert res.exit_code == 0, res.stderr
    data = json.loads(res.stdout)
    assert data["claims"][0]["claim"] == "normal-hamiltonian" and len(data["claims"][0]["mutants"]) == 2
    assert "no report written" in res.stderr and not (tmp_path / "reports").exists()


@pytest.mark.parametrize("args, message", [
    (["no-such-claim"], "unknown claim"),
    (["normal-flow", "--method", "auto"], "unknown method 'auto'"),
    (["normal-flow", "--size", "2,3"], "needs r <= n"),
    (["normal-flow", "--size", "x"], "is not a size"),
    (["normal-flow", "euclidean-flow", "--mutant", "3"], "exactly one CLAIM"),
    (["--seed", "-1"], "--seed"),
])
def test_cli_bad_input_is_one_line_and_exit_2(args, message):
    res = _invoke(args)
    assert res.exit_code == 2
    assert res.stderr.count("\n") == 1 and message in res.stderr, res.stderr
    assert res.stdout == ""


def test_cli_exits_1_when_a_mutant_survives(monkeypatch, tmp_path):
    import stiefelsym.analyses.mutate as engine

    def fake(claims, **kw):
        base = MutantOutcome("c", None, "as printed", None, "", "", _cells(BASE), "baseline")
        o = classify(MutantOutcome("c", 7, "line 3: flip", 3, "sign", "", _cells(
            {((3, 2), "exact"): "fails", ((3, 2), "rational"): "checked", ((3, 1), "rational"): "checked",
             (None, "free"): "undecided"})), base)
        from stiefelsym.analyses.mutate import ClaimMutation
        cm = ClaimMutation("c", ["c"], "", "id", [(3, 2), (3, 1)], ["exact", "rational", "free"], 1, base, [o])
        kw["on_result"](o)
        return MutationReport([cm])

    monkeypatch.setattr(engine, "run_mutation", fake)
    res = _invoke(["normal-flow", "--report-dir", str(tmp_path)])
    assert res.exit_code == 1
    assert "c#7 survivor: line 3: flip" in res.stdout and "SURVIVOR of rational" in res.stdout
    assert "c#7 survived rational" in res.stdout
    assert "survived rational" in (tmp_path / "mutation.md").read_text()


# --------------------------------------------------------------------------- the whole catalog

@pytest.mark.slow
def test_whole_catalog_no_method_survives_a_mutant():
    rep = run_mutation(list(load_catalog()), jobs=2)
    proved_by_free = [o.line() for o in rep.outcomes() if "free" in o.survived]
    assert not proved_by_free, "the dimension-free method proved a refuted mutant:\n" + "\n".join(proved_by_free)
    assert rep.ok(), "survivors:\n" + "\n".join(o.line() for o in rep.survivors())


# --------------------------------------------------------------------------- the errata section

def _erratum_results():
    from stiefelsym.results import Result

    def res(n, r, verdict, variant=None, **extra):
        return Result(claim="general-line", paper=["2r-integrals"], section="8", kind="id",
                      title="The general line.", statement=r"\mathcal I_2=\dots", n=n, r=r, method="modular",
                      verdict=verdict, expected=True, seconds=0.1, seed=0, variant=variant,
                      rerun=f"stiefelsym verify general-line --size {n},{r} --method modular --seed 0",
                      **extra)
    return [res(3, 1, "checked"),
            res(3, 2, "fails", witness={"seed": 0, "entry": "(0, 0)", "value": "7"}, residual="(0, 0) = 7",
                erratum="The mixed terms do not belong."),
            res(4, 2, "fails", witness={"seed": 0, "entry": "(0, 0)", "value": "5"}),
            res(3, 1, "checked", variant=r"$\Phi_{ij}^2$ in the second sum"),
            res(3, 2, "checked", variant=r"$\Phi_{ij}^2$ in the second sum"),
            res(4, 2, "checked", variant=r"$\Phi_{ij}^2$ in the second sum")]


def test_errata_section_reads_like_a_referees_report():
    from stiefelsym.reports.report import render_latex, render_markdown
    md = render_markdown(_erratum_results())
    errata = md[md.index("## Errata"):md.index("## Summary")]
    note = next(line for line in errata.splitlines() if line.startswith("**Note for the authors.**"))
    assert "(5) §8 [2r-integrals]" in note and "fails at every computed size with r = 2 (the largest r computed): (3,2), (4,2)" in note
    assert "holds as printed at (3,1)" in note and "seed 0" in note and "(0, 0) = 7" in note
    assert "Phi_{ij}^2" in note and "correction" in note
    assert "holds as printed at (3,1)" in errata
    assert "What is wrong: The mixed terms do not belong." in errata
    assert "- rerun: `stiefelsym verify general-line --size 3,2 --method modular --seed 0`" in errata
    assert "Every other failure, reproducible with:" in errata
    assert "- `stiefelsym verify general-line --size 4,2 --method modular --seed 0`" in errata
    assert "It holds at every size checked with the correction: " in note
    assert "Corrections found" not in errata     # said once, in the note (and listed with its runs)
    tex = render_latex(_erratum_results())
    assert r"\textbf{Note for the authors.}" in tex and r"$\Phi_{ij}^2$" in tex


def test_cli_corrections_json_declares_the_search_space():
    res = CliRunner().invoke(mutate_command, ["vvb-left-factor-size", "--corrections", "--size", "3,2",
                                              "--method", "rational", "--format", "json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    names = {op["name"] for op in data["search_space"]}
    assert {"invert", "normalize", "letters", "sign2", "helper", "expect"} <= names
    (found,) = data["claims"]
    assert found["claim"] == "vvb-left-factor-size" and found["sizes"] == [[3, 2]]
    assert [c["description"] for c in found["corrections"]] == [
        next(c["description"] for c in found["corrections"] if "drop the term `s.r` from `s.n - s.r`" in c["description"])]


def test_exact_residual_texts_of_metric_flow_mutants_do_not_depend_on_the_run():
    """The exact residual of a mutant reads the same whichever mutants the run evaluated before it (they share
    the printed claim's points and its ring of rational functions, whose variables come in the order the run
    met them): all mutants of metric-flow, then three of them in another order."""
    claim = load_catalog().get("metric-flow")

    def texts(only):
        rep = run_mutation([claim], sizes=[Size(4, 2)], methods=["exact"], only=only, jobs=1)
        return {m.index: [c.message for c in m.cells] for m in rep.claims[0].mutants if m.index in (3, 11, 12)}
    every, some = texts(None), texts([12, 11, 3])
    assert set(every) == {3, 11, 12} and every == some, (every, some)
    assert all("= (" in t[0] for t in every.values()) and len({t[0] for t in every.values()}) == 3


def test_a_symbolic_run_at_a_size_refuted_already_is_capped_by_a_count_of_term_products(monkeypatch):
    """While points are lent, a mutant's symbolic run at a size where the rational or modular method has refuted
    it stops at a product of more than MUTANT_REFUTED_TERM_PRODUCTS term products (here 1: at its first
    product); at the other sizes at MUTANT_TERM_PRODUCTS (far above these runs); for the printed claim and with
    fresh points no run is capped."""
    import stiefelsym.analyses.mutate as mutate
    monkeypatch.setattr(mutate, "MUTANT_REFUTED_TERM_PRODUCTS", 1)
    claim = load_catalog().get("manakov-square")
    capped, free = 0, 0
    for lend in (True, False):
        rep = run_mutation([claim], methods=("exact", "rational"), limit=12, lend=lend)
        cm = rep.claims[0]
        assert all("term products" not in (c.message or "") for c in cm.baseline.cells)
        for o in cm.mutants:
            refuted = {(c.n, c.r) for c in o.cells if c.method == "rational" and c.verdict == "fails"}
            for c in o.cells:
                if c.method != "exact":
                    continue
                cut = "term products" in (c.message or "")
                assert not cut or (lend and (c.n, c.r) in refuted), (o.index, c)
                capped += cut
                free += (c.n, c.r) not in refuted and c.verdict == "proved"
    assert capped and free


def test_a_mutants_symbolic_run_is_capped_by_a_count_of_term_products_wherever_it_runs(monkeypatch):
    """While points are lent, a mutant's symbolic run at a size where no point method refuted it stops at a
    product of more than MUTANT_TERM_PRODUCTS term products (here 1: at its first product; a count, so it stops
    at the same step on every machine, where a time would not); the printed claim is never capped."""
    import stiefelsym.analyses.mutate as mutate
    monkeypatch.setattr(mutate, "MUTANT_TERM_PRODUCTS", 1)
    claim = load_catalog().get("manakov-square")
    rep = run_mutation([claim], methods=("exact", "rational"), limit=6, lend=True)
    cm = rep.claims[0]
    assert all(c.verdict == "proved" for c in cm.baseline.cells if c.method == "exact")
    unrefuted = [c for o in cm.mutants for c in o.cells if c.method == "exact" and not any(
        d.method == "rational" and d.verdict == "fails" and (d.n, d.r) == (c.n, c.r) for d in o.cells)]
    assert unrefuted and all(c.verdict == "inconclusive" and "(the cap is 1)" in c.message for c in unrefuted), \
        [(c.n, c.r, c.verdict, c.message) for c in unrefuted]


def test_the_reports_account_of_the_mutants_symbolic_budgets_is_the_analysis_own():
    """mutation.md says what budgets the symbolic method had on mutants: the numbers are the analysis's."""
    import stiefelsym.analyses.mutate as mutate
    from stiefelsym.reports.report import MUTATION_EXPLANATION

    def power(k: int) -> str:
        m, e = k, 0
        while m % 10 == 0:
            m, e = m // 10, e + 1
        return f"{m} x 10^{e}" if m != 1 else f"10^{e}"
    assert f"{mutate.MUTANT_EXACT_SECONDS:g} s per run of a mutant" in MUTATION_EXPLANATION
    assert f"at most {power(mutate.MUTANT_TERM_PRODUCTS)} term products per symbolic product" in MUTATION_EXPLANATION
    assert f"at most {power(mutate.MUTANT_REFUTED_TERM_PRODUCTS)} (a run stopped there" in MUTATION_EXPLANATION


def test_the_claim_line_of_an_error_is_named_the_same_in_every_clone():
    """An error's claim line names a catalog file as proofs/<file>, not by the absolute path of one checkout, so
    that make mutate writes the same mutation.json in every clone (the path was in 9747 messages)."""
    import os
    import stiefelsym.proofs as catalog
    from stiefelsym.methods.fixed_size import _describe
    ns: dict = {}
    exec(compile("def f():\n    return [] - []\n", os.path.join(catalog.__path__[0], "sec1_introduction.py"), "exec"), ns)
    try:
        ns["f"]()
    except TypeError as exc:
        message = _describe(exc)
    assert message.endswith("(at proofs/sec1_introduction.py:2)")
    assert os.path.sep + "proofs" + os.path.sep not in message.replace("(at proofs/", "")


def test_a_claims_file_cannot_have_its_error_named_as_the_catalogs(monkeypatch):
    """Code of a claims file can give its code objects the file name of a catalog module (the review of stop 69):
    once a claims file is in the process (the seal), no frame is named as the catalog's."""
    import os
    import stiefelsym.ir.seal as seal
    import stiefelsym.proofs as catalog
    from stiefelsym.methods.fixed_size import _describe
    monkeypatch.setattr(seal, "sealed", lambda: True)
    path = os.path.join(catalog.__path__[0], "sec3_geodesic_flows.py")
    ns: dict = {}
    exec(compile("def f():\n    return [] - []\n", path, "exec"), ns)
    try:
        ns["f"]()
    except TypeError as exc:
        message = _describe(exc)
    assert "(at proofs/" not in message and message.endswith(f"(at {path}:2, as the code names its file)")


def test_a_slice_of_checks_is_shared_by_content_and_never_once_a_claims_file_is_in(monkeypatch):
    """The slice a mutant's group of checks reads is one object per content (its passes are computed once for
    every mutant that leaves the group as it was); once the process is sealed, an entry of the table (which claim
    code that ran in the process could have written) is never used."""
    import stiefelsym.ir.seal as seal
    from stiefelsym.ir.graph import Graph
    from stiefelsym.methods import fixed_size as fs
    monkeypatch.setattr(fs, "_SLICES", fs.OrderedDict())

    def slice_of(op: str) -> Graph:
        g = Graph()
        x = g.add("leaf", ("X",))
        g.output = g.add("dict", (("c",), (g.add(op, (x, x)),)))
        return g
    first, again, other = slice_of("add"), slice_of("add"), slice_of("sub")
    assert fs._interned(first) is first and fs._interned(again) is first and fs._interned(other) is other
    # a forged entry under the key of a new slice: used unsealed (the catalog's own runs), never sealed
    forged = slice_of("sub")
    fresh = slice_of("matmul")
    fs._SLICES[(fresh.digest(), (), 0, None)] = forged
    monkeypatch.setattr(seal, "sealed", lambda: True)
    assert fs._interned(fresh) is fresh
