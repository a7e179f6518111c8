"""A graph compiled into a straight-line program over the entries of its matrices.

The interpreter (:mod:`.evaluate`) evaluates a graph node by node on whole matrices of a
backend: every product goes through the matrix class, the backend, its memo and numpy object
arrays, which at small sizes costs far more than the arithmetic of the entries.  For a graph
made of the matrix algebra alone (``add sub neg mul matmul T``, integer constants, containers,
the attributes of the scene and the tangent vectors of its derivatives), this module writes the
same computation out entry by entry, once per graph and *pattern of its leaves*, as the code of
one Python function:

* a leaf (an attribute of the scene) is given by the pattern of its entries: an integer constant
  (0 and 1 of the chart's X = (E_1..E_r), say) or an input, possibly the same input as another
  entry's up to sign (Φ = PXᵀ − XPᵀ on the chart); the inputs are the program's arguments,
  passed in at every run;
* integer constants are folded, structural zeros skipped (a product with a zero entry is not
  written, a sum with one is its other term), a product by 1 is its other factor, and integer
  coefficients (signs, the 2 of 1 + 2κ) ride along with an entry until they meet another
  entry, so a negation or a difference of two negated terms costs no operation;
* a 1 x 1 matrix is one entry, and a transpose is a new view of the same entries;
* the same operation on the same values is written once (a sum or a product in either order);
* only the entries the outputs read are computed (dead code is dropped).

What is written is a function of the graph and the leaf pattern only: no value of an input is
seen while compiling, and no entry of any input is assumed to be anything but an element of a
commutative ring (the program uses ``+``, ``-``, ``*`` and ``-x`` on the inputs and integers).
Two entries that are the same computation are never cancelled while compiling (x - x is
written and computed): the values of the outputs come from running the program.

A graph with any other op (inverses, traces, entries, blocks, traced functions, engine steps
other than the tangent vector, rank and count statements, fractions) is not compiled
(:class:`NotCompiled`): its evaluation stays with the interpreter.
"""
from __future__ import annotations

from fractions import Fraction
from typing import Any, Callable

from stiefelsym.ir.graph import Graph, Named, Ref

#: the engine step the derivative pass writes for the tangent vector of a flow (the components the
#: flow gives, 0 for the others), see :func:`stiefelsym.ir.derivative.tangent_vector`
TANGENT = "stiefelsym.ir.derivative.tangent_vector"


class NotCompiled(Exception):
    """A graph (or a leaf) the straight-line compiler does not handle: the reason."""


class Leaf:
    """The pattern of one leaf: ``rows`` of entries, each an ``int`` (a constant of the pattern),
    None (an input of its own) or a pair (c, key): c (1 or -1) times the input named ``key``, one
    input for every entry of every leaf with that key (the chart's Φ = PXᵀ − XPᵀ has the entries of
    P, up to sign); ``scalar``: a number of the scene rather than a matrix."""

    __slots__ = ("rows", "scalar")

    def __init__(self, rows: list[list[int | None]], scalar: bool = False) -> None:
        self.rows, self.scalar = rows, scalar

    def key(self) -> tuple:
        return (self.scalar, tuple(tuple(r) for r in self.rows))


# An entry while compiling: an int (a constant) or (c, name): c times the value named ``name`` (c a
# nonzero int).  A matrix: a tuple of rows of entries.  A number of the scene: ("s", entry).
class _Mat(tuple):
    __slots__ = ()


class _Num:
    __slots__ = ("e",)

    def __init__(self, e: Any) -> None:
        self.e = e


