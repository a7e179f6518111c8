"""The IR: claims traced once into a typed graph that every method evaluates.

claim code → :func:`.trace.trace` (tracers, no values) → :class:`.graph.Graph`
(pure data, a digest) → :mod:`.passes` and :mod:`.derivative` (derivatives
along flows and gradients rewritten into ordinary nodes) →
:func:`.evaluate.evaluate` on a method's scene.  See ``docs/architecture.md``.
"""
from __future__ import annotations

import contextvars
import pickle
import threading
import weakref
from collections import OrderedDict
from typing import Any, Callable

from stiefelsym.ir.families import SizeFamily
from stiefelsym.ir.graph import Graph, Named, Ref, Size
from stiefelsym.ir.statements import Count, Inverse, Rank, RightInverse
from stiefelsym.ir.trace import Dim, TraceRefused, Tracer, TraceScene, block, is_tracer, named, primitive, trace

__all__ = ["Graph", "Named", "Ref", "Size", "SizeFamily", "Count", "Inverse", "Rank", "RightInverse", "Dim", "TraceRefused", "Tracer", "TraceScene",
           "block", "is_tracer", "named", "primitive", "trace", "compile_claim", "first_trace", "graph_pair",
           "NotDeterministic", "GraphUnavailable", "stated_families"]


class NotDeterministic(ValueError):
    """Two tracings of a claim gave different graphs."""


def recursion_text() -> str:
    """What a RecursionError met while a claim was traced means (Python's own message says neither whose frames
    nor what to do).  The engine's walks of a graph are loops (a graph of 100,000 nested sums is traced, checked,
    written and verified); what has a depth is the claim's own Python: a helper that calls itself once per term or
    per level of nesting, with the engine's tracer on top of its frames."""
    import sys
    return (f"the claim's code went deeper than Python's recursion limit ({sys.getrecursionlimit()} frames, the "
            "engine's tracer on top of the claim's own) while it was traced: an expression built by a function "
            "that calls itself once per term or level of nesting is nested too deeply for Python; build it with a "
            "loop (M = M + X in a for loop) or sum(terms, start), which the engine handles however deep")


class GraphUnavailable(ValueError):
    """No graph of the claim at the size asked for is at hand (a claims file traced in a child process at the
    sizes a run needed only): not a fault of the claim, nothing said about it at that size."""


#: graphs traced in this process, the most recent first out last: (function, n, r, realization) ->
#: graph, or the exception that refused it (a run's methods, probes and passes share one graph;
#: older graphs are dropped)
_GRAPHS: "OrderedDict[tuple, Any]" = OrderedDict()
GRAPH_CACHE_SIZE = 24
#: traces made elsewhere of a function that will be compiled (:func:`first_trace`): (function, n, r,
#: realization) -> (function, graph), each taken by the function's next compilation as its first trace
_FIRST: "OrderedDict[tuple, tuple]" = OrderedDict()
FIRST_CACHE_SIZE = 64


def first_trace(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable], g: Graph) -> None:
    """Take ``g``, a trace of ``func`` at (n, r) (None: with symbolic sizes) that the caller made (a mutant's
    graph, traced by the tracer when the mutant was made), as the first of the two traces the next
    compilation of ``func`` there compares: it traces ``func`` once more and refuses it when the digests
    differ, as with two traces of its own.  A graph with refusals is not taken."""
    if g.refusals:
        return
    _FIRST[(id(func), n, r, constraints[0])] = (func, g)
    while len(_FIRST) > FIRST_CACHE_SIZE:
        _FIRST.popitem(last=False)


#: the families of sizes a claim is stated on, declared for its functions while the engine runs the claim
#: (:func:`stated_families`): id(function) -> (function, families)
_STATED: dict[int, tuple[Callable, tuple[SizeFamily, ...]]] = {}


class stated_families:    # noqa: N801 - a context manager, named as the function it replaces
    """While the engine runs a claim stated on families of sizes (r = 1, r = 2, r = n, for every n), the
    graph of ``func`` at a size of one of them is its graph on that family (:func:`_compile`), as the graph
    with symbolic sizes is the graph at every size of a claim that has one.  ``families`` is what the
    engine read from the claim's statement (None, the whole of n >= r >= 1, is left out)."""

    __slots__ = ("func", "families", "old")

    def __init__(self, func: Callable, families: Any) -> None:
        self.func = func
        self.families = tuple(f for f in families or () if isinstance(f, SizeFamily))
        self.old: Any = None

    def __enter__(self) -> None:
        key = id(self.func)
        self.old = _STATED.get(key)
        _STATED[key] = (self.func, self.families)

    def __exit__(self, *exc: Any) -> None:
        if self.old is None:
            _STATED.pop(id(self.func), None)
        else:
            _STATED[id(self.func)] = self.old


