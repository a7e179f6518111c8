"""Mutation analysis: how sensitive is each verification method to a small corruption?

A *mutant* of a claim is the claim's function with one small change of its source:
the sign of a term flipped, the operands of a product or commutator swapped, a
factor transposed, a term dropped, a scene letter replaced by another of the same
kind, a rational coefficient changed, a matrix function of A and the spectral
parameter inverted or not (a resolvent (μI − A)⁻¹ and μI − A, M.inv() and M,
A + λI and its inverse), the normalization of a resolvent changed ((A − μI)⁻¹,
(−μI − A)⁻¹, (A + μI)⁻¹, (I − A/μ)⁻¹), or two letters of the same shape swapped in
one term.  The space of changes is declared once, in :data:`OPERATORS` (and
:data:`LETTER_SWAPS` for the letters); every claim of the catalog gets every mutant
its source admits.

Each mutant runs, through :func:`stiefelsym.run.runner.run_one`, with every fixed-size
method at a few sizes and with the dimension-free method.  The claim as printed
runs too (the *baseline*): a cell (size, method) where the printed claim does not
pass says nothing about a mutant, and is not counted.  Then:

* a mutant is **killed** by a method when, at some counted size, its verdict is not
  ``proved``/``checked``/``numeric`` (``fails``: refuted with a witness; ``error``:
  e.g. ill-typed, the engine refused it; ``inconclusive``/``undecided``: the method
  could not decide, which is not a refutation); the tables count the refutations
  (fails, error) apart from the mutants left undecided, and print both rates
  (:func:`stiefelsym.reports.report.kill_rate`): a method that decides nothing is
  never credited with a refutation;
* a mutant that passes at every counted cell is **equivalent**: a true statement at
  the sizes run (often trivially so, sometimes only because the sizes are small, e.g.
  a condition n <= 2r + 1 changed to n <= 2r + 2 when no size has n = 2r + 2; the list
  is reported); so is a mutant that no method refutes and ``free`` proves for all n, r
  (with its re-checked certificate), even where a fixed-size method ran out of budget;
* a mutant that one method refutes (``fails`` or ``error``) at a size where another
  method passes it is a **survivor** of the passing method: a soundness or
  sensitivity problem;
* the dimension-free method ``free`` must never prove a mutant that is not
  equivalent (that would be a false proof for all n, r);
* a mutant that is only killed by ``inconclusive``/``undecided`` verdicts and passes
  elsewhere is **unresolved**.

With ``on="graphs"`` (``stiefelsym mutate --on graphs``) the mutants are made on each claim's
graphs instead (:mod:`stiefelsym.ir.mutants`, :func:`graph_mutants`): the same kinds of change, each
made at one **site** (:mod:`stiefelsym.ir.sites`: the claim expression, in the claim or a function of its
own, that built the nodes) and at every node built there, in the graph with symbolic sizes or in every
size's graph (:func:`stiefelsym.ir.mutants.site_mutants`: loop iterations and sizes alike, so graphs that
part between sizes are covered); each mutant a graph the tracer typed
(:class:`stiefelsym.ir.replay.GraphClaim`), described in the paper's notation; no Python of the claim runs
again.  Nodes the engine built (no claim frame made them) are not mutated.  By default (``sites="claim"``)
only the sites of the claim's own function are changed, as the source mode edits the claim's own function,
and those of its nearest helpers where it offers no mutant of its formulas (:func:`site_rings`); ``sites="all"``: every
site, the helpers of its package and the Hamiltonians it hands to the engine included.  A graph with no site (a
claims file's graph, replayed here) is mutated node by node, per size where its graphs have one
skeleton (:func:`stiefelsym.ir.mutants.sized_graph_mutants`).  A claim with no graph at a size run is
reported as not covered; with ``on="auto"`` it is mutated on its source instead, and the claim's record
says what its mutants were made on (``on``) and why it fell back (``fallback``).

The same machinery searches corrections of a printed formula that fails:
:func:`search_corrections` returns the candidates that pass every method at every size.
Its search space (:func:`correction_candidates`, :data:`SEARCH_EXTRAS`) is the same for
every claim: every operator above, in the claim and in the helper functions of its own
package that it calls (where the printed formulas usually live), the signs of two terms
at once (tried only when no one-step candidate passes), and, for a statement the paper
says does not hold, that it holds.  A candidate that makes a residual read E − E, or
whose left sides vanish as well (0 = 0), is no correction and is left out.
"""
from __future__ import annotations

import ast
import contextlib
import copy
import functools
import gc
import inspect
import json
import sys
import textwrap
import time
import types
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Iterator, Sequence

from stiefelsym.claims import Claim, Size
from stiefelsym.results import PASSING, Result

SCHEMA_VERSION = 1
FIXED_METHODS = ("exact", "rational", "modular", "float")
METHODS = FIXED_METHODS + ("free",)
DEFAULT_N_MAX = 4
DEFAULT_SIZE_COUNT = 3
#: verdicts that refute a mutant (as opposed to "could not decide")
DECISIVE = ("fails", "error")
#: the order in which the kind of a kill is reported when a method killed at several sizes
KILL_ORDER = ("fails", "error", "inconclusive", "undecided")
MESSAGE_WIDTH = 240
#: the symbolic method's budget per run of a mutant (its own is 120 s): at n <= 4 every claim as
#: printed is decided in under 2 s, and every mutant that no point method refutes at that size in
#: under 3 s but one, which stops either way (manakov-integrals with L(μ) inverted)
MUTANT_EXACT_SECONDS = 15.0
#: the most term products one symbolic product (or step of an inverse) of a mutant may take at a size where
#: the rational or modular method has already refuted it with an exact witness (:class:`.polyfield.term_cap`):
#: there the symbolic run can only be wrong by proving it, and the changes that make it expensive (a symbolic
#: matrix inverted, a resolvent that no longer cancels) took 4-33 s each to refute symbolically what the
#: witness had refuted already.  A count, not a time: the run stops at the same step on every machine.
#: 10^7 term products take 0.2-0.7 s in flint.
MUTANT_REFUTED_TERM_PRODUCTS = 10 ** 7
#: the most term products one symbolic product (or step of an inverse) of a mutant may take where no method has
#: refuted it: a count, so that the run stops at the same step on every machine, where MUTANT_EXACT_SECONDS (a
#: time, the same for every mutant) stops it wherever the machine has got to.  In the catalog's analysis the
#: largest product of a symbolic run that finishes is 1.34 * 10^7 term products; the one mutant that no
#: symbolic run decides (manakov-integrals with L(μ) inverted, true: checked by every point method) reaches
#: 6.9 * 10^7 about 6 s into each of its runs (at (4,2) and (4,3)), which went on to 15 s.
MUTANT_TERM_PRODUCTS = 3 * 10 ** 7
#: the methods whose ``fails`` at a size is an exact witness for MUTANT_REFUTED_TERM_PRODUCTS
WITNESS_METHODS = ("rational", "modular")

#: scene letters and the letters of the same kind that replace them (one place, both directions)
LETTER_SWAPS: dict[str, tuple[str, ...]] = {
    # a point of T*V and its momentum (n x r)
    "X": ("P",), "P": ("X",),
    # the second point of T*V
    "Y": ("Q",), "Q": ("Y",),
    # generic elements of so(n), of so(r)
    "xi": ("zeta",), "zeta": ("xi",),
    "eta": ("theta",), "theta": ("eta",),
    # the two momentum maps (so(n) and so(r): ill-typed unless n = r)
    "Phi": ("Psi",), "Psi": ("Phi",),
    # A and its inverse; the two identities (ill-typed unless n = r)
    "A": ("Ainv",), "Ainv": ("A",),
    "In": ("Ir",), "Ir": ("In",),
    # scalar parameters
    "lam": ("kappa",), "kappa": ("lam",),
    # the two components of a flow, and its two multipliers
    "Xdot": ("Pdot",), "Pdot": ("Xdot",),
    "Lambda": ("Pi",), "Pi": ("Lambda",),
}
#: calls whose two operands are swapped (commutator, brackets: antisymmetric)
SWAPPED_CALLS = ("comm", "bracket", "canonical_bracket")
#: calls whose integer arguments are sizes or indices, not coefficients
INDEX_CALLS = ("range", "len", "unit", "sym_unit", "wedge_basis", "lower_block", "zeros", "identity",
               "general_params", "skew_params", "sym_params", "generic")


# --------------------------------------------------------------------------- mutants

@dataclass(frozen=True)
class Mutant:
    """One small corruption of a claim: what changed (in words, with the source line) and
    the corrupted claim function."""

    description: str
    lineno: int
    func: Callable = field(repr=False, compare=False)
    operator: str = ""
    #: position in mutants(claim): stable for a given source, used to rerun one mutant
    index: int = 0
    #: the corrupted expression, as source
    source: str = ""
    #: a changed expectation of the claim ("holds" for a statement the paper says does not hold)
    expect: str | None = None
    #: builds the mutant with each residual a − b replaced by its left side a (errata search: a
    #: candidate whose left sides vanish too is vacuous); None: no such test
    left: Callable[[], Callable | None] | None = field(default=None, repr=False, compare=False)
    #: what changed in the paper's notation (:func:`notation`): one dict per change (where, old, new
    #: and their LaTeX); filled in for the corrections :func:`search_corrections` returns
    notation: tuple = ()
    #: called before the mutant runs (a mutant of a graph: its graphs as traced when it was made are handed
    #: to the compilation of ``func`` as first traces, :meth:`stiefelsym.ir.mutants.GraphMutant.traced`)
    prepare: Callable[[], None] | None = field(default=None, repr=False, compare=False)

    @property
    def text(self) -> str:
        """The change in the paper's notation, with the source edit in parentheses."""
        return described(list(self.notation), self.description)


@dataclass
class _Site:
    node: ast.AST
    replacement: ast.AST
    operator: str
    text: str


def _code(node: ast.AST, width: int = 70) -> str:
    text = " ".join(ast.unparse(node).split())
    return "`" + (text if len(text) <= width else text[: width - 1] + "…") + "`"


def _neg(node: ast.AST) -> ast.AST:
    return ast.UnaryOp(op=ast.USub(), operand=copy.deepcopy(node))


def _transposed(node: ast.AST) -> ast.AST:
    return ast.Attribute(value=copy.deepcopy(node), attr="T", ctx=ast.Load())


