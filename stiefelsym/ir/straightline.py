"""A graph compiled into a straight-line program over the entries of its matrices.

The interpreter (:mod:`.evaluate`) evaluates a graph node by node on whole matrices of a
backend: every product goes through the matrix class, the backend, its memo and numpy object
arrays, which at small sizes costs far more than the arithmetic of the entries.  For a graph
made of the matrix algebra (``add sub neg mul matmul T``, division by a rational constant,
rational constants, containers, the attributes of the scene and the tangent vectors of its
derivatives), entries, slices and blocks (``entry``, ``block``), and the scene's methods that
are the same algebra written out (``tr``, ``killing``, ``q``, ``const``, ``zeros``,
``identity``, ``scalar_matrix``, ``mat``, and the claim's own fresh parameters ``scalar`` and
``generic``, which are leaves), this module writes the same computation out entry by entry,
once per graph and *pattern of its leaves*, as the code of one Python function:

* a leaf (an attribute of the scene) is given by the pattern of its entries: an integer constant
  (0 and 1 of the chart's X = (E_1..E_r), say) or an input, possibly the same input as another
  entry's up to sign (Φ = PXᵀ − XPᵀ on the chart); the inputs are the program's arguments,
  passed in at every run;
* rational constants are folded, structural zeros skipped (a product with a zero entry is not
  written, a sum with one is its other term), a product by 1 is its other factor, and rational
  coefficients (signs, the 2 of 1 + 2κ, the -1/2 of the pairing) ride along with an entry until
  they meet another entry, so a negation or a difference of two negated terms costs no
  operation; a constant that is not an integer is an element of the ring made once from the
  exact fraction (``K0``, ``K1``, ..), never a Python division or a float;
* a 1 x 1 matrix is one entry, and a transpose is a new view of the same entries;
* the same operation on the same values is written once (a sum or a product in either order);
* only the entries the outputs read are computed (dead code is dropped).

What is written is a function of the graph and the leaf pattern only: no value of an input is
seen while compiling, and no entry of any input is assumed to be anything but an element of a
commutative ring containing Q (the program uses ``+``, ``-``, ``*`` and ``-x`` on the inputs,
integers and the ring's rational constants).
Two entries that are the same computation are never cancelled while compiling (x - x is
written and computed): the values of the outputs come from running the program.

A graph with any other op (inverses and resolvents, division by anything but a rational
constant, traced functions, engine steps other than the tangent vector, other methods of the
scene, rank and count statements) is not
compiled (:class:`NotCompiled`): its evaluation stays with the interpreter.
"""
from __future__ import annotations

import math
from fractions import Fraction
from typing import Any, Callable

from stiefelsym.ir.graph import Graph, Named, Ref, Size

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


def _const(x: Any) -> bool:
    """Whether an entry while compiling is a constant (an int or a Fraction) rather than (c, name)."""
    return type(x) is not tuple


def _norm(x: Any) -> Any:
    """A rational constant as an int when it is one (constants compare and fold as numbers)."""
    return int(x) if type(x) is Fraction and x.denominator == 1 else x


