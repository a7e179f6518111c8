"""A graph as a claim: :class:`GraphClaim` replays a graph's nodes on the scene it is traced with.

A graph (a mutant of a claim's graph, a correction) becomes a claim function that
the tracer traces like any other: it performs, node by node and in the graph's
order, the operation the node records (``s.X``, ``a @ b``, ``M.T``,
``s.resolvent(mu)``, an engine step, a block matrix, ...) on the tracers the
trace hands it, and returns the graph's checks.  No claim code runs: the replay
is engine code whose only input is data.  The graph a method evaluates is the
tracer's output, never the object handed in, so a graph passes the same door as
claim code: the tracer checks every type, refuses what it refuses, numbers and
shares the nodes itself and computes the digest; :func:`~stiefelsym.ir.compile_claim`
traces it twice and compares.  The replay does only what claim code could do
through the documented API (attributes and methods of the scene that are in it,
the matrix algebra, registered engine steps and constants, ``Rank`` and
``Count``), and refuses a graph that is not in the order a trace makes (a
reference to a later node), an op outside the IR, or a private name.  A graph
handed in is therefore no stronger than the claim code that would have built it.

An ``edit`` (used by :mod:`.mutants`) replaces the value of one node by a
function of the replayed values of that node's arguments: the mutant's graph is
what the tracer makes of the edited replay (an ill-typed edit is refused there).

:class:`SizedGraphClaim` makes the graphs of a claim traced per size (one graph at
each size it runs at) one claim function: at a size it replays that size's graph;
it reads the size through the tracer's door of a size's number, so with symbolic
sizes it is refused, as claim code that reads its sizes is.
"""
from __future__ import annotations

import importlib
import inspect
import operator
import sys
from collections import OrderedDict
from fractions import Fraction
from typing import Any, Callable

from stiefelsym.ir.graph import Graph, Named, Ref, Size
from stiefelsym.ir.statements import Count, Inverse, Rank, RightInverse
from stiefelsym.ir.trace import INVERSE_ELEMENTS, TraceRefused, _NAMED, block

#: the ops a graph may hold (:mod:`.graph`)
OPS = frozenset("""scene param attr call prim apply add sub neg matmul mul div pow T inv trace entry item block
    list tuple dict kw fn const rank count inverse right_inverse""".split())


class ReplayError(TraceRefused):
    """A graph that no trace makes (an op outside the IR, a private name, a reference forward)."""


def _registered(qualname: str) -> Any:
    """The engine object a graph names.  Its module registers it when imported: a module of the engine's steps
    not imported yet in this process (stiefelsym.twisted, say) is imported first, and only one of the fixed
    list :data:`stiefelsym.ir.seal.STEP_MODULES` is (a module file that appeared on disk since the package was
    digested is never imported here, whatever a graph names)."""
    for attempt in range(2):
        for qual, obj in list(_NAMED.values()):
            if qual == qualname:
                return obj
        if attempt == 0:
            from stiefelsym.ir.seal import engine_module_of
            module = engine_module_of(qualname)
            if module is None or module in sys.modules:
                break
            importlib.import_module(module)
    raise ReplayError(f"refused: an engine object that is not registered: {qualname!r}")


def _check_graph(ops: tuple, args: tuple, output: Any) -> None:
    """Every node refers to earlier nodes only (the order of a trace), its op is one of the IR's, and its
    names are public; the output is a ``dict`` node."""
    def refs(a: Any, i: int) -> None:
        t = type(a)
        if t is Ref:
            if not 0 <= a.i < i:
                raise ReplayError(f"refused: node {i} refers to node {a.i}, which is not an earlier node")
        elif t is tuple:
            for x in a:
                refs(x, i)
        elif t is Size:
            if a.d not in ("n", "r") or type(a.k) is not int or a.k < 1:
                raise ReplayError(f"refused: a size {a!r} outside the IR")
        elif not (t in (int, Fraction, str, bool, Named) or a is None):
            raise ReplayError(f"refused: a {t.__name__} is not a value of the IR")
    if len(ops) != len(args):
        raise ReplayError("refused: a graph whose ops and arguments differ in number")
    for i, (op, a) in enumerate(zip(ops, args)):
        if type(op) is not str or op not in OPS:
            raise ReplayError(f"refused: an op outside the IR: {op!r}")
        if type(a) is not tuple:
            raise ReplayError(f"refused: the arguments of node {i} are not a tuple")
        refs(a, i)
        if op in ("attr", "call") and (len(a) < 2 or type(a[1]) is not str or a[1].startswith("_")):
            raise ReplayError(f"refused: node {i} names no public attribute")
    if type(output) is not Ref or not 0 <= output.i < len(ops) or ops[output.i] != "dict":
        raise ReplayError("refused: the output of a graph is a dict node of it")


