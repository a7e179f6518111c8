"""The IR: a typed, hash-consed DAG of the operations a claim performed on its scene.

A node is ``(op, args)``; an argument is a reference to an earlier node (``Ref``),
an allow-listed literal (``int``, ``Fraction``, ``str``, ``bool``, ``None``), a
size expression (``Size``), a named engine object (``Named``: a function or
constant of the engine, by its qualified name) or a tuple of these.  Nodes are
numbered in the order the claim made them and shared when equal (common
subexpressions are one node).  The graph holds no number of any backend: it is
pure data, the same for every method, and its digest names it.

Ops (the evaluator, :mod:`.evaluate`, gives each its meaning):

* ``scene``: the scene of a claim (arg: 0) or the scene parameter of a function
  (arg: the function's number);
* ``param``: a further parameter of a function (function, index);
* ``attr``: an attribute of the API (``X``, ``Phi``, ``lam``...) of a scene or of
  a flow (object, name);
* ``call``: a scene method of the API (scene, name, args...), with keyword
  arguments as a trailing ``("kw", ((name, value), ...))``;
* ``prim``: an engine function recorded as one step (``Named``, args...);
* ``apply``: an operator the engine handed out, applied (operator, args...);
* ``add sub neg matmul mul rmul div rdiv pow T``: the matrix and scalar algebra;
* ``entry``: an entry or a block of a matrix (matrix, i, j), ``item``: a part of
  a structured value (value, key);
* ``block``: a block matrix (rows, cols, blocks...);
* ``list tuple dict``: containers (the claim's returned structure and arguments);
* ``fn``: a function the claim handed to the engine, traced once (number, arity,
  body); ``rank``, ``count``: the claim's rank and count statements.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from stiefelsym.ir.sites import here


class Ref(tuple):
    """A reference to the node numbered ``i`` (a 1-tuple, so that the graph's keys hash in C)."""

    __slots__ = ()

    def __new__(cls, i: int) -> "Ref":
        return tuple.__new__(cls, (i,))

    @property
    def i(self) -> int:
        return self[0]

    def __repr__(self) -> str:
        return f"Ref({self[0]})"

    def __reduce__(self):
        return (Ref, (self[0],))


@dataclass(frozen=True)
class Named:
    """An engine object (a function, an operator space...) by its qualified name."""
    qualname: str


@dataclass(frozen=True)
class Size:
    """A size expression ``k·d`` (d: "n" or "r") with, at a fixed size, its value."""
    k: int
    d: str
    value: int | None

    def text(self) -> str:
        return self.d if self.k == 1 else f"{self.k}{self.d}"


LITERALS = (int, Fraction, str, bool, type(None))

#: the references made so far, by number (a Ref is immutable: one object per number serves every graph),
#: and their text in a digest
_REFS: list[Ref] = []
_REF_TEXT: list[str] = []


def _ref(i: int) -> Ref:
    """Ref(i), shared."""
    if i >= len(_REFS):
        more = range(len(_REFS), 2 * i + 1024)
        _REF_TEXT.extend(f"%{k}" for k in more)
        _REFS.extend(Ref(k) for k in more)
    return _REFS[i]


def _encode(a: Any) -> str:
    """Canonical text of an argument (what the digest hashes); the value of a size is left out, so
    that a graph traced with symbolic sizes and one traced at a size have the same digest when the
    claim did the same thing."""
    t = type(a)
    if t is Ref:
        return f"%{a[0]}"
    if t is tuple:
        return "(" + ",".join(map(_encode, a)) + ")"
    if t is str:
        return repr(a)
    if t is Size:
        return f"<{a.k}{a.d}>"
    if t is Named:
        return f"@{a.qualname!r}"     # quoted: a name cannot pose as more of the line
    if t is Fraction:
        return f"{a.numerator}/{a.denominator}"
    if t is bool or a is None:
        return repr(a)
    if t is int:
        return str(a)
    raise TypeError(f"not an IR argument: {type(a).__name__}")


def _encode_args(a: tuple) -> str:
    """_encode(a) of a node's argument tuple, with the common arguments encoded in line (the same text)."""
    if type(a) is not tuple:
        return _encode(a)
    parts = []
    texts = _REF_TEXT
    known = len(texts)
    for x in a:
        t = type(x)
        if t is Ref:
            k = x[0]
            parts.append(texts[k] if k < known else f"%{k}")
        elif t is str:
            parts.append(repr(x))
        elif t is int:
            parts.append(str(x))
        else:
            parts.append(_encode(x))
    return "(" + ",".join(parts) + ")"


#: the arguments whose text is their value's, by type: equal values of one of these types have the same text
_PLAIN_TEXT = frozenset({str, int, bool, type(None)})
#: the arguments of which one object has one text
_SAME_OBJECT_TEXT = frozenset({Ref, str, int, bool, type(None)})


def _same_argument(a: Any, b: Any) -> bool:
    """Whether :func:`_encode` gives two arguments the same text (True only then; False also where it cannot tell
    without the text)."""
    t = type(a)
    if t is not type(b):
        return False
    if t is Ref:
        return type(a[0]) is int and type(b[0]) is int and a[0] == b[0]
    if t is tuple:
        return len(a) == len(b) and all(_same_argument(x, y) for x, y in zip(a, b))
    if t in _PLAIN_TEXT:
        return a == b
    if t is Fraction:
        return type(a.numerator) is int and type(a.denominator) is int and type(b.numerator) is int \
            and type(b.denominator) is int and a.numerator == b.numerator and a.denominator == b.denominator
    return _encode(a) == _encode(b)


class Graph:
    """The nodes of one trace, with the claim's output (a ``Ref`` to a ``dict`` node)."""

    __slots__ = ("ops", "args", "index", "output", "refusals", "fns", "cache", "sizes", "sites")

    def __init__(self) -> None:
        self.ops: list[str] = []
        self.args: list[tuple] = []
        self.index: dict[tuple, int] = {}
        self.output: Ref | None = None
        #: every refused operation of the trace, in order (a refusal the claim caught still counts)
        self.refusals: list[str] = []
        #: the number of functions traced so far
        self.fns = 0
        #: what the passes computed of this graph (not part of its digest)
        self.cache: dict[str, Any] = {}
        #: the size (n, r) it was traced at, or None (symbolic sizes)
        self.sizes: tuple[int, int] | None = None
        #: per node, the claim expression that made it (:class:`.sites.SourceSite`) or None, when the
        #: trace recorded sites (None otherwise); metadata: not in the digest, the lines or the pickle
        self.sites: list | None = None

    def add(self, op: str, args: tuple) -> Ref:
        key = (op, args)
        i = self.index.get(key)
        if i is None:
            i = self.index[key] = len(self.ops)
            self.ops.append(op)
            self.args.append(args)
            if self.sites is not None:
                self.sites.append(here())
        return _REFS[i] if i < len(_REFS) else _ref(i)

    def __len__(self) -> int:
        return len(self.ops)

    def lines(self) -> list[str]:
        return [f"%{i} = {op}{_encode_args(a)}" for i, op, a in zip(range(len(self.ops)), self.ops, self.args)] + \
               [f"out {_encode(self.output) if self.output is not None else '-'}"]

    def digest(self) -> str:
        d = self.cache.get("digest")
        if d is not None:
            return d
        # every line followed by a newline, hashed in one piece (the same bytes as line by line)
        text = "\n".join(self.lines()) + "\n"
        d = self.cache["digest"] = hashlib.sha256(text.encode()).hexdigest()
        return d

    def sealed(self) -> "Graph":
        """A copy of the graph that no object of the trace refers to (claim code that kept a handle on
        the graph being traced cannot change this one or its cache)."""
        g = Graph.__new__(Graph)
        g.ops, g.args, g.output, g.refusals, g.fns, g.sizes = (list(self.ops), list(self.args), self.output,
                                                               list(self.refusals), self.fns, self.sizes)
        g.index = dict(self.index)      # the same keys: a copy, not a rebuild
        g.cache = {}
        g.sites = None if self.sites is None else list(self.sites)
        return g

    def same_lines(self, other: "Graph") -> bool:
        """Whether the two graphs have the same :meth:`lines` (so the same digest), read from their nodes without
        writing the text: True only then (every op a str, every argument of the same type in both, with the
        same value; a size or an engine name with the same text); False also where it cannot tell so
        cheaply (the text then decides).  1, True and Fraction(1) differ, as in the text."""
        ops, args = self.ops, self.args
        if len(ops) != len(other.ops) or len(args) != len(ops) or len(other.args) != len(ops):
            return False
        plain = _SAME_OBJECT_TEXT
        try:
            if ops != other.ops or args != other.args:   # (equal values, in C: 1 == True == Fraction(1) still)
                return False
            if not all(type(o) is str for o in ops) or not all(type(o) is str for o in other.ops):
                return False
            # the types, argument by argument (a Ref is one shared object per number: the same object, the same text)
            for a, b in zip(args, other.args):
                if type(a) is not tuple or type(b) is not tuple or len(a) != len(b):
                    if not _same_argument(a, b):
                        return False
                    continue
                for x, y in zip(a, b):
                    if x is y and type(x) in plain:
                        continue
                    if not _same_argument(x, y):
                        return False
            return _same_argument(self.output, other.output)
        except Exception:   # noqa: BLE001 - an argument that cannot be compared so: the text decides
            return False

    def refs(self, i: int) -> list[int]:
        """The nodes node ``i`` reads (last argument first, nested tuples likewise), from its arguments
        each time: not kept in the graph's cache, which claim code that reaches the graph being traced
        could fill with lies for the trace-time checks to read (review of stop 58)."""
        return self._nested(self.args[i])

    def needed(self) -> set[int]:
        """The nodes the output reads, directly or not (the output included; none without an output)."""
        if self.output is None:
            return set()
        # a node reads nodes made before it: one sweep down from the output marks what is read
        args = self.args
        mark = bytearray(len(args))
        top = self.output.i
        mark[top] = 1
        for i in range(top, -1, -1):
            if not mark[i]:
                continue
            for x in args[i]:
                t = type(x)
                if t is Ref:
                    j = x[0]
                elif t is tuple:
                    for j in self._nested(x):
                        if j >= i:
                            return self._needed_by_search()
                        mark[j] = 1
                    continue
                else:
                    continue
                if j >= i:
                    return self._needed_by_search()     # not in creation order: searched node by node
                mark[j] = 1
        return {i for i, v in enumerate(mark) if v}

    @staticmethod
    def _nested(a: tuple) -> list[int]:
        """The nodes a tuple of arguments refers to (last first, nested tuples likewise)."""
        out: list[int] = []
        for x in reversed(a):
            t = type(x)
            if t is Ref:
                out.append(x[0])
            elif t is tuple:
                # a nested tuple's nodes come at its place (last first), before the arguments left of it
                for y in reversed(x):
                    t = type(y)
                    if t is Ref:
                        out.append(y[0])
                    elif t is tuple:
                        out.extend(Graph._nested_tuple(y))
        return out

    @staticmethod
    def _nested_tuple(a: tuple) -> list[int]:
        """:meth:`_nested` of a nested tuple, with an explicit stack (no recursion however deep the nesting)."""
        out: list[int] = []
        stack = list(a)
        while stack:
            x = stack.pop()
            t = type(x)
            if t is Ref:
                out.append(x[0])
            elif t is tuple:
                stack.extend(x)
        return out

    def output_keys(self) -> tuple[str, ...] | None:
        """The names of the checks of a graph whose output is a dict of named checks (None otherwise)."""
        out = self.output
        if out is None or self.ops[out[0]] != "dict":
            return None
        keys = self.args[out[0]][0]
        return keys if type(keys) is tuple and all(type(k) is str for k in keys) else None

    def checks_slice(self, keys: frozenset[str]) -> "Graph":
        """The graph of the checks ``keys`` of the output alone: the nodes they read, renumbered in their
        order, and a dict of those checks as the output.  Pure data from pure data (no claim code runs):
        every pass and every method sees only what these checks compute (an entry read, a constant, a
        division made for another check is not in it)."""
        names = self.output_keys()
        if names is None or not keys or not keys <= set(names):
            raise ValueError("a slice names checks of the graph's output dict")
        values = self.args[self.output[0]][1]
        kept = [(k, v) for k, v in zip(names, values) if k in keys]
        need: set[int] = set()
        stack = [j for _k, v in kept for j in ([v[0]] if type(v) is Ref else
                                                self._nested(v) if type(v) is tuple else [])]
        while stack:
            i = stack.pop()
            if i not in need:
                need.add(i)
                stack.extend(self.refs(i))
        order = sorted(need)
        new = {old: k for k, old in enumerate(order)}

        def moved(a: Any) -> Any:
            t = type(a)
            if t is Ref:
                j = new[a[0]]
                return _REFS[j] if j < len(_REFS) else _ref(j)
            if t is tuple:
                return tuple(moved(x) for x in a)
            return a
        g = Graph()
        g.ops = [self.ops[i] for i in order]
        g.args = [moved(self.args[i]) for i in order]
        g.index = {(o, a): k for k, (o, a) in enumerate(zip(g.ops, g.args))}
        g.refusals, g.fns, g.sizes = list(self.refusals), self.fns, self.sizes
        g.output = g.add("dict", (tuple(k for k, _v in kept), tuple(moved(v) for _k, v in kept)))
        if self.sites is not None:
            g.sites = [self.sites[i] for i in order] + [None] * (len(g.ops) - len(order))
        return g

    def _needed_by_search(self) -> set[int]:
        need: set[int] = set()
        stack = [self.output.i] if self.output is not None else []
        while stack:
            i = stack.pop()
            if i in need:
                continue
            need.add(i)
            stack.extend(self.refs(i))
        return need

    def __getstate__(self):
        return (self.ops, self.args, self.output, self.refusals, self.fns, self.sizes)

    def __setstate__(self, state) -> None:
        self.ops, self.args, self.output, self.refusals, self.fns, self.sizes = state
        self.index = {(o, a): i for i, (o, a) in enumerate(zip(self.ops, self.args))}
        self.cache = {}
        self.sites = None


def node_keys(g: Graph) -> list[bytes]:
    """For every node, a digest of its whole subgraph (its op, its literal arguments and, in place of
    every reference, the digest of the node referred to): equal keys in two graphs name the same
    computation, whatever the nodes' numbers."""
    keys = g.cache.get("node_keys")
    if keys is None:
        keys = []

        hexes: list[str] = []

        def enc(a: Any) -> str:
            t = type(a)
            if t is Ref:
                return "%" + hexes[a[0]]
            if t is tuple:
                return "(" + ",".join(["%" + hexes[x[0]] if type(x) is Ref else enc(x) for x in a]) + ")"
            return _encode(a)
        blake2b = hashlib.blake2b
        for op, a in zip(g.ops, g.args):
            k = blake2b((op + enc(a)).encode(), digest_size=20).digest()
            keys.append(k)
            hexes.append(k.hex())
        g.cache["node_keys"] = keys
    return keys