def _call_name(node: ast.Call) -> str:
    f = node.func
    return f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""


def _is_int(node: ast.AST) -> bool:
    return isinstance(node, ast.Constant) and type(node.value) is int


def _in_index(node: ast.AST, parents: list[ast.AST]) -> bool:
    """Inside the arguments of range(), len() and the other index calls, or the index of a subscript
    (M[i + 1, j], not the matrix M): sizes and indices, not mathematics."""
    if any(isinstance(p, ast.Call) and _call_name(p) in INDEX_CALLS for p in parents):
        return True
    chain = list(parents) + [node]
    return any(isinstance(p, ast.Subscript) and chain[k + 1] is p.slice for k, p in enumerate(chain[:-1]))


def _sign_sites(node, parents, names) -> Iterator[_Site]:
    """a + b <-> a - b; a unary minus added to the first term, or removed."""
    if _in_index(node, parents):
        return
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
        op = ast.Sub() if isinstance(node.op, ast.Add) else ast.Add()
        new = ast.BinOp(left=copy.deepcopy(node.left), op=op, right=copy.deepcopy(node.right))
        yield _Site(node, new, "sign", f"flip the sign of the term {_code(node.right)} in {_code(node)}")
        if not (isinstance(node.left, ast.UnaryOp) and isinstance(node.left.op, ast.USub)):
            new = ast.BinOp(left=_neg(node.left), op=copy.deepcopy(node.op), right=copy.deepcopy(node.right))
            yield _Site(node, new, "sign", f"negate the term {_code(node.left)} in {_code(node)}")
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        yield _Site(node, copy.deepcopy(node.operand), "sign", f"remove the unary minus in {_code(node)}")


def _swap_sites(node, parents, names) -> Iterator[_Site]:
    """a @ b -> b @ a; comm(a, b) -> comm(b, a) (and the brackets)."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult):
        if ast.dump(node.left) != ast.dump(node.right):
            new = ast.BinOp(left=copy.deepcopy(node.right), op=ast.MatMult(), right=copy.deepcopy(node.left))
            yield _Site(node, new, "swap", f"swap the operands of @ in {_code(node)}")
    if isinstance(node, ast.Call) and _call_name(node) in SWAPPED_CALLS and len(node.args) == 2 \
            and not node.keywords and ast.dump(node.args[0]) != ast.dump(node.args[1]):
        new = copy.deepcopy(node)
        new.args = [copy.deepcopy(node.args[1]), copy.deepcopy(node.args[0])]
        yield _Site(node, new, "swap", f"swap the operands of {_call_name(node)} in {_code(node)}")


def _transpose_sites(node, parents, names) -> Iterator[_Site]:
    """Remove a transpose anywhere; add one to a factor of @ or an operand of comm."""
    if isinstance(node, ast.Attribute) and node.attr == "T" and isinstance(node.ctx, ast.Load):
        yield _Site(node, copy.deepcopy(node.value), "transpose",
                    f"remove the transpose in {_code(node)}{_context(parents)}")
    factors: list[ast.AST] = []
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult):
        factors = [node.left, node.right]
    elif isinstance(node, ast.Call) and _call_name(node) == "comm" and len(node.args) == 2:
        factors = list(node.args)
    for k, f in enumerate(factors):
        if isinstance(f, ast.Attribute) and f.attr == "T":
            continue   # removing it is the site above
        new = copy.deepcopy(node)
        if isinstance(new, ast.BinOp):
            setattr(new, ("left", "right")[k], _transposed(f))
        else:
            new.args[k] = _transposed(f)
        yield _Site(node, new, "transpose", f"transpose the factor {_code(f)} in {_code(node)}")


def _drop_sites(node, parents, names) -> Iterator[_Site]:
    """a ± b -> a; a + b -> b, a - b -> -b."""
    if _in_index(node, parents):
        return
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
        yield _Site(node, copy.deepcopy(node.left), "drop", f"drop the term {_code(node.right)} from {_code(node)}")
        right = copy.deepcopy(node.right) if isinstance(node.op, ast.Add) else _neg(node.right)
        yield _Site(node, right, "drop", f"drop the term {_code(node.left)} from {_code(node)}")


def _context(parents: list[ast.AST]) -> str:
    """`` in `expr` `` for the enclosing expression (none for a statement)."""
    parent = parents[-1] if parents else None
    return f" in {_code(parent)}" if isinstance(parent, ast.expr) else ""


def _letter_sites(node, parents, names) -> Iterator[_Site]:
    """s.X -> s.P etc. (LETTER_SWAPS); also local names bound to letters, and flow["Lambda"]."""
    if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Load) and node.attr in LETTER_SWAPS:
        for alt in LETTER_SWAPS[node.attr]:
            new = ast.Attribute(value=copy.deepcopy(node.value), attr=alt, ctx=ast.Load())
            yield _Site(node, new, "letter", f"replace {_code(node)} by {_code(new)}{_context(parents)}")
    if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load) and node.id in LETTER_SWAPS:
        for alt in LETTER_SWAPS[node.id]:
            if alt in names:
                new = ast.Name(id=alt, ctx=ast.Load())
                yield _Site(node, new, "letter", f"replace {_code(node)} by {_code(new)}{_context(parents)}")
    if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant) \
            and isinstance(node.slice.value, str) and node.slice.value in LETTER_SWAPS:
        for alt in LETTER_SWAPS[node.slice.value]:
            new = copy.deepcopy(node)
            new.slice = ast.Constant(alt)
            yield _Site(node, new, "letter", f"replace {_code(node)} by {_code(new)}{_context(parents)}")


def _inside(parents: list[ast.AST], kinds: tuple[type, ...]) -> bool:
    return any(isinstance(p, kinds) for p in parents)


def _coefficient_sites(node, parents, names) -> Iterator[_Site]:
    """An integer coefficient k -> k + 1 (so / 2 -> / 3, s.q(1, 2) -> s.q(1, 3)); s.q(a, b) -> s.q(a, b + 1)."""
    if _is_int(node):
        if _inside(parents, (ast.Subscript, ast.Slice)):
            return   # indices are not coefficients
        if any(isinstance(p, ast.Call) and _call_name(p) in INDEX_CALLS for p in parents):
            return
        new = ast.Constant(node.value + 1)
        yield _Site(node, new, "coefficient",
                    f"change the coefficient {node.value} to {node.value + 1}{_context(parents)}")
    if isinstance(node, ast.Call) and _call_name(node) == "q" and len(node.args) == 2 and not _is_int(node.args[1]):
        new = copy.deepcopy(node)
        new.args[1] = ast.BinOp(left=copy.deepcopy(node.args[1]), op=ast.Add(), right=ast.Constant(1))
        yield _Site(node, new, "coefficient", f"change the denominator in {_code(node)} to {_code(new.args[1])}")


#: names of the spectral parameter and of scalar matrices (a matrix function of A and the spectral
#: parameter is an expression in A and one of them)
SPECTRAL_NAMES = ("lam", "mu", "nu", "kappa")
SPECTRAL_CALLS = ("scalar", "scalar_matrix")


def _inverted(node: ast.AST) -> ast.AST:
    return ast.Call(func=ast.Attribute(value=copy.deepcopy(node), attr="inv", ctx=ast.Load()), args=[], keywords=[])


def _mentions(node: ast.AST, names: Iterable[str]) -> bool:
    names = set(names)
    for sub in ast.walk(node):
        if isinstance(sub, ast.Attribute) and sub.attr in names or isinstance(sub, ast.Name) and sub.id in names:
            return True
    return False


def _spectral(node: ast.AST) -> bool:
    return _mentions(node, SPECTRAL_NAMES) or any(
        isinstance(sub, ast.Call) and _call_name(sub) in SPECTRAL_CALLS for sub in ast.walk(node))


def _invert_sites(node, parents, names) -> Iterator[_Site]:
    """Invert or not a matrix function of A and the spectral parameter: a resolvent (μI − A)⁻¹ becomes
    μI − A, an explicit inverse M.inv() becomes M, a sum in A and the spectral parameter (A + λI) becomes
    its inverse."""
    if isinstance(node, ast.Call) and _call_name(node) == "resolvent" and len(node.args) == 1:
        yield _Site(node, _inverted(node), "invert",
                    f"invert the resolvent {_code(node)} (μI − A in place of (μI − A)⁻¹){_context(parents)}")
    if isinstance(node, ast.Call) and _call_name(node) == "inv" and not node.args \
            and isinstance(node.func, ast.Attribute):
        yield _Site(node, copy.deepcopy(node.func.value), "invert",
                    f"drop the inverse in {_code(node)}{_context(parents)}")
    if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)) \
            and not (parents and isinstance(parents[-1], ast.BinOp) and isinstance(parents[-1].op, (ast.Add, ast.Sub))) \
            and _mentions(node, ("A",)) and _spectral(node):
        yield _Site(node, _inverted(node), "invert", f"invert the matrix {_code(node)}{_context(parents)}")


def _negated_argument(arg: ast.AST) -> ast.AST:
    if isinstance(arg, ast.UnaryOp) and isinstance(arg.op, ast.USub):
        return copy.deepcopy(arg.operand)
    return _neg(arg)


def _normalization_sites(node, parents, names) -> Iterator[_Site]:
    """Change the normalization of a resolvent R(μ) = (μI − A)⁻¹: (A − μI)⁻¹ = −R(μ), (−μI − A)⁻¹ = R(−μ),
    (A + μI)⁻¹ = −R(−μ), (I − A/μ)⁻¹ = μR(μ)."""
    if not (isinstance(node, ast.Call) and _call_name(node) == "resolvent" and len(node.args) == 1):
        return
    arg = node.args[0]
    flipped = copy.deepcopy(node)
    flipped.args = [_negated_argument(arg)]
    ctx = _context(parents)
    yield _Site(node, _neg(node), "normalize", f"(A − μI)⁻¹ in place of {_code(node)}{ctx}")
    yield _Site(node, flipped, "normalize", f"(−μI − A)⁻¹: {_code(flipped)} in place of {_code(node)}{ctx}")
    yield _Site(node, _neg(flipped), "normalize", f"(A + μI)⁻¹: {_code(_neg(flipped))} in place of {_code(node)}{ctx}")
    scaled = ast.BinOp(left=copy.deepcopy(arg), op=ast.Mult(), right=copy.deepcopy(node))
    yield _Site(node, scaled, "normalize", f"(I − A/μ)⁻¹: {_code(scaled)} in place of {_code(node)}{ctx}")


class _SwapLetters(ast.NodeTransformer):
    def __init__(self, a: str, b: str) -> None:
        self.map = {a: b, b: a}

    def visit_Attribute(self, node: ast.Attribute) -> ast.AST:
        self.generic_visit(node)
        if isinstance(node.ctx, ast.Load) and node.attr in self.map:
            node.attr = self.map[node.attr]
        return node

    def visit_Name(self, node: ast.Name) -> ast.AST:
        if isinstance(node.ctx, ast.Load) and node.id in self.map:
            node.id = self.map[node.id]
        return node


def _letters(node: ast.AST, names: set[str]) -> list[str]:
    out = []
    for sub, _ in _walk(node, []):   # source order
        if isinstance(sub, ast.Attribute) and isinstance(sub.ctx, ast.Load) and sub.attr in LETTER_SWAPS:
            out.append(sub.attr)
        elif isinstance(sub, ast.Name) and isinstance(sub.ctx, ast.Load) and sub.id in LETTER_SWAPS \
                and all(alt in names for alt in LETTER_SWAPS[sub.id]):
            out.append(sub.id)
    return list(dict.fromkeys(out))


def _term_swap_sites(node, parents, names) -> Iterator[_Site]:
    """Swap two letters of the same shape (LETTER_SWAPS) everywhere in one term: a maximal product
    (X.T @ R @ P -> P.T @ R @ X) or an operand of comm."""
    term = isinstance(node, ast.BinOp) and isinstance(node.op, ast.MatMult) \
        and not (parents and isinstance(parents[-1], ast.BinOp) and isinstance(parents[-1].op, ast.MatMult))
    if not term:
        return
    present = _letters(node, names)
    done = set()
    for a in present:
        for b in LETTER_SWAPS[a]:
            if b in present and frozenset((a, b)) not in done:
                done.add(frozenset((a, b)))
                new = _SwapLetters(a, b).visit(copy.deepcopy(node))
                if ast.dump(new) != ast.dump(node):
                    yield _Site(node, new, "letters", f"swap the letters {a} and {b} in the term {_code(node)}")


#: the declared space of corruptions: (name, what it does, site generator)
OPERATORS: tuple[tuple[str, str, Callable], ...] = (
    ("sign", "flip the sign of one term (a + b <-> a - b), add or remove a unary minus", _sign_sites),
    ("swap", "swap the operands of a product @ or of comm / bracket", _swap_sites),
    ("transpose", "transpose one factor (add or remove .T)", _transpose_sites),
    ("drop", "drop a term (a ± b -> a, or -> ±b)", _drop_sites),
    ("letter", "replace a scene letter by another of the same kind (LETTER_SWAPS)", _letter_sites),
    ("coefficient", "change a rational coefficient (an integer k -> k + 1; s.q(a, b) -> s.q(a, b + 1))",
     _coefficient_sites),
    ("invert", "invert or not a matrix function of A and the spectral parameter (a resolvent, an explicit "
     "inverse, A + λI)", _invert_sites),
    ("normalize", "change the normalization of a resolvent (μI − A)⁻¹: (A − μI)⁻¹, (−μI − A)⁻¹, (A + μI)⁻¹, "
     "(I − A/μ)⁻¹", _normalization_sites),
    ("letters", "swap two letters of the same shape (LETTER_SWAPS) in one term", _term_swap_sites),
)

#: the errata search adds to OPERATORS: the signs of two terms at once (in one function), the mutants
#: of the helper functions a claim calls (of its own package), and, for a statement that the paper says
#: does not hold, the statement that it does
SEARCH_EXTRAS: tuple[tuple[str, str], ...] = (
    ("sign2", "flip the signs of two terms at once (two sites of the sign operator in one function)"),
    ("helper", "every operator above, applied inside a helper function of the claim's package that the claim "
               "calls (directly or through other helpers, up to depth 3)"),
    ("expect", "a statement the paper says does not hold (expect='nonzero'): it holds (the residual vanishes); "
               "for such a statement this is the whole search space"),
)


def _function_ast(fn: Callable) -> tuple[ast.FunctionDef, str]:
    """The function's definition (decorators stripped), with the line numbers of its file."""
    lines, start = inspect.getsourcelines(fn)
    tree = ast.parse(textwrap.dedent("".join(lines)))
    defn = next(n for n in tree.body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)))
    ast.increment_lineno(defn, max(start, 1) - 1)
    defn.decorator_list = []
    defn.returns = None   # annotations are not evaluated in the mutant
    for a in defn.args.posonlyargs + defn.args.args + defn.args.kwonlyargs:
        a.annotation = None
    for a in (defn.args.vararg, defn.args.kwarg):
        if a is not None:
            a.annotation = None
    filename = inspect.getsourcefile(fn) or inspect.getfile(fn)
    return defn, filename