class _Writer:
    """The lines of the program and the names of its values."""

    def __init__(self) -> None:
        self.lines: list[tuple[str, str, tuple[str, ...]]] = []    # (target, expression, names read)
        self.k = 0
        #: the rational constants that are not integers, in order: the program's names K0, K1, ..
        #: (elements of the ring, made once per function from the exact fraction)
        self.constants: list[Fraction] = []
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

    def lit(self, c: Any) -> str:
        """A constant in the program's text: an int as itself, a Fraction as the name of the ring's
        element (never a Python float: 1/2 is not written as a division)."""
        c = _norm(c)
        if type(c) is int:
            return str(c) if c >= 0 else f"({c})"
        if c not in self.constants:
            self.constants.append(c)
        return f"K{self.constants.index(c)}"

    def emit2(self, a: str, op: str, b: str) -> str:
        """a op b for op + or * (commutative: the operands in a fixed order), or -."""
        if op != "-" and _order(b) < _order(a):
            a, b = b, a
        return self.emit(f"{a} {op} {b}", (a, b))

    # -- entries ---------------------------------------------------------------------------------
    def neg(self, x: Any) -> Any:
        return -x if _const(x) else (-x[0], x[1])

    def add(self, x: Any, y: Any) -> Any:
        if _const(x) and _const(y):
            return _norm(x + y)
        if _const(x):
            x, y = y, x
        if _const(y):                           # x an entry, y a constant
            if y == 0:
                return x
            c, a = x
            if c == 1:
                return (1, self.emit(f"{a} + {self.lit(y)}", (a,)))
            if c == -1:
                return (1, self.emit(f"{self.lit(y)} - {a}", (a,)))
            return (1, self.emit(f"{self.lit(c)} * {a} + {self.lit(y)}", (a,)))
        (c, a), (d, b) = x, y
        if c == d:
            return (c, self.emit2(a, "+", b))
        if c == -d:
            return (c, self.emit2(a, "-", b))
        q = _norm(Fraction(d) / Fraction(c))
        if type(q) is int:
            return (c, self.emit(f"{a} + {self.lit(q)} * {b}", (a, b)))
        q = _norm(Fraction(c) / Fraction(d))
        if type(q) is int:
            return (d, self.emit(f"{self.lit(q)} * {a} + {b}", (a, b)))
        return (1, self.emit(f"{self.lit(c)} * {a} + {self.lit(d)} * {b}", (a, b)))

    def mul(self, x: Any, y: Any) -> Any:
        if _const(x) and _const(y):
            return _norm(x * y)
        if _const(x):
            x, y = y, x
        if _const(y):
            return 0 if y == 0 else (_norm(x[0] * y), x[1])
        (c, a), (d, b) = x, y
        return (_norm(c * d), self.emit2(a, "*", b))

    def sum(self, terms: list) -> Any:
        acc: Any = 0
        for t in terms:
            acc = self.add(acc, t)
        return acc

    def final(self, x: Any) -> str:
        """An entry of an output as an expression (a constant, a name, or a name times its
        coefficient)."""
        if _const(x):
            return f"ZERO + {self.lit(x)}" if x else "ZERO"
        c, a = x
        if c == 1:
            return a
        if c == -1:
            return f"-{a}"
        return f"{self.lit(c)} * {a}"


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
    rows of values), ``inputs``: which leaf entries the program reads, in order ((leaf node, i, j));
    ``constants``: the rational constants (not integers) the program names K0, K1, ..; ``scalars``:
    the checks that are numbers (each given as a 1 x 1 matrix)."""

    def __init__(self, source: str, inputs: list[tuple[int, int, int]], outputs: dict[str, tuple[int, int]],
                 operations: int, constants: tuple[Fraction, ...] = (), scalars: frozenset = frozenset()) -> None:
        self.source, self.inputs, self.outputs, self.operations = source, inputs, outputs, operations
        self.constants, self.scalars = constants, scalars
        self._fn: tuple[Any, Callable] | None = None

    def function(self, zero: Any, fraction: Callable[[int, int], Any] | None = None) -> Callable:
        """The program as a Python function of the inputs (compiled once; ``zero``: the ring's 0, the
        value of an output entry that is a structural zero; ``fraction(p, q)``: the ring's exact p/q
        for a program with rational constants, each made once as ``zero + fraction(p, q)``)."""
        if self._fn is None or self._fn[0] is not zero:
            scope: dict[str, Any] = {"ZERO": zero}
            if self.constants:
                if fraction is None:
                    raise NotCompiled("a program with rational constants and no fractions of the ring")
                for k, c in enumerate(self.constants):
                    scope[f"K{k}"] = zero + fraction(c.numerator, c.denominator)
            exec(compile(self.source, "<straight-line program>", "exec"), scope)   # noqa: S102 - generated from the graph
            self._fn = (zero, scope["program"])
        return self._fn[1]


def compile_graph(g: Graph, leaves: Callable[[int, Any], Leaf],
                  size: Callable[[str], int] | None = None) -> Program:
    """The straight-line program of a graph's output (a dict of checks, each a matrix), its leaves
    given by ``leaves(node, name)``: the scene's attributes (``name`` a str) and the fresh parameters
    of the claim's own (``name`` a pair: the scene's method ``scalar`` or ``generic`` and its literal
    arguments); ``size(d)``: the value of the dimension d ("n", "r") of the scene, for the sizes of
    ``zeros``, ``identity`` and ``scalar_matrix``.  Raises :class:`NotCompiled` for a graph outside
    the compiled ops."""
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
        if type(a) is int or type(a) is Fraction:
            return _Num(_norm(a))
        if type(a) is Size:         # a dimension of the scene (s.n, s.r) as a number
            return _Num(dim(a))
        raise NotCompiled(f"a literal {type(a).__name__} in arithmetic")

    def dim(x: Any) -> int:
        if type(x) is int:
            return x
        if type(x) is Size and size is not None:
            return x.k * size(x.d)
        raise NotCompiled("a size that is not an int or a dimension of the scene")

    def matrix(x: Any, why: str) -> _Mat:
        if type(x) is not _Mat:
            raise NotCompiled(why)
        if not x or not x[0]:
            raise NotCompiled("an empty matrix (a block of n − r = 0 rows, say)")
        return x

    def number(x: Any, why: str) -> Any:
        if type(x) is not _Num:
            raise NotCompiled(why)
        return x.e

    def leaf_value(i: int, name: Any) -> Any:
        leaf = leaves(i, name)
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
        if not rows or not rows[0]:
            raise NotCompiled("an empty matrix (a block of n − r = 0 rows, say)")
        return _Num(rows[0][0]) if leaf.scalar else _Mat(tuple(rows))

    def call(i: int, a: tuple) -> Any:
        """A method of the claim's scene (``s.tr(M)``, ``s.q(1, 2)``, ..): its value written out."""
        sc, name, cargs, kw = a
        if type(sc) is not Ref or vals[sc.i] is not SCENE:
            raise NotCompiled("a method of something other than the claim's scene")
        if name in ("scalar", "generic"):
            if kw or not all(type(x) is str for x in cargs):
                raise NotCompiled(f"a call of {name} with arguments that are not names")
            return leaf_value(i, (name, tuple(cargs)))
        xs = [val(x) if type(x) is Ref else x for x in cargs]
        if kw and (name not in ("mat", "zeros", "identity", "scalar_matrix")
                   or any(k not in ("tags", "tag") for k, _ in kw)):
            raise NotCompiled(f"a call of {name} with keywords other than the spaces")
        if name in ("q", "const"):
            if not all(type(x) in (int, Fraction) for x in xs) or len(xs) not in (1, 2) \
                    or (name == "const" and len(xs) != 1) or (len(xs) == 2 and xs[1] == 0):
                raise NotCompiled(f"a call of {name} with arguments that are not rational constants")
            return _Num(_norm(Fraction(xs[0]) / (Fraction(xs[1]) if len(xs) == 2 else 1)))
        if name == "tr":
            M = matrix(xs[0], "a trace of a number")
            if len(M) != len(M[0]):
                raise NotCompiled("a trace of a matrix that is not square")
            return _Num(w.sum([M[k][k] for k in range(len(M))]))
        if name == "killing":
            x, y = matrix(xs[0], "a pairing of a number"), matrix(xs[1], "a pairing of a number")
            if len(x[0]) != len(y) or len(x) != len(y[0]):
                raise NotCompiled("a pairing of matrices whose sizes do not match")
            terms = [w.mul(x[p][q], y[q][p]) for p in range(len(x)) for q in range(len(y))
                     if x[p][q] != 0 and y[q][p] != 0]
            return _Num(w.mul(Fraction(-1, 2), w.sum(terms)))
        if name == "zeros":
            return _Mat(tuple(tuple(0 for _ in range(dim(xs[1]))) for _ in range(dim(xs[0]))))
        if name in ("identity", "scalar_matrix"):
            c, m = (1, xs[0]) if name == "identity" else (number(xs[0], "a scalar matrix of a matrix"), xs[1])
            m = dim(m)
            return _Mat(tuple(tuple(c if p == q else 0 for q in range(m)) for p in range(m)))
        if name == "mat":
            rows = xs[0]
            if type(rows) not in (list, tuple) or not rows or not all(type(r) in (list, tuple) for r in rows) \
                    or len({len(r) for r in rows}) != 1 or not rows[0]:
                raise NotCompiled("a matrix from something other than rows of numbers")
            return _Mat(tuple(tuple(number(val(x) if type(x) is not _Num else x, "a matrix with an entry that is "
                                           "not a number") for x in r) for r in rows))
        raise NotCompiled(f"the scene's method {name!r}")

    def entry(M: Any, idx: tuple) -> Any:
        """M[i, j], a block M[i0:i1, j0:j1], a row M[i, :] or a column M[:, j] (numpy's indexing)."""
        M = matrix(M, "an entry of a number")
        if len(idx) != 2:
            raise NotCompiled("an entry with other than two indices")
        sl = []
        for x in idx:
            if type(x) is int:
                sl.append(x)
            elif type(x) is tuple and all(y is None or type(y) is int for y in x[1:]):
                sl.append(slice(*x[1:]))
            else:
                raise NotCompiled("an index that is not an int or a slice of ints")
        i, j = sl
        if type(i) is int and type(j) is int:
            return _Num(M[i][j])
        rows = [M[i]] if type(i) is int else list(M[i])
        out = tuple(tuple(row[j]) if type(j) is slice else (row[j],) for row in rows)
        if not out or not out[0]:
            raise NotCompiled("an empty block")
        return _Mat(out)

    def block(nrows: int, ncols: int, blocks: list) -> _Mat:
        grid = [[matrix(b, "a block that is not a matrix") for b in blocks[p * ncols:(p + 1) * ncols]]
                for p in range(nrows)]
        out = []
        for row in grid:
            if len({len(b) for b in row}) != 1:
                raise NotCompiled("a block row of blocks with different numbers of rows")
            for k in range(len(row[0])):
                out.append(tuple(e for b in row for e in b[k]))
        if len({len(r) for r in out}) != 1:
            raise NotCompiled("a block matrix whose rows have different lengths")
        return _Mat(tuple(out))

    def divide(x: Any, y: Any) -> Any:
        """x / c for a rational constant c (a product by 1/c, exact); any other divisor is not
        compiled."""
        if type(y) is not _Num or not _const(y.e):
            raise NotCompiled("a division by something other than a rational constant")
        if y.e == 0:
            raise NotCompiled("a division by 0")
        c = _norm(1 / Fraction(y.e))
        if type(x) is _Num:
            return _Num(w.mul(x.e, c))
        if type(x) is _Mat:
            return _scaled(w, c, x)
        raise NotCompiled("a division of a container")

    for i in sorted(need):
        op, a = ops[i], args[i]
        if op == "scene":
            if a != (0,):
                raise NotCompiled("the scene of a traced function")
            v: Any = SCENE
        elif op == "attr":
            if type(a[0]) is not Ref or vals[a[0].i] is not SCENE:
                raise NotCompiled("an attribute of something other than the claim's scene")
            v = leaf_value(i, a[1])
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
            v = tuple(val(x) if type(x) is Ref else x for x in a)
        elif op == "list":
            v = [val(x) if type(x) is Ref else x for x in a]
        elif op == "call":
            v = call(i, a)
        elif op == "entry":
            v = entry(val(a[0]), a[1:])
        elif op == "block":
            v = block(a[0], a[1], [val(b) for b in a[2]])
        elif op == "div":
            v = divide(val(a[0]), val(a[1]))
        elif op == "item":
            x = vals[a[0].i] if type(a[0]) is Ref else None
            if type(x) not in (dict, tuple, list) or type(a[1]) not in (str, int):
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
    if type(out) is not dict or not out or not all(type(x) is _Num or (type(x) is _Mat and x and x[0])
                                                   for x in out.values()):
        raise NotCompiled("an output that is not a dict of matrices and numbers")
    # a check that is a number is computed as a 1 x 1 matrix and named in ``scalars``
    scalars = frozenset(name for name, x in out.items() if type(x) is _Num)
    out = {name: _Mat(((x.e,),)) if type(x) is _Num else x for name, x in out.items()}
    # the program: live lines only (backwards from the outputs)
    finals = {name: [[w.final(e) for e in row] for row in m] for name, m in out.items()}
    live: set[str] = set()
    for m in out.values():
        for row in m:
            for e in row:
                if not _const(e):       # an integer or a rational constant is written as such
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
    return Program(src, inputs, shapes, len(body), tuple(w.constants), scalars)


