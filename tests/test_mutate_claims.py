"""`stiefelsym mutate --claims FILE`: the file is imported and traced in child processes
(stiefelsym.run.userfile), and its claims are mutated, and corrected, on their graphs."""
import json
import os
from pathlib import Path

from click.testing import CliRunner

from stiefelsym.cli.mutate import mutate as mutate_command

FILE = str(Path(__file__).resolve().parent / "claims_for_mutate.py")


def _invoke(args, monkeypatch, tmp_path):
    res = CliRunner().invoke(mutate_command, ["--claims", FILE, *args])
    try:
        err = res.stderr
    except ValueError:          # an older click: standard error mixed into the output
        err = ""
    ran = {int(x.split()[1]) for x in (res.output + err).splitlines() if x.startswith("claims-for-mutate-pid ")}
    assert os.getpid() not in ran, "the claims file ran in the verifying process"
    return res, ran


def test_a_users_claims_are_mutated_on_their_graphs_and_the_file_never_runs_here(monkeypatch, tmp_path):
    res, ran = _invoke(["mc-psi-skew", "--method", "modular", "--jobs", "1", "--format", "json"], monkeypatch,
                       tmp_path)
    assert res.exit_code == 0, res.output
    assert ran, "the file was not imported at all"
    data = json.loads(res.stdout)
    assert data["meta"]["on"] == "graphs"
    (c,) = data["claims"]
    assert c["claim"] == "mc-psi-skew" and c["mutants"], c
    assert all("(graph: node %" in m["description"] for m in c["mutants"]), c["mutants"]
    # the mutants are corruptions the method notices: every one is killed or a true statement
    assert {m["classification"] for m in c["mutants"]} <= {"killed", "equivalent"}, c["mutants"]
    assert any(m["classification"] == "killed" for m in c["mutants"])


def test_a_claim_traced_per_size_is_mutated_on_its_graph_at_each_size(monkeypatch, tmp_path):
    """tr(XᵀX) = r with r read as a number: its graphs at (3,2), (3,1), (3,3) (the file's, traced in the child)
    are one computation, so each mutant is one change at the same node of each; all are noticed."""
    res, _ = _invoke(["mc-per-size", "--method", "modular", "--jobs", "1", "--format", "json"], monkeypatch, tmp_path)
    assert res.exit_code == 0, res.output
    (c,) = json.loads(res.stdout)["claims"]
    assert not c["skipped"] and c["on"] == "graphs per size" and c["mutants"], c
    assert all("(graphs at (3,2), (3,1), (3,3): node %" in m["description"] for m in c["mutants"]), c["mutants"]
    assert {m["classification"] for m in c["mutants"]} <= {"killed", "equivalent"}, c["mutants"]
    assert any(m["classification"] == "killed" for m in c["mutants"])


def test_the_correction_search_of_a_users_claim_works_on_its_graph(monkeypatch, tmp_path):
    res, _ = _invoke(["mc-wrong-sign", "--corrections", "--format", "json"], monkeypatch, tmp_path)
    assert res.exit_code == 0, res.output
    out = json.loads(res.stdout)
    (c,) = out["claims"]
    assert c["on"] == "graphs" and out["graph_search_space"], out
    # the sign of either side: Ψ = XᵀP − PᵀX, or −Ψ = PᵀX − XᵀP, the same equation (the second was dropped as
    # vacuous while the filter looked at (1,1) only, where its left side −Ψ is the 1 x 1 zero matrix)
    assert [k["operator"] for k in c["corrections"]] == ["sign", "sign"], c
    assert "Ψ + PᵀX − XᵀP" in c["corrections"][0]["notation"], c
    assert "Ψ → −Ψ" in c["corrections"][1]["notation"], c


