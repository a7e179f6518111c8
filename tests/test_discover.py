"""Discovery of conserved quantities: the space found is verified, its dimension is exact at the
points sampled, and a corrupted flow or a corrupted integral is told apart."""
from fractions import Fraction

from stiefelsym.claims import Claim, Size, admissible
from stiefelsym.analyses.discover import Integral, Monomial, ansatz, closed_words, conserved, resolve_flow
from stiefelsym.run.runner import run_one


def test_closed_words_are_one_per_trace_class_and_reduced():
    words = closed_words(2, 1)
    assert ("P", "Pt") in words and ("A", "X", "Xt") in words
    assert all(not any(a == "Xt" and b == "X" for a, b in zip(w, w[1:] + w[:1])) for w in words)
    # tr(PPᵀ) and tr(PᵀP) are one class (rotation), tr(XPᵀ) and tr(PXᵀ) too (transposition)
    assert len({frozenset(w) for w in words}) <= len(words)
    assert len(ansatz(4)) == 25


def test_the_euclidean_neumann_flow_has_its_hamiltonian_and_the_right_momentum():
    flow, _ = resolve_flow("neumann-euclidean")
    d = conserved(flow, Size(4, 2), degree=4, verify=("auto", "free"))
    texts = {I.text() for I in d.integrals}
    assert texts == {"tr(AXXᵀ) + tr(PPᵀ)", "tr(PXᵀPXᵀ)"}, texts
    assert all(I.verified for I in d.integrals)


def test_a_corrupted_flow_loses_the_energy():
    good, _ = resolve_flow("neumann-euclidean")

    def bad(s):
        v = good(s)
        return {"X": v["X"], "P": v["P"] + s.A @ s.X * 2}     # the force with the wrong sign
    d = conserved(bad, Size(4, 2), degree=2, verify=("auto",))
    assert "tr(AXXᵀ) + tr(PPᵀ)" not in {I.text() for I in d.integrals}


def test_the_probes_are_evaluated_after_the_derivative_pass(monkeypatch):
    """The derivatives of the ansatz along the flow are graph nodes, as in the methods: no dual scene is
    built (one would raise here), and the space found is the same."""
    import stiefelsym.scene as scene_module

    def refused(*args, **kwargs):
        raise AssertionError("a dual scene")
    flow, _ = resolve_flow("neumann-euclidean")
    monkeypatch.setattr(scene_module.TangentScene, "__init__", refused)
    d = conserved(flow, Size(4, 2), degree=2, verify=())
    assert {I.text() for I in d.integrals} == {"tr(AXXᵀ) + tr(PPᵀ)"}


def test_a_corrupted_integral_fails_verification():
    flow, _ = resolve_flow("neumann-euclidean")
    wrong = Integral([(Fraction(1), Monomial((("A", "X", "Xt"),))), (Fraction(2), Monomial((("P", "Pt"),)))])
    F = wrong.function()
    claim = Claim(id="wrong-integral", paper=("t",), kind="id", section="t",
                  func=lambda s: {"dI/dt": s.d(F, flow(s))}, sizes=admissible(4))
    assert run_one(claim, Size(4, 2), "auto", 0).verdict == "fails"


def test_a_users_flow_from_a_file_through_the_command_line(tmp_path):
    from pathlib import Path
    from click.testing import CliRunner
    from stiefelsym.cli import main
    example = Path(__file__).resolve().parent.parent / "examples" / "my_flow.py"
    r = CliRunner().invoke(main, ["discover", f"{example}:flow_A2", "--max-a", "2", "--degree", "2"])
    assert r.exit_code == 0, r.output
    assert "I1 = tr(AAXXᵀ) + tr(PPᵀ)    [auto proved, free (all n, r) proved]" in r.output
    bad = CliRunner().invoke(main, ["discover", "no-such-flow"])
    assert bad.exit_code == 2 and "unknown flow" in bad.output


