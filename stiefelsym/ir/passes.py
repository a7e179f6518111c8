"""Passes over a graph: what a method decides from the claim's structure, before any value exists.

* :func:`coordinate_reads`: the looks at coordinates that break the equivariance
  reduction, decided from the graph whatever spaces the claim named: an entry or
  a block of a matrix one of whose sides involves ℝⁿ (structurally: built from
  X, P, A and the other n-sided objects, or sized by plain ints), and a constant
  matrix on such a side that is not a multiple of I.
* :func:`constants`: the exact constants of the graph (for the float method's
  range check).
* :func:`parameter_free`: whether the residuals are numbers computed from the sizes
  alone (counts), so that no point of T*V enters them.
"""
from __future__ import annotations

from fractions import Fraction

from stiefelsym.ir.graph import Graph, Ref, Size
from stiefelsym.ir.trace import MATRICES

_N, _R = "n", "r"

_LEAF_SPACES = {"X": (_N, _R), "P": (_N, _R), "Y": (_N, _R), "Q": (_N, _R),
                "A": (_N, _N), "Ainv": (_N, _N), "Phi": (_N, _N), "In": (_N, _N), "xi": (_N, _N),
                "zeta": (_N, _N), "Psi": (_R, _R), "Ir": (_R, _R), "eta": (_R, _R), "theta": (_R, _R)}


class _Sides:
    """Union-find over the spaces of the rows and columns of the graph's matrices.

    A space is an atom (ℝⁿ, ℝʳ), a variable (a side sized by a plain int: unknown until an operation
    joins it to another side), a direct sum (the side of a block matrix) or opaque (a side of an
    engine value: it may be anything)."""

    N, R = 0, 1      # the atoms, made first

    def __init__(self) -> None:
        self.parent: list[int] = []
        self.atom: list[str | None] = []       # "n", "r", "opaque" or None (a variable)
        self.parts: list[tuple] = []
        #: pairs of sides joined although their splittings into direct sums differ (a side of R^r or R^n
        #: split into coordinate blocks: e_1 of R^2 as a block of 1 x 1 pieces of I and 0 used on R^r)
        self.splits: list[tuple[int, int]] = []
        #: whether a side of R^n was joined to a side of R^r (an untyped piece of an int size used on both,
        #: possible at r = n only): the graph then takes R^r for R^n
        self.n_joined_r = False

    def new(self, atom: str | None = None, parts: tuple = ()) -> int:
        self.parent.append(len(self.parent))
        self.atom.append(atom)
        self.parts.append(parts)
        return len(self.parent) - 1

    def find(self, x: int) -> int:
        while self.parent[x] != x:
            self.parent[x] = self.parent[self.parent[x]]
            x = self.parent[x]
        return x

    def union(self, a: int, b: int) -> None:
        a, b = self.find(a), self.find(b)
        if a == b:
            return
        ta, tb = self.atom[a], self.atom[b]
        if (len(self.parts[a]) > 1 or len(self.parts[b]) > 1) and not self.alike(a, b):
            self.splits.append((a, b))
        if ta == "opaque" or tb == "opaque":
            # joined with an engine value's side: a variable may now be anything (an atom stays itself)
            other = b if ta == "opaque" else a
            if self.atom[other] is None:
                self.atom[other] = "opaque"
            return
        if ta is None:
            atom = tb
        elif tb is None or ta == tb:
            atom = ta
        else:
            atom = "opaque"                     # a join of ℝⁿ and ℝʳ (n = r): either
            if {ta, tb} == {"n", "r"}:
                self.n_joined_r = True
        self.parent[b] = a
        self.atom[a] = atom
        self.parts[a] = self.parts[a] or self.parts[b]

    def _single(self, x: int) -> int:
        """The side a chain of one-part splittings ends at (a cycle of them, a side split into itself by joins of
        zero blocks, ends where it closes)."""
        x = self.find(x)
        seen = {x}
        while len(self.parts[x]) == 1:
            y = self.find(self.parts[x][0])
            if y in seen:
                break
            seen.add(y)
            x = y
        return x

    def alike(self, a: int, b: int) -> bool:
        """Whether two sides may be joined without taking one splitting into blocks for another: the same
        side, an engine value's side (it may be anything), a side not yet known (it takes the other's
        splitting), sums of alike parts, or two atoms of one kind (a sum joined to ℝⁿ or ℝʳ, a side not
        yet known paired with another part inside a sum, or ℝⁿ with ℝʳ, is not)."""
        try:
            return self._alike(a, b, frozenset())
        except RecursionError:
            return False        # splittings nested beyond the interpreter's stack: not known to be alike

    def _alike(self, a: int, b: int, seen: frozenset) -> bool:
        """:meth:`alike` below the pairs ``seen`` on the way down: every level compared, however deep (a cut at a
        depth that answered "alike" let two splittings nested 33 deep pass for one), and a pair met again on its
        own way down (a side split into itself) is not alike: the answer that keeps the coordinate read."""
        a, b = self._single(a), self._single(b)
        if a == b:
            return True
        if (a, b) in seen:
            return False
        ta, tb = self.atom[a], self.atom[b]
        if ta == "opaque" or tb == "opaque":
            return True
        pa, pb = self.parts[a], self.parts[b]
        if (ta is None and not pa) or (tb is None and not pb):
            # a side not yet known (sized by plain ints, a matrix of given entries) takes the other's
            # splitting; inside a sum its size is not known to match the part it is paired with
            return not seen
        if pa or pb:
            inner = seen | {(a, b)}
            return len(pa) == len(pb) and all(self._alike(x, y, inner) for x, y in zip(pa, pb))
        return ta == tb

    def involves_n(self, x: int, seen: frozenset = frozenset()) -> bool:
        x = self.find(x)
        if self.atom[x] in ("n", "opaque"):
            return True
        if x in seen:
            return False
        return any(self.involves_n(p, seen | {x}) for p in self.parts[x])