def test_the_correction_search_of_a_users_claim_traced_per_size_works_on_its_graphs(monkeypatch, tmp_path):
    """tr(XᵀX) = −r, traced per size: the candidates are one change at the same node of its graph at every
    size searched; the sign of r is the correction, written in the paper's notation."""
    res, _ = _invoke(["mc-per-size-wrong-sign", "--corrections", "--format", "json"], monkeypatch, tmp_path)
    assert res.exit_code == 0, res.output
    (c,) = json.loads(res.stdout)["claims"]
    assert c["on"] == "graphs" and c["candidates"] > 0 and c["corrections"], c
    assert all(k["operator"] == "sign" and "(graphs at (3,2), " in k["description"]
               for k in c["corrections"]), c
    # written at (3,2), where r = 2: tr(XᵀX) + 2 → tr(XᵀX) − 2; and tr(XᵀX) → −tr(XᵀX), the same equation
    assert [k["notation"] for k in c["corrections"]] == ["in tr: 2 → −2", "in tr: tr(XᵀX) → −tr(XᵀX)"], c


def test_source_mutation_of_a_users_file_is_refused(monkeypatch, tmp_path):
    res, ran = _invoke(["mc-psi-skew", "--on", "source"], monkeypatch, tmp_path)
    assert res.exit_code == 2 and "--on graphs" in res.stderr and not ran, res.output


def test_the_left_sides_of_a_graph_candidate_are_its_checks_without_their_right_sides():
    """The errata search leaves out a candidate whose left sides vanish too (0 = 0): on graphs, each check
    a − b (also inside a list) is replaced by a."""
    from stiefelsym.ir import compile_claim
    from stiefelsym.ir.mutants import output_key
    from stiefelsym.analyses.mutate import _graph_left_sides
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS["standard"]
    cons = (cons.name, cons.build)
    g = compile_claim(lambda s: {"a": s.X.T @ s.X - s.Ir, "b": [s.Psi - s.Psi.T, s.Phi]}, None, None, cons)
    left = compile_claim(_graph_left_sides(g), None, None, cons)
    want = compile_claim(lambda s: {"a": s.X.T @ s.X, "b": [s.Psi, s.Phi]}, None, None, cons)
    assert output_key(left) == output_key(want)       # (the replay keeps the nodes no output reads)
    assert _graph_left_sides(compile_claim(lambda s: {"a": s.Psi + s.Psi.T}, None, None, cons)) is None


def test_without_a_named_claim_the_files_claims_alone_are_mutated(monkeypatch, tmp_path):
    """As verify --claims: the file's claims, not the file's followed by the whole catalog's."""
    res, _ = _invoke(["--method", "modular", "--jobs", "1", "--format", "json", "--limit", "1"], monkeypatch,
                     tmp_path)
    assert res.exit_code == 0, res.output
    ids = [c["claim"] for c in json.loads(res.stdout)["claims"]]
    assert ids and all(i.startswith("mc-") for i in ids), ids


def test_a_claim_whose_graphs_part_between_sizes_is_mutated_at_each_size_on_its_own(monkeypatch, tmp_path):
    """A loop over r: the graphs at (3,2), (3,1), (3,3) are not one computation and carry no site, so each
    node of each size's graph is changed on its own; the claim is covered and every mutant is noticed."""
    res, _ = _invoke(["mc-loop-over-r", "--method", "modular", "--method", "rational", "--jobs", "1",
                      "--format", "json"], monkeypatch, tmp_path)
    assert res.exit_code == 0, res.output
    (c,) = json.loads(res.stdout)["claims"]
    assert not c["skipped"] and c["on"] == "graphs per size" and c["mutants"], c
    at = {m["description"].split("(graph at (")[1].split(")")[0] for m in c["mutants"]}
    assert at == {"3,2", "3,1", "3,3"}, at
    assert {m["classification"] for m in c["mutants"]} <= {"killed", "equivalent"}, c["mutants"]
    # a mutant changed at one size only is refuted at that size and passes at the others
    for m in c["mutants"]:
        if m["classification"] == "killed":
            size = [int(x) for x in m["description"].split("(graph at (")[1].split(")")[0].split(",")]
            bad = {(x["n"], x["r"]) for x in m["cells"] if x["verdict"] not in ("checked", "proved", "numeric")}
            assert bad == {tuple(size)}, m


def test_the_correction_search_of_a_claim_whose_graphs_part_between_sizes_is_refused(monkeypatch, tmp_path):
    """A correction is one change at every size: changes of one size's graph alone are no candidates."""
    res, _ = _invoke(["mc-loop-over-r", "--corrections"], monkeypatch, tmp_path)
    assert res.exit_code == 2 and "graphs per size differ" in res.stderr, res.output