def test_the_lax_partner_of_la2_is_found_and_proved_for_all_sizes():
    from stiefelsym.analyses.discover import LAX, lax_partner, resolve_function
    flow, _ = resolve_flow("neumann-normal")
    space, verdicts = lax_partner(resolve_function("LA2", LAX), flow, Size(4, 2), degree=2)
    assert space.text() == "−XPᵀ + PXᵀ − λ·A"
    assert sorted(space.text(b) for b in space.basis) == ["I_n", "λ·I_n"]
    assert verdicts == {"auto": "proved", "free (all n, r)": "proved"}


def test_an_empty_space_is_certified_by_a_rank():
    from stiefelsym.analyses.discover import lax_partner
    flow, _ = resolve_flow("geodesic-normal")
    space, verdicts = lax_partner(lambda s: s.X @ s.X.T, flow, Size(4, 2), degree=0)
    assert space.particular is None and not verdicts
    assert space.certificate().startswith("no formula in this 4-term space holds") and space.rank < space.rank_augmented


# -- corrections as solution spaces ---------------------------------------------------------------

import dataclasses  # noqa: E402

import pytest  # noqa: E402


def _space(name, **kw):
    from stiefelsym.analyses.discover import correction_space
    from stiefelsym.analyses.discover_ansatze import CORRECTIONS
    return correction_space(CORRECTIONS[name](), **kw)


def test_man_la_correction_space_holds_the_registered_correction_and_is_proved_for_all_sizes():
    sp = _space("manakov-dual-lax", verify=("auto", "free"))
    assert (sp.N, sp.dimension, sp.zero_dim) == (96, 3, 8)
    assert sp.text() == "[XᵀAP + λ·XᵀP, XᵀAX + λ·I_r; −PᵀAP − λ·PᵀP, −PᵀAX − λ·PᵀX]"
    # the directions: 𝓛*_man(λ) itself, and λI_{2r}, I_{2r} (what commutes with every 𝓛)
    assert sp.text(sp.basis[0]) == "[−Xᵀ(λI_n − A)⁻¹P, −Xᵀ(λI_n − A)⁻¹X; Pᵀ(λI_n − A)⁻¹P, Pᵀ(λI_n − A)⁻¹X]"
    assert sp.contains_registered and sp.contains_printed is False
    assert sp.verdicts == {"auto at (3,2), (2,1), (4,2), (4,3)": "proved", "free (all n, r)": "proved"}


@pytest.mark.parametrize("name, block_12, block_21", [
    ("double-neumann-dual-lax", "−Xᵀ(λI_n − A)⁻¹Y", "I_r + Ẋᵀ(λI_n − A)⁻¹Ẏ"),
    ("complex-neumann-dual-lax", "−Zᵀ(λI_n − A)⁻¹Z̄", "I_r + Żᵀ(λI_n − A)⁻¹Ż̄"),
], ids=["LA3*D", "LA3*"])
def test_la3_star_corrections_are_the_only_formulas_of_their_shape(name, block_12, block_21):
    sp = _space(name)
    assert (sp.N, sp.dimension) == (48, 0)
    assert sp.text() == f"[0, {block_12}; {block_21}, 0]"
    assert sp.contains_registered and sp.contains_printed is False and sp.verified


def test_c_eq_correction_is_y_pi_alone():
    sp = _space("coupled-neumann-flow")
    assert (sp.N, sp.dimension, sp.text()) == (32, 0, "YΠ")
    assert sp.contains_registered and sp.contains_printed is False and sp.verified


def test_so_nn_printed_order_space_is_certified_empty():
    sp = _space("coupled-big-lax-normal")
    assert sp.empty and sp.rank < sp.rank_augmented and not sp.verdicts
    assert sp.certificate().startswith("no formula in this 64-term space holds")


