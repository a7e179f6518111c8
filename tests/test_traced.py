"""The outputs of a claim as traced: every record carries its graph read back in the paper's notation (what every
method evaluated), the reports print it, `stiefelsym show` prints it, and `stiefelsym check` rejects a record whose
text is not its graph's.

This is how the reports make the one route left open at the boundary of a job visible (tests/adversary/README.md,
stop 85): a claims file whose code sends the graph of another function (c7_forged_line.py) gets the verdict of that
graph, and the report now prints that graph, XᵀX − Iᵣ, where the file's code reads X Xᵀ − Iₙ."""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
FORGED = HERE / "adversary" / "s85" / "h4" / "c7_forged_line.py"

CLAIMS = '''
from stiefelsym import admissible, claim


@claim("mine-orth", kind="id", sizes=admissible(n_max=3))
def mine_orth(s):
    """The constraints of V(n, r)."""
    return {"orth": s.X.T @ s.X - s.Ir, "tangent": s.X.T @ s.P + s.P.T @ s.X}


@claim("mine-entry", kind="id", sizes=[(2, 1), (3, 1)])
def mine_entry(s):
    """A sum over the rows (n used as a number): traced at each size."""
    return {"x11": sum(s.X[i, 0] * s.X[i, 0] for i in range(s.n)) - (s.X.T @ s.X)[0, 0]}
'''


def _invoke(cwd: Path, *args: str):
    from click.testing import CliRunner
    from stiefelsym import cli
    old = os.getcwd()
    os.chdir(cwd)
    try:
        return CliRunner().invoke(cli.main, list(args), prog_name="stiefelsym")
    finally:
        os.chdir(old)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    d = tmp_path_factory.mktemp("traced")
    (d / "mine.py").write_text(CLAIMS, encoding="utf-8")
    out = _invoke(d, "verify", "--claims", "mine.py", "--method", "exact", "--method", "free",
                  "--report-dir", "rep", "--jobs", "1")
    assert out.exit_code == 0, out.output
    return d


def _records(d: Path) -> list[dict]:
    return json.loads((d / "rep" / "results.json").read_text(encoding="utf-8"))["results"]


def test_every_record_carries_its_graph_in_notation(run):
    recs = _records(run)
    orth = [r for r in recs if r["claim"] == "mine-orth"]
    assert orth and all(r["traced"] == [["orth", "XᵀX − Iᵣ", "X^T X - I_r"],
                                        ["tangent", "XᵀP + PᵀX", "X^T P + P^T X"]] for r in orth)
    entry = {(r["n"], r["r"]): r["traced"] for r in recs if r["claim"] == "mine-entry" and r["n"] is not None}
    assert set(entry) == {(2, 1), (3, 1)} and all(t and t[0][0] == "x11" for t in entry.values())


def test_the_reports_print_the_outputs_as_traced(run):
    md = (run / "rep" / "verification.md").read_text(encoding="utf-8")
    assert "one graph for every size run" in md and "- orth: XᵀX − Iᵣ" in md
    # a claim traced at each size: the smallest size's graph, and how many graphs there are
    assert "at (2,1) only: the claim's code reads the sizes, and each of its 2 sizes has a graph of its own" in md
    tex = (run / "rep" / "verification.tex").read_text(encoding="utf-8")
    assert r"\item orth: " in tex and r"{$X^T X - I_r$}" in tex


def test_check_rejects_an_edited_or_missing_text(run):
    path = run / "rep" / "results.json"
    good = _invoke(run, "check", str(path), "--claims", "mine.py", "--no-rerun")
    assert good.exit_code == 0, good.output
    payload = json.loads(path.read_text(encoding="utf-8"))
    for k, edit in enumerate((lambda r: r["traced"][0].__setitem__(1, "XXᵀ − Iₙ"), lambda r: r.pop("traced"))):
        forged = json.loads(json.dumps(payload))
        edit(forged["results"][0])
        p = run / f"forged{k}.json"
        p.write_text(json.dumps(forged), encoding="utf-8")
        out = _invoke(run, "check", str(p), "--claims", "mine.py", "--no-rerun")
        assert out.exit_code == 1 and "outputs as traced are not what its graph computes" in out.output, out.output