def _family_at(func: Callable, n: int, r: int) -> SizeFamily | None:
    """The family of sizes, stated for ``func``'s claim, that (n, r) belongs to (r = n first: a size in two
    families belongs to r = n, as in the dimension-free method's union), or None."""
    hit = _STATED.get(id(func))
    if hit is None or hit[0] is not func:
        return None
    return next((f for f in sorted(hit[1], key=lambda f: f.r is not None) if f.holds(n, r)), None)


def compile_claim(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable],
                  family: SizeFamily | None = None) -> Graph:
    """The graph of a claim's function (see :func:`_compiled_graph`), as a copy of its own: changing it
    changes nothing the methods evaluate.  The engine evaluates the graph it keeps (the graph a method
    evaluates is handed to no claim code, see docs/architecture.md)."""
    return _compiled_graph(func, n, r, constraints, family).sealed()


def _compiled_graph(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable],
                    family: SizeFamily | None = None) -> Graph:
    """The graph of a claim's function: traced once with symbolic sizes when it can be (then that one
    graph is the claim at every size: every fixed-size method and the dimension-free method evaluate
    the same graph, and the claim's code never runs at a number), otherwise at (n, r).  Each graph is
    traced twice; a claim whose two graphs differ is refused, and so is a claim whose trace met a
    refusal, even one it caught.

    With a ``family`` of sizes (n = r = None): the graph traced with symbolic sizes on that family alone
    (see :mod:`.families`), for the dimension-free method's proof on the family."""
    if family is not None and (n is not None or r is not None):
        raise ValueError("a graph is compiled at a size or on a family of sizes, not both")
    g = _compile(func, n, r, constraints, family=family)
    if isinstance(g, Graph):
        return g
    raise _fresh(g)


def numbers_only(claim: Any, n: int, r: int, func: Callable | None = None) -> bool:
    """Whether the claim's graph at (n, r) has residuals that are numbers given outright (counts of integers:
    :func:`stiefelsym.ir.passes.parameter_free`), so that its exact evaluation costs nothing at any size and
    no symbolic budget applies; False where the claim does not trace here (its run says why)."""
    from stiefelsym.ir.passes import parameter_free
    from stiefelsym.scene import REALIZATIONS
    cons = REALIZATIONS.get(getattr(claim, "realization", "standard"))
    func = func or getattr(claim, "func", None)
    if cons is None or func is None:
        return False
    try:
        return parameter_free(_compiled_graph(func, n, r, (cons.name, cons.build)))
    except Exception:   # noqa: BLE001 - a claim that does not trace here: the run itself says why
        return False


def compile_at_size(func: Callable, n: int, r: int, constraints: tuple[str, Callable], twice: bool = True) -> Graph:
    """The graph traced at (n, r) itself, the claim's code running at the numbers: only to compare a
    claim's graph on a family of sizes with its graphs at the family's sizes (a claim that traces with
    plain symbolic sizes is never traced at a number, see :func:`_compile`); traced once only
    (``twice=False``) where it is only compared with a graph that was traced twice."""
    g = _compile(func, n, r, constraints, twice=twice, at_numbers=True)
    if isinstance(g, Graph):
        return g.sealed()
    raise _fresh(g)


