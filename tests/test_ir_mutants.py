"""Graphs as claims (stiefelsym.ir.replay) and mutants made on graphs (stiefelsym.ir.mutants)."""
from __future__ import annotations


import pytest
from click.testing import CliRunner

from stiefelsym.claims import Claim, Size, admissible, load_catalog
from stiefelsym.cli.mutate import mutate as mutate_command
from stiefelsym.ir import compile_claim
from stiefelsym.ir.graph import Graph, Named, Ref
from stiefelsym.ir.mutants import OPERATORS, MutantCensus, graph_mutants, output_key, sites
from stiefelsym.ir.replay import GraphClaim, ReplayError
from stiefelsym.ir.trace import trace
from stiefelsym.analyses.mutate import run_mutation
from stiefelsym.run.runner import run_one
from stiefelsym.scene import REALIZATIONS

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)
METHODS = ("exact", "rational", "modular", "float", "free")


@pytest.fixture(scope="module")
def catalog():
    return load_catalog()


def graph_of(claim: Claim) -> Graph:
    cons = REALIZATIONS[claim.realization]
    return compile_claim(claim.func, None, None, (cons.name, cons.build))


def toy_claim(func, cid: str = "toy") -> Claim:
    return Claim(id=cid, paper=("toy",), kind="id", section="", func=func, sizes=admissible(n_max=3))


# --------------------------------------------------------------------------- a graph as a claim

def test_replaying_a_claims_graph_gives_the_same_graph(catalog):
    """Every claim of the catalog that traces with symbolic sizes: its graph, replayed by the tracer,
    is the very graph (same nodes, same numbers, same digest)."""
    count = 0
    for c in catalog:
        try:
            g = graph_of(c)
        except Exception:    # noqa: BLE001 - traced per size
            continue
        cons = REALIZATIONS[c.realization]
        again = trace(GraphClaim(g), None, None, (cons.name, cons.build))
        assert again.digest() == g.digest(), c.id
        assert not again.refusals
        count += 1
    assert count >= 80


def test_compile_claim_traces_a_graph_claim_like_any_claim(catalog):
    g = graph_of(catalog.get("neumann-lax"))
    gc = GraphClaim(g)
    h = compile_claim(gc, None, None, CONS)
    assert h is not g and h.digest() == g.digest()
    # at a fixed size too (the same graph: it reads no size)
    assert compile_claim(gc, 4, 2, CONS).digest() == g.digest()


# --------------------------------------------------------------------------- mutants

def test_every_operator_is_declared_and_found_on_the_catalog(catalog):
    seen = set()
    for cid in ("neumann-lax", "manakov-dual-lax", "invariants-so-n", "euclidean-flow", "momentum-maps-poisson"):
        seen |= {s.operator for s in sites(graph_of(catalog.get(cid)))}
    assert seen == {name for name, _ in OPERATORS}


def test_mutants_of_la1_are_well_typed_distinct_and_written_in_the_papers_notation(catalog):
    g = graph_of(catalog.get("neumann-lax"))
    census = MutantCensus()
    ms = graph_mutants(g, CONS, census)
    assert len(ms) >= 40
    keys = [m.key for m in ms]
    assert len(set(keys)) == len(keys) and output_key(g) not in keys
    assert census.sites == len(ms) + census.ill_typed + census.same_as_claim + census.duplicates
    assert census.ill_typed > 0            # e.g. a factor Xᵀ transposed: X @ P does not type
    for m in ms:
        assert not m.graph.refusals and m.graph.digest() != g.digest()
        assert m.description().startswith(("in LA1: ", "in LA1, at the "))
    texts = {m.description().split(" (graph:")[0] for m in ms}
    assert "in LA1: XᵀAX → XᵀA⁻¹X" in texts
    assert "in LA1: Φ − λA → Φ" in texts


def test_no_mutant_computes_what_the_claim_computes():
    """A change of a node that no check reads (here: an unused product) leaves the checks as they are:
    no mutant is made of it; two changes that give the same checks make one mutant."""
    def claim(s):
        _ = s.X.T @ s.P          # computed, read by no check
        return {"c": s.X + s.X}
    g = trace(claim, None, None, CONS)
    census = MutantCensus()
    ms = graph_mutants(g, CONS, census)
    unused = next(i for i, op in enumerate(g.ops) if op == "matmul")
    assert census.same_as_claim == 2 and all(m.node != unused for m in ms)   # Xᵀ@P swapped; P → X in it
    assert census.duplicates >= 1          # X + X: dropping either term gives X
    assert output_key(g) not in {m.key for m in ms}
    assert len({m.key for m in ms}) == len(ms)


