"""Evaluation of a graph on an engine scene: every method's only way to run a claim.

The evaluator gives each op of :mod:`.graph` its meaning on the values of one
backend: scene attributes and methods are the engine scene's, the algebra is the
backend's matrices and numbers, a traced function becomes a closure that
evaluates its body for the scene (and arguments) the engine passes.  Values are
computed once per node and per call of the function whose parameters they read.
No claim code runs here.
"""
from __future__ import annotations

import operator
from fractions import Fraction
from typing import Any, Callable

from stiefelsym.backends.fields import DegenerateError
from stiefelsym.backends.matrix import CoordinateTracker, Mat
from stiefelsym.backends.native import backend
from stiefelsym.backends.matrix import block as _block
from stiefelsym.ir.graph import Graph, Named, Ref, Size, node_keys
from stiefelsym.ir.statements import Count, InverseIdentities, Rank, RightInverseIdentities
from stiefelsym.ir.trace import API, PRIMITIVES, VALUE_ATTRS


class GraphError(ValueError):
    """A graph that is not a trace (an op or a name outside the IR)."""


def at_node(exc: BaseException, g: Graph, i: int) -> None:
    """Name in a division error's message the node whose evaluation raised it, in the paper's notation
    (``…, at the division by tr(XᵀX) − r``): the first evaluation to see the error names it (the innermost
    node: an enclosing node's evaluation sees it with its name already given).  The text is read from the
    graph alone, so it is the same for every method and run; nothing is named where it cannot be read."""
    if getattr(exc, "node_text", None) is not None or not exc.args or type(exc.args[0]) is not str or i < 0:
        return
    texts = g.cache.setdefault("node_texts", {})
    what = texts.get(i)
    if what is None:
        what = texts[i] = _node_text(g, i)
    exc.node_text = what
    if what:
        exc.args = (f"{exc.args[0]}, at {what}",) + exc.args[1:]


def _node_text(g: Graph, i: int) -> str:
    from stiefelsym.ir.notation import render
    op, a = g.ops[i], g.args[i]
    try:
        if op == "div" and type(a[1]) is Ref:
            return f"the division by {render(g, a[1])}"
        if op == "inv" and type(a[0]) is Ref:
            return f"the inverse of {render(g, a[0])}"
        return f"the computation of {render(g, i)}"
    except Exception:  # noqa: BLE001 - a name the notation cannot give is left out, never an error of its own
        return ""


_MISSING = object()


def _deps(g: Graph) -> list[frozenset]:
    """For every node, the functions whose parameters it reads (0: the claim's scene only)."""
    cached = g.cache.get("deps")
    if cached is not None:
        return cached
    deps: list[frozenset] = []
    empty: frozenset = frozenset()
    nested = g._nested
    for op, args in zip(g.ops, g.args):
        # Graph.refs in line: most nodes read plain refs (a nested tuple is read through Graph._nested); the
        # order of ``below`` does not matter, only its entries (a union) and their number
        below = []
        for x in args:
            t = type(x)
            if t is Ref:
                dx = deps[x[0]]
                if dx:
                    below.append(dx)
            elif t is tuple:
                below += [deps[j] for j in nested(x) if deps[j]]
        if op != "scene" and op != "param" and op != "fn" and len(below) <= 1:
            deps.append(below[0] if below else empty)      # the common case: no set to build
            continue
        deps.append(_deps_of(op, args, below))
    g.cache["deps"] = deps
    return deps


def _deps_of(op: str, args: tuple, below: list[frozenset]) -> frozenset:
    """The entry of :func:`_deps` of a scene, param or fn node, or of a node that reads nodes of several
    functions (``below``: the nonempty entries of the nodes it reads)."""
    d: set = set()
    if op == "scene" and args[0] != 0:
        d.add(args[0])
    elif op == "param":
        d.add(args[0])
    for x in below:
        d |= x
    if op == "fn":
        d.discard(args[0])
    return frozenset(d)


def _structure(g: Graph) -> tuple[list[list[int]], list[frozenset], dict[int, list[int]]]:
    """For every node the nodes it reads (:meth:`Graph.refs`) and the functions whose parameters it reads
    (:func:`_deps`), and for every node read the nodes that read it, in order (a node that reads it twice is
    there twice): one pass over the nodes, once per graph (again where the graph has grown since; the lists are
    read only).  What the program of a graph is built from (:func:`_program` and its fusions,
    :func:`release_plan`)."""
    size = len(g.ops)
    hit = g.cache.get("structure")
    if hit is not None and len(hit[0]) == size:
        return hit
    known = g.cache.get("deps")
    fresh = known is None or len(known) != size
    deps: list[frozenset] = [] if fresh else known
    refs: list[list[int]] = []
    readers: dict[int, list[int]] = {}
    nested = g._nested
    empty: frozenset = frozenset()
    for i, (op, args) in enumerate(zip(g.ops, g.args)):
        rs = nested(args)
        refs.append(rs)
        for j in rs:
            got = readers.get(j)
            if got is None:
                readers[j] = [i]
            else:
                got.append(i)
        if fresh:       # as _deps computes it
            below = [deps[j] for j in rs if deps[j]]
            if op != "scene" and op != "param" and op != "fn" and len(below) <= 1:
                deps.append(below[0] if below else empty)
            else:
                deps.append(_deps_of(op, args, below))
    if fresh:
        g.cache["deps"] = deps
    out = g.cache["structure"] = (refs, deps, readers)
    return out


#: values that are the same in every number system (never lifted)
_PLAIN = (int, Fraction, bool, str, bytes, type(None))


def _liftable(v: Any) -> bool:
    """A matrix or a number of a scene (or a list or tuple of them), as opposed to a scene, a flow,
    a function, a statement or a plain constant: what an inner scene must lift to compute with."""
    if isinstance(v, Mat):
        return True
    if isinstance(v, (list, tuple)):
        return bool(v) and all(_liftable(x) or isinstance(x, _PLAIN) for x in v) and any(_liftable(x) for x in v)
    if isinstance(v, _PLAIN) or callable(v):
        return False
    t = type(v)
    return hasattr(t, "__mul__") and hasattr(t, "__add__") and hasattr(t, "__neg__")