def _spaces(g: Graph) -> tuple["_Sides", list]:
    cached = g.cache.get("sides")
    if cached is not None:
        return cached
    S = _Sides()
    n_atom, r_atom = S.new("n"), S.new("r")
    assert (n_atom, r_atom) == (_Sides.N, _Sides.R)
    opaque = S.new("opaque")
    nv, rv = g.sizes if g.sizes is not None else (None, None)

    def atom(d: str) -> int:
        return n_atom if d == "n" else r_atom

    def sized(a) -> int:
        if type(a) is Size:
            return atom(a.d) if a.k == 1 else S.new(parts=tuple(atom(a.d) for _ in range(a.k)))
        return S.new()

    def tagged(tag: str, m) -> int:
        if tag in ("n", "r") and m is not None and m == (nv if tag == "n" else rv):
            return atom(tag)
        return S.new()

    sides: list = []

    def of(a):
        return sides[a.i] if type(a) is Ref else None

    def _square(x) -> None:
        # a trace, an inverse or a power is of a square matrix: its row and column sides are one space
        # (else a trace of Xᵀ B with B of given entries would leave B's columns unjoined to R^r)
        if x:
            S.union(x[0], x[1])

    for op, a in zip(g.ops, g.args):
        sd = None
        if op == "attr":
            if a[1] in _LEAF_SPACES:
                sd = tuple(atom(x) for x in _LEAF_SPACES[a[1]])
            elif a[1] in ("Xdot", "Pdot"):
                sd = (n_atom, r_atom)
            elif a[1] in ("Zc", "Zc_dot"):
                sd = (S.new(parts=(n_atom, n_atom)), S.new(parts=(r_atom, r_atom)))
            elif a[1] not in ("lam", "kappa", "eps"):
                sd = (opaque, opaque)
        elif op == "call":
            name, args = a[1], a[2]
            if name == "resolvent":
                sd = (n_atom, n_atom)
            elif name in ("generic", "fresh"):
                # ℝⁿ⁻ʳ is no atom: a side of its own, unknown until an operation joins it (as an int-sized zero block's)
                sd = tuple(atom(d) if d in ("n", "r") else S.new() for d in (args[1], args[2]))
            elif name == "zeros":
                sd = (sized(args[0]), sized(args[1]))
            elif name == "identity":
                x = sized(args[0])
                sd = (x, x)
            elif name == "scalar_matrix":
                x = sized(args[1])
                sd = (x, x)
            elif name == "general_params":
                sd = (sized(args[1]), sized(args[2]))
            elif name == "mat":
                rows, tags = args
                if type(rows) is Ref and g.ops[rows.i] == "list":
                    cells = g.args[rows.i]
                    m = len(cells)
                    k = len(g.args[cells[0].i]) if m and type(cells[0]) is Ref else 0
                    sd = (tagged(tags[0], m), tagged(tags[1], k))
                else:
                    sd = (S.new(), S.new())
            elif name == "conj":
                sd = of(args[0])
            elif name == "d":
                body = g.args[args[0].i][2] if type(args[0]) is Ref and g.ops[args[0].i] == "fn" else None
                sd = of(body) if type(body) is Ref and of(body) else (opaque, opaque)
            elif name == "realify":
                u, v = of(args[0]), of(args[1])
                if u and v:
                    S.union(u[0], v[0])
                    S.union(u[1], v[1])
                    sd = (S.new(parts=(u[0], u[0])), S.new(parts=(u[1], u[1])))
            elif name == "tr":
                _square(of(args[0]))
            elif name == "killing":
                # <a, b> = -1/2 tr(ab): a's columns are b's rows and b's columns a's rows
                u, v = of(args[0]), of(args[1])
                if u and v:
                    S.union(u[1], v[0])
                    S.union(u[0], v[1])
            elif name not in ("q", "const", "scalar", "bracket", "canonical_bracket"):
                sd = (opaque, opaque)
        elif op == "trace":
            _square(of(a[0]))
        elif op in ("T", "inv"):
            x = of(a[0])
            if op == "inv":
                _square(x)
            sd = (x[1], x[0]) if x else None
        elif op in ("add", "sub"):
            x, y = of(a[0]), of(a[1])
            if x and y:
                S.union(x[0], y[0])
                S.union(x[1], y[1])
            sd = _known(x, y, opaque)
        elif op == "matmul":
            x, y = of(a[0]), of(a[1])
            if x and y:
                S.union(x[1], y[0])
                sd = (x[0], y[1])
            else:
                sd = (opaque, opaque)
        elif op in ("mul", "div"):
            # a number times a matrix has the matrix's sides: a number an engine call made (s.d of a scalar
            # function) has an engine value's sides, which would hide the matrix's joins (c·I₃ with I₃ used on
            # ℝⁿ and ℝʳ at r = n)
            sd = _known(of(a[0]), of(a[1]), opaque)
        elif op in ("neg", "pow"):
            sd = of(a[0])
            if op == "pow":
                _square(sd)
        elif op == "entry":
            sd = (S.new(), S.new()) if any(type(i) is tuple for i in a[1:]) else None
        elif op == "block":
            rows, cols, blocks = a
            bs = [of(b) or (opaque, opaque) for b in blocks]
            rparts, cparts = [], []
            for i in range(rows):
                row = bs[i * cols:(i + 1) * cols]
                for b in row[1:]:
                    S.union(row[0][0], b[0])
                rparts.append(row[0][0])
            for j in range(cols):
                col = bs[j::cols]
                for b in col[1:]:
                    S.union(col[0][1], b[1])
                cparts.append(col[0][1])
            sd = (S.new(parts=tuple(rparts)), S.new(parts=tuple(cparts)))
        elif op == "item":
            # a part of a node that is none of the structured values _element reads (an entry of a row of a
            # Jacobian, say) has an engine value's sides, as _element says at its first step
            base = a[0]
            if type(base) is Ref and g.ops[base[0]] not in _STRUCTURED:
                sd = (opaque, opaque)
            else:
                sd = _element(g, base, a[1], sides, (opaque, opaque))
        elif op in ("list", "tuple", "dict", "fn"):
            sd = None
        elif op == "prim" and a[0].qualname == DERIVATIVE_STEP:
            # the derivative of F at a point along a tangent vector is shaped like F's value there (as
            # a `d` call is): its sides are those of F's body, not an engine value's
            body = _step_body(g, a)
            sd = of(body) if type(body) is Ref and of(body) else (opaque, opaque)
        elif op in ("prim", "apply", "param"):
            sd = (opaque, opaque)
        sides.append(sd)
    g.cache["sides"] = (S, sides)
    return S, sides