def test_a_malformed_text_is_refused_and_unsafe_latex_is_never_printed(run):
    from stiefelsym.results import record_problems
    rec = dict(_records(run)[0])
    for bad in ("XᵀX", [["orth", "XᵀX"]], [["orth", "XᵀX", 3]]):
        assert any("traced" in p for p in record_problems(dict(rec, traced=bad)))
    payload = json.loads((run / "rep" / "results.json").read_text(encoding="utf-8"))
    for r in payload["results"]:
        if r["traced"]:
            r["traced"][0][2] = r"\input{/etc/hostname}"
    (run / "unsafe.json").write_text(json.dumps(payload), encoding="utf-8")
    # the report itself traces a claims file's claims again: an edited text is refused before anything is rendered
    out = _invoke(run, "report", "--results", "unsafe.json", "--report-dir", "unsafe")
    assert out.exit_code == 2 and "outputs as traced are not what its graph computes" in out.output, out.output
    # and the LaTeX of a text is printed only when it is mathematics (else its Unicode, escaped)
    from stiefelsym.reports.report import ClaimResults, _tex_traced
    from stiefelsym.results import Result
    res = Result.from_json(dict(rec, traced=[["orth", "XᵀX − Iᵣ", r"\input{/etc/hostname}"]]))
    c = ClaimResults(res)
    c.add(res)
    text = "\n".join(_tex_traced(c))
    assert r"\input" not in text and "orth:" in text


def test_show_prints_the_outputs_as_traced(tmp_path):
    out = _invoke(tmp_path, "show", "euclidean-flow")
    assert out.exit_code == 0 and "traced:      at every size" in out.output and "dP/dt: Ṗ + XPᵀP" in out.output
    out = _invoke(tmp_path, "show", "stiefel-corank-one")      # traced at fixed sizes: its smallest
    assert out.exit_code == 0 and "traced:      at (2,1) only" in out.output
    out = _invoke(tmp_path, "show", "stiefel-corank-one", "--size", "9,1")
    assert out.exit_code == 2 and "not stated at (9,1)" in out.output


def test_a_forged_answer_line_is_visible_in_the_report(tmp_path):
    """The job's answer forged by the file (stop 85's h4 W6): the verdict is that of the graph sent, XᵀX − Iᵣ, and
    the report prints that graph, which a reader compares with the file's code (X Xᵀ − Iₙ)."""
    out = _invoke(tmp_path, "verify", "--claims", str(FORGED), "--method", "exact", "--size", "3,1",
                  "--report-dir", "rep", "--jobs", "1")
    recs = _records(tmp_path)
    assert [r["traced"] for r in recs] == [[["x", "XᵀX − Iᵣ", "X^T X - I_r"]]], out.output
    md = (tmp_path / "rep" / "verification.md").read_text(encoding="utf-8")
    assert "- x: XᵀX − Iᵣ" in md


def test_the_appendix_constants_are_written_as_letters(tmp_path):
    """E₁, Π₁, S₁ (stiefelsym.twisted's constant matrices) print as the letters of their docstrings, also on a
    point of the claim's own, never as a call with the scene among its arguments."""
    out = _invoke(tmp_path, "show", "block-jensen-hamiltonian")
    assert out.exit_code == 0 and "⟨Ψ − Π₁ΨΠ₁, Π₁ηΠ₁⟩" in out.output and "block_projector" not in out.output
    out = _invoke(tmp_path, "show", "magnetic-grassmannian-flow")
    assert out.exit_code == 0 and "E₁" in out.output and "basis_vector" not in out.output
    out = _invoke(tmp_path, "show", "manakov-reflections")
    assert out.exit_code == 0 and "S₁X" in out.output and "reflection(" not in out.output