def _spans(ops: tuple, args: tuple) -> dict[int, tuple[int, int]]:
    """For each traced function k: the nodes from its scene node to its ``fn`` node (the trace made its
    body there, while the function was traced)."""
    start: dict[int, int] = {}
    out: dict[int, tuple[int, int]] = {}
    for i, (op, a) in enumerate(zip(ops, args)):
        if op == "scene" and a and type(a[0]) is int and a[0] != 0 and a[0] not in start:
            start[a[0]] = i
        elif op == "fn":
            k = a[0] if a else None
            if type(k) is not int or k not in start or k in out:
                raise ReplayError(f"refused: node {i} is a function whose scene node is not before it")
            out[k] = (start[k], i)
    if set(start) != set(out):
        raise ReplayError("refused: a function's scene node without its function")
    return out


class _Frame:
    __slots__ = ("k", "bind", "memo", "parent")

    def __init__(self, k: int, bind: dict, parent: "_Frame | None") -> None:
        self.k, self.bind, self.memo, self.parent = k, bind, {}, parent



def _value_table(pairs: list, what: str) -> Callable:
    """A function of the scene and arguments that returns the graph's value recorded for those arguments
    (known by their nodes), and refuses any other arguments: the op or inverse of a replayed statement."""
    def f(s: Any, *args: Any) -> Any:
        key = tuple(getattr(x, "_r", None) for x in args)
        for arg, value in pairs:
            if key == tuple(getattr(x, "_r", None) for x in arg):
                return value
        raise ReplayError(f"refused: {what} applied to other arguments than the graph's")
    return f