#: the engine step of the derivative of a function at a point of the caller's own along a tangent vector
#: (``systems.derivative(s, F, z, v)``): its value has the shape of F's value
DERIVATIVE_STEP = "stiefelsym.systems.derivative"


def _known(x, y, opaque: int):
    """The sides of a sum or a product by a number: the operand's whose sides the pass knows (not an engine
    value's), else either."""
    if x and y and x == (opaque, opaque):
        return y
    return x or y


def _step_body(g: Graph, a: tuple):
    """The body of the function a derivative step differentiates (None where the graph does not say)."""
    f = a[2] if len(a) > 2 else None
    if type(f) is Ref and g.ops[f.i] == "fn":
        return g.args[f.i][2]
    return None


#: the ops of the nodes whose parts :func:`_element` looks into (a part of any other node has the default sides)
_STRUCTURED = frozenset({"list", "tuple", "dict", "param", "call", "prim"})


def _element(g: Graph, base: Ref, key, sides: list, default):
    """The sides of a part of a structured value, where the graph says what it is: a part of a
    container, of a parameter shaped like a point of the claim's, of a derivative of a function
    (shaped like the function's value), of a gradient (two n x r matrices)."""
    for _ in range(64):
        op, a = g.ops[base.i], g.args[base.i]
        if op in ("list", "tuple"):
            if type(key) is int and 0 <= key < len(a):
                el = a[key]
                return sides[el.i] if type(el) is Ref else None
            return default
        if op == "dict":
            keys, vals = a
            if key in keys:
                el = vals[keys.index(key)]
                return sides[el.i] if type(el) is Ref else None
            return default
        if op == "param" and len(a) == 3 and type(a[2]) is Ref:
            base = a[2]
            continue
        if op == "call" and a[1] == "d":
            f = a[2][0]
            base = g.args[f.i][2]
            continue
        if op == "prim" and a[0].qualname == DERIVATIVE_STEP and type(_step_body(g, a)) is Ref:
            base = _step_body(g, a)
            continue
        if op == "call" and a[1] == "gradient":
            return (_Sides.N, _Sides.R)
        return default
    return default


