"""Mutants of a graph: one small change of a claim's computation, made on its graph, not on its source.

The changes (:data:`OPERATORS`), each at one node of the graph (so at every use of that
node: a node is a subexpression, shared where the claim computed it once):

* ``sign``: a + b ↔ a − b; the first term of a sum negated (−a + b); a unary minus removed;
* ``swap``: the operands of a product a @ b, or of a Poisson bracket, swapped;
* ``transpose``: one factor of a product transposed, or a transpose removed;
* ``drop``: a term of a sum or difference dropped (a ± b → a, → ±b);
* ``letter``: a leaf of the scene replaced by another of the same kind (the pairs of
  :data:`LETTER_SWAPS`: X ↔ P, Y ↔ Q, Φ ↔ Ψ, λ ↔ κ, A ↔ A⁻¹, ...);
* ``invert``: a resolvent (μI − A)⁻¹ replaced by μI − A, an explicit inverse M⁻¹ by M;
* ``normalize``: a resolvent R(μ) = (μI − A)⁻¹ replaced by (A − μI)⁻¹ = −R(μ), (−μI − A)⁻¹ = R(−μ),
  (A + μI)⁻¹ = −R(−μ) or (I − A/μ)⁻¹ = μR(μ);
* ``coefficient``: an exact constant k (int or Fraction) of the algebra, of s.q, s.const,
  s.scalar_matrix, a power, an expected rank or count, changed to k + 1 (s.q(a, b): a + 1 or b + 1);
  an expected rank also to k − 1 (a generic rank is refuted by a point where the rank is higher).

A mutant is made by replaying the graph with the one node changed
(:class:`.replay.GraphClaim`): the tracer builds the mutant's graph, so an ill-typed change
(a sum or product whose spaces do not match, Φ in place of Ψ where n ≠ r) is refused there and
left out, and so is a change that computes the same outputs as the claim (the digest of the
output's subgraph, :func:`.evaluate.node_keys`, equal to the claim's) or as an earlier mutant.
Nothing here runs claim code or evaluates a value.

The mutation analysis makes its changes at the claim's **sites** (:func:`site_mutants`): the graphs traced
with the source span of the claim expression that built each node (:mod:`.sites`), one change at one
site is made at every node built there (every iteration of a loop) in every size's graph, as an edit of
the claim's source at that place would be; nodes the engine built have no site and are not changed.

Without sites, a claim that has no graph with symbolic sizes has one graph per size (it reads its sizes: a
coordinate, a loop over n).  :func:`sized_graph_mutants` mutates those graphs when they have the same
skeleton (:func:`skeleton`: the same ops in the same order on the same nodes, the numbers of sizes
aside): a node is then known by its place in the order of the trace, and a mutant is one change made at
that node of every size's graph (:class:`.replay.SizedGraphClaim`).  Where the skeletons differ (a loop
or a condition over the sizes makes other nodes at other sizes) no node is the same node at every size,
and :class:`SkeletonMismatch` says where.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any, Callable, Iterator

from stiefelsym.ir.graph import Graph, Ref, Size, node_keys
from stiefelsym.ir.replay import GraphClaim, SizedGraphClaim
from stiefelsym.ir.sites import SourceSite

#: scene leaves and the leaves of the same kind that replace them (the source mutation's pairs)
LETTER_SWAPS: dict[str, tuple[str, ...]] = {
    "X": ("P",), "P": ("X",), "Y": ("Q",), "Q": ("Y",),
    "xi": ("zeta",), "zeta": ("xi",), "eta": ("theta",), "theta": ("eta",),
    "Phi": ("Psi",), "Psi": ("Phi",), "A": ("Ainv",), "Ainv": ("A",), "In": ("Ir",), "Ir": ("In",),
    "lam": ("kappa",), "kappa": ("lam",), "Xdot": ("Pdot",), "Pdot": ("Xdot",),
    "Lambda": ("Pi",), "Pi": ("Lambda",),
}
#: scene methods whose two arguments are swapped (antisymmetric brackets)
SWAPPED_CALLS = ("bracket", "canonical_bracket")

#: the declared space of changes: (name, what it does)
OPERATORS: tuple[tuple[str, str], ...] = (
    ("sign", "a + b <-> a - b; -a + b for a + b; a unary minus removed"),
    ("swap", "the operands of a product @ or of a Poisson bracket swapped"),
    ("transpose", "one factor of a product transposed (where the spaces allow), or a transpose removed"),
    ("drop", "a term of a sum or difference dropped (a ± b -> a, -> ±b)"),
    ("letter", "a leaf of the scene replaced by another of the same kind (LETTER_SWAPS)"),
    ("invert", "a resolvent (μI − A)⁻¹ replaced by μI − A; an inverse M⁻¹ by M"),
    ("normalize", "a resolvent (μI − A)⁻¹ replaced by (A − μI)⁻¹, (−μI − A)⁻¹, (A + μI)⁻¹ or (I − A/μ)⁻¹"),
    ("coefficient", "an exact constant k of the algebra, of s.q, s.const, s.scalar_matrix, a power, an expected "
                    "rank or count changed to k + 1 (an expected rank also to k − 1)"),
)

Edit = Callable[[Any, tuple, Any], Any]
#: the words of a change of a statement's expected value (a rank or a count), not of a formula
STATEMENT_CHANGES = ("the expected rank ", "the expected count ")


@dataclass(frozen=True)
class Site:
    """One change at one node: the operator, what it does (in words) and the edit of the node's value
    (a function of the replay, the node's arguments and the replay's frame)."""

    node: int
    operator: str
    text: str
    edit: Edit = field(repr=False, compare=False)


def _is_const(x: Any) -> bool:
    return type(x) in (int, Fraction)


def _bump(a: tuple, k: int) -> tuple:
    return a[:k] + (a[k] + 1,) + a[k + 1:]


def certificate_only(g: Graph) -> set[int]:
    """The nodes only a rank's kernel certificate reads (``Rank(M, k, kernel=K)``): not part of the
    statement.  A change there leaves the statement as it is (the method then decides the rank without
    the certificate, or with it where it is still one), so the mutation analysis does not change them."""
    ops, args = g.ops, g.args
    kernels = [a[4] for op, a in zip(ops, args) if op == "rank" and len(a) > 4 and type(a[4]) is Ref]
    if not kernels or g.output is None:
        return set()
    mark = bytearray(len(args))
    stack = [g.output.i]
    while stack:
        i = stack.pop()
        if mark[i]:
            continue
        mark[i] = 1
        a = args[i]
        # a rank with a kernel reads its matrix (argument 0) for the statement; the kernel (argument 4) is
        # the certificate's
        reads = g.refs(i) if ops[i] != "rank" or len(a) <= 4 else [a[0].i] if type(a[0]) is Ref else []
        stack.extend(j for j in reads if not mark[j])
    return {i for i in range(len(args)) if not mark[i]}     # (and nodes nothing reads: no change there shows)


def sites(g: Graph) -> Iterator[Site]:
    """Every change of :data:`OPERATORS` the graph offers, node by node (a fixed order: mutants are
    numbered by it), outside a rank's kernel certificate (:func:`certificate_only`).  Changes that do
    not type are only found out when the mutant is built."""
    ops, args = g.ops, g.args
    skip = certificate_only(g)

    def v(rp, x, f):
        return rp.arg(x, f)
    for i, (op, a) in enumerate(zip(ops, args)):
        if i in skip:
            continue
        if op in ("add", "sub"):
            x, y = a
            flip = "−" if op == "add" else "+"
            yield Site(i, "sign", f"the sign of the second term flipped ({flip})",
                       (lambda rp, a, f: v(rp, a[0], f) - v(rp, a[1], f)) if op == "add" else
                       (lambda rp, a, f: v(rp, a[0], f) + v(rp, a[1], f)))
            if type(x) is Ref and ops[x.i] != "neg":
                yield Site(i, "sign", "the first term negated",
                           (lambda rp, a, f: -v(rp, a[0], f) + v(rp, a[1], f)) if op == "add" else
                           (lambda rp, a, f: -v(rp, a[0], f) - v(rp, a[1], f)))
            yield Site(i, "drop", "the second term dropped", lambda rp, a, f: v(rp, a[0], f))
            yield Site(i, "drop", "the first term dropped",
                       (lambda rp, a, f: v(rp, a[1], f)) if op == "add" else (lambda rp, a, f: -v(rp, a[1], f)))
            for k in (0, 1):
                if _is_const(a[k]):
                    yield Site(i, "coefficient", f"the constant {a[k]} changed to {a[k] + 1}",
                               lambda rp, a, f, k=k, op=op: getattr(rp, "_" + op)(_bump(a, k), f))
        elif op == "neg":
            yield Site(i, "sign", "a unary minus removed", lambda rp, a, f: v(rp, a[0], f))
        elif op == "matmul":
            x, y = a
            if x != y:
                yield Site(i, "swap", "the operands of a product swapped", lambda rp, a, f: v(rp, a[1], f) @ v(rp, a[0], f))
            if not (type(x) is Ref and ops[x.i] == "T"):
                yield Site(i, "transpose", "the left factor transposed", lambda rp, a, f: v(rp, a[0], f).T @ v(rp, a[1], f))
            if not (type(y) is Ref and ops[y.i] == "T"):
                yield Site(i, "transpose", "the right factor transposed", lambda rp, a, f: v(rp, a[0], f) @ v(rp, a[1], f).T)
        elif op == "T":
            yield Site(i, "transpose", "a transpose removed", lambda rp, a, f: v(rp, a[0], f))
        elif op == "inv":
            yield Site(i, "invert", "an inverse removed", lambda rp, a, f: v(rp, a[0], f))
        elif op in ("mul", "div"):
            for k in (0, 1):
                if _is_const(a[k]):
                    yield Site(i, "coefficient", f"the constant {a[k]} changed to {a[k] + 1}",
                               lambda rp, a, f, k=k, op=op: getattr(rp, "_" + op)(_bump(a, k), f))
        elif op == "pow" and type(a[1]) is int:
            yield Site(i, "coefficient", f"the exponent {a[1]} changed to {a[1] + 1}",
                       lambda rp, a, f: v(rp, a[0], f) ** (a[1] + 1))
        elif op == "attr" and a[1] in LETTER_SWAPS:
            for alt in LETTER_SWAPS[a[1]]:
                yield Site(i, "letter", f"{a[1]} replaced by {alt}", lambda rp, a, f, alt=alt: getattr(v(rp, a[0], f), alt))
        elif op == "item" and type(a[1]) is str and a[1] in LETTER_SWAPS:
            for alt in LETTER_SWAPS[a[1]]:
                yield Site(i, "letter", f"[{a[1]!r}] replaced by [{alt!r}]", lambda rp, a, f, alt=alt: v(rp, a[0], f)[alt])
        elif op == "call":
            yield from _call_sites(i, a, v)
        elif op == "rank" and type(a[1]) is int:
            yield Site(i, "coefficient", f"the expected rank {a[1]} changed to {a[1] + 1}",
                       lambda rp, a, f: rp._rank(_bump(a, 1), f))
            if a[1] > 0:     # a generic rank found lower at a point is no refutation; one found higher is
                yield Site(i, "coefficient", f"the expected rank {a[1]} lowered to {a[1] - 1}",
                           lambda rp, a, f: rp._rank(a[:1] + (a[1] - 1,) + a[2:], f))
        elif op == "count" and type(a[1]) is int:
            yield Site(i, "coefficient", f"the expected count {a[1]} changed to {a[1] + 1}",
                       lambda rp, a, f: rp._count(_bump(a, 1), f))


def _call_sites(i: int, a: tuple, v: Callable) -> Iterator[Site]:
    name, cargs = a[1], a[2]

    def call(rp, a, f, new_args):
        return getattr(v(rp, a[0], f), a[1])(*new_args)
    if name == "resolvent" and len(cargs) == 1:
        def R(rp, a, f, mu=None):
            mu = v(rp, a[2][0], f) if mu is None else mu
            return v(rp, a[0], f).resolvent(mu)
        yield Site(i, "invert", "the resolvent (μI − A)⁻¹ replaced by μI − A", lambda rp, a, f: R(rp, a, f).inv())
        yield Site(i, "normalize", "(A − μI)⁻¹ in place of (μI − A)⁻¹", lambda rp, a, f: -R(rp, a, f))
        yield Site(i, "normalize", "(−μI − A)⁻¹ in place of (μI − A)⁻¹",
                   lambda rp, a, f: R(rp, a, f, -v(rp, a[2][0], f)))
        yield Site(i, "normalize", "(A + μI)⁻¹ in place of (μI − A)⁻¹",
                   lambda rp, a, f: -R(rp, a, f, -v(rp, a[2][0], f)))
        yield Site(i, "normalize", "(I − A/μ)⁻¹ in place of (μI − A)⁻¹",
                   lambda rp, a, f: v(rp, a[2][0], f) * R(rp, a, f))
    elif name in SWAPPED_CALLS and len(cargs) == 2 and cargs[0] != cargs[1]:
        yield Site(i, "swap", f"the arguments of {name} swapped",
                   lambda rp, a, f: call(rp, a, f, [v(rp, a[2][1], f), v(rp, a[2][0], f)]))
    elif name == "q" and len(cargs) == 2 and all(type(x) is int for x in cargs):
        yield Site(i, "coefficient", f"q({cargs[0]}, {cargs[1]}) changed to q({cargs[0] + 1}, {cargs[1]})",
                   lambda rp, a, f: call(rp, a, f, [a[2][0] + 1, a[2][1]]))
        yield Site(i, "coefficient", f"q({cargs[0]}, {cargs[1]}) changed to q({cargs[0]}, {cargs[1] + 1})",
                   lambda rp, a, f: call(rp, a, f, [a[2][0], a[2][1] + 1]))
    elif name == "const" and len(cargs) == 1 and _is_const(cargs[0]):
        yield Site(i, "coefficient", f"the constant {cargs[0]} changed to {cargs[0] + 1}",
                   lambda rp, a, f: call(rp, a, f, [a[2][0] + 1]))
    elif name == "scalar_matrix" and len(cargs) == 3 and _is_const(cargs[0]):
        yield Site(i, "coefficient", f"the constant {cargs[0]} of a scalar matrix changed to {cargs[0] + 1}",
                   lambda rp, a, f: call(rp, a, f, [a[2][0] + 1] + [v(rp, x, f) for x in a[2][1:]]))


@dataclass
class GraphMutant:
    """One mutant of a graph: the change (operator, node, words), the mutant's graph, the digest of its
    output's subgraph and the change in the paper's notation (:func:`.notation.diff`)."""

    index: int
    node: int
    operator: str
    text: str
    #: the mutant's graph (None for a claim traced per size: see ``sized``)
    graph: Graph | None
    key: str
    changes: list = field(default_factory=list)
    #: for a claim traced per size: per size (n, r), the claim's graph there and the mutant's edit of it
    #: (its graphs are not kept: they are what the tracer makes of the edited replays, at every run);
    #: ``key`` is then the digests of the outputs at every size, joined
    sized: dict | None = None
    #: a mutant at a site (:func:`site_mutants`): the claim expression changed, and the number of nodes
    #: (over every size's graph) the change was made at
    site: SourceSite | None = None
    nodes: int = 1
    #: a mutant of one size's graph only (:func:`per_size_mutants`): that size
    at: tuple[int, int] | None = None
    #: the mutant's graphs as the tracer made them when the mutant was made (None: with symbolic sizes; or
    #: per size with an edit), each the first of the two traces its compilation compares (:meth:`traced`)
    made: dict | None = field(default=None, repr=False, compare=False)

    @property
    def func(self) -> GraphClaim | SizedGraphClaim:
        """The mutant as a claim function (its graph, or the claim's graph at each size with the one change,
        replayed by the tracer)."""
        name = f"mutant {self.index} (node %{self.node})"
        if self.sized is None:
            assert self.graph is not None
            return GraphClaim(self.graph, name=name)
        return SizedGraphClaim({z: g for z, (g, _) in self.sized.items()},
                               {z: e for z, (_, e) in self.sized.items()}, name=name)

    def traced(self, func: Any, constraints: tuple) -> None:
        """The graphs traced when the mutant was made, taken by the compilations of ``func`` (this mutant's
        :attr:`func`) as their first traces (:func:`stiefelsym.ir.first_trace`): each compilation traces
        the mutant once more, not twice."""
        from stiefelsym.ir import first_trace
        for z, g in (self.made or {}).items():
            first_trace(func, None if z is None else z[0], None if z is None else z[1], constraints, g)

    def graphs(self, constraints: tuple) -> dict:
        """The mutant's graph at each size (traced again for a claim traced per size)."""
        if self.sized is None:
            return {None: self.graph}
        from stiefelsym.ir import _clean
        from stiefelsym.ir.trace import trace
        return {z: _clean(trace, GraphClaim(g, e), z[0], z[1], constraints) for z, (g, e) in self.sized.items()}

    def description(self) -> str:
        from stiefelsym.ir.notation import describe
        if self.site is not None:
            src = self.site.text()
            at = f"`{src}` at " if src else ""
            sizes = "" if self.sized is None else ", graphs at " + ", ".join(f"({n},{r})" for n, r in self.sized)
            many = f", {self.nodes} nodes" if self.nodes > 1 else ""
            return f"{describe(self.changes)} ({at}{self.site.where()}{sizes}: {self.operator}: {self.text}{many})"
        if self.sized is None:
            return f"{describe(self.changes)} (graph: node %{self.node}, {self.operator}: {self.text})"
        if self.at is not None:
            return (f"{describe(self.changes)} (graph at ({self.at[0]},{self.at[1]}) only: node %{self.node}, "
                    f"{self.operator}: {self.text})")
        at = ", ".join(f"({n},{r})" for n, r in self.sized)
        return f"{describe(self.changes)} (graphs at {at}: node %{self.node}, {self.operator}: {self.text})"


