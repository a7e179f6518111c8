"""The paper's notation of IR graphs (stiefelsym.ir.notation) and the smallest change between the
graph of a claim and that of a mutant or a correction."""
from __future__ import annotations

import json
import os

import pytest

from stiefelsym import block, comm
from stiefelsym.claims import Claim, Size, admissible, load_catalog
from stiefelsym.ir import compile_claim
from stiefelsym.ir.notation import changes_text, describe, diff, outputs, render
from stiefelsym.latex import math_ok
from stiefelsym.analyses.mutate import ClaimMutation, MutantOutcome, MutationReport, mutants, notation
from stiefelsym.reports.report import render_markdown, render_latex, render_mutation_markdown
from stiefelsym.run.runner import graph_change, verify
from stiefelsym.scene import REALIZATIONS

CONS = REALIZATIONS["standard"]


def _graph(func, n=None, r=None):
    return compile_claim(func, n, r, (CONS.name, CONS.build))


def _show(func, n=None, r=None, tex=False, cap=40):
    g = _graph(func, n, r)
    return {name: render(g, v, tex=tex, cap=cap) for name, v in outputs(g)}


def H(t):
    return t.killing(t.Phi, t.Phi)


# --------------------------------------------------------------------------- the printer

def test_products_and_transposes_by_juxtaposition():
    out = _show(lambda s: {"M": s.X.T @ s.A @ s.X, "N": (s.X @ s.P.T).T, "K": s.X.T @ (s.A - s.In) @ s.X})
    assert out == {"M": "XᵀAX", "N": "(XPᵀ)ᵀ", "K": "Xᵀ(A − Iₙ)X"}
    tex = _show(lambda s: {"M": s.X.T @ s.A @ s.X, "K": s.X.T @ (s.A - s.In) @ s.X}, tex=True)
    assert tex == {"M": "X^T A X", "K": "X^T (A - I_n) X"}


def test_sums_with_signs_and_coefficients_as_fractions():
    out = _show(lambda s: {"E": s.Phi - s.q(1, 2) * (s.X @ s.P.T) + 2 * s.A,
                           "F": s.A - (-(s.X @ s.X.T)), "G": s.Phi / 3, "D": s.Phi / s.lam,
                           "C": s.q(-3, 4) * s.A, "Z": s.A - s.A + s.X @ s.P.T, "N": s.q(1, 1) / s.lam})
    assert out == {"E": "Φ − ½XPᵀ + 2A", "F": "A + XXᵀ", "G": "⅓Φ", "D": "Φ/λ", "C": "−¾A", "Z": "XPᵀ",
                   "N": "λ⁻¹"}
    tex = _show(lambda s: {"E": s.Phi - s.q(1, 2) * (s.X @ s.P.T), "D": s.Phi / s.lam}, tex=True)
    assert tex == {"E": r"\Phi - \tfrac{1}{2} X P^T", "D": r"\frac{\Phi}{\lambda}"}


def test_resolvent_is_lambda_I_minus_A_inverse():
    """The scene's resolvent(μ) is (μIₙ − A)⁻¹; −(−μIₙ − A)⁻¹ is written (A + μIₙ)⁻¹."""
    out = _show(lambda s: {"R": s.resolvent(s.lam), "S": -s.resolvent(-s.lam),
                           "T": (s.A + s.lam * s.In).inv(), "U": s.resolvent(s.lam).inv()})
    assert out == {"R": "(λIₙ − A)⁻¹", "S": "(A + λIₙ)⁻¹", "T": "(A + λIₙ)⁻¹", "U": "λIₙ − A"}
    assert _show(lambda s: {"R": s.resolvent(s.lam)}, tex=True) == {"R": r"(\lambda I_n - A)^{-1}"}


def test_commutator_trace_pairing_entry_and_block():
    out = _show(lambda s: {"c": comm(s.Phi, s.A) - comm(s.X @ s.X.T, s.A), "t": s.tr(s.X.T @ s.A @ s.X),
                           "k": s.killing(s.Phi, s.xi),
                           "b": block([[s.X.T @ s.X, s.Ir], [s.zeros(s.r, s.r, ("r", "r")), -s.Ir]])})
    assert out == {"c": "[Φ, A] − [XXᵀ, A]", "t": "tr(XᵀAX)", "k": "⟨Φ, ξ⟩", "b": "(XᵀX, Iᵣ; 0, −Iᵣ)"}
    tex = _show(lambda s: {"b": block([[s.X.T @ s.X, s.Ir], [s.Ir, -s.Ir]]), "k": s.killing(s.Phi, s.xi)},
                tex=True)
    assert tex == {"b": r"\begin{pmatrix}X^T X & I_r\\ I_r & -I_r\end{pmatrix}", "k": r"\langle \Phi, \xi\rangle"}
    assert _show(lambda s: {"e": s.X[0, 1] * s.P[1, 0], "b": s.X[0:2, :].T @ s.P[0:2, :]}, 3, 2) == \
        {"e": "X₁₂P₂₁", "b": "X[1..2, :]ᵀP[1..2, :]"}