def _walk(node: ast.AST, parents: list[ast.AST]) -> Iterator[tuple[ast.AST, list[ast.AST]]]:
    """Pre-order, with the ancestors of each node (a fixed order: mutants are numbered by it).
    f-strings are names (of checks, of parameters), not mathematics: nothing inside is mutated."""
    if isinstance(node, ast.JoinedStr):
        return
    yield node, parents
    for child in ast.iter_child_nodes(node):
        yield from _walk(child, parents + [node])


def _bound_names(defn: ast.FunctionDef) -> set[str]:
    names = {a.arg for a in defn.args.posonlyargs + defn.args.args + defn.args.kwonlyargs}
    for node in ast.walk(defn):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
    return names


def _body(defn: ast.FunctionDef) -> list[ast.stmt]:
    """The statements of the body without the docstring."""
    body = defn.body
    if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) \
            and isinstance(body[0].value.value, str):
        body = body[1:]
    return body


def _compile(fn: Callable, defn: ast.FunctionDef, filename: str) -> Callable:
    """The mutated definition as a function of the claim's module (same globals, same closure values)."""
    freevars = fn.__code__.co_freevars
    if freevars:   # a claim defined inside a function: rebuild its closure through a factory
        factory = ast.FunctionDef(name="__mutant_factory", args=ast.arguments(
            posonlyargs=[], args=[ast.arg(arg=v) for v in freevars], vararg=None, kwonlyargs=[],
            kw_defaults=[], kwarg=None, defaults=[]), body=[defn, ast.Return(ast.Name(defn.name, ast.Load()))],
            decorator_list=[], returns=None, type_params=[])
        ast.copy_location(factory, defn)
        module = ast.Module(body=[factory], type_ignores=[])
    else:
        module = ast.Module(body=[defn], type_ignores=[])
    ast.fix_missing_locations(module)
    code = compile(module, filename, "exec", dont_inherit=True)
    namespace: dict[str, Any] = {}
    exec(code, fn.__globals__, namespace)   # noqa: S102 - the claim's own source, mutated
    if freevars:
        func = namespace["__mutant_factory"](*(c.cell_contents for c in fn.__closure__))
    else:
        func = namespace[defn.name]
    func.__defaults__ = fn.__defaults__
    func.__kwdefaults__ = fn.__kwdefaults__
    func.__doc__ = fn.__doc__
    func.__qualname__ = fn.__qualname__ + "<mutant>"
    return func


def _function_sites(defn: ast.FunctionDef, names: set[str]) -> Iterator[_Site]:
    """Every site of every operator in the body of defn, in source order (node by node, then operator)."""
    for stmt in _body(defn):
        for node, parents in _walk(stmt, [defn]):
            for _, _, gen in OPERATORS:
                yield from gen(node, parents, names)


def _vacuous(defn: ast.FunctionDef) -> bool:
    """Whether the mutated body contains a difference of two identical expressions (E − E, E + (−E)):
    a mutant that makes a residual vanish for no reason (e.g. the letters of XᵀP − PᵀX swapped in one
    term) is no candidate correction."""
    for node in ast.walk(defn):
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Sub, ast.Add)):
            right = node.right
            if isinstance(node.op, ast.Add):
                if not (isinstance(right, ast.UnaryOp) and isinstance(right.op, ast.USub)):
                    continue
                right = right.operand
            if ast.dump(node.left) == ast.dump(right):
                return True
    return False


class _LeftSides(ast.NodeTransformer):
    """In the returned dict of checks, each residual ``a - b`` becomes its left side ``a``."""

    def __init__(self) -> None:
        self.changed = False

    def visit_Dict(self, node: ast.Dict) -> ast.AST:
        self.generic_visit(node)
        node.values = [self._left(v) for v in node.values]
        return node

    def visit_DictComp(self, node: ast.DictComp) -> ast.AST:
        self.generic_visit(node)
        node.value = self._left(node.value)
        return node

    def visit_Assign(self, node: ast.Assign) -> ast.AST:   # checks[name] = a - b
        self.generic_visit(node)
        if len(node.targets) == 1 and isinstance(node.targets[0], ast.Subscript):
            node.value = self._left(node.value)
        return node

    def _left(self, v: ast.AST) -> ast.AST:
        if isinstance(v, ast.BinOp) and isinstance(v.op, ast.Sub):
            self.changed = True
            return v.left
        return v


def _left_sides(fn: Callable, defn: ast.FunctionDef | None = None, filename: str = "") -> Callable | None:
    """fn with every residual a − b of its checks replaced by a (None when no check is a difference):
    a candidate correction whose left sides vanish as well makes the printed equation read 0 = 0."""
    if defn is None:
        try:
            defn, filename = _function_ast(fn)
        except (OSError, TypeError, SyntaxError, StopIteration):
            return None
    tr = _LeftSides()
    new = tr.visit(copy.deepcopy(defn))
    return _compile(fn, ast.fix_missing_locations(new), filename) if tr.changed else None


def _function_mutants(fn: Callable, vacuity: bool = True) -> list[tuple[str, int, Callable, str, str, bool]]:
    """(description, line, mutated function, operator, source, vacuous) for every one-step mutant of
    fn, in source order, without duplicates; [] when the source is not available (``vacuity``
    False: vacuous is not looked at, and False: the mutation analysis runs every mutant)."""
    try:
        defn, filename = _function_ast(fn)
    except (OSError, TypeError, SyntaxError, StopIteration):
        return []
    names = _bound_names(defn)
    seen = {ast.unparse(defn)}
    repeats: dict[str, int] = {}
    out = []
    for site in _function_sites(defn, names):
        mutated = _mutated(defn, site)
        text = ast.unparse(mutated)
        if text in seen:
            continue
        seen.add(text)
        lineno = getattr(site.node, "lineno", defn.lineno)
        description = f"line {lineno}: {site.text}"
        repeats[description] = repeats.get(description, 0) + 1
        if repeats[description] > 1:   # the same text at another place of the line
            description += f" (occurrence {repeats[description]})"
        out.append((description, lineno, _compile(fn, mutated, filename), site.operator,
                    " ".join(ast.unparse(site.replacement).split()), vacuity and _vacuous(mutated),
                    (lambda m=mutated: _left_sides(fn, m, filename))))
    return out


