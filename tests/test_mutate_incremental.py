"""A graph mutant evaluated incrementally at the printed claim's point (the values of the nodes whose whole
subgraph it did not change are read from the claim's evaluation, ``_node_memo``; only the cone above its
change is computed) has exactly the values of a full evaluation at that point, over Q, over a prime field
and in floating point; a key that forgets a literal breaks that (the negative control)."""
from __future__ import annotations

import random
from fractions import Fraction

import numpy as np
import pytest

from stiefelsym.analyses.mutate import graph_mutants, mutation_sizes
from stiefelsym.backends.fields import ErrNum, FloatField, ModularField, RationalField
from stiefelsym.backends.matrix import Mat
from stiefelsym.claims import load_catalog
from stiefelsym.ir import compile_claim
from stiefelsym.ir import evaluate as ev
from stiefelsym.ir.derivative import derivatives, scene_flows
from stiefelsym.scene import REALIZATIONS, Scene

#: a claim with one graph for every size (flows of a Hamiltonian, a Lax matrix), one traced per size whose
#: changes sit in a helper under a derivative, and one with a resolvent
CLAIMS = ("neumann-lax", "invariants-complete", "manakov-lax")
FIELDS = {"exact": lambda: RationalField(), "modular": lambda: ModularField(), "float": lambda: FloatField()}
SIZE = (4, 2)


def same(a, b) -> bool:
    """Equal values, entry by entry (no tolerance: the same operations on the same numbers)."""
    if type(a) is not type(b):
        return False
    if isinstance(a, Mat):
        x, y = np.asarray(a._a), np.asarray(b._a)
        return x.shape == y.shape and all(same(u, v) for u, v in zip(x.ravel().tolist(), y.ravel().tolist()))
    if type(a) is ErrNum:           # a float with its error bound: the value, the bound and the scale alike
        return (a.v, a.e, a.m, a.u) == (b.v, b.e, b.m, b.u)
    if type(a) is dict:
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if type(a) in (list, tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if type(a) in (int, float, Fraction, bool, str) or a is None:
        return a == b
    if hasattr(a, "__dict__"):
        return same(vars(a), vars(b))
    return a == b


@pytest.fixture(scope="module")
def mutants():
    reg = load_catalog()
    out = []
    for cid in CLAIMS:
        c = reg.get(cid)
        muts, why = graph_mutants(c, mutation_sizes(c))
        assert not why and muts, cid
        sample = random.Random(cid).sample(muts, min(6, len(muts)))
        out.append((c, sample))
    return out


def graph_at(claim, func):
    cons = REALIZATIONS[claim.realization]
    return compile_claim(func, SIZE[0], SIZE[1], (cons.name, cons.build))


def values(claim, muts, kind: str, shared: bool = True):
    """Per mutant: its checks evaluated on a lent copy of the printed claim's point, incrementally (with the
    printed claim's node values: ``shared``) or in full."""
    base = Scene(*SIZE, FIELDS[kind](), rng=random.Random(7))
    base._node_memo = memo = {}
    outcome(derivatives(graph_at(claim, claim.func), scene_flows(base)), base)
    assert memo
    out = []
    for m in muts:
        g = derivatives(graph_at(claim, m.func), scene_flows(base))
        lent = base._lent()
        if shared:
            lent._node_memo = dict(memo)
        out.append(outcome(g, lent))
    return out


def outcome(g, scene):
    """The value of the graph on the scene, or the error its evaluation raised (a mutant may read an entry
    its changed matrix does not have)."""
    try:
        return ev.evaluate(g, scene)
    except Exception as exc:    # noqa: BLE001 - compared like a value
        return (type(exc).__name__, str(exc))


@pytest.mark.parametrize("kind", sorted(FIELDS))
def test_an_incremental_evaluation_of_a_graph_mutant_is_the_full_evaluation(mutants, kind):
    count = 0
    for claim, muts in mutants:
        full = values(claim, muts, kind, shared=False)
        for m, incremental, whole in zip(muts, values(claim, muts, kind), full):
            assert same(incremental, whole), (claim.id, m.index, kind)
            count += 1
    assert count >= 12


def test_a_key_that_forgets_a_literal_gives_other_values(mutants, monkeypatch):
    """The negative control: node keys that leave out the literal arguments (the attribute or the entry
    read, the constant) make a mutant read the claim's value of another node, and the values differ."""
    full = [values(claim, muts, "modular", shared=False) for claim, muts in mutants]
    real = ev.node_keys

    def forgetful(g):
        keys = g.cache.get("forgetful")
        if keys is None:
            h = ev.Graph()
            h.ops = list(g.ops)
            h.args = [tuple(x for x in a if type(x) is ev.Ref) for a in g.args]
            keys = g.cache["forgetful"] = real(h)
        return keys
    monkeypatch.setattr(ev, "node_keys", forgetful)
    differ = 0
    for (claim, muts), whole in zip(mutants, full):
        differ += sum(not same(x, y) for x, y in zip(values(claim, muts, "modular"), whole))
    assert differ
