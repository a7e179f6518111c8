"""Derivatives along flows (forward mode) and gradients (reverse mode) as graph transforms.

A claim's ``s.d(F, flow)`` is traced as a ``call`` node whose function
argument is the traced body of F (a ``fn`` node).  :func:`derivatives` rewrites
each such node whose body is built from operations with a known derivative
into ordinary nodes of the graph, by the rules of the tangent map:

* d(a ± b) = da ± db, d(−a) = −da, d(ab) = da·b + a·db (matrix and scalar
  products), d(a/c) = da/c − (a/c)·dc/c, d(cᵏ) = k·cᵏ⁻¹·dc, d(Aᵀ) = (dA)ᵀ,
  d(M⁻¹) = −M⁻¹·dM·M⁻¹, d tr M = tr dM, d⟨a, b⟩ = ⟨da, b⟩ + ⟨a, db⟩;
  entries, blocks, block matrices, containers and realified or conjugated
  matrices: taken part by part (all of these are linear);
* the point's primitives X, P (Y, Q, Zc, Zc_dot) ↦ the flow's components,
  Φ = PXᵀ − XPᵀ and Ψ = XᵀP − PᵀX by the product rule;
* everything that does not depend on the point (A, the resolvents (μI − A)⁻¹
  at a constant μ, λ, κ, ε, generic parameters, I, 0, constants, and values
  of the enclosing scene the body closes over) ↦ 0.  Zeros are structural:
  a sum with a zero term is the other term, and a zero is built (as ``x·0``)
  only where a value must be handed on (a block, a part of a container, the
  value of the whole derivative).

The flow's components are read by one engine step, :func:`tangent_vector`, which
checks the flow the way the scene's own tangent does (its keys, the shapes and
spaces of its components) and gives each component the spaces of the
primitive it moves.  So the transformed graph computes what the scene's dual
numbers computed, in the scene's own arithmetic, and refuses what they
refused.

A body with an operation whose derivative the graph does not show (a nested
derivative, gradient, flow or bracket, an engine step, an operator applied,
the double point, a resolvent at a point-dependent μ) keeps its ``call`` node:
the scene differentiates it as before.  :func:`coverage` says, per ``d`` node,
whether it was transformed and, if not, why.  On a scene that says so (``NESTED_DERIVATIVES``: the
dimension-free scene, whose dual numbers do not nest) a derivative nested in the function of another is
written as nodes from the inside out (:func:`_nested`): the inner one over the enclosing function's scene,
its tangent step's components then moving along the outer flow as the flow's parts do.

``s.gradient(H)`` of a number H built by matrix operations is rewritten the
same way, in reverse mode: the adjoint of each node of H's body, from H down to
X and P, by the rules of the cyclic derivative of a trace form (for C = AB:
Ā = C̄Bᵀ, B̄ = AᵀC̄; for C = Aᵀ: Ā = C̄ᵀ; for tr M: M̄ = I; for C = M⁻¹:
M̄ = −CᵀC̄Cᵀ; Φ and Ψ by their formulas; a matrix's adjoint is a sum of matrices
and a multiple of I, which a product absorbs).  Y, Q and everything else
are constants of a gradient, as on the scene's reverse tape.  The pair is handed
on by one engine step, :func:`gradient_pair`, which makes the scene's own
checks (the dimension-free scene refuses an ambient gradient unless it keeps
H as written) and gives the n x r spaces.  An entry or a block inside H (their
adjoints need coordinates) keeps the call node.

``s.canonical_flow(H)``, ``s.dirac_flow(H)``, ``s.multiplier_flow(H)`` and ``s.bracket(F, G)`` are
rewritten where the scene lets the graph compute them (:func:`scene_flows`: a point scene of the
standard realization whose multipliers have closed forms): H's gradient by the reverse sweep, then
(dot_XP) with Π = sym(XᵀH_P), Λ = sym(XᵀH_X − H_PᵀP + ΠK − KΠ), K = XᵀP (:class:`_Flow`), and the
Dirac bracket as tr(F_Xᵀ Ẋ) + tr(F_Pᵀ Ṗ) along the Dirac flow of G (:class:`_Bracket`).  The flow is
handed on by one engine step, :func:`graph_flow`, as the scene's method hands it.  Elsewhere (the
metric realization, the free algebra) and for a Hamiltonian the reverse sweep refuses, the call
node stays.

The engine steps of :mod:`stiefelsym.systems`, whose functions take a scene and a point of the
caller's own (a dict of matrices), are rewritten on a coordinate scene (:data:`SYSTEMS`): the derivative
at a point by the tangent map with the point's variables z[k] moving (:class:`_PointDerivative`), the
gradients of a function of the point by the backward sweep with z[k] as its leaves
(:class:`_PointGradient`, one adjoint per key), the flow of pairs of Stiefel points from those gradients
(:class:`_PairsFlow`), and the Euler–Lagrange equations from a gradient and a derivative made functions
of the new graph and a second derivative by the second-order tangent map (:class:`_EulerLagrange`,
:class:`_PointSecond`).  On the dimension-free scene the derivative at its own point is the tangent map
along the tangent vector (:data:`SYSTEMS_OWN`).

The digest of a claim stays the digest of its graph as traced (what
results.json records and ``stiefelsym check`` re-traces); the transformed graph
is derived from it, once per graph, and is what the methods evaluate.
"""
from __future__ import annotations

import itertools
from fractions import Fraction
from typing import Any

from stiefelsym.ir.graph import _REFS, Graph, Named, Ref, _ref
from stiefelsym.ir.trace import CONSTANT_PRIMITIVES, MATRICES, NUMBERS, PRIMITIVES, ZERO_PRIMITIVES

#: the engine step that reads a flow's components (registered below)
TANGENT = "stiefelsym.ir.derivative.tangent_vector"

#: primitives of the point a flow moves (their components), and of the momentum maps built from X, P
MOVED = ("X", "P", "Y", "Q", "Zc", "Zc_dot")
#: matrices and numbers of the scene that do not move along any flow
CONSTANT_ATTRS = frozenset({"A", "Ainv", "In", "Ir", "xi", "zeta", "eta", "theta"}) | frozenset(NUMBERS)
#: scene methods whose value does not depend on the point
CONSTANT_CALLS = frozenset({"q", "const", "scalar", "zeros", "identity", "generic", "fresh", "general_params"})
#: scene methods whose value is a number or a matrix (a zero of it may be built as x·0)
NUMERIC_CALLS = frozenset({"tr", "killing", "resolvent", "q", "const", "scalar", "mat", "zeros", "identity",
                           "scalar_matrix", "generic", "fresh", "general_params", "conj", "realify"})
#: ops whose value is a number or a matrix
NUMERIC_OPS = frozenset({"add", "sub", "neg", "matmul", "mul", "div", "pow", "T", "inv", "trace", "entry",
                         "block"})


def tangent_vector(scene: Any, flow: Any, keys: tuple) -> dict:
    """The components ``keys`` of a flow (a Flow of the engine, or a mapping from the moved primitives
    to matrices) on ``scene``, checked as the scene's tangent checks them; a component the flow does not
    give is 0.  Engine step of the transformed graphs (never handed to claim code)."""
    f = getattr(scene, "_tangent_vector", None)
    if f is None:
        raise TypeError(f"a derivative along a flow on a {type(scene).__name__} (a scene with no tangent vectors)")
    return f(flow, tuple(keys))


PRIMITIVES[TANGENT] = tangent_vector


class Unsupported(Exception):
    """A body whose derivative the graph does not show (the reason, in a mathematician's terms)."""


class _Container:
    """The derivative of a list, tuple or dict of the body, kept part by part until it is handed on."""

    __slots__ = ("op", "keys", "parts", "primals")

    def __init__(self, op: str, keys: Any, parts: list, primals: list) -> None:
        self.op, self.keys, self.parts, self.primals = op, keys, parts, primals


#: the flows of a Hamiltonian (and the Dirac bracket) a point scene of the standard realization lets
#: the graph compute (what ``Scene._graph_flows`` says there)
POINT_FLOWS = frozenset({"canonical_flow", "dirac_flow", "multiplier_flow", "bracket"})


def scene_flows(scene: Any) -> frozenset:
    """The flows (and brackets) the graph may compute on ``scene``: what the scene says
    (``_graph_flows``, decided without building its point), nothing for a scene that does not say."""
    f = getattr(type(scene), "_graph_flows", None)      # on the class: a scene's own lookup may refuse
    return frozenset() if f is None else frozenset(f(scene))


def derivatives(g: Graph, flows: frozenset = frozenset()) -> Graph:
    """The graph with every ``d`` and ``gradient`` node it can differentiate structurally rewritten
    into ordinary nodes, and every flow of a Hamiltonian and Dirac bracket named in ``flows`` (see
    :func:`scene_flows`) whose Hamiltonians allow it (computed once per graph and set of flows;
    the graph itself and its digest are unchanged; the graph itself when no node is rewritten)."""
    key = "derived:" + ",".join(sorted(flows))
    out = g.cache.get(key)
    if out is None:
        out, report = _transform(g, frozenset(flows))
        if NESTED_DERIVATIVES in flows and any(nm == "d" and why in _NESTING for _, nm, why in report):
            out, report = _nested(out, report, frozenset(flows))
        g.cache[key], g.cache[key + ":report"] = out, report
    return out


#: what a scene says (``_graph_flows``) when a derivative along a flow nested in the function of another
#: derivative may be graph nodes (:func:`_nested`): the inner derivative written as nodes over the enclosing
#: function's scene, then differentiated with them along the outer flow (the tangent map of the tangent map)
NESTED_DERIVATIVES = "derivatives nested in derivatives"
#: the flag of the passes that rewrite the ``d`` nodes of a function's scene (see :func:`_nested`)
_NESTED_PASS = "a pass over the derivatives inside functions"
#: the reasons the first pass gives for the derivatives :func:`_nested` may rewrite
_NESTING = ("a derivative on a scene other than the claim's (inside a function of the scene)",
            "s.d inside the function (a nested derivative along a flow)")


def _nested(g: Graph, report: list, flows: frozenset) -> tuple[Graph, list]:
    """The graph ``g`` (the first pass's) with its nested derivatives rewritten from the inside out: each pass
    writes every ``d`` node whose function holds no derivative as nodes, a derivative on a function's scene
    too (its tangent step reads the function's scene), and the next pass differentiates those nodes along the
    enclosing derivative's flow (a tangent step's components move as the flow's components do).  Kept only when
    every tangent step of the result is the claim's own (no derivative left inside a function the scene
    evaluates, a Hamiltonian say): otherwise the first pass's graph, where the scene differentiates as before."""
    out, inner = g, flows | {_NESTED_PASS}
    for _ in range(16):
        nxt, _report = _transform(out, inner)
        if nxt is out:
            break
        out = nxt
    probe = Graph()
    probe.cache["flows"] = flows
    if out is g or any(op == "prim" and type(a[0]) is Named and a[0].qualname == TANGENT
                       and not _claim_scene(out, a[1], probe, True) for op, a in zip(out.ops, out.args)):
        return g, report
    left = any(op == "call" and a[1] in ("d", "bracket") for op, a in zip(out.ops, out.args))
    return out, [(i, nm, None if nm in ("d", "bracket") and why in _NESTING and not left else why)
                 for i, nm, why in report]


def coverage(g: Graph, name: str = "d", flows: frozenset = POINT_FLOWS) -> list[tuple[int, str | None]]:
    """Per ``d`` node (``name``: or ``gradient``, ``dirac_flow``, ``multiplier_flow``, ``canonical_flow``
    or ``bracket`` node) of the graph as traced: (node, None) when the pass rewrote it, (node, reason)
    when the scene computes it (``flows``: those the scene lets the graph compute, by default a
    point scene's of the standard realization)."""
    derivatives(g, flows)
    return [(i, why) for i, nm, why in g.cache["derived:" + ",".join(sorted(flows)) + ":report"] if nm == name]


def _deps(g: Graph) -> list[frozenset]:
    from stiefelsym.ir.evaluate import _deps as deps
    return deps(g)


def _transform(g: Graph, flows: frozenset = frozenset()) -> tuple[Graph, list]:
    deps = _deps(g)
    new = Graph()
    new.refusals, new.fns, new.sizes = list(g.refusals), g.fns, g.sizes
    new.cache["flows"] = flows
    remap: dict[int, Ref] = {}

    def m(a: Any) -> Any:
        t = type(a)
        if t is Ref:
            return remap[a[0]]
        if t is tuple:
            return tuple([remap[x[0]] if type(x) is Ref else m(x) if type(x) is tuple else x for x in a])
        return a

    report: list = []
    # the nodes before the first that a pass may rewrite are copied as they are (the same numbers: the
    # graph is hash-consed, each node once), without going through add one by one
    start = 0
    if len(g.index) == len(g.ops):
        start = next((i for i, (op, a) in enumerate(zip(g.ops, g.args))
                      if (op == "call" and (a[1] in _PASSES or a[1] in _FLOW_PASSES))
                      or (op == "prim" and (a[0].qualname in _TWISTED_STEPS or a[0].qualname in _SYSTEMS_STEPS))),
                     len(g.ops))
        new.ops, new.args = g.ops[:start], g.args[:start]
        new.index = dict(itertools.islice(g.index.items(), start))
        remap.update((i, _ref(i)) for i in range(start))
    nested = _NESTED_PASS in flows      # only the derivatives along flows (see :func:`_nested`)
    index, new_ops, new_args = new.index, new.ops, new.args
    plain = new.sites is None
    for i in range(start, len(g.ops)):
        op, a = g.ops[i], g.args[i]
        if plain and op != "call" and op != "prim":
            # no pass rewrites it: copied (Graph.add in line)
            a = m(a)
            k = index.get((op, a))
            if k is None:
                k = index[(op, a)] = len(new_ops)
                new_ops.append(op)
                new_args.append(a)
            remap[i] = _ref(k)
            continue
        rewrite = None
        if nested:
            if op == "call" and a[1] == "d":
                rewrite = _Derivative
            elif op == "call" and a[1] == "bracket" and BRACKET_ALONG_FLOW in flows:
                rewrite = _BracketAlongFlow     # the derivative along the scene's own Dirac flow
        elif op == "call" and a[1] in _PASSES:
            rewrite = _PASSES[a[1]]
        elif op == "call" and a[1] in _FLOW_PASSES:
            if a[1] in flows:
                rewrite = _FLOW_PASSES[a[1]]
            elif a[1] == "bracket" and BRACKET_ALONG_FLOW in flows:
                rewrite = _BracketAlongFlow
            elif a[1] == "dirac_flow" and GRADIENT_FLOW in flows:
                rewrite = _GradientFlow
            else:
                report.append((i, a[1], "the scene's own multipliers here (another realization, a chart or a "
                                        "field without their closed forms, or the free algebra's solve)"))
        elif op == "prim" and a[0].qualname in _TWISTED_STEPS:
            if TWISTED in flows:
                rewrite = _Twisted
            elif TWISTED_ALONG_FLOW in flows and a[0].qualname == "stiefelsym.twisted.bracket":
                rewrite = _TwistedAlongFlow
                try:                            # a bracket of a bracket: the derivation along the flow of f
                    remap[i] = _TwistedNestedAlongFlow(g, deps, new, remap, i).build()
                    report.append((i, a[0].qualname, None))
                    continue
                except Unsupported:
                    pass
            else:
                report.append((i, a[0].qualname, "the scene's own gradients (not a coordinate scene)"))
        elif op == "prim" and a[0].qualname in _SYSTEMS_STEPS:
            if SYSTEMS in flows:
                rewrite = _SYSTEMS_STEPS[a[0].qualname]
            elif SYSTEMS_OWN in flows and a[0].qualname == "stiefelsym.systems.derivative":
                rewrite = _OwnPointDerivative
            else:
                report.append((i, a[0].qualname, "the scene's own derivatives (not a coordinate scene)"))
        if rewrite is not None:
            name = a[1] if op == "call" else a[0].qualname
            try:
                remap[i] = rewrite(g, deps, new, remap, i).build()
                report.append((i, name, None))
                continue
            except Unsupported as exc:
                why = str(exc)
            second = _OF_BRACKETS.get(name) if TWISTED_NODES in flows else None
            if second is not None:
                try:                    # a derivative or bracket of a bracket: the inner one as graph nodes
                    remap[i] = second(g, deps, new, remap, i).build()
                    report.append((i, name, None))
                    continue
                except Unsupported as exc:
                    why = f"{why}; {exc}"
            report.append((i, name, why))
        remap[i] = new.add(op, m(a))
    if g.output is not None:
        new.output = remap[g.output.i]
    if not any(why is None for _, _, why in report):
        return g, report                # nothing rewritten: the graph itself (and what was computed of it)
    return _pruned(new), report