@dataclass
class MutantCensus:
    """What became of the sites of one graph."""

    sites: int = 0
    ill_typed: int = 0
    same_as_claim: int = 0
    duplicates: int = 0
    refusals: dict = field(default_factory=dict)
    #: of the ill-typed changes of graphs traced per size, those that type at some of the sizes
    ill_typed_somewhere: int = 0


def output_key(g: Graph) -> str:
    """The digest of the subgraph of a graph's output: equal for two graphs that compute the same
    outputs the same way, whatever their node numbers and their nodes that no output reads."""
    return node_keys(g)[g.output.i].hex()


def graph_mutants(g: Graph, constraints: tuple, census: MutantCensus | None = None,
                  notation: bool = True) -> list[GraphMutant]:
    """Every well-typed mutant of ``g`` (a graph traced with symbolic sizes; ``constraints``: the
    realization it was traced with), in the order of :func:`sites`, without one that computes what the
    claim or an earlier mutant computes."""
    from stiefelsym.ir import _clean
    from stiefelsym.ir.notation import diff
    from stiefelsym.ir.trace import trace
    census = census if census is not None else MutantCensus()
    base = output_key(g)
    seen = {base}
    out: list[GraphMutant] = []
    for site in sites(g):
        census.sites += 1
        try:
            m = _clean(trace, GraphClaim(g, {site.node: site.edit}), g.sizes and g.sizes[0],
                       g.sizes and g.sizes[1], constraints)
            if m.refusals:
                raise TypeError(m.refusals[0])
        except Exception as exc:   # noqa: BLE001 - the tracer refused the change: ill-typed
            census.ill_typed += 1
            why = str(exc).removeprefix("refused: ").split(" (")[0][:80]
            census.refusals[why] = census.refusals.get(why, 0) + 1
            continue
        key = output_key(m)
        if key == base:
            census.same_as_claim += 1
            continue
        if key in seen:
            census.duplicates += 1
            continue
        seen.add(key)
        gm = GraphMutant(len(out), site.node, site.operator, site.text, m, key, made={g.sizes or None: m})
        if notation:
            gm.changes = diff(g, m)
        out.append(gm)
    return out