class _Frame:
    __slots__ = ("fn", "bind", "memo", "parent")

    def __init__(self, fn: int, bind: dict, parent: "_Frame | None") -> None:
        self.fn, self.bind, self.memo, self.parent = fn, bind, {}, parent


class Evaluator:
    """The values of one graph's nodes for one engine scene."""

    def __init__(self, g: Graph, scene: Any) -> None:
        self.g = g
        if not g.cache.get("valid"):
            bad = set(g.ops) - set(self._ops)
            if bad:
                raise GraphError(f"ops outside the IR: {', '.join(sorted(bad))}")
            g.cache["valid"] = True
        self.refs, self.deps, _ = _structure(g)
        self.root = _Frame(0, {0: scene}, None)

    def run(self) -> Any:
        if self.g.output is None:
            raise GraphError("the graph has no output")
        memo = self.root.memo
        shared = getattr(self.root.bind[0], "_node_memo", None)
        if shared is None:
            scene = self.root.bind[0]
            forgets = _forgets(scene)
            prog = _program(self.g, self.deps, fused=_fuses(scene))
            plan = release_plan(self.g, prog) if forgets else None
            if plan is None:
                i = -1
                try:
                    for i, kernel in prog:
                        memo[i] = kernel(memo, self)
                except (ZeroDivisionError, DegenerateError) as exc:
                    at_node(exc, self.g, i)
                    raise
                return memo[self.g.output.i]
            # every value goes once the last node that reads it is computed: its arrays are
            # reused by the nodes after it instead of all living to the end of the evaluation
            # (the native matrices a value held when it was computed: a matrix may change its
            # storage later, and only what was counted is uncounted)
            live: dict[int, int] = {}
            held: dict[int, tuple] = {}
            for (i, kernel), dead in zip(prog, plan):
                try:
                    v = memo[i] = kernel(memo, self)
                except (ZeroDivisionError, DegenerateError) as exc:
                    at_node(exc, self.g, i)
                    raise
                xs = held[i] = _natives(v)
                for x, _f in xs:
                    live[id(x)] = live.get(id(x), 0) + 1
                for j in dead:
                    del memo[j]
                    for x, f in held.pop(j):
                        k = id(x)
                        c = live[k] - 1
                        if c:
                            live[k] = c
                        else:
                            del live[k]
                            _forget(x, f, live)
            return memo[self.g.output.i]
        # values shared with other graphs evaluated on this very point, by the structure of the
        # node's whole subgraph (the mutation analysis: a mutant recomputes only what it changed)
        # Each shared value keeps the looks at coordinates (and refusals) its computation recorded, in
        # order and repeats included, and a graph that takes the value records them again: the record
        # of the scene is the one a computation of every node would give (the exact method decides its
        # chart from it)
        keys = node_keys(self.g)
        ops = self.g.ops
        tracker = getattr(self.root.bind[0], "_tracker", None)
        if type(tracker) is not CoordinateTracker:
            tracker = None
        for i, kernel in _program(self.g, self.deps, fused=_fuses(self.root.bind[0])):
            if ops[i] in UNSHARED:
                memo[i] = kernel(memo, self)
                continue
            k = keys[i]
            hit = shared.get(k, _MISSING)
            if hit is _MISSING:
                try:
                    v, log = _recorded(tracker, lambda: kernel(memo, self))
                except (ZeroDivisionError, DegenerateError) as exc:
                    at_node(exc, self.g, i)
                    raise
                if shareable(v):
                    shared[k] = (v, log)
            else:
                v, log = hit
                if log and tracker is not None:
                    tracker.replay(log)
            memo[i] = v
        return memo[self.g.output.i]

    # -- values -----------------------------------------------------------------------------------
    def _memo(self, i: int, frame: _Frame) -> dict:
        """The memo of the frame that owns node i: the innermost enclosing call whose parameters it
        reads (the root for a node that reads none)."""
        return self._owner(i, frame).memo

    def _owner(self, i: int, frame: _Frame) -> _Frame:
        """The frame that owns node i (see :meth:`_memo`): node i is computed there."""
        deps = self.deps[i]
        if not deps:
            return self.root
        owner = frame
        while owner.fn != 0 and owner.fn not in deps:
            owner = owner.parent
        return owner

    def value(self, ref: Ref, frame: _Frame) -> Any:
        i = ref[0]
        # a node that reads no function's parameter is the root's (:meth:`_owner`), without the call
        memo = self._memo(i, frame) if self.deps[i] else self.root.memo
        v = memo.get(i, _MISSING)
        if v is not _MISSING:
            return v if memo is frame.memo or frame.fn == 0 else self._outer(v, memo, frame)
        # the nodes below i first, with an explicit stack (a body may be a chain of thousands of
        # nodes: a sum over a basis at n = 7), then i; a traced function's body waits for its calls
        ops, args, g = self.g.ops, self.g.args, self.g
        stack = [i]
        while stack:
            j = stack[-1]
            fj = self._owner(j, frame)
            mj = fj.memo
            if j in mj:
                stack.pop()
                continue
            if ops[j] != "fn":
                pending = [k for k in self.refs[j] if k not in self._memo(k, frame)]
                if pending:
                    stack.extend(pending)
                    continue
            # computed in the frame that owns it: a node read from an enclosing frame is that frame's
            # value, never one computed from values lifted into an inner function's scene
            try:
                mj[j] = self._ops[ops[j]](self, args[j], fj)
            except (ZeroDivisionError, DegenerateError) as exc:
                at_node(exc, g, j)
                raise
            stack.pop()
        v = memo[i]
        return v if memo is frame.memo or frame.fn == 0 else self._outer(v, memo, frame)

    @staticmethod
    def _outer(v: Any, memo: dict, frame: _Frame) -> Any:
        """A matrix a function's body reads from an enclosing frame (a matrix the claim built outside
        the function it hands to the scene), lifted into the function's scene when that scene is the
        enclosing scene's lift (the reverse numbers of a gradient, the duals of a derivative the scene
        computes): a constant there, as the graph's own derivatives take it.  Without the lift the
        scene's gradient met a matrix of another number system (a TypeError)."""
        if not _liftable(v):
            return v
        inner = frame.bind.get(frame.fn)
        if getattr(type(inner), "_lift_primitive", None) is None:
            return v
        owner = frame.parent
        while owner is not None and owner.memo is not memo:
            owner = owner.parent
        if owner is None:
            return v
        home = owner.bind.get(owner.fn)
        # the scenes from the function's own up to (not including) the one the value was computed on: the value
        # is lifted once per level, from the outermost in (a value of a scene two levels up lifted once, or not at
        # all, kept the ε of its own level, which the inner level's numbers took for theirs: review F2)
        chain, sc = [], inner
        while sc is not home and sc is not None:
            chain.append(sc)
            sc = getattr(sc, "base", None)
        if sc is None:
            if getattr(inner, "_field", None) is getattr(home, "_field", None):
                return v
            raise TypeError("a value computed on a scene that does not enclose the function reading it (a "
                            "derivative or gradient taken on another scene inside a function): its numbers are "
                            "of another level")
        for sc in reversed(chain):
            lift = getattr(type(sc), "_lift_primitive", None)
            if lift is not None:
                v = lift(sc, v, None)
            elif getattr(sc, "_field", None) is not getattr(getattr(sc, "base", None), "_field", None):
                raise TypeError("a value of an enclosing scene read through a scene that cannot lift it")
        return v


    def arg(self, a: Any, frame: _Frame) -> Any:
        t = type(a)
        if t is Ref:
            return self.value(a, frame)
        if t is Size:
            scene = self.root.bind[0]
            return a.k * getattr(scene, a.d) if a.k != 1 else getattr(scene, a.d)
        if t is Named:
            f = PRIMITIVES.get(a.qualname)
            if f is None:
                raise GraphError(f"unknown engine object {a.qualname!r}")
            return f
        if t is tuple:
            return tuple(self.arg(x, frame) for x in a)
        return a

    def _kw(self, a: tuple, frame: _Frame) -> tuple[list, dict]:
        args, kw = list(a), {}
        if args and type(args[-1]) is Ref and self.g.ops[args[-1].i] == "kw":
            kw = {k: self.arg(v, frame) for k, v in self.g.args[args.pop().i]}
        return [self.arg(x, frame) for x in args], kw

    def _lookup(self, key: Any, frame: _Frame) -> Any:
        f = frame
        while f is not None:
            if key in f.bind:
                return f.bind[key]
            f = f.parent
        raise GraphError(f"an unbound parameter {key!r}")

    # -- the ops ------------------------------------------------------------------------------------
    def _attr(self, a, frame):
        obj, name = self.arg(a[0], frame), a[1]
        if name not in API and name not in VALUE_ATTRS:
            raise GraphError(f"an attribute outside the API: {name!r}")
        return getattr(obj, name)

    def _call(self, a, frame):
        scene, name, args, kw = a
        if name not in API:
            raise GraphError(f"a scene method outside the API: {name!r}")
        method = getattr(self.arg(scene, frame), name)
        return method(*[self.arg(x, frame) for x in args], **{k: self.arg(v, frame) for k, v in kw})

    def _entry(self, a, frame):
        M = self.arg(a[0], frame)
        return M[tuple(slice(*x[1:]) if type(x) is tuple else x for x in a[1:])]

    def _prim(self, a, frame):
        f = self.arg(a[0], frame)
        args, kw = self._kw(a[1:], frame)
        return f(*args, **kw)

    def _block(self, a, frame):
        rows, cols, blocks = a
        vals = [self.arg(b, frame) for b in blocks]
        return _block([vals[r * cols:(r + 1) * cols] for r in range(rows)])

    def _binary(f):
        def op(self, a, frame):
            x, y = self.arg(a[0], frame), self.arg(a[1], frame)
            if type(x) is Fraction or type(y) is Fraction:
                x, y = _fractions(self, x, y)
            return f(x, y)
        return op

    _ops: dict = {
        "add": _binary(operator.add), "sub": _binary(operator.sub), "matmul": _binary(operator.matmul),
        "mul": _binary(operator.mul), "div": _binary(operator.truediv),
        "neg": lambda self, a, frame: -self.arg(a[0], frame),
        "T": lambda self, a, frame: self.arg(a[0], frame).T,
        "inv": lambda self, a, frame: self.arg(a[0], frame).inv(),
        "trace": lambda self, a, frame: self.arg(a[0], frame).trace(),
        "pow": lambda self, a, frame: _power(self.arg(a[0], frame), a[1]),
        "attr": _attr, "call": _call, "entry": _entry, "prim": _prim, "apply": _prim, "block": _block,
        "item": lambda self, a, frame: self.arg(a[0], frame)[a[1]],
        "scene": lambda self, a, frame: self._lookup(a[0], frame),
        "param": lambda self, a, frame: self._lookup((a[0], a[1]), frame),
        "fn": lambda self, a, frame: self._function(a, frame),
        "list": lambda self, a, frame: [self.arg(x, frame) for x in a],
        "tuple": lambda self, a, frame: tuple(self.arg(x, frame) for x in a),
        "dict": lambda self, a, frame: {k: self.arg(v, frame) for k, v in zip(a[0], a[1])},
        "const": lambda self, a, frame: a[0],
        "kw": lambda self, a, frame: {k: self.arg(v, frame) for k, v in a},
        "rank": lambda self, a, frame: _rank(self.arg(a[0], frame), a[1], a[2], a[3],
                                             self.arg(a[4], frame) if len(a) > 4 else None),
        "count": lambda self, a, frame: Count(a[0], a[1], a[2]),
        "inverse": lambda self, a, frame: InverseIdentities(self.arg(a[6], frame), a[7], a[8]),
        "right_inverse": lambda self, a, frame: RightInverseIdentities(self.arg(a[5], frame), a[6], a[7], a[8]),
    }
    del _binary

    def compute(self, i: int, frame: _Frame) -> Any:
        op = self.g.ops[i]
        f = self._ops.get(op)
        if f is None:
            raise GraphError(f"an op outside the IR: {op!r}")
        return f(self, self.g.args[i], frame)

    def _function(self, a: tuple, frame: _Frame) -> Any:
        k, arity, body = a

        def fn(*args: Any) -> Any:
            if len(args) != arity:
                raise TypeError(f"a traced function of {arity} arguments called with {len(args)}")
            bind = {k: args[0]}
            for j, x in enumerate(args[1:], 1):
                bind[(k, j)] = x
            return self.arg(body, _Frame(k, bind, frame))
        fn.__name__ = f"traced_function_{k}"
        return fn