def _compile(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable],
             twice: bool = True, family: SizeFamily | None = None, at_numbers: bool = False,
             cached: bool = True) -> Any:
    """The graph, or the exception that refused it (both cached per process), traced twice and compared
    (once where it is only compared with a graph that was: ``twice=False``).

    At a fixed size the claim is first traced with symbolic sizes: when that succeeds, its graph is the
    claim's graph at (n, r) too (once it types there: :func:`_typed_at`), and the claim is never traced at
    (n, r).  So no trace of a claim that
    has a graph for every size holds a number of a size (not in a size, a tracer, the trace's state or
    the frames of its thread): claim code that reads one by introspection reads nothing, and cannot
    give a graph at an unlisted size other than the one a proof for every n, r is about.  Only a claim
    refused with symbolic sizes (it read a size through the door of :class:`~.trace.Dim`, or asked for
    coordinates) is traced at (n, r), and it has no proof for every n, r (``at_numbers``: traced at
    (n, r) whatever, for :func:`compile_at_size`).

    ``cached=False``: nothing is read from (or kept in) this process's caches, which claim code running in
    the process can write (a claims file's tracing interpreter, :mod:`stiefelsym.run.userfile`: the file
    was imported there, and a graph it put under its own function's key would be sent as its graph)."""
    if n is not None and not at_numbers:
        free = _compile(func, None, None, constraints, cached=cached)
        if isinstance(free, Graph):
            return _typed_at(func, free, n, r, constraints, cached)
        if isinstance(free, NotDeterministic):
            # two traces with symbolic sizes disagreed: the claim is not deterministic, at every size (a trace at
            # (n, r) would only be a later call of the same code, whose graphs may agree)
            return free
        # a claim stated on a family of sizes that traces on it: that graph is its graph at each of its sizes
        # (the claim's code runs at the numbers of a size only to be compared with it: the dimension-free
        # method's proof on the family is about the graph every method evaluates at every size of it)
        fam = _family_at(func, n, r) if r is not None and cached else None
        if fam is not None:
            on_family = _compile(func, None, None, constraints, family=fam)
            if isinstance(on_family, Graph):
                return _same_at_numbers(func, on_family, n, r, constraints, fam)
    if twice and func in _ONCE:
        from stiefelsym.ir.seal import sealed
        twice = sealed()         # a mutant of the reviewed catalog, while no claims file is in the process: once
    # by identity: a callable's own __eq__ is never asked; a graph traced once is kept apart from one
    # traced twice (a trace compared with itself is no determinism check)
    key = (id(func), n, r, family, constraints[0], twice)
    for k in ((key,) if twice else (key[:-1] + (True,), key)) if cached else ():
        hit = _GRAPHS.get(k)
        if hit is not None and hit[0] is func:
            _GRAPHS.move_to_end(k)
            return hit[1]
    try:
        seeded = _FIRST.pop((id(func), n, r, constraints[0]), None) if twice and family is None and cached else None
        if seeded is not None and seeded[0] is func:
            first = seeded[1]        # traced by the caller (first_trace): the trace below is the second
        else:
            first = _clean(trace, func, n, r, constraints, family)
        _check_refusals(first)
        second = _clean(trace, func, n, r, constraints, family) if twice else first
        _check_refusals(second)
        for x in (first, second):
            x.cache.clear()        # digests from the content now (claim code can reach a trace's graph)
        # the first graph's digest is kept for the methods; the second is compared node by node, and its digest
        # is computed only where that comparison cannot tell the two texts are the same
        if first.digest() and not first.same_lines(second) and first.digest() != second.digest():
            raise NotDeterministic("the claim is not deterministic: two tracings at the same size gave "
                                   "different graphs")
        out: Any = _replayed(func, first, n, r, constraints, family, cached)
    except Exception as exc:      # noqa: BLE001 - the claim's own failure, reported by the caller
        exc._first_traceback = exc.__traceback__      # type: ignore[attr-defined]
        out = exc
    return _remember(key, func, out) if cached else out


#: the functions traced once per size instead of twice (:func:`trace_once`)
_ONCE: "weakref.WeakSet[Callable]" = weakref.WeakSet()


def trace_once(func: Callable) -> None:
    """Trace ``func`` once per size, not twice: for the mutants the mutation analysis makes of the reviewed
    catalog's own functions (one operator, leaf or constant of a function whose two traces agree, edited in its
    source: an edit that adds no state).  Honoured only while no claims file has been imported into the process
    (:func:`.seal.sealed`): a claims file's function is always traced twice, and compared."""
    _ONCE.add(func)