def test_derivative_along_a_flow_and_gradient():
    def f(s):
        flow = s.dirac_flow(H)
        gX, gP = s.gradient(H)
        return {"Phi": s.d(lambda t: t.Phi, flow), "L": s.d(lambda t: t.Phi + t.lam * t.A, flow), "g": gX - gP}
    out = _show(f)
    assert out == {"Phi": "Φ̇", "L": "d/dt(Φ + λA)", "g": "∂⟨Φ, Φ⟩/∂X − ∂⟨Φ, Φ⟩/∂P"}
    tex = _show(f, tex=True)
    assert tex["Phi"] == r"\dot{\Phi}" and tex["L"] == r"\frac{d}{dt}(\Phi + \lambda A)"


def test_unknown_operations_read_as_function_calls():
    out = _show(lambda s: {"Z": s.realify(s.X, s.P) - s.Zc})
    assert out == {"Z": "realify(X, P) − Z"}


def test_a_huge_expression_is_cut_short():
    def big(s):
        acc = s.A
        for k in range(1, 60):
            acc = acc + k * (s.X @ s.P.T)
        return {"big": acc}
    text = _show(big, cap=12)["big"]
    assert text.startswith("A + XPᵀ + 2XPᵀ") and text.endswith("+ …") and len(text) < 80
    tex = _show(big, tex=True, cap=12)["big"]
    assert tex.endswith(r"+ \dots") and math_ok(tex)


def test_latex_of_every_output_of_the_catalog_is_balanced():
    """Every claim's outputs (capped) print as balanced LaTeX math, and in Unicode, at (3,2)."""
    count = 0
    for c in load_catalog():
        if not c.sizes.admits(3, 2):
            continue
        cons = REALIZATIONS[c.realization]
        try:
            g = compile_claim(c.func, 3, 2, (cons.name, cons.build))
        except Exception:   # noqa: BLE001 - claims stated elsewhere
            continue
        for name, v in outputs(g):
            tex = render(g, v, tex=True, cap=30)
            assert math_ok(tex), (c.id, name, tex)
            assert render(g, v, cap=30), (c.id, name)
            count += 1
    assert count > 100


# --------------------------------------------------------------------------- the diff

def test_manakov_dual_lax_correction_in_the_papers_notation():
    """The registered correction of (LA-MAN3): (A + λI)⁻¹ → A + λI in every block of 𝓐*_man(λ), which the
    correction names (its blocks are 𝓐*_man's, not the residual's)."""
    c = load_catalog().get("manakov-dual-lax")
    changes = diff(_graph(c.func), _graph(c.corrections[0].func))
    assert describe(changes) == ("in d𝓛*_man/dt − [𝓛*_man, 𝓐*_man], blocks (1,1), (1,2), (2,1), (2,2): "
                                 "(A + λIₙ)⁻¹ → A + λIₙ")
    assert (changes[0].old_tex, changes[0].new_tex) == (r"(A + \lambda I_n)^{-1}", r"A + \lambda I_n")
    assert c.corrections[0].blocks_of == "𝓐*_man(λ) in (9) §4"
    named = diff(_graph(c.func), _graph(c.corrections[0].func), blocks_of=c.corrections[0].blocks_of)
    assert named[0].where == ("d𝓛*_man/dt − [𝓛*_man, 𝓐*_man], blocks (1,1), (1,2), (2,1), (2,2) "
                              "of 𝓐*_man(λ) in (9) §4")
    assert graph_change(c, c.corrections[0].func, Size(3, 2)) == [named[0].to_json()]


@pytest.mark.parametrize("cid, display", [("double-neumann-dual-lax", "(5) §10"),
                                          ("double-neumann-dual-lax-extends-la3", "(5) §10"),
                                          ("complex-neumann-dual-lax", "(15) §10")])