#: ops whose values are never shared between graphs: the scene itself and a function's parameters
#: (bound per evaluation), containers (cheap to rebuild, and mutable), traced functions (closures
#: over their own evaluation) and the rank, count, inverse and right inverse statements
UNSHARED = frozenset({"list", "tuple", "dict", "kw", "fn", "rank", "count", "inverse", "right_inverse", "scene",
                      "param"})


def shareable(v: Any) -> bool:
    """Whether a node's value may be read by another graph's evaluation: a value, not an object that
    builds and keeps things lazily (a scene of its own, e.g. at another point of T*V) or that acts
    (an operator the engine handed out), whose later use by one graph would be seen by the next."""
    if callable(v) or hasattr(v, "_cache"):
        return False
    if type(v) in (tuple, list):
        return all(shareable(x) for x in v)
    if type(v) is dict:
        return all(shareable(x) for x in v.values())
    return True


def _rank(matrix: Any, expected: int, generic: bool, meaning: str, kernel: Any) -> Rank:
    """A rank statement as the methods evaluate it.  Its kernel must be a matrix with as many rows as
    the matrix has columns: the trace refuses any other where it knows the kind and the sizes, and a
    graph traced with symbolic sizes (or a value of unknown kind, a flow) is known only here, where
    every method refuses it alike (an error, not a certificate some methods drop and others crash on)."""
    if kernel is not None and isinstance(matrix, Mat):
        if not isinstance(kernel, Mat):
            raise TypeError(f"Rank: the kernel must be a matrix of the scene (its columns the kernel vectors), "
                            f"not {type(kernel).__name__}")
        rows, cols = kernel._shape()[0], matrix._shape()[1]
        if rows != cols:
            raise TypeError(f"Rank: the kernel has {rows} rows and the matrix {cols} columns "
                            f"(the kernel's columns are vectors v with M v = 0)")
    return Rank(matrix, expected, generic, meaning, kernel)