def mutants(claim: Claim | Callable, helpers: bool = False) -> list[Mutant]:
    """Every mutant of a claim (or of a claim function), in source order, without duplicates.

    ``helpers``: also the mutants of the helper functions of the claim's package that the claim
    calls (see :func:`helper_functions`), each run with the claim's own code unchanged.
    Returns [] when the function's source is not available."""
    fn = claim.func if isinstance(claim, Claim) else claim
    out: list[Mutant] = []
    for description, lineno, func, op, source, _, _ in _function_mutants(fn, vacuity=False):
        out.append(Mutant(description=description, lineno=lineno, func=func, operator=op,
                          index=len(out), source=source))
    if helpers:
        for name, helper in helper_functions(fn):
            for description, lineno, func, op, source, _, _ in _function_mutants(helper, vacuity=False):
                out.append(Mutant(description=f"in {name}(), {description}", lineno=lineno,
                                  func=_patched(fn, helper, func), operator=op, index=len(out), source=source))
    return out


# --------------------------------------------------------------------------- mutants of a graph

#: what a mutation analysis mutates: the claims' Python source, their graphs, or their graphs where they
#: can be (with symbolic sizes, or per size with one skeleton) and their source otherwise
MUTATION_MODES = ("source", "graphs", "auto")
#: how the mutants of a claim were made (ClaimMutation.on)
ON_GRAPH, ON_GRAPHS_PER_SIZE, ON_SOURCE = "graph", "graphs per size", "source"


#: which sites of a claim's graphs the mutation analysis changes (``stiefelsym mutate --sites``): "claim",
#: those of the claim's own function (with the functions and lambdas defined in it: the scope of the source
#: mode), widened to the functions of its package it calls, one level at a time, for a claim whose own
#: function offers no mutant (:func:`site_rings`); "all", every site (the helpers of the claim's package and
#: the Hamiltonians it hands to the engine included: about twice the mutants, many of them equivalent)
SITE_SCOPES = ("claim", "all")
#: the helpers of a claim are looked for this many calls deep (as :func:`helper_functions`)
HELPER_DEPTH = 3


def graph_mutants(claim: Claim, sizes: Sequence[Size] | None = None,
                  census: Any = None, sites: str = "all") -> tuple[list[Mutant], str]:
    """The mutants of the claim's graph, each a :class:`Mutant` whose function is its graph
    (:class:`stiefelsym.ir.replay.GraphClaim`), with its change in the paper's notation and its site (the
    line and the source of the claim expression changed); and "", or why the claim is not covered.  Each
    mutant is one change at one site of the claim's source made at every node built there
    (:func:`stiefelsym.ir.mutants.site_mutants`): in its graph with symbolic sizes, or, for a claim with
    none, in its graphs at ``sizes`` (the first: where its changes are written), whatever loops over the
    sizes made them.  A claim with no graph at one of ``sizes`` is not covered, and the reason says so.
    Graphs with no site (a claims file's, replayed) are mutated node by node
    (:func:`stiefelsym.ir.mutants.graph_mutants`; per size :func:`~stiefelsym.ir.mutants.sized_graph_mutants`,
    where the graphs have one skeleton).  ``sites`` (:data:`SITE_SCOPES`): every site ("all", the correction
    search's space: printed formulas often live in helpers), or those of the claim's own function, else of
    its nearest helpers ("claim", :func:`site_rings`)."""
    return _graph_mutants(claim, sizes, census, sites=sites)[:2]


def _graph_mutants(claim: Claim, sizes: Sequence[Size] | None = None, census: Any = None,
                   each_size: bool = False, sites: str = "all") -> tuple[list[Mutant], str, str, str]:
    """:func:`graph_mutants`, how they were made (:data:`ON_GRAPH`, :data:`ON_GRAPHS_PER_SIZE`) and the
    sites changed (:func:`site_rings`: "" for every site).  ``each_size`` (the mutation analysis): graphs per
    size with no site that are not one computation are mutated at each size on its own
    (:func:`stiefelsym.ir.mutants.per_size_mutants`); otherwise (the correction search: a correction is one
    change at every size) such a claim is not covered."""
    from stiefelsym.ir import _compiled_graph as compile_claim
    from stiefelsym.ir.mutants import (STATEMENT_CHANGES, MutantCensus, SkeletonMismatch, per_size_mutants,
                                       site_mutants, sized_graph_mutants)
    from stiefelsym.ir.mutants import graph_mutants as on_graph
    from stiefelsym.scene import REALIZATIONS
    if sites not in SITE_SCOPES:
        raise ValueError(f"unknown scope of sites {sites!r} (one of {', '.join(SITE_SCOPES)})")
    cons = REALIZATIONS[claim.realization]
    constraints = (cons.name, cons.build)

    def at_sites(sited: dict) -> tuple[list, str]:
        if sites == "all":
            return site_mutants(sited, constraints, census), ""
        # the rings so far, together (one call: the mutants numbered and told apart as one claim's), until they
        # offer a change of the claim's formulas: a rank's or count's expected value alone is not enough
        rings = site_rings(claim.func)
        made: list = []
        for k in range(len(rings)):
            keeps = [keep for _, keep in rings[:k + 1]]
            tried = MutantCensus()
            made = site_mutants(sited, constraints, tried, keep=lambda site, keeps=keeps: any(f(site) for f in keeps))
            if any(not m.text.startswith(STATEMENT_CHANGES) for m in made) or k == len(rings) - 1:
                if census is not None:
                    census.__dict__.update(vars(tried))
                return made, "; ".join(text for text, _ in rings[:k + 1])
        return made, ""
    try:
        g = compile_claim(claim.func, None, None, constraints)
    except Exception as exc:    # noqa: BLE001 - the claim traces per size (or not at all)
        why = " ".join(str(exc).removeprefix("refused: ").split())[:200]
        at = list(dict.fromkeys((z.n, z.r) for z in sizes or () if z is not None))
        head = f"not covered on graphs: the claim has no graph with symbolic sizes (its trace stopped at: {why})"
        if not at:
            return [], head + ", and no size to trace it at", "", ""
        graphs = {}
        for n, r in at:
            try:
                graphs[(n, r)] = compile_claim(claim.func, n, r, constraints)
            except Exception as exc:    # noqa: BLE001 - no graph at that size
                return [], f"{head}, and no graph at ({n},{r}): {str(exc).removeprefix('refused: ')[:160]}", "", ""
        sited = _sited(claim.func, graphs, constraints)
        scope = ""
        if sited is not None:
            made, scope = at_sites(sited)
        else:
            try:
                made = sized_graph_mutants(graphs, constraints, census)
            except SkeletonMismatch as exc:
                if not each_size:
                    return [], f"{head}; its graphs per size differ: {exc}", "", ""
                # no node is the same node at every size, and no site says which are one expression:
                # each node of each size's graph is changed on its own
                made = per_size_mutants(graphs, constraints, census)
        return [_as_mutant(gm, functools.partial(_sized_left_sides, gm, constraints), constraints) for gm in made], \
            "", ON_GRAPHS_PER_SIZE, scope
    sited = _sited(claim.func, {None: g}, constraints)
    made, scope = at_sites(sited) if sited is not None else (on_graph(g, constraints, census), "")
    return [_as_mutant(gm, functools.partial(_graph_left_sides, gm.graph), constraints) for gm in made], "", \
        ON_GRAPH, scope


def _functions_site(functions: Sequence[Callable]) -> Callable[[Any], bool]:
    """Whether a site (:class:`stiefelsym.ir.sites.SourceSite`) is in one of ``functions`` or in a function,
    lambda or comprehension defined inside one of them (its file, and its qualified name or one under it)."""
    scopes = {(f.__code__.co_filename, f.__code__.co_qualname) for f in functions if hasattr(f, "__code__")}
    within = tuple((file, q + ".") for file, q in scopes)

    def keep(site: Any) -> bool:
        return (site.file, site.function) in scopes or \
            any(site.file == file and site.function.startswith(q) for file, q in within)
    return keep


def site_rings(fn: Callable, depth: int = HELPER_DEPTH) -> list[tuple[str, Callable[[Any], bool]]]:
    """The sites of a claim's graphs the mutation analysis changes, as rings added in order until together
    they offer a change of the claim's formulas (not only of a statement's expected value): the claim's own
    function (and what is defined inside it: the scope of the source mode's mutants); then the functions of
    its package it calls (:func:`helper_functions`), one level of calls at a time (where a claim's formulas
    live in helpers); then every other site (a Hamiltonian handed over as an object, a method of a class).
    Each ring: (what it is, in words; whether a site is in it); the rings are disjoint."""
    levels = _helper_levels(fn, depth)
    rings: list[tuple[str, Callable[[Any], bool]]] = [("the claim's function", _functions_site([fn]))]
    for k, level in enumerate(levels, 1):
        names = ", ".join(name for name, _ in level)
        what = "the functions it calls" if k == 1 else f"the functions those call ({k} calls deep)"
        rings.append((f"{what}: {names}", _functions_site([h for _, h in level])))
    inner = [keep for _, keep in rings]
    rings.append(("every site", lambda site: not any(keep(site) for keep in inner)))
    return rings


def _sited(func: Callable, graphs: dict, constraints: tuple) -> dict | None:
    """The claim's graphs (with symbolic sizes: key None; or per size) traced once more with their sites
    (:mod:`stiefelsym.ir.sites`), each the same graph as the one compiled (the same digest); None when no
    node of them has a site of claim code (a graph handed over, a claims file's graph replayed: the
    mutants are then made node by node)."""
    from stiefelsym.ir import NotDeterministic, _clean
    from stiefelsym.ir.trace import trace
    out = {}
    for z, g in graphs.items():
        m = _clean(trace, func, None if z is None else z[0], None if z is None else z[1], constraints, None, True)
        if m.digest() != g.digest():
            raise NotDeterministic("the claim traced with its sites gave another graph")
        out[z] = m
    return out if any(x is not None for m in out.values() for x in m.sites or ()) else None