def test_so_nn_reordered_space_holds_the_registered_correction_only():
    sp = _space("coupled-big-lax-normal/[A,L]")
    assert (sp.N, sp.dimension, sp.text()) == (64, 0, "[0, −ν⁻¹·XYᵀ; −ν⁻¹·YXᵀ, 0]")
    # the order alone does not repair it: the printed +ν⁻¹K is not in the space
    assert sp.contains_registered and sp.contains_printed is False and sp.verified


def test_a_corrupted_lax_matrix_has_no_partner_of_the_man_la_shape():
    """Negative control: with the (1,1) block of 𝓛*_man(λ) negated, no 𝓐 of the ansatz holds."""
    from stiefelsym import block, comm
    from stiefelsym.analyses.discover import _catalog_module, correction_space
    from stiefelsym.analyses.discover_ansatze import manakov_dual_lax
    sec4 = _catalog_module("sec4_integrability")

    def L_bad(s):
        L = sec4.L_man_dual(s)
        R = s.resolvent(s.lam)
        X, P = s.X, s.P
        return L + block([[X.T @ R @ P * 2, s.zeros(s.r, s.r, ("r", "r"))],
                          [s.zeros(s.r, s.r, ("r", "r")), s.zeros(s.r, s.r, ("r", "r"))]])

    def residual(s, slot):
        flow = s.dirac_flow(sec4.H_manakov_square)
        return s.d(L_bad, flow) - comm(L_bad(s), slot(s, {"X": s.X, "P": s.P}))
    sp = correction_space(dataclasses.replace(manakov_dual_lax(), residual=residual))
    assert sp.empty and sp.contains_registered is False
    assert sp.certificate().startswith("no formula in this 96-term space holds")


def test_a_corrupted_c_eq_does_not_return_the_corruption():
    """Negative control: the printed QΠ is never a solution, and the Q̇ of a corrupted flow (−AX with the
    wrong sign) has no last term of the shape that repairs it."""
    from stiefelsym.analyses.discover import correction_space
    from stiefelsym.analyses.discover_ansatze import coupled_neumann_flow
    a = coupled_neumann_flow()

    def residual(s, slot):
        return a.residual(s, lambda t, w: slot(t, w) - t.A @ w["X"] * 2)
    sp = correction_space(dataclasses.replace(a, residual=residual))
    assert sp.empty


@pytest.mark.parametrize("l, N", [(1, 6), (2, 17), (3, 23)], ids=["l=1", "l=2", "l=3"])
def test_the_general_line_of_the_spectral_integrals_is_the_only_one_of_its_shape(l, N):
    sp = _space(f"2r-integrals-general-line/l={l}")
    assert (sp.N, sp.dimension) == (N, 0) and sp.contains_registered and sp.verified
    assert sp.contains_printed is (l == 3)      # the printed line holds for l = r only


def test_the_report_does_not_test_the_schematic_printed_line_at_1_lt_l_lt_r():
    """At 1 < l < r the printed general line of (5) §8 ends in “+ ⋯”: discover.md says that no printed formula
    is tested there (as verification.md does) and what its literal reading gives; at l = 1 and l = r it gives
    the printed formula's verdict."""
    from stiefelsym.reports.discover_report import render_markdown
    md = {l: render_markdown([_space(f"2r-integrals-general-line/l={l}")]) for l in (1, 2, 3)}
    assert "- the printed formula is not in the space." in md[1] and "- the printed formula holds." in md[3]
    assert "the printed formula" not in md[2]
    assert ("- the printed line is schematic at 1 < l < r (it ends in “+ ⋯”, which states no further term), so no "
            "printed formula is tested at l = 2; read literally as the sums of its l vectors e and any number of p, "
            "it is not in the space.") in md[2]


def test_the_general_line_holds_at_every_l_up_to_n_4():
    """At random points mod p (auto proves it exactly at the sizes within the claim's symbolic budget, which
    takes two minutes: the slow test up to n = 6 runs auto)."""
    from stiefelsym.analyses.discover_ansatze import sweep_general_line
    res = sweep_general_line(4, method="modular")
    assert len(res) == 20 and all(v == "checked" for *_, v in res), res