#: engine steps whose values are coordinates (unit matrices of a basis): reading them is reading
#: entries, whatever the claim does with them (a product and a trace read an entry just the same)
COORDINATE_STEPS = frozenset({"stiefelsym.systems.real_coordinates", "stiefelsym.systems.complex_coordinates"})

#: the read of a block matrix used as a matrix on ℝⁿ (see :func:`coordinate_reads`)
BLOCK_SPLITTING = "a block splitting of R^n"
#: the read of a space split into blocks in two different ways (see :func:`coordinate_reads`)
TWO_SPLITTINGS = "a space split into blocks in two ways"


def coordinate_reads(g: Graph) -> dict[str, frozenset]:
    """The looks at coordinates the graph makes that break the equivariance reduction by O(n)
    (each with the spaces it involves), whatever spaces the claim named:

    * an entry or a block of a matrix with a side on ℝⁿ (or on an engine value's side);
    * a matrix of given entries (``s.mat``) with a side on ℝⁿ: not a multiple of I (a matrix of
      fresh parameters, ``s.general_params``, is generic and moves with O(n));
    * a block matrix used as a matrix on ℝⁿ (a splitting of ℝⁿ into coordinate blocks);
    * a side split into blocks in two different ways, or ℝⁿ (ℝʳ) joined to a sum of pieces (ℝⁿ ⊕ ℝʳ taken
      for ℝʳ ⊕ ℝⁿ: [X; 0]ᵀ[I_r; 0] is the top r × r block of X).
    Entries of ℝʳ-sided matrices are recorded too (for charts that also reduce by O(r))."""
    cached = g.cache.get("reads")
    if cached is not None:
        return cached
    S, sides = _spaces(g)
    reads: dict[str, frozenset] = {}

    def add(what: str, inv: set) -> None:
        reads[what] = reads.get(what, frozenset()) | frozenset(inv)

    def spaces_of(sd) -> set:
        out = set()
        for x in sd:
            if S.involves_n(x):
                out.add("n")
            root = S.find(x)
            if S.atom[root] == "r":
                out.add("r")
        return out

    # nodes the claim's own algebra reads (an engine step handed a coordinate basis uses it inside a
    # covariant construction, e.g. Euler–Lagrange equations in coordinates; claim algebra on it reads
    # coordinates)
    claim_uses: set | None = None      # computed when a coordinate step is met
    for i, (op, a) in enumerate(zip(g.ops, g.args)):
        if op == "entry":
            sd = sides[a[0].i] if type(a[0]) is Ref else None
            inv = spaces_of(sd) if sd else {"n"}
            if inv:
                add("an entry or a block of a matrix on " + _text(inv), inv)
        elif op == "call" and a[1] == "mat" and sides[i]:
            inv = spaces_of(sides[i]) & {"n"}
            if inv:
                add("a constant matrix on R^n", inv)
        elif op == "prim" and a[0].qualname in COORDINATE_STEPS:
            if claim_uses is None:
                claim_uses = {j for k, op_k in enumerate(g.ops) if op_k != "prim" for j in g.refs(k)}
            if i in claim_uses:
                add("the coordinate basis of R^n (an engine step)", {"n"})
        elif op == "block" and sides[i]:
            if any(S.atom[S.find(x)] in ("n", "opaque") for x in sides[i]):
                add(BLOCK_SPLITTING, {"n"})
    # a side split into blocks in two ways (ℝⁿ ⊕ ℝʳ taken for ℝʳ ⊕ ℝⁿ: [X; 0]ᵀ[I_r; 0] is the top r x r block
    # of X, with no block that has a side on ℝⁿ alone), or ℝⁿ / ℝʳ itself taken for a sum of pieces
    for pair in S.splits:
        inv = {"n"} if any(S.involves_n(x) for x in pair) else set()
        if any(_involves_r(S, x) for x in pair):
            inv.add("r")
        if inv:
            add(TWO_SPLITTINGS, inv)
    g.cache["reads"] = reads
    return reads


#: the leaves a graph covariant under O(r) acting on the right may read: the point (X, P), what is built
#: from it (Φ, Ψ), A, its inverse and eigenvalues, identities, generic elements and the scalar parameters
#: (a second, complex or double point, velocities and other engine leaves are not admitted)
RIGHT_LEAVES = frozenset({"X", "P", "Phi", "Psi", "A", "Ainv", "a", "In", "Ir", "xi", "zeta", "eta",
                          "lam", "kappa", "eps"})