def _pruned(g: Graph) -> Graph:
    """The nodes the output needs, renumbered in order (a differentiated function's body is dropped)."""
    if g.output is None:
        return g
    order = sorted(g.needed())
    _ref(len(order))        # the shared references, made once for every new number
    num = {i: _REFS[k] for k, i in enumerate(order)}      # old number -> the reference to its new number

    def m(a: Any) -> Any:
        t = type(a)
        if t is Ref:
            return num[a[0]]
        if t is tuple:
            return tuple([num[x[0]] if type(x) is Ref else m(x) if type(x) is tuple else x for x in a])
        return a
    out = Graph()
    out.refusals, out.fns, out.sizes = g.refusals, g.fns, g.sizes
    # g is hash-consed (each (op, args) once) and the renumbering is one to one, so the nodes stay distinct:
    # the lists and the index are built at once, not node by node through add (checked: else node by node)
    ops = [g.ops[i] for i in order]
    args = [m(g.args[i]) for i in order]
    index = dict(zip(zip(ops, args), range(len(order))))
    if len(index) == len(order):
        out.ops, out.args, out.index = ops, args, index
    else:
        for op, a in zip(ops, args):
            out.add(op, a)
    out.output = Ref(num[g.output.i][0])
    return out


class _Derivative:
    """The derivative of one ``d`` node's function along its flow, built into the new graph."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int, f: Any = None,
                 at: tuple | None = None) -> None:
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        scene, name, args, kw = g.args[i] if at is None else at + ((), ())
        if f is None:
            if kw or len(args) != 2:
                raise Unsupported("a derivative with further arguments")
            f, flow = args
        else:
            flow = None                     # made by :meth:`make_flow` when the derivative is built
        if not (_claim_scene(g, scene, new, name == "d") or (
                name == "d" and _NESTED_PASS in new.cache.get("flows", ()) and type(scene) is Ref
                and g.ops[scene.i] == "scene")):
            # (a pass over nested derivatives: one on a function's scene too, see :func:`_nested`)
            raise Unsupported(f"{_WHAT.get(name, 'a derivative')} on a scene other than the claim's (inside a "
                              "function of the scene)")
        if type(f) is not Ref or g.ops[f.i] != "fn" or (flow is not None and type(flow) is not Ref):
            raise Unsupported("a derivative of something that is not a traced function")
        self.k, arity, self.body = g.args[f.i]
        if arity != 1:
            raise Unsupported("a derivative of a function of more than the scene")
        self.S = remap[scene.i]
        self.flow = flow
        # the keys a flow given as a dict moves (other flows: the engine's Flow, whose keys are read)
        self.keys = None
        if flow is not None and g.ops[flow.i] == "dict":
            self.keys = frozenset(g.args[flow.i][0])
        self.P: dict[int, Ref] = {}
        self.D: dict[int, Any] = {}
        self.read: set[str] = set()
        self._tangent: Ref | None = None

    # -- the new graph's nodes ------------------------------------------------------------------
    def add(self, op: str, args: tuple) -> Ref:
        return self.new.add(op, args)

    def primal(self, a: Any) -> Any:
        """An argument of the body as the new graph holds it (the function's scene is the call's)."""
        t = type(a)
        if t is Ref:
            if self.k in self.deps[a.i]:
                return self.P[a.i]
            return self.remap[a.i]
        if t is tuple:
            return tuple(self.primal(x) for x in a)
        return a

    def sum(self, x: Any, y: Any, op: str = "add") -> Any:
        if y is None:
            return x
        if x is None:
            return self.add("neg", (y,)) if op == "sub" else y
        return self.add(op, (x, y))

    def zero(self, j: Any) -> Ref:
        """A zero shaped like the body's node j (or literal): x·0, or the scene's 0 for a literal."""
        g = self.g
        if type(j) is not Ref:
            return self.add("call", (self.S, "const", (0,), ()))
        op, a = g.ops[j.i], g.args[j.i]
        if op == "const":
            return self.add("call", (self.S, "const", (0,), ()))
        if op in ("list", "tuple", "dict"):
            return self.hand_on(None, j)
        if op == "item" and type(a[0]) is Ref:
            # a part of a container (the value of a nested derivative, paired with its tangent step): its zero
            base = a[0] if g.ops[a[0].i] in ("list", "tuple", "dict") else self.container(a[0])
            part = None if base is None else _part(g, base, a[1])
            if part is not None:
                return self.zero(part)
        if op == "attr":
            numeric = a[1] in MATRICES or a[1] in NUMBERS or a[1] in ("Xdot", "Pdot")
        elif op == "call":
            numeric = a[1] in NUMERIC_CALLS
        elif op == "item":
            base = a[0]
            numeric = type(base) is Ref and g.ops[base.i] == "attr" and g.args[base.i][1] == "a"
        else:
            numeric = op in NUMERIC_OPS
        if not numeric:
            raise Unsupported(f"a value of the function that is not a number or a matrix ({op})")
        return self.add("mul", (self.primal(j), 0))

    def hand_on(self, d: Any, j: Any) -> Ref:
        """The derivative d of the body's node (or literal) j as a node: zeros built, containers made."""
        if d is None:
            g = self.g
            if type(j) is Ref and g.ops[j.i] in ("list", "tuple", "dict"):
                a = g.args[j.i]
                elems = a[1] if g.ops[j.i] == "dict" else a
                d = _Container(g.ops[j.i], a[0] if g.ops[j.i] == "dict" else None, [None] * len(elems),
                               list(elems))
            else:
                return self.zero(j)
        if type(d) is _Container:
            parts = tuple(self.hand_on(x, p) for x, p in zip(d.parts, d.primals))
            return self.add(d.op, (d.keys, parts) if d.op == "dict" else parts)
        return d

    def component(self, key: str) -> Any:
        """The flow's component moving ``key`` (None when a flow given as a dict does not move it)."""
        if self.keys is not None and key not in self.keys:
            return None
        self.read.add(key)
        return ("component", key)     # resolved once every key the body reads is known

    def body_nodes(self) -> list[int]:
        """The body's nodes that read the function's scene, in the graph's order."""
        todo, seen = [], set()
        stack = [self.body] if type(self.body) is Ref else []
        while stack:
            r = stack.pop()
            if r.i in seen or self.k not in self.deps[r.i]:
                continue
            seen.add(r.i)
            todo.append(r.i)
            stack.extend(Ref(j) for j in self.g.refs(r.i))
        return sorted(todo)

    # -- the rules ------------------------------------------------------------------------------
    def build(self) -> Ref:
        g, k = self.g, self.k
        todo = self.body_nodes()
        # first the rules (components stay placeholders), then the nodes: a placeholder is resolved
        # when the derivative is written into the graph
        self.plan: dict[int, Any] = {}
        for j in todo:
            plan = self.rule(j)
            if type(plan) is tuple and plan[0] == g.ops[j] != "scene" and not any(self.moves(Ref(x)) for x in g.refs(j)):
                plan = None                 # an operation on values that do not move
            self.plan[j] = plan
        if type(self.body) is not Ref:
            raise Unsupported("a function whose value is a constant")
        # the flow's components, read (and the flow checked) by one engine step
        keys = tuple(sorted(self.read))
        flow = self.make_flow() if self.flow is None else self.remap[self.flow.i]
        self._tangent = self.tangent_step(flow, keys)
        for j in todo:
            self.P[j] = self.primal_node(j)
            self.D[j] = self.emit(j, self.plan[j])
        b = self.body.i
        d = self.D.get(b) if k in self.deps[b] else None
        value = self.hand_on(d, self.body)
        # the derivative is the flow's check and the value: the flow is checked whatever the body reads
        pair = self.add("tuple", (self._tangent, value))
        return self.add("item", (pair, 1))

    def make_flow(self) -> Ref:
        raise AssertionError("a derivative with no flow")

    def tangent_step(self, flow: Ref, keys: tuple) -> Ref:
        """The engine step that reads (and checks) the flow's components ``keys``."""
        return self.add("prim", (Named(TANGENT), self.S, flow, keys))

    def primal_node(self, j: int) -> Ref:
        """The value of the body's node j in the new graph (the function's scene is the call's)."""
        g = self.g
        return self.S if g.ops[j] == "scene" else self.add(g.ops[j], self.primal(g.args[j]))

    def rule(self, j: int) -> Any:
        """The derivative of node j as a recipe over the derivatives of its arguments (D) and their
        primal values (P), checked for support before anything is written."""
        g = self.g
        op, a = g.ops[j], g.args[j]
        if op == "scene":
            if a[0] != self.k:
                raise Unsupported("a function that reads another function's scene")
            return ("scene",)
        if op == "attr":
            base, name = a
            if type(base) is not Ref or g.ops[base.i] != "scene":
                raise Unsupported(f"an attribute {name!r} of an engine value that moves with the point")
            if name in ("X", "P", "Y", "Q", "Zc", "Zc_dot"):
                c = self.component(name)
                return None if c is None else c
            if name in ("Phi", "Psi"):
                return (name, self.component("X"), self.component("P"))
            if name in CONSTANT_ATTRS:
                return None
            if name == "a":
                return None
            raise Unsupported(f"the scene's {name} (its derivative along a flow is the scene's business)")
        if op == "call":
            scene, name, args, kw = a
            if kw:
                raise Unsupported(f"s.{name} with keyword arguments")
            if type(scene) is not Ref or g.ops[scene.i] != "scene" or g.args[scene.i] != (self.k,):
                raise Unsupported(f"s.{name} of another scene")
            if name in CONSTANT_CALLS or name == "sym_operator":
                return None                 # (the operator: its coefficients are constants of the point)
            if name in ("tr", "conj"):
                return (op, name)
            if name in ("killing", "realify", "scalar_matrix"):
                return (op, name)
            if name == "resolvent":
                return (op, name) if self.moves(args[0]) else None
            if name == "mat":
                rows = args[0]
                if type(rows) is not Ref or g.ops[rows.i] != "list" or any(
                        type(x) is not Ref or g.ops[x.i] != "list" for x in g.args[rows.i]):
                    raise Unsupported("a matrix of entries an engine step made")
                return (op, name)
            raise Unsupported(f"s.{name} inside the function (a nested {_NESTED.get(name, name)})")
        if op in ("add", "sub", "neg", "matmul", "mul", "div", "pow", "T", "inv", "trace", "entry", "block",
                  "list", "tuple", "dict"):
            return (op,)
        if op == "item":
            base, key = a
            if type(base) is Ref and g.ops[base.i] in ("list", "tuple", "dict"):
                return (op,)
            if type(base) is Ref and self._tangent_of_own(base.i):
                return (op,)                # a component of a flow, read by a nested derivative
            if type(base) is Ref and self.container(base) is not None:
                return (op,)                # a part of a part of a container (a nested derivative's value)
            if type(base) is Ref and g.ops[base.i] == "attr" and g.args[base.i][1] == "a":
                return None                 # an eigenvalue of A
            raise Unsupported("a part of an engine value that moves with the point")
        if op == "fn":
            raise Unsupported("a function of the scene defined inside the function (a nested derivative, "
                              "gradient, flow or bracket)")
        if op == "prim" and type(a[0]) is Named and a[0].qualname in ZERO_PRIMITIVES:
            self.check_at_rest(a)
            return None                     # zero wherever it is defined, at arguments that do not move
        if op == "prim" and type(a[0]) is Named and a[0].qualname in CONSTANT_PRIMITIVES:
            if any(self.moves(x) for x in a[1:]):
                raise Unsupported(f"an engine step ({a[0].qualname.rsplit('.', 1)[-1]}) at a moving argument")
            return None                     # a coordinate basis vector: constant along every flow
        if op == "apply" and _own_operator(g, a, self.k):
            return (op,)                    # 𝔸 linear with constant coefficients: d𝔸(x) = 𝔸(dx)
        if op == "prim" and type(a[0]) is Named and a[0].qualname == SOLVE:
            return ("solve",)               # x = C⁻¹b: dx = C⁻¹(db − dC·x)
        if self._tangent_of_own(j):
            # a derivative nested in this one, written as nodes (see :func:`_nested`): its tangent step reads
            # the components of its flow, which move as the flow's parts do (a flow given by its parts)
            flow = a[2]
            if not self.moves(flow):
                return None
            if type(flow) is not Ref or g.ops[flow.i] != "dict":
                raise Unsupported("a derivative nested in the function along a flow that moves with the point "
                                  "and is not given by its components")
            return ("tangent",)
        if op == "prim" and type(a[0]) is Named and a[0].qualname == SYM_COORDS:
            return ("linear",)              # a linear step of its matrix
        if op in ("prim", "apply"):
            what = a[0].qualname.rsplit(".", 1)[-1] if op == "prim" and type(a[0]) is Named else "an operator"
            raise Unsupported(f"an engine step ({what}) that moves with the point")
        raise Unsupported(f"a {op} inside the function")

    def container(self, a: Ref) -> Ref | None:
        """The list, tuple or dict node that ``a``, a part of a part of a container (an ``item`` of an
        ``item`` ... of a container, each key of the container), stands for (None when it is not one)."""
        g = self.g
        seen = 0
        while g.ops[a.i] == "item" and seen < 64:
            base, key = g.args[a.i]
            if type(base) is not Ref or g.ops[base.i] not in ("list", "tuple", "dict", "item"):
                return None
            if g.ops[base.i] == "item":
                inner = self.container(base)
                if inner is None:
                    return None
                base = inner
            part = _part(g, base, key)
            if type(part) is not Ref:
                return None
            a, seen = part, seen + 1
        return a if g.ops[a.i] in ("list", "tuple", "dict") else None

    def _tangent_of_own(self, j: int) -> bool:
        """Whether node j is the tangent step of a derivative on the function's own scene (a derivative
        nested in this one, written as nodes by an earlier pass)."""
        g = self.g
        if g.ops[j] != "prim":
            return False
        a = g.args[j]
        return (type(a[0]) is Named and a[0].qualname == TANGENT and len(a) == 4 and type(a[1]) is Ref
                and g.ops[a[1].i] == "scene" and g.args[a[1].i] == (self.k,))

    def check_at_rest(self, a: tuple) -> None:
        """A check step (a zero primitive) is constant, and hands its arguments no adjoint, only where none of its
        arguments depends on the function's scene: a check made at the point says nothing of its first order (a
        gradient right at the point and not along the flow, or on V(n, r) and not off it, would have its wrong
        derivative taken).  Elsewhere it is left to the scene, whose dual numbers make the check in both parts."""
        if any(type(x) is Ref and self.k in self.deps[x.i] for x in a[1:]):
            raise Unsupported(f"an engine check ({a[0].qualname.rsplit('.', 1)[-1]}) at a moving argument")

    def moves(self, a: Any) -> bool:
        """Whether an argument of the body moves with the point (reads the function's scene through
        something with a nonzero derivative)."""
        if type(a) is not Ref:
            return False
        if self.k not in self.deps[a.i]:
            return False
        return self.plan.get(a.i) not in (None, ("scene",))

    def d(self, a: Any) -> Any:
        """The derivative of an argument (None: 0)."""
        if type(a) is not Ref or self.k not in self.deps[a.i]:
            return None
        return self.D[a.i]

    def dref(self, a: Any) -> Any:
        """The derivative of an argument as a node (containers built), or None."""
        x = self.d(a)
        if type(x) is _Container:
            return self.hand_on(x, a)
        return x

    def resolve(self, c: Any) -> Any:
        if c is None:
            return None
        return self.add("item", (self._tangent, c[1]))

    def emit(self, j: int, plan: Any) -> Any:
        """Write the derivative of one node into the new graph (its arguments' derivatives written)."""
        if plan is None or plan == ("scene",) or plan == ("tangent",):
            return None                     # (a tangent step: its components' derivatives are read by item)
        if plan[0] == "component":
            return self.resolve(plan)
        if plan[0] in ("Phi", "Psi"):
            dX, dP = self.resolve(plan[1]), self.resolve(plan[2])
            X, P = self.add("attr", (self.S, "X")), self.add("attr", (self.S, "P"))
            T = lambda x: None if x is None else self.add("T", (x,))      # noqa: E731
            mm = lambda x, y: None if x is None or y is None else self.add("matmul", (x, y))   # noqa: E731
            if plan[0] == "Phi":        # Φ = PXᵀ − XPᵀ
                first = self.sum(mm(dP, self.add("T", (X,))), mm(P, T(dX)))
                second = self.sum(mm(dX, self.add("T", (P,))), mm(X, T(dP)))
            else:                       # Ψ = XᵀP − PᵀX
                first = self.sum(mm(T(dX), P), mm(self.add("T", (X,)), dP))
                second = self.sum(mm(T(dP), X), mm(self.add("T", (P,)), dX))
            return self.sum(first, second, "sub")
        return self._op(j)

    def _op(self, j: int) -> Any:      # noqa: C901 - one branch per op, as in the evaluator
        g, add, d, p = self.g, self.add, self.d, self.primal
        op, a = g.ops[j], g.args[j]
        if op in ("add", "sub"):
            return self.sum(d(a[0]), d(a[1]), op)
        if op == "neg":
            x = d(a[0])
            return None if x is None else add("neg", (x,))
        if op in ("T", "trace"):
            x = d(a[0])
            return None if x is None else add(op, (x,))
        if op in ("matmul", "mul"):
            x, y = d(a[0]), d(a[1])
            left = None if x is None else add(op, (x, p(a[1])))
            right = None if y is None else add(op, (p(a[0]), y))
            return self.sum(left, right)
        if op == "div":                 # (a/c)' = a'/c − (a/c)·c'/c
            x, y = d(a[0]), d(a[1])
            c = p(a[1])
            left = None if x is None else add("div", (x, c))
            right = None if y is None else add("div", (add("mul", (self.P[j], y)), c))
            return self.sum(left, right, "sub")
        if op == "pow":                 # (cᵏ)' = k·cᵏ⁻¹·c'
            x, e = d(a[0]), a[1]
            if x is None or e == 0:
                return None
            if e == 1:
                return x
            return add("mul", (add("mul", (e, add("pow", (p(a[0]), e - 1)))), x))
        if op == "inv":                 # (M⁻¹)' = −M⁻¹ M' M⁻¹
            x = d(a[0])
            if x is None:
                return None
            return add("neg", (add("matmul", (add("matmul", (self.P[j], x)), self.P[j])),))
        if op == "entry":
            x = self.dref(a[0])
            return None if x is None else add("entry", (x,) + tuple(a[1:]))
        if op == "apply":
            x = self.dref(a[1])
            return None if x is None else add("apply", (p(a[0]), x))
        if op == "prim" and a[0].qualname == SYM_COORDS:
            x = self.dref(a[2])
            return None if x is None else add("prim", (a[0], self.S, x))
        if op == "prim":                # x = solve(C, b): C dx = db − dC·x
            C, b = a[2], a[3]
            rhs = self.solve_rhs(self.dref(C), self.dref(b), self.P[j])
            return None if rhs is None else add("prim", (a[0], self.S, p(C), rhs) + tuple(p(a[4:])))
        if op == "block":
            rows, cols, blocks = a
            ds = [self.dref(b) for b in blocks]
            if all(x is None for x in ds):
                return None
            return add("block", (rows, cols, tuple(x if x is not None else self.zero(b) for x, b in zip(ds, blocks))))
        if op in ("list", "tuple", "dict"):
            elems = a[1] if op == "dict" else a
            parts = [d(x) for x in elems]
            if all(x is None for x in parts):
                return None
            return _Container(op, a[0] if op == "dict" else None, parts, list(elems))
        if op == "item":
            base, key = a
            bop, ba = g.ops[base.i], g.args[base.i]
            if bop == "prim":               # the component ``key`` of a nested derivative's flow
                keys, vals = g.args[ba[2].i]
                return self.dref(vals[keys.index(key)]) if key in keys else None
            if bop == "item":               # a part of a part of a container
                part = _part(g, self.container(base), key)
                return d(part) if type(part) is Ref else None
            if bop == "dict":
                keys, vals = ba
                return d(vals[keys.index(key)]) if key in keys else None
            return d(ba[key]) if type(key) is int and -len(ba) <= key < len(ba) else None
        if op == "call":
            name, args = a[1], a[2]
            S = self.S
            if name in ("tr", "conj"):
                x = self.dref(args[0])
                return None if x is None else add("call", (S, name, (x,), ()))
            if name == "resolvent":        # R(μ) = (μI − A)⁻¹: R' = −μ'·R²
                x = self.dref(args[0])
                if x is None:
                    return None
                R = self.P[j]
                return add("neg", (add("mul", (x, add("matmul", (R, R)))),))
            if name == "killing":
                x, y = self.dref(args[0]), self.dref(args[1])
                left = None if x is None else add("call", (S, "killing", (x, p(args[1])), ()))
                right = None if y is None else add("call", (S, "killing", (p(args[0]), y), ()))
                return self.sum(left, right)
            if name == "realify":
                x, y = self.dref(args[0]), self.dref(args[1])
                if x is None and y is None:
                    return None
                x = x if x is not None else self.zero(args[0])
                y = y if y is not None else self.zero(args[1])
                return add("call", (S, "realify", (x, y), ()))
            if name == "scalar_matrix":
                x = self.dref(args[0])
                return None if x is None else add("call", (S, "scalar_matrix", (x,) + tuple(p(args[1:])), ()))
            if name == "mat":
                rows, tags = args
                cells = [[d(c) for c in g.args[row.i]] for row in g.args[rows.i]]
                if all(c is None for row in cells for c in row):
                    return None
                new_rows = tuple(add("list", tuple(c if c is not None else 0 for c in row)) for row in cells)
                return add("call", (S, "mat", (add("list", new_rows), tags), ()))
        raise AssertionError(f"no rule for {op}")


    def solve_rhs(self, dC: Any, db: Any, x: Ref) -> Any:
        """The right-hand side db − dC·x of the tangent of x = solve(C, b) (None: 0)."""
        return self.sum(db, None if dC is None else self.add("matmul", (dC, x)), "sub")


