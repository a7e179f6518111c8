"""A claims file whose claim function is the engine's GraphClaim with an edit of its own: the edit is run while
the graph is replayed, after the first statement's checks, and points that inverse's division by 2 at
tr(PᵀP) (the route of rewrite_after_check.py, through a replay instead of the claim's code; stop 59)."""
from stiefelsym import Inverse, admissible, claim
from stiefelsym.ir import compile_claim
from stiefelsym.ir.graph import Ref
from stiefelsym.ir.replay import GraphClaim
from stiefelsym.scene import REALIZATIONS

SIZES = admissible(n_max=3)
_C = (REALIZATIONS["standard"].name, REALIZATIONS["standard"].build)


def _norm(t):
    return t.tr(t.P.T @ t.P)


def _inv(t, y):
    _norm(t)
    return y / 2


def _honest(s):
    return {"a": Inverse(lambda t, x: _norm(t) * x, _inv, on="Sym(r)"),
            "b": Inverse(lambda t, x: 3 * x, lambda t, y: y / 3, on="Sym(r)")}


_G = compile_claim(_honest, 3, 2, _C)
_B = next(i for i, op in enumerate(_G.ops) if op == "inverse" and i > min(k for k, o in enumerate(_G.ops) if o == "inverse"))


def _edit(rp, args, frame):
    g = rp.scene._t.g
    for i, (op, a) in enumerate(zip(g.ops, g.args)):
        if op == "div" and a[-1] == 2:
            tr = max(k for k in range(i) if g.ops[k] == "call" and g.args[k][1] == "tr")
            g.args[i] = a[:-1] + (Ref(tr),)
    from stiefelsym.ir.replay import _DISPATCH
    return _DISPATCH[rp.ops[_B]](rp, args, frame)


_F = GraphClaim(_G, {_B: _edit}, name="graph_claim_edits")
try:
    claim("s59-graph-claim-edits", kind="id", sizes=SIZES)(_F)   # registered, then fails to set _F.claim
except AttributeError:
    pass