#: the scene's calls whose values move with O(r) acting on the right when their arguments do (a generic
#: matrix moves with it and stays generic; a matrix of given entries is checked by its sides)
RIGHT_CALLS = frozenset({"generic", "fresh", "zeros", "identity", "scalar_matrix", "general_params", "mat",
                         "resolvent", "tr", "killing", "q", "const", "scalar", "d", "dirac_flow", "bracket"})
#: engine steps whose value is a constant matrix on R^n alone (no side on R^r): S_1, diag(I_2, 0)
RIGHT_STEPS = frozenset({"stiefelsym.twisted.reflection", "stiefelsym.twisted.eigenspace_projector"})


def right_action_breaks(g: Graph) -> list[str]:
    """What in the graph may break covariance under O(r) acting on the right, (X, P) -> (Xh, Ph), h in
    O(r), every R^r side of a generic matrix moving with h (empty: none).  A graph whose leaves move
    with h (:data:`RIGHT_LEAVES`), whose calls are the typed covariant ones (:data:`RIGHT_CALLS`), whose
    engine steps are constants on R^n (:data:`RIGHT_STEPS`), and which reads no entry or block of a
    matrix with a side on R^r (or on an engine value's side), builds no matrix of given entries with
    a side on R^r and takes no rank or count, computes with typed matrix operations only, each of which
    commutes with the action: its residuals are covariant, whatever it reads of R^n.  A side of R^r is
    also reached by a block of a matrix on R^n alone whose result meets R^r (rows 0..r-1 of I_n times X),
    by a direct sum joined to R^r (e_1 of R^2 as a block of 1 x 1 pieces of I and 0) or two different
    splittings of a side on R^r joined, and by a matrix of given entries paired with R^r only through a
    trace (tr(X^T B): a trace, a pairing, an inverse and a power join their matrix's two sides)."""
    S, sides = _spaces(g)

    def on_r(sd) -> bool:
        if not sd:
            return True          # a side the pass does not know: it may be R^r
        return any(_involves_r(S, x) for x in sd)

    out: dict[str, None] = {}
    for i, (op, a) in enumerate(zip(g.ops, g.args)):
        if op == "attr" and a[1] not in RIGHT_LEAVES:
            out[f"the leaf {a[1]}"] = None
        elif op == "call" and a[1] not in RIGHT_CALLS:
            out[f"the engine call {a[1]}"] = None
        elif op == "call" and a[1] == "mat" and on_r(sides[i]):
            out["a matrix of given entries on R^r"] = None
        elif op == "entry" and on_r(sides[a[0].i] if type(a[0]) is Ref else None):
            out["an entry or a block of a matrix on R^r"] = None
        elif op == "entry" and sides[i] and on_r(sides[i]):
            # a block of a matrix on R^n alone used on R^r (rows 0..r-1 of I_n times X: the top block X1)
            out["a block of a matrix used on R^r"] = None
        elif op == "prim" and a[0].qualname not in RIGHT_STEPS:
            out["an engine step"] = None
        elif op in ("rank", "count", "apply"):
            out[f"a {op}"] = None
    if any(_involves_r(S, x) for pair in S.splits for x in pair):
        out["a splitting of R^r into blocks"] = None
    if S.n_joined_r:
        # at r = n an untyped piece of an int size may meet R^n and R^r (X E with E = s.identity(3), then
        # X E - (X E)^T): X taken for a matrix on R^n reads what moves with h (X = I on the square chart)
        out["R^r taken for R^n (an untyped piece joined to both)"] = None
    return list(out)


def _involves_r(S: "_Sides", x: int, seen: frozenset = frozenset()) -> bool:
    """Whether a side may involve R^r: R^r, an engine value's side, or a sum with such a part."""
    x = S.find(x)
    if S.atom[x] in ("r", "opaque"):
        return True
    if x in seen:
        return False
    return any(_involves_r(S, p, seen | {x}) for p in S.parts[x])


def _text(inv) -> str:
    return " and ".join({"n": "R^n", "r": "R^r"}[x] for x in sorted(inv))


def constants(g: Graph) -> list:
    """The exact constants of the graph (ints and Fractions in any argument)."""
    out = []

    def walk(x):
        if type(x) is tuple:
            for y in x:
                walk(y)
        elif type(x) in (int, Fraction) and type(x) is not bool:
            out.append(x)
    for a in g.args:
        walk(a)
    return out


def power_exponents(g: Graph) -> int:
    """The product of |k| over the graph's powers x^k (1 where it has none): a structural degree can exceed the
    degree of the graph's products only by this factor, each power multiplying the degree of its base by |k|."""
    cached = g.cache.get("powers")
    if cached is None:
        cached = 1
        for op, a in zip(g.ops, g.args):
            if op == "pow" and len(a) > 1 and type(a[1]) is int:
                cached *= max(1, abs(a[1]))
        g.cache["powers"] = cached
    return cached