# --------------------------------------------------------------------------- graphs traced per size

class SkeletonMismatch(ValueError):
    """The graphs of a claim traced at several sizes are not one computation at every size."""


def _shape(a: Any) -> Any:
    t = type(a)
    if t is Ref:
        return a
    if t is tuple:
        return tuple(_shape(x) for x in a)
    if t is int:
        return int          # a number that may be a size (s.zeros(n, 2) at n = 4 reads 4)
    if t is Size:
        return (Size, a.k, a.d)
    return a


def skeleton(g: Graph) -> tuple:
    """The graph with the numbers of its sizes left out: per node its op and its arguments, with every
    int (a size, an index or a constant: they cannot be told apart at a fixed size) replaced by ``int``.
    Two graphs with the same skeleton make the same ops in the same order on the same nodes."""
    return tuple((op, _shape(a)) for op, a in zip(g.ops, g.args)) + (g.output,)


def _first_difference(a: Graph, b: Graph) -> str:
    for i, (x, y) in enumerate(zip(skeleton(a), skeleton(b))):
        if x != y:
            if i >= min(len(a.ops), len(b.ops)):
                break
            if a.ops[i] == b.ops[i]:
                return f"node %{i} ({a.ops[i]}) has other arguments"
            return f"node %{i} is {a.ops[i]} in one and {b.ops[i]} in the other"
    return f"{len(a.ops)} and {len(b.ops)} nodes"