@pytest.mark.slow
def test_the_general_line_holds_at_every_l_up_to_n_6():
    from stiefelsym.analyses.discover_ansatze import sweep_general_line
    res = sweep_general_line(6)
    assert len(res) == 56 and all(v in ("proved", "checked") for *_, v in res), res


def test_correct_through_the_command_line_and_the_report_is_reproducible(tmp_path):
    from click.testing import CliRunner
    from stiefelsym.cli import main
    runs = [CliRunner().invoke(main, ["discover", "--correct", "coupled-neumann-flow", "--correct",
                                      "coupled-big-lax-normal", "--report-dir", str(tmp_path / d)]) for d in "ab"]
    assert all(r.exit_code == 0 for r in runs), runs[0].output
    assert "the last term of Q̇ = YΠ    [auto at (3,2), (2,1), (4,2), (4,3) proved]" in runs[0].output
    assert "no formula in this 64-term space holds" in runs[0].output
    for f in ("discover.md", "discover.tex"):
        assert (tmp_path / "a" / f).read_bytes() == (tmp_path / "b" / f).read_bytes()
    md = (tmp_path / "a" / "discover.md").read_text(encoding="utf-8")
    assert "| `coupled-neumann-flow` (C-eq) |" in md and "$Y\\Pi$ | matches" in md
    bad = CliRunner().invoke(main, ["discover", "--correct", "no-such-claim"])
    assert bad.exit_code == 2 and "no correction ansatz" in bad.output


def test_correct_as_a_real_subprocess():
    import subprocess
    import sys
    out = subprocess.run([sys.executable, "-m", "stiefelsym", "discover", "--correct", "coupled-neumann-flow"],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert "exactly one formula holds in this 32-term space" in out.stdout


def test_a_users_own_correction_search_through_the_command_line_and_the_api():
    from pathlib import Path
    from click.testing import CliRunner
    from stiefelsym.cli import main
    from stiefelsym.analyses.discover import correction_space, load_object
    example = Path(__file__).resolve().parent.parent / "examples" / "my_correction.py"
    # the command runs no code of a file in the process that gives its verdicts: a search of one's own runs from Python
    r = CliRunner().invoke(main, ["discover", "--correct", f"{example}:ANSATZ"])
    assert r.exit_code == 2 and "runs no code of a file" in r.output, r.output
    sp = correction_space(load_object(str(example), "ANSATZ"), verify=("auto", "free"))
    assert (sp.N, sp.dimension) == (5, 2)
    assert "X·M = XXᵀAX − XPᵀP    [auto proved, free (all n, r) proved]" in "\n".join(sp.lines())


def test_a_users_flow_is_traced_in_the_sandbox_so_a_file_that_patches_the_engine_gets_no_verdict(tmp_path):
    """discover FILE.py:F imported F's file in the verifying process, where its import could replace the engine's
    functions (run_one giving "proved", the probe's derivatives 0) and have a non-integral reported as proved.  Now
    F is traced in the claims files' sandbox and only its graphs come back: the engine's seal refuses the file."""
    from click.testing import CliRunner
    from stiefelsym.cli import main
    (tmp_path / "patching.py").write_text(
        "import stiefelsym.run.runner as _runner\n"
        "_runner.run_one = lambda *a, **k: None\n\n\n"
        "def flow(s):\n"
        "    return {'X': s.P, 'P': -(s.A @ s.X) - s.X @ s.P.T @ s.P + s.X @ s.X.T @ s.A @ s.X}\n", encoding="utf-8")
    r = CliRunner().invoke(main, ["discover", f"{tmp_path / 'patching.py'}:flow", "--size", "3,2", "--degree", "2",
                                  "--no-products"])
    assert r.exit_code == 2 and "the engine was changed by claim code" in r.output, r.output
    from stiefelsym.run import runner
    assert runner.run_one.__module__ == "stiefelsym.run.runner"
    # the same flow without the patch: its one integral (the energy) found and proved
    (tmp_path / "honest.py").write_text("from helper import flow\n", encoding="utf-8")     # a helper beside it
    (tmp_path / "helper.py").write_text("\n".join((tmp_path / "patching.py").read_text().splitlines()[3:]) + "\n")
    r = CliRunner().invoke(main, ["discover", f"{tmp_path / 'honest.py'}:flow", "--size", "3,2", "--degree", "2",
                                  "--no-products"])
    assert r.exit_code == 0, r.output
    assert "I1 = tr(AXXᵀ) + tr(PPᵀ)    [auto proved, free (all n, r) proved]" in r.output
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".stiefelsym-discover-")]