def _fail(why: str) -> Any:
    raise NotCompiled(why)


# -- the same program at the level of coefficients ---------------------------------------------------
#
# With coordinates of integer coefficients, at small sizes the entries are polynomials of a few terms, and a polynomial operation of
# the program costs what calling the polynomial library costs (about half a microsecond), not its
# arithmetic.  :func:`coefficient_program` writes the same program once more, one level down: every
# value of the program is a sum of terms c_m x^m over the monomials m it can have -- its *support*,
# found while writing from the supports of its operands (m1 + m2 for a product, the union for a sum),
# never from the values of the coefficients -- and each coefficient is a line of integer arithmetic
# on the coefficients of the inputs.  What is compiled in is the monomials of the inputs (the
# pattern of the chart's coordinates one level finer) and which terms of which operands meet in
# which monomial; what the program computes at every run is every coefficient of every entry of
# every output, from the coefficients of the inputs, in exact integer arithmetic (a rational constant
# of the program's text rides along with a coefficient as its factor, as the compiler's integer
# coefficients ride along with an entry).  No coefficient is
# dropped or cancelled while writing: a monomial whose coefficient is 0 at the run (x - x) is
# computed and is 0 then.  An entry of an output is 0 exactly when every one of its coefficients is.


class _CoefficientWriter:
    """The lines of the coefficient program (``cap``: most integer operations it may take)."""

    def __init__(self, cap: int) -> None:
        self.lines: list[tuple[str, str, tuple[str, ...], int]] = []     # (target, expression, reads, ops)
        self.seen: dict[str, str] = {}
        self.k = 0
        self.ops = 0
        self.cap = cap
        #: the monomial 1 (the exponents of a constant)
        self.unit: tuple[int, ...] = ()

    def emit(self, expr: str, reads: tuple[str, ...], ops: int) -> str:
        hit = self.seen.get(expr)
        if hit is not None:
            return hit
        self.ops += ops
        if self.ops > self.cap:
            raise NotCompiled(f"a coefficient program of more than {self.cap} integer operations")
        name = f"c{self.k}"
        self.k += 1
        self.lines.append((name, expr, reads, ops))
        self.seen[expr] = name
        return name