def _power(x: Any, k: int) -> Any:
    """x^k by products (square and multiply; a negative k: the reciprocal), the same on every number
    system whether or not it has a power of its own."""
    if k < 0:
        return 1 / _power(x, -k)
    if k == 0:
        return x * 0 + 1
    acc, base = None, x
    while k:
        if k & 1:
            acc = base if acc is None else acc * base
        k >>= 1
        if k:
            base = base * base
    return acc


def _kernel(op: str, a: tuple) -> Callable:
    """The computation of one node at the top level from the values of its arguments (``m``: the
    values so far, by node)."""
    f = _ARITH.get(op)
    if f is not None:
        x, y = a
        if type(x) is Ref and type(y) is Ref:
            i, j = x.i, y.i
            if op == "mul":
                return lambda m, ev: _scale(m[i], m[j])
            return lambda m, ev: f(m[i], m[j])
        if type(x) is Ref and type(y) is int:
            i = x.i
            return lambda m, ev: f(m[i], y)
        if type(y) is Ref and type(x) is int:
            j = y.i
            return lambda m, ev: f(x, m[j])
        if type(x) is Ref and type(y) is Fraction:
            i = x.i
            return lambda m, ev: f(*_fractions(ev, m[i], y))
        if type(y) is Ref and type(x) is Fraction:
            j = y.i
            return lambda m, ev: f(*_fractions(ev, x, m[j]))
    if op == "neg" and type(a[0]) is Ref:
        i = a[0].i
        return lambda m, ev: -m[i]
    if op == "T" and type(a[0]) is Ref:
        i = a[0].i
        return lambda m, ev: m[i].T
    if op == "item" and type(a[0]) is Ref:
        i, key = a[0].i, a[1]
        return lambda m, ev: m[i][key]
    if op == "entry" and type(a[0]) is Ref and type(a[1]) is int and type(a[2]) is int:
        i, idx = a[0].i, (a[1], a[2])
        return lambda m, ev: m[i][idx]
    if op == "attr" and type(a[0]) is Ref and (a[1] in API or a[1] in VALUE_ATTRS):
        i, name = a[0].i, a[1]
        return lambda m, ev: getattr(m[i], name)
    return lambda m, ev: ev._ops[op](ev, a, ev.root)


def _fractions(ev: "Evaluator", x: Any, y: Any) -> tuple[Any, Any]:
    """The operands of an arithmetic op where one is a Fraction constant: next to a number of the scene
    (not a matrix, which converts constants itself) the constant becomes that scene's own element
    (``scene.const``), since number types such as nmod, fmpq or a symengine symbol do not mix with a
    Fraction; a whole number (Fraction(2), Fraction(1, 3) * 3) becomes the int it is, as an int constant
    is passed (every method then takes it alike: s89 h2 F1)."""
    scene = ev.root.bind[0]
    if type(x) is Fraction and type(y) is not Fraction and not isinstance(y, Mat):
        return (int(x) if x.denominator == 1 else scene.const(x)), y
    if type(y) is Fraction and type(x) is not Fraction and not isinstance(x, Mat):
        return x, (int(y) if y.denominator == 1 else scene.const(y))
    return x, y


def _scale(x: Any, y: Any) -> Any:
    """x * y; for a matrix y scaled by a number x whose own product gives way to the matrix's
    (returns NotImplemented for it, so that Python calls ``y.__rmul__(x)``), that reflected product
    at once (a symengine scalar first converts the matrix, ≈ 3 µs a product)."""
    if type(y) is Mat:
        t = type(x)
        if t in _YIELDS_TO_MAT:
            return y.__rmul__(x)
        if t.__module__.startswith("symengine") and t not in _KEEPS:
            # a symengine class: its product with a Mat converts the Mat by ``Mat._symengine_``
            # (a constant of the class) and gives way to it or not, the same for every Mat
            v = t.__mul__(x, y)
            if v is NotImplemented:
                _YIELDS_TO_MAT.add(t)
                return y.__rmul__(x)
            _KEEPS.add(t)
            return v
    return x * y


