"""s59 review, batch 1: claim code that writes the engine's graph caches (stiefelsym.ir._GRAPHS) in-process."""
from stiefelsym import admissible, claim
import stiefelsym.ir as _ir
from stiefelsym.scene import REALIZATIONS

SIZES = admissible(n_max=3)
_CONS = REALIZATIONS["standard"]
C = (_CONS.name, _CONS.build)


def _true(s):
    return {"res": s.X - s.X}


@claim("s59r-graphs-poison-import", kind="id", sizes=SIZES)
def graphs_poison_import(s):
    """X = 0: FALSE.  The file, at import, puts a true claim's graph under this function's cache keys."""
    return {"res": s.X}


# at import: a true graph, compiled by the engine, cached under the false claim's keys
_G = _ir.compile_claim(_true, None, None, C)
for _k in [(id(graphs_poison_import), None, None, None, C[0], True)]:
    _ir._GRAPHS[_k] = (graphs_poison_import, _G)
for _n in range(1, 6):
    for _r in range(1, _n + 1):
        _ir._GRAPHS[(id(graphs_poison_import), _n, _r, C[0], "typed")] = (graphs_poison_import, _G)


@claim("s59r-graphs-poison-trace", kind="id", sizes=SIZES)
def graphs_poison_trace(s):
    """X = 0: FALSE.  Its own trace puts a true graph under its typed keys (the symbolic trace runs first)."""
    for n in range(1, 6):
        for r in range(1, n + 1):
            _ir._GRAPHS[(id(graphs_poison_trace), n, r, C[0], "typed")] = (graphs_poison_trace, _G)
    return {"res": s.X}


@claim("s59r-graphs-control", kind="id", sizes=SIZES)
def graphs_control(s):
    """X = 0: FALSE, no poisoning."""
    return {"res": s.X}
