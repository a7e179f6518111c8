"""s58 batch 1: Graph.refs cached in graph.cache["refs"] (commit 02ef643), reached by claim code.

Claim code reaches the graph being traced (s._t is a slot of TraceScene, found without __getattr__:
s._t.g is the Graph) and puts a list of its own under g.cache["refs"].  The trace-time checks of an
Inverse statement (Trace._divisor/_constant, _reads_elements, same_graph) walk the graph with g.refs,
so they see the lies.  The claim uses the size door (int(s.n)) so that it is traced only at numbers
(no replay of its symbolic graph by a fresh, unpoisoned trace).  The sealed graph has an empty cache:
the methods evaluate the real graph."""
from stiefelsym import Inverse, admissible, claim

SIZES = admissible(n_max=3)


class _Refs(list):
    """refs(i): the true list, except () for a call of tr (so tr(PᵀP) looks like a constant); never
    extended by Graph.refs (its length is huge)."""
    def __init__(self, g):
        super().__init__()
        self.g = g

    def __len__(self):
        return 1 << 40

    def __getitem__(self, i):
        g = self.g
        if g.ops[i] == "call" and g.args[i][1] == "tr":
            return ()
        return tuple(g._nested(g.args[i]))


def _poison(s):
    g = s._t.g
    g.cache["refs"] = _Refs(g)


def _norm(t):
    return t.tr(t.P.T @ t.P)


@claim("s58-refs-inv-div-trace", kind="id", sizes=SIZES)
def refs_inv_div_trace(s):
    """x ↦ tr(PᵀP)·x on Sym(r), inverted by y/tr(PᵀP): FALSE (not invertible at P = 0).
    The refs cache is poisoned so that _constant(tr(PᵀP)) sees no argument of the tr call."""
    int(s.n)            # the door: traced at numbers only
    _poison(s)
    return {"inv": Inverse(lambda t, x: _norm(t) * x, lambda t, y: y / _norm(t), on="Sym(r)")}


@claim("s58-refs-inv-div-trace-control", kind="id", sizes=SIZES)
def refs_inv_div_trace_control(s):
    """Control: the same claim without the poisoning (must be refused / error)."""
    int(s.n)
    return {"inv": Inverse(lambda t, x: _norm(t) * x, lambda t, y: y / _norm(t), on="Sym(r)")}


@claim("s58-refs-inv-div-symbolic", kind="id", sizes=SIZES)
def refs_inv_div_symbolic(s):
    """The same poisoning without the door (the symbolic graph is replayed at (n, r) by an unpoisoned
    trace): FALSE."""
    _poison(s)
    return {"inv": Inverse(lambda t, x: _norm(t) * x, lambda t, y: y / _norm(t), on="Sym(r)")}