#: the engine step that makes the claim's problem at another point of T*V (a scene of its own)
AT_POINT = "stiefelsym.twisted.at_point"


#: what the dimension-free scene says (``_graph_flows``) when a derivative along a flow at the claim's problem
#: at another point of T*V (``twisted.at_point``) may be graph nodes: the point's values and the flow's
#: components there are the point scene's own (computed at its generic point, then evaluated at the point)
POINT_DERIVATIVES = "derivatives at the problem at another point"


def _part(g: Graph, base: Any, key: Any) -> Any:
    """The part ``key`` of a list, tuple or dict node ``base`` (None when there is no such part)."""
    if type(base) is not Ref:
        return None
    op, a = g.ops[base.i], g.args[base.i]
    if op == "dict":
        return a[1][a[0].index(key)] if key in a[0] else None
    if op in ("list", "tuple") and type(key) is int and -len(a) <= key < len(a):
        return a[key]
    return None


def _claim_scene(g: Graph, scene: Any, new: Graph, derivative: bool = False) -> bool:
    """Whether a derivative's, gradient's or flow's scene is the claim's: its own scene, or, on a coordinate
    scene (the pass was given ``TWISTED``), the claim's problem at another point of T*V
    (``twisted.at_point(s, X, P)``, a copy of the scene with that point); for a ``derivative`` along a flow,
    also the dimension-free scene's problem at another point (the pass was given ``POINT_DERIVATIVES``)."""
    if type(scene) is not Ref:
        return False
    if g.ops[scene.i] == "scene":
        return g.args[scene.i] == (0,)
    a = g.args[scene.i]
    flows = new.cache.get("flows", ())
    return (g.ops[scene.i] == "prim" and type(a[0]) is Named and a[0].qualname == AT_POINT
            and (TWISTED in flows or (derivative and POINT_DERIVATIVES in flows)) and len(a) == 4
            and type(a[1]) is Ref and g.ops[a[1].i] == "scene" and g.args[a[1].i] == (0,))


def _own_operator(g: Graph, a: tuple, k: int) -> bool:
    """Whether an ``apply`` node's arguments ``a`` apply the symmetric operator of the function's own
    scene (``s.sym_operator(name)``, k the function's number) to one matrix."""
    f = a[0]
    if len(a) != 2 or type(f) is not Ref or g.ops[f.i] != "call" or g.args[f.i][1] != "sym_operator":
        return False
    sc = g.args[f.i][0]
    return type(sc) is Ref and g.ops[sc.i] == "scene" and g.args[sc.i] == (k,)


_NESTED = {"d": "derivative along a flow", "gradient": "gradient", "dirac_flow": "flow",
           "multiplier_flow": "flow", "canonical_flow": "flow", "bracket": "Poisson bracket",
           "canonical_bracket": "Poisson bracket", "jacobian": "Jacobian", "tangent": "tangent scene",
           "constraint_bracket_matrix": "matrix of constraint brackets", "sym_operator": "operator"}


# ---------------------------------------------------------------------------------------------
# gradients: reverse mode over the matrix operations (the cyclic derivative of a trace form)

#: the engine step that hands a gradient over as the scene hands its own (registered below)
GRADIENT = "stiefelsym.ir.derivative.gradient_pair"


def gradient_pair(scene: Any, HX: Any, HP: Any, *value: Any) -> tuple:
    """(∂H/∂X, ∂H/∂P) computed by the graph, as the scene's own gradient hands them on (the scene's
    checks of a gradient made, the spaces n x r; None: a zero gradient, the scene's exact zero).
    ``value``: H's value, not used (an argument so that H is evaluated, as the scene's reverse tape
    evaluates it: its reads of coordinates recorded, its refusals made, whatever the adjoints need).
    Engine step of the transformed graphs."""
    f = getattr(scene, "_gradient_pair", None)
    if f is None:
        raise TypeError(f"a gradient on a {type(scene).__name__} (a scene with no gradients)")
    return f(HX, HP)


PRIMITIVES[GRADIENT] = gradient_pair

#: the engine steps of the adjoints of coordinate reads (registered below)
SCATTER = "stiefelsym.ir.derivative.scatter"
ADJOINT = "stiefelsym.ir.derivative.adjoint_part"
BLOCK_ADJOINT = "stiefelsym.ir.derivative.block_adjoint"
ADJOINT_MATRIX = "stiefelsym.ir.derivative.adjoint_matrix"


def _index(key: tuple) -> tuple:
    return tuple(slice(*k[1:]) if type(k) is tuple else k for k in key)


def _number(field: Any, x: Any) -> Any:
    return field.const(x) if type(x) in (int, Fraction) else x


def _full(like: Any, G: Any, c: Any) -> Any:
    """G + c·I (G None: 0; c None: 0), a matrix of ``like``'s field, shape and spaces."""
    from stiefelsym.backends.matrix import Mat, scalar_matrix
    f = like.field
    if c is not None:
        m, k = like._shape()
        if m != k:
            raise ValueError("a multiple of I as the adjoint of a matrix that is not square")
        I = scalar_matrix(_number(f, c), m, f, like.tags[0], like.tracker)
        I = I._retyped(f, like.tags, like.tracker)
        G = I if G is None else G + I
    if G is None:
        G = Mat.zeros(*like._shape(), f, like.tags, like.tracker)
    return G


def scatter(scene: Any, like: Any, value: Any, *key: Any) -> Any:
    """The adjoint of the read of ``like`` at ``key`` (an entry, or a block read by slices) whose
    adjoint is ``value``: the zero matrix of ``like``'s shape and spaces with ``value`` at ``key``, as
    the scene's reverse tape scatters it (nothing recorded: the read itself is made, and recorded, as
    a part of H's value, which :func:`gradient_pair` takes).  Engine step of the transformed graphs."""
    from stiefelsym.backends.matrix import Mat
    out = Mat.zeros(*like._shape(), like.field, like.tags, like.tracker)
    a, idx = out._a, _index(key)
    if isinstance(value, Mat):
        part = a[idx]
        a[idx] = value._view().reshape(part.shape)
    else:
        a[idx] = _number(like.field, value)
    return out


def adjoint_matrix(scene: Any, like: Any, G: Any, c: Any) -> Any:
    """The adjoint G + c·I of the matrix ``like`` as one matrix of its shape and spaces.  Engine step
    of the transformed graphs."""
    return _full(like, G, c)


def adjoint_part(scene: Any, like: Any, G: Any, c: Any, i: int, j: int) -> Any:
    """Entry (i, j) of the adjoint G + c·I of the matrix ``like`` (a matrix of given entries: the
    adjoint of each entry), read as the scene's reverse tape reads it (nothing recorded).  Engine
    step of the transformed graphs."""
    return _full(like, G, c)._view()[i, j]


def block_adjoint(scene: Any, whole: Any, G: Any, c: Any, rows: int, cols: int, k: int, *blocks: Any) -> Any:
    """The part of the adjoint G + c·I of the block matrix ``whole`` at its ``k``-th block (of
    ``rows`` x ``cols``, in the order of ``blocks``), with that block's spaces.  Engine step of the
    transformed graphs."""
    from stiefelsym.backends.matrix import Mat
    shapes = [b._shape() for b in blocks]
    r, q = divmod(k, cols)
    r0 = sum(shapes[i * cols][0] for i in range(r))
    c0 = sum(shapes[j][1] for j in range(q))
    m, w = shapes[k]
    a = _full(whole, G, c)._view()[r0:r0 + m, c0:c0 + w].copy()
    return Mat._wrap(a, whole.field, blocks[k].tags, whole.tracker)


PRIMITIVES[SCATTER] = scatter
PRIMITIVES[ADJOINT] = adjoint_part
PRIMITIVES[BLOCK_ADJOINT] = block_adjoint
PRIMITIVES[ADJOINT_MATRIX] = adjoint_matrix