#: number types whose ``__mul__`` returns NotImplemented for every :class:`Mat` (ints and fractions
#: know no matrices; symengine classes are added when one first gives way)
_YIELDS_TO_MAT: set = {int, Fraction}
#: symengine classes whose product with a Mat did not give way (never short-cut)
_KEEPS: set = set()


_ARITH = {"add": operator.add, "sub": operator.sub, "matmul": operator.matmul, "mul": operator.mul,
          "div": operator.truediv}


def _program(g: Graph, deps: list, fused: bool = False) -> list:
    """The nodes the output needs at the top level (not inside a traced function), in order, each
    with its kernel (made once per graph).  ``fused``: the trace of a product that no other node
    reads is computed from the product's operands (:func:`_trace_products`), and the product is not
    computed."""
    name = "program_fused" if fused else "program"
    prog = g.cache.get(name)
    if prog is not None:
        return prog
    skip: dict[int, tuple] = {}
    kernels: dict[int, Callable] = {}
    if fused:
        for i, (s, x, y) in _trace_products(g, deps).items():
            skip[i], kernels[i] = (s, x, y), _trace_product_kernel(s, x, y)
        for i, (s, x, terms, kind, whole, tree) in _paired_products(g, deps).items():
            # (the factors of cancelled products too: a value that cannot be computed is an error still)
            skip[i] = (s, x) + tuple(j for _, a, b in whole for j in (a, b))
            kernels[i] = _paired_product_kernel(s, x, terms, kind, tree)
        for i, (s, words, atoms, tree) in _trace_words(g, deps, skip).items():
            skip[i], kernels[i] = (s,) + atoms, _trace_word_kernel(s, words, tree)
    refs = _structure(g)[0]
    need = set()
    stack = [g.output.i]
    while stack:
        i = stack.pop()
        if i in need or deps[i]:
            continue
        need.add(i)
        if i in skip:
            stack.extend(skip[i])
        elif g.ops[i] != "fn":
            stack.extend(refs[i])
    prog = g.cache[name] = [(i, kernels[i] if i in skip else _kernel(g.ops[i], g.args[i])) for i in sorted(need)]
    return prog


def _readers(g: Graph) -> dict[int, list[int]]:
    """For every node read by the graph's nodes, the nodes that read it (each as many times as it reads it; read
    only: :func:`_structure`)."""
    return _structure(g)[2]


def _trace_products(g: Graph, deps: list) -> dict[int, tuple[int, int, int]]:
    """{i: (scene, x, y)} for every top-level node i = tr(x @ y) whose product is read by i alone
    (not the output, not by a traced function's body, not twice): the trace needs the product's
    diagonal only."""
    ops, args = g.ops, g.args
    readers = _readers(g)
    out = {}
    top = g.output.i if g.output is not None else -1
    for i, op in enumerate(ops):
        if op != "call" or deps[i]:
            continue
        a = args[i]
        if a[1] != "tr" or a[3] or len(a[2]) != 1 or type(a[0]) is not Ref or type(a[2][0]) is not Ref:
            continue
        j = a[2][0].i
        if ops[j] != "matmul" or deps[j] or j == top or len(readers.get(j, ())) != 1:
            continue
        x, y = args[j]
        if type(x) is Ref and type(y) is Ref:
            out[i] = (a[0].i, x.i, y.i)
    return out


#: the most words (signed products of nodes) and the longest word a trace is expanded into (:func:`_trace_words`)
MAX_TRACE_WORDS = 8
MAX_WORD = 4


def _trace_words(g: Graph, deps: list, taken: dict) -> dict[int, tuple[int, tuple, tuple, tuple]]:
    """{i: (scene, words, atoms, tree)} for top-level nodes i = tr(y) not taken by the other fusions, where y is
    a sum of products of sums ... (add, sub, neg, matmul) whose nodes only y's own nodes read (not the output,
    not a traced function's body): by linearity tr(y) is a signed sum of traces of words w = x_1 ... x_k of
    the other nodes (``atoms``), k <= MAX_WORD, and by cyclicity a word is one of its rotations (so the
    words of a derivative of tr(M^3), tr(M'MM) + tr(MM'M) + tr(MMM'), are one word taken three times).  Each
    word's trace is then computed with the cheapest adjacent pair multiplied out (see
    :func:`_trace_word_kernel`): the nodes of y, the large products of a derivative M' by M among them, are
    not computed at all.  ``tree``: y's nodes (node, op, operands), in order, then ("tr", y), for their
    checks on zero matrices (:func:`_typed_on_zeros`)."""
    ops, args = g.ops, g.args
    readers = _readers(g)
    top = g.output.i if g.output is not None else -1

    def inner(j: int) -> bool:
        return ops[j] in ("add", "sub", "neg", "matmul") and not deps[j] and j != top and len(readers.get(j, ())) == 1 \
            and all(type(v) is Ref for v in args[j])

    def words(j: int, nodes: list) -> list | None:
        """The signed words of node j (a list of (sign, word)), or None beyond the bounds."""
        if not inner(j):
            return [(1, (j,))]
        nodes.append(j)
        a = [v.i for v in args[j]]
        if ops[j] == "neg":
            w = words(a[0], nodes)
            return None if w is None else [(-c, x) for c, x in w]
        left, right = words(a[0], nodes), words(a[1], nodes)
        if left is None or right is None:
            return None
        if ops[j] == "matmul":
            out = [(c * d, x + y) for c, x in left for d, y in right]
        else:
            out = left + [(-d if ops[j] == "sub" else d, y) for d, y in right]
        if len(out) > MAX_TRACE_WORDS or any(len(x) > MAX_WORD for _, x in out):
            return None
        return out

    found = {}
    for i, op in enumerate(ops):
        if op != "call" or deps[i] or i in taken:
            continue
        a = args[i]
        if a[1] != "tr" or a[3] or len(a[2]) != 1 or type(a[0]) is not Ref or type(a[2][0]) is not Ref:
            continue
        y, nodes = a[2][0].i, []
        w = words(y, nodes) if inner(y) else None
        if not w:
            continue
        merged: dict[tuple, int] = {}
        for c, x in w:
            key = min(x[k:] + x[:k] for k in range(len(x)))
            merged[key] = merged.get(key, 0) + c
        tree = tuple((k, ops[k], tuple(v.i for v in args[k])) for k in sorted(nodes)) + (("tr", y),)
        atoms = tuple(sorted({j for _, x in w for j in x}))
        found[i] = (a[0].i, tuple((c, x) for x, c in merged.items() if c), atoms, tree)
    return found