def _replayed(func: Callable, g: Graph, n: int | None, r: int | None, constraints: tuple[str, Callable],
              family: SizeFamily | None, cached: bool = True) -> Graph:
    """The type-checking pass: the claim's graph ``g`` replayed by the tracer (:class:`.replay.GraphClaim`:
    engine code; no code of the claim runs) where it was traced, and the replay's graph returned in its
    place once the two have the same digest.  Claim code can reach the graph it is traced into (Python
    hides nothing) and change a node, or what a trace-time check reads, after the check; the replay makes
    every node again from the final graph, with every check of the tracer, in a graph no claim code has
    seen.  A graph that is not what the tracer makes of it is refused.  A graph claim (a mutant, a claims
    file's graph) is replayed too: its edits are functions, and a claims file can make one with its own.

    The pass runs once a claims file has been imported into this process (the engine is sealed,
    :mod:`.seal`: in a claims file's tracing interpreter, or in-process through ``load_claims_file``).
    Before that, the process has run the engine's code, the reviewed catalog's and its caller's own, none
    of which is a claims file to be guarded against (the seal's rule too): the first graph is the claim's."""
    from stiefelsym.ir.replay import GraphClaim, ReplayError
    from stiefelsym.ir.seal import sealed
    if not sealed():
        return g
    # a graph of this content (its digest, computed now) replayed and checked where it was traced already:
    # that graph (a claim traced again, its graph dropped from the cache of graphs meanwhile)
    key = (g.digest(), n, r, family, constraints[0])
    hit = _VERIFIED.get(key) if cached else None
    if hit is not None:
        _VERIFIED.move_to_end(key)
        return hit
    try:
        again = _clean(trace, GraphClaim(g, name=getattr(func, "__name__", "claim")), n, r, constraints, family)
        _check_refusals(again)
    except (TraceRefused, ReplayError) as exc:
        raise TraceRefused("the claim's graph is refused when the tracer replays it (claim code changed the "
                           f"graph it was traced into?): {str(exc).removeprefix('refused: ')}") from None
    if again.digest() != key[0]:
        raise NotDeterministic("the claim's graph is not what the tracer makes of it when replayed (claim code "
                               "changed the graph it was traced into): no verdict is given")
    # pure data of its own: the replay's literals (a Fraction, a size, an engine name) are objects the
    # claim handed over or shares with other graphs; a copy through pickle holds none of them, so claim code
    # that runs later (another claim's trace, a thread) cannot change the graph a method evaluates
    out = pickle.loads(pickle.dumps(again, protocol=pickle.HIGHEST_PROTOCOL))
    if out.digest() != key[0]:
        raise NotDeterministic("the claim's graph changed while it was copied: no verdict is given")
    if cached:
        _VERIFIED[key] = out
    while len(_VERIFIED) > VERIFIED_CACHE_SIZE:
        _VERIFIED.popitem(last=False)
    return out


#: the graphs the type-checking pass replayed and copied (:func:`_replayed`), by digest and where they were
#: traced: the graph of a claim traced again with the same content is that one
_VERIFIED: "OrderedDict[tuple, Graph]" = OrderedDict()
VERIFIED_CACHE_SIZE = 64


def _typed_at(func: Callable, free: Graph, n: int, r: int, constraints: tuple[str, Callable],
              cached: bool = True) -> Any:
    """The graph of symbolic sizes ``free`` as the claim's graph at (n, r), once it types there, or the
    refusal.  A size the claim wrote as an int (s.zeros(3, 2)) cannot be told from n, r with symbolic
    sizes; at (n, r) the graph is replayed by the tracer (:class:`.replay.GraphClaim`: engine code, no code
    of the claim runs, no trace of the claim holds a number), which checks every shape with the numbers."""
    from stiefelsym.ir.replay import GraphClaim
    key = (id(func), n, r, constraints[0], "typed")
    hit = _GRAPHS.get(key) if cached else None
    if hit is not None and hit[0] is func:
        _GRAPHS.move_to_end(key)
        return hit[1]
    try:
        try:
            # the replay is engine code (no code of the claim runs): traced in this thread, in an empty
            # context as a thread of its own would give it, with no thread to start per size
            g = contextvars.Context().run(trace, GraphClaim(free, name=getattr(func, "__name__", "claim")), n, r,
                                          constraints)
            _check_refusals(g)
        except TraceRefused as exc:
            raise TraceRefused(f"the claim's graph with symbolic sizes does not type at ({n},{r}): "
                               f"{str(exc).removeprefix('refused: ')}") from None
        if g.digest() != free.digest():
            raise NotDeterministic(f"the claim's graph with symbolic sizes replays to another graph at ({n},{r})")
        out: Any = free
    except Exception as exc:      # noqa: BLE001 - reported by the caller
        exc._first_traceback = exc.__traceback__      # type: ignore[attr-defined]
        out = exc
    return _remember(key, func, out) if cached else out


