"""Mutants of the graphs of a claim traced per size (stiefelsym.ir.mutants.sized_graph_mutants): one change
at the same node of every size's graph, and the fall-back to the source where the graphs differ."""
from __future__ import annotations

import pytest

from stiefelsym.analyses.mutate import ON_GRAPHS_PER_SIZE, ON_SOURCE, graph_mutants, notation_text, run_mutation
from stiefelsym.claims import Claim, Size, admissible, load_catalog
from stiefelsym.ir import compile_claim
from stiefelsym.ir.mutants import MutantCensus, SkeletonMismatch, sized_graph_mutants, skeleton
from stiefelsym.ir.replay import GraphClaim, SizedGraphClaim
from stiefelsym.ir.trace import TraceRefused, trace
from stiefelsym.reports.report import render_mutation_markdown, render_mutation_summary
from stiefelsym.run.runner import run_one
from stiefelsym.scene import REALIZATIONS

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
SIZES = [Size(3, 2), Size(3, 1), Size(3, 3)]
FIXED = ("exact", "rational", "modular", "float")


def reads_its_size(s):
    """XᵀX = I_r on V (the claim reads n: it has no graph with symbolic sizes, one graph per size)."""
    assert int(s.n) >= 1
    X = s.X
    return {"XtX": X.T @ X - s.Ir}


def loops_over_r(s):
    """r·XᵀX = r·I_r, the sum over a loop of r terms (its graphs at two sizes are not one computation)."""
    X = s.X
    total = X.T @ X
    for _ in range(int(s.r) - 1):
        total = total + X.T @ X
    return {"rXtX": total - int(s.r) * s.Ir}


def toy(func, cid: str) -> Claim:
    return Claim(id=cid, paper=("toy",), kind="id", section="", func=func, sizes=admissible(n_max=3))


def per_size(func) -> dict:
    return {(z.n, z.r): compile_claim(func, z.n, z.r, CONS) for z in SIZES}


def test_the_toy_claims_trace_per_size_only():
    for f in (reads_its_size, loops_over_r):
        with pytest.raises(TraceRefused):
            compile_claim(f, None, None, CONS)
    assert len({skeleton(g) for g in per_size(reads_its_size).values()}) == 1
    assert len({skeleton(g) for g in per_size(loops_over_r).values()}) > 1


def test_graphs_per_size_as_one_claim_replay_each_size_and_refuse_symbolic_sizes():
    graphs = per_size(reads_its_size)
    gc = SizedGraphClaim(graphs)
    for (n, r), g in graphs.items():
        assert trace(gc, n, r, CONS).digest() == g.digest()
    with pytest.raises(TraceRefused):
        trace(gc, None, None, CONS)          # it reads its size, as the claim does
    with pytest.raises(TraceRefused):
        trace(gc, 4, 2, CONS)                # no graph at (4,2)


def test_a_mutant_is_one_change_at_the_same_node_of_every_sizes_graph():
    graphs = per_size(reads_its_size)
    census = MutantCensus()
    ms = sized_graph_mutants(graphs, CONS, census)
    assert ms and census.sites == len(ms) + census.ill_typed + census.same_as_claim + census.duplicates
    for m in ms:
        assert set(m.sized) == set(graphs)
        assert {tuple(e) for _, e in m.sized.values()} == {(m.node,)}   # the same node at every size
        made = m.graphs(CONS)
        for z, g in graphs.items():   # the edit changes the output at each size, at that node
            assert made[z].digest() != g.digest()
            assert made[z].ops[:m.node] == g.ops[:m.node]


def test_a_per_size_mutant_is_refuted_by_every_method():
    """XᵀX − I_r → XᵀX + I_r made on the graphs at (3,2), (3,1), (3,3): every fixed-size method refutes it at
    every size (the claim as printed passes there), the dimension-free method proves nothing of it."""
    c = toy(reads_its_size, "toy-per-size")
    muts, why = graph_mutants(c, SIZES)
    assert not why
    flip = next(m for m in muts if m.operator == "sign" and "flipped" in m.description)
    assert isinstance(flip.func, SizedGraphClaim)
    for z in SIZES:
        for method in FIXED:
            assert run_one(c, z, method, 0).verdict in ("proved", "checked", "numeric"), (z, method)
            assert run_one(c, z, method, 0, func=flip.func, variant="flip").verdict == "fails", (z, method)
    assert run_one(c, None, "free", 0, func=flip.func).verdict != "proved"
    rep = run_mutation([c], sizes=SIZES, on="graphs")
    cm = rep.claims[0]
    assert cm.on == ON_GRAPHS_PER_SIZE and not cm.skipped and rep.ok()
    o = next(o for o in cm.mutants if o.description == flip.description)
    assert o.classification == "killed" and set(o.killed_by) == set(FIXED) | {"free"}
    assert all(o.killed_by[m] == "fails" for m in FIXED) and o.killed_by["free"] == "undecided"