#: the nodes whose value's degree is at most the sum of their arguments' (a product, a quotient, an inverse)
PRODUCT_OPS = frozenset({"mul", "matmul", "div", "inv", "inverse", "right_inverse"})
#: where :func:`product_degree` stops counting
PRODUCT_DEGREE_CAP = 1 << 64


def product_degree(g: Graph) -> int:
    """A rough degree of the graph's products: every node reading no other node 1, a product (:data:`PRODUCT_OPS`)
    the sum of its arguments', a power x^k |k| times its base's (so that products and powers in a row multiply:
    fourteen squarings then a power 256 pass each gate alone), any other node (a call's arguments in their tuples
    included) the largest of its arguments' (capped at :data:`PRODUCT_DEGREE_CAP`).
    Not a bound (an engine step or an inverse multiplies degrees by a size), but the part of the degree that grows
    through products written in a row: x = x * x forty times is u^(2^40) with no power node, where a product of
    twenty matrices is 20."""
    cached = g.cache.get("product degree")
    if cached is None:
        deg: list[int] = []
        for op, a in zip(g.ops, g.args):
            refs = [deg[j] for j in Graph._nested(a)]
            if not refs:
                d = 1
            elif op in PRODUCT_OPS:
                d = min(sum(refs), PRODUCT_DEGREE_CAP)
            elif op == "pow" and len(a) > 1 and type(a[1]) is int:
                d = min(max(refs) * max(1, abs(a[1])), PRODUCT_DEGREE_CAP)     # k products of the base in one node
            else:
                d = max(refs)
            deg.append(d)
        cached = g.cache["product degree"] = max(deg, default=0)
    return cached


#: the exponent range in which a constant's float64 value and its error term are normal numbers
FLOAT_EXPONENT_LIMIT = 1000


def outside_float_range(g: Graph) -> list:
    """The constants of the graph that float64 cannot carry with a meaningful error term (|c| above
    2^1000, or nonzero below 2^-1000): the float method starts at high precision instead."""
    cached = g.cache.get("wide")
    if cached is None:
        hi, lo = Fraction(2) ** FLOAT_EXPONENT_LIMIT, Fraction(1, 2 ** FLOAT_EXPONENT_LIMIT)
        cached = g.cache["wide"] = [c for c in constants(g) if c and not lo < abs(Fraction(c)) < hi]
    return cached


#: what an engine step reads, for the steps that need coordinates (by the step's function name)
_STEP_NEEDS = {
    "double_point": "a generic point of the double Neumann system (X = X₀DU in coordinates)",
    "complex_coordinates": "the real coordinates of complex matrices",
    "real_coordinates": "the coordinates of the matrices of a phase space",
    "hamiltonian_flow": "a Hamiltonian flow solved in coordinates",
    "euler_lagrange": "Euler–Lagrange equations solved in coordinates",
    # the twisted brackets of the scalar constraints, indexed by a basis of Sym(r)
    "constraint_bracket_matrix": "a Jacobian in the coordinates of X, P",
}


def coordinate_needs(g: Graph) -> list[str]:
    """What a graph traced at a fixed size reads that a statement for every n, r cannot: the
    reasons, in a mathematician's terms, why the dimension-free method leaves the claim to the
    fixed-size methods (empty when the graph reads none of them)."""
    out: dict[str, None] = {}
    ops = set(g.ops)
    if "rank" in ops:
        out["a rank (a dimension at fixed n, r)"] = None
    if "count" in ops:
        out["a count of dimensions at fixed n, r"] = None
    for i, (op, a) in enumerate(zip(g.ops, g.args)):
        if op == "attr" and a[1] == "a":
            out["the eigenvalues a_i of A"] = None
        elif op == "call" and a[1] in ("jacobian", "constraint_bracket_matrix"):
            out["a Jacobian in the coordinates of X, P"] = None
        elif op == "prim":
            name = a[0].qualname.rsplit(".", 1)[-1]
            if name in _STEP_NEEDS:
                out[_STEP_NEEDS[name]] = None
        elif op == "call" and a[1] == "mat":
            out[_GIVEN] = None
    for what in coordinate_reads(g):
        out[what.replace("an entry or a block", "entries")] = None
    if "a constant matrix on R^n" in out:
        out.pop(_GIVEN, None)
    return list(out)


_GIVEN = "a matrix of given entries (basis vectors, projectors, coordinate matrices)"


