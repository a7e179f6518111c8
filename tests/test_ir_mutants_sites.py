"""Mutants at the claim's sites (stiefelsym.ir.sites, stiefelsym.ir.mutants.site_mutants): every node a claim
expression built carries that expression's span of source (metadata, never in a digest or a verdict), and
one change at one site is made at every node built there, in every size's graph."""
from __future__ import annotations

import pickle

import pytest

from stiefelsym.analyses.mutate import ON_GRAPH, ON_GRAPHS_PER_SIZE, graph_mutants, notation_text, run_mutation
from stiefelsym.claims import Claim, Size, admissible, load_catalog
from stiefelsym.ir import _clean, compile_claim
from stiefelsym.ir.mutants import MutantCensus, SkeletonMismatch, site_groups, site_mutants, sized_graph_mutants
from stiefelsym.ir.replay import GraphClaim, SizedGraphClaim
from stiefelsym.ir.trace import trace
from stiefelsym.run.runner import run_one
from stiefelsym.scene import REALIZATIONS
from test_ir_mutants_sized import loops_over_r  # the claim with a loop over r

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
SIZES = [Size(3, 2), Size(3, 1), Size(3, 3)]
FIXED = ("exact", "rational", "modular", "float")


def symbolic(s):
    """XᵀP + PᵀX = 0 on T*V (traced with symbolic sizes)."""
    return {"sym": s.X.T @ s.P + s.P.T @ s.X}


def toy(func, cid: str) -> Claim:
    return Claim(id=cid, paper=("toy",), kind="id", section="", func=func, sizes=admissible(n_max=3))


def sited(func, n=None, r=None):
    return _clean(trace, func, n, r, CONS, None, True)


def test_a_site_is_the_claim_expression_that_built_the_node():
    g = sited(symbolic)
    texts = {g.sites[i].text() for i, op in enumerate(g.ops) if op == "matmul"}
    assert texts == {"s.X.T @ s.P", "s.P.T @ s.X"}
    add = g.ops.index("add")
    assert g.sites[add].text() == "s.X.T @ s.P + s.P.T @ s.X" and g.sites[add].function == "symbolic"
    assert g.sites[add].line == symbolic.__code__.co_firstlineno + 2
    # the claim's output and the claim's scene are made by the engine: no site; nor has any node of a replay
    assert g.sites[g.output.i] is None and g.sites[0] is None
    assert not any(sited(GraphClaim(g)).sites)


def test_sites_never_enter_the_digest_the_lines_or_the_pickle():
    for func, n, r in ((symbolic, None, None), (loops_over_r, 3, 3)):
        plain, with_sites = trace(func, n, r, CONS), sited(func, n, r)
        assert plain.sites is None and with_sites.sites is not None and any(with_sites.sites)
        assert len(with_sites.sites) == len(with_sites.ops)
        assert with_sites.digest() == plain.digest() and with_sites.lines() == plain.lines()
        assert pickle.loads(pickle.dumps(with_sites)).sites is None
        assert with_sites.sealed().sites == with_sites.sites
    # the graph every method evaluates is traced without them
    assert compile_claim(symbolic, None, None, CONS).sites is None
    # (a control: the digest does tell two graphs apart)
    assert sited(loops_over_r, 3, 2).digest() != sited(loops_over_r, 3, 3).digest()


def test_a_loop_over_r_mutated_at_one_site_changes_every_iterations_node():
    graphs = {(z.n, z.r): sited(loops_over_r, z.n, z.r) for z in SIZES}
    with pytest.raises(SkeletonMismatch):           # no node is the same node at every size ...
        sized_graph_mutants(graphs, CONS)
    census = MutantCensus()
    ms = site_mutants(graphs, CONS, census)         # ... but every site is the same expression
    assert ms and census.sites == len(ms) + census.ill_typed + census.same_as_claim + census.duplicates
    flip = next(m for m in ms if m.site.text() == "total + X.T @ X" and m.operator == "sign"
                and "flipped" in m.text)
    assert flip.nodes == 0 + 1 + 2                  # r − 1 iterations at r = 1, 2, 3
    made = flip.graphs(CONS)
    for (n, r), g in graphs.items():
        loop = [i for i, s in enumerate(g.sites or ()) if s == flip.site and g.ops[i] == "add"]
        assert len(loop) == r - 1 and set(flip.sized[(n, r)][1]) == set(loop)
        # every iteration's sum became a difference, at every size (r = 1: no iteration, no change)
        assert made[(n, r)].ops.count("add") == 0
        assert made[(n, r)].ops.count("sub") == g.ops.count("sub") + r - 1
        assert (made[(n, r)].digest() == g.digest()) == (r == 1)
    # a site's group holds one change per (site, operator, change), at every size it built nodes at
    groups = site_groups(graphs)
    assert all(set(per) <= set(graphs) for per in groups.values())