class _Replay:
    """One replay of a graph on one traced scene."""

    def __init__(self, gc: "GraphClaim", scene: Any) -> None:
        self.ops, self.args, self.spans = gc._ops, gc._args, gc._spans
        self.edits = gc._edits
        self.deps = gc._deps
        self.root = _Frame(0, {0: scene}, None)
        self.scene = scene
        self.functions: dict[int, Callable] = {}
        # the nodes inside a function's span (replayed when the function is traced, not at the top)
        self.inner = [0] * len(self.ops)
        # the values of the claim's dict (made in their order once the claim returned: see _structured)
        out = gc._output
        self.checks: frozenset[int] = frozenset()
        if out is not None and self.ops[out.i] == "dict" and len(self.args[out.i]) == 2:
            self.checks = frozenset(v.i for v in self.args[out.i][1] if type(v) is Ref)
        for k, (a, b) in self.spans.items():
            for i in range(a, b):
                self.inner[i] = max(self.inner[i], 1)

    def run(self, output: Ref) -> Any:
        self.forward(0, len(self.ops), self.root, top=True)
        return self.value(output.i, self.root)

    def forward(self, a: int, b: int, frame: _Frame, top: bool = False) -> None:
        """The nodes a ≤ i < b in order, skipping the spans of the functions traced within."""
        i = a
        while i < b:
            op = self.ops[i]
            if op == "scene" and self.args[i][0] != 0 and self.args[i][0] != frame.k:
                i = self.spans[self.args[i][0]][1]      # its fn node: the body is made when it is traced
                continue
            if op not in ("list", "tuple", "dict", "kw", "const"):   # containers: made where they are used
                self.value(i, frame)
            if top and i in self.checks and op in _STRUCTURED:
                self._structured(i, frame)
            i += 1

    def _structured(self, i: int, frame: _Frame) -> None:
        """A value of the claim's dict (a Rank or Count statement, a list of residuals, a constant) made now,
        in the graph's order: the tracer structures the dict's values in their order once the claim has
        returned, and an inverse statement's elements, made between two of them, are made in order too."""
        t = getattr(self.scene, "_t", None)
        if t is None:
            raise ReplayError("refused: a graph replayed on a scene that is not traced")
        t.structure(self.value(i, frame))

    def _frame_of(self, i: int, frame: _Frame) -> _Frame:
        deps = self.deps[i]
        f = frame
        while f.k != 0 and f.k not in deps:
            f = f.parent
        return f

    def value(self, i: int, frame: _Frame) -> Any:
        owner = self._frame_of(i, frame)
        memo = owner.memo
        if i in memo:
            return memo[i]
        edit = self.edits.get(i)
        if edit is not None:
            v = edit(self, self.args[i], frame)
        else:
            op = _DISPATCH.get(self.ops[i])
            if op is None:
                raise ReplayError(f"refused: an op outside the IR: {self.ops[i]!r}")
            v = op(self, self.args[i], frame)
        memo[i] = v
        return v

    def arg(self, a: Any, frame: _Frame) -> Any:
        t = type(a)
        if t is Ref:
            return self.value(a.i, frame)
        if t is Size:
            d = getattr(self.scene, a.d)
            return d if a.k == 1 else d * a.k
        if t is Named:
            return _registered(a.qualname)
        if t is tuple:
            return tuple(self.arg(x, frame) for x in a)
        return a

    def _kwargs(self, a: tuple, frame: _Frame) -> tuple[list, dict]:
        args, kw = list(a), {}
        if args and type(args[-1]) is Ref and self.ops[args[-1].i] == "kw":
            kw = self.value(args.pop().i, frame)
        return [self.arg(x, frame) for x in args], kw

    # -- the ops --------------------------------------------------------------------------------
    def _scene(self, a, frame):
        f = frame
        while f is not None:
            if a[0] in f.bind:
                return f.bind[a[0]]
            f = f.parent
        raise ReplayError("refused: a function's scene used outside the function")

    def _param(self, a, frame):
        f = frame
        while f is not None:
            if (a[0], a[1]) in f.bind:
                return f.bind[(a[0], a[1])]
            f = f.parent
        raise ReplayError("refused: a function's parameter used outside the function")

    def _attr(self, a, frame):
        return getattr(self.arg(a[0], frame), a[1])

    def _call(self, a, frame):
        scene, name, args = self.arg(a[0], frame), a[1], a[2]
        kw = a[3] if len(a) > 3 else ()
        if type(args) is not tuple or type(kw) is not tuple:
            raise ReplayError("refused: a call whose arguments are not a tuple")
        if name == "generic" and args and type(args[0]) is str and args[0].startswith(INVERSE_ELEMENTS):
            # an element of an Inverse statement, made again before the statement (which checks that its
            # op and inv read the elements through their arguments only)
            t = getattr(scene, "_t", None)
            if t is None:
                raise ReplayError("refused: a graph replayed on a scene that is not traced")
            t._elements = True
            try:
                return scene.generic(*args)
            finally:
                t._elements = False
        if name == "fresh":
            # a fresh element: the tracer numbers it again (the graph's number is no argument of s.fresh;
            # a graph in the order of a trace gets the same numbers)
            if len(args) != 3 or type(args[0]) is not int or kw:
                raise ReplayError("refused: a fresh element is call fresh (number, m, k)")
            return scene.fresh(*args[1:])
        return getattr(scene, name)(*[self.arg(x, frame) for x in args],
                                    **{k: self.arg(v, frame) for k, v in kw})

    def _prim(self, a, frame):
        f = self.arg(a[0], frame)
        if type(a[0]) is not Named:
            raise ReplayError("refused: an engine step that is not named")
        args, kw = self._kwargs(a[1:], frame)
        return f(*args, **kw)

    def _apply(self, a, frame):
        f = self.arg(a[0], frame)
        args, kw = self._kwargs(a[1:], frame)
        return f(*args, **kw)

    def _add(self, a, frame): return self.arg(a[0], frame) + self.arg(a[1], frame)
    def _sub(self, a, frame): return self.arg(a[0], frame) - self.arg(a[1], frame)
    def _matmul(self, a, frame): return self.arg(a[0], frame) @ self.arg(a[1], frame)
    def _mul(self, a, frame): return self.arg(a[0], frame) * self.arg(a[1], frame)
    def _div(self, a, frame): return self.arg(a[0], frame) / self.arg(a[1], frame)
    def _neg(self, a, frame): return -self.arg(a[0], frame)
    def _pow(self, a, frame): return self.arg(a[0], frame) ** a[1]
    def _T(self, a, frame): return self.arg(a[0], frame).T
    def _inv(self, a, frame): return self.arg(a[0], frame).inv()
    def _trace(self, a, frame): return self.arg(a[0], frame).trace()

    def _entry(self, a, frame):
        idx = []
        for x in a[1:]:
            if type(x) is tuple and len(x) == 4 and x[0] == "slice":
                idx.append(slice(*x[1:]))
            elif type(x) is int:
                idx.append(x)
            else:
                raise ReplayError("refused: an entry index that is not an int or a slice")
        return self.arg(a[0], frame)[tuple(idx)]

    def _item(self, a, frame):
        base, key = self.arg(a[0], frame), a[1]
        if type(key) not in (int, str):
            raise ReplayError("refused: an item key that is not an int or a string")
        return base[key]

    def _block(self, a, frame):
        rows, cols, blocks = a
        vals = [self.arg(b, frame) for b in blocks]
        if type(rows) is not int or type(cols) is not int or rows * cols != len(vals):
            raise ReplayError("refused: a block matrix whose grid does not match its blocks")
        return block([vals[r * cols:(r + 1) * cols] for r in range(rows)])

    def _list(self, a, frame): return [self.arg(x, frame) for x in a]
    def _tuple(self, a, frame): return tuple(self.arg(x, frame) for x in a)

    def _dict(self, a, frame):
        keys, vals = a
        return {k: self.arg(v, frame) for k, v in zip(keys, vals)}

    def _kw(self, a, frame):
        return {k: self.arg(v, frame) for k, v in a}

    def _const(self, a, frame):
        return a[0]

    def _rank(self, a, frame):
        return Rank(self.arg(a[0], frame), a[1], a[2], a[3], self.arg(a[4], frame) if len(a) > 4 else None)

    def _count(self, a, frame):
        return Count(*a)

    def _inverse(self, a, frame):
        """The statement again, with op and inv the graph's values: op maps inv(y) (and x) to the graph's
        op(inv(y)) (op(x)), inv maps y (and op(x)) to inv(y) (inv(op(x))), the arguments known by their
        nodes (the tracer makes y and x again, the same nodes)."""
        ys, inv_y, op_inv_y, xs, op_x, inv_op_x = (self.arg(p, frame) for p in a[:6])
        if type(a[7]) is not tuple or type(a[8]) is not str:
            raise ReplayError("refused: an inverse statement whose spaces or meaning are not literals")

        table = lambda pairs: _value_table(pairs, "an inverse statement")     # noqa: E731
        statement = Inverse(table([(inv_y, op_inv_y), (xs, op_x)]), table([(ys, inv_y), (op_x, inv_op_x)]), a[7], a[8])
        t = getattr(self.scene, "_t", None)
        if t is None:
            raise ReplayError("refused: a graph replayed on a scene that is not traced")
        t.inverse(statement)    # its node now, in the graph's order (the claim's dict finds it made)
        return statement

    def _right_inverse(self, a, frame):
        """A right inverse statement again, as :meth:`_inverse` makes an inverse statement: op maps inv(y)
        (and x) to the graph's op(inv(y)) (op(x)), inv maps y to inv(y)."""
        ys, inv_y, op_inv_y, xs, op_x = (self.arg(p, frame) for p in a[:5])
        if type(a[6]) is not tuple or type(a[7]) is not tuple or type(a[8]) is not str:
            raise ReplayError("refused: a right inverse statement whose spaces or meaning are not literals")

        table = lambda pairs: _value_table(pairs, "a right inverse statement")     # noqa: E731
        statement = RightInverse(table([(inv_y, op_inv_y), (xs, op_x)]), table([(ys, inv_y)]), a[6], a[7], a[8])
        t = getattr(self.scene, "_t", None)
        if t is None:
            raise ReplayError("refused: a graph replayed on a scene that is not traced")
        t.inverse(statement)    # its node now, in the graph's order (the claim's dict finds it made)
        return statement

    def _fn(self, a, frame):
        k, arity, body = a
        if type(arity) is not int or arity < 1:
            raise ReplayError("refused: a function of no argument")
        start, end = self.spans[k]
        rp = self

        def fn(*params: Any) -> Any:
            bind = {k: params[0]}
            for j, x in enumerate(params[1:], 1):
                bind[(k, j)] = x
            inner = _Frame(k, bind, frame)
            rp.forward(start + 1, end, inner)
            return rp.arg(body, inner)
        fn.__signature__ = inspect.Signature(            # type: ignore[attr-defined]
            [inspect.Parameter(f"x{j}", inspect.Parameter.POSITIONAL_ONLY) for j in range(arity)])
        fn.__name__ = f"replayed_function_{k}"
        return fn