def test_flipped_resolvent_is_written_as_printed(cid, display):
    """(λ⁻¹Iₙ − A)⁻¹/λ, the scene's form of the printed (Iₙ − λA)⁻¹, is written as the paper prints it, and the
    correction changes the whole inverse, in the off-diagonal blocks of 𝓛(λ)."""
    c = load_catalog().get(cid)
    changes = graph_change(c, c.corrections[0].func, Size(3, 2))
    assert [(ch["old"], ch["new"]) for ch in changes] == [("(Iₙ − λA)⁻¹", "(λIₙ − A)⁻¹")]
    assert changes[0]["where"].endswith(f"blocks (1,2), (2,1) of 𝓛(λ) in {display}")
    assert changes[0]["old_tex"] == r"(I_n - \lambda A)^{-1}"


@pytest.mark.parametrize("fragment, expected", [
    ("flip the sign of the term `s.lam * s.A` in `s.Phi + s.lam * s.A`", "in Lax (B = A^1), Lax (B = A^2), at the 3rd of its 3 places: λA → −λA"),
    ("replace `s.A` by `s.Ainv` in `s.lam * s.A`", "in Lax (B = A^1), Lax (B = A^2), at the 3rd of its 3 places: λA → λA⁻¹"),
    ("invert the matrix `s.Phi + s.lam * s.A`", "in Lax (B = A^1), Lax (B = A^2), at the 3rd of its 3 places: Φ + λA → (Φ + λA)⁻¹"),
    # [𝔸(Φ) + λB, Φ + λA] → [Φ + λA, 𝔸(Φ) + λB] with B = A^k and 𝔸(Φ) = Σ A^m Φ A^(k-1-m), at (3, 2): k = 1, 2
    ("swap the operands of comm in `comm(M, L)`",
     "in Lax (B = A^2): [ΦA + AΦ + λAA, Φ + λA] → [Φ + λA, ΦA + AΦ + λAA]"),   # at B = A, 𝓐 = 𝓛
    ("negate the term `t.lam * t.A + t.P @ t.X.T` in",
     "in d tr L^1/dt (B = A^1), d tr L^2/dt (B = A^1), d tr L^3/dt (B = A^1), d tr L^1/dt (B = A^2), "
     "d tr L^2/dt (B = A^2), d tr L^3/dt (B = A^2): λA + PXᵀ − XPᵀ → −λA − PXᵀ − XPᵀ"),
    ("swap the letters P and X in the term `t.P @ t.X.T`",
     "in d tr L^1/dt (B = A^1), d tr L^2/dt (B = A^1), d tr L^3/dt (B = A^1), d tr L^1/dt (B = A^2), "
     "d tr L^2/dt (B = A^2), d tr L^3/dt (B = A^2): PXᵀ → XPᵀ"),
])
def test_real_mutants_of_manakov_lax(fragment, expected):
    c = load_catalog().get("manakov-lax")
    m = next(m for m in mutants(c) if fragment in m.description)
    text = changes_text(notation(c, m, Size(3, 2)))
    assert text.startswith(expected), text


def test_an_ill_typed_mutant_has_no_notation_and_dead_code_no_change():
    c = load_catalog().get("manakov-lax")
    ms = mutants(c)
    ill = next(m for m in ms if "replace `s.Phi` by `s.Psi` in `s.Phi + s.lam * s.A`" in m.description)
    assert notation(c, ill, Size(3, 2)) == []
    # a change of a value no output uses
    printed = Claim(id="dead", paper=("prep",), kind="id", section="2", func=_with_dead_code,
                    sizes=admissible(3, n_min=3, r_min=2, r_max=2))
    assert changes_text(graph_change(printed, _with_other_dead_code, Size(3, 2))) == "no change in the graph"
    # a changed printed number: the statement it is part of
    c = load_catalog().get("invariant-metrics")
    rank = next(m for m in mutants(c) if "drop the term `span` from `unknowns - span`" in m.description)
    assert changes_text(notation(c, rank, Size(3, 2))) == "in invariant forms: rank(…) = 4 everywhere → rank(…) = 6 everywhere"
    # a changed right inverse: the identity op(inv(y)) = y it is part of
    c = load_catalog().get("constraints-independent")
    right = next(m for m in mutants(c) if "change the coefficient 4 to 5" in m.description)
    assert changes_text(notation(c, right, Size(3, 2))) == (
        "in rank d(F, G): ¼[y\u0303₁ + y\u0303₁ᵀ, XᵀP] → (1/5)[y\u0303₁ + y\u0303₁ᵀ, XᵀP]")


def _with_dead_code(s):
    unused = s.X @ s.P.T   # noqa: F841
    return {"E": comm(s.Phi, s.A)}


def _with_other_dead_code(s):
    unused = s.P @ s.X.T   # noqa: F841
    return {"E": comm(s.Phi, s.A)}