class _Writer:
    """The lines of the program and the names of its values."""

    def __init__(self) -> None:
        self.lines: list[tuple[str, str, tuple[str, ...]]] = []    # (target, expression, names read)
        self.k = 0
        #: the name of every expression written so far (the same computation of the same values is
        #: written once; a sum or a product of two names in either order is one computation)
        self.seen: dict[str, str] = {}

    def emit(self, expr: str, reads: tuple[str, ...]) -> str:
        hit = self.seen.get(expr)
        if hit is not None:
            return hit
        name = f"v{self.k}"
        self.k += 1
        self.lines.append((name, expr, reads))
        self.seen[expr] = name
        return name

    def emit2(self, a: str, op: str, b: str) -> str:
        """a op b for op + or * (commutative: the operands in a fixed order), or -."""
        if op != "-" and _order(b) < _order(a):
            a, b = b, a
        return self.emit(f"{a} {op} {b}", (a, b))

    # -- entries ---------------------------------------------------------------------------------
    def neg(self, x: Any) -> Any:
        return -x if type(x) is int else (-x[0], x[1])

    def add(self, x: Any, y: Any) -> Any:
        if type(x) is int and type(y) is int:
            return x + y
        if type(x) is int:
            x, y = y, x
        if type(y) is int:                      # x an entry, y a constant
            if y == 0:
                return x
            c, a = x
            if c == 1:
                return (1, self.emit(f"{a} + {y}", (a,)))
            if c == -1:
                return (1, self.emit(f"{y} - {a}", (a,)))
            return (1, self.emit(f"{c} * {a} + {y}", (a,)))
        (c, a), (d, b) = x, y
        if c == d:
            return (c, self.emit2(a, "+", b))
        if c == -d:
            return (c, self.emit2(a, "-", b))
        if d % c == 0:
            return (c, self.emit(f"{a} + {d // c} * {b}", (a, b)))
        if c % d == 0:
            return (d, self.emit(f"{c // d} * {a} + {b}", (a, b)))
        return (1, self.emit(f"{c} * {a} + {d} * {b}", (a, b)))

    def mul(self, x: Any, y: Any) -> Any:
        if type(x) is int and type(y) is int:
            return x * y
        if type(x) is int:
            x, y = y, x
        if type(y) is int:
            return 0 if y == 0 else (x[0] * y, x[1])
        (c, a), (d, b) = x, y
        return (c * d, self.emit2(a, "*", b))

    def sum(self, terms: list) -> Any:
        acc: Any = 0
        for t in terms:
            acc = self.add(acc, t)
        return acc

    def final(self, x: Any) -> str:
        """An entry of an output as an expression (a constant, a name, or a name times its
        coefficient)."""
        if type(x) is int:
            return f"ZERO + {x}" if x else "ZERO"
        c, a = x
        if c == 1:
            return a
        if c == -1:
            return f"-{a}"
        return f"{c} * {a}"


def _order(name: str) -> tuple[int, int]:
    """A name's place in the order of commutative operands (inputs first, then values by number)."""
    return (0 if name[0] == "x" else 1, int(name[1:]))


def _entrywise(w: _Writer, f: Callable, x: _Mat, y: _Mat) -> _Mat:
    if len(x) != len(y) or (x and len(x[0]) != len(y[0])):
        raise NotCompiled("a sum of matrices of different shapes")
    return _Mat(tuple(f(a, b) for a, b in zip(rx, ry)) for rx, ry in zip(x, y))


def _scaled(w: _Writer, c: Any, x: _Mat) -> _Mat:
    return _Mat(tuple(w.mul(c, a) for a in row) for row in x)


def _matmul(w: _Writer, x: _Mat, y: _Mat) -> _Mat:
    k = len(x[0]) if x else 0
    if k != len(y):
        raise NotCompiled("a product of matrices whose sizes do not match")
    cols = list(zip(*y)) if y else []
    if not cols:
        raise NotCompiled("a product with no columns")
    return _Mat(tuple(w.sum([w.mul(a, b) for a, b in zip(row, col) if a != 0 and b != 0]) for col in cols)
                for row in x)


class Program:
    """A compiled graph: ``run(inputs)`` gives the outputs' entries (a dict: the check's name to its
    rows of values), ``inputs``: which leaf entries the program reads, in order ((leaf node, i, j))."""

    def __init__(self, source: str, inputs: list[tuple[int, int, int]], outputs: dict[str, tuple[int, int]],
                 operations: int) -> None:
        self.source, self.inputs, self.outputs, self.operations = source, inputs, outputs, operations
        self._fn: tuple[Any, Callable] | None = None

    def function(self, zero: Any) -> Callable:
        """The program as a Python function of the inputs (compiled once; ``zero``: the ring's 0, the
        value of an output entry that is a structural zero)."""
        if self._fn is None or self._fn[0] is not zero:
            scope: dict[str, Any] = {"ZERO": zero}
            exec(compile(self.source, "<straight-line program>", "exec"), scope)   # noqa: S102 - generated from the graph
            self._fn = (zero, scope["program"])
        return self._fn[1]