def _as_mutant(gm: Any, left: Callable, constraints: tuple) -> Mutant:
    site = gm.site
    func = gm.func
    return Mutant(description=gm.description(), lineno=site.line if site is not None else 0, func=func,
                  operator=gm.operator, index=gm.index, source=site.text() if site is not None else f"%{gm.node}",
                  left=left,
                  notation=tuple(c.to_json() for c in gm.changes),
                  prepare=functools.partial(gm.traced, func, constraints))


def _sized_left_sides(gm: Any, constraints: tuple) -> Callable | None:
    """:func:`_graph_left_sides` of a mutant of a claim traced per size (its graphs traced again), as one
    claim function."""
    from stiefelsym.ir.replay import SizedGraphClaim
    graphs = gm.graphs(constraints)
    edits = {z: _left_edits(g) for z, g in graphs.items()}
    return SizedGraphClaim(graphs, edits, name="left sides") if any(edits.values()) else None


def _graph_left_sides(g: Any) -> Callable | None:
    """The graph ``g`` with each of its checks a − b replaced by its left side a (the errata search: a
    candidate whose left sides vanish too is vacuous), as a claim function; None when no check is a
    difference."""
    from stiefelsym.ir.replay import GraphClaim
    edits = _left_edits(g)
    return GraphClaim(g, edits, name="left sides") if edits else None


def _left_edits(g: Any) -> dict[int, Callable]:
    from stiefelsym.ir.graph import Ref
    edits: dict[int, Callable] = {}
    stack = list(g.args[g.output.i][1])
    while stack:
        x = stack.pop()
        if type(x) is not Ref:
            continue
        op = g.ops[x.i]
        if op == "sub":
            edits[x.i] = lambda rp, a, f: rp.arg(a[0], f)
        elif op in ("list", "tuple"):
            stack.extend(g.args[x.i])
    return edits


# --------------------------------------------------------------------------- helpers of a claim

def _referenced_names(fn: Callable) -> list[str]:
    """The global names a function's code (and the lambdas and functions inside it) refers to."""
    out: list[str] = []
    stack = [fn.__code__]
    while stack:
        code = stack.pop()
        out.extend(code.co_names)
        stack.extend(c for c in code.co_consts if isinstance(c, types.CodeType))
    return list(dict.fromkeys(out))


def _module_package(module: str) -> str:
    """The package a module belongs to: the catalog (``stiefelsym.proofs``) is a package of its own
    (not the engine), any other module the top-level package of its name."""
    from stiefelsym.claims import CATALOG
    if module == CATALOG or module.startswith(CATALOG + "."):
        return CATALOG
    return module.split(".")[0]


def _package(fn: Callable) -> str:
    return _module_package(getattr(fn, "__module__", "") or "")


def helper_functions(fn: Callable, depth: int = HELPER_DEPTH) -> list[tuple[str, Callable]]:
    """The plain functions of the claim's own package (not the engine's, not other claims) that the
    claim refers to, directly or through such helpers, up to ``depth`` levels: the formulas a claim
    builds from (the printed Lax matrices, Hamiltonians, resolvent factors)."""
    return [h for level in _helper_levels(fn, depth) for h in level]


def _helper_levels(fn: Callable, depth: int) -> list[list[tuple[str, Callable]]]:
    """:func:`helper_functions` by level: those the claim refers to, those they refer to, ... (each once,
    at its first level; empty levels left out)."""
    if not hasattr(fn, "__code__"):
        return []
    pkg = _package(fn)
    found: set[int] = set()
    levels: list[list[tuple[str, Callable]]] = []
    frontier = [fn]
    for _ in range(depth):
        nxt: list[tuple[str, Callable]] = []
        for f in frontier:
            for name in _referenced_names(f):
                obj = f.__globals__.get(name)
                if isinstance(obj, types.FunctionType) and obj is not fn and id(obj) not in found \
                        and _package(obj) == pkg and pkg and pkg != "stiefelsym" and not hasattr(obj, "claim"):
                    found.add(id(obj))
                    nxt.append((name, obj))
        if nxt:
            levels.append(nxt)
        frontier = [h for _, h in nxt]
    return levels


def _patched(fn: Callable, original: Callable, replacement: Callable) -> Callable:
    """fn, run with every binding of ``original`` in the modules of fn's package (and of the helper's)
    replaced by ``replacement`` for the duration of the call."""
    packages = {_package(fn), _package(original)}

    def run(*args, **kwargs):
        slots = []
        for mname, mod in list(sys.modules.items()):
            if mod is None or _module_package(mname) not in packages:
                continue
            d = vars(mod)
            slots += [(d, k) for k, v in list(d.items()) if v is original]
        for d, k in slots:
            d[k] = replacement
        try:
            return fn(*args, **kwargs)
        finally:
            for d, k in slots:
                d[k] = original
    run.__doc__ = fn.__doc__
    run.__name__ = getattr(fn, "__name__", "claim")
    run.__qualname__ = getattr(fn, "__qualname__", "claim") + "<mutant>"
    return run


# --------------------------------------------------------------------------- the errata search space

#: at most this many pairs of sign sites per function in the errata search
MAX_SIGN_PAIRS = 300


def _flip_in_place(node: ast.AST, site: _Site) -> None:
    """Apply a sign site to its (cloned) node in place, so that nested sites of one sum compose:
    a + b <-> a - b toggles the operator, "negate the term" wraps the left operand."""
    if site.text.startswith("flip the sign"):
        node.op = ast.Sub() if isinstance(node.op, ast.Add) else ast.Add()
    else:
        node.left = ast.UnaryOp(op=ast.USub(), operand=node.left)


def _sign_pairs(fn: Callable, label: str = "") -> list[tuple[str, int, Callable, str, Callable]]:
    """Mutants changing the signs of two terms at once (two "flip the sign" / "negate the term" sites
    of one function, nested ones included: two terms of one sum)."""
    try:
        defn, filename = _function_ast(fn)
    except (OSError, TypeError, SyntaxError, StopIteration):
        return []
    names = _bound_names(defn)
    sites = [s for s in _function_sites(defn, names) if s.operator == "sign"
             and (s.text.startswith("flip the sign") or s.text.startswith("negate the term"))]
    seen = {ast.unparse(defn)}
    out = []
    for i, a in enumerate(sites):
        for b in sites[i + 1:]:
            if len(out) >= MAX_SIGN_PAIRS:
                return out
            memo: dict[int, Any] = {}
            mutated = copy.deepcopy(defn, memo)
            _flip_in_place(memo[id(a.node)], a)
            _flip_in_place(memo[id(b.node)], b)
            text = ast.unparse(mutated)
            if text in seen or _vacuous(mutated):
                continue
            seen.add(text)
            lineno = getattr(a.node, "lineno", defn.lineno)
            line_b = getattr(b.node, "lineno", defn.lineno)
            where = f"line {lineno}" if lineno == line_b else f"lines {lineno}, {line_b}"
            out.append((f"{label}{where}: {a.text}; and {b.text}", lineno, _compile(fn, mutated, filename),
                        " ".join(ast.unparse(a.replacement).split()) + " ; "
                        + " ".join(ast.unparse(b.replacement).split()),
                        (lambda m=mutated: _left_sides(fn, m, filename))))
    return out


def correction_candidates(claim: Claim, helpers: bool = True, pairs: bool = True) -> list[Mutant]:
    """The declared search space of the errata search, for any claim: every one-step mutant of the
    claim (:data:`OPERATORS`) and, with ``helpers``, of the helper functions it calls; with ``pairs``,
    the signs of two terms at once; for a statement the paper says does not hold, only that it holds.
    Mutants that make a residual vanish for no reason (E − E) are left out."""
    fn = claim.func
    out: list[Mutant] = []

    def add(description, lineno, func, op, source, expect=None, left=None):
        out.append(Mutant(description=description, lineno=lineno, func=func, operator=op, index=len(out),
                          source=source, expect=expect, left=left))
    if claim.expect == "nonzero":
        # the paper says the residual does not vanish: a corrupted residual that does not vanish either
        # corrects nothing; the one correction is that the statement holds
        add("the statement holds: every residual vanishes (the paper says it does not)",
            getattr(fn, "__code__", None) and fn.__code__.co_firstlineno or 0, fn, "expect", "", "holds")
        return out
    for description, lineno, func, op, source, vacuous, left in _function_mutants(fn):
        if not vacuous:
            add(description, lineno, func, op, source, left=left)
    if pairs:
        for description, lineno, func, source, left in _sign_pairs(fn):
            add(description, lineno, func, "sign2", source, left=left)
    if helpers:
        claim_left: list = []

        def patched_left(helper, func):
            def build():
                if not claim_left:
                    claim_left.append(_left_sides(fn))
                return None if claim_left[0] is None else _patched(claim_left[0], helper, func)
            return build
        for name, helper in helper_functions(fn):
            for description, lineno, func, op, source, vacuous, _ in _function_mutants(helper):
                if not vacuous:
                    add(f"in {name}(), {description}", lineno, _patched(fn, helper, func), op, source,
                        left=patched_left(helper, func))
            if pairs:
                for description, lineno, func, source, _ in _sign_pairs(helper, f"in {name}(), "):
                    add(description, lineno, _patched(fn, helper, func), "sign2", source,
                        left=patched_left(helper, func))
    return out


def _mutated(defn: ast.FunctionDef, site: _Site) -> ast.FunctionDef:
    """A copy of defn with site.node replaced (the copy keeps node identity through a memo)."""
    return _mutated_many(defn, [site])


def _mutated_many(defn: ast.FunctionDef, sites: Sequence[_Site]) -> ast.FunctionDef:
    """A copy of defn with the (non-nested) nodes of several sites replaced: the nodes on the paths
    from the root to the sites are copied, every other subtree is shared with defn (never changed in
    place: a caller that edits a mutated tree copies it first), each replacement is a deep copy."""
    targets = {id(site.node): site for site in sites}

    def rebuild(node: ast.AST) -> ast.AST:
        site = targets.get(id(node))
        if site is not None and site.node is node:
            return ast.copy_location(copy.deepcopy(site.replacement), node)
        changed: dict[str, Any] = {}
        for name, value in ast.iter_fields(node):
            if isinstance(value, list):
                new = [rebuild(v) if isinstance(v, ast.AST) else v for v in value]
                if any(a is not b for a, b in zip(new, value)):
                    changed[name] = new
            elif isinstance(value, ast.AST):
                new_node = rebuild(value)
                if new_node is not value:
                    changed[name] = new_node
        if not changed:
            return node
        clone = copy.copy(node)
        for name, value in changed.items():
            setattr(clone, name, value)
        return clone

    out = rebuild(defn)
    return out if out is not defn else copy.copy(defn)