def sized_graph_mutants(graphs: dict[tuple[int, int], Graph], constraints: tuple,
                        census: MutantCensus | None = None, notation: bool = True) -> list[GraphMutant]:
    """The mutants of a claim traced per size (``graphs``: its graph at each size, in the order of the sizes
    its changes are written at: the first where the change changes an output), each one change at one node made at every size: the graphs must have the
    same :func:`skeleton`, else :class:`SkeletonMismatch`.  A change that does not type at one of the
    sizes is left out (counted ill-typed), and so is one that computes at every size what the claim or
    an earlier mutant computes."""
    from stiefelsym.ir.notation import diff
    census = census if census is not None else MutantCensus()
    sizes = list(graphs)
    first = graphs[sizes[0]]
    shape = skeleton(first)
    for z in sizes[1:]:
        if skeleton(graphs[z]) != shape:
            raise SkeletonMismatch(
                f"the graphs at ({sizes[0][0]},{sizes[0][1]}) and ({z[0]},{z[1]}) are not the same computation "
                f"({_first_difference(first, graphs[z])}: a loop or a condition over the sizes)")
    per = {z: list(sites(graphs[z])) for z in sizes}
    names = [(x.node, x.operator) for x in per[sizes[0]]]
    for z in sizes[1:]:
        if [(x.node, x.operator) for x in per[z]] != names:
            raise SkeletonMismatch(f"the graphs at ({sizes[0][0]},{sizes[0][1]}) and ({z[0]},{z[1]}) offer other "
                                   "changes (their constants differ in kind)")
    base = tuple(output_key(graphs[z]) for z in sizes)
    seen = {base}
    out: list[GraphMutant] = []
    for k, site in enumerate(per[sizes[0]]):
        census.sites += 1
        made = _made_at_sizes(graphs, {z: {site.node: per[z][k].edit} for z in sizes}, constraints, census)
        if made is None:
            continue
        key = tuple(output_key(made[z]) for z in sizes)
        if not _new(key, base, seen, census):
            continue
        # written at the first size where it changes an output (a change may vanish at a small size)
        z = next(z for j, z in enumerate(sizes) if key[j] != base[j])
        gm = GraphMutant(len(out), site.node, site.operator, site.text, None, "/".join(key),
                         sized={y: (graphs[y], {site.node: per[y][k].edit}) for y in sizes}, made=made)
        if notation:
            gm.changes = diff(graphs[z], made[z])
        out.append(gm)
    return out


