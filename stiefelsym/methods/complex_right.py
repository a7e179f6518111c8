"""The complex point of the exact method reduced by U(r) acting on the right.

The point (Z, Ż) of TW(n, r) (realified, 2n × 2r) is the first r columns of the unitary Cayley
transform of S = [[S11, −K*], [K, 0]] (S11 skew-Hermitian), Z = [I − S11 − K*K; −2K] M⁻¹ with
M = I + S11 + K*K: the r² real parameters of S11 enter every entry of Z through det M, and at
(3, 3) the chart needs a realified 6 × 6 inverse.  Where the graph is covariant under
(Z, Ż) ↦ (Z R(h), Ż R(h)), h ∈ U(r) (R(h) the realified h; :func:`unitary_right_breaks` finds
nothing), the chart with S11 = 0 suffices: the points Z(K) h fill a dense open set of W(n, r).  Then
M⁻¹ = I − K*(I + KK*)⁻¹K where n − r < r (Woodbury: an (n − r) × (n − r) complex inverse, a scalar
1/(1 + |K|²) at n − r = 1; M⁻¹ itself, r × r complex, otherwise), and at r = n the chart is Z = I, Ż = W (W skew-Hermitian).

The pass types every value of the graph: a matrix has a row and a column side, each an R^n side
(nothing acts on it) or a realified C^r side on which h acts as R(h) or, after a conjugation, as
R(h̄) = J R(h) J (J = diag(I, −I)); a number is invariant.  Products, sums and traces must join sides
that move alike (a parity union-find: a conjugation flips the parity, a side joined to itself with
odd parity, or a side of R^n joined to one that moves, breaks covariance); multiples of the identity
(I, λI, realify(cI, dI), 0) commute with both R(h) and R(h̄) and join nothing.  A block matrix's sides are split
into parts, joined part by part: a type carries the sizes of its parts (computed from n and r), and two splittings
are joined only where their parts have the same sizes (a picker split (1, 4r − 1) against the columns (2r, 2r) of
[Z, Z] reads one column of Z); a conjugation of a split side (J of the whole side, not of each part) breaks.  Anything else (an entry,
a leaf other than the complex point, A, I_n, I_r and the scalars, an engine call or step not listed)
breaks covariance.
"""
from __future__ import annotations

from typing import Any

from stiefelsym.ir.graph import Ref, Size

#: the reduction stated in the record of a run whose complex point is reduced by U(r)
REDUCTION = (
    "; the point (Z, Zdot) of TW(n, r), realified, reduced by U(r) acting on the right: Z = [I - K*K; -2K] M^{-1}, "
    "M = I + K*K (M^{-1} = I - K*(I + KK*)^{-1}K where n - r < r; K generic complex (n - r) x r; the first r columns of the unitary "
    "Cayley transform of [[S11, -K*], [K, 0]] at S11 = 0; at r = n, Z = I), Zdot = ZW' + (I - ZZ*)Y' (W' skew-Hermitian, Y' generic with its first r rows 0).  "
    "The map (K, h) -> Z(K)h, h in U(r), has an injective differential at (0, I) onto the tangent space of the "
    "irreducible W(n, r) (dK gives [0; -2dK], h = exp(eta) gives [eta; 0], eta skew-Hermitian), and (Z(K)h, Zdot h) "
    "is every tangent vector at Z(K)h (W' -> h*W'h, Y' -> Y'h): the chart moved by U(r) is dense in TW(n, r).  The "
    "residuals are covariant under (Z, Zdot) -> (Z R(h), Zdot R(h)) (R(h) realified), because the graph reads the "
    "complex point, A, I_n, I_r and scalars only, through typed matrix operations that join the realified C^r "
    "sides consistently (R(h) and, after a conjugation, R(conj h); multiples of the identity commute with both): "
    "no entry, no other point, no engine step but constants on R^n and derivatives along tangent vectors that "
    "move as the point")

#: the leaves the pass types
_NSIDE_LEAVES = frozenset({"A", "Ainv"})
_SCALAR_MATRIX_LEAVES = frozenset({"In", "Ir"})
_SCALAR_LEAVES = frozenset({"lam", "kappa", "eps"})
#: engine steps that are constant matrices on R^n
_NSIDE_STEPS = frozenset({"stiefelsym.twisted.reflection", "stiefelsym.twisted.eigenspace_projector"})
_DERIVATIVE = "stiefelsym.systems.derivative"


class _Break(Exception):
    pass