def _trace_word_kernel(s: int, words: tuple, tree: tuple) -> Callable:
    """The kernel of a trace expanded into words (see :func:`_trace_words`): y's nodes are checked on zero
    matrices first (the refusals of an ill-typed sum or product are the unfused ones), then each word's trace
    is taken: tr(x) for one node, tr(x y) from the product's diagonal, and for three or four nodes the
    adjacent pair of least product cost (``Mat._product_cost``, the term products of polynomial matrices)
    multiplied out, once per evaluation, the rest as a trace of a product."""
    nodes, last = list(tree[:-1]), tree[-1]

    def pair(m: dict, scene: Any, x: int, y: int) -> Any:
        return _once(m, ("@", x, y), lambda: m[x] @ m[y], scene)

    def cost(m: dict, x: int, y: int) -> float:
        u, v = m[x], m[y]
        return u._product_cost(v) if type(u) is Mat and type(v) is Mat else 0

    def word_trace(m: dict, scene: Any, w: tuple) -> Any:
        if len(w) == 1:
            return scene.tr(m[w[0]])
        if len(w) == 2:
            return scene.tr_product(m[w[0]], m[w[1]])
        if len(w) == 3:
            k = min(range(3), key=lambda k: cost(m, w[k], w[(k + 1) % 3]))
            return scene.tr_product(pair(m, scene, w[k], w[(k + 1) % 3]), m[w[(k + 2) % 3]])
        k = min(range(2), key=lambda k: cost(m, w[k], w[k + 1]) + cost(m, w[k + 2], w[(k + 3) % 4]))
        return scene.tr_product(pair(m, scene, w[k], w[k + 1]), pair(m, scene, w[k + 2], w[(k + 3) % 4]))

    def run(m: dict, ev: "Evaluator") -> Any:
        scene = m[s]
        _typed_on_zeros(m, scene, nodes, last)
        acc = None
        for c, w in words:
            v = word_trace(m, scene, w)
            for _ in range(abs(c)):
                acc = (v if c > 0 else -v) if acc is None else (acc + v if c > 0 else acc - v)
        return scene.q(0) if acc is None else acc
    return run


def _trace_product_kernel(s: int, x: int, y: int) -> Callable:
    """The kernel of a trace of a product of the nodes x, y (see :func:`_trace_products`)."""
    return lambda m, ev: m[s].tr_product(m[x], m[y])


def _paired_products(g: Graph, deps: list) -> dict[int, tuple[int, int, tuple, str, tuple, tuple]]:
    """{i: (scene, x, ((sign, a, b), ...), kind, whole, tree)} for top-level nodes i = <x, y> (kind "killing": the scene's
    pairing -1/2 tr(x y), symmetric in its arguments) or i = tr(x @ y) (kind "tr"; or tr(y @ x)) where y is a
    product a @ b, or a sum of (at most MAX_PAIRED_TERMS) products and their negatives, commutators among them:
    then <x, a b> = <x a, b>, and the product x a is computed instead of a b; for a commutator,
    <x, [a, b]> = <[x, a], b>; a product with its own negative in the sum (the commutator [a, a]) cancels and
    is not computed.  A Lie-Poisson bracket -<ξ, [∇f, ∇g]> of many pairs of functions so computes [ξ, ∇f] once
    per function (once per evaluation: kept with the node values) and one pairing, of n² products, per pair,
    instead of two n x n products per pair.

    The nodes of y (its sums and products) are then not computed at all, so a pairing is reassociated only when
    every node that reads a node of its y is reassociated too (or is the product x @ y a trace alone reads).
    Pairings that share nodes of y (tr(x[z, w]) and tr((x − A)[z, w]): one commutator, two traces) are decided
    together: a pairing alone with its y is reassociated (stop 55), and traces and pairings are when every
    product of their y's cancels ([z, z] = z z − z z).  The checks of the nodes of y (sizes and spaces of its
    products and sums, and of the trace or pairing itself) are made on zero matrices of the same shapes and
    spaces (``tree``), so that an ill-typed y is refused as the unfused evaluation refuses it."""
    ops, args = g.ops, g.args
    top = g.output.i if g.output is not None else -1
    readers = _readers(g)

    def flat(j: int, sign: int, out: list, inner: list) -> bool:
        """The signed products of the sum j, added to out (its nodes to inner)."""
        if deps[j] or j == top or len(out) >= MAX_PAIRED_TERMS:
            return False
        a = args[j]
        if ops[j] == "matmul":
            if type(a[0]) is not Ref or type(a[1]) is not Ref:
                return False
            out.append((sign, a[0].i, a[1].i))
            inner.append(j)
            return True
        if ops[j] in ("add", "sub") and all(type(v) is Ref for v in a):
            inner.append(j)
            return flat(a[0].i, sign, out, inner) and flat(a[1].i, sign if ops[j] == "add" else -sign, out, inner)
        if ops[j] == "neg" and type(a[0]) is Ref:
            inner.append(j)
            return flat(a[0].i, -sign, out, inner)
        return False

    def terms_of(y: int) -> tuple[tuple, list] | None:
        out: list = []
        inner: list = []
        return (tuple(out), inner) if flat(y, 1, out, inner) else None

    cands: dict[int, tuple] = {}      # i -> (scene, x, terms, kind, inner nodes, own nodes)
    for i, op in enumerate(ops):
        if op != "call" or deps[i]:
            continue
        a = args[i]
        if a[3] or type(a[0]) is not Ref:
            continue
        if a[1] == "killing" and len(a[2]) == 2:
            u, v = a[2]
            if type(u) is not Ref or type(v) is not Ref or u.i == v.i:
                continue
            pairs, own, kind, last = ((u.i, v.i), (v.i, u.i)), (i,), "killing", ("killing", u.i, v.i)
        elif a[1] == "tr" and len(a[2]) == 1 and type(a[2][0]) is Ref:
            j = a[2][0].i
            if ops[j] != "matmul" or deps[j] or j == top or len(readers.get(j, ())) != 1:
                continue
            u, v = args[j]
            if type(u) is not Ref or type(v) is not Ref:
                continue
            pairs, own, kind, last = ((u.i, v.i), (v.i, u.i)), (i, j), "tr", ("tr", j)
        else:
            continue
        for x, y in pairs:
            found = terms_of(y)
            if found is not None and x not in found[1]:
                nodes = sorted(set(found[1]) | set(own[1:]))
                tree = tuple((k, ops[k], tuple(r.i for r in args[k])) for k in nodes) + (last,)
                cands[i] = (a[0].i, x, _cancelled(found[0]), kind, found[1], own, found[0], tree)
                break
    # a pairing whose y has a node another node reads (not a pairing taken here) cannot skip that node
    while True:
        allowed = {k for c in cands.values() for k in (*c[4], *c[5])}
        drop = [i for i, c in cands.items() if any(k not in allowed for j in c[4] for k in readers.get(j, ()))]
        if not drop:
            break
        for i in drop:
            del cands[i]
    # clusters of pairings sharing a node of y; each reassociated or not as a whole
    owner: dict[int, int] = {}
    parent = {i: i for i in cands}

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for i, c in cands.items():
        for j in c[4]:
            k = owner.setdefault(j, i)
            if k != i:
                parent[find(k)] = find(i)
    clusters: dict[int, list] = {}
    for i in cands:
        clusters.setdefault(find(i), []).append(i)
    out = {}
    for members in clusters.values():
        # a pairing whose y no other node reads (stop 55), or traces and pairings whose products all cancel
        # (then nothing is multiplied at all).  Traces sharing a commutator are not reassociated otherwise:
        # fewer products are not less work where the x a have larger entries than the a b (review of stop 83:
        # a family of k matrices built from the point, 17.5 s -> 109 s at k = 10)
        if (len(members) == 1 and cands[members[0]][3] == "killing") or all(not cands[i][2] for i in members):
            for i in members:
                s, x, terms, kind, _inner, _own, whole, tree = cands[i]
                out[i] = (s, x, terms, kind, whole, tree)
    return out