def per_size_mutants(graphs: dict[tuple[int, int], Graph], constraints: tuple,
                     census: MutantCensus | None = None, notation: bool = True) -> list[GraphMutant]:
    """The mutants of a claim traced per size whose graphs are not one computation (a loop or a condition
    over the sizes made other nodes at other sizes) and have no sites (a claims file's graphs, replayed):
    each is one change at one node of one size's graph (:func:`sites`), the other sizes keeping the claim's
    graph, so every node of every size is changed once.  A change the tracer refuses is left out (ill-typed),
    and so is one that computes what the claim or an earlier mutant computes."""
    from stiefelsym.ir.notation import diff
    census = census if census is not None else MutantCensus()
    sizes = list(graphs)
    base = tuple(output_key(graphs[z]) for z in sizes)
    seen = {base}
    out: list[GraphMutant] = []
    for j, z in enumerate(sizes):
        for site in sites(graphs[z]):
            census.sites += 1
            made = _made_at_sizes(graphs, {z: {site.node: site.edit}}, constraints, census)
            if made is None:
                continue
            key = base[:j] + (output_key(made[z]),) + base[j + 1:]
            if not _new(key, base, seen, census):
                continue
            gm = GraphMutant(len(out), site.node, site.operator, site.text, None, "/".join(key),
                             sized={y: (graphs[y], {site.node: site.edit} if y == z else {}) for y in sizes},
                             at=z, made=made)
            if notation:
                gm.changes = diff(graphs[z], made[z])
            out.append(gm)
    return out