#: the ops of a value of the claim's dict that the tracer makes when it structures the dict
_STRUCTURED = frozenset(("list", "tuple", "dict", "const", "rank", "count"))

#: the replay of each op of the IR (and of nothing else)
_DISPATCH: dict[str, Callable] = {op: getattr(_Replay, "_" + op) for op in OPS}


def _deps(ops: tuple, args: tuple) -> list[frozenset]:
    g = Graph()
    g.ops, g.args = list(ops), list(args)
    from stiefelsym.ir.evaluate import _deps as deps
    return deps(g)


#: the graphs replayed last, checked (:func:`_checked`): id -> (graph, its data, spans, dependencies); kept
#: here, not in the graph's cache, which whoever holds the graph can write
_CHECKED: "OrderedDict[int, tuple]" = OrderedDict()
CHECKED_CACHE_SIZE = 8


def _same(a: tuple, b: tuple) -> bool:
    return len(a) == len(b) and all(map(operator.is_, a, b))


def _checked(g: Graph) -> tuple:
    """A copy of the graph's data (ops, arguments, output), checked (:func:`_check_graph`), with its
    functions' spans and its nodes' dependencies.  Kept for the next replay of the same graph object (every
    mutant of a claim replays the claim's graph) while it holds the very same objects, else checked again."""
    ops, args, output = tuple(g.ops), tuple(g.args), g.output
    hit = _CHECKED.get(id(g))
    if hit is not None and hit[0] is g and hit[3] is output and _same(hit[1], ops) and _same(hit[2], args):
        _CHECKED.move_to_end(id(g))
        return hit[1:]
    _check_graph(ops, args, output)
    out = (ops, args, output, _spans(ops, args), _deps(ops, args))
    _CHECKED[id(g)] = (g,) + out
    while len(_CHECKED) > CHECKED_CACHE_SIZE:
        _CHECKED.popitem(last=False)
    return out