def compile_graph(g: Graph, leaves: Callable[[int, str], Leaf]) -> Program:
    """The straight-line program of a graph's output (a dict of checks, each a matrix), its leaves
    (the scene's attributes) given by ``leaves(node, name)``; raises :class:`NotCompiled` for a graph
    outside the compiled ops."""
    if g.output is None:
        raise NotCompiled("a graph with no output")
    w = _Writer()
    ops, args = g.ops, g.args
    need = g.needed()
    vals: dict[int, Any] = {}
    inputs: list[tuple[int, int, int]] = []
    named: dict[Any, str] = {}
    SCENE = object()

    def val(a: Any) -> Any:
        if type(a) is Ref:
            return vals[a.i]
        if type(a) is int and type(a) is not bool:
            return _Num(a)
        if type(a) is Fraction and a.denominator == 1:
            return _Num(int(a))
        raise NotCompiled(f"a literal {type(a).__name__} in arithmetic")

    for i in sorted(need):
        op, a = ops[i], args[i]
        if op == "scene":
            if a != (0,):
                raise NotCompiled("the scene of a traced function")
            v: Any = SCENE
        elif op == "attr":
            if type(a[0]) is not Ref or vals[a[0].i] is not SCENE:
                raise NotCompiled("an attribute of something other than the claim's scene")
            leaf = leaves(i, a[1])
            rows = []
            for r, row in enumerate(leaf.rows):
                out = []
                for c, x in enumerate(row):
                    if x is None or type(x) is tuple:
                        sign, key = (1, object()) if x is None else x
                        if sign not in (1, -1):
                            raise NotCompiled("an input of the pattern with a coefficient other than 1 or -1")
                        name = named.get(key)
                        if name is None:
                            inputs.append((i, r, c))
                            name = named[key] = f"x{len(inputs) - 1}"
                        out.append((sign, name))
                    else:
                        out.append(int(x))
                rows.append(tuple(out))
            v = _Num(rows[0][0]) if leaf.scalar else _Mat(tuple(rows))
        elif op == "const":
            v = val(a[0])
        elif op in ("add", "sub"):
            x, y = val(a[0]), val(a[1])
            f = w.add if op == "add" else (lambda p, q: w.add(p, w.neg(q)))
            if type(x) is _Num and type(y) is _Num:
                v = _Num(f(x.e, y.e))
            elif type(x) is _Mat and type(y) is _Mat:
                v = _entrywise(w, f, x, y)
            else:
                raise NotCompiled("a sum of a number and a matrix")
        elif op == "neg":
            x = val(a[0])
            v = _Num(w.neg(x.e)) if type(x) is _Num else _Mat(tuple(w.neg(e) for e in row) for row in x) \
                if type(x) is _Mat else _fail("a negation of a container")
        elif op == "mul":
            x, y = val(a[0]), val(a[1])
            if type(x) is _Num and type(y) is _Num:
                v = _Num(w.mul(x.e, y.e))
            elif type(x) is _Num and type(y) is _Mat:
                v = _scaled(w, x.e, y)
            elif type(x) is _Mat and type(y) is _Num:
                v = _scaled(w, y.e, x)
            else:
                raise NotCompiled("a product * of two matrices")
        elif op == "matmul":
            x, y = val(a[0]), val(a[1])
            if type(x) is not _Mat or type(y) is not _Mat:
                raise NotCompiled("a matrix product of a number")
            v = _matmul(w, x, y)
        elif op == "T":
            x = val(a[0])
            if type(x) is not _Mat:
                raise NotCompiled("a transpose of a number")
            v = _Mat(tuple(zip(*x))) if x else x
        elif op == "dict":
            keys, refs = a
            v = {k: val(x) for k, x in zip(keys, refs)}
        elif op == "tuple":
            v = tuple(val(x) for x in a)
        elif op == "item":
            x = vals[a[0].i] if type(a[0]) is Ref else None
            if type(x) not in (dict, tuple) or type(a[1]) not in (str, int):
                raise NotCompiled("an item of something other than a container")
            v = x[a[1]]
        elif op == "prim" and a and a[0] == Named(TANGENT):
            if len(a) != 4 or type(a[1]) is not Ref or vals[a[1].i] is not SCENE or type(a[2]) is not Ref:
                raise NotCompiled("a tangent vector of an unexpected form")
            flow, keys = vals[a[2].i], a[3]
            if type(flow) is not dict:
                raise NotCompiled("a tangent vector of a flow that is not a dict of matrices")
            v = {}
            for k in keys:
                comp = flow.get(k)
                if comp is None:
                    comp = leaves(-1, k)        # the shape of the primitive (a missing component is 0)
                    comp = _Mat(tuple(tuple(0 for _ in row) for row in comp.rows))
                if type(comp) is not _Mat:
                    raise NotCompiled("a component of a tangent vector that is not a matrix")
                v[k] = comp
        else:
            raise NotCompiled(f"the op {op!r}")
        vals[i] = v

    out = vals[g.output.i]
    if type(out) is not dict or not out or not all(type(x) is _Mat and x and x[0] for x in out.values()):
        raise NotCompiled("an output that is not a dict of matrices")
    # the program: live lines only (backwards from the outputs)
    finals = {name: [[w.final(e) for e in row] for row in m] for name, m in out.items()}
    live: set[str] = set()
    for m in out.values():
        for row in m:
            for e in row:
                if type(e) is not int:
                    live.add(e[1])
    body: list[str] = []
    for target, expr, reads in reversed(w.lines):
        if target in live:
            body.append(f"    {target} = {expr}")
            live.update(reads)
    body.reverse()
    unpack = ", ".join(f"x{k}" for k in range(len(inputs)))
    ret = ", ".join("(" + ", ".join("(" + ", ".join(row) + ",)" for row in rows) + ",)" for rows in finals.values())
    src = "\n".join(["def program(X):",
                     f"    {unpack}, = X" if inputs else "    pass",
                     *body,
                     f"    return ({ret},)"]) + "\n"
    shapes = {name: (len(m), len(m[0])) for name, m in out.items()}
    return Program(src, inputs, shapes, len(body))


def _fail(why: str) -> Any:
    raise NotCompiled(why)