# --------------------------------------------------------------------------- mutants at a site

_NUMBER = re.compile(r"-?\d+(?:/\d+)?")


def _change_key(site: Site) -> tuple[str, str]:
    """What a change does whatever the numbers it reads (``the constant 2 changed to 3`` and ``... 3 changed
    to 4`` are one change of the constant a site makes: at each iteration of a loop, at each size)."""
    return site.operator, _NUMBER.sub("k", site.text)


def site_groups(graphs: dict[Any, Graph], keep: Callable[[SourceSite], bool] | None = None
                ) -> dict[tuple, dict[Any, dict[int, Edit]]]:
    """The changes of :func:`sites` grouped by the claim expression that made their nodes (the graphs'
    :attr:`~.graph.Graph.sites`): per (source site, operator, change whatever its numbers, occurrence at the
    node), per size, the edits of every node built at that site that offers the change.  In source order
    (file, line, column), then the order of :data:`OPERATORS`.  Nodes with no site (made by the engine) are
    left out, and so are those whose site ``keep`` (when given) refuses."""
    order = {name: k for k, (name, _) in enumerate(OPERATORS)}
    groups: dict[tuple, dict[Any, dict[int, Edit]]] = {}
    texts: dict[tuple, str] = {}
    for z, g in graphs.items():
        if g.sites is None:
            raise ValueError("a graph traced without sites (trace(..., sites=True))")
        seen: dict[tuple, int] = {}
        for x in sites(g):
            src = g.sites[x.node]
            if src is None or (keep is not None and not keep(src)):
                continue
            change = _change_key(x)
            k = seen[(x.node,) + change] = seen.get((x.node,) + change, -1) + 1
            key = (src, order.get(x.operator, len(order)), change[1], k, x.operator)
            if key not in groups:
                texts[key] = x.text
            groups.setdefault(key, {}).setdefault(z, {})[x.node] = x.edit
    return {key + (texts[key],): groups[key] for key in sorted(groups, key=lambda key: key[:4])}