#: the leaves whose values are the same at every r for a fixed n: A, its inverse, its eigenvalues, I_n,
#: the generic elements ξ, ζ of so(n) and the scalar parameters (every point of T*V, Φ and Ψ included, has
#: a side on ℝʳ or is built from one)
R_FREE_LEAVES = frozenset({"A", "Ainv", "a", "In", "xi", "zeta", "lam", "kappa", "eps"})
#: the scene's calls whose values depend on r only through their arguments (sizes and index spaces,
#: which the pass checks): generic parameters, constants, pairings, the resolvent of A
R_FREE_CALLS = frozenset({"generic", "fresh", "zeros", "identity", "scalar_matrix", "general_params", "mat",
                          "resolvent", "tr", "killing", "q", "const", "scalar", "sym_operator"})
#: the engine steps that evaluate a function of the claim on a space of the claim's choice (gl(n), so(n):
#: the index space is an argument, which the pass checks) and read nothing else of the scene
R_FREE_STEPS = frozenset({"stiefelsym.brackets.form_gradient", "stiefelsym.brackets.polynomial_gradient",
                          "stiefelsym.brackets.tensor_value", "stiefelsym.brackets.symmetric_operator_check",
                          "stiefelsym.brackets.gradient_check"})
#: the operations that compute from their arguments alone
_R_FREE_OPS = frozenset({"scene", "param", "fn", "apply", "add", "sub", "neg", "mul", "rmul", "div", "rdiv",
                         "pow", "matmul", "T", "inv", "trace", "entry", "item", "block", "list", "tuple", "dict",
                         "kw", "rank", "count", "inverse", "right_inverse"})


def _mentions_r(x) -> bool:
    """Whether an argument holds a size in r or the index space "r" (of a generic matrix, a tag, a space)."""
    t = type(x)
    if t is tuple:
        return any(_mentions_r(y) for y in x)
    if t is Size:
        return x.d == _R
    return t is str and x in (_R, "n-r")


#: operations whose value, in a graph at fixed sizes, is a number or container of numbers given outright
_NUMBER_OPS = frozenset({"dict", "count", "const", "tuple", "list"})


def parameter_free(g: Graph) -> bool:
    """Whether every node the output reads is a count of numbers, an exact constant or a container of these
    (a graph at fixed sizes whose checks are Counts of plain integers): no leaf of the scene (X, P, A, λ, …),
    no call of it and no engine step enters the residuals, so their values are the same at every point and
    an exact evaluation of them is the computation of a few integers, at any size."""
    cached = g.cache.get("parameter-free")
    if cached is None:
        needed = g.needed()
        cached = bool(needed) and all(g.ops[i] in _NUMBER_OPS for i in needed)
        g.cache["parameter-free"] = cached
    return cached


def r_dependence(g: Graph) -> str:
    """Why the graph's value may depend on r at a fixed n ("" when it cannot): a node with a size in r or
    the index space ℝʳ, a leaf that is not on ℝⁿ alone (X, P, Φ, Ψ, I_r, η ... or an attribute the pass
    does not know), a call of the scene or an engine step outside the short lists above, an operation it
    does not know.  A graph with symbolic sizes is then the same graph at every (n, r); a graph traced at
    (n, r) may hold r's number as a plain int (a claim that read int(s.r)): its value is the same at every
    r only where the claim's graphs at those sizes are the same (the runner compares them)."""
    cached = g.cache.get("r-dependence")
    if cached is not None:
        return cached
    why = ""
    for i, (op, a) in enumerate(zip(g.ops, g.args)):
        if why:
            break
        if _mentions_r(a):
            why = f"node %{i} ({op}) involves the dimension r"
        elif op == "attr":
            if a[1] not in R_FREE_LEAVES:
                why = f"node %{i} reads {a[1]}"
        elif op == "call":
            if a[1] not in R_FREE_CALLS:
                why = f"node %{i} calls {a[1]}"
        elif op == "prim":
            if a[0].qualname not in R_FREE_STEPS:
                why = f"node %{i} is the engine step {a[0].qualname}"
        elif op not in _R_FREE_OPS:
            why = f"node %{i} is an operation {op}"
    g.cache["r-dependence"] = why
    return why


#: the scene's matrices that are skew at every point: the generic elements ξ, ζ of so(n) and η of so(r), and
#: the momentum maps Φ = PXᵀ − XPᵀ, Ψ (a difference of a matrix and its transpose, on and off T*V)
_SKEW_LEAVES = frozenset({"eta", "theta", "xi", "zeta", "Phi", "Psi"})
#: the scene's numbers (stiefelsym.ir.trace.NUMBERS)
_SCALAR_LEAVES = frozenset({"lam", "eps", "kappa"})
#: engine steps whose value is skew: the magnetic form's F = E₁∧E₂
_SKEW_STEPS = frozenset({"stiefelsym.twisted.magnetic_matrix"})