_S, _M, _L, _O = "number", "matrix", "list", "operator"
#: scene matrices and numbers the gradient treats as constants (only X and P are its variables)
_GRAD_CONSTANT_ATTRS = CONSTANT_ATTRS | {"Y", "Q", "Zc", "Zc_dot"}
_MATRIX_CALLS = frozenset({"resolvent", "mat", "zeros", "identity", "scalar_matrix", "generic", "fresh", "general_params",
                           "conj", "realify"})
_SCALAR_CALLS = frozenset({"tr", "killing", "q", "const", "scalar"})


def _constant_vector(a: Any) -> bool:
    """Whether an engine step is a constant matrix of coordinates: a basis vector of ℝʳ, the projector of a
    block of ℝʳ, a reflection of ℝⁿ."""
    return (type(a) is Named and a.qualname in CONSTANT_PRIMITIVES
            and a.qualname.rsplit(".", 1)[-1] in ("basis_vector", "last_basis_vector", "block_projector",
                                                  "reflection", "eigenspace_projector", "kernel_frame",
                                                  "kernel_annihilator"))


class _Gradient(_Derivative):
    """(∂H/∂X, ∂H/∂P) of one ``gradient`` node's function H, a number built by matrix operations:
    the adjoints of the body's nodes, from the value down to X and P (a matrix's adjoint is a sum of
    matrices and of a multiple of I, which a trace makes and a product absorbs)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int, f: Any = None,
                 at: tuple | None = None) -> None:
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        scene, name, args, kw = g.args[i] if at is None else at + ((), ())
        what = _WHAT.get(name, "a gradient")
        if f is None:
            if kw or len(args) != 1:
                raise Unsupported(f"{what} with further arguments")
            f = args[0]
        if not _claim_scene(g, scene, new):
            raise Unsupported(f"{what} on a scene other than the claim's (inside a function of the scene)")
        if type(f) is not Ref or g.ops[f.i] != "fn":
            raise Unsupported(f"{what} of something that is not a traced function")
        self.k, arity, self.body = g.args[f.i]
        if arity != 1 or type(self.body) is not Ref:
            raise Unsupported("a gradient of a function of more than the scene")
        self.S = remap[scene.i]
        self.P: dict[int, Ref] = {}

    def kind(self, a: Any) -> str:
        if type(a) is not Ref:
            return _S
        return self.kinds.get(a.i) or self._kind_of(a.i)

    def _kind_of(self, j: int) -> str:
        g = self.g
        op, a = g.ops[j], g.args[j]
        if op in ("matmul", "T", "inv", "block", "apply"):
            return _M
        if op == "list":
            return _L
        if op == "call" and a[1] == "sym_operator":
            return _O
        if op in ("trace", "pow", "const"):
            return _S
        if op in ("add", "sub", "neg", "div"):
            return self.kind(a[0])
        if op == "mul":
            return _M if _M in (self.kind(a[0]), self.kind(a[1])) else _S
        if op == "attr":
            if a[1] in MATRICES:
                return _M
            if a[1] in NUMBERS:
                return _S
        if op == "call":
            if a[1] in _MATRIX_CALLS:
                return _M
            if a[1] in _SCALAR_CALLS:
                return _S
        if op == "entry":
            return _S if all(type(x) is int for x in a[1:]) else _M
        if op == "item" and type(a[0]) is Ref and g.ops[a[0].i] == "attr" and g.args[a[0].i][1] == "a":
            return _S
        if op == "attr" and a[1] == "a":
            return _S                       # the eigenvalues of A, read one by one (constants)
        if op == "prim" and _constant_vector(a[0]):
            return _M                       # a coordinate basis vector (a constant)
        if op == "prim" and type(a[0]) is Named and a[0].qualname in ZERO_PRIMITIVES:
            return _M                       # a check whose value is a zero matrix
        raise Unsupported(f"a {op} whose kind (number or matrix) the graph does not show")

    def build(self) -> Ref:
        HX, HP, value = self.adjoints()
        return self.add("prim", (Named(GRADIENT), self.S, HX, HP) + value)

    def adjoints(self) -> tuple[Any, Any, tuple]:
        """(H_X, H_P, (H,)): the adjoints of X and P as nodes (None where H does not depend on it) and
        H's value (empty where H does not read the point)."""
        g, k = self.g, self.k
        todo = self.body_nodes()
        self.kinds: dict[int, str] = {}
        self.moves_set: set[int] = set()
        for j in todo:
            if (g.ops[j] == "attr" and g.args[j][1] in ("X", "P", "Phi", "Psi")) or any(
                    r in self.moves_set for r in g.refs(j)):
                self.moves_set.add(j)
        for j in todo:
            if g.ops[j] != "scene":
                self.kinds[j] = self._kind_of(j)
                self.check(j)
        if k in self.deps[self.body.i] and self.kinds[self.body.i] != _S:
            raise Unsupported("a gradient of a function whose value is not a number")
        # the point first, then the body's values (the scene's reverse mode makes its leaves X, P
        # before it evaluates H: parameters drawn on first use are drawn in that order)
        X, P = self.add("attr", (self.S, "X")), self.add("attr", (self.S, "P"))
        for j in todo:
            self.P[j] = self.S if g.ops[j] == "scene" else self.add(g.ops[j], self.primal(g.args[j]))
        # adjoints, from the value down: a matrix's adjoint is (terms, coefficient of I), a number's a term list
        adj: dict[int, tuple[list, list]] = {}
        grads: dict[str, list] = {"X": [], "P": []}
        if k in self.deps[self.body.i]:
            adj[self.body.i] = ([1], [])
        for j in reversed(todo):
            if j not in adj or g.ops[j] == "scene":
                continue
            terms, ident = adj.pop(j)
            self.propagate(j, terms, ident, adj, grads)
        HX = self.total(grads["X"], X)
        HP = self.total(grads["P"], P)
        value = (self.P[self.body.i],) if k in self.deps[self.body.i] else ()
        return HX, HP, value

    def check(self, j: int) -> None:
        """Refuse (before anything is written) what the backward sweep has no rule for."""
        g = self.g
        op, a = g.ops[j], g.args[j]
        if op == "attr":
            if type(a[0]) is not Ref or g.ops[a[0].i] != "scene":
                raise Unsupported(f"an attribute {a[1]!r} of an engine value that moves with the point")
            if a[1] not in ("X", "P", "Phi", "Psi", "a") and a[1] not in _GRAD_CONSTANT_ATTRS:
                raise Unsupported(f"the scene's {a[1]} in a gradient")
        elif op == "call":
            if a[1] in CONSTANT_CALLS:
                return
            if a[1] == "resolvent" and not self.moving(a[2][0]):
                return
            if a[1] in ("tr", "killing", "sym_operator"):
                return
            if a[1] == "mat":
                rows = a[2][0] if a[2] else None
                if a[3] or len(a[2]) != 2 or type(rows) is not Ref or g.ops[rows.i] != "list" or any(
                        type(x) is not Ref or g.ops[x.i] != "list" for x in g.args[rows.i]):
                    raise Unsupported("a matrix of entries an engine step made inside the function of a gradient")
                return
            raise Unsupported(f"s.{a[1]} inside the function of a gradient")
        elif op == "item":
            if not (type(a[0]) is Ref and g.ops[a[0].i] == "attr" and g.args[a[0].i][1] == "a"):
                raise Unsupported("a part of a value inside the function of a gradient")
        elif op == "apply":
            if not _own_operator(g, a, self.k):
                raise Unsupported("an operator other than the scene's symmetric operator inside the function of a gradient")
        elif op == "list":
            return                          # the rows of a matrix of given entries (s.mat sends to its cells)
        elif op == "prim" and type(a[0]) is Named and a[0].qualname in ZERO_PRIMITIVES:
            self.check_at_rest(a)
            return                          # zero wherever defined, at arguments that do not move: no adjoint
        elif op == "prim" and _constant_vector(a[0]):
            if any(self.moving(x) for x in a[1:]):
                raise Unsupported("a coordinate basis vector at a moving argument inside the function of a gradient")
        elif op not in ("add", "sub", "neg", "matmul", "mul", "div", "pow", "T", "inv", "trace", "const", "entry",
                        "block"):
            raise Unsupported(f"a {op} inside the function of a gradient")

    def moving(self, a: Any) -> bool:
        """Whether an argument reads X or P (through the function's scene)."""
        return type(a) is Ref and a.i in self.moves_set

    # -- the backward sweep -----------------------------------------------------------------------
    def scalar_sum(self, terms: list) -> Any:
        lits = [t for t in terms if type(t) is not Ref]
        refs = [t for t in terms if type(t) is Ref]
        c = sum(lits) if lits else 0
        acc = None
        for t in refs:
            acc = t if acc is None else self.add("add", (acc, t))
        if acc is None:
            return c
        return acc if c == 0 else self.add("add", (acc, self.lit(c)))

    def lit(self, x: Any) -> Any:
        """A literal number as an argument: an int as it is, a fraction as the scene's constant (the
        backends' numbers take ints, not Fractions)."""
        if type(x) is Ref or type(x) is int:
            return x
        x = Fraction(x)
        if x.denominator == 1:
            return int(x)
        return self.add("call", (self.S, "const", (x,), ()))

    def smul(self, x: Any, y: Any) -> Any:
        """x·y for numbers (refs or literals), folding literal ones."""
        if type(x) is not Ref and type(y) is not Ref:
            return x * y
        x, y = (v if type(v) is Ref or v == 1 else self.lit(v) for v in (x, y))
        if type(x) is not Ref and x == 1:
            return y
        if type(y) is not Ref and y == 1:
            return x
        if type(x) is not Ref:
            return self.add("mul", (x, y))
        return self.add("mul", (x, y)) if type(y) is Ref else self.add("mul", (y, x))

    def mat_sum(self, terms: list) -> Any:
        acc = None
        for t in terms:
            acc = t if acc is None else self.add("add", (acc, t))
        return acc

    def send(self, adj: dict, a: Any, terms: list, ident: list = ()) -> None:
        if not self.moving(a):
            return
        t, i = adj.setdefault(a.i, ([], []))
        t.extend(terms)
        i.extend(ident)

    def leaf(self, grads: dict, name: str, terms: list) -> None:
        grads[name].extend(terms)

    def propagate(self, j: int, terms: list, ident: list, adj: dict, grads: dict) -> None:  # noqa: C901
        g, add, p = self.g, self.add, self.primal
        op, a = g.ops[j], g.args[j]
        T = lambda x: add("T", (x,))                        # noqa: E731
        mm = lambda x, y: add("matmul", (x, y))             # noqa: E731
        if self.kinds[j] == _S:
            s = self.scalar_sum(terms)
            if type(s) is not Ref and s == 0:
                return
            if op == "add":
                self.send(adj, a[0], [s])
                self.send(adj, a[1], [s])
            elif op == "sub":
                self.send(adj, a[0], [s])
                self.send(adj, a[1], [self.neg(s)])
            elif op == "neg":
                self.send(adj, a[0], [self.neg(s)])
            elif op == "mul":                               # both numbers
                self.send(adj, a[0], [self.smul(s, p(a[1]))])
                self.send(adj, a[1], [self.smul(p(a[0]), s)])
            elif op == "div":                               # v = x/c: x̄ = s/c, c̄ = −s·v/c
                c = p(a[1])
                self.send(adj, a[0], [self.div(s, c)])
                self.send(adj, a[1], [self.div(self.neg(self.smul(s, self.P[j])), c)])
            elif op == "pow":                               # (xᵉ)' = e·xᵉ⁻¹
                e = a[1]
                if e != 0:
                    base = p(a[0]) if e == 2 else add("pow", (p(a[0]), e - 1))
                    self.send(adj, a[0], [self.smul(s, self.smul(e, base))])
            elif op in ("trace",) or (op == "call" and a[1] == "tr"):
                M = a[0] if op == "trace" else a[2][0]
                self.send(adj, M, [], [s])
            elif op == "call" and a[1] == "killing":        # ⟨a, b⟩ = −½ tr(ab)
                x, y = a[2]
                h = self.smul(Fraction(-1, 2), s)
                self.send(adj, x, [self.mscale(h, T(p(y)))])
                self.send(adj, y, [self.mscale(h, T(p(x)))])
            elif op == "entry":                             # x = M[i, j]: M̄ = x̄ at (i, j), 0 elsewhere
                self.send(adj, a[0], [add("prim", (Named(SCATTER), self.S, p(a[0]), self.lit(s)) + tuple(a[1:]))])
            elif op == "attr" or op == "call" or op == "const" or op == "item":
                return
            else:
                raise Unsupported(f"no rule for a {op} of numbers")
            return
        # a matrix node: adjoint Σ terms + (Σ ident)·I
        M = self.mat_sum(terms)
        c = self.scalar_sum(ident) if ident else 0
        has_c = type(c) is Ref or c != 0
        if M is None and not has_c:
            return
        if op == "add":
            self.send(adj, a[0], [M] if M is not None else [], [c] if has_c else [])
            self.send(adj, a[1], [M] if M is not None else [], [c] if has_c else [])
        elif op in ("sub", "neg"):
            nM = [add("neg", (M,))] if M is not None else []
            nc = [self.neg(c)] if has_c else []
            if op == "sub":
                self.send(adj, a[0], [M] if M is not None else [], [c] if has_c else [])
                self.send(adj, a[1], nM, nc)
            else:
                self.send(adj, a[0], nM, nc)
        elif op == "T":
            self.send(adj, a[0], [T(M)] if M is not None else [], [c] if has_c else [])
        elif op == "matmul":                                # C = AB: Ā = C̄Bᵀ, B̄ = AᵀC̄
            A, B = p(a[0]), p(a[1])
            left = ([mm(M, T(B))] if M is not None else []) + ([self.mscale(c, T(B))] if has_c else [])
            right = ([mm(T(A), M)] if M is not None else []) + ([self.mscale(c, T(A))] if has_c else [])
            self.send(adj, a[0], left)
            self.send(adj, a[1], right)
        elif op == "mul":                                   # C = x·Y (x a number)
            xs, ys = (a[0], a[1]) if self.kind(a[0]) == _S else (a[1], a[0])
            x, Y = p(xs), p(ys)
            self.send(adj, ys, [self.mscale(x, M)] if M is not None else [], [self.smul(x, c)] if has_c else [])
            self.send(adj, xs, self.inner(M, c if has_c else None, Y))
        elif op == "div":                                   # C = Y/x: Ȳ = C̄/x, x̄ = −⟨C̄, C⟩/x
            x = p(a[1])
            self.send(adj, a[0], [add("div", (M, x))] if M is not None else [],
                      [self.div(c, x)] if has_c else [])
            inner = self.inner(M, c if has_c else None, self.P[j])
            if inner:
                self.send(adj, a[1], [self.div(self.neg(self.scalar_sum(inner)), x)])
        elif op == "inv":                                   # C = M⁻¹: M̄ = −Cᵀ C̄ Cᵀ
            C = T(self.P[j])
            parts = ([mm(mm(C, M), C)] if M is not None else []) + ([self.mscale(c, mm(C, C))] if has_c else [])
            self.send(adj, a[0], [add("neg", (x,)) for x in parts])
        elif op == "attr" and a[1] in ("X", "P"):
            if has_c:
                raise Unsupported("a multiple of I as the adjoint of X or P")
            self.leaf(grads, a[1], [M])
        elif op == "attr" and a[1] in ("Phi", "Psi"):
            if M is None:
                return                                      # c·I: Φ and Ψ are skew, ⟨I, dΦ⟩ = 0
            X, P = self.add("attr", (self.S, "X")), self.add("attr", (self.S, "P"))
            K = add("sub", (M, T(M)))
            if a[1] == "Phi":                               # Φ = PXᵀ − XPᵀ: X̄ = −(C̄ − C̄ᵀ)P, P̄ = (C̄ − C̄ᵀ)X
                self.leaf(grads, "X", [add("neg", (mm(K, P),))])
                self.leaf(grads, "P", [mm(K, X)])
            else:                                           # Ψ = XᵀP − PᵀX: X̄ = −P(C̄ − C̄ᵀ), P̄ = X(C̄ − C̄ᵀ)
                self.leaf(grads, "X", [add("neg", (mm(P, K),))])
                self.leaf(grads, "P", [mm(X, K)])
        elif op == "entry":                                 # a block read by slices: scattered back
            G = self.full(j, M, c, has_c)
            self.send(adj, a[0], [add("prim", (Named(SCATTER), self.S, p(a[0]), G) + tuple(a[1:]))])
        elif op == "block":                                 # a block matrix: each block its part of the adjoint
            rows, cols, blocks = a
            G, cc = M, (self.lit(c) if has_c else None)
            prim = [p(b) for b in blocks]
            for k, b in enumerate(blocks):
                if self.moving(b):
                    self.send(adj, b, [add("prim", (Named(BLOCK_ADJOINT), self.S, self.P[j], G, cc, rows, cols, k)
                                           + tuple(prim))])
        elif op == "call" and a[1] == "mat":                # a matrix of given entries: each cell its entry
            G, cc = M, (self.lit(c) if has_c else None)
            for ri, row in enumerate(g.args[a[2][0].i]):
                for ci, x in enumerate(g.args[row.i]):
                    if self.moving(x):
                        self.send(adj, x, [add("prim", (Named(ADJOINT), self.S, self.P[j], G, cc, ri, ci))])
        elif op == "apply":                                 # y = 𝔸(x), 𝔸 self-adjoint for ⟨,⟩: x̄ = 𝔸(ȳ)
            self.send(adj, a[1], [add("apply", (p(a[0]), self.full(j, M, c, has_c)))])
        elif op in ("attr", "call", "const"):
            return                                          # constants
        elif op == "prim" and type(a[0]) is Named and a[0].qualname in ZERO_PRIMITIVES:
            pass                                            # zero wherever defined: its arguments get no adjoint
        else:
            raise Unsupported(f"no rule for a {op} of matrices")

    def full(self, j: int, M: Any, c: Any, has_c: bool) -> Any:
        """The adjoint Σ terms + c·I of the body's matrix node j as one matrix."""
        if not has_c:
            return M
        return self.add("prim", (Named(ADJOINT_MATRIX), self.S, self.P[j], M, self.lit(c)))

    def div(self, s: Any, c: Any) -> Any:
        """s/c for numbers (refs or exact literals)."""
        if type(s) is not Ref and s == 0:
            return 0
        if type(s) is not Ref and type(c) is not Ref:
            return Fraction(s) / c
        return self.add("div", (self.lit(s), self.lit(c)))

    def neg(self, s: Any) -> Any:
        return -s if type(s) is not Ref else self.add("neg", (s,))

    def mscale(self, x: Any, M: Ref) -> Ref:
        """x·M (x a number, ref or literal)."""
        if type(x) is not Ref and x == 1:
            return M
        return self.add("mul", (self.lit(x), M))

    def inner(self, M: Any, c: Any, Y: Ref) -> list:
        """⟨M + cI, Y⟩ = tr(MᵀY) + c·tr(Y), as terms."""
        out = []
        if M is not None:
            out.append(self.add("call", (self.S, "tr", (self.add("matmul", (self.add("T", (M,)), Y)),), ())))
        if c is not None:
            out.append(self.smul(c, self.add("call", (self.S, "tr", (Y,), ()))))
        return out

    def total(self, terms: list, leaf: Ref) -> Ref | None:
        """The adjoint of X or P: None where H does not depend on it (the scene's exact zero then,
        as its reverse tape gives it: no rounding error for float bounds to carry)."""
        return self.mat_sum(terms)


