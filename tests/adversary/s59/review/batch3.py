"""s59 review, batch 3: a user's claim whose code, run in-process after the paper's catalog is loaded,
rewrites the compiled graphs of two catalog claims (reached through the public stiefelsym.ir.compile_claim,
which hands back the cached graph object; its digest is cached in it, so nothing sees the change)."""
from stiefelsym import admissible, claim
from stiefelsym.ir import compile_claim
from stiefelsym.ir.graph import Ref
from stiefelsym.scene import REALIZATIONS
import sys

SIZES = admissible(n_max=3)
_CONS = REALIZATIONS["standard"]
C = (_CONS.name, _CONS.build)


def _repoint(g, value_of):
    """The output dict's values replaced by value_of(g, old value); the methods' memos of the old graph
    dropped, its digest kept."""
    keys, vals = g.args[g.output[0]]
    new = tuple(value_of(g, v) for v in vals)
    g.ops.append("dict")
    g.args.append((keys, new))
    g.output = Ref(len(g.ops) - 1)
    g.index = {(o, a): i for i, (o, a) in enumerate(zip(g.ops, g.args))}
    d = g.cache["digest"]
    g.cache.clear()
    g.cache["digest"] = d


def _to_zero(g, v):
    g.ops.append("sub")
    g.args.append((v, v))
    return Ref(len(g.ops) - 1)


def _to_x(g, v):
    return Ref(next(i for i, (o, a) in enumerate(zip(g.ops, g.args)) if o == "attr" and a[1] == "X"))


_DONE = set()


@claim("s59r-catalog-mutator", kind="id", sizes=SIZES)
def catalog_mutator(s):
    """X - X = 0: TRUE.  Its code rewrites two catalog claims' compiled graphs at (3,2)."""
    # the catalog's functions as the caller loaded them (its modules in sys.modules; not reloaded)
    funcs = {getattr(v, "claim").id: v for name, mod in list(sys.modules.items())
             if name.startswith("stiefelsym.proofs.") for v in list(vars(mod).values())
             if callable(v) and hasattr(v, "claim") and hasattr(getattr(v, "claim"), "id")}
    for cid, how in (("invariants-so-n", _to_x), ("gram-not-in-involution-with-psi", _to_zero)):
        f = funcs.get(cid)
        if f is None:
            continue
        for nr in [(3, 2), (None, None)]:
            try:
                g = compile_claim(f, *nr, C)
            except Exception:
                continue
            if id(g) not in _DONE:
                _DONE.add(id(g))
                _repoint(g, how)
    return {"zero": s.X - s.X}
