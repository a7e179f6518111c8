"""A mutant of a graph is traced by the tracer when it is made; its compilation takes that graph as the first
of the two traces it compares (stiefelsym.ir.first_trace) and traces the mutant once more, not twice.  The
graphs compiled are those of two traces of their own, and a first trace that is not the mutant's is refused."""
from __future__ import annotations

import pytest

import stiefelsym.ir as ir
from stiefelsym.claims import Size
from stiefelsym.ir import NotDeterministic, _clean, compile_claim
from stiefelsym.ir.mutants import MutantCensus, site_mutants
from stiefelsym.ir.trace import trace
from stiefelsym.scene import REALIZATIONS
from test_ir_mutants_sized import loops_over_r  # the claim with a loop over r

CONS = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)


def symbolic(s):
    """XᵀP + PᵀX = 0 and Φ = PXᵀ − XPᵀ skew (traced with symbolic sizes)."""
    phi = s.P @ s.X.T - s.X @ s.P.T
    return {"sym": s.X.T @ s.P + s.P.T @ s.X, "skew": phi + phi.T}


def _sited_graphs(func, sizes):
    if sizes is None:
        return {None: _clean(trace, func, None, None, CONS, None, True)}
    return {(z.n, z.r): _clean(trace, func, z.n, z.r, CONS, None, True) for z in sizes}


def _traces_of(monkeypatch, compile_all) -> int:
    count = [0]
    real = ir._clean

    def counted(f, *args):
        count[0] += 1
        return real(f, *args)
    monkeypatch.setattr(ir, "_clean", counted)
    try:
        compile_all()
    finally:
        monkeypatch.setattr(ir, "_clean", real)
    return count[0]


@pytest.mark.parametrize("func, sizes", [(symbolic, None), (loops_over_r, [Size(3, 2), Size(3, 1), Size(3, 3)])])
def test_a_mutant_is_compiled_with_its_trace_as_made_and_one_trace_more(monkeypatch, func, sizes):
    graphs = _sited_graphs(func, sizes)
    made = site_mutants(graphs, CONS, MutantCensus())
    assert len(made) >= 4
    at = [None] if sizes is None else [(z.n, z.r) for z in sizes]

    def compile_at(f):
        return lambda: [compile_claim(f, *(z or (None, None)), CONS).digest() for z in at]
    for gm in made:
        seeded, fresh = gm.func, gm.func
        gm.traced(seeded, CONS)
        with_first = _traces_of(monkeypatch, compile_at(seeded))
        without = _traces_of(monkeypatch, compile_at(fresh))
        assert compile_at(seeded)() == compile_at(fresh)()          # the same graphs
        assert with_first == without - len(gm.made), (gm.text, with_first, without)


def test_a_first_trace_that_is_not_the_mutants_is_refused():
    """Negative control: the compilation compares its one trace with the graph handed to it, so another
    mutant's graph handed as the first trace makes the compilation refuse the mutant (not deterministic)."""
    graphs = _sited_graphs(symbolic, None)
    a, b = site_mutants(graphs, CONS, MutantCensus())[:2]
    f = a.func
    ir.first_trace(f, None, None, CONS, b.made[None])
    with pytest.raises(NotDeterministic):
        compile_claim(f, None, None, CONS)


def test_a_source_mutant_of_the_catalog_is_traced_once_per_size_while_no_claims_file_is_in(monkeypatch):
    """trace_once: a function the mutation analysis made from the reviewed catalog's own source is traced once
    per size (no second trace to compare: an edit of one operator of a deterministic function adds no state);
    another function is traced twice; and once a claims file has been imported into the process (the seal),
    even a registered function is traced twice again."""
    import stiefelsym.ir.seal as seal

    def edited(s):
        return {"sym": s.X.T @ s.P - s.P.T @ s.X}

    def plain(s):
        return {"sym": s.X.T @ s.P - s.P.T @ s.X}
    ir.trace_once(edited)
    assert _traces_of(monkeypatch, lambda: compile_claim(plain, None, None, CONS)) == 2
    assert _traces_of(monkeypatch, lambda: compile_claim(edited, None, None, CONS)) == 1
    assert compile_claim(edited, None, None, CONS).digest() == compile_claim(plain, None, None, CONS).digest()

    def sealed_twin(s):
        return {"sym": s.X.T @ s.P - s.P.T @ s.X}
    ir.trace_once(sealed_twin)
    monkeypatch.setattr(seal, "sealed", lambda: True)
    assert _traces_of(monkeypatch, lambda: ir._compile(sealed_twin, None, None, CONS, cached=False)) == 3   # and the replay