# ---------------------------------------------------------------------------------------------
# flows of a Hamiltonian and the Dirac bracket: the gradient by reverse mode, the multipliers in
# closed form

FLOW = "stiefelsym.ir.derivative.graph_flow"

_WHAT = {"gradient": "a gradient", "dirac_flow": "a Dirac flow", "multiplier_flow": "a multiplier flow",
         "canonical_flow": "a canonical flow", "bracket": "a Dirac bracket"}


def graph_flow(scene: Any, kind: str, H: Any, Xd: Any, Pd: Any, *multipliers: Any) -> Any:
    """A flow of H (``kind``: canonical_flow, dirac_flow, multiplier_flow) the graph computed, handed on
    as the scene's own method hands it (the closed forms' condition XᵀX = I_r checked there; the
    multipliers Λ, Π with the multiplier flow).  Engine step of the transformed graphs."""
    f = getattr(scene, "_graph_flow", None)
    if f is None:
        raise TypeError(f"a flow on a {type(scene).__name__} (a scene whose flows the graph does not compute)")
    Lam, Pi = multipliers if multipliers else (None, None)
    return f(kind, H, Xd, Pd, Lam, Pi)


PRIMITIVES[FLOW] = graph_flow


class _Flow:
    """The flow of one ``dirac_flow``, ``multiplier_flow`` or ``canonical_flow`` node's Hamiltonian H
    (or of the second function of a ``bracket`` node), built into the new graph: (H_X, H_P) by the
    reverse mode of :class:`_Gradient` (which refuses what it cannot differentiate: then the scene
    computes the flow), the canonical flow (H_P, −H_X), and for (dot_XP)

        Ẋ = H_P − XΠ,   Ṗ = −H_X + XΛ + PΠ,
        Π = sym(XᵀH_P),   Λ = sym(XᵀH_X − H_PᵀP + ΠK − KΠ),   K = XᵀP,   sym M = ½(M + Mᵀ),

    the unique symmetric multipliers for which d/dt(XᵀX) = 0 and d/dt(XᵀP + PᵀX) = 0 where XᵀX = I_r
    (with XᵀX = I: sym(XᵀẊ) = sym(XᵀH_P) − Π, and sym(ẊᵀP + XᵀṖ) = sym(H_PᵀP − ΠK − XᵀH_X + KΠ) + Λ).
    The same products, in the same order, as the scene's closed forms."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int, kind: str | None = None,
                 f: Any = None) -> None:
        self.g, self.deps, self.new, self.remap, self.i = g, deps, new, remap, i
        scene, name, args, kw = g.args[i]
        self.kind = kind or name
        if f is None:
            if kw or len(args) != 1:
                raise Unsupported(f"{_WHAT[name]} with further arguments")
            f = args[0]
        self.f = f
        self.grad = _Gradient(g, deps, new, remap, i, f)       # its checks made before anything is built
        self.S = self.grad.S

    def build(self) -> Ref:
        add, S = self.new.add, self.S
        pair = self.grad.build()
        HX, HP = add("item", (pair, 0)), add("item", (pair, 1))
        H = self.remap[self.f.i]
        if self.kind == "canonical_flow":
            return add("prim", (Named(FLOW), S, self.kind, H, HP, add("neg", (HX,))))
        X, P = add("attr", (S, "X")), add("attr", (S, "P"))
        XT = add("T", (X,))
        half = add("call", (S, "q", (1, 2), ()))

        def sym(M: Ref) -> Ref:
            return add("mul", (add("add", (M, add("T", (M,)))), half))

        Pi = sym(add("matmul", (XT, HP)))
        K = add("matmul", (XT, P))
        L = add("sub", (add("matmul", (XT, HX)), add("matmul", (add("T", (HP,)), P))))
        L = add("sub", (add("add", (L, add("matmul", (Pi, K)))), add("matmul", (K, Pi))))
        Lam = sym(L)
        Xd = add("sub", (HP, add("matmul", (X, Pi))))
        Pd = add("add", (add("add", (add("neg", (HX,)), add("matmul", (X, Lam)))), add("matmul", (P, Pi))))
        extra = (Lam, Pi) if self.kind == "multiplier_flow" else ()
        return add("prim", (Named(FLOW), S, self.kind, H, Xd, Pd) + extra)


class _Bracket:
    """The Dirac bracket {F, G} of one ``bracket`` node: the derivative of F along the Dirac flow of G
    (the scene's (Dirac_bracket) {F, G}_0 + Σ {F_i, F}_0 C^{ij} {F_j, G}_0 is ⟨∇F, X_G⟩ for the Dirac
    flow X_G = Ω∇G − Σ w_i Ω∇F_i, w = C{F, G}_0), as the scene computes it: ∇F by reverse mode (so a
    function that is not a number is refused as the scene refuses it) and

        {F, G} = tr(F_Xᵀ Ẋ) + tr(F_Pᵀ Ṗ),   (Ẋ, Ṗ) the Dirac flow of G (:class:`_Flow`)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        scene, name, args, kw = g.args[i]
        if kw or len(args) != 2:
            raise Unsupported("a Dirac bracket with further arguments")
        F, G = args
        self.new = new
        self.gradF = _Gradient(g, deps, new, remap, i, F)
        self.flowG = _Flow(g, deps, new, remap, i, "dirac_flow", G)
        self.S = self.gradF.S

    def build(self) -> Ref:
        add, S = self.new.add, self.S
        pair = self.gradF.build()
        flow = self.flowG.build()
        terms = []
        for k, comp in enumerate(("Xdot", "Pdot")):
            if self.new.args[pair.i][2 + k] is None:
                continue                    # F does not depend on X (on P): no term, not a product with 0
            G = add("item", (pair, k))
            terms.append(add("call", (S, "tr", (add("matmul", (add("T", (G,)), add("attr", (flow, comp)))),), ())))
        value = terms[0] if len(terms) == 1 else (add("add", tuple(terms)) if terms
                                                   else add("call", (S, "const", (0,), ())))
        # the value with the flow (made, and checked, whatever F reads) and F's gradient (F evaluated,
        # as the scene evaluates it, where its gradient is 0)
        return add("item", (add("tuple", (flow, value, pair)), 1))


#: what a scene says (``_graph_flows``) when its Dirac bracket is the derivative of F along its own Dirac flow
#: of G (the free algebra's): the derivative is then graph nodes, the flow the scene's
BRACKET_ALONG_FLOW = "bracket along the scene's Dirac flow"


class _BracketAlongFlow(_Derivative):
    """{F, G} = dF/dt along the scene's own Dirac flow of G (a ``call dirac_flow`` node): the derivative
    by the tangent map of :class:`_Derivative`, the flow computed by the scene (on the free algebra, whose
    multipliers are solved modulo its rewriting system)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        scene, name, args, kw = g.args[i]
        if kw or len(args) != 2:
            raise Unsupported("a Dirac bracket with further arguments")
        F, self.G = args
        if type(self.G) is not Ref or g.ops[self.G.i] != "fn":
            raise Unsupported("a Dirac bracket of something that is not a traced function")
        super().__init__(g, deps, new, remap, i, F)

    def make_flow(self) -> Ref:
        return self.add("call", (self.S, "dirac_flow", (self.remap[self.G.i],), ()))


#: the engine steps of a Jacobian (registered below)
UNIT_TANGENT = "stiefelsym.ir.derivative.unit_tangent"
JACOBIAN = "stiefelsym.ir.derivative.jacobian_rows"


def unit_tangent(scene: Any, k: int) -> dict:
    """The k-th unit tangent vector of the 2nr coordinates of X, P (X's entries by rows, then P's), as
    the scene's Jacobian moves the point.  Engine step of the transformed graphs."""
    f = getattr(scene, "_unit_tangent", None)
    if f is None:
        raise TypeError(f"a Jacobian on a {type(scene).__name__} (a scene with no coordinates of X, P)")
    return f(k)


def jacobian_rows(scene: Any, symmetric: bool, *columns: Any) -> list:
    """The Jacobian (rows: the scalar components of F, columns: the 2nr coordinates) from its columns,
    the derivatives of F along the unit tangent vectors, as the scene's Jacobian hands it on.  Engine
    step of the transformed graphs."""
    f = getattr(scene, "_jacobian_rows", None)
    if f is None:
        raise TypeError(f"a Jacobian on a {type(scene).__name__} (a scene with no coordinates of X, P)")
    return f(symmetric, columns)


PRIMITIVES[UNIT_TANGENT] = unit_tangent
PRIMITIVES[JACOBIAN] = jacobian_rows


class _Jacobian:
    """``s.jacobian(F, symmetric)`` at a size the graph fixes: its 2nr columns, the derivatives of F's
    body along the unit tangent vectors (:class:`_Derivative`, each along one :func:`unit_tangent`), the
    rows made by one engine step, :func:`jacobian_rows` (F's matrices read entry by entry, or by their
    upper triangles when ``symmetric``)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        scene, name, args, kw = g.args[i]
        if kw or len(args) != 2 or type(args[1]) is not bool:
            raise Unsupported("a Jacobian with other arguments")
        if g.sizes is None:
            raise Unsupported("a Jacobian in a graph traced with symbolic sizes (its columns are 2nr)")
        n, r = g.sizes
        self.new, self.symmetric = new, args[1]
        self.columns = [_Along(g, deps, new, remap, i, args[0], k) for k in range(2 * n * r)]
        self.S = remap[scene.i]

    def build(self) -> Ref:
        cols = tuple(c.build() for c in self.columns)
        return self.new.add("prim", (Named(JACOBIAN), self.S, self.symmetric) + cols)


class _Along(_Derivative):
    """The derivative of F along the k-th unit tangent vector (a column of a Jacobian)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int, f: Any, k: int) -> None:
        super().__init__(g, deps, new, remap, i, f)
        self.unit = k

    def make_flow(self) -> Ref:
        return self.add("prim", (Named(UNIT_TANGENT), self.S, self.unit))


#: what a coordinate scene says (``_graph_flows``) when the magnetic systems' flows and brackets (the
#: engine steps of :mod:`stiefelsym.twisted`) may take the gradients the graph computes
TWISTED = "magnetic flows and brackets from the graph's gradients"
#: the engine steps the pass rewrites there: (the step as traced, its functions, the step it becomes)
_TWISTED_STEPS = {"stiefelsym.twisted.flow": (1, "stiefelsym.twisted.flow:graph"),
                  "stiefelsym.twisted.bracket": (2, "stiefelsym.twisted.bracket:graph")}