def skew_by_construction(g: Graph, x) -> bool:
    """Whether the matrix of node ``x`` is skew (Mᵀ = −M) by its construction alone: a generic skew matrix
    (``s.generic(name, m, m, "skew")``), a skew leaf of the scene (:data:`_SKEW_LEAVES`), a zero matrix, the
    magnetic form's F, M − Mᵀ, an explicit matrix with zeros on its diagonal and opposite entries (equal
    constants, or an entry and its negation) across it, and sums, differences, negations, transposes and
    multiples of these by numbers (the scene's numbers, traces, pairings, and entries of matrices by
    construction: F = η₀₁·J).  Decided from the graph, the same for every method and at every size; a
    skew matrix built otherwise (a product gAgᵀ of a skew A, or entries equal only as functions) is not
    recognised (False), so an engine step that needs a skew matrix refuses it with one message everywhere."""
    memo: dict[int, bool] = {}

    def skew(a) -> bool:
        if type(a) is not Ref:
            return False
        k = a[0]
        hit = memo.get(k)
        if hit is None:
            memo[k] = False                          # a cycle (none in a graph) is not skew
            hit = memo[k] = _skew_node(k)
        return hit

    def _skew_node(k: int) -> bool:
        op, args = g.ops[k], g.args[k]
        if op == "attr":
            return args[1] in _SKEW_LEAVES
        if op == "call":
            name, cargs = args[1], args[2]
            if name == "generic":
                return len(cargs) == 4 and cargs[3] == "skew"
            if name == "zeros":
                return len(cargs) >= 2 and cargs[0] == cargs[1]
            if name == "mat":
                return _skew_rows(cargs[0] if cargs else None)
            return False
        if op == "prim":
            return args[0].qualname in _SKEW_STEPS
        if op in ("neg", "T"):
            return skew(args[0])
        if op in ("add", "sub"):
            a, b = args
            if op == "sub" and type(a) is Ref and type(b) is Ref and (
                    _transpose_of(b) == a[0] or _transpose_of(a) == b[0]):
                return True                          # M − Mᵀ, Mᵀ − M
            return skew(a) and skew(b)
        if op == "mul":
            a, b = args
            return (skew(a) and _scalar(b)) or (skew(b) and _scalar(a))
        if op == "div":
            return skew(args[0]) and _scalar(args[1])
        return False

    def _transpose_of(a: Ref) -> int | None:
        k = a[0]
        return g.args[k][0][0] if g.ops[k] == "T" and type(g.args[k][0]) is Ref else None

    def _scalar(a) -> bool:
        if type(a) in (int, Fraction):
            return True
        if type(a) is not Ref:
            return False
        op, args = g.ops[a[0]], g.args[a[0]]
        if op == "attr":
            return args[1] in _SCALAR_LEAVES
        if op == "item":                             # an eigenvalue a_i of A
            b = args[0]
            return type(b) is Ref and g.ops[b[0]] == "attr" and g.args[b[0]][1] == "a"
        if op == "call":
            return args[1] in ("tr", "scalar", "q", "killing")
        if op == "entry":                            # M[i, j] at int indices of a matrix by construction
            m = args[0]
            return type(args[1]) is int and type(args[2]) is int and type(m) is Ref and _matrix(m)
        if op in ("neg",):
            return _scalar(args[0])
        if op in ("add", "sub", "mul", "div"):
            return _scalar(args[0]) and _scalar(args[1])
        return False

    def _matrix(a: Ref) -> bool:
        """Whether node a is a matrix by its construction: a matrix of the scene, a product of two (@ takes
        matrices only), a generic, zero, identity or explicit matrix, or a skew one by construction."""
        op, args = g.ops[a[0]], g.args[a[0]]
        if op == "attr":
            return args[1] in MATRICES
        if op == "matmul":
            return True
        if op == "call":
            return args[1] in ("generic", "zeros", "identity", "mat")
        return skew(a)

    def _negation(a, b) -> bool:
        if type(a) in (int, Fraction) and type(b) in (int, Fraction):
            return a == -b
        return any(type(u) is Ref and g.ops[u[0]] == "neg" and g.args[u[0]][0] == v for u, v in ((a, b), (b, a)))

    def _skew_rows(rows) -> bool:
        if type(rows) is not Ref or g.ops[rows[0]] != "list":
            return False
        body = []
        for row in g.args[rows[0]]:
            if type(row) is not Ref or g.ops[row[0]] != "list":
                return False
            body.append(g.args[row[0]])
        m = len(body)
        if any(len(row) != m for row in body):
            return False
        for i in range(m):
            if not (type(body[i][i]) in (int, Fraction) and body[i][i] == 0):
                return False
            for j in range(i + 1, m):
                if not _negation(body[i][j], body[j][i]):
                    return False
        return True

    return skew(x)