def test_report_refuses_an_edited_text_of_a_catalog_claim(tmp_path):
    out = _invoke(tmp_path, "verify", "euclidean-flow", "--size", "2,1", "--method", "exact", "--report-dir", "rep",
                  "--jobs", "1")
    assert out.exit_code == 0, out.output
    payload = json.loads((tmp_path / "rep" / "results.json").read_text(encoding="utf-8"))
    payload["results"][0]["traced"][0][1] = "Ẋ − 2P"
    (tmp_path / "forged.json").write_text(json.dumps(payload), encoding="utf-8")
    out = _invoke(tmp_path, "report", "--results", "forged.json", "--report-dir", "forged")
    assert out.exit_code == 2 and "outputs as traced are not what its graph computes" in out.output, out.output
    assert not (tmp_path / "forged").exists()


def test_a_large_graph_is_named_by_its_size_and_the_report_prints_a_smaller_one(tmp_path, monkeypatch):
    """A graph of more nodes than TRACED_NODES is not read back (about 70 µs a node); the report prints the smallest
    size whose graph was."""
    import stiefelsym.run.runner as runner
    from stiefelsym.claims import load_claims_file
    (tmp_path / "mine.py").write_text(CLAIMS, encoding="utf-8")
    c = next(c for c in load_claims_file(tmp_path / "mine.py") if c.id == "mine-entry")
    from stiefelsym.claims import Size
    small = runner.traced_text(c, Size(2, 1))
    monkeypatch.setattr(runner, "TRACED_NODES", 5)
    runner._TRACED.clear()
    big = runner.traced_text(c, Size(3, 1))
    assert small[0][0] == "x11" and big[0][0] == "" and big[0][1].startswith("(a graph of ")
    from stiefelsym.reports.report import ClaimResults
    from stiefelsym.results import Result
    recs = [Result(claim="mine-entry", paper=[], section="", kind="id", title="", statement="", n=n, r=1,
                   method="exact", verdict="proved", expected=True, seconds=None, seed=None, digest=f"d{n}",
                   traced=t) for n, t in ((3, big), (4, big), (2, small))]
    cr = ClaimResults(recs[0])
    for r in recs:
        cr.add(r)
    assert cr.traced() == ("(2,1)", small, 3)


def test_the_number_of_graphs_is_not_printed_as_the_number_of_sizes():
    """Sizes that share a graph: the report counts the sizes and the distinct graphs apart."""
    from stiefelsym.reports.report import ClaimResults, traced_intro
    from stiefelsym.results import Result
    traced = [["x11", "x", "x"]]
    recs = [Result(claim="shared", paper=[], section="", kind="id", title="", statement="", n=n, r=r,
                   method="exact", verdict="proved", expected=True, seconds=None, seed=None,
                   digest="d1" if r == 1 else "d2", traced=traced) for n, r in ((2, 1), (3, 1), (3, 2), (4, 2))]
    cr = ClaimResults(recs[0])
    for r in recs:
        cr.add(r)
    where, _, graphs = cr.traced()
    assert (graphs, cr.traced_sizes()) == (2, 4)
    text = traced_intro(where, graphs, sizes=cr.traced_sizes())
    assert "its graph depends on the size: its 4 sizes give 2 distinct graphs" in text
    assert "sizes has a graph of its own" not in text
    assert "each of its 2 sizes has a graph of its own" in traced_intro("(2,1)", 2, sizes=2)


SPOOF = '''
from stiefelsym import admissible, claim


@claim("spoof-point", kind="id", sizes=admissible(n_max=3))
def spoof_point(s):
    """A generic matrix named X, Greek chi and 1: never printed as the point X or the number 1."""
    G, H = s.generic("X", "n", "r"), s.generic("\\u03a7", "n", "r")
    one = s.scalar("1")
    return {"x": G.T @ G - s.Ir, "chi": H.T @ H - s.Ir, "one": one * s.X - s.X, "mine": s.scalar("mu") * s.X}
'''