class _Twisted:
    """``twisted.flow(s, H, F)`` and ``twisted.bracket(s, f, g, F)`` (F given or the default) on a coordinate
    scene: the gradients of their functions by the reverse sweep of :class:`_Gradient`, handed with the
    functions to the same engine step made from them (which builds the constraint bracket matrix, solves
    the Dirac multipliers and applies the twisted Poisson tensor as before).  The scene's ε is drawn
    before the functions are evaluated, as the step taking the gradients itself draws it."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        a = g.args[i]
        nf, self.step = _TWISTED_STEPS[a[0].qualname]
        rest, self.F = a[2 + nf:], None
        if len(rest) == 1 and type(rest[0]) is Ref and g.ops[rest[0].i] == "kw":
            kw = g.args[rest[0].i]
            if [k for k, _ in kw] != ["F"]:
                raise Unsupported("a magnetic flow or bracket with further arguments")
            self.F = kw[0][1]                               # the field strength, given by name
        elif len(rest) == 1:
            self.F = rest[0]                                # ... or in its place
        elif rest:
            raise Unsupported("a magnetic flow or bracket with further arguments")
        if any(type(f) is not Ref or g.ops[f.i] != "fn" for f in a[2:2 + nf]):
            raise Unsupported("a magnetic flow or bracket of something that is not a traced function")
        self.new, self.remap, self.fs = new, remap, a[2:2 + nf]
        self.grads = [_Gradient(g, deps, new, remap, i, f, at=(a[1], "gradient")) for f in self.fs]
        self.S = self.grads[0].S

    def build(self) -> Ref:
        add, S = self.new.add, self.S
        add("attr", (S, "X")), add("attr", (S, "P"))
        eps = add("attr", (S, "eps"))
        pairs = tuple(gr.build() for gr in self.grads)
        F = self.remap[self.F.i] if type(self.F) is Ref else self.F
        return add("prim", (Named(self.step), S) + tuple(self.remap[f.i] for f in self.fs) + (F, eps) + pairs)


#: what the free algebra says (``_graph_flows``) when its magnetic bracket is the derivative of f along its
#: own magnetic flow of g (``twisted.bracket`` there): the derivative is then graph nodes, the flow the scene's
TWISTED_ALONG_FLOW = "magnetic bracket along the scene's magnetic flow"


class _TwistedAlongFlow(_Derivative):
    """``twisted.bracket(s, f, g, F)`` on the free algebra: the derivative of f (by the tangent map of
    :class:`_Derivative`) along the scene's own twisted flow of g, a ``twisted.flow`` step (whose Λ, Π
    the free algebra solves), as the scene's bracket computes it."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        a = g.args[i]
        if a[0].qualname != "stiefelsym.twisted.bracket":
            raise Unsupported("a magnetic flow the scene solves")
        rest, self.F = a[4:], None
        if len(rest) == 1 and type(rest[0]) is Ref and g.ops[rest[0].i] == "kw":
            kw = g.args[rest[0].i]
            if [k for k, _ in kw] != ["F"]:
                raise Unsupported("a magnetic bracket with further arguments")
            self.F = kw[0][1]
        elif len(rest) == 1:
            self.F = rest[0]
        elif rest:
            raise Unsupported("a magnetic bracket with further arguments")
        f, self.G = a[2], a[3]
        if type(self.G) is not Ref or g.ops[self.G.i] != "fn":
            raise Unsupported("a magnetic bracket of something that is not a traced function")
        super().__init__(g, deps, new, remap, i, f, at=(a[1], "bracket"))

    def make_flow(self) -> Ref:
        F = self.remap[self.F.i] if type(self.F) is Ref else self.F
        return self.add("prim", (Named("stiefelsym.twisted.flow"), self.S, self.remap[self.G.i], F))


#: what a scene of the standard realization says (``_graph_flows``) when its magnetic bracket may also be
#: written as graph nodes (the constraint gradients of (cond_XP) in closed form, the constraint bracket matrix
#: and the solve of the Dirac multipliers as nodes): a bracket whose function is itself a magnetic bracket
TWISTED_NODES = "magnetic brackets as graph nodes"
#: the engine steps of a magnetic bracket as graph nodes: C x = b (registered by :mod:`stiefelsym.twisted`), the
#: units S_ij of Sym(r) side by side and the coordinates ⟨S_ij, M⟩ of r x r blocks (registered below)
SOLVE = "stiefelsym.twisted.solve:graph"
UNITS = "stiefelsym.ir.derivative.constraint_units"
SYM_COORDS = "stiefelsym.ir.derivative.sym_coordinates"


def constraint_units(scene: Any, F: Any) -> tuple:
    """(S_1 … S_m) and (S_1F … S_mF), r x rm: S_ij = E_ij + E_ji (2E_ii) for i ≤ j in the order of the scene's
    constraint gradients, so that XS_ij is the X-gradient of the (i, j) entry of XᵀX.  Engine step of the
    transformed graphs (constants of the point)."""
    from stiefelsym.backends.matrix import Mat
    r, f = scene.r, F.field
    Fv = F._view()
    U: list[list[Any]] = [[] for _ in range(r)]
    UF: list[list[Any]] = [[] for _ in range(r)]
    for i in range(r):
        for j in range(i, r):
            S = [[f.const((1 if (p, q) in ((i, j), (j, i)) else 0) * (2 if i == j else 1)) for q in range(r)]
                 for p in range(r)]
            SF = [[f.normalize(sum((S[p][t] * Fv[t, q] for t in range(r)), f.const(0))) for q in range(r)]
                  for p in range(r)]
            for p in range(r):
                U[p].extend(S[p])
                UF[p].extend(SF[p])
    return (Mat._rows(U, f, ("r", "?"), F.tracker), Mat._rows(UF, f, ("r", "?"), F.tracker))


def sym_coordinates(scene: Any, M: Any) -> Any:
    """The column of ⟨S_ij, M_b⟩ = M_b[i, j] + M_b[j, i] (i ≤ j) for each r x r block M_b of M (r x rq):
    an m x q matrix (m = r(r + 1)/2), linear in M.  Engine step of the transformed graphs."""
    from stiefelsym.backends.matrix import Mat
    r = scene.r
    a, f = M._view(), M.field
    q = a.shape[1] // r
    rows = [[f.normalize(a[i, b * r + j] + a[j, b * r + i]) for b in range(q)] for i in range(r) for j in range(i, r)]
    return Mat._rows(rows, f, ("?", "?"), M.tracker)


PRIMITIVES[UNITS] = constraint_units
PRIMITIVES[SYM_COORDS] = sym_coordinates


def _inner_bracket(g: Graph, deps: list, G: Ref, what: str) -> tuple:
    """The magnetic bracket G = {g, h}_F that a traced function of one argument returns, read off its graph:
    (the bracket step's arguments, the field strength, the scene attribute naming it or None), or
    Unsupported (``what``: the rule's subject) for a function that is another thing, a bracket at another
    scene, or a bracket whose functions read the function's scene."""
    kG, arity, body = g.args[G.i]
    if (arity != 1 or type(body) is not Ref or g.ops[body.i] != "prim"
            or g.args[body.i][0].qualname != "stiefelsym.twisted.bracket"):
        raise Unsupported(f"{what} of a function that is not a magnetic bracket")
    b = g.args[body.i]
    if type(b[1]) is not Ref or g.ops[b[1].i] != "scene" or g.args[b[1].i] != (kG,):
        raise Unsupported(f"{what} at another scene")
    F = _parse_field_strength(g, b[4:], "a magnetic bracket")
    if any(type(x) is not Ref or g.ops[x.i] != "fn" or kG in deps[x.i] for x in (b[2], b[3])):
        raise Unsupported(f"{what} whose functions read its scene")
    return b, F, _constant_field_strength(g, deps, F, b[1], kG)


def _parse_field_strength(g: Graph, rest: tuple, what: str) -> Any:
    """The field strength F of a magnetic step's arguments after its functions (None: the default)."""
    if len(rest) == 1 and type(rest[0]) is Ref and g.ops[rest[0].i] == "kw":
        kw = g.args[rest[0].i]
        if [k for k, _ in kw] != ["F"]:
            raise Unsupported(f"{what} with further arguments")
        return kw[0][1]
    if len(rest) == 1:
        return rest[0]
    if rest:
        raise Unsupported(f"{what} with further arguments")
    return None


def _constant_field_strength(g: Graph, deps: list, F: Any, scene: Ref, k: int) -> str | None:
    """For a field strength F of a bracket inside the function k: the name of the constant of the function's
    scene it is (such as s.eta), or None when F does not read that scene (refused when it moves with it)."""
    if type(F) is not Ref or k not in deps[F.i]:
        return None
    fa = g.args[F.i]
    if g.ops[F.i] != "attr" or fa[0] != scene or fa[1] not in MATRICES or fa[1] not in CONSTANT_ATTRS:
        raise Unsupported("a magnetic bracket whose field strength moves with its point")
    return fa[1]


class _Same(dict):
    """The identity map of a graph's nodes (a pass over nodes of the new graph itself)."""

    def __missing__(self, i: int) -> Ref:
        return _ref(i)


class _AlongStep(_Derivative):
    """The derivative of a function of the new graph along a flow made by an engine step (a node of the
    new graph)."""

    def __init__(self, new: Graph, scene: Ref, fn: Ref, flow: Ref) -> None:
        from stiefelsym.ir.evaluate import _deps as deps_of
        deps = deps_of(new)
        del new.cache["deps"]               # the graph grows: computed afresh for each use
        super().__init__(new, deps, new, _Same(), 0, fn, at=(scene, "d"))
        self._flow = flow

    def make_flow(self) -> Ref:
        return self._flow


class _BracketFunction:
    """A function G(t) = ``twisted.bracket(t, g, h[, F])`` of the claim (a magnetic bracket at the function's
    own point), differentiated along a flow on a coordinate scene of the standard realization: G is written
    as graph nodes of a function of the new graph,

        G = ⟨∇g, W⁻¹∇h⟩ + aᵀ x,   C x = b,   a_i = ⟨∇F_i, W⁻¹∇g⟩,   b_j = ⟨∇F_j, W⁻¹∇h⟩,
        C_ij = ⟨∇F_i, W⁻¹∇F_j⟩,   W⁻¹(u_X, u_P) = (u_P, −u_X − ε u_P F)

    (the scene's twisted Dirac bracket (Dirac_bracket) {g, h}_ε + Σ {F_i, g}_ε C^{ij} {F_j, h}_ε), ∇g, ∇h by
    the backward sweep, the constraint gradients of (cond_XP) in closed form (XS_ij; PS_ij, XS_ij), the
    products ⟨∇F_i, ·⟩ read by one linear step (:func:`sym_coordinates`) and x by one engine step
    (:func:`solve`); its derivative is the tangent map (:class:`_Derivative`), with
    d(solve(C, b)) = solve(C, db − dC·x).  ``at``: the claim's scene (or its problem at another point)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, at: Any, G: Any) -> None:
        if TWISTED_NODES not in new.cache.get("flows", ()):
            raise Unsupported("a magnetic bracket off the standard realization's coordinate scenes")
        if not _claim_scene(g, at, new):
            raise Unsupported("a derivative of a magnetic bracket on a scene other than the claim's")
        if type(G) is not Ref or g.ops[G.i] != "fn":
            raise Unsupported("a derivative of something that is not a traced function")
        b, self.Finner, self.Fattr = _inner_bracket(g, deps, G, "a magnetic bracket")
        inner = (b[2], b[3])
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        self.inner, self.at, self.S = inner, at, remap[at.i]

    def along(self, flow: Ref) -> Ref:
        """dG along ``flow`` (a node of the new graph), as nodes."""
        new, add = self.new, self.new.add
        new.fns += 1
        k = new.fns
        value = self.bracket_nodes(add("scene", (k,)))
        return _AlongStep(new, self.S, add("fn", (k, 1, value)), flow).build()

    def bracket_nodes(self, T: Ref) -> Ref:
        """The magnetic bracket {g, h}_ε at the scene T as nodes (see the class)."""
        add = self.new.add
        grads = []
        for h in self.inner:
            gr = _Gradient(self.g, self.deps, self.new, self.remap, 0, h, at=(self.at, "gradient"))
            gr.S = T
            HX, HP, _ = gr.adjoints()
            grads.append((HX, HP))
        X, P, eps = add("attr", (T, "X")), add("attr", (T, "P")), add("attr", (T, "eps"))
        Fm = (add("attr", (self.S, self.Fattr)) if self.Fattr is not None
              else self.remap[self.Finner.i] if type(self.Finner) is Ref
              else add("prim", (Named("stiefelsym.twisted.magnetic_matrix"), self.S)))

        def plus(x: Any, y: Any, op: str = "add") -> Any:
            if y is None:
                return x
            if x is None:
                return add("neg", (y,)) if op == "sub" else y
            return add(op, (x, y))

        def pi(u: tuple) -> tuple:          # W⁻¹u = (u_P, −u_X − ε u_P F)
            uX, uP = u
            epsF = None if uP is None else add("mul", (eps, add("matmul", (uP, Fm))))
            return uP, plus(None if uX is None else add("neg", (uX,)), epsF, "sub")

        def dot(u: tuple, v: tuple) -> Ref:     # ⟨u, v⟩ = tr(u_Xᵀ v_X) + tr(u_Pᵀ v_P)
            acc = None
            for x, y in zip(u, v):
                if x is not None and y is not None:
                    acc = plus(acc, add("call", (T, "tr", (add("matmul", (add("T", (x,)), y)),), ())))
            return acc if acc is not None else add("call", (T, "const", (0,), ()))

        units = add("prim", (Named(UNITS), self.remap[0], Fm))        # (S_1 … S_m), (S_1F … S_mF)
        U, UF = add("item", (units, 0)), add("item", (units, 1))
        XU, PU = add("matmul", (X, U)), add("matmul", (P, U))

        def coords(v: tuple) -> Any:    # ⟨∇F_i, v⟩: the XᵀX constraints, then the XᵀP + PᵀX ones
            vX, vP = v
            XT = add("T", (X,))
            if vX is None and vP is None:
                return None                 # a function with a zero gradient: no correction
            # (a zero where v has no X part: Xᵀ v_P·0, of the shape of the coordinates' argument)
            top = add("matmul", (XT, vX)) if vX is not None else add("mul", (add("matmul", (XT, vP)), 0))
            low = plus(None if vX is None else add("matmul", (add("T", (P,)), vX)),
                       None if vP is None else add("matmul", (XT, vP)))
            return add("block", (2, 1, (add("prim", (Named(SYM_COORDS), T, top)),
                                        add("prim", (Named(SYM_COORDS), T, low)))))

        pig, pih = pi(grads[0]), pi(grads[1])
        # W⁻¹∇F_j: (0, −XS_j) for the XᵀX constraints, (XS_j, −PS_j − ε XS_jF) for the XᵀP + PᵀX ones
        C = add("block", (1, 2, (coords((None, add("neg", (XU,)))),
                                 coords((XU, plus(add("neg", (PU,)), add("mul", (eps, add("matmul", (X, UF)))), "sub"))))))
        avec, bvec = coords(pig), coords(pih)
        acc = dot(grads[0], pih)
        if avec is None or bvec is None:
            return acc
        x = add("prim", (Named(SOLVE), T, C, bvec, Fm))
        return add("add", (acc, add("entry", (add("matmul", (add("T", (avec,)), x)), 0, 0))))


class _TwistedNested:
    """``twisted.bracket(s, f, G)`` on a coordinate scene of the standard realization where G is itself a
    magnetic bracket, G(t) = ``twisted.bracket(t, g, h)`` (the Jacobi identity of the twisted bracket): G's
    gradient needs the derivative of a bracket whose Dirac multipliers the step solves.  The Dirac bracket
    is skew, {f, G}_ε = −{G, f}_ε = −dG(X_f), X_f the twisted flow of f (from f's gradient by the backward
    sweep, one ``twisted.flow`` step as :class:`_Twisted` makes it), dG by :class:`_BracketFunction`."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        a = g.args[i]
        if a[0].qualname != "stiefelsym.twisted.bracket":
            raise Unsupported("a magnetic flow of a bracket")
        self.F = _parse_field_strength(g, a[4:], "a magnetic bracket")
        self.G = _BracketFunction(g, deps, new, remap, a[1], a[3])
        self.new, self.remap, self.f = new, remap, a[2]
        if type(self.f) is not Ref or g.ops[self.f.i] != "fn":
            raise Unsupported("a magnetic bracket of something that is not a traced function")
        self.gradf = _Gradient(g, deps, new, remap, i, self.f, at=(a[1], "gradient"))
        self.S = self.gradf.S

    def build(self) -> Ref:
        add, S = self.new.add, self.S
        # the flow of f, as :class:`_Twisted` makes it
        add("attr", (S, "X")), add("attr", (S, "P"))
        eps = add("attr", (S, "eps"))
        pair = self.gradf.build()
        F = self.remap[self.F.i] if type(self.F) is Ref else self.F
        flow = add("prim", (Named("stiefelsym.twisted.flow:graph"), S, self.remap[self.f.i], F, eps, pair))
        return add("neg", (self.G.along(flow),))