def test_the_latex_table_of_corrections_breaks_names_and_fits_its_columns(tmp_path):
    """A referee's PDF: a claim's name may break after its hyphens (it overran the next column), every
    cell is ragged right, a solution wider than its column is shrunk to it, and the fragment compiles
    with no overfull line."""
    import shutil
    import subprocess
    from stiefelsym.reports.discover_report import render_latex
    spaces = [_space("double-neumann-dual-lax"), _space("coupled-big-lax-normal")]
    tex = render_latex(spaces)
    assert r"\texttt{double-\allowbreak{}neumann-\allowbreak{}dual-\allowbreak{}lax} (LA3*D)" in tex
    # the words of the slot break as text; only the matrix, which TeX cannot break, is shrunk to the cell
    assert r"\raggedright the off-diagonal blocks of $\mathcal L(\lambda) ={}$ \resizebox{\ifdim\width>" \
           r"\linewidth\linewidth\else\width\fi}{!}{$\begin{pmatrix}" in tex
    assert tex.count(r"\tabularnewline") == 1 + len(spaces) and r"\\ \hline" not in tex
    if shutil.which("pdflatex") is None:
        return
    (tmp_path / "discover.tex").write_text(tex, encoding="utf-8")
    (tmp_path / "w.tex").write_text("\\documentclass{article}\\usepackage{amsmath,amssymb,longtable,graphicx}\n"
                                    "\\begin{document}\\input{discover}\\end{document}\n", encoding="utf-8")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "w.tex"], cwd=tmp_path,
                         capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    assert "Overfull" not in (tmp_path / "w.log").read_text(encoding="latin-1")


def test_a_flow_of_one_s_own_that_is_zero_at_symbolic_sizes_proves_nothing_for_all_sizes(tmp_path):
    """A flow file that gives the Neumann tangent where int(s.n) works and a zero tangent where it does not (the
    dimension-free trace): traced in the sandbox, its catch of the refusal still counts, so no integral of the zero
    tangent is proved for every n, r; at the size, tr(AXXᵀ) alone fails along the true flow."""
    from stiefelsym.analyses.discover import confined_function
    from stiefelsym.claims import Claim
    (tmp_path / "twofaced.py").write_text(
        "def flow(s):\n"
        "    try:\n        int(s.n)\n        fixed = True\n    except Exception:\n        fixed = False\n"
        "    X, P, A = s.X, s.P, s.A\n"
        "    if fixed:\n        return {'X': P, 'P': -(A @ X) - X @ P.T @ P + X @ X.T @ A @ X}\n"
        "    return {'X': P - P, 'P': P - P}\n", encoding="utf-8")
    flow = confined_function(str(tmp_path / "twofaced.py"), "flow", "tangent", [Size(3, 2)])
    wrong = Claim(id="twofaced-wrong", paper=("x",), kind="id", section="t", sizes=admissible(4),
                  func=lambda s: {"d": s.d(lambda t: t.tr(t.A @ t.X @ t.X.T), flow(s))})
    assert run_one(wrong, Size(3, 2), "auto", 0).verdict == "fails"
    assert run_one(wrong, None, "free", 0).verdict == "undecided"