class _UF:
    """Sides: a union-find with the parity of each side to its class's root; a class may contain the
    side that moves with R(h) (``H``) or the sides of R^n (``N``)."""

    H, N = 0, 1

    def __init__(self) -> None:
        self.parent = [0, 1]
        self.parity = [0, 0]
        self.odd = [False, False]      # a class in which a side met itself with odd parity

    def new(self) -> int:
        self.parent.append(len(self.parent))
        self.parity.append(0)
        self.odd.append(False)
        return len(self.parent) - 1

    def find(self, x: int) -> tuple[int, int]:
        p = 0
        while self.parent[x] != x:
            p ^= self.parity[x]
            x = self.parent[x]
        return x, p

    def union(self, a: int, b: int, par: int = 0) -> None:
        (ra, pa), (rb, pb) = self.find(a), self.find(b)
        if ra == rb:
            if pa ^ pb != par:
                self.odd[ra] = True
        else:
            if rb in (self.H, self.N):
                ra, rb, pa, pb = rb, ra, pb, pa
            self.parent[rb] = ra
            self.parity[rb] = pa ^ pb ^ par
            self.odd[ra] = self.odd[ra] or self.odd[rb]
        root = self.find(a)[0]
        if self.find(self.H)[0] == self.find(self.N)[0]:
            raise _Break("a side of R^n joined to a side of C^r that moves with U(r)")
        if root == self.find(self.H)[0] and self.odd[root]:
            raise _Break("a side of C^r joined to its conjugate")


class _M:
    """A matrix's type: its two sides (an int, or a tuple of them for a block matrix), whether it is a
    multiple of the identity (commutes with R(h) and R(conj h), joins nothing), and the sizes of its sides
    (an int, or the tuple of its parts' sizes for a block matrix: two splittings are joined part by part only
    where their parts have the same sizes)."""

    __slots__ = ("row", "col", "scal", "rs", "cs")

    def __init__(self, row: Any, col: Any, scal: bool = False, rs: Any = None, cs: Any = None) -> None:
        self.row, self.col, self.scal, self.rs, self.cs = row, col, scal, rs, cs


def _total(s: Any) -> int:
    return sum(s) if type(s) is tuple else s


def _aligned(a: Any, b: Any) -> None:
    """Two sides joined: a splitting into parts is joined to another part by part, so their parts must have the
    same sizes (a picker split (1, 4r − 1) joined to the columns (2r, 2r) of [Z, Z] reads one column of Z)."""
    if a is None or b is None:
        raise _Break("a matrix of unknown size")
    if (type(a) is tuple or type(b) is tuple) and a != b:
        raise _Break("block matrices joined across parts of different sizes")


_SCALAR = "scalar"


def _join(U: _UF, a: Any, b: Any, par: int = 0) -> None:
    if type(a) is tuple or type(b) is tuple:
        if not (type(a) is tuple and type(b) is tuple and len(a) == len(b)):
            raise _Break("a block matrix joined to a matrix of another splitting")
        for x, y in zip(a, b):
            _join(U, x, y, par)
    else:
        U.union(a, b, par)


def _flip(U: _UF, a: Any) -> Any:
    """A side that moves with the conjugate of what ``a`` moves with."""
    if type(a) is tuple:
        return tuple(_flip(U, x) for x in a)
    b = U.new()
    U.union(b, a, 1)
    return b


def _nside(U: _UF, a: Any) -> None:
    if type(a) is tuple:
        for x in a:
            _nside(U, x)
    else:
        U.union(a, U.N)