def site_mutants(graphs: dict[Any, Graph], constraints: tuple, census: MutantCensus | None = None,
                 notation: bool = True, keep: Callable[[SourceSite], bool] | None = None) -> list[GraphMutant]:
    """The mutants of a claim at its sites: ``graphs`` its graph with symbolic sizes (key None) or its graph
    at each size (keys (n, r), in the order of the sizes its changes are written at), traced with sites.
    A mutant is one change at one site (:func:`site_groups`) made at every node built there, in every
    size's graph: the analogue of one edit of the claim's source, whatever loops and conditions over the
    sizes made those nodes (the graphs need not have one skeleton).  A change refused by the tracer at one
    of the sizes is left out (counted ill-typed), and so is one that computes at every size what the claim
    or an earlier mutant computes; it is written (:func:`.notation.diff`) at the first size where it
    changes an output.  ``keep``: the sites changed (default: every site; the mutation analysis keeps those
    of the claim's own function, :func:`stiefelsym.analyses.mutate.site_rings`)."""
    from stiefelsym.ir.notation import diff
    census = census if census is not None else MutantCensus()
    sizes = list(graphs)
    base = tuple(output_key(graphs[z]) for z in sizes)
    seen = {base}
    out: list[GraphMutant] = []
    for (src, _, _, _, operator, text), per in site_groups(graphs, keep).items():
        census.sites += 1
        made = _made_at_sizes(graphs, per, constraints, census)
        if made is None:
            continue
        key = tuple(output_key(made[z]) if z in made else base[j] for j, z in enumerate(sizes))
        if not _new(key, base, seen, census):
            continue
        first = next(j for j, z in enumerate(sizes) if key[j] != base[j])
        z0 = sizes[first]
        x0 = next(iter(per[z0]))
        nodes = sum(len(e) for e in per.values())
        if z0 is None:
            gm = GraphMutant(len(out), x0, operator, text, made[z0], key[0], site=src, nodes=nodes, made=made)
        else:
            gm = GraphMutant(len(out), x0, operator, text, None, "/".join(key),
                             sized={y: (graphs[y], per.get(y, {})) for y in sizes}, site=src, nodes=nodes, made=made)
        if notation:
            gm.changes = diff(graphs[z0], made[z0])
        out.append(gm)
    return out