def test_a_resolvent_is_inverted_and_renormalized(catalog):
    ms = graph_mutants(graph_of(catalog.get("manakov-dual-lax")), CONS)
    texts = [m.description() for m in ms if m.operator == "invert"]
    assert any("(λIₙ − A)⁻¹ → λIₙ − A" in t or "⁻¹ → " in t for t in texts), texts
    assert any(m.operator == "normalize" for m in ms)


def test_a_graph_mutant_is_evaluated_by_every_method():
    def claim(s):
        return {"c": s.X.T @ s.P + s.P.T @ s.X}
    c = toy_claim(claim)
    g = trace(claim, None, None, CONS)
    flip = next(m for m in graph_mutants(g, CONS) if m.operator == "sign" and "flipped" in m.text)
    for method in ("rational", "modular", "float", "exact"):
        assert run_one(c, Size(3, 2), method, 0).verdict in ("checked", "numeric", "proved")
        assert run_one(c, Size(3, 2), method, 0, func=flip.func, variant="flip").verdict == "fails", method
    assert run_one(c, None, "free", 0, func=flip.func).verdict != "proved"


def test_every_graph_mutant_of_la1_is_killed_by_exact_and_free_or_is_a_true_statement(catalog):
    """LA1 on graphs: every mutant that is not a true statement is refuted by exact and not proved by
    free; the equivalent ones (changes of H's Ψ-terms, of the constant λ²A under d/dt, tr(PᵀP) → tr(PPᵀ)...)
    are proved for all n, r by free, with its certificate.  (At n = 3: at n = 4 a mutant with A⁻¹ is a
    symbolic 4x4 solve, beyond the exact method's budget, which says inconclusive there.)"""
    rep = run_mutation([catalog.get("neumann-lax")], sizes=[Size(3, 2)], methods=("exact", "free"), on="graphs",
                       sites="all")
    cm = rep.claims[0]
    assert not cm.skipped and cm.mutant_count == len(cm.mutants) >= 40
    assert rep.ok() and not rep.survivors()
    for o in cm.mutants:
        assert o.classification in ("killed", "equivalent"), o.line()
        if o.classification == "killed":
            assert o.killed_by.get("exact") == "fails" and "free" in o.killed_by, o.line()
        else:
            assert [c.verdict for c in o.cells if c.method == "free"] == ["proved"], o.line()
        assert o.notation and o.description.startswith(("in LA1: ", "in LA1, at the "))


# --------------------------------------------------------------------------- crafted graphs

def _crafted(ops, args, output) -> Graph:
    g = Graph()
    g.ops, g.args, g.output = list(ops), list(args), output
    return g


def _verdicts(func) -> set[tuple[str, str]]:
    """(method, verdict) of every method on the claim whose function is ``func`` (at (3,2), and free)."""
    c = toy_claim(func, "crafted")
    n_r = Size(3, 2)
    out = {(m, run_one(c, n_r, m, 0).verdict) for m in ("exact", "rational", "modular", "float")}
    out.add(("free", run_one(c, None, "free", 0).verdict))
    return out


def test_a_crafted_graph_is_just_another_claim():
    """A graph built by hand and handed over as a claim's function: it goes through the tracer like
    claim code (every method evaluates the tracer's graph, not the object handed in); what it states
    gets the verdict the same statement written in Python gets; what the tracer refuses is refused."""
    # XᵀP = 0, false on T*V: fails under every fixed-size method, free does not prove it
    false = _crafted(["scene", "attr", "attr", "T", "matmul", "dict"],
                     [(0,), (Ref(0), "X"), (Ref(0), "P"), (Ref(1),), (Ref(3), Ref(2)), (("c",), (Ref(4),))], Ref(5))
    gc = GraphClaim(false)
    # a forged cache (a digest, no coordinate reads, a valid mark) is not read: the compiled graph is the tracer's
    false.cache.update(digest="0" * 64, valid=True, sides=None, program=[])
    h = compile_claim(gc, 3, 2, CONS)
    assert h is not false and h.digest() != "0" * 64 and not h.cache.get("program")
    def written(s):
        X, P = s.X, s.P
        return {"c": X.T @ P}
    assert h.digest() == trace(written, None, None, CONS).digest()
    verdicts = _verdicts(gc)
    assert verdicts == _verdicts(written)
    assert {v for _, v in verdicts} == {"fails", "undecided"}