class _BracketDerivative:
    """``s.d(G, flow)`` for G(t) = ``twisted.bracket(t, g, h)`` on a coordinate scene of the standard
    realization: dG along the flow by :class:`_BracketFunction`."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        scene, name, args, kw = g.args[i]
        if kw or len(args) != 2 or type(args[1]) is not Ref:
            raise Unsupported("a derivative with further arguments")
        self.G = _BracketFunction(g, deps, new, remap, scene, args[0])
        self.flow = remap[args[1].i]

    def build(self) -> Ref:
        return self.G.along(self.flow)


class _AlongGiven(_Derivative):
    """The derivative of a function of the graph along a flow given as a node of the new graph, at the
    claim's scene."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, at: Any, f: Any, flow: Ref) -> None:
        super().__init__(g, deps, new, remap, 0, f, at=(at, "bracket"))
        self._flow = flow

    def make_flow(self) -> Ref:
        return self._flow


def _reads_claim_point(g: Graph, roots: tuple) -> bool:
    """Whether the nodes ``roots`` (function bodies included) read the claim's scene other than through its
    constants (A, ξ, η, ..., its numbers and constant matrices) and the scene methods that compute with their
    arguments only: a value of the claim's point, which a function of another scene holds as a constant."""
    seen: set[int] = set()
    stack = [x.i for x in roots if type(x) is Ref]
    claim = lambda x: type(x) is Ref and g.ops[x.i] == "scene" and g.args[x.i] == (0,)   # noqa: E731
    while stack:
        j = stack.pop()
        if j in seen:
            continue
        seen.add(j)
        op, a = g.ops[j], g.args[j]
        if claim(Ref(j)):
            return True
        if op == "attr" and claim(a[0]) and a[1] in CONSTANT_ATTRS:
            continue
        if op == "call" and claim(a[0]) and a[1] in NUMERIC_CALLS:
            stack.extend(r for r in g.refs(j) if r != a[0].i)      # its arguments only
            continue
        if op == "prim" and (_constant_vector(a[0]) or getattr(a[0], "qualname", None) == "stiefelsym.twisted.magnetic_matrix"):
            continue
        stack.extend(g.refs(j))
    return False


class _TwistedNestedAlongFlow:
    """``twisted.bracket(s, f, G)`` on the free algebra where G(t) = ``twisted.bracket(t, g, h)`` (the Jacobi
    identity of the twisted bracket): G's flow would need the gradient of a bracket.  The bracket is skew,
    {f, G}_ε = −dG(X_f), and on the free algebra G at the scene's own point is a value, dg along the scene's
    magnetic flow X_h of h (graph nodes, as :class:`_TwistedAlongFlow` makes them), which the scene
    differentiates along its magnetic flow X_f of f by the derivation of the free algebra (``s.d`` of a value:
    X_f is tangent to T*V, so the derivation keeps the ideal of the constraints)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        a = g.args[i]
        if type(a[1]) is not Ref or g.ops[a[1].i] != "scene" or g.args[a[1].i] != (0,):
            raise Unsupported("a magnetic bracket of a bracket on a scene other than the claim's")
        self.F = _parse_field_strength(g, a[4:], "a magnetic bracket")
        f, G = a[2], a[3]
        if any(type(x) is not Ref or g.ops[x.i] != "fn" for x in (f, G)):
            raise Unsupported("a magnetic bracket of something that is not a traced function")
        b, self.Finner, self.Fattr = _inner_bracket(g, deps, G, "a magnetic bracket of a bracket")
        # G at the scene's point is a value the derivation moves with every X, P it holds: a value of the claim's
        # point that g, h or the field strength close over (a constant of G) would be moved too
        if _reads_claim_point(g, (b[2], b[3]) + ((self.Finner,) if self.Fattr is None else ())):
            raise Unsupported("a magnetic bracket of a bracket whose functions or field strength close over the "
                              "claim's point")
        self.g, self.deps, self.new, self.remap, self.at = g, deps, new, remap, a[1]
        self.f, self.inner = f, (b[2], b[3])
        self.S = remap[a[1].i]

    def build(self) -> Ref:
        add, S, m = self.new.add, self.S, self.remap
        Fi = (add("attr", (S, self.Fattr)) if self.Fattr is not None
              else m[self.Finner.i] if type(self.Finner) is Ref else self.Finner)
        Fo = m[self.F.i] if type(self.F) is Ref else self.F
        gf, hf = self.inner
        Xh = add("prim", (Named("stiefelsym.twisted.flow"), S, m[hf.i], Fi))
        G = _AlongGiven(self.g, self.deps, self.new, m, self.at, gf, Xh).build()
        Xf = add("prim", (Named("stiefelsym.twisted.flow"), S, m[self.f.i], Fo))
        return add("neg", (add("call", (S, "d", (G, Xf), ())),))


#: where a scene says TWISTED_NODES, what the pass tries when the first rule refuses: a derivative of a
#: magnetic bracket, a magnetic bracket of one
_OF_BRACKETS: dict[str, Any] = {"d": _BracketDerivative, "stiefelsym.twisted.bracket": _TwistedNested}

#: the calls the pass rewrites, by scene method
_PASSES = {"d": _Derivative, "gradient": _Gradient, "jacobian": _Jacobian}
#: the flows and brackets it rewrites where the scene lets the graph compute them (:func:`scene_flows`)
_FLOW_PASSES = {"dirac_flow": _Flow, "multiplier_flow": _Flow, "canonical_flow": _Flow, "bracket": _Bracket}


# ---------------------------------------------------------------------------------------------
# derivatives and gradients at points of the caller's own (stiefelsym.systems): functions of a scene
# and of a point, a dict of matrices, whose variables are the point's entries z[k]

#: what a coordinate scene says (``_graph_flows``) when the engine steps of :mod:`stiefelsym.systems`
#: may take the graph's derivatives and gradients at points of the caller's own
SYSTEMS = "derivatives and flows at points of the caller's own from the graph"
#: the engine steps of the transformed graphs (registered by :mod:`stiefelsym.systems`)
POINT_TANGENT = "stiefelsym.systems.derivative:tangent"
PAIRS_FLOW = "stiefelsym.systems.stiefel_pairs_flow:graph"


def _claim_scene_function(g: Graph, scene: Any, f: Any, what: str) -> tuple:
    """:func:`_point_function` of ``f`` for a step on the claim's own scene, whose value is not a constant."""
    if type(scene) is not Ref or g.ops[scene.i] != "scene" or g.args[scene.i] != (0,):
        raise Unsupported(f"{what} on a scene other than the claim's (inside a function of the scene)")
    k, body, param = _point_function(g, f, what)
    if type(body) is not Ref:
        raise Unsupported(f"{what} of a function whose value is a constant")
    return k, body, param


def _point_function(g: Graph, f: Any, what: str) -> tuple[int, Any, int | None]:
    """(k, body, the node of its point) of a traced function of a scene and of a point."""
    if type(f) is not Ref or g.ops[f.i] != "fn":
        raise Unsupported(f"{what} of something that is not a traced function")
    k, arity, body = g.args[f.i]
    if arity != 2:
        raise Unsupported(f"{what} of a function that is not of a scene and a point")
    param = g.index.get(("param", (k, 1)))
    if param is None:
        param = next((j for j, (op, a) in enumerate(zip(g.ops, g.args))
                      if op == "param" and a[0] == k and a[1] == 1), None)
    return k, body, param


def _positional(g: Graph, a: tuple, count: int, what: str) -> tuple:
    """The positional arguments of an engine step (refused: keyword arguments, another count)."""
    if len(a) != count or any(type(x) is Ref and g.ops[x.i] == "kw" for x in a):
        raise Unsupported(f"{what} with other arguments")
    return a


#: what the dimension-free scene says (``_graph_flows``) when ``systems.derivative`` at its own point (X, P, Y, Q,
#: its letters) is its derivative along the tangent vector: graph nodes along the scene's own tangent
SYSTEMS_OWN = "derivatives at the scene's own point along a tangent vector"


#: engine steps linear in their one argument (their derivative: the step of the argument's derivative)
_LINEAR_STEPS = frozenset({"stiefelsym.systems.hermitian_entries"})


class _PointDerivative(_Derivative):
    """``systems.derivative(s, F, point, tangent)``: the derivative of F(t, z) at z = point along the
    tangent vector (a dict of matrices, a component not given: 0) by the tangent map of
    :class:`_Derivative`, the point's variables z[k] moving with the tangent's components and everything
    of the scene constant (the scene's X, P, Y, Q included: the point is the caller's).  The components
    are read, and the tangent checked as the step checks it, by one engine step (``POINT_TANGENT``)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        _, scene, f, point, tangent = _positional(g, g.args[i], 5, "a derivative at a point")
        if type(scene) is not Ref or g.ops[scene.i] != "scene" or g.args[scene.i] != (0,):
            raise Unsupported("a derivative at a point on a scene other than the claim's (inside a function of the "
                              "scene)")
        self.k, self.body, self.param = _point_function(g, f, "a derivative at a point")
        if type(point) is not Ref or type(tangent) is not Ref:
            raise Unsupported("a derivative at a point that is not a value of the graph")
        self.S, self.point, self.flow = remap[scene.i], remap[point.i], tangent
        self.keys = frozenset(g.args[tangent.i][0]) if g.ops[tangent.i] == "dict" else None
        self.P, self.D, self.read, self._tangent = {}, {}, set(), None

    def rule(self, j: int) -> Any:
        g = self.g
        op, a = g.ops[j], g.args[j]
        if op == "param":
            if j != self.param:
                raise Unsupported("a function that reads another function's point")
            return ("param",)
        if op == "item" and type(a[0]) is Ref and a[0].i == self.param:
            return self.component(a[1])
        if op == "prim" and type(a[0]) is Named and a[0].qualname in _LINEAR_STEPS and len(a) == 2:
            return ("prim",)
        if op == "attr" and type(a[0]) is Ref and g.ops[a[0].i] == "scene" and a[1] in MOVED + ("Phi", "Psi"):
            if g.args[a[0].i] != (self.k,):
                raise Unsupported("a function that reads another function's scene")
            return None                     # the scene's own point does not move with the caller's
        return super().rule(j)

    def tangent_step(self, flow: Ref, keys: tuple) -> Ref:
        return self.add("prim", (Named(POINT_TANGENT), self.S, self.point, flow, keys))

    def emit(self, j: int, plan: Any) -> Any:
        if plan == ("prim",):               # a linear engine step (the components of a Hermitian matrix)
            x = self.dref(self.g.args[j][1])
            return None if x is None else self.add("prim", (self.g.args[j][0], x))
        return super().emit(j, plan)

    def primal_node(self, j: int) -> Ref:
        if j == self.param:
            return self.point
        return super().primal_node(j)


class _PointGradient(_Gradient):
    """The gradients of a scalar function H(t, z) of a scene and of a point with respect to the point's
    variables z[k] (``wrt``), by the backward sweep of :class:`_Gradient` with the variables z[k] as its
    leaves (the scene's X, P constants here).  :meth:`sweep` gives {k: the adjoint of z[k] or None}."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, scene: Any, f: Any, point: Any,
                 what: str, wrt: frozenset | None = None) -> None:
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        self.k, self.body, self.param = _claim_scene_function(g, scene, f, what)
        if type(point) is not Ref:
            raise Unsupported(f"{what} at a point that is not a value of the graph")
        self.S, self.point, self.wrt = remap[scene.i], point, wrt      # (the point: a node of the new graph)
        self.P = {}

    def variable(self, j: int) -> bool:
        """Whether the body's node j is a variable of the gradient, z[k] for k in ``wrt``."""
        g = self.g
        a = g.args[j]
        return (g.ops[j] == "item" and type(a[0]) is Ref and a[0].i == self.param
                and (self.wrt is None or a[1] in self.wrt))

    def _kind_of(self, j: int) -> str:
        g = self.g
        if j == self.param:
            return _L
        a = g.args[j]
        if g.ops[j] == "item" and type(a[0]) is Ref and a[0].i == self.param:
            return _M
        return super()._kind_of(j)

    def check(self, j: int) -> None:
        g = self.g
        a = g.args[j]
        if j == self.param or (g.ops[j] == "item" and type(a[0]) is Ref and a[0].i == self.param):
            return
        if g.ops[j] == "param":
            raise Unsupported("a function that reads another function's point")
        if g.ops[j] == "scene" and a != (self.k,):
            raise Unsupported("a function that reads another function's scene")
        if g.ops[j] == "call" and a[1] == "conj" and not a[3] and len(a[2]) == 1:
            return
        if g.ops[j] == "call" and a[1] == "realify" and not a[3] and not any(self.moving(x) for x in a[2]):
            return                          # a constant realified matrix
        super().check(j)

    def primal_node(self, j: int) -> Ref:
        if j == self.param:
            return self.point
        return _Derivative.primal_node(self, j)

    def sweep(self) -> tuple[dict, Ref]:
        """({key: adjoint or None}, H's value): the body's values written, then the adjoints."""
        g = self.g
        todo = self.body_nodes()
        self.kinds, self.moves_set = {}, set()
        for j in todo:
            if self.variable(j) or any(r in self.moves_set for r in g.refs(j)):
                self.moves_set.add(j)
        for j in todo:
            if g.ops[j] != "scene":
                self.kinds[j] = self._kind_of(j)
                self.check(j)
        if self.kinds.get(self.body.i, _S) != _S:
            raise Unsupported("a gradient of a function whose value is not a number")
        for j in todo:
            self.P[j] = self.primal_node(j)
        adj: dict[int, tuple[list, list]] = {}
        grads: dict[Any, list] = {}
        if self.body.i in self.moves_set:
            adj[self.body.i] = ([1], [])
        for j in reversed(todo):
            if j not in adj or g.ops[j] == "scene":
                continue
            terms, ident = adj.pop(j)
            self.propagate(j, terms, ident, adj, grads)
        value = self.P[self.body.i] if self.body.i in self.P else self.remap[self.body.i]
        return {key: self.mat_sum(ts) for key, ts in grads.items()}, value

    def propagate(self, j: int, terms: list, ident: list, adj: dict, grads: dict) -> None:
        g = self.g
        a = g.args[j]
        if g.ops[j] == "call" and a[1] == "conj":         # conj M = JMJ, J = diag(I, −I): its own adjoint
            M = self.mat_sum(terms)
            c = self.scalar_sum(ident) if ident else 0
            has_c = type(c) is Ref or c != 0
            if M is not None or has_c:
                self.send(adj, a[2][0], [self.add("call", (self.S, "conj", (self.full(j, M, c, has_c),), ()))])
            return
        if self.variable(j):
            M = self.mat_sum(terms)
            c = self.scalar_sum(ident) if ident else 0
            has_c = type(c) is Ref or c != 0
            if M is None and not has_c:
                return
            grads.setdefault(self.g.args[j][1], []).append(self.full(j, M, c, has_c))
            return
        super().propagate(j, terms, ident, adj, grads)