def test_a_site_mutant_is_refuted_by_every_method():
    """Σ XᵀX → Σ (−XᵀX) in the loop over r (each iteration's term): every fixed-size method refutes it where
    the loop runs, the dimension-free method proves nothing of it; a symbolic-size claim likewise."""
    c = toy(loops_over_r, "toy-loop")
    muts, why = graph_mutants(c, SIZES)
    assert not why
    flip = next(m for m in muts if m.source == "total + X.T @ X" and m.operator == "sign" and "flipped" in m.description)
    assert isinstance(flip.func, SizedGraphClaim) and flip.lineno == loops_over_r.__code__.co_firstlineno + 5
    for z in SIZES:
        for method in FIXED:
            assert run_one(c, z, method, 0).verdict in ("proved", "checked", "numeric"), (z, method)
            verdict = run_one(c, z, method, 0, func=flip.func, variant="flip").verdict
            assert verdict == ("fails" if z.r > 1 else run_one(c, z, method, 0).verdict), (z, method)
    rep = run_mutation([c], sizes=SIZES, on="graphs")
    cm = rep.claims[0]
    assert cm.on == ON_GRAPHS_PER_SIZE and not cm.skipped and rep.ok()
    o = next(o for o in cm.mutants if o.description == flip.description)
    assert o.classification == "killed" and set(o.killed_by) == set(FIXED) | {"free"}
    assert all(o.killed_by[m] == "fails" for m in FIXED) and o.killed_by["free"] == "undecided"
    rep = run_mutation([toy(symbolic, "toy-symbolic")], sizes=SIZES[:1], on="graphs")
    cm = rep.claims[0]
    assert cm.on == ON_GRAPH and rep.ok() and cm.mutants
    assert all(o.classification in ("killed", "equivalent") for o in cm.mutants)
    assert any(o.classification == "killed" and set(o.killed_by) == set(FIXED) | {"free"} for o in cm.mutants)


def test_site_mutants_are_written_in_the_papers_notation():
    c = toy(loops_over_r, "toy-loop")
    muts, _ = graph_mutants(c, SIZES)
    texts = [notation_text(m.notation) for m in muts]
    assert any("XᵀX" in t for t in texts), texts
    for m in muts:
        t = notation_text(m.notation)
        assert t and ".T" not in t and "@" not in t        # no Python in the change itself
        assert m.description.startswith(t) and "in loops_over_r()" in m.description


def test_catalog_claims_whose_graphs_part_between_sizes_are_mutated_on_their_graphs():
    """`tangency` loops over n and r: its graphs per size have other skeletons, and it is mutated on them."""
    c = load_catalog().get("tangency")
    at = [Size(4, 2), Size(4, 1), Size(4, 3)]
    muts, why = graph_mutants(c, at)
    assert not why and len(muts) >= 20
    assert all(m.lineno and m.source and m.notation for m in muts)


def test_a_site_mutant_of_a_claim_traced_per_size_changes_every_size_its_site_built_nodes_at():
    """`invariants-complete` (a loop over the fibre's directions, a function under a derivative): each mutant
    is one change at one site made at every size; its graph differs from the claim's at every size where the
    site built a node, and only there."""
    c = load_catalog().get("invariants-complete")
    at = [Size(4, 2), Size(4, 1), Size(4, 3)]
    cons = (REALIZATIONS[c.realization].name, REALIZATIONS[c.realization].build)
    base = {(z.n, z.r): compile_claim(c.func, z.n, z.r, cons).digest() for z in at}
    muts, why = graph_mutants(c, at)
    assert not why and len(muts) >= 10
    everywhere = 0
    for m in muts:
        edits = {z: gc._edits for z, gc in m.func._claims.items()}
        assert edits.keys() == base.keys() and any(edits.values())
        for z, digest in base.items():
            changed = compile_claim(m.func, z[0], z[1], cons).digest() != digest
            assert changed == bool(edits[z]), (m.index, z)
        everywhere += all(edits.values())
    assert everywhere >= 10