@pytest.mark.parametrize("ops,args,output,why,written", [
    # an ill-typed sum X + Xᵀ (n x r and r x n): refused by the tracer, as in claim code
    (["scene", "attr", "T", "add", "dict"], [(0,), (Ref(0), "X"), (Ref(1),), (Ref(1), Ref(2)), (("c",), (Ref(3),))],
     Ref(4), "spaces do not match", lambda s: {"c": s.X + s.X.T}),
    # an op outside the IR
    (["scene", "attr", "evil", "dict"], [(0,), (Ref(0), "X"), (Ref(1),), (("c",), (Ref(2),))], Ref(3), "outside the IR",
     None),
    # a private attribute of the scene (the trace behind it)
    (["scene", "attr", "dict"], [(0,), (Ref(0), "_t"), (("c",), (Ref(1),))], Ref(2), "public", None),
    # a reference to a later node (a cycle)
    (["scene", "neg", "dict"], [(0,), (Ref(1),), (("c",), (Ref(1),))], Ref(2), "not an earlier node", None),
    # an engine object that is not registered
    (["scene", "prim", "dict"], [(0,), (Named("os.system"), "true"), (("c",), (Ref(1),))], Ref(2), "not registered",
     None),
    # a float constant
    (["scene", "attr", "mul", "dict"], [(0,), (Ref(0), "X"), (Ref(1), 0.5), (("c",), (Ref(2),))], Ref(3),
     "not a value of the IR", None),
    # a name outside the scene's API
    (["scene", "attr", "dict"], [(0,), (Ref(0), "field"), (("c",), (Ref(1),))], Ref(2), "has no 'field'",
     lambda s: {"c": s.field}),
    # an eigenvalue a_i of A: it needs fixed sizes, so the graph is traced per size, as the claim written
    # in Python is (and is false: a₁ ≠ 0)
    (["scene", "attr", "item", "dict"], [(0,), (Ref(0), "a"), (Ref(1), 0), (("c",), (Ref(2),))], Ref(3),
     "eigenvalues", lambda s: {"c": s.a[0]}),
])
def test_a_crafted_graph_gets_the_verdicts_of_the_claim_it_writes(ops, args, output, why, written):
    """What the tracer refuses in a graph it refuses in claim code: the verdicts are those of the same
    claim written in Python, and with no such claim (an op outside the IR, a private name, a cycle, an
    unregistered engine object) an error under every fixed-size method, and no proof by free."""
    try:
        gc = GraphClaim(_crafted(ops, args, output))
    except ReplayError as exc:          # refused when it is handed over
        assert why in str(exc) and written is None
        return
    with pytest.raises(Exception) as info:
        compile_claim(gc, None, None, CONS)
    assert why in str(info.value)
    verdicts = _verdicts(gc)
    if written is not None:
        assert verdicts == _verdicts(written)
    else:
        assert {v for m, v in verdicts if m != "free"} == {"error"}
    assert ("free", "proved") not in verdicts and not {v for _, v in verdicts} & {"proved", "checked", "numeric"}


def test_a_graph_claims_state_changed_after_it_was_made_is_still_traced():
    """Changing a graph claim's data behind its back (object.__setattr__ on its slots) makes another claim,
    traced like the first: a forward reference there is refused when it is replayed."""
    g = trace(lambda s: {"c": s.X.T @ s.X - s.Ir}, None, None, CONS)
    gc = GraphClaim(g)
    args = list(gc._args)
    args[1] = (Ref(len(args) - 1), "X")
    object.__setattr__(gc, "_args", tuple(args))
    with pytest.raises(Exception):
        compile_claim(gc, None, None, CONS)