def _made_at_sizes(graphs: dict[Any, Graph], edits: dict[Any, dict], constraints: tuple,
                   census: MutantCensus) -> dict[Any, Graph] | None:
    """The graphs with ``edits[z]`` made in ``graphs[z]``, traced again, for each size z of ``edits``; None
    (counted ill-typed in ``census``) when the tracer refuses the change at one of the sizes."""
    from stiefelsym.ir import _clean
    from stiefelsym.ir.trace import trace
    made: dict[Any, Graph] = {}
    refused = ""
    for z, edit in edits.items():
        g = graphs[z]
        try:
            m = _clean(trace, GraphClaim(g, edit), g.sizes and g.sizes[0], g.sizes and g.sizes[1], constraints)
            if m.refusals:
                raise TypeError(m.refusals[0])
            made[z] = m
        except Exception as exc:   # noqa: BLE001 - the tracer refused the change at this size
            refused = refused or str(exc).removeprefix("refused: ").split(" (")[0][:80]
    if refused:
        census.ill_typed += 1
        census.ill_typed_somewhere += bool(made)
        census.refusals[refused] = census.refusals.get(refused, 0) + 1
        return None
    return made


def _new(key: tuple, base: tuple, seen: set, census: MutantCensus) -> bool:
    """Whether a mutant computing ``key`` (its output at each size) is new: not the claim's ``base``, not an
    earlier mutant's (counted in ``census`` otherwise); it is then added to ``seen``."""
    if key == base:
        census.same_as_claim += 1
        return False
    if key in seen:
        census.duplicates += 1
        return False
    seen.add(key)
    return True