# --------------------------------------------------------------------------- the paper's notation

def notation(claim: Claim, m: Mutant, size: Size | None = None) -> list[dict[str, str]]:
    """What the mutant (or correction) ``m`` changes in the claim's graph, in the paper's notation
    (:func:`stiefelsym.run.runner.graph_change`; ``size``: where the graphs are traced when they need
    fixed sizes, by default :func:`notation_size` of the claim's sizes).  [] for a mutant that does
    not trace or that changes the expectation only."""
    from stiefelsym.run.runner import graph_change
    if m.expect is not None and m.func is claim.func:
        return []
    if size is None:
        size = notation_size([s for s in claim.sizes if not claim.expects_failure(s.n, s.r)] or list(claim.sizes))
    return graph_change(claim, m.func, size)


def notation_size(sizes: Iterable[Size | None]) -> Size | None:
    """The size at which a change is printed (a claim that reads coordinates traces per size): the
    smallest n with 1 < r < n, else the smallest n (small explicit matrices read best)."""
    fixed = sorted((s for s in sizes if s is not None), key=lambda s: (not 1 < s.r < s.n, s.n, s.r))
    return fixed[0] if fixed else None


def notation_text(changes: Sequence[dict[str, str]]) -> str:
    """The changes in Unicode, one line (:func:`stiefelsym.ir.notation.changes_text`)."""
    from stiefelsym.ir.notation import changes_text
    return changes_text(changes)


def described(changes: Sequence[dict[str, str]], description: str) -> str:
    """The paper's notation first, the source edit after it in parentheses."""
    text = notation_text(changes)
    if not text or description.startswith(text):   # a graph mutant's description is its notation
        return description
    return f"{text} (source: {description})"


# --------------------------------------------------------------------------- sizes and plan

def mutation_sizes(claim: Claim, n_max: int = DEFAULT_N_MAX, count: int = DEFAULT_SIZE_COUNT) -> list[Size]:
    """Up to ``count`` sizes with n <= n_max where the printed claim is stated and expected to hold:
    first one with 1 < r < n (largest n), then sizes with distinct r (largest n first)."""
    cands = [s for s in claim.sizes if s.n <= n_max and not claim.expects_failure(s.n, s.r)]
    if not cands:
        cands = [Size(n, r) for n in range(1, n_max + 1) for r in range(1, n + 1)
                 if claim.sizes.admits(n, r) and not claim.expects_failure(n, r)]
    order = sorted(cands, key=lambda s: (-s.n, s.r))
    chosen: list[Size] = []
    mid = [s for s in order if 1 < s.r < s.n]
    if mid:
        chosen.append(mid[0])
    for s in order:
        if len(chosen) >= count:
            break
        if all(c.r != s.r for c in chosen):
            chosen.append(s)
    for s in order:   # fewer distinct r than wanted: fill with the remaining sizes
        if len(chosen) >= count:
            break
        if s not in chosen:
            chosen.append(s)
    return chosen


def _exact_ok(claim: Claim, size: Size) -> bool:
    return claim.exact_at(size.n, size.r)


def cells(claim: Claim, sizes: Sequence[Size], methods: Sequence[str]) -> list[tuple[Size | None, str]]:
    """The (size, method) runs of one mutant: exact only within the claim's symbolic budget, no float
    for dimension claims (as the runner plans them), ``free`` once (size None)."""
    out: list[tuple[Size | None, str]] = []
    for s in sizes:
        for m in methods:
            if m == "free" or (m == "exact" and not _exact_ok(claim, s)) or (m == "float" and claim.kind == "dim"):
                continue
            out.append((s, m))
    if "free" in methods:
        out.append((None, "free"))
    return out


# --------------------------------------------------------------------------- records

@dataclass
class Cell:
    """One run of a mutant (or of the printed claim): the verdict at one size by one method."""

    n: int | None
    r: int | None
    method: str
    verdict: str
    seconds: float = 0.0
    seed: int | None = None
    message: str = ""

    @property
    def size(self) -> str:
        return "all n, r" if self.n is None else f"({self.n},{self.r})"

    @classmethod
    def of(cls, res: Result) -> "Cell":
        msg = " ".join((res.message or res.residual or res.certificate or "").split())
        if len(msg) > MESSAGE_WIDTH:
            msg = msg[: MESSAGE_WIDTH - 1] + "…"
        return cls(res.n, res.r, res.method, res.verdict, round(res.seconds, 3), res.seed, msg)


@dataclass
class MutantOutcome:
    """What every method said about one mutant, and its classification."""

    claim: str
    index: int | None          # None: the printed claim (the baseline)
    description: str
    lineno: int | None
    operator: str
    source: str = ""
    cells: list[Cell] = field(default_factory=list)
    #: killed | survivor | equivalent | unresolved | unexercised | baseline
    classification: str = ""
    #: method -> kind of its kill (fails, error, inconclusive, undecided)
    killed_by: dict[str, str] = field(default_factory=dict)
    #: methods that passed the mutant at a size where another method refuted it (free: proved it)
    survived: list[str] = field(default_factory=list)
    #: what changed in the paper's notation (:func:`notation`)
    notation: list[dict[str, str]] = field(default_factory=list)

    @property
    def label(self) -> str:
        return f"{self.claim}#{self.index}" if self.index is not None else f"{self.claim} (as printed)"

    def verdicts(self) -> dict[str, str]:
        """Per method: its verdicts over the sizes, e.g. ``fails (4,2), checked (4,1)``."""
        out: dict[str, list[str]] = {}
        for c in self.cells:
            out.setdefault(c.method, []).append(c.verdict if c.n is None else f"{c.verdict} {c.size}")
        return {m: ", ".join(v) for m, v in out.items()}

    def line(self) -> str:
        """One greppable line."""
        per = "; ".join(f"{m} {v}" for m, v in self.verdicts().items())
        tag = "  SURVIVOR of " + ", ".join(self.survived) if self.survived else ""
        return f"{self.label} {self.classification}: {described(self.notation, self.description)} [{per}]{tag}"


@dataclass
class ClaimMutation:
    """The mutation analysis of one claim."""

    claim: str
    paper: list[str]
    section: str
    kind: str
    sizes: list[tuple[int, int]]
    methods: list[str]
    mutant_count: int = 0
    baseline: MutantOutcome | None = None
    mutants: list[MutantOutcome] = field(default_factory=list)
    #: why the claim was not mutated (empty when it was)
    skipped: str = ""
    seconds: float = 0.0
    #: what its mutants were made on: "graph" (its graph with symbolic sizes), "graphs per size" (one
    #: change at the same node of its graph at each size) or "source" (its Python source)
    on: str = ""
    #: why a mutation on graphs fell back to the source (``on="auto"``)
    fallback: str = ""
    #: what became of the changes of its graphs (sites, ill_typed, same_as_claim, duplicates, ...)
    census: dict = field(default_factory=dict)
    #: on graphs with ``sites="claim"``: the sites changed (:func:`site_rings`: the claim's function, or the
    #: helpers it calls where its function offers no mutant); empty for every site or on the source
    sites: str = ""

    def counted(self) -> set[tuple[int | None, int | None, str]]:
        """The cells where the printed claim passes (free: always counted)."""
        if self.baseline is None:
            return set()
        return {(c.n, c.r, c.method) for c in self.baseline.cells
                if c.method == "free" or c.verdict in PASSING}

    def table(self) -> list[dict[str, Any]]:
        """Per method: total, killed (by kind), survived, equivalent, unresolved, missed, baseline."""
        rows = []
        for m in self.methods:
            base = [c for c in (self.baseline.cells if self.baseline else []) if c.method == m]
            if not base:
                continue
            counted = {k for k in self.counted() if k[2] == m}
            ran = [o for o in self.mutants if any((c.n, c.r, c.method) in counted for c in o.cells)]
            row = {"claim": self.claim, "method": m, "total": len(ran), "killed": 0,
                   "fails": 0, "error": 0, "inconclusive": 0, "undecided": 0,
                   "survived": 0, "equivalent": 0, "unresolved": 0, "missed": 0,
                   "baseline": _baseline_text(base),
                   "baseline_passes": any(c.verdict in PASSING for c in base)}
            for o in ran:
                if o.classification == "equivalent":
                    row["equivalent"] += 1
                elif m in o.survived:
                    row["survived"] += 1
                elif m in o.killed_by:
                    row["killed"] += 1
                    row[o.killed_by[m]] += 1
                elif o.classification == "unresolved":
                    row["unresolved"] += 1
                else:
                    row["missed"] += 1
            rows.append(row)
        return rows


def _baseline_text(base: list[Cell]) -> str:
    """The printed claim's verdicts by one method: ``proved`` or ``checked; inconclusive at (4,3)``."""
    passing = list(dict.fromkeys(c.verdict for c in base if c.verdict in PASSING))
    other: dict[str, list[str]] = {}
    for c in base:
        if c.verdict not in PASSING:
            other.setdefault(c.verdict, []).append(c.size)
    parts = passing + [v if all(s == "all n, r" for s in where) else f"{v} at {', '.join(where)}"
                       for v, where in other.items()]
    return "; ".join(parts)