def _same_at_numbers(func: Callable, on_family: Graph, n: int, r: int, constraints: tuple[str, Callable],
                     family: SizeFamily) -> Any:
    """The family's graph (``on_family``) as the claim's graph at (n, r), once the claim traced at the numbers
    of (n, r) gives the same graph (the same digest: the graph at the numbers types there, and so does the
    family's, node for node); otherwise the refusal.  A claim whose graph on its family is another computation than its graph at
    a size (it tells the two tracings apart, by introspection) has no verdict at that size, listed or not: the
    dimension-free method's proof on the family is about its graph on the family."""
    key = (id(func), n, r, constraints[0], "compared", family)
    hit = _GRAPHS.get(key)
    if hit is not None and hit[0] is func:
        _GRAPHS.move_to_end(key)
        return hit[1]
    at = _compile(func, n, r, constraints, twice=False, at_numbers=True)
    out: Any = on_family
    if not isinstance(at, Graph):
        out = NotDeterministic(f"the claim traces on its sizes {family} but not at ({n},{r}) itself: "
                               f"{type(at).__name__}: {at}")
    elif at.digest() != on_family.digest():
        out = NotDeterministic(f"the claim's graph on its sizes {family} differs from its graph traced at ({n},{r}) "
                               f"(digest {on_family.digest()[:12]} against {at.digest()[:12]}): it tells the two "
                               "tracings apart, and no verdict is given at this size")
    return _remember(key, func, out)


def _remember(key: tuple, func: Callable, out: Any) -> Any:
    """``out`` (a graph or a refusal) cached under ``key`` for ``func``, the oldest entries dropped."""
    _GRAPHS[key] = (func, out)
    while len(_GRAPHS) > GRAPH_CACHE_SIZE:
        _GRAPHS.popitem(last=False)
    return out


def _clean(f: Callable, *args: Any) -> Any:
    """f(*args) in a thread of its own: claim code traced there sees no frame of the engine's callers
    (which method asked, which command runs), only the tracing's own."""
    out: list = []

    def run() -> None:
        try:
            out.append((True, f(*args)))
        except BaseException as exc:   # noqa: BLE001 - handed back to the caller as it is
            out.append((False, exc))
    t = threading.Thread(target=run, name="stiefelsym-trace")
    t.start()
    t.join()
    ok, value = out[0]
    if not ok:
        raise value
    return value


def _fresh(exc: BaseException) -> BaseException:
    """A cached refusal, raised again with the traceback of its first raise (where in the claim it
    was refused), not with those of its earlier raises: each raise of one object appends to it."""
    return exc.with_traceback(getattr(exc, "_first_traceback", None))


def _check_refusals(g: Graph) -> None:
    if g.refusals:
        raise TraceRefused("the claim was refused: " + "; ".join(dict.fromkeys(g.refusals))
                           + " (a refusal the claim caught still counts)")


def graph_pair(printed: Callable, variant: Callable, n: int | None, r: int | None,
               constraints: tuple[str, Callable]) -> tuple[Graph, Graph] | None:
    """The graphs of a claim's function and of a variant of it (a mutant, a correction) traced the same
    way: both with symbolic sizes when both trace so, otherwise both as graphs at (n, r) (a function that
    traces with symbolic sizes has that graph there too); None when either does not trace (a refused or
    ill-typed variant).  Shared with the runs' cache."""
    a, b = _printed(printed, None, None, constraints), _compile(variant, None, None, constraints)
    if isinstance(a, Graph) and isinstance(b, Graph):
        return a, b
    if n is None:
        return None
    a, b = _printed(printed, n, r, constraints), _compile(variant, n, r, constraints)
    if isinstance(a, Graph) and isinstance(b, Graph):
        return a, b
    return None


#: the graphs of the claims as printed that variants were compared with (a mutation analysis compares
#: every mutant of a claim with one graph, which the runs' smaller cache may have dropped meanwhile)
_PRINTED: "OrderedDict[tuple, Any]" = OrderedDict()
PRINTED_CACHE_SIZE = 64


def _printed(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable]) -> Any:
    key = (id(func), n, r, constraints[0])
    hit = _PRINTED.get(key)
    if hit is not None and hit[0] is func:
        _PRINTED.move_to_end(key)
        return hit[1]
    out = _compile(func, n, r, constraints)
    _PRINTED[key] = (func, out)
    while len(_PRINTED) > PRINTED_CACHE_SIZE:
        _PRINTED.popitem(last=False)
    return out
