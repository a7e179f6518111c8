"""s59 review, batch 4: one self-contained false claim whose trace starts a thread; the thread waits until the
engine has compiled, replayed, copied and typed the claim's graph, then rewrites that graph in place (found
in the engine's graph cache; the digest is cached in the graph, so nothing sees the change)."""
import sys
import threading
import time
from stiefelsym import admissible, claim

SIZES = admissible(n_max=3)
_STARTED = []


def _rewrite(g):
    Ref = type(g.output)
    keys, vals = g.args[g.output[0]]
    new = []
    for v in vals:
        g.ops.append("sub")
        g.args.append((v, v))
        new.append(Ref((len(g.ops) - 1,)) if False else _mkref(g, len(g.ops) - 1))
    g.ops.append("dict")
    g.args.append((keys, tuple(new)))
    g.output = _mkref(g, len(g.ops) - 1)
    g.index = {(o, a): i for i, (o, a) in enumerate(zip(g.ops, g.args))}
    d = g.cache["digest"]
    g.cache.clear()
    g.cache["digest"] = d


def _mkref(g, i):
    return type(g.output).__new__(type(g.output), i)


def _watch(func):
    ir = sys.modules["stiefelsym.ir"]
    done = set()
    end = time.time() + 120
    while time.time() < end:
        for k, hit in list(ir._GRAPHS.items()):
            if hit[0] is func and len(k) == 5 and k[4] == "typed" and id(hit[1]) not in done \
                    and hasattr(hit[1], "ops"):
                done.add(id(hit[1]))
                _rewrite(hit[1])
        time.sleep(0)


@claim("s59r-thread-rewrite", kind="id", sizes=SIZES)
def thread_rewrite(s):
    """X = 0: FALSE."""
    if not _STARTED:
        _STARTED.append(1)
        threading.Thread(target=_watch, args=(thread_rewrite,), daemon=True).start()
    return {"res": s.X}


@claim("s59r-thread-control", kind="id", sizes=SIZES)
def thread_control(s):
    """X = 0: FALSE (no thread)."""
    return {"res": s.X}