def _lit(c: int) -> str:
    return str(c) if c >= 0 else f"({c})"


def _q(x: Any) -> Any:
    """A rational constant as an int where it is one, else a Fraction."""
    return int(x) if type(x) is int or x.denominator == 1 else Fraction(x)


def _integers(ratios: list) -> tuple[int, list[int]]:
    """(L, [L * q for q in ratios]): the least L >= 1 that makes every ratio an integer."""
    L = 1
    for q in ratios:
        if type(q) is Fraction:
            L = L * q.denominator // math.gcd(L, q.denominator)
    return L, [int(q * L) for q in ratios]


def _term(k: int, e: str, first: bool) -> str:
    """k * e in a sum (k a nonzero int): its sign, and the factor where it is not 1."""
    s = e if abs(k) == 1 else f"{abs(k)} * {e}"
    return (s if k > 0 else f"-{s}") if first else f" + {s}" if k > 0 else f" - {s}"


class _Sparse:
    """A value of the program while writing its coefficient program: monomial -> atom, an atom being a
    rational constant (of the program's text, folded like the program folds them) or (c, name): c
    times the integer coefficient named ``name`` (c a nonzero rational constant of the text, an int
    where it is one).  Only integers are written in the program: a rational factor stays with its
    atom, as the compiler's integer coefficients ride along with an entry."""

    __slots__ = ("t", "w")

    def __init__(self, t: dict, w: _CoefficientWriter) -> None:
        self.t, self.w = t, w

    def _lift(self, o: Any) -> "_Sparse":
        if type(o) is _Sparse:
            return o
        if type(o) is int or type(o) is Fraction:
            return _Sparse({self.w.unit: _q(o)} if o else {}, self.w)
        raise NotCompiled(f"a coefficient program with a {type(o).__name__} in arithmetic")

    def _sum(self, terms: list[tuple[Any, str, tuple[str, ...]]], const: Any) -> Any:
        """The atom of sum(c * e for c, e, _ in terms) + const (``terms`` not empty; e a name or a
        product of two names), one line of integer arithmetic unless it is one name."""
        w = self.w
        c0 = terms[0][0]
        if len(terms) == 1 and not const and len(terms[0][2]) == 1 and terms[0][1] == terms[0][2][0]:
            return (c0, terms[0][1])
        L, ks = _integers([Fraction(c) / c0 for c, _, _ in terms] + ([Fraction(const) / c0] if const else []))
        parts = [_term(k, e, i == 0) for i, (k, (_, e, _)) in enumerate(zip(ks, terms))]
        ops = sum((" * " in e) + (abs(k) != 1) for k, (_, e, _) in zip(ks, terms)) + len(terms) - 1
        if const:
            parts.append(f" + {ks[-1]}" if ks[-1] > 0 else f" - {-ks[-1]}")
            ops += 1
        return (_q(Fraction(c0) / L), w.emit("".join(parts), tuple(x for _, _, rd in terms for x in rd), ops))

    def _add(self, x: Any, y: Any) -> Any:
        if type(x) is not tuple and type(y) is not tuple:
            return _q(x + y)
        if type(x) is not tuple:
            x, y = y, x
        if type(y) is not tuple:
            return x if y == 0 else self._sum([(x[0], x[1], (x[1],))], y)
        (c, a), (d, b) = x, y
        if c == d:
            a, b = sorted((a, b), key=_corder)
            return (c, self.w.emit(f"{a} + {b}", (a, b), 1))
        if c == -d:
            return (c, self.w.emit(f"{a} - {b}", (a, b), 1))
        return self._sum([(c, a, (a,)), (d, b, (b,))], 0)

    def __add__(self, o: Any) -> "_Sparse":
        o = self._lift(o)
        t = dict(self.t)
        for m, y in o.t.items():
            x = t.get(m)
            if x is None:
                t[m] = y
            else:
                z = self._add(x, y)
                if type(z) is not tuple and z == 0:
                    del t[m]        # two constants of the program's text that sum to 0
                else:
                    t[m] = z
        return _Sparse(t, self.w)

    __radd__ = __add__

    def __neg__(self) -> "_Sparse":
        return _Sparse({m: -x if type(x) is not tuple else (-x[0], x[1]) for m, x in self.t.items()}, self.w)

    def __sub__(self, o: Any) -> "_Sparse":
        return self + (-self._lift(o))

    def __rsub__(self, o: Any) -> "_Sparse":
        return self._lift(o) + (-self)

    def __mul__(self, o: Any) -> "_Sparse":
        o = self._lift(o)
        w = self.w
        if w.ops + len(self.t) * len(o.t) > w.cap:      # every pair of terms is at least one operation
            raise NotCompiled(f"a coefficient program of more than {w.cap} integer operations")
        acc: dict[tuple, list] = {}
        for m1, x in self.t.items():
            for m2, y in o.t.items():
                m = tuple(p + q for p, q in zip(m1, m2))
                acc.setdefault(m, []).append((x, y))
        t: dict[tuple, Any] = {}
        for m, pairs in acc.items():
            const: Any = 0
            terms: list[tuple[Any, str, tuple[str, ...]]] = []     # (c, "a * b" or "a", reads)
            for x, y in pairs:
                if type(x) is not tuple and type(y) is not tuple:
                    const = _q(const + x * y)
                elif type(x) is not tuple or type(y) is not tuple:
                    k, (c, a) = (x, y) if type(x) is not tuple else (y, x)
                    terms.append((_q(k * c), a, (a,)))
                else:
                    (c, a), (d, b) = x, y
                    a, b = sorted((a, b), key=_corder)
                    terms.append((_q(c * d), f"{a} * {b}", (a, b)))
            if not terms:
                if const:
                    t[m] = const
                continue
            terms.sort(key=lambda z: z[1])
            t[m] = self._sum(terms, const)
        return _Sparse(t, w)

    __rmul__ = __mul__