class GraphClaim:
    """A graph as a claim function: called on a traced scene, it replays the graph's nodes (with
    ``edits``: node -> replacement of its value) and returns its checks.  Holds a copy of the graph's
    data; the graph a method evaluates is the tracer's output (see the module docstring)."""

    __slots__ = ("_ops", "_args", "_output", "_spans", "_deps", "_edits", "__name__", "__qualname__")

    def __init__(self, g: Graph, edits: dict[int, Callable] | None = None, name: str = "graph") -> None:
        self._ops, self._args, self._output, self._spans, self._deps = _checked(g)
        self._edits = dict(edits or {})
        self.__name__ = self.__qualname__ = name

    def __call__(self, s: Any) -> Any:
        return _Replay(self, s).run(self._output)

    def __repr__(self) -> str:
        return f"<graph claim {self.__name__} ({len(self._ops)} nodes)>"

    def __reduce__(self):
        raise TypeError("a graph claim is not pickled (its graph is: Graph pickles)")


class SizedGraphClaim:
    """Graphs traced per size as one claim function: called on a scene traced at a fixed size (n, r), it
    replays the graph of that size (with ``edits[(n, r)]``: node -> replacement of its value), as
    :class:`GraphClaim` does.  It learns the size by the tracer's door of a size's number (``int(s.n)``),
    so traced with symbolic sizes (or on a family of sizes) it is refused and the refusal recorded, as
    claim code that reads its sizes is; at a size it has no graph for it is refused too."""

    __slots__ = ("_claims", "__name__", "__qualname__")

    def __init__(self, graphs: dict[tuple[int, int], Graph],
                 edits: dict[tuple[int, int], dict[int, Callable]] | None = None, name: str = "graphs") -> None:
        if not graphs:
            raise ReplayError("refused: no graph to replay")
        edits = edits or {}
        self._claims = {(int(n), int(r)): GraphClaim(g, edits.get((n, r)), name=name) for (n, r), g in graphs.items()}
        self.__name__ = self.__qualname__ = name

    @property
    def sizes(self) -> tuple[tuple[int, int], ...]:
        return tuple(self._claims)

    def __call__(self, s: Any) -> Any:
        size = (int(s.n), int(s.r))      # the door of the sizes' numbers: refused with symbolic sizes
        gc = self._claims.get(size)
        if gc is None:
            at = ", ".join(f"({n},{r})" for n, r in self._claims)
            raise ReplayError(f"refused: graphs traced at {at} only, none at ({size[0]},{size[1]})")
        return gc(s)

    def __repr__(self) -> str:
        at = ", ".join(f"({n},{r})" for n, r in self._claims)
        return f"<graph claim {self.__name__} (graphs at {at})>"

    def __reduce__(self):
        raise TypeError("a graph claim is not pickled (its graphs are: Graph pickles)")