def test_a_directional_derivative_names_its_tangent_vector():
    c = load_catalog().get("left-momentum-map")
    m = next(m for m in mutants(c) if "replace `s.X` by `s.P` in `s.xi @ s.X`" in m.description)
    assert changes_text(notation(c, m, Size(3, 2))) == "in dX/dt = xi X, equivariance: ξX → ξP"
    g = _graph(lambda s: {"D": s.d(lambda t: t.X.T @ t.X, {"X": s.P, "P": s.zeros(s.n, s.r, ("n", "r"))})})
    assert render(g, outputs(g)[0][1]) == "d/dt(XᵀX) along (Ẋ, Ṗ) = (P, 0)"
    tex = render(g, outputs(g)[0][1], tex=True)
    assert tex.startswith(r"\frac{d}{dt}") and r"\ \text{along}\ " in tex and math_ok(tex)


def test_the_diff_is_deterministic():
    c = load_catalog().get("manakov-lax")
    ms = mutants(c)[:12]
    first = [json.dumps(notation(c, m, Size(3, 2)), ensure_ascii=False) for m in ms]
    again = [json.dumps(notation(c, m, Size(3, 2)), ensure_ascii=False) for m in mutants(c)[:12]]
    assert first == again


def test_negative_control_a_graph_against_itself():
    for cid in ("manakov-dual-lax", "manakov-lax"):
        c = load_catalog().get(cid)
        g = _graph(c.func, 3, 2) if cid == "manakov-lax" else _graph(c.func)
        assert diff(g, g) == [] and describe(diff(g, g)) == "no change"
        # a second tracing is another graph object with the same keys
        g2 = _graph(c.func, 3, 2) if cid == "manakov-lax" else _graph(c.func)
        assert diff(g, g2) == []


def test_the_same_expression_computed_another_way_is_named_so():
    changes = diff(_graph(lambda s: {"E": s.X}), _graph(lambda s: {"E": s.X.T.T}))
    assert describe(changes) == "in E (written the same, computed another way): X → X"


# --------------------------------------------------------------------------- the reports

def _outcome(notation_, description="line 7: flip the sign of the term `s.lam * s.A`"):
    return MutantOutcome("c", 3, description, 7, "sign", "", [], "equivalent", notation=notation_)


def test_mutation_report_prints_the_notation_first_and_the_source_after():
    change = {"where": "Lax", "old": "λA", "new": "−λA", "old_tex": r"\lambda A", "new_tex": r"-\lambda A"}
    rep = MutationReport(claims=[ClaimMutation(claim="c", paper=[], section="1", kind="lax", sizes=[(3, 2)],
                                               methods=["rational"], mutants=[_outcome([change])])])
    md = render_mutation_markdown(rep)
    assert "- `c#3` in Lax: λA → −λA (source: line 7: flip the sign of the term `s.lam * s.A`)" in md
    assert md == render_mutation_markdown(MutationReport.from_json(json.loads(rep.dumps())))
    from stiefelsym.reports.report import _tex_mutant_text
    tex = _tex_mutant_text(rep.to_json()["claims"][0]["mutants"][0])
    assert tex.startswith(r"in Lax: $\lambda A$ $\to$ $-\lambda A$ {\small (source: line 7:")


def wrong_sign(s):
    """[Φ, A] + [A, Φ] = 0, printed with the operands of the second commutator in the wrong order."""
    return {"E": comm(s.Phi, s.A) + comm(s.Phi, s.A)}


def _wrong_order(cid: str) -> Claim:
    """The erratum wrong_sign with its correction (the operands of the second commutator swapped)."""
    c = Claim(id=cid, paper=("prep",), kind="id", section="2", func=wrong_sign,
              sizes=admissible(3, n_min=3, r_min=2, r_max=2), expect="fails", erratum="an order")

    @c.correction("the operands of the second commutator swapped")
    def fixed(s):
        return {"E": comm(s.Phi, s.A) + comm(s.A, s.Phi)}
    return c


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
def test_a_corrections_change_read_in_the_worker_is_the_parents_and_bound_to_its_size():
    from stiefelsym.run import runner
    from stiefelsym.run.pool import Outcome
    c = _wrong_order("wrong-order-w")
    forked = [r for r in verify([c], methods=("modular",), sizes=[Size(3, 2)], jobs=2) if r.variant]
    here = [r for r in verify([c], methods=("modular",), sizes=[Size(3, 2)], jobs=1, fork=False) if r.variant]
    assert forked and changes_text(forked[0].change) == changes_text(here[0].change) == "in E, at the 2nd of its 2 places: [Φ, A] → [A, Φ]"
    # a record that says it read its change at another size (a run shared across r, copied) is read again
    task = (0, 3, 2, "modular", 0)
    res = runner._execute([c], 0, None, 60.0, False, task)
    res.change = [{"where": "E", "old": "forged", "new": "forged", "old_tex": "", "new_tex": ""}]
    res._change_at = (3, 1)
    settled = runner._settle(Outcome("ok", res), task, [c], 0, None)
    assert changes_text(settled.change) == "in E, at the 2nd of its 2 places: [Φ, A] → [A, Φ]"