def test_a_graph_claim_made_without_its_checks_replays_only_the_ops_of_the_ir():
    """A graph claim built around its constructor's checks (object.__new__, its slots set by hand) with an
    op outside the IR, or one named like a helper of the replay, is refused when it is traced."""
    g = trace(lambda s: {"c": s.X.T @ s.X - s.Ir}, None, None, CONS)
    for op in ("evil", "kwargs", "frame_of", "value"):
        gc = object.__new__(GraphClaim)
        ok = GraphClaim(g)
        for slot in GraphClaim.__slots__:
            object.__setattr__(gc, slot, getattr(ok, slot))
        ops = list(ok._ops)
        ops[2] = op
        object.__setattr__(gc, "_ops", tuple(ops))
        with pytest.raises(Exception, match="outside the IR"):
            compile_claim(gc, None, None, CONS)


def test_a_graph_claim_is_not_pickled_and_holds_no_graph_object():
    g = trace(lambda s: {"c": s.X.T @ s.X - s.Ir}, None, None, CONS)
    gc = GraphClaim(g)
    g.ops[1] = "evil"                      # the graph handed in, changed afterwards: the claim kept a copy
    assert compile_claim(gc, None, None, CONS).ops[1] != "evil"
    import pickle
    with pytest.raises(TypeError):
        pickle.dumps(gc)


# --------------------------------------------------------------------------- the command

def test_cli_mutate_on_graphs(catalog):
    res = CliRunner().invoke(mutate_command, ["invariants-so-n", "invariants-complete", "--on", "graphs",
                                              "--method", "rational", "--size", "3,2", "--limit", "4",
                                              "--jobs", "1", "--format", "json"])
    assert res.exit_code == 0, res.output
    import json
    data = json.loads(res.stdout)
    assert data["meta"]["on"] == "graphs" and "--on graphs" in data["meta"]["command"]
    by_id = {c["claim"]: c for c in data["claims"]}
    # traced per size (at the one size asked for here): mutated on its graph there
    ci = by_id["invariants-complete"]
    assert not ci["skipped"] and ci["on"] == "graphs per size" and len(ci["mutants"]) == 4
    # each at a site of the claim's source (its line), in the graph of each size
    assert all(", graphs at (3,2): " in o["description"] and o["notation"] and o["lineno"] for o in ci["mutants"])
    inv = by_id["invariants-so-n"]
    assert not inv["skipped"] and len(inv["mutants"]) == 4
    assert all(".py:" in o["description"] and o["notation"] and o["lineno"] for o in inv["mutants"])
    # the sites of the claim's own function by default; every site with --sites all (the command says so)
    assert data["meta"]["sites"] == "claim" and "--sites" not in data["meta"]["command"]
    assert inv["sites"] == ci["sites"] == "the claim's function"
    res = CliRunner().invoke(mutate_command, ["invariants-so-n", "--on", "graphs", "--sites", "all", "--method",
                                              "rational", "--size", "3,2", "--limit", "2", "--jobs", "1",
                                              "--format", "json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert data["meta"]["sites"] == "all" and "--sites all" in data["meta"]["command"]
    assert data["claims"][0]["sites"] == ""
    # the source mode has no sites to choose: refused, not ignored
    res = CliRunner().invoke(mutate_command, ["invariants-so-n", "--sites", "all", "--size", "3,2", "--jobs", "1"])
    assert res.exit_code == 2 and "--sites" in res.output
    # the source mode stays the default
    res = CliRunner().invoke(mutate_command, ["invariants-so-n", "--method", "rational", "--size", "3,2",
                                              "--limit", "2", "--jobs", "1", "--format", "json"])
    data = json.loads(res.stdout)
    assert "on" not in data["meta"] and data["claims"][0]["mutants"][0]["description"].startswith("line ")


def test_a_graph_replayed_again_is_checked_again_once_its_data_changed():
    """The checks of a graph are kept for the next replay of the same graph object (every mutant replays
    the claim's graph) only while it holds the very same objects: a node changed in place afterwards (here
    a reference to a later node) is checked again and refused."""
    g = trace(lambda s: {"c": s.X.T @ s.X - s.Ir}, None, None, CONS)
    assert compile_claim(GraphClaim(g), None, None, CONS).digest() == g.digest()
    again = GraphClaim(g)
    assert again._ops is GraphClaim(g)._ops          # the checked copy is shared
    g.args[1] = (Ref(len(g.args) - 1), "X")
    with pytest.raises(ReplayError, match="not an earlier node"):
        GraphClaim(g)
    g.args[1] = tuple(g.args[1])                     # an equal tuple, another object: checked again too
    with pytest.raises(ReplayError, match="not an earlier node"):
        GraphClaim(g)