@dataclass
class MutationReport:
    """The mutation analysis of several claims, with the run's metadata."""

    claims: list[ClaimMutation] = field(default_factory=list)
    meta: dict[str, Any] = field(default_factory=dict)

    def outcomes(self) -> list[MutantOutcome]:
        return [o for c in self.claims for o in c.mutants]

    def survivors(self) -> list[MutantOutcome]:
        """Mutants that some method passed although another refuted them, or that free proved."""
        return [o for o in self.outcomes() if o.survived]

    def equivalents(self) -> list[MutantOutcome]:
        return [o for o in self.outcomes() if o.classification == "equivalent"]

    def table(self) -> list[dict[str, Any]]:
        return [row for c in self.claims for row in c.table()]

    def totals(self) -> list[dict[str, Any]]:
        """The table summed over claims, per method."""
        out: dict[str, dict[str, Any]] = {}
        for row in self.table():
            if not row["baseline_passes"]:
                continue   # nothing a method could kill where the printed claim does not pass
            t = out.setdefault(row["method"], {k: 0 for k in row
                                               if k not in ("claim", "method", "baseline", "baseline_passes")})
            for k in t:
                t[k] += row[k]
        return [{"claim": "all claims", "method": m, **t, "baseline": "", "baseline_passes": True}
                for m, t in out.items()]

    def ok(self) -> bool:
        """No survivor (in particular, free proved no mutant that is not equivalent)."""
        return not self.survivors()

    def to_json(self) -> dict[str, Any]:
        return {"schema": SCHEMA_VERSION, "meta": self.meta,
                "claims": [asdict(c) for c in self.claims],
                "table": self.table(), "totals": self.totals()}

    def dumps(self) -> str:
        return json.dumps(self.to_json(), indent=1, default=str) + "\n"

    @classmethod
    def from_json(cls, d: dict[str, Any]) -> "MutationReport":
        def outcome(o: dict[str, Any] | None) -> MutantOutcome | None:
            if o is None:
                return None
            o = dict(o)
            o["cells"] = [Cell(**c) for c in o.get("cells", [])]
            return MutantOutcome(**o)

        claims = []
        for c in d.get("claims", []):
            c = dict(c)
            c["sizes"] = [tuple(s) for s in c.get("sizes", [])]
            c["baseline"] = outcome(c.get("baseline"))
            c["mutants"] = [outcome(o) for o in c.get("mutants", [])]
            claims.append(ClaimMutation(**c))
        return cls(claims=claims, meta=dict(d.get("meta", {})))

    @classmethod
    def load(cls, path: str | Path) -> "MutationReport":
        return cls.from_json(json.loads(Path(path).read_text(encoding="utf-8")))


# --------------------------------------------------------------------------- running

def _run_cells(claim: Claim, plan: Sequence[tuple[Size | None, str]], seed: int,
               func: Callable | None, variant: str | None, loan: Any = None) -> list[Cell]:
    """The cells of the plan, in its order.  A mutant's symbolic runs come after its other runs: a
    refutation attaches the witness of a rational point, which the rational run at the same size has
    computed on the same lent points (:func:`stiefelsym.methods.fixed_size._rational_witness`); every run of a
    mutant is independent of the others (each lent point a copy of the same snapshot), so the order
    changes no verdict.  The printed claim's runs (which record the points) keep the plan's order.  A
    mutant's symbolic run at a size where a method of WITNESS_METHODS has refuted it is capped at
    MUTANT_REFUTED_TERM_PRODUCTS term products per product while the ``loan`` lends (with fresh points the
    symbolic method has its own budgets); elsewhere at MUTANT_TERM_PRODUCTS.  The claim as printed is never
    capped."""
    from stiefelsym.run.runner import run_one
    order = sorted(range(len(plan)), key=lambda k: func is not None and plan[k][1] == "exact")
    out: dict[int, Cell] = {}
    for k in order:
        s, m = plan[k]
        symbolic = func is not None and m == "exact"
        refuted = symbolic and any(
            plan[j][0] == s and plan[j][1] in WITNESS_METHODS and c.verdict == "fails" for j, c in out.items())
        with _capped(loan, MUTANT_REFUTED_TERM_PRODUCTS if refuted else MUTANT_TERM_PRODUCTS if symbolic else None):
            out[k] = Cell.of(run_one(claim, s, m, seed, func=func, variant=variant))
    return [out[k] for k in range(len(plan))]


@contextlib.contextmanager
def _capped(loan: Any, products: int | None) -> Iterator[None]:
    """The loan's cap of term products per symbolic product set to ``products`` for the block (no loan: no
    cap, as with fresh points, where the symbolic method has its own budget too)."""
    if loan is None:
        yield
        return
    old, loan.term_products = loan.term_products, products
    try:
        yield
    finally:
        loan.term_products = old


def classify(outcome: MutantOutcome, baseline: MutantOutcome) -> MutantOutcome:
    """Fill in the classification, the kills per method and the survivals (see the module docstring)."""
    counted = {(c.n, c.r, c.method) for c in baseline.cells if c.method == "free" or c.verdict in PASSING}
    fixed = [c for c in outcome.cells if c.method != "free" and (c.n, c.r, c.method) in counted]
    free = [c for c in outcome.cells if c.method == "free"]
    kills: dict[str, list[str]] = {}
    refuted_at: set[tuple[int | None, int | None]] = set()
    for c in fixed:
        if c.verdict not in PASSING:
            kills.setdefault(c.method, []).append(c.verdict)
            if c.verdict in DECISIVE:
                refuted_at.add((c.n, c.r))
    outcome.killed_by = {m: min(vs, key=KILL_ORDER.index) for m, vs in kills.items()}
    survived = [c.method for c in fixed if (c.n, c.r) in refuted_at and c.verdict in PASSING]
    if not fixed:
        outcome.classification = "unexercised"
    elif not kills:
        outcome.classification = "equivalent"
    elif refuted_at:
        outcome.classification = "survivor" if survived else "killed"
    else:
        outcome.classification = "unresolved"
    if not refuted_at and any(c.verdict == "proved" for c in free):
        # nothing refuted it and it is proved for all n, r with a re-checked certificate: a true
        # statement, even where a fixed-size method could not decide it (e.g. exact out of budget)
        outcome.classification = "equivalent"
        outcome.killed_by = {}
    for c in free:
        if c.verdict == "proved" and outcome.classification != "equivalent":
            survived.append("free")   # a dimension-free proof of a statement a method refuted: unsound
        elif c.verdict != "proved" and outcome.classification != "equivalent":
            outcome.killed_by["free"] = c.verdict if c.verdict in KILL_ORDER else "undecided"
    if "free" in survived and outcome.classification in ("killed", "unresolved", "unexercised"):
        outcome.classification = "survivor"
    outcome.survived = list(dict.fromkeys(survived))
    return outcome


#: filled in before worker processes are forked (mutant functions cannot be pickled)
_WORK: dict[str, Any] = {}


def _select(muts: list[Mutant], limit: int | None, only: Iterable[int] | None) -> list[Mutant]:
    if only is not None:
        wanted = set(only)
        return [m for m in muts if m.index in wanted]
    if limit is None or limit >= len(muts):
        return muts
    if limit <= 0:
        return []
    # evenly spread over the source, so that a limited run still sees every part of the claim
    step = len(muts) / limit
    return [muts[int(k * step)] for k in range(limit)]


def run_mutation(claims: Sequence[Claim], sizes: Sequence[Size] | None = None,
                 methods: Sequence[str] = METHODS, seed: int = 0,
                 on_result: Callable[[MutantOutcome], None] | None = None, *,
                 limit: int | None = None, only: Iterable[int] | None = None,
                 jobs: int = 1, lend: bool = True, on: str = "source", sites: str = "claim") -> MutationReport:
    """Run every mutant of every claim with every method; classify each mutant.

    ``sizes``: the fixed sizes (default: :func:`mutation_sizes` of each claim; given sizes
    are filtered by what each claim admits and expects to hold).  ``limit``: at most that many
    mutants per claim, evenly spread over the source; ``only``: these mutant indices.
    ``on_result`` is called with the baseline and then with each mutant, in order.
    ``jobs`` > 1 runs mutants in that many forked worker processes.  ``lend``: the point methods
    evaluate each mutant at the points of the claim as printed, recomputing only the nodes of its
    graph that the change reaches (:class:`stiefelsym.methods.fixed_size.PointLoan`); False: every mutant on
    points of its own, as a verify run of it would be (slower).  ``on``: "source" mutates each claim's
    Python source and traces every mutant (:func:`mutants`); "graphs" mutates the claim's graph
    (:func:`graph_mutants`; no Python of the claim runs again), or its graphs per size where they have
    one skeleton (the others are reported as not covered); "auto": graphs where they can be, the source
    otherwise.  ``sites`` (on graphs, :data:`SITE_SCOPES`): "claim" changes the sites of the claim's own
    function, as the source mode changes its own source (those of its nearest helpers where it has none,
    :func:`site_rings`); "all" every site of its graphs."""
    from stiefelsym.methods.fixed_size import PointLoan, lending_points, mutation_analysis
    if on not in MUTATION_MODES:
        raise ValueError(f"unknown mutation mode {on!r} (one of {', '.join(MUTATION_MODES)})")
    if sites not in SITE_SCOPES:
        raise ValueError(f"unknown scope of sites {sites!r} (one of {', '.join(SITE_SCOPES)})")
    loan = PointLoan(exact_seconds=MUTANT_EXACT_SECONDS)
    with mutation_analysis(), lending_points(loan) if lend else contextlib.nullcontext():
        return _run_mutation(claims, sizes, methods, seed, on_result, limit, only, jobs, loan, on, sites)


def _run_mutation(claims, sizes, methods, seed, on_result, limit, only, jobs, loan, on="source",
                  sites="claim") -> MutationReport:
    methods = list(dict.fromkeys(methods))
    for m in methods:
        if m not in METHODS:
            raise ValueError(f"unknown mutation method {m!r} (one of {', '.join(METHODS)})")
    if seed < 0:
        raise ValueError("the seed must be a non-negative integer")
    report = MutationReport()
    work: list[tuple[Claim, list]] = []
    for claim in claims:
        if sizes is None:
            chosen = mutation_sizes(claim)
        else:
            chosen = [s for s in sizes if claim.sizes.admits(s.n, s.r) and not claim.expects_failure(s.n, s.r)]
        cm = ClaimMutation(claim=claim.id, paper=list(claim.paper), section=claim.section, kind=claim.kind,
                           sizes=[(s.n, s.r) for s in chosen], methods=list(methods))
        report.claims.append(cm)
        work.append((claim, cells(claim, chosen, methods)))

    # one task per claim (its mutants generated, its printed claim run first, then its mutants, in one
    # process: the mutants borrow the printed claim's points there); the largest first, so that the
    # workers finish together; the results are taken in the catalog's order whatever the schedule
    order = sorted(range(len(work)), key=lambda ci: -_weight(*work[ci]))
    _WORK.clear()
    _WORK.update(claims=work, seed=seed, limit=limit, only=only, loan=loan, on=on, sites=sites)
    if "exact" in methods:
        import sympy.polys.matrices  # noqa: F401 (once, before the workers and their exact children fork)
    done: dict[int, _ClaimRun] = {}
    emitted = 0
    try:
        with _collector_for_many_runs():
            for ci, run in zip(order, _map(order, jobs)):
                done[ci] = run
                while emitted in done:
                    _take(report.claims[emitted], done.pop(emitted), on_result)
                    emitted += 1
    finally:
        _WORK.clear()
    return report