def test_registered_correction_records_carry_their_change_and_reports_show_it():
    c = _wrong_order("wrong-order")
    results = verify([c], methods=("modular",), sizes=[Size(3, 2)], jobs=1, fork=False)
    corrected = [r for r in results if r.variant is not None]
    assert corrected and corrected[0].verdict == "checked"
    assert changes_text(corrected[0].change) == "in E, at the 2nd of its 2 places: [Φ, A] → [A, Φ]"
    md = render_markdown(results)
    # the note for the authors gives the registered words; the list of candidates has the change and the words
    assert ("It holds at every size checked with the correction: the operands of the second commutator swapped (the "
            "change of the formula as computed is in the candidate corrections below).") in md
    row = "| in E, at the 2nd of its 2 places: \\[Φ, A\\] → \\[A, Φ\\] | the operands of the second commutator swapped | **"
    assert row + "verified at the computed sizes** |" in md or row + "proved for all n, r** |" in md
    assert md == render_markdown(results)
    tex = render_latex(results)
    assert r"in \ensuremath{E}, at the 2nd of its 2 places: $[\Phi, A]$ $\to$ $[A, \Phi]$ {\small (registered as: the operands of the second" in tex


def test_a_hand_edited_change_of_a_correction_is_caught():
    """`stiefelsym check`: a correction's record carries its change of the graph, which the graphs of the
    claim and the correction give again; an edited one is rejected, the honest one passes."""
    from stiefelsym.claims import Registry
    from stiefelsym.run.integrity import check_results
    c = Claim(id="wrong-order", paper=("prep",), kind="id", section="2", func=wrong_sign,
              sizes=admissible(3, n_min=3, r_min=2, r_max=2), expect="fails", erratum="an order")

    @c.correction("the operands of the second commutator swapped")
    def fixed(s):
        return {"E": comm(s.Phi, s.A) + comm(s.A, s.Phi)}
    reg = Registry()
    reg.add(c)
    results = verify([c], methods=("modular",), sizes=[Size(3, 2)], jobs=1, fork=False)
    honest = [json.loads(json.dumps(r.to_json())) for r in results if r.variant is not None]
    assert honest and honest[0]["change"]
    lines: list[str] = []
    assert check_results(honest, reg, echo=lines.append, rerun=False) == 0, lines
    forged = [dict(honest[0], change=[dict(honest[0]["change"][0], new="[Φ, A]")])]
    assert check_results(forged, reg, echo=lines.append, rerun=False) == 1
    assert "change in the paper's notation" in lines[-2]


def test_a_doubling_graph_is_read_in_linear_time():
    """x ← x + x forty times: 2⁴⁰ terms if every shared sum were copied; printed cut short."""
    def doubling(s):
        x = s.X @ s.P.T
        for _ in range(40):
            x = x + x
        return {"D": x}
    text = _show(doubling, cap=10)["D"]
    assert "…" in text and len(text) < 200


def test_at_most_four_changes_are_listed():
    old = _graph(lambda s: {f"c{k}": k * s.X for k in range(1, 7)})
    new = _graph(lambda s: {f"c{k}": (k + 10) * s.X for k in range(1, 7)})
    changes = diff(old, new)
    assert describe(changes) == "in c1: X → 11X; in c2: 2X → 12X; in c3: 3X → 13X; and 3 more changes"
    assert changes_text([c.to_json() for c in changes]).endswith("and 3 more changes")


def test_one_change_below_many_places_is_found():
    """neumann2-kernel: negating a term of a matrix whose entries fill a big block matrix changes every
    block; the change is the term's sign, named once with its places."""
    from stiefelsym.analyses.mutate import mutation_sizes, notation_size
    c = load_catalog().get("neumann2-kernel")
    m = next(m for m in mutants(c) if "negate the term `h` in `h + X @ X.T`" in m.description)   # h = P0Xᵀ − XP0ᵀ
    text = changes_text(notation(c, m, notation_size(mutation_sizes(c))))
    assert text.startswith("in rank Lambda1(h+v) at Psi = 0, blocks (1,1), (1,2), (1,3) and ")
    assert "(P − XXᵀP)Xᵀ → −(P − XXᵀP)Xᵀ" in text and len(text) < 400