def _cancelled(terms: tuple) -> tuple:
    """The signed products left when a product and its negative cancel (b a − b a, [a, a])."""
    left = list(terms)
    out = []
    while left:
        t = left.pop(0)
        neg = (-t[0], t[1], t[2])
        if neg in left:
            left.remove(neg)
        else:
            out.append(t)
    return tuple(out)


def _parts(terms: tuple) -> list[tuple[str, int, int, int]]:
    """The pairing's parts: ("[]", sign, a, b) for a product a b whose sum also holds −b a (a commutator), else
    ("@", sign, a, b)."""
    parts: list[tuple[str, int, int, int]] = []
    left = list(terms)
    while left:
        sign, a, b = left.pop(0)
        if (-sign, b, a) in left and a != b:
            left.remove((-sign, b, a))
            parts.append(("[]", sign, a, b))
        else:
            parts.append(("@", sign, a, b))
    return parts


def _once(m: dict, key: tuple, compute: Callable[[], Any], scene: Any) -> Any:
    """A value computed once per evaluation for the kernels of several nodes (kept with the node values
    under ``key``), with the looks at coordinates its computation recorded: a node that takes it again
    records them again, so that each node's record is the one its own computation gives (a node's value
    and record are shared with other graphs in the mutation analysis, :meth:`Evaluator.run`)."""
    tracker = getattr(scene, "_tracker", None)
    if type(tracker) is not CoordinateTracker:
        tracker = None
    hit = m.get(key)
    if hit is not None:
        v, log = hit
        if log and tracker is not None:
            tracker.replay(log)
        return v
    v, log = m[key] = _recorded(tracker, compute)
    return v


def _recorded(tracker: CoordinateTracker | None, compute: Callable[[], Any]) -> tuple[Any, tuple]:
    """compute(), and the looks at coordinates (and refusals) the tracker recorded meanwhile, in order (they
    are recorded as ever too: a computation inside another's is in both logs)."""
    if tracker is None:
        return compute(), ()
    outer, tracker._log = tracker._log, []
    try:
        v = compute()
    finally:
        log, tracker._log = tuple(tracker._log), outer
        if outer is not None:
            outer.extend(log)
    return v, log


#: the most signed products of a sum that a pairing is reassociated over (:func:`_paired_products`)
MAX_PAIRED_TERMS = 16


def _paired_product_kernel(s: int, x: int, terms: tuple[tuple[int, int, int], ...], kind: str = "killing",
                           tree: tuple = ()) -> Callable:
    """The kernel of a pairing (kind "killing") or a trace of a product (kind "tr") of x with a sum of signed
    products (see :func:`_paired_products`): a product a b whose sum also holds −b a is a commutator, paired as
    <[x, a], b>; any other as <x a, b>.  [x, a] and x a are computed once per evaluation.  First the nodes not
    computed (``tree``: (node, op, operands) in order, then the trace or pairing) are checked on zero matrices of
    their operands' shapes and spaces: the refusals of an ill-typed sum or product are the unfused ones."""
    parts = _parts(terms)
    nodes, last = (list(tree[:-1]), tree[-1]) if tree else ([], None)

    def run(m: dict, ev: "Evaluator") -> Any:
        scene = m[s]
        if last is not None:
            _typed_on_zeros(m, scene, nodes, last)
        pair = scene.killing if kind == "killing" else scene.tr_product
        acc = None
        for how, sign, a, b in parts:
            if how == "[]":
                xa = _once(m, ("[]", x, a), lambda: m[x] @ m[a] - m[a] @ m[x], scene)
            else:
                xa = _once(m, ("@", x, a), lambda: m[x] @ m[a], scene)
            v = pair(xa, m[b])
            acc = (v if sign > 0 else -v) if acc is None else (acc + v if sign > 0 else acc - v)
        return scene.q(0) if acc is None else acc
    return run