class _PairsFlow:
    """``systems.stiefel_pairs_flow(s, H, point, pairs)`` on a coordinate scene: the gradients of H with
    respect to the point's variables by the backward sweep of :class:`_PointGradient`, handed with H's
    value to one engine step (``PAIRS_FLOW``) that makes the flow from them as the step made it from its
    reverse tape (the closed forms of the multipliers where they hold, else the constraint gradients of
    (cond_XP) in closed form and the solve of the Dirac multipliers)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        _, scene, H, point, pairs = _positional(g, g.args[i], 5, "a flow of pairs of Stiefel points")
        self.new, self.remap = new, remap
        if type(point) is not Ref:
            raise Unsupported("a flow of pairs of Stiefel points at a point that is not a value of the graph")
        self.grad = _PointGradient(g, deps, new, remap, scene, H, remap[point.i], "a flow of pairs of Stiefel points")
        self.H, self.point, self.pairs = H, point, pairs

    def build(self) -> Ref:
        grads, value = self.grad.sweep()
        m = self.remap
        keys = tuple(sorted(grads, key=str))
        parts = tuple(grads[key] for key in keys)
        pairs = m[self.pairs.i] if type(self.pairs) is Ref else self.pairs
        return self.new.add("prim", (Named(PAIRS_FLOW), self.grad.S, m[self.H.i], m[self.point.i], pairs, value,
                                     keys) + parts)


#: the engine steps of :mod:`stiefelsym.systems` the pass rewrites on a scene that says ``SYSTEMS``
_SYSTEMS_STEPS = {"stiefelsym.systems.derivative": _PointDerivative,
                  "stiefelsym.systems.stiefel_pairs_flow": _PairsFlow}

EULER_LAGRANGE = "stiefelsym.systems.euler_lagrange:graph"


class _PointSecond(_PointDerivative):
    """D²F(v, v) at z = point, F a function of a scene and of a point: the second derivative of
    F(point + εv) at ε = 0, by the second-order tangent map (linear operations act on both orders;
    d²(ab) = d²a·b + 2·da·db + a·d²b for matrix and scalar products; z[k] moves with v[k], its second
    derivative 0; everything of the scene constant).  ``point`` and ``tangent``: nodes of the new graph."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, scene: Any, f: Any, point: Ref,
                 tangent: Ref, what: str) -> None:
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        self.k, self.body, self.param = _claim_scene_function(g, scene, f, what)
        self.S, self.point, self.flow, self.keys = remap[scene.i], point, None, None
        self._v = tangent
        self.P, self.D, self.read, self._tangent = {}, {}, set(), None

    def make_flow(self) -> Ref:
        return self._v

    _LINEAR = frozenset({"add", "sub", "neg", "T", "trace", "entry", "list", "tuple"})

    def rule(self, j: int) -> Any:
        g = self.g
        op, a = g.ops[j], g.args[j]
        plan = super().rule(j)
        if plan is None or plan in (("scene",), ("param",), ("prim",)) or plan[0] == "component":
            return plan
        if op in self._LINEAR or op in ("matmul", "mul"):
            return plan
        if op == "item" and type(a[0]) is Ref and g.ops[a[0].i] in ("list", "tuple", "dict"):
            return plan
        if op == "div" and not self.moves(a[1]):
            return plan
        if op == "call" and a[1] in ("tr", "conj", "realify"):
            return plan
        raise Unsupported(f"a {op if op != 'call' else 's.' + a[1]} in a second derivative")

    def build(self) -> Ref:
        g = self.g
        todo = self.body_nodes()
        self.plan = {}
        for j in todo:
            plan = self.rule(j)
            if type(plan) is tuple and plan[0] == g.ops[j] != "scene" and not any(self.moves(Ref(x)) for x in g.refs(j)):
                plan = None
            self.plan[j] = plan
        keys = tuple(sorted(self.read))
        self._tangent = self.tangent_step(self.make_flow(), keys)
        self.D2: dict[int, Any] = {}
        for j in todo:
            self.P[j] = self.primal_node(j)
            self.D[j] = self.emit(j, self.plan[j])
            self.D2[j] = self.second(j, self.plan[j])
        b = self.body.i
        d2 = self.D2.get(b) if self.k in self.deps[b] else None
        value = self.filled(d2, self.body)
        return self.add("item", (self.add("tuple", (self._tangent, value)), 1))

    def filled(self, d: Any, j: Any) -> Ref:
        """A derivative as a node, a zero (of j's shape) where it is 0."""
        if d is None:
            if type(j) is Ref and self.g.ops[j.i] in ("list", "tuple"):
                return self.add(self.g.ops[j.i], tuple(self.filled(None, x) for x in self.g.args[j.i]))
            if type(j) is Ref and self.g.ops[j.i] == "prim":
                return self.add("prim", (self.g.args[j.i][0], self.filled(None, self.g.args[j.i][1])))
            return self.zero(j)
        return d

    def d2(self, a: Any) -> Any:
        if type(a) is not Ref or self.k not in self.deps[a.i]:
            return None
        return self.D2.get(a.i)

    def second(self, j: int, plan: Any) -> Any:
        """The second derivative of node j (None: 0)."""
        if plan is None or plan in (("scene",), ("param",)) or plan[0] == "component":
            return None
        g, add, p = self.g, self.add, self.primal
        op, a = g.ops[j], g.args[j]
        if plan == ("prim",):
            x = self.d2(a[1])
            return None if x is None else add("prim", (a[0], x))
        if op in ("add", "sub"):
            return self.sum(self.d2(a[0]), self.d2(a[1]), op)
        if op in ("neg", "T", "trace"):
            x = self.d2(a[0])
            return None if x is None else add(op, (x,))
        if op == "entry":
            x = self.d2(a[0])
            return None if x is None else add("entry", (x,) + tuple(a[1:]))
        if op in ("list", "tuple"):
            parts = [self.d2(x) for x in a]
            if all(x is None for x in parts):
                return None
            return add(op, tuple(self.filled(x, e) for x, e in zip(parts, a)))
        if op == "item":
            base, key = a
            bop, ba = g.ops[base.i], g.args[base.i]
            if bop == "dict":
                return self.d2(ba[1][ba[0].index(key)]) if key in ba[0] else None
            return self.d2(ba[key])
        if op == "div":
            x = self.d2(a[0])
            return None if x is None else add("div", (x, p(a[1])))
        if op in ("matmul", "mul"):             # d²(ab) = d²a·b + 2·da·db + a·d²b
            x1, y1 = self.dref(a[0]), self.dref(a[1])
            x2, y2 = self.d2(a[0]), self.d2(a[1])
            left = None if x2 is None else add(op, (x2, p(a[1])))
            mid = None if x1 is None or y1 is None else add("mul", (2, add(op, (x1, y1))))
            right = None if y2 is None else add(op, (p(a[0]), y2))
            return self.sum(self.sum(left, mid), right)
        if op == "call" and a[1] in ("tr", "conj"):
            x = self.d2(a[2][0])
            return None if x is None else add("call", (self.S, a[1], (x,), ()))
        if op == "call" and a[1] == "realify":
            x, y = self.d2(a[2][0]), self.d2(a[2][1])
            if x is None and y is None:
                return None
            return add("call", (self.S, "realify", (self.filled(x, a[2][0]), self.filled(y, a[2][1])), ()))
        raise AssertionError(f"no second-order rule for {op}")


class _EulerLagrange:
    """``systems.euler_lagrange(s, T, U, constraints, position, velocity, coords)`` on a coordinate scene:
    the gradients and derivatives the step took from its reverse tape and dual numbers as graph nodes,
    handed to one engine step (``EULER_LAGRANGE``) that solves for the accelerations and the multipliers
    as the step did: ∇T as a function of the velocity (a function of the new graph, the backward sweep of
    :class:`_PointGradient` over its point; the step takes it at 0 and at each basis vector b_b of the
    coordinates, K b_b = ∇T(b_b) − ∇T(0)), ∇U at the position, the derivative of the constraints along a
    tangent vector (a function of the new graph, :class:`_PointAlong`; the step takes it along each
    basis vector: the columns of Dg) and D²g(q̇, q̇) (:class:`_PointSecond`).  The number of coordinates
    is the step's (so a graph traced with symbolic sizes is rewritten too)."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        _, scene, T, U, cons, position, velocity, coords = _positional(g, g.args[i], 8, "Euler-Lagrange equations")
        if type(coords) is not Ref or g.ops[coords.i] != "prim" or not g.args[coords.i][0].qualname.endswith(
                ("systems.real_coordinates", "systems.complex_coordinates")):
            raise Unsupported("Euler-Lagrange equations in coordinates other than the unit matrices of the step's own")
        names = g.args[coords.i][2] if len(g.args[coords.i]) == 3 else None
        if type(names) is not Ref or g.ops[names.i] not in ("list", "tuple") or any(
                type(x) is Ref for x in g.args[names.i]):
            raise Unsupported("Euler-Lagrange equations in coordinates of variables the graph does not name")
        if any(type(x) is not Ref for x in (position, velocity)):
            raise Unsupported("Euler-Lagrange equations at a point that is not a value of the graph")
        self.new, self.wrt = new, list(dict.fromkeys(g.args[names.i]))
        self.S = remap[scene.i]
        self.args = (remap[position.i], remap[velocity.i], remap[coords.i])
        add = new.add
        w = frozenset(self.wrt)
        new.fns += 1
        self.kK = new.fns
        v = add("param", (self.kK, 1, self.args[1]))
        self.kinetic = _PointGradient(g, deps, new, remap, scene, T, v, "the kinetic energy's gradient", w)
        self.potential = _PointGradient(g, deps, new, remap, scene, U, self.args[0], "the potential's gradient", w)
        new.fns += 1
        self.kJ = new.fns
        u = add("param", (self.kJ, 1, self.args[0]))
        self.column = _PointAlong(g, deps, new, remap, scene, cons, self.args[0], u)
        self.hess = _PointSecond(g, deps, new, remap, scene, cons, self.args[0], self.args[1],
                                 "the constraints' second derivative")

    def build(self) -> Ref:
        add = self.new.add
        parts = []
        for gr in (self.kinetic, self.potential):
            grads, value = gr.sweep()
            parts.append(add("tuple", tuple(grads.get(k) for k in self.wrt) + (value,)))
        fK = add("fn", (self.kK, 2, parts[0]))
        fJ = add("fn", (self.kJ, 2, self.column.build()))
        hess = self.hess.build()
        return add("prim", (Named(EULER_LAGRANGE), self.S) + self.args + (tuple(self.wrt), fK, parts[1], fJ, hess))


class _PointAlong(_PointDerivative):
    """The derivative of F(t, z) at z = point along a tangent vector made by an engine step (nodes of the
    new graph): a column of a Jacobian at a point of the caller's own."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, scene: Any, f: Any, point: Ref,
                 tangent: Ref) -> None:
        self.g, self.deps, self.new, self.remap = g, deps, new, remap
        if type(scene) is not Ref or g.ops[scene.i] != "scene" or g.args[scene.i] != (0,):
            raise Unsupported("a derivative at a point on a scene other than the claim's")
        self.k, self.body, self.param = _point_function(g, f, "a derivative at a point")
        self.S, self.point, self.flow, self.keys, self._v = remap[scene.i], point, None, None, tangent
        self.P, self.D, self.read, self._tangent = {}, {}, set(), None

    def make_flow(self) -> Ref:
        return self._v


_SYSTEMS_STEPS["stiefelsym.systems.euler_lagrange"] = _EulerLagrange


class _OwnPointDerivative(_PointDerivative):
    """``systems.derivative(s, F, point, tangent)`` on the dimension-free scene at its own point (a dict of
    its letters X, P, Y, Q under their own names, as the graph shows it): the derivative of F(t, z) at
    z = point along the tangent — the tangent map of :class:`_PointDerivative` (z[k] moves, F's scene and its
    letters do not), the components read (and the tangent checked) by the scene's own step
    (:func:`tangent_vector`).  Any other point (the double or the complex point, which
    the scene differentiates its own way) keeps the step."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        super().__init__(g, deps, new, remap, i)
        point = g.args[i][3]
        ok = g.ops[point.i] == "dict"
        if ok:
            keys, vals = g.args[point.i]
            ok = bool(keys) and all(
                k in ("X", "P", "Y", "Q") and type(v) is Ref and g.ops[v.i] == "attr" and g.args[v.i][1] == k
                and type(g.args[v.i][0]) is Ref and g.ops[g.args[v.i][0].i] == "scene" and g.args[g.args[v.i][0].i] == (0,)
                for k, v in zip(keys, vals))
        if not ok:
            raise Unsupported("a derivative at a point other than the scene's own letters (X, P, Y, Q)")

    # (the function's scene keeps its X, P, Y, Q, as at a point of the caller's own (rule of
    # _PointDerivative): d/dε F(t, point + ε·tangent) moves the point handed to F only; moving the scene's
    # letters with it proved d/dε tr(t.Xᵀ A z_X) = 2 tr(XᵀAP), which every coordinate scene refutes)

    def tangent_step(self, flow: Ref, keys: tuple) -> Ref:
        return self.add("prim", (Named(TANGENT), self.S, flow, keys))


#: what a coordinate scene says (``_graph_flows``) when its Dirac flow, where the graph does not compute its
#: multipliers (the metric realization, whose multipliers solve Lyapunov equations; a chart or field without
#: the closed forms), may take the gradient of H the graph computes
GRADIENT_FLOW = "the Dirac flow from the graph's gradient"
DIRAC_FROM_GRADIENT = "stiefelsym.ir.derivative.dirac_flow_from_gradient"


def dirac_flow_from_gradient(scene: Any, H: Any, HX: Any, HP: Any) -> Any:
    """The Dirac flow of H on ``scene`` from the gradient (H_X, H_P) the graph computed: the scene makes it
    as its own :meth:`dirac_flow` does (its multipliers, closed or solved).  Engine step of the transformed
    graphs."""
    f = getattr(scene, "_graph_dirac_flow", None)
    if f is None:
        raise TypeError(f"a Dirac flow on a {type(scene).__name__} (a scene whose flows the graph does not compute)")
    return f(H, HX, HP)


PRIMITIVES[DIRAC_FROM_GRADIENT] = dirac_flow_from_gradient


class _GradientFlow:
    """``s.dirac_flow(H)`` where the scene solves its multipliers: H's gradient by the backward sweep of
    :class:`_Gradient` (the scene's checks of a gradient made by :func:`gradient_pair`), handed with H to one
    engine step, :func:`dirac_flow_from_gradient`."""

    def __init__(self, g: Graph, deps: list, new: Graph, remap: dict, i: int) -> None:
        scene, name, args, kw = g.args[i]
        if kw or len(args) != 1:
            raise Unsupported("a Dirac flow with further arguments")
        self.new, self.remap, self.f = new, remap, args[0]
        self.grad = _Gradient(g, deps, new, remap, i, self.f)
        self.S = self.grad.S

    def build(self) -> Ref:
        add = self.new.add
        pair = self.grad.build()
        HX, HP = add("item", (pair, 0)), add("item", (pair, 1))
        return add("prim", (Named(DIRAC_FROM_GRADIENT), self.S, self.remap[self.f.i], HX, HP))