def unitary_right_breaks(g: Any, n: int | None = None, r: int | None = None) -> list[str]:
    """What in the graph may break covariance under U(r) acting on the right of the complex point (empty:
    nothing); see the module's docstring.  The sizes (n, r) are the graph's own by default."""
    if n is None or r is None:
        if g.sizes is None:
            return ["a graph of symbolic sizes"]
        n, r = g.sizes
    U = _UF()
    types: list[Any] = []

    def of(a: Any) -> Any:
        if type(a) is Ref:
            t = types[a.i]
            if t is None:
                raise _Break("a value of an untyped node")
            return t
        if isinstance(a, (int, float)) or type(a).__name__ == "Fraction" or type(a) is Size:
            return _SCALAR
        raise _Break(f"an argument {type(a).__name__}")

    def mat(t: Any) -> _M:
        if not isinstance(t, _M):
            raise _Break("a matrix operation on a value that is not a matrix")
        return t

    def scalar_matrix(rs: Any, cs: Any) -> _M:
        if not (type(rs) is int and type(cs) is int):
            raise _Break("a multiple of the identity of a size that is not an int")
        v = U.new()
        return _M(v, v, True, rs, cs)

    def size(args: Any, kwargs: Any, i: int, name: str) -> int:
        """The int size given to an engine call as its i-th argument or by name."""
        x = args[i] if len(args) > i else dict(kwargs or ()).get(name)
        if type(x) is Size and x.d in ("n", "r") and type(x.k) is int:
            v = x.k * (n if x.d == "n" else r)
            if x.value is not None and x.value != v:
                raise _Break("a size traced at another size")
            return v
        if type(x) is not int:
            raise _Break("a size that is not an int")
        return x

    fn_params: dict[int, list[Any]] = {}
    try:
        for i, (op, a) in enumerate(zip(g.ops, g.args)):
            t: Any = None
            if op == "scene":
                t = "scene"
            elif op == "attr":
                name = a[1]
                if of(a[0]) != "scene":
                    raise _Break(f"the attribute {name} of a value that is not the scene")
                if name in ("Zc", "Zc_dot"):
                    t = _M(U.N, U.H, False, 2 * n, 2 * r)
                elif name in _NSIDE_LEAVES:
                    t = _M(U.N, U.N, False, n, n)
                elif name in _SCALAR_MATRIX_LEAVES:
                    t = scalar_matrix(n, n) if name == "In" else scalar_matrix(r, r)
                elif name in _SCALAR_LEAVES:
                    t = _SCALAR
                else:
                    raise _Break(f"the leaf {name}")
            elif op == "call":
                name, args = a[1], a[2]
                kw = a[3] if len(a) > 3 else ()
                if of(a[0]) != "scene":
                    raise _Break(f"the call {name} on a value that is not the scene")
                if name == "conj":
                    x = mat(of(args[0]))
                    if type(x.row) is tuple or type(x.col) is tuple:
                        # J = diag(I, −I) of the whole side, not of each part
                        raise _Break("a conjugation of a block matrix")
                    t = x if x.scal else _M(_flip(U, x.row), _flip(U, x.col), False, x.rs, x.cs)
                elif name == "realify":
                    x, y = mat(of(args[0])), mat(of(args[1]))
                    if type(x.rs) is not int or type(x.cs) is not int:
                        raise _Break("a realification of a block matrix")
                    if x.scal and y.scal:
                        t = scalar_matrix(2 * x.rs, 2 * x.cs)
                    else:
                        for z in (x, y):
                            if not z.scal:
                                _nside(U, z.row)
                                _nside(U, z.col)
                        t = _M(U.N, U.N, False, 2 * x.rs, 2 * x.cs)
                elif name in ("q", "const", "scalar"):
                    t = _SCALAR
                elif name == "identity":
                    t = scalar_matrix(size(args, kw, 0, "m"), size(args, kw, 0, "m"))
                elif name == "zeros":
                    t = scalar_matrix(size(args, kw, 0, "m"), size(args, kw, 1, "k"))
                elif name == "scalar_matrix":
                    c0 = args[0] if args else dict(kw or ()).get("c")
                    if of(c0) != _SCALAR:
                        raise _Break("a multiple of the identity by a value that is not a number")
                    t = scalar_matrix(size(args, kw, 1, "m"), size(args, kw, 1, "m"))
                elif name == "resolvent":
                    t = _M(U.N, U.N, False, n, n)
                elif name == "tr":
                    x = mat(of(args[0]))
                    _aligned(x.rs, x.cs)
                    _join(U, x.row, x.col)
                    t = _SCALAR
                else:
                    raise _Break(f"the engine call {name}")
            elif op == "T":
                x = mat(of(a[0]))
                t = _M(x.col, x.row, x.scal, x.cs, x.rs)
            elif op == "neg":
                x = of(a[0])
                t = x if x == _SCALAR else mat(x)
            elif op in ("add", "sub"):
                x, y = of(a[0]), of(a[1])
                if x == _SCALAR and y == _SCALAR:
                    t = _SCALAR
                else:
                    x, y = mat(x), mat(y)
                    if x.scal and y.scal:
                        t = scalar_matrix(_total(x.rs), _total(x.cs))
                    elif x.scal or y.scal:
                        z, s = (y, x) if x.scal else (x, y)
                        _aligned(z.rs, z.cs)
                        _join(U, z.row, z.col)        # cI + M: M's sides move alike
                        t = _M(z.row, z.col, False, z.rs, z.cs)
                    else:
                        _aligned(x.rs, y.rs)
                        _aligned(x.cs, y.cs)
                        _join(U, x.row, y.row)
                        _join(U, x.col, y.col)
                        t = _M(x.row, x.col, False, x.rs, x.cs)
            elif op == "matmul":
                x, y = mat(of(a[0])), mat(of(a[1]))
                if x.scal and y.scal or x.scal and x.rs != x.cs or y.scal and y.rs != y.cs:
                    # a product with a zero that is not square is a zero of another size
                    t = scalar_matrix(_total(x.rs), _total(y.cs))
                elif x.scal:
                    t = y
                elif y.scal:
                    t = x
                else:
                    _aligned(x.cs, y.rs)
                    _join(U, x.col, y.row)
                    t = _M(x.row, y.col, False, x.rs, y.cs)
            elif op in ("mul", "div"):
                x, y = of(a[0]), of(a[1])
                if x == _SCALAR and y == _SCALAR:
                    t = _SCALAR
                elif y == _SCALAR:
                    t = mat(x)
                elif x == _SCALAR and op == "mul":
                    t = mat(y)
                else:
                    raise _Break(f"a {op} of two matrices")
            elif op == "trace":
                x = mat(of(a[0]))
                if not x.scal:
                    _aligned(x.rs, x.cs)
                    _join(U, x.row, x.col)
                t = _SCALAR
            elif op == "block":
                rows, cols, blocks = a
                bs = [mat(of(b)) for b in blocks]
                rparts, cparts = [], []
                for ii in range(rows):
                    row = bs[ii * cols:(ii + 1) * cols]
                    side = U.new()
                    for b in row:
                        if not b.scal:
                            _join(U, side, b.row)
                    rparts.append(side)
                for j in range(cols):
                    col = bs[j::cols]
                    side = U.new()
                    for b in col:
                        if not b.scal:
                            _join(U, side, b.col)
                    cparts.append(side)
                # a multiple of the identity as a block is fixed by R(h) and R(conj h) alike only where
                # its row and column parts move alike
                for ii in range(rows):
                    for j in range(cols):
                        if bs[ii * cols + j].scal:
                            _join(U, rparts[ii], cparts[j])
                rsz = tuple(_total(bs[ii * cols].rs) for ii in range(rows))
                csz = tuple(_total(bs[j].cs) for j in range(cols))
                t = _M(tuple(rparts), tuple(cparts), False, rsz, csz)
            elif op in ("list", "tuple"):
                t = ("seq", [of(x) for x in a])
            elif op == "dict":
                t = ("map", dict(zip(a[0], [of(x) for x in a[1]])))
            elif op == "item":
                x = of(a[0])
                if not (type(x) is tuple and x[0] in ("seq", "map")):
                    raise _Break("an item of a value that is not a container")
                try:
                    t = x[1][a[1]]
                except (KeyError, IndexError, TypeError):
                    raise _Break("an item not in its container") from None
            elif op == "param":
                if a[1] != 1 or len(a) < 3:
                    raise _Break("a parameter of a function other than its point")
                t = of(a[2])
                fn_params.setdefault(a[0], []).append(t)
            elif op == "fn":
                t = ("fn", a[0], of(a[2]))
            elif op == "prim":
                q = a[0].qualname
                if q in _NSIDE_STEPS:
                    t = _M(U.N, U.N, False, n, n)
                elif q == _DERIVATIVE and len(a) == 5:
                    f, point, tangent = of(a[2]), of(a[3]), of(a[4])
                    if not (type(f) is tuple and f[0] == "fn"):
                        raise _Break("a derivative of a value that is not a traced function")
                    for p in fn_params.get(f[1], []) + [tangent]:
                        _unify(U, point, p)
                    t = f[2]
                else:
                    raise _Break("an engine step")
            else:
                raise _Break(f"the operation {op}")
            types.append(t)
        of(g.output)
    except _Break as exc:
        return [str(exc)]
    return []