def _zeros_like(v: Any) -> Any:
    """A zero matrix of the shape, spaces and coordinate record of the matrix v (v itself if it is not a Mat)."""
    if type(v) is not Mat:
        return v
    m, k = v._shape()
    z = Mat.zeros(m, k, v._field, v._tags, v._tracker)
    z._coords = v._coords
    return z


def _typed_on_zeros(m: dict, scene: Any, nodes: list, last: tuple) -> None:
    """The operations of ``nodes`` ((node, op, operands), in order) and the trace or pairing ``last``, on zero
    matrices of the shapes and spaces of their operands' values in m: their checks, not their products."""
    z: dict = {}

    def get(j: int) -> Any:
        v = z.get(j)
        if v is None:
            v = z[j] = _zeros_like(m[j])
        return v
    for j, op, refs in nodes:
        z[j] = -get(refs[0]) if op == "neg" else _ARITH[op](get(refs[0]), get(refs[1]))
    if last[0] == "tr":
        scene.tr(get(last[1]))
    else:
        scene.killing(get(last[1]), get(last[2]))


def _fuses(scene: Any) -> bool:
    """Whether traces of products are computed fused on this scene: its backend offers
    ``trace_matmul`` and keeps every value to the end (no release plan), and the scene is the
    fixed-size scene (which has ``tr_product``)."""
    field = getattr(scene, "_field", None)
    if field is None or getattr(type(scene), "tr_product", None) is None:
        return False
    be = backend(field)
    return getattr(be, "trace_matmul", None) is not None and getattr(be, "forget", None) is None


def release_plan(g: Graph, prog: list) -> list | None:
    """For every step of the program, the nodes whose values no later step reads (never the
    output); None where values must stay to the end: a graph with a traced function, whose body
    may read a top-level node whenever the function is called.  A ``kw`` node's arguments are read
    by the node that takes the keywords (see :meth:`Evaluator._kw`), so they stay until it runs."""
    if "release_plan" in g.cache:
        return g.cache["release_plan"]
    ops = g.ops
    plan: list | None = None
    if not any(ops[i] == "fn" for i, _k in prog):
        refs = _structure(g)[0]
        last: dict[int, int] = {}
        for step, (i, _k) in enumerate(prog):
            for j in refs[i]:
                last[j] = step
                if ops[j] == "kw":
                    for k in refs[j]:
                        last[k] = step
        _transposes_live(g, prog, last)
        plan = [[] for _ in prog]
        out = g.output.i
        for j, step in last.items():
            if j != out:
                plan[step].append(j)
    g.cache["release_plan"] = plan
    return plan


def _transposes_live(g: Graph, prog: list, last: dict) -> None:
    """Keep a node, and the nodes it reads, up to every later node whose value is its transpose by
    structure (Tᵀ = the node T reads; (x y)ᵀ = yᵀ xᵀ, (x ± y)ᵀ = xᵀ ± yᵀ, x + y = y + x): a backend
    may find that value as the transpose of the earlier one, through what it remembers of the
    earlier node and its operands (the float backend does, see
    :meth:`.native.Float64Backend.forget`), which must not be forgotten before then."""
    ops, args = g.ops, g.args
    refs = _structure(g)[0]
    tr: dict[int, int] = {}
    seen: dict[tuple, int] = {}
    for step, (i, _k) in enumerate(prog):
        op, a = ops[i], args[i]
        if op == "T" and len(a) == 1 and type(a[0]) is Ref:
            tr.setdefault(i, a[0].i)
            tr.setdefault(a[0].i, i)
            continue
        if op not in ("matmul", "add", "sub") or len(a) != 2 or type(a[0]) is not Ref or type(a[1]) is not Ref:
            continue
        x, y = a[0].i, a[1].i
        tx, ty = tr.get(x), tr.get(y)
        if tx is not None and ty is not None:
            cands = [(op, ty, tx)] if op == "matmul" else [(op, tx, ty)] + ([(op, ty, tx)] if op == "add" else [])
            for key in cands:
                j = seen.get(key)
                if j is not None:
                    tr.setdefault(i, j)
                    tr.setdefault(j, i)
                    for k in (j, *refs[j]):
                        if last.get(k, -1) < step:
                            last[k] = step
                    break
        seen.setdefault((op, x, y), i)


def _forgets(scene: Any) -> bool:
    """Whether the backend of the scene's number system frees what it remembers of a value the
    evaluation reads no more (otherwise values are simply kept to the end: nothing to gain)."""
    field = getattr(scene, "_field", None)
    if field is None:
        return False
    return getattr(backend(field), "forget", None) is not None


def _natives(v: Any) -> tuple:
    """The matrices in native storage a node's value holds (itself, or the members of a
    container), as (native storage, field) pairs."""
    t = type(v)
    if t is Mat:
        return () if v._n is None else ((v._n, v._field),)
    if t is list or t is tuple:
        xs = v
    elif t is dict:
        xs = v.values()
    else:
        return ()
    return tuple((x._n, x._field) for x in xs if type(x) is Mat and x._n is not None)


def _forget(x: Any, field: Any, live: dict) -> None:
    """Tell the backend of a native matrix that the evaluation reads it no more (``live``: the ids
    of the native matrices it still reads; see :meth:`.native.Float64Backend.forget`); nothing for
    a backend that remembers nothing."""
    forget = getattr(field.__dict__.get("_backend"), "forget", None)
    if forget is not None:
        forget(x, live)


def evaluate(g: Graph, scene: Any) -> Any:
    """The value of a graph's output on an engine scene."""
    return Evaluator(g, scene).run()