def _corder(name: str) -> tuple[int, int]:
    return (0 if name[0] == "i" else 1, int(name[1:]))


class CoefficientProgram:
    """A program over Z[x] written at the level of coefficients: ``function(C)`` gives, from the
    coefficients ``C`` of the inputs (in the order of ``terms``), the tuple of the computed
    coefficients of the outputs; ``entries``: for every output (in order), its rows of entries, each
    a pair (constant terms, slots): the terms that are constants of the program's text ((monomial,
    rational) pairs) and the computed ones ((index into the tuple, monomial, c): c, a rational
    constant, times that value is the coefficient of the monomial); ``operations``: integer
    operations per run."""

    def __init__(self, source: str, entries: list, operations: int, constant_terms: bool) -> None:
        self.source, self.entries, self.operations = source, entries, operations
        #: whether some output has a term that is a constant of the program's text (then an output is
        #: not 0 when its computed coefficients are)
        self.constant_terms = constant_terms
        scope: dict[str, Any] = {}
        exec(compile(source, "<coefficient program>", "exec"), scope)   # noqa: S102 - generated from the program
        self.function = scope["coefficients"]


def coefficient_program(prog: Program, terms: list[list[tuple[tuple[int, ...], int]]], nvars: int,
                        cap: int) -> CoefficientProgram:
    """``prog`` written at the level of coefficients, for inputs whose terms are ``terms`` (per input,
    its (monomial, integer coefficient) pairs; the coefficients are the new program's inputs, in that
    order, the monomials are compiled in); ``nvars``: the length of a monomial; at most ``cap``
    integer operations per run (:class:`NotCompiled` beyond)."""
    w = _CoefficientWriter(cap)
    w.unit = (0,) * nvars
    xs, k = [], 0
    for tt in terms:
        t = {}
        for m, c in tt:
            if len(m) != nvars or type(c) is not int or not c:
                raise NotCompiled("an input term that is not a monomial of the ring with a nonzero integer coefficient")
            t[tuple(m)] = (1, f"i{k}")
            k += 1
        xs.append(_Sparse(t, w))
    scope: dict[str, Any] = {"ZERO": _Sparse({}, w), **{f"K{j}": _Sparse({w.unit: _q(c)}, w)
                                                        for j, c in enumerate(prog.constants)}}
    exec(compile(prog.source, "<straight-line program>", "exec"), scope)   # noqa: S102 - generated from the graph
    outs = scope["program"](xs)
    slots: list[str] = []
    entries = []
    has_constants = False
    for m in outs:
        rows = []
        for row in m:
            out_row = []
            for e in row:
                if type(e) is not _Sparse:
                    raise NotCompiled("an output entry that is not a polynomial")
                consts = tuple((mono, x) for mono, x in e.t.items() if type(x) is not tuple)
                has_constants = has_constants or bool(consts)
                sl = []
                for mono, x in e.t.items():
                    if type(x) is tuple:
                        sl.append((len(slots), mono, x[0]))
                        slots.append(x[1])
                out_row.append((consts, tuple(sl)))
            rows.append(tuple(out_row))
        entries.append(tuple(rows))
    live = set(slots)
    body: list[str] = []
    ops = 0
    for target, expr, reads, n_ops in reversed(w.lines):
        if target in live:
            body.append(f"    {target} = {expr}")
            live.update(reads)
            ops += n_ops
    body.reverse()
    unpack = ", ".join(f"i{j}" for j in range(k))
    src = "\n".join(["def coefficients(C):",
                     f"    {unpack}, = C" if k else "    pass",
                     *body,
                     f"    return ({', '.join(slots)},)" if slots else "    return ()"]) + "\n"
    return CoefficientProgram(src, entries, ops, has_constants)