#: the cyclic garbage collector's thresholds during a mutation analysis (see _collector_for_many_runs)
COLLECTOR_THRESHOLDS = (20_000, 20, 20)


@contextlib.contextmanager
def _collector_for_many_runs() -> Iterator[None]:
    """Python's cyclic garbage collector scheduled for thousands of short runs (inherited by forked
    workers): what exists before them (the engine, the libraries, the catalog, the claims' graphs) is
    frozen out of its passes, and its youngest generation is collected every 20,000 allocations, not
    every 700.  At the default schedule the collector took about a quarter of the CPU time (the
    analyses of ym-second-derivative and pencil-rank-a1: 7.0 of 25 s, with 37 full passes; so: 1.9 of
    17 s, none).  Nothing is freed that would not be freed anyway, only later; no result depends on it."""
    old = gc.get_threshold()
    gc.collect()
    gc.freeze()
    gc.set_threshold(*COLLECTOR_THRESHOLDS)
    try:
        yield
    finally:
        gc.set_threshold(*old)
        gc.unfreeze()


@dataclass
class _ClaimRun:
    """What a worker sends back of one claim: its mutants' count, why it was skipped, its outcomes."""
    mutant_count: int
    skipped: str
    baseline: MutantOutcome | None
    mutants: list[MutantOutcome]
    seconds: float
    on: str = ""
    fallback: str = ""
    census: dict = field(default_factory=dict)
    sites: str = ""


def _weight(claim: Claim, plan: list) -> int:
    """A cheap estimate of a claim's share of the work (its source's length times its cells), to
    schedule the largest first; no result depends on it."""
    if claim.expect == "fails" or not plan:
        return 0
    try:
        size = len(inspect.getsource(claim.func))
    except (OSError, TypeError):
        size = 0
    return size * len(plan)


def _take(cm: ClaimMutation, run: _ClaimRun, on_result: Callable[[MutantOutcome], None] | None) -> None:
    cm.mutant_count, cm.skipped, cm.baseline, cm.mutants = run.mutant_count, run.skipped, run.baseline, run.mutants
    cm.seconds = round(run.seconds, 2)
    cm.on, cm.fallback, cm.census, cm.sites = run.on, run.fallback, run.census, run.sites
    if on_result is not None and cm.baseline is not None:
        on_result(cm.baseline)
        for o in cm.mutants:
            on_result(o)


def _claim_task(ci: int) -> _ClaimRun:
    """Claim number ci of _WORK: its mutants, the claim as printed (its points kept for the mutants),
    then every selected mutant, classified against it."""
    claim, plan = _WORK["claims"][ci]
    seed, loan = _WORK["seed"], _WORK["loan"]
    mode = _WORK.get("on", "source")
    uncovered, made_on, fallback, scope = "", "", "", ""
    census = None
    if claim.expect == "fails":
        muts = []
    elif mode in ("graphs", "auto"):
        from stiefelsym.ir.mutants import MutantCensus
        census = MutantCensus()
        # the sizes of the plan, the one the changes are written at first
        at = [s for s, _ in plan if s is not None]
        where = notation_size(at)
        at = list(dict.fromkeys(([where] if where is not None else []) + at))
        muts, uncovered, made_on, scope = _graph_mutants(claim, at, census, each_size=True,
                                                          sites=_WORK.get("sites", "claim"))
        if uncovered and mode == "auto":
            fallback, uncovered, census = uncovered.removeprefix("not covered on graphs: "), "", None
            muts, made_on = mutants(claim), ON_SOURCE
    else:
        muts, made_on = mutants(claim), ON_SOURCE
    on_graphs = made_on in (ON_GRAPH, ON_GRAPHS_PER_SIZE)
    if claim.expect == "fails":
        skipped = ("the printed statement fails at every size (a documented erratum): a mutation "
                   "analysis needs a true statement")
    elif uncovered:
        skipped = uncovered
    elif not muts and on_graphs:
        skipped = "the claim's graph offers no well-typed mutant"
    elif not muts:
        skipped = "the claim's source is not available, or offers no mutation site"
    elif not plan:
        skipped = "no size at which the printed statement is expected to hold, and no method to run"
    else:
        skipped = ""
    if claim.reviewed and made_on == ON_SOURCE:
        from stiefelsym.ir import trace_once
        for m in muts:           # edits of the catalog's own source: traced once per size (no determinism check)
            trace_once(m.func)
    run = _ClaimRun(len(muts), skipped, None, [], 0.0, "" if skipped else made_on, fallback,
                    {} if census is None else {k: v for k, v in asdict(census).items() if k != "refusals"},
                    "" if skipped else scope)
    if skipped:
        return run
    t0 = time.perf_counter()
    loan.recording = True          # the baseline's points are kept for its mutants
    try:
        run.baseline = MutantOutcome(claim.id, None, "the claim as printed", None, "", "",
                                     _run_cells(claim, plan, seed, None, None), "baseline")
    finally:
        loan.recording = False
    where = notation_size(s for s, _ in plan)
    try:
        for m in _select(muts, _WORK["limit"], _WORK["only"]):
            if m.prepare is not None:
                m.prepare()
            o = MutantOutcome(claim.id, m.index, m.description, (m.lineno or None) if on_graphs else m.lineno, m.operator,
                              m.source, _run_cells(claim, plan, seed, m.func, m.description, loan),
                              notation=list(m.notation) if on_graphs else notation(claim, m, where))
            run.mutants.append(classify(o, run.baseline))
    finally:
        loan.forget(claim.id)      # its points serve no other claim
    run.seconds = time.perf_counter() - t0
    return run


def _map(order: list[int], jobs: int) -> Iterator[_ClaimRun]:
    """The claims' runs, in the given order; in ``jobs`` forked workers when jobs > 1."""
    if jobs <= 1 or len(order) <= 1:
        for ci in order:
            yield _claim_task(ci)
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor
    with ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("fork")) as ex:
        try:
            yield from ex.map(_claim_task, order, chunksize=1)
        except BaseException:
            ex.shutdown(wait=False, cancel_futures=True)
            raise


# --------------------------------------------------------------------------- errata search

def search_corrections(claim: Claim, sizes: Sequence[Size] | None = None,
                       methods: Sequence[str] = ("rational", "modular"), seed: int = 0,
                       candidates: Sequence[Mutant] | None = None,
                       on_candidate: Callable[[Mutant, bool], None] | None = None,
                       minimal: bool = True) -> list[Mutant]:
    """The candidates (default: :func:`correction_candidates`, the declared search space) that pass
    every method at every given size: corrections of a printed formula that fails, verified by the
    same methods as the claims.

    Default sizes: the claim's own sizes with n <= 4.  Each candidate is run cell by cell and
    dropped at its first cell that does not pass, so a wrong candidate costs one run.  A candidate
    with a changed expectation (``expect``) runs as a claim with that expectation.
    ``on_candidate(mutant, passed)`` is called after each candidate.  ``minimal``: the two-step
    candidates (two signs, operator ``sign2``) are tried only when no one-step candidate passes."""
    from dataclasses import replace

    from stiefelsym.run.runner import run_one
    if sizes is None:
        sizes = [s for s in claim.sizes if s.n <= DEFAULT_N_MAX] or list(claim.sizes)[:1]
    for m in methods:
        if m not in METHODS:
            raise ValueError(f"unknown method {m!r} (one of {', '.join(METHODS)})")
    plan = cells(claim, list(sizes), list(methods))

    def passes(m: Mutant, s: Size | None, meth: str) -> bool:
        c = claim if m.expect is None else _same_review(replace(claim, expect=m.expect, fails_at=None, erratum=""),
                                                         claim)
        verdict = run_one(c, s, meth, seed, func=m.func, variant=m.description).verdict
        return verdict == "proved" if meth == "free" else verdict in PASSING

    def vacuous(m: Mutant) -> bool:
        """The candidate's left sides vanish too, at every fixed-size cell of the plan: it reads 0 = 0.  (A
        left side that vanishes at the smallest size only, Ψ = 0 at r = 1, is no reason to drop a candidate
        that holds at the larger sizes; the largest sizes are tried first, where a left side rarely vanishes.)"""
        left = m.left() if m.left is not None else None
        fixed = [(s, meth) for s, meth in plan if meth != "free"]
        if left is None or not fixed:
            return False
        sides = Mutant(m.description + " (left sides)", m.lineno, left, expect=m.expect)
        return all(passes(sides, s, meth) for s, meth in reversed(fixed))

    found: list[Mutant] = []
    pool = list(correction_candidates(claim) if candidates is None else candidates)
    pool.sort(key=lambda m: m.operator == "sign2")   # one-step candidates first (stable)
    from stiefelsym.methods.fixed_size import PointLoan, lending_points, mutation_analysis
    loan = PointLoan()
    with mutation_analysis(), lending_points(loan):
        # the printed formula's points, lent to every candidate (which recomputes only what it changed)
        loan.recording = True
        try:
            for s, meth in plan:
                if meth != "free":
                    run_one(claim, s, meth, seed)
        finally:
            loan.recording = False
        for m in pool:
            if minimal and m.operator == "sign2" and any(f.operator != "sign2" for f in found):
                break
            if m.prepare is not None:
                m.prepare()
            ok = bool(plan) and all(passes(m, s, meth) for s, meth in plan) and not vacuous(m)
            if ok:
                if not m.notation:          # (a mutant of the graph carries its change already)
                    m = replace(m, notation=tuple(notation(claim, m, notation_size(s for s, _ in plan))))
                found.append(m)
            if on_candidate is not None:
                on_candidate(m, ok)
    return found


def _same_review(made: Claim, claim: Claim) -> Claim:
    """``made`` (a copy of ``claim`` with another expectation, made here) reviewed as ``claim`` is: with the same
    functions, none of them a mutant's."""
    from stiefelsym.claims import _mark_reviewed, reviewed_functions
    funcs = reviewed_functions(claim)
    return _mark_reviewed(made, funcs) if funcs else made