def test_a_parameter_never_prints_as_an_engine_letter(tmp_path):
    """A claim's own parameter whose name reads as a letter of the engine's (X, Y, xi, lam, E1), a number, or is not
    ASCII (a Greek capital chi looks like X) is printed quoted: what the reports show as traced reads as the graph."""
    from stiefelsym.claims import Size, load_claims_file
    from stiefelsym.run.runner import traced_text
    (tmp_path / "spoof.py").write_text(SPOOF, encoding="utf-8")
    c = next(iter(load_claims_file(tmp_path / "spoof.py")))
    text = {name: uni for name, uni, _tex in traced_text(c, Size(3, 2))}
    assert text == {"x": "‘X’ᵀ‘X’ − Iᵣ", "chi": "‘Χ’ᵀ‘Χ’ − Iᵣ", "one": "‘1’X − X", "mine": "μX"}, text
    tex = {name: t for name, _uni, t in traced_text(c, Size(3, 2))}
    assert tex["chi"] == r"\mathtt{u03a7}^T \mathtt{u03a7} - I_r", tex


def test_a_function_named_like_a_letter_is_quoted():
    from stiefelsym.claims import load_catalog
    from stiefelsym.ir import _compiled_graph
    from stiefelsym.ir.graph import Named
    from stiefelsym.ir.notation import Reader, unicode
    from stiefelsym.scene import REALIZATIONS
    c = next(c for c in load_catalog() if c.id == "euclidean-flow")
    cons = REALIZATIONS[c.realization]
    rd = Reader(_compiled_graph(c.func, None, None, (cons.name, cons.build)))
    assert unicode(rd.arg(Named("mine.X"))) == "‘X’" and unicode(rd.arg(Named("mine.energy"))) == "energy"



def test_show_at_a_large_size_ends_within_its_budget(tmp_path, monkeypatch):
    """A claim that needs fixed sizes runs its own loops at the size asked: `show --size 60,60` is budgeted, never a
    hang."""
    from stiefelsym import cli
    monkeypatch.setattr(cli, "SHOW_SECONDS", 1.0)
    out = _invoke(tmp_path, "show", "dual-lax-determines-the-point", "--size", "60,60")
    assert out.exit_code == 0 and "the trace did not end within 1 s at this size" in out.output, out.output


NESTED = '''
from stiefelsym import admissible, claim


@claim("doubling", kind="id", sizes=admissible(n_max=3))
def doubling(s):
    """Forty products, each reading the one before twice: a text of exponential length written whole."""
    M = s.X.T @ s.X
    for _ in range(40):
        M = M @ M - M
    return {"M": M - M}
'''


def test_show_full_prints_what_the_records_cut(tmp_path, monkeypatch):
    """h4's W8 (stop 86): a record's text is cut to a reader's length (a long sum ends in …, a matrix of many blocks
    is named by its shape); `show --full` prints every term and block, and a text too long to write whole ends within
    the show's budget with a message that says why."""
    from stiefelsym import cli
    (tmp_path / "nested.py").write_text(NESTED, encoding="utf-8")
    cut = _invoke(tmp_path, "show", "gen-chasles")
    whole = _invoke(tmp_path, "show", "gen-chasles", "--full")
    assert cut.exit_code == 0 and whole.exit_code == 0, (cut.output, whole.output)
    assert "(2×2 matrix)" in cut.output and "(2×2 matrix)" not in whole.output
    assert "read back from the claim's graph, whole:" in whole.output
    assert "−Xᵀ(λIₙ − A)⁻¹P, −Xᵀ(λIₙ − A)⁻¹X; Iᵣ + Pᵀ(λIₙ − A)⁻¹P, Pᵀ(λIₙ − A)⁻¹X" in whole.output
    monkeypatch.setattr(cli, "SHOW_SECONDS", 2.0)
    out = _invoke(tmp_path, "show", "doubling", "--claims", "nested.py", "--full")
    assert out.exit_code == 0 and "did not end within 2 s: written whole" in out.output, out.output
    out = _invoke(tmp_path, "show", "doubling", "--claims", "nested.py")
    assert out.exit_code == 0 and "M: (" in out.output and "…" in out.output, out.output