def test_the_description_of_a_per_size_mutant_is_in_the_papers_notation():
    c = toy(reads_its_size, "toy-per-size")
    muts, _ = graph_mutants(c, SIZES)
    texts = [notation_text(m.notation) for m in muts]
    assert "in XtX: −Iᵣ → Iᵣ" in texts and "in XtX: XᵀX − Iᵣ → XᵀX" in texts, texts
    assert any("X → P" in t for t in texts), texts
    for m in muts:
        assert m.description.startswith(notation_text(m.notation))
        # made at the claim's expression (its site), in each size's graph
        assert " in reads_its_size(), graphs at (3,2), (3,1), (3,3): " in m.description


def refused_where_r_is_n(s):
    """XᵀX = I_r, written with a transpose of a number where r = n (no graph at those sizes)."""
    X = s.X
    if int(s.r) == int(s.n):
        s.eps.T
    return {"XtX": X.T @ X - s.Ir}


def test_graphs_that_are_not_one_computation_are_mutated_at_their_sites():
    c = toy(loops_over_r, "toy-loop")
    with pytest.raises(SkeletonMismatch, match="not the same computation"):
        sized_graph_mutants(per_size(loops_over_r), CONS)
    muts, why = graph_mutants(c, SIZES)          # one change at one site, made in every size's graph
    assert muts and not why
    rep = run_mutation([c], sizes=SIZES, methods=("rational",), on="graphs")
    cm = rep.claims[0]
    assert cm.on == ON_GRAPHS_PER_SIZE and not cm.skipped and cm.mutants and rep.ok()
    assert any(o.classification == "killed" for o in cm.mutants)


def test_a_claim_with_no_graph_at_a_size_falls_back_to_the_source():
    c = toy(refused_where_r_is_n, "toy-refused")
    muts, why = graph_mutants(c, SIZES)
    assert not muts and "no graph at (3,3)" in why
    rep = run_mutation([c], sizes=SIZES, methods=("rational",), on="graphs")
    assert rep.claims[0].skipped.startswith("not covered on graphs") and not rep.claims[0].mutants
    rep = run_mutation([c], sizes=SIZES, methods=("rational",), on="auto")
    cm = rep.claims[0]
    assert cm.on == ON_SOURCE and "no graph at (3,3)" in cm.fallback and not cm.skipped
    assert cm.mutants and all(o.lineno for o in cm.mutants) and rep.ok()    # source mutants, by line
    assert any(o.classification == "killed" for o in cm.mutants)
    # the reports say so
    summary, md = render_mutation_summary(rep.to_json()), render_mutation_markdown(rep.to_json())
    assert "mutants made on: source: 1 claim (1 fell back from graphs to the source)" in summary
    assert "Claims mutated on their source because their graphs could not be:" in md
    assert "`toy-refused`: the claim has no graph with symbolic sizes" in md and "no graph at (3,3)" in md
    # a source run says nothing of graphs
    assert "made on" not in render_mutation_summary(run_mutation([c], sizes=SIZES[:1], methods=("rational",),
                                                                 limit=1).to_json())


def test_the_catalogs_graphs_per_size_replay_to_themselves():
    """Each claim of the catalog traced per size: its graph at a size, replayed by the tracer, is the very
    graph (so a mutant of it differs from it by its change only)."""
    count = 0
    for c in load_catalog():
        cons = REALIZATIONS[c.realization]
        try:
            compile_claim(c.func, None, None, (cons.name, cons.build))
            continue
        except Exception:   # noqa: BLE001 - traced per size
            pass
        z = next(iter(c.sizes), None)
        if z is None:
            continue
        g = compile_claim(c.func, z.n, z.r, (cons.name, cons.build))
        assert trace(GraphClaim(g), z.n, z.r, (cons.name, cons.build)).digest() == g.digest(), c.id
        count += 1
    assert count >= 30
