"""The IR: claims traced once into a typed graph that every method evaluates.

claim code → :func:`.trace.trace` (tracers, no values) → :class:`.graph.Graph`
(pure data, a digest) → :mod:`.passes` → :func:`.evaluate.evaluate` on a
method's scene.  See ``docs/architecture.md``.
"""
from __future__ import annotations

from collections import OrderedDict
from typing import Callable

from .graph import Graph, Named, Ref, Size
from .statements import Count, Rank
from .trace import Dim, TraceRefused, Tracer, TraceScene, block, is_tracer, named, primitive, trace

__all__ = ["Graph", "Named", "Ref", "Size", "Count", "Rank", "Dim", "TraceRefused", "Tracer", "TraceScene",
           "block", "is_tracer", "named", "primitive", "trace", "compile_claim", "NotDeterministic"]


class NotDeterministic(ValueError):
    """Two tracings of a claim gave different graphs."""


#: graphs traced in this process, the most recent first out last: (function, n, r, realization) ->
#: graph (a run's methods, probes and passes share one graph; older graphs are dropped)
_GRAPHS: "OrderedDict[tuple, Graph]" = OrderedDict()
GRAPH_CACHE_SIZE = 24


def compile_claim(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable]) -> Graph:
    """The graph of a claim's function at (n, r) (None, None: symbolic sizes), traced twice; a claim
    whose two graphs differ is refused, and so is a claim whose trace met a refusal, even one it
    caught.  Traced once per process and size."""
    key = (func, n, r, constraints[0])
    g = _GRAPHS.get(key)
    if g is not None:
        _GRAPHS.move_to_end(key)
        return g
    first = trace(func, n, r, constraints)
    _check_refusals(first)
    second = trace(func, n, r, constraints)
    _check_refusals(second)
    if first.digest() != second.digest():
        raise NotDeterministic("the claim is not deterministic: two tracings at the same size gave "
                               "different graphs")
    _GRAPHS[key] = first
    while len(_GRAPHS) > GRAPH_CACHE_SIZE:
        _GRAPHS.popitem(last=False)
    return first


def _check_refusals(g: Graph) -> None:
    if g.refusals:
        raise TraceRefused("the claim was refused: " + "; ".join(dict.fromkeys(g.refusals))
                           + " (a refusal the claim caught still counts)")