def _unify(U: _UF, a: Any, b: Any) -> None:
    """Join the types of two values that must move alike (a point and its tangent vector)."""
    if isinstance(a, _M) and isinstance(b, _M):
        if a.scal or b.scal:
            raise _Break("a point or tangent vector with a multiple of the identity")
        _aligned(a.rs, b.rs)
        _aligned(a.cs, b.cs)
        _join(U, a.row, b.row)
        _join(U, a.col, b.col)
    elif type(a) is tuple and type(b) is tuple and a[0] == b[0] == "map":
        if set(a[1]) != set(b[1]):
            raise _Break("a tangent vector with other keys than its point")
        for k in a[1]:
            _unify(U, a[1][k], b[1][k])
    else:
        raise _Break("a point or tangent vector that is not a map of matrices")


def applies(graph: Any, realization: str | None, n: int, r: int) -> bool:
    """Whether the exact method may reduce the complex point of ``graph`` by U(r) on the right: the standard
    realization, the graph reads the complex point, and nothing in it may break covariance (computed once per
    graph)."""
    if (realization or "standard") != "standard":
        return False
    if not any(op == "attr" and a[1] in ("Zc", "Zc_dot") for op, a in zip(graph.ops, graph.args)):
        return False
    key = f"unitary right action breaks at {n},{r}"      # the sizes of block parts are the size's
    breaks = graph.cache.get(key)
    if breaks is None:
        breaks = graph.cache[key] = tuple(unitary_right_breaks(graph, n, r))
    return not breaks
