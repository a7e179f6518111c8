"""s59 review, batch 2: a later claim's code reaches an earlier claim's compiled graph through the public
stiefelsym.ir.compile_claim (it returns the cached object) and rewrites it in place; the digest is cached in
the graph, so nothing sees the change."""
from stiefelsym import admissible, claim
from stiefelsym.ir import compile_claim
from stiefelsym.ir.graph import Ref
from stiefelsym.scene import REALIZATIONS

SIZES = admissible(n_max=3)
_CONS = REALIZATIONS["standard"]
C = (_CONS.name, _CONS.build)


@claim("s59r-victim", kind="id", sizes=SIZES)
def victim(s):
    """X = 0: FALSE."""
    return {"res": s.X}


def _zero_out(g):
    # point the output's residual at X - X (a new node "sub" appended; the dict node re-pointed)
    out = g.output[0]
    keys, vals = g.args[out]
    x = vals[0]
    g.ops.append("sub")
    g.args.append((x, x))
    new = Ref(len(g.ops) - 1)
    g.ops.append("dict")
    g.args.append((keys, (new,)))
    g.output = Ref(len(g.ops) - 1)
    g.index = {(o, a): i for i, (o, a) in enumerate(zip(g.ops, g.args))}
    d = g.cache["digest"]
    g.cache.clear()             # what the methods computed of the old graph (its program) goes; the digest stays
    g.cache["digest"] = d


@claim("s59r-mutator", kind="id", sizes=SIZES)
def mutator(s):
    """X - X = 0: TRUE.  Its code rewrites the victim's compiled graphs (symbolic and at (3,2))."""
    for nr in [(3, 2), (None, None)]:
        try:
            g = compile_claim(victim, *nr, C)     # compiled (and cached) now if it was not yet
            g.digest()
            if g.ops[-1] != "dict" or g.ops[-2] != "sub":
                _zero_out(g)
        except Exception:
            pass
    return {"zero": s.X - s.X}
