"""Verification methods: each turns (claim, n, r, seed) into one Result.

* ``exact``    symbolic (symengine): the residual is identically zero on a chart
               of the constraint set; the reduction used is stated.
* ``rational`` exact rationals at seeded random points of the Cayley chart
               (integers in [-2^62, 2^62]), with the Schwartz-Zippel false-pass
               bound from a degree bound; as many points as the bound 1e-30 needs.
* ``modular``  the same over GF(p), a fresh prime p in [2^62, 2^63) per point,
               with a height bound for the primes that divide the numerator.
* ``float``    float64 with a running error bound; mpmath escalation.
* ``ball``     rigorous ball arithmetic (arb) at the float method's exact points, 53 to 424 bits.

Sampled methods never decide a rank "at every point" (verdict ``undecided``),
and a check without entries is an error under every method.
"""
from __future__ import annotations

import contextlib
import contextvars
import dataclasses
import functools
import gc
import math
import os
import random
import re
import weakref
import time
from collections import OrderedDict
from contextlib import contextmanager
from dataclasses import dataclass, field as dc_field
from fractions import Fraction
from typing import Any, Callable, Iterator

import numpy as np

from stiefelsym._lazy import lazy
from stiefelsym.claims import Claim, Count, Expired, Rank, deadline
from stiefelsym.ir.statements import InverseIdentities
from stiefelsym.ir.graph import Named
from stiefelsym.methods import cayley_right, complex_right, costmodel
from stiefelsym.methods.costmodel import BudgetError as BudgetError  # the methods raise it (re-exported)
from stiefelsym.ir import _compiled_graph as _compile_whole
from stiefelsym.ir.derivative import derivatives, scene_flows
from stiefelsym.ir.notation import power_of_ten
from stiefelsym.ir.evaluate import evaluate
from stiefelsym.ir.seal import verify as verify_engine
from stiefelsym.ir.passes import (BLOCK_SPLITTING, FLOAT_EXPONENT_LIMIT, coordinate_needs, coordinate_reads, outside_float_range,
                                  power_exponents, product_degree)
from stiefelsym.scene import REALIZATIONS
from stiefelsym.backends.fields import (PRIME_BITS, PRIME_LOW, PRIMES_IN_RANGE_LOWER, ConstantDegenerate, DegenerateError, DegreeField,
                     ErrNum, Field, FloatField, ModularField, RationalField, SymbolicBudget, random_prime)
from stiefelsym.backends.polyfield import SymbolicField
from stiefelsym.backends.matrix import Mat, is_scene_number
from stiefelsym.backends.native import F64, DegMat, _buf, backend, one_blas_thread, quiet_numpy
from stiefelsym.backends.paired import PairField, marker_of
from stiefelsym.results import CheckOutcome, Result, short_value
from stiefelsym.scene import CoordinateAccess, PointRead, Scene, SizeError

flint = lazy("flint", globals())
mpmath = lazy("mpmath", globals())

EXACT_CAYLEY_MAX_N = 7       # the symbolic Cayley chart (used when coordinates are read; one r x r inverse for r < n)
EXACT_TIME_LIMIT = 120.0      # seconds per (claim, size) for the symbolic method
MAX_RESAMPLE = 8
FLOAT_RESOLUTION = 1e-8       # a pass must be able to see a relative residual this small
#: float64, then mpmath at 30, 60, 120 digits with the same error model.  For an identity, when
#: float64's bounds cannot decide, the rigorous ball method decides first (arb at 53 to 424 bits at the
#: same exact point); mpmath is the last resort only where the balls stay inconclusive (float64 term
#: scales that overflow)
FLOAT_LADDER = (None, 30, 60, 120)


class RankNotDecided(Exception):
    """A rank at every point that the exact method can neither prove (no constant nonzero maximal
    minor) nor refute (the rank over the function field is the stated one, so no point where it drops
    is known): the verdict is ``undecided``, never ``fails`` without a witness."""


class ExactTimeout(Expired):
    pass


def check_budget(method: str, n: int, r: int, claim: Claim | None = None, budget: float | None = None) -> float:
    """The size must be a Stiefel variety (1 <= r <= n); with a claim and a budget, the cost
    model's predicted seconds of the run must fit the budget (BudgetError otherwise, with the
    prediction and a faster method).  Returns the prediction (0 without a claim)."""
    if r < 1:
        raise SizeError(f"r = {r} < 1: a Stiefel variety V(n, r) needs r >= 1")
    if r > n:
        raise SizeError(f"r = {r} > n = {n}: V(n, r) needs r <= n")
    if claim is None or budget is None or method == "free":
        return 0.0
    return costmodel.check(method, claim, n, r, budget)


#: whose number a dimension claim's message quotes beside the computed one: the paper's for the catalog's
#: claims, the claim's own for a user's (set for the run of one claim by :func:`_quoting`)
_EXPECTED_BY: contextvars.ContextVar[str] = contextvars.ContextVar("expected_by", default="claimed")


def _stated(k: Any) -> str:
    """The number the claim states, as a message quotes it: "paper: k" (the catalog) or "claimed: k"."""
    return f"{_EXPECTED_BY.get()}: {k}"


def _who() -> str:
    """Who states the claim's numbers, as a message names it: "the paper" (the catalog) or "the claim"."""
    return "the paper" if _EXPECTED_BY.get() == "paper" else "the claim"


def _quoting(run: Callable) -> Callable:
    """A method's run of one claim (its first argument), whose messages quote the claim's numbers as the paper's
    where the claim is the catalog's, and as claimed otherwise."""
    @functools.wraps(run)
    def quoting(claim: Claim, *args: Any, **kwargs: Any) -> Any:
        token = _EXPECTED_BY.set("paper" if getattr(claim, "reviewed", False) else "claimed")
        try:
            return run(claim, *args, **kwargs)
        finally:
            _EXPECTED_BY.reset(token)
    return quoting


def time_limit(seconds: float | None):
    """Interrupt a symbolic computation that exceeds its budget (main thread only)."""
    return deadline(seconds, "the symbolic computation", lambda message: ExactTimeout(message))


#: the thresholds of the cyclic garbage collector while a claim is traced or evaluated at points (the
#: defaults are (700, 10, 10)): tracing and the paired numbers of the randomized methods make millions
#: of small objects, most of them freed by reference counting before a collection could see them, and
#: a collection of the oldest generation scans every graph a worker keeps (millions of objects)
SPACED_COLLECTIONS = (20000, 20, 20)


@contextmanager
def spaced_collections() -> Iterator[None]:
    """Meanwhile the garbage collector runs less often (:data:`SPACED_COLLECTIONS`); its thresholds are
    restored on leaving, so that the collections it deferred run at the next allocations: nothing
    collects less afterwards (a symbolic attempt forked later inherits no more garbage than before).
    A collector switched off (threshold 0) stays off."""
    old = gc.get_threshold()
    if old[0]:
        gc.set_threshold(*(max(a, b) for a, b in zip(old, SPACED_COLLECTIONS)))
    try:
        yield
    finally:
        gc.set_threshold(*old)


# ---------------------------------------------------------------------------
# flattening checks

def _entries(value: Any, prefix: str = "") -> list[tuple[str, Any]]:
    """(position, scalar) pairs of a residual: a Mat, a scalar, or a list/tuple/dict of them.

    A check without a single entry (an empty list or dict, a 0 x 0 matrix) is vacuous: it
    would pass under every method without saying anything, so it is an error."""
    out = _flatten(value, prefix)
    if not out:
        raise TypeError(f"check {prefix or 'value'} has no entries (an empty matrix, list or dict): "
                        "a vacuous check proves nothing")
    return out


def _flatten(value: Any, prefix: str) -> list[tuple[str, Any]]:
    if isinstance(value, Mat):
        a = value._view()
        rows, cols = a.shape
        return [(f"{prefix}[{i + 1},{j + 1}]", a[i, j]) for i in range(rows) for j in range(cols)]
    if isinstance(value, dict):
        out = []
        for k, v in value.items():
            out.extend(_flatten(v, f"{prefix}.{k}"))
        return out
    if isinstance(value, (list, tuple)):
        out = []
        for k, v in enumerate(value):
            out.extend(_flatten(v, f"{prefix}#{k + 1}"))
        return out
    if not is_scene_number(value):
        raise TypeError(f"check {prefix or 'value'}: a residual must be a matrix or a scalar of the scene "
                        f"(use s.q(num, den) for constants), not {type(value).__name__}")
    return [(prefix or "value", value)]


def _residual_entries(value: Any, prefix: str) -> list[tuple[str, Any]]:
    """:func:`_entries`, where a residual matrix is held by an exact backend that gives its entries as
    scalars of its own (the polynomial backend: rational functions in flint) in those scalars, so that
    a nonzero residual is not converted as a whole to the scene's numbers (symengine expressions)."""
    if isinstance(value, Mat) and value._n is not None:
        scalars = getattr(backend(value.field), "scalars", None)
        xs = scalars(value._n) if scalars is not None else None
        if xs is not None:
            rows, cols = value._shape()
            if rows and cols:
                return [(f"{prefix}[{i + 1},{j + 1}]", xs[i * cols + j]) for i in range(rows) for j in range(cols)]
    return _entries(value, prefix)


def _natively_zero(value: Any) -> bool:
    """Whether a residual matrix held by an exact whole-matrix backend is zero (one native
    comparison; False sends the caller to the entries)."""
    if not isinstance(value, Mat) or value._n is None:
        return False
    be = backend(value.field)
    if be is None or not value.field.exact or not all(value._shape()):
        return False
    return be.is_zero(value._n)


def _float_entries(value: Any, name: str, u: float) -> list[tuple[str, Any]]:
    """The entries of a float64 residual that decide the float method's verdict.

    Every decision of the float method is a maximum, an "every entry" or a "first entry such
    that" over the entries; for a matrix in native float64 storage these are found with whole-
    array operations and only the deciding entries are returned, in their order (the largest
    |v|, e and e/m, the first non-finite, the first clear, the first clear that resolves, the
    first that does not resolve)."""
    if not (isinstance(value, Mat) and value._n is not None and type(value._n) is F64 and all(value._shape())):
        return _entries(value, name)
    s = value._n
    v, m = s.v.ravel(), s.m.ravel()
    e1 = float(s.e)
    cols = s.v.shape[1]
    with np.errstate(all="ignore"):
        av = np.abs(v, out=_buf(v.shape))            # (the arrays of this test are the backend's pooled ones)
        fast = math.isfinite(e1) and math.isfinite(float(av.sum())) and math.isfinite(float(m.sum()))
    if fast:
        # every value, bound and scale finite (the sums would be inf or nan otherwise), the bound the
        # same for every entry: the same picks from fewer passes (the largest e/m is e over the
        # scales, inf where a scale is 0; the ratio is 0 everywhere when e = 0; the largest e is the
        # first entry's)
        with np.errstate(all="ignore"):
            picks = {int(np.argmax(av)), 0, int(np.argmax(np.divide(e1, m, out=_buf(m.shape)))) if e1 > 0.0 else 0}
            clear = av > e1
            resolves = e1 <= np.multiply(FLOAT_RESOLUTION, m, out=_buf(m.shape))
            for mask in (clear, clear & resolves, ~resolves):
                i = int(np.argmax(mask))
                if mask[i]:
                    picks.add(i)
        return [(f"{name}[{i // cols + 1},{i % cols + 1}]", ErrNum(float(v[i]), e1, float(m[i]), u))
                for i in sorted(picks)]
    e = np.full(v.shape, e1)
    with np.errstate(all="ignore"):
        finite = np.isfinite(v) & np.isfinite(e) & np.isfinite(m)
        clear = np.abs(v) > e
        resolves = finite & (e <= FLOAT_RESOLUTION * m)
        ratio = np.where(m != 0, e / np.where(m != 0, m, 1.0), np.where(e == 0, 0.0, np.inf))
    picks = {int(np.argmax(np.abs(v))), int(np.argmax(e)), int(np.argmax(ratio))}
    for mask in (~finite, clear, clear & resolves, ~resolves):
        hit = np.flatnonzero(mask)
        if hit.size:
            picks.add(int(hit[0]))
    return [(f"{name}[{i // cols + 1},{i % cols + 1}]", ErrNum(float(v[i]), float(e[i]), float(m[i]), u))
            for i in sorted(picks)]


#: the checks a run of the exact method is about (see :func:`_run_check_groups`): (function, names) while
#: the method proves a group of a claim's checks on a chart of their own, None otherwise
_CHECKS: "contextvars.ContextVar[tuple[Callable, frozenset[str]] | None]" = contextvars.ContextVar(
    "stiefelsym_checks", default=None)


def _claim_graph(func: Callable, n: int | None, r: int | None, constraints: tuple[str, Callable],
                  family: Any = None) -> Any:
    """The claim's graph (:func:`stiefelsym.ir.compile_claim`), or, while the exact method proves a group
    of its checks (:data:`_CHECKS`), the slice of the graph those checks read
    (:meth:`~stiefelsym.ir.graph.Graph.checks_slice`): every evaluation, pass, probe, degree bound,
    draw and memo of the run is about the slice."""
    g = _compile_whole(func, n, r, constraints, family=family)
    group = _CHECKS.get()
    if group is not None and group[0] is func and n is not None and family is None:
        key = ("checks", group[1])
        sliced = g.cache.get(key)
        if sliced is None:
            sliced = g.cache[key] = _interned(g.checks_slice(group[1]))
        g = sliced
    return g


#: slices of graphs by content (:func:`_interned`), the most recent last
_SLICES: "OrderedDict[tuple, Any]" = OrderedDict()
SLICE_CACHE_SIZE = 32


def _interned(g: Any) -> Any:
    """The slice ``g``, or an earlier slice of the same content (its digest, refusals, functions and size) in
    its place, with what the passes computed of it (derivatives, evaluation program, coordinate reads): the
    graph of a group of checks that a mutant of a claim leaves as it was is the same slice for every mutant.
    A slice is pure data made by the engine from a graph (no claim code runs); one that carries the claim's
    source sites (for its messages) is kept as it is, and so is every slice once a claims file has been imported
    into the process (:func:`~stiefelsym.ir.seal.sealed`): claim code that ran here could have written into this
    table, as into any of the process's caches."""
    from stiefelsym.ir.seal import sealed
    if g.sites is not None or sealed():
        return g
    key = (g.digest(), tuple(g.refusals), g.fns, g.sizes)
    hit = _SLICES.get(key)
    if hit is not None:
        _SLICES.move_to_end(key)
        return hit
    _SLICES[key] = g
    while len(_SLICES) > SLICE_CACHE_SIZE:
        _SLICES.popitem(last=False)
    return g


def call_claim(func: Callable, scene: Any, family: Any = None) -> dict[str, Any]:
    """A claim's checks on a method's scene: the claim's graph (traced once per size, never with
    the scene's values), its derivatives along flows and gradients rewritten into ordinary nodes
    where their bodies allow (:mod:`.ir.derivative`), evaluated on the scene; the graph's looks at
    coordinates are recorded in the scene's record first, whatever spaces the claim named.  A
    dimension-free scene may be given a family of sizes (:class:`~stiefelsym.ir.SizeFamily`): the graph
    is then the one traced on that family."""
    n, r = scene.n, scene.r
    free = type(n) is not int
    if family is not None and not free:
        raise ValueError("a family of sizes is for a dimension-free scene")
    cons = REALIZATIONS[getattr(scene, "realization", None) or "standard"]
    g = _claim_graph(func, None if free else n, None if free else r, (cons.name, cons.build), family=family)
    tracker = getattr(scene, "tracker", None)
    if tracker is not None:
        watched_spaces = {"?"} | set(tracker.spaces)
        for what, inv in coordinate_reads(g).items():
            if free and what == BLOCK_SPLITTING:
                continue    # the free algebra keeps a block matrix as its blocks, each for every n, r
            if inv & watched_spaces:
                tracker.touch(what)
    verify_engine("before an evaluation")
    checks = evaluate(derivatives(g, scene_flows(scene)), scene)
    if not isinstance(checks, dict) or not checks:
        raise TypeError("a claim must return a non-empty dict of named checks")
    for k in checks:
        if not isinstance(k, str):
            raise TypeError("check names must be strings")
    return checks


def draw_key(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None, graph: Any = None) -> str:
    """The source of every random draw of a verification of ``func`` (the claim, or a variant of it) at
    (n, r): the seed, the digest of the graph the run evaluates, the claim's id and the size.  The
    points, primes and probe points are a function of what the claim states (Fiat-Shamir): a claim
    cannot be written to vanish at its own points, because every constant it would need to compute
    them enters the digest they are drawn from.  The same commit, claim and seed give the same draws."""
    if graph is None:
        cons = REALIZATIONS[claim.realization or "standard"]
        graph = _claim_graph(func or claim.func, n, r, (cons.name, cons.build))
    return f"{seed}|{graph.digest()}|{claim.id}|{n}|{r}"


@dataclass
class Evaluation:
    outcomes: list[CheckOutcome]
    nonzero: list[tuple[str, str, Any]]   # (check, position, value) of failing residual entries
    rank_problems: list[str]              # every rank that does not match (certain or not)
    count_problems: list[str]
    rank_certain: list[str] = dc_field(default_factory=list)   # rank mismatches that are certain
    every_point: list[str] = dc_field(default_factory=list)    # "at every point" ranks this method cannot decide
    full: list[str] = dc_field(default_factory=list)           # generic ranks that are the matrix's full size here


#: what a rank function may say about a Rank statement (True/False: the exact method's "ok"/"mismatch")
RANK_STATUSES = ("ok", "mismatch", "certain", "every-point", "full")


def _evaluate(checks: dict[str, Any], field: Field, rank_fn: Callable[[Rank], tuple[str, Any]] | None) -> Evaluation:
    outcomes, nonzero, rank_problems, count_problems = [], [], [], []
    rank_certain, every_point, full = [], [], []
    for name, value in checks.items():
        if isinstance(value, Count):
            ok = value.value == value.expected
            detail = f"{value.meaning + ': ' if value.meaning else ''}{value.value} ({_stated(value.expected)})"
            outcomes.append(CheckOutcome(name, "count" if ok else "count-mismatch", detail))
            if not ok:
                count_problems.append(f"{name}: {detail}")
            continue
        if isinstance(value, Rank):
            if rank_fn is None:
                outcomes.append(CheckOutcome(name, "skipped", "ranks are decided by exact methods"))
                rank_problems.append(f"{name}: rank not decided by this method")
                continue
            detail, status = rank_fn(value)
            if status is True or status is False:
                status = "ok" if status else "mismatch"
            if status not in RANK_STATUSES:
                raise ValueError(f"unknown rank status {status!r}")
            ok = status in ("ok", "every-point", "full")
            if status == "full":
                full.append(name)
            if value.meaning:
                detail = f"{value.meaning}: {detail}"
            outcomes.append(CheckOutcome(name, "rank" if ok else "rank-mismatch", detail))
            if not ok:
                rank_problems.append(f"{name}: {detail}")
            if status == "certain":
                rank_certain.append(f"{name}: {detail}")
            elif status == "every-point":
                every_point.append(name)
            continue
        # an Inverse statement is its identities (residuals); its outcome says what they prove
        said = value.describe() if isinstance(value, InverseIdentities) else ""
        if _natively_zero(value):
            outcomes.append(CheckOutcome(name, "zero", said))
            continue
        bad = [(pos, x) for pos, x in _residual_entries(value, name) if not field.is_zero(x)]
        if bad:
            nonzero.extend((name, pos, x) for pos, x in bad)
            outcomes.append(CheckOutcome(name, "nonzero", f"{len(bad)} nonzero entries"
                                         + (" (op is not inverted by inv)" if said else "")))
        else:
            outcomes.append(CheckOutcome(name, "zero", said))
    return Evaluation(outcomes, nonzero, rank_problems, count_problems, rank_certain, every_point, full)


def _telling_entry(nonzero: list, field: Any) -> tuple:
    """The nonzero residual entry a witness names: over the rationals the largest in absolute value (the first
    of them), so that a failure does not read like rounding (an entry of 10⁻³⁶ at a point near one where it
    vanishes, beside entries of size 1); over a prime field, where values have no size, the first."""
    if getattr(field, "name", "") != "rational" or len(nonzero) == 1:
        return nonzero[0]
    try:
        return max(nonzero, key=lambda e: abs(getattr(e[2], "v", e[2])))     # (a Pair: its value)
    except TypeError:
        return nonzero[0]


def _base_result(claim: Claim, n: int | None, r: int | None, method: str, seed: int | None) -> Result:
    return Result(claim=claim.id, paper=list(claim.paper), section=claim.section, kind=claim.kind,
                  title=claim.title, statement=claim.statement, n=n, r=r, method=method,
                  verdict="error", expected=False, seconds=0.0, seed=seed, expect=claim.expect,
                  realization=claim.realization)


def expected_verdict(claim: Claim, verdict: str, variant: str | None = None,
                     n: int | None = None, r: int | None = None) -> bool:
    """Whether a verdict is the one the catalog expects (documented errata fail)."""
    if variant is None and claim.expects_failure(n, r):
        return verdict == "fails"
    return verdict in ("proved", "checked", "numeric")


# ---------------------------------------------------------------------------
# the symbolic method

def _symbolic_rows(M: Mat) -> list[list]:
    """The entries of a matrix of the symbolic method as symengine expressions (a scalar the flint
    backend keeps, e.g. an entry of a Jacobian built from traces, is converted)."""
    f = M._field
    return [[x if isinstance(x, _se_basic()) else f.normalize(x) for x in row] for row in M._view().tolist()]


def _se_basic() -> type:
    import symengine as se
    return se.Basic


def _sympy_rows(M: Mat):
    import sympy
    return [[sympy.sympify(x) for x in row] for row in _symbolic_rows(M)]


#: the largest coefficient matrix (rows x columns·monomials) :func:`_coefficient_rank_bound` builds
COEFFICIENT_BOUND_ENTRIES = 400_000


def _backend_polynomials(M: Mat):
    """The matrix as the flint backend holds it, over one common denominator (a nonzero factor of the whole
    matrix leaves its rank over the function field as it is): the rows of numerators; None where the backend
    does not hold the matrix as flint polynomials."""
    be = backend(M._field)
    if be is None or not hasattr(be, "ring"):
        return None
    from stiefelsym.backends import ratmat
    from stiefelsym.backends.polyfield import PolyMat
    from stiefelsym.backends.ratmat import RatMat
    try:
        X = M._n if M._n is not None else be.from_obj(M._view())
    except Exception:   # noqa: BLE001 - an entry flint does not hold: no bound from the coefficients
        return None
    if type(X) is RatMat:
        X = ratmat.common(be, X)
    if type(X) is not PolyMat:
        return None
    X = be._fix(X)
    m, k = X.a.shape
    if X.z:
        return [[be.ring.zero] * k for _ in range(m)]
    return X.a.tolist()


def _coefficient_rank_bound(polys) -> tuple[int, str] | None:
    """An upper bound on the rank over the function field of a matrix of polynomials (a matrix of rational
    functions times a nonzero common denominator), proved: a linear relation with rational coefficients
    among its rows (or its columns), as vectors of polynomials, holds over the function field too, so the rank is at most the rank over Q of the rows' (columns') vectors of
    coefficients, one coordinate per (column, monomial) (per (row, monomial)); each computed exactly (flint).
    Duplicated, zero and proportional rows and columns are caught so.  None where the coefficient matrix
    would exceed COEFFICIENT_BOUND_ENTRIES entries."""
    if not polys or not polys[0]:
        return 0, "an empty matrix"
    best = None
    for side, lines in (("rows", polys), ("columns", [list(c) for c in zip(*polys)])):
        spots: dict = {}
        for line in lines:
            for j, p in enumerate(line):
                if p != 0:
                    for e in p.monoms():
                        spots.setdefault((j, e), len(spots))
        if len(lines) * len(spots) > COEFFICIENT_BOUND_ENTRIES:
            continue
        vectors = []
        for line in lines:
            v = [0] * len(spots)
            for j, p in enumerate(line):
                if p != 0:
                    for e, c in zip(p.monoms(), p.coeffs()):
                        v[spots[(j, e)]] = c
            vectors.append(v)
        rank = flint.fmpq_mat(vectors).rank() if spots else 0
        if best is None or rank < best[0]:
            best = (rank, side)
    if best is None:
        return None
    rank, side = best
    return rank, (f"its {side} (times the common denominator of its entries), as vectors of polynomial "
                  f"coefficients, span a space of dimension {rank} over Q (a rational linear relation among them "
                  f"holds over the function field)")


def _function_field_rank(M: Mat) -> int:
    """The rank over the field of rational functions of the chart parameters: fraction-free
    (Bareiss) elimination over flint's multivariate polynomials, each row multiplied by the least
    common multiple of its entries' denominators (a nonzero factor per row leaves the rank as it is)
    when the entries are rational functions; sympy's DomainMatrix when they are not."""
    rows = _symbolic_rows(M)
    polys = _flint_rows(rows)
    polys = polys if polys is not None else _flint_rows_cleared(rows)
    if polys is not None:
        if all(p.is_constant() for row in polys for p in row):     # a matrix of rational numbers
            return flint.fmpq_mat([[p.leading_coefficient() if p != 0 else 0 for p in row]
                                   for row in polys]).rank() if polys and polys[0] else 0
        return _bareiss_rank(polys)
    dM = _domain_matrix(M)
    return 0 if dM is None else len(dM.rref_den()[2])   # fraction-free: pivots of the reduced form


def _flint_polynomials(M: Mat):
    """The entries as flint fmpq_mpoly (None if an entry is not a polynomial)."""
    return _flint_rows(_symbolic_rows(M))


def _flint_rows(rows: list):
    """Rows of symengine expressions as flint fmpq_mpoly in one ring (None if one is not a polynomial)."""
    import symengine as se
    rows = [[se.expand(se.sympify(x)) for x in row] for row in rows]
    syms = sorted({y for row in rows for x in row for y in x.free_symbols}, key=str)
    ctx = flint.fmpq_mpoly_ctx.get(tuple(f"v{i}" for i in range(max(1, len(syms)))), "degrevlex")
    gens = ctx.gens()
    index = {s: i for i, s in enumerate(syms)}
    zero = ctx.from_dict({})

    def conv(x):
        if x.is_Symbol:
            return gens[index[x]]
        if x.is_Number:
            if not x.is_Rational:
                raise TypeError("not a rational number")
            q = Fraction(str(x))
            return zero + flint.fmpq(q.numerator, q.denominator)
        if x.is_Add:
            out = zero
            for a in x.args:
                out = out + conv(a)
            return out
        if x.is_Mul:
            out = zero + 1
            for a in x.args:
                out = out * conv(a)
            return out
        if x.is_Pow:
            b, e = x.args
            if not (e.is_Integer and int(e) >= 0):
                raise TypeError("not a polynomial")
            return conv(b) ** int(e)
        raise TypeError("not a polynomial")

    try:
        return [[conv(x) for x in row] for row in rows]
    except TypeError:
        return None


def _flint_rows_cleared(entries: list):
    """Rows of rational functions (symengine expressions) as flint fmpq_mpoly, each multiplied by the least
    common multiple of its denominators (None if an entry is not a rational function of the chart parameters)."""
    import symengine as se
    # each row's numerators and denominators side by side, all in one ring
    rows = [[p for x in row for p in se.sympify(x).as_numer_denom()] for row in entries]
    if not rows or not rows[0]:
        return None
    polys = _flint_rows(rows)
    if polys is None:
        return None
    out = []
    for row in polys:
        nums, dens = row[0::2], row[1::2]
        if any(d == 0 for d in dens):
            return None
        lcm = dens[0]
        for d in dens[1:]:
            lcm = lcm * d / lcm.gcd(d)      # (exact divisions)
        out.append([a * (lcm / d) for a, d in zip(nums, dens)])
    return out


def _bareiss_rank(P) -> int:
    """Rank by fraction-free Gaussian elimination (every division is exact)."""
    P = [list(row) for row in P]
    if not P or not P[0]:
        return 0
    m, k = len(P), len(P[0])
    rank, prev = 0, None
    for col in range(k):
        piv = next((i for i in range(rank, m) if P[i][col] != 0), None)
        if piv is None:
            continue
        P[rank], P[piv] = P[piv], P[rank]
        p = P[rank][col]
        for i in range(rank + 1, m):
            a = P[i][col]
            for j in range(col + 1, k):
                v = p * P[i][j] - a * P[rank][j]
                P[i][j] = v if prev is None else v / prev
            P[i][col] = P[i][col] * 0
        prev, rank = p, rank + 1
    return rank


def _domain_matrix(M: Mat):
    from sympy.polys.matrices import DomainMatrix
    rows = _sympy_rows(M)
    if not rows or not rows[0]:
        return None
    return DomainMatrix.from_list_sympy(len(rows), len(rows[0]), rows)


#: CPU seconds the explicit kernel vectors of a rank below the printed one may take: the verdict rests on
#: the function-field rank alone, the vectors only illustrate it
KERNEL_CERTIFICATE_SECONDS = 5.0


def _kernel_certificate(M: Mat, limit: int = 3) -> str:
    """Explicit kernel vectors over the function field, each checked to be annihilated by M (within
    KERNEL_CERTIFICATE_SECONDS; beyond that, the record says they were not computed)."""
    try:
        with deadline(KERNEL_CERTIFICATE_SECONDS, "the explicit kernel vectors", lambda message: ExactTimeout(message),
                      cpu=True):
            return _kernel_vectors(M, limit)
    except ExactTimeout:
        return (f"; explicit kernel vectors not computed (beyond {KERNEL_CERTIFICATE_SECONDS:.0f} s; the rank over "
                f"the function field decides)")


def _kernel_vectors(M: Mat, limit: int) -> str:
    dM = _domain_matrix(M)
    if dM is None:
        return ""
    F = dM.to_field()
    K = F.nullspace()
    vecs = K.to_Matrix().tolist() if K.shape[0] else []
    # M v = 0 for each vector, in the exact arithmetic of the matrix's field of fractions (no simplification
    # heuristics: the product's entries are elements of the field, zero or not)
    if vecs and not F.matmul(K.transpose()).is_zero_matrix:
        return ""
    shown = "; ".join("(" + ", ".join(str(x) for x in v) + ")" for v in vecs[:limit])
    more = f" and {len(vecs) - limit} more" if len(vecs) > limit else ""
    return f"; explicit kernel ({len(vecs)} vectors, each checked M v = 0): {_short(shown + more, 400)}"


def _rational_constant_matrix(M: Mat):
    """The matrix as a flint fmpq_mat when every entry is a rational number (None otherwise)."""
    rows = _symbolic_rows(M)
    out = []
    for row in rows:
        out_row = []
        for x in row:
            if not (x.is_Number and x.is_Rational):
                return None
            out_row.append(flint.fmpq(int(x.p), int(x.q)))
        out.append(out_row)
    if not out or not out[0]:
        return flint.fmpq_mat(len(out), 0)
    return flint.fmpq_mat(out)


def _constant_minor_rank(M: Mat, field: Field) -> int:
    """Elimination using only nonzero numeric pivots: the product of the pivots is a
    constant (hence everywhere nonzero) minor of the returned size."""
    import symengine as se
    rows = _symbolic_rows(M)
    rank = 0
    if not rows:
        return 0
    for col in range(len(rows[0])):
        piv = None
        for i in range(rank, len(rows)):
            x = se.expand(rows[i][col])
            if x.is_Number and x != 0:
                piv = i
                break
        if piv is None:
            continue
        rows[rank], rows[piv] = rows[piv], rows[rank]
        p = rows[rank][col]
        for i in range(len(rows)):
            if i != rank:
                f = se.expand(rows[i][col] / p)
                if f != 0:
                    rows[i] = [se.expand(a - f * b) for a, b in zip(rows[i], rows[rank])]
        rank += 1
    return rank


#: CPU seconds the symbolic function-field rank may take before the upper bound is taken at random
#: points of prime fields instead (the lower bound is always exact); CPU time, so that which route a record
#: takes does not depend on the machine's load
SYMBOLIC_RANK_SECONDS = 5.0
#: ... and where the rank at an exact point is below the printed one (the printed rank is then very likely too
#: large, and only the function-field rank refutes it with certainty): the time that refutation may take, outside
#: the mutation analysis (whose mutants are refuted by a point method already).  A rank said one too large of the
#: map ξ ↦ [ξ, XXᵀ] at (4,2) takes 15 s
REFUTING_RANK_SECONDS = 60.0


class _RandomizedRank:
    """The exact method's rank at random points when the function-field rank is out of reach:
    collects the upper bounds' false-pass probabilities for the verdict."""

    def __init__(self) -> None:
        self.bounds: list[float] = []
        #: whether a generic rank was taken at a point drawn from the run's seed (a proof all the
        #: same: the record then carries the seed, which reproduces the point)
        self.drew = False


def _point_values(M: Mat, rng: random.Random, modulus: int | None, height: int = 2**62):
    """The matrix's symbolic entries at a random integer point of its parameters, coordinates in [−height, height):
    fmpq (modulus None) or residues mod p; None when the point is a pole of an entry."""
    bound = height if modulus is None else modulus
    values_at = getattr(backend(M._field), "values_at", None)
    if values_at is not None:
        # the backend's own polynomials evaluated at the point (flint), without symengine expressions
        vals = values_at(M._n if M._n is not None else M._view(), lambda k: [rng.randrange(-bound, bound) if modulus is None else rng.randrange(modulus)
                                          for _ in range(k)])
        if vals is not NotImplemented:
            if vals is None or modulus is None:
                return vals
            out = []
            for row in vals:
                out_row = []
                for q in row:
                    num, den = int(q.p), int(q.q)
                    if den % modulus == 0:
                        return None
                    out_row.append(flint.nmod(num, modulus) / flint.nmod(den, modulus))
                out.append(out_row)
            return out
    import symengine as se
    rows = _symbolic_rows(M)
    syms = set()
    for row in rows:
        for x in row:
            syms |= se.sympify(x).free_symbols
    syms = sorted(syms, key=str)
    point = {s: rng.randrange(-bound, bound) if modulus is None else rng.randrange(modulus) for s in syms}
    out = []
    for row in rows:
        out_row = []
        for x in row:
            v = se.sympify(x).subs(point)
            if not v.is_Number or not v.is_finite:
                return None
            q = Fraction(int(v.p), int(v.q)) if hasattr(v, "p") else Fraction(str(v))
            if modulus is None:
                out_row.append(flint.fmpq(q.numerator, q.denominator))
            else:
                if q.denominator % modulus == 0:
                    return None
                out_row.append(flint.nmod(q.numerator, modulus) / flint.nmod(q.denominator, modulus))
        out.append(out_row)
    return out


#: the prime modulo which the rank of a rational matrix is taken first (:func:`rational_rank`): any prime bounds
#: the rank over Q from below; this one (2^61 − 1) keeps every residue in a machine word
RANK_PRIME = 2**61 - 1


def rational_rank(vals: list[list[Any]]) -> int:
    """The exact rank over Q of a matrix of flint rationals.  The integer matrix d·M (d the common denominator of
    the entries) has the same rank, and its rank modulo a prime is at most that: where the rank modulo
    :data:`RANK_PRIME` is already min(rows, cols) it is the rank over Q; otherwise flint's exact rank over Q
    (a prime dividing a minor lowers the rank modulo p only, never the rank over Q)."""
    Q = flint.fmpq_mat(vals)
    full = min(Q.nrows(), Q.ncols())
    if full and flint.nmod_mat(Q.numer_denom()[0], RANK_PRIME).rank() == full:
        return full
    return Q.rank()


def _rank_at_point(M: Mat, rng: random.Random, modulus: int | None = None, height: int = 2**62) -> int | None:
    for _ in range(8):
        vals = _point_values(M, rng, modulus, height)
        if vals is not None:
            if not vals or not vals[0]:
                return 0
            if modulus is None:
                return rational_rank(vals)
            return flint.nmod_mat(vals, modulus).rank()
    return None


#: the coordinates' height of the first point at which a kernel certificate's full rank is sought: the polynomials
#: of a kernel (hundreds of thousands of terms for the pencil's) are evaluated at once at small integers, and a
#: point where a minor vanishes only sends the rank to the usual point (:func:`_full_rank_at_point`)
SMALL_HEIGHT = 2**8


def _full_rank_at_point(M: Mat, rng: random.Random) -> int | None:
    """The rank of M at an exact rational point (:func:`_rank_at_point`), first at a point of small height drawn
    from M's shape alone (without drawing from ``rng``): a full rank there is the rank at every point where a
    full-size minor does not vanish, so it is returned as it is; a smaller one is the rank at that point only,
    and the rank is then taken at ``rng``'s point, as without the small point.  Of a matrix with many more rows
    than columns, the rows with the fewest terms are tried first (:func:`_cheapest_rows_rank`)."""
    full = min(M._shape())
    if full:
        small = random.Random(f"small point|{M._shape()}")
        if _cheapest_rows_rank(M, small) == full or _rank_at_point(M, small, height=SMALL_HEIGHT) == full:
            return full
    return _rank_at_point(M, rng)


def _cheapest_rows_rank(M: Mat, rng: random.Random) -> int | None:
    """The rank at a point of small height of the 2c nonzero rows of M with the fewest terms (c its columns), or
    None where M is not held by a backend that counts terms or has at most 2c rows.  Rows of M: a full rank c
    there is a nonzero c x c minor of M (the kernel certificate of the pencil at a generic t at (7, 3): 4 million
    terms, 1.7 s to evaluate at the run's point, 0.3 s on its 14 cheapest rows at the small point)."""
    rows, cols = M._shape()
    if rows <= 2 * cols:
        return None
    be = backend(M._field)
    if be is None or not hasattr(be, "row_terms"):
        return None
    held = M._n if M._n is not None else M._view()
    terms = be.row_terms(held)
    if terms is None:
        return None
    pick = sorted(sorted((i for i in range(rows) if terms[i]), key=lambda i: terms[i])[:2 * cols])
    if len(pick) < cols:
        return None
    sub = be.take(held, pick, list(range(cols))) if M._n is not None else held[pick]
    vals = be.values_at(sub, lambda k: [rng.randrange(-SMALL_HEIGHT, SMALL_HEIGHT) for _ in range(k)])
    if vals is None or vals is NotImplemented:
        return None
    return rational_rank(vals)


def _exact_rank(R: Rank, field: Field, randomized: _RandomizedRank | None = None,
                minor_degree: Callable[[], int] | None = None, key: str = "0") -> tuple[str, Any]:
    """Two-sided rank certificates.  Lower bound: the exact rank at a random integer point (a
    nonzero minor there is a nonzero polynomial).  Upper bound: full rank, or the rank over the
    function field (symbolic, within SYMBOLIC_RANK_SECONDS), or, beyond that, the rank at random
    points of prime fields with a Schwartz-Zippel bound from the degree of the next minors
    (status "randomized": the verdict is then ``checked``).  ``key``: the run's :func:`draw_key`."""
    M = R.matrix
    rng = random.Random(f"{key}|rank|{M._shape()}")
    size = min(M._shape())
    if R.expected > size:
        # no matrix of this size has a larger rank, at any point (the sampled methods say so at once; the symbolic
        # rank would spend its budget first: the s83 hidden trial's M2)
        return (f"the matrix is {M._shape()[0]}x{M._shape()[1]}: no rank exceeds its full size {size} < "
                f"{R.expected} ({_stated(R.expected)}; certain)", "certain")
    if size == 0 and R.expected == 0:
        return (f"the matrix is {M._shape()[0]}x{M._shape()[1]}, empty: rank 0 at every point "
                f"({_stated(R.expected)})", True)
    if R.generic and randomized is not None:
        randomized.drew = True
    if R.generic:
        lower = _rank_at_point(M, rng)
        if lower is not None and lower > R.expected:
            return (f"rank {lower} at an exact rational point, so rank >= {lower} over the function field "
                    f"({_stated(R.expected)})", "certain")
        if lower is not None and lower == R.expected == min(M._shape()):
            return (f"rank {lower} at an exact rational point: full rank over the function field "
                    f"({_stated(R.expected)})", True)
        note = ""
        if R.kernel is not None:
            decided, note = _kernel_rank(R, rng, lower)
            if decided is not None:
                return decided
        try:
            with deadline(SYMBOLIC_RANK_SECONDS if randomized is not None else None,
                          "the rank bound from rational relations", lambda message: ExactTimeout(message), cpu=True):
                polys = _backend_polynomials(M)
                bound = _coefficient_rank_bound(polys) if polys is not None else None
        except ExactTimeout:
            bound = None
        if bound is not None and bound[0] < R.expected:
            return (f"rank <= {bound[0]} over the function field: {bound[1]} ({_stated(R.expected)}; certain)",
                    "certain")
        if bound is not None and bound[0] == R.expected and (lower == bound[0] or bound[0] == 0):
            # two-sided: the rank at a point from below, the bound from above (a rank 0 needs no point)
            if bound[0] == 0:
                return ("the zero matrix: every entry is identically 0 in the chart (its numerator is the zero "
                        f"polynomial), so rank 0 over the function field ({_stated(0)})", True)
            return (f"{_lower_words(lower)} and rank <= {bound[0]}: {bound[1]}; two-sided ({_stated(R.expected)})",
                    True)
        seconds = SYMBOLIC_RANK_SECONDS
        if lower is not None and lower < R.expected and not _MUTATION_ANALYSIS:
            seconds = REFUTING_RANK_SECONDS
        try:
            with deadline(seconds if randomized is not None else None, "the function-field rank",
                          lambda message: ExactTimeout(message), cpu=True):
                generic = _function_field_rank(M)
        except ExactTimeout:
            generic = None
        if generic is not None:
            ok = generic == R.expected
            kernel = _kernel_certificate(M) if generic < R.expected else ""
            return (f"rank over the function field Q(chart parameters) = {generic} "
                    f"({_stated(R.expected)}); two-sided: exact rank of the generic matrix{kernel}{note}", ok)
        # the upper bound at random points of prime fields
        if lower is None or lower < R.expected:
            # a point can be special: without the function-field rank a lower rank is not certain; what random
            # points of prime fields say is evidence for the reader, not a verdict (a refutation needs a witness)
            raise ExactTimeout(f"the function-field rank exceeded {seconds:.0f} s, and the rank "
                               f"at an exact rational point, {lower}, is below {_who()}'s {R.expected}{note}"
                               + _sampled_below(M, rng, lower, R.expected, minor_degree))
        D = max(1, minor_degree() if minor_degree else 1)
        joint, pts = 1.0, 0
        while joint > POINTS_TARGET and pts < POINTS_CAP:
            p = random_prime(rng)
            rk = _rank_at_point(M, rng, p)
            if rk is None:
                continue
            if rk > R.expected:
                return (f"rank {rk} at a point of GF({p}), so rank >= {rk} over the function field "
                        f"({_stated(R.expected)})", "certain")
            joint *= min(1.0, D / p)
            pts += 1
        if joint > POINTS_TARGET:
            # the printed rank is what every point says: only the bound on a false pass is too weak to give the
            # verdict checked (a degree near the primes): not decided, never evidence against the printed rank
            raise ExactTimeout(f"the function-field rank exceeded {seconds:.0f} s, and the rank {R.expected} found "
                               f"at {pts} random points of prime fields is not a verdict: the ({R.expected + 1})-minors "
                               f"have degree <= {D}, so the false-pass bound {power_of_ten(joint)} stays above "
                               f"{power_of_ten(POINTS_TARGET)}{note}")
        randomized.bounds.append(joint)
        return (f"{_lower_words(lower, 'rank >= {lower} (exact rank at a rational point)')} and rank <= "
                f"{R.expected} with false-pass "
                f"probability <= {power_of_ten(joint)} (rank {R.expected} at {pts} random points of prime fields "
                f"p > 2^{PRIME_BITS}; the ({R.expected + 1})-minors have degree <= {D}; the symbolic function-field rank "
                f"exceeded {SYMBOLIC_RANK_SECONDS:.0f} s); {_stated(R.expected)}{note}", "ok")
    constant = _rational_constant_matrix(M)
    if constant is not None:
        # every entry a rational number: the matrix is the same at every point of the chart, and its
        # rank over Q (flint, exact) is the rank at every point of the chart (the record's reductions
        # say how the chart covers T*V), both sides at once
        rank = constant.rank() if M.shape[0] and M.shape[1] else 0
        return (f"a matrix of rational numbers ({M.shape[0]}x{M.shape[1]}, the same at every point of the chart): "
                f"exact rank {rank} over Q, so rank {rank} at every point; {_stated(R.expected)}", rank == R.expected)
    const = _constant_minor_rank(M, field)
    if const == R.expected == min(M.shape):
        return (f"a constant nonzero {const}x{const} minor: rank {const} at every point (full rank); "
                f"{_stated(R.expected)}", True)
    generic = _function_field_rank(M)
    if generic == R.expected and const < R.expected:
        raise RankNotDecided(
            f"rank {generic} over the function field ({_stated(R.expected)}), and the largest constant nonzero "
            f"minor is {const}x{const}: the rank is at least {const} at every point and {R.expected} at almost "
            f"every point; whether it drops below {R.expected} somewhere on T*V is not decided (no such point "
            f"is known).  A constant nonzero {R.expected}x{R.expected} minor would prove it; for a differential, "
            f"a RightInverse proves full rank at every point")
    ok = generic == R.expected and const == R.expected
    kernel = _kernel_certificate(M) if generic < R.expected else ""
    return (f"a constant nonzero {const}x{const} minor (rank >= {const} at every point) and rank "
            f"{generic} over the function field (rank <= {generic} at every point); {_stated(R.expected)}{kernel}", ok)


#: exact rational points at which a kernel certificate's rank bound is sought when the first point is special
KERNEL_POINTS = 3


#: the points of prime fields at which a rank below the printed one is looked at again, for the message
SAMPLED_BELOW_POINTS = 2


def _sampled_below(M: Mat, rng: random.Random, lower: int | None, expected: int,
                   minor_degree: Callable[[], int] | None) -> str:
    """For the message of a generic rank found below the printed one at an exact point, where the function-field
    rank is out of reach: the ranks at a few random points of prime fields, and the probability that a printed rank
    that were true shows so low a rank at all of them (every ``expected``-minor vanishing there; degree <= the
    (expected + 1)-minors' bound).  Evidence, not a verdict; kernel vectors are the certain refutation."""
    if lower is None:
        return ""
    ranks = [_rank_at_point(M, rng, random_prime(rng)) for _ in range(SAMPLED_BELOW_POINTS)]
    if any(k is None or k >= expected for k in ranks):
        return ""
    D = max(1, minor_degree() if minor_degree else 1)
    bound = (D / 2 ** PRIME_BITS) ** len(ranks)
    return (f"; at {len(ranks)} random points of prime fields the rank is {' and '.join(map(str, ranks))}, below "
            f"{expected} too, which a generic rank {expected} would show with probability <= {power_of_ten(bound)}: {_who()}'s "
            f"rank is very likely false, but a "
            f"refutation needs an exact witness (kernel vectors given with Rank(..., kernel=...) bound the rank "
            f"from above with certainty)")


def _kernel_rank(R: Rank, rng: random.Random, lower: int | None) -> tuple[tuple[str, Any] | None, str]:
    """The generic rank of R.matrix bounded from above by the claim's kernel certificate: M K = 0
    identically in the chart (every entry of the product is zero in the symbolic field), and rank K >= d
    at an exact rational point, so rank K >= d over the function field and rank M <= cols − d there.
    Returns (the rank's detail and status, or None when the certificate does not decide) and a note for
    the detail of the route taken instead.  A kernel is never evidence against the printed rank unless
    it proves the rank smaller: M K = 0 holds, so cols − d is a proved upper bound."""
    M, K = R.matrix, R.kernel
    cols = M._shape()[1]
    if K._shape()[0] != cols:
        return None, f"; the kernel certificate has {K._shape()[0]} rows, not {cols}: not used"
    f = M._field
    if K._field is not f:
        return None, "; the kernel certificate is not a matrix of the chart's field: not used"
    # the product of the entries as they are (whatever index spaces the claim gave the kernel, only M K = 0
    # entry by entry is relied on), in the backend's own matrices where both are held there (flint's: the rows
    # of M that are renamed copies of others under parameters K does not contain are not multiplied again,
    # PolyBackend.product_vanishes)
    be = backend(f)
    if be is not None:
        a, b = (X._n if X._n is not None else be.from_obj(X._view()) for X in (M, K))
        vanishes = (be.product_vanishes(a, b) if hasattr(be, "product_vanishes") else be.is_zero(be.matmul(a, b)))
    else:
        vanishes = all(f.is_zero(f.normalize(x)) for x in np.dot(M._view(), K._view()).flat)
    if not vanishes:
        return None, "; the kernel certificate is not one: M K is not identically 0 in the chart (not used)"
    d = _full_rank_at_point(K, rng)
    if d is None:
        return None, "; the kernel certificate's rank was not found at an exact point (poles): not used"
    upper = cols - d
    bound = (f"{d} kernel vector{'' if d == 1 else 's'} of the claim, M K = 0 identically in the chart and rank K = {d} at an exact "
             f"rational point, so rank <= {cols} − {d} = {upper} over the function field")
    if upper < R.expected:
        return (f"{bound} ({_stated(R.expected)}; certain)", "certain"), ""
    if upper > R.expected:
        return None, f"; the kernel certificate bounds the rank by {upper} only ({_stated(R.expected)})"
    tries = 0
    while (lower is None or lower < upper) and tries < KERNEL_POINTS:
        tries += 1
        again = _rank_at_point(M, rng)
        if again is not None and (lower is None or again > lower):
            lower = again
    if lower is None or lower < upper:
        return None, f"; the kernel certificate gives rank <= {upper}, and the rank at exact points stayed {lower}"
    if lower > upper:       # M K = 0 and rank K = d at points: impossible, so an internal error
        raise RuntimeError(f"rank {lower} at a point exceeds the kernel certificate's bound {upper}")
    return (f"{_lower_words(lower)} and {bound}; two-sided ({_stated(R.expected)})", True), ""


#: the lower side of a two-sided rank where the rank at a point is 0: "rank >= 0" is true of every matrix, no evidence
NO_LOWER_BOUND = "no lower bound (none is needed: no rank is below 0)"


def _lower_words(lower: int, words: str = "rank {lower} at an exact rational point (rank >= {lower} over the function "
                 "field)") -> str:
    """The lower side of a two-sided rank: the rank at an exact point, which bounds the generic rank from below;
    none where it is 0."""
    return NO_LOWER_BOUND if lower == 0 else words.format(lower=lower)


EQUIVARIANT_REDUCTION = (
    "equivariance: X = X0 = (E_1..E_r), P = (W; Z) with W skew, A generic symmetric; O(n) moves X0 to "
    "every point of V(n, r), and the residuals are covariant under (X, P, A) -> (gX, gP, gAg^T), g in O(n), "
    "because {why}")
def covariant_by_construction(spaces: tuple[str, ...]) -> str:
    """Why a claim that read no coordinates of the recorded spaces is covariant."""
    who = "the claim" if _CHECKS.get() is None else "these checks"      # (a group of checks: _run_check_groups)
    return f"{who} read no coordinates of {' or '.join('R^' + x for x in spaces)} (recorded by the engine)"
CAYLEY_REDUCTION = (
    "rational parametrization: X = first r columns of (I - S)(I + S)^{{-1}}{D}, P = XW + (I - XX^T)Z "
    "(S, W skew, Z arbitrary), A = diag(a); dense in T*V(n, r){comp}")
#: the symbolic method's Cayley chart for r < n (Scene._reduced_cayley_point)
REDUCED_CAYLEY_REDUCTION = (
    "rational parametrization: X = first r columns of (I - S)(I + S)^{-1} for S = [[S11, -K^T], [K, 0]] "
    "(S11 skew r x r, K generic (n - r) x r), i.e. X = [I - S11 - K^T K; -2K] M^{-1}, M = I + S11 + K^T K; "
    "P = XW + (I - XX^T)Z (W skew, Z = [0; Z2] with Z2 arbitrary (n - r) x r: onto the normal space "
    "{N : X^T N = 0} wherever the top r x r block X1 = (I - S11 - K^T K)M^{-1} of X is invertible, a "
    "dense open set), A = diag(a); the map (S11, K) -> X has an injective "
    "differential at 0 onto the tangent space of the irreducible V(n, r): dense in T*V(n, r)")


UNCONSTRAINED_REDUCTION = (
    "no constraint used: X, P independent generic n x r matrices (every entry a parameter), A = diag(a); the "
    "residual vanishes identically as a rational function of them, so on T*V(n, r) wherever the computation "
    "divides by nothing that vanishes there, a dense open set: at an exact point of {where} over GF(p) it met "
    "no zero divisor")

#: the leaves of a point that the unconstrained chart replaces or derives from (X, P): a graph that reads
#: another point (a second, double or complex point) goes to the charts of that point
UNCONSTRAINED_LEAVES = frozenset({"X", "P", "Phi", "Psi"})


class _UnconstrainedScene(Scene):
    """The Cayley chart's scene with its point (X, P) two independent generic n x r matrices (``free``), or the
    chart's own point of T*V (the probe); in both, every engine step is computed as for a point off T*V
    (no closed form that holds on T*V only), so that the probe makes the divisions the symbolic run makes."""

    ON_V_SHORTCUTS = False

    def __init__(self, *args: Any, free: bool = True, **kw: Any) -> None:
        super().__init__(*args, **kw)
        self._free = free

    def _point(self):
        if not self._free:
            return super()._point()
        n, r = self.n, self.r
        return self._cached("point", lambda: (self._general_params("point:X", n, r, ("n", "r")),
                                              self._general_params("point:P", n, r, ("n", "r"))))


class _UnconstrainedTimeout(ExactTimeout):
    """The unconstrained chart's own deadline expired: the Cayley chart decides."""


#: the unconstrained chart's share of the exact method's time budget (and its limit without one): a graph
#: whose powers of tr(XᵀX) the Cayley chart takes as numbers can swell there, and goes to the Cayley chart
UNCONSTRAINED_SHARE = 0.25
UNCONSTRAINED_SECONDS = 30.0


def _unconstrained_chart(claim: Claim, n: int, r: int, func: Callable, graph: Any, key: str,
                         calls: list, width: list, time_budget: float | None) -> tuple | None:
    """The unconstrained chart of a graph that reads coordinates (the Cayley chart's domain): the Cayley
    chart's scene with its point (X, P) replaced by two independent generic n x r matrices, so that no
    constraint and no inverse of the chart is computed.  An identity that holds there holds on T*V(n, r):
    every value of the scene is a rational function of X, P and of the chart's other parameters, and the
    chart's point (X(S), P(S, W, Z)) substituted into it is the claim's value on T*V, wherever no divisor of
    the computation vanishes after the substitution; one exact point of T*V per component of O(n) at which
    the same computation (:class:`_UnconstrainedScene`: no closed form of T*V) meets no zero divisor shows
    that none vanishes identically.

    Returns ((scene, reduction), evaluation) when every residual is identically 0 there; None when the chart
    does not apply (a rank or count, a claim said not to vanish, another point read), when the identity
    fails at a random point of the unconstrained space (it needs the constraints: the Cayley chart decides),
    when the probe meets a zero divisor or any exception, or when the symbolic evaluation is not 0, beyond
    the symbolic budget or past its share of the time budget.  Soundness does not rest on the pre-test at a
    random point, only on the symbolic evaluation and the probe."""
    if claim.expect == "nonzero" or "rank" in graph.ops or "count" in graph.ops:
        return None
    points = {a[1] for op, a in zip(graph.ops, graph.args) if op == "attr" and type(a[1]) is str} & POINT_LEAVES
    if not points <= UNCONSTRAINED_LEAVES:
        return None

    def vanishes(sc: Scene) -> bool:
        return not _evaluate(call_claim(func, sc), sc._field, None).nonzero

    try:
        # the pre-test: an identity that needs the constraints fails at a random point of the unconstrained space
        F = ModularField(random_prime(random.Random(f"{key}|unconstrained|prime")))
        if not vanishes(_UnconstrainedScene(n, r, F, chart="cayley", rng=random.Random(f"{key}|unconstrained"),
                                            realization=claim.realization)):
            return None
        # the probe: the same computation at a point of T*V on each component of O(n)
        for comp in ((0, 1) if r == n else (0,)):
            prng = random.Random(f"{key}|unconstrained|probe|{comp}")
            call_claim(func, _UnconstrainedScene(n, r, ModularField(random_prime(prng)), chart="cayley", rng=prng,
                                                 component=comp, realization=claim.realization, free=False))
    except Expired:
        raise
    except Exception:       # noqa: BLE001 - a zero divisor, a degenerate point, anything: the Cayley chart decides
        return None

    def build() -> tuple:
        f = SymbolicField(width[0])
        return f, _UnconstrainedScene(n, r, f, chart="cayley", realization=claim.realization)
    limit = UNCONSTRAINED_SHARE * time_budget if time_budget is not None else UNCONSTRAINED_SECONDS
    try:
        with deadline(limit, "the unconstrained chart", lambda message: _UnconstrainedTimeout(message)):
            field, scene, checks = _chart_checks((claim.id, claim.realization, "exact", n, r, "unconstrained"),
                                                 build, func, graph, calls)
    except (SymbolicBudget, CoordinateAccess, _UnconstrainedTimeout):
        return None
    width[0] = max(width[0], _ring_width(field))
    ev = _evaluate(checks, field, None)
    if ev.nonzero or ev.rank_problems or ev.count_problems:
        return None
    where = "each of the two components of T*V(n, n)" if r == n else "T*V(n, r)"
    return (scene, UNCONSTRAINED_REDUCTION.format(where=where) + scene.second_point_text()), ev


def _reads_rn(graph: Any) -> bool:
    """Whether the graph reads coordinates of ℝⁿ (an index in ℝⁿ, or one not known): what the O(n) chart's record
    watches (see :func:`call_claim`)."""
    return any(inv & {"?", "n"} for inv in coordinate_reads(graph).values())


def _equivariant_chart_unused(claim: Claim, n: int, r: int, func: Callable, graph: Any, unitary: bool) -> bool:
    """Whether the equivariant chart of the standard realization (O(n) alone) is certain not to decide the graph:
    the graph reads coordinates of ℝⁿ that :func:`call_claim` records before any evaluation, and no reviewed
    reason of equivariance can be relied on for ``func``, so the exact method would evaluate the graph there and
    drop the values for the unconstrained or the Cayley chart.  Not in the mutation analysis (whose lent charts
    and reviewed claims' mutants go their own ways), and not above EXACT_CAYLEY_MAX_N, where the record names
    every look at coordinates the evaluation made."""
    if (claim.realization or "standard") != "standard" or unitary or n > EXACT_CAYLEY_MAX_N \
            or _LOAN is not None or _MUTATION_ANALYSIS:
        return False
    if claim.reviewed and claim.equivariance and _reviewed_function(claim, func):
        return False
    return _reads_rn(graph)


def _reads_coordinates(claim: Claim, n: int, r: int, func: Callable, graph: Any = None) -> list[str]:
    """What the claim's graph visibly reads of coordinates: an entry or a block of any matrix, a matrix
    of given entries, an engine step indexed by a basis (the constraints, the coordinates of a phase
    space).  A chart that also reduces by O(r) acting on the right (A11, or B11 in the metric
    realization, diagonal) is used only for a graph that reads none: O(r) mixes the coordinates of
    R^r and of Sym(r), and what a graph reads through an engine step or an opaque space is not
    always seen by the scene's record while evaluating."""
    if graph is None:
        cons = REALIZATIONS[claim.realization]
        graph = _claim_graph(func, n, r, (cons.name, cons.build))
    g = graph
    out = g.cache.get("reads coordinates")      # a function of the graph: computed once per graph
    if out is None:
        out = [w for w in coordinate_needs(g) if not w.startswith(("a rank", "a count"))]
        if "entry" in g.ops:
            out.append("an entry or a block of a matrix")
        g.cache["reads coordinates"] = out = tuple(out)
    return list(out)


#: the graph's leaves that are (or are built from) a point of T*V, a second, complex or double point
POINT_LEAVES = frozenset({"X", "P", "Phi", "Psi", "Y", "Q", "Zc", "Zc_dot", "DX", "DY", "DXdot", "DYdot"})


def _point_free(claim: Claim, n: int, r: int, func: Callable, graph: Any = None) -> bool:
    """Whether the diagonal chart is worth trying: the claim's graph names no point of T*V among its
    leaves and takes no engine step (a step may read a point, or build matrices entrywise, which the
    evaluation finds only at its end).  Soundness does not rest on this: a point read on the diagonal
    chart raises PointRead, a coordinate read is recorded, and either sends the graph on."""
    g = graph
    if g is None:
        cons = REALIZATIONS[claim.realization]
        g = _claim_graph(func, n, r, (cons.name, cons.build))
    return not any(op == "prim" and not (type(a[0]) is Named and a[0].qualname in _CHECK_STEPS)
                   or op == "attr" and a[1] in POINT_LEAVES for op, a in zip(g.ops, g.args))


#: engine steps that check a function of the claim's graph at a value of it and return zero (their functions'
#: bodies are nodes of the graph, searched for a point like the rest): no reason to pass over the diagonal chart
_CHECK_STEPS = frozenset({"stiefelsym.brackets.gradient_check"})


def _reviewed_function(claim: Claim, func: Callable) -> bool:
    """Whether ``func`` is the claim's own function or one of its corrections as the catalog registered them: the
    functions a catalog claim's stated reason of equivariance was reviewed with (a correction added to the
    claim later, by anyone, is not one of them; a claim the catalog did not register has none)."""
    from stiefelsym.claims import reviewed_functions
    return any(func is f for f in reviewed_functions(claim))


#: the statements of a graph that are not residuals: a rank and a count hold or not, they do not vanish
NOT_RESIDUALS = {"rank": "a rank", "count": "a count"}


def nonzero_statements(claim: Claim, n: int, r: int, func: Callable | None = None) -> str:
    """Why a claim that expects its checks NOT to vanish (expect="nonzero") cannot be run: its graph holds a
    statement that is no residual (a rank, a count), which that expectation has nothing to say about (before,
    the methods decided such a claim by its residuals alone and passed over the rank or count: a wrong count
    beside a nonzero residual was `proved`).  "" when the claim expects its checks to hold, or has residuals
    only, or does not trace at (n, r) (its run says why)."""
    if claim.expect != "nonzero":
        return ""
    cons = REALIZATIONS[claim.realization or "standard"]
    try:
        ops = set(_claim_graph(func or claim.func, n, r, (cons.name, cons.build)).ops)
    except Exception:   # noqa: BLE001 - the run itself meets what does not trace
        return ""
    found = [what for op, what in NOT_RESIDUALS.items() if op in ops]
    if not found:
        return ""
    return (f"the claim expects its checks not to vanish (expect='nonzero'), and it states {' and '.join(found)}, "
            "which is no residual: refused (state the rank or count in a claim of its own, which says it holds)")


def _refused_nonzero(claim: Claim, n: int, r: int, method: str, seed: int | None, func: Callable | None) -> Result | None:
    """The ``error`` of :func:`nonzero_statements` as the method's result, or None."""
    why = nonzero_statements(claim, n, r, func)
    if not why:
        return None
    res = _base_result(claim, n, r, method, seed)
    res.verdict, res.message = "error", why
    return res


#: the largest structural degree of a residual (or rank minor) that the exact and rational methods write out: the
#: terms of a symbolic polynomial, and the digits of a rational value, grow with the degree.  Beyond it they answer
#: ``inconclusive`` at once, where they would otherwise expand until their time or memory ran out ((t/(t+1))^(2^40)
#: ran 140 s before flint failed to allocate); the modular and float methods evaluate any degree.  The catalog's
#: residuals are of degree below 10^3.
EXPANDABLE_DEGREE = 1 << 20

#: the product of the exponents of a graph's powers up to which the structural degree bound is not computed
#: before an exact or rational run: a degree beyond :data:`EXPANDABLE_DEGREE` is then reached only through
#: products, each of them written out by the method (the terms grow with it, and the run's time budget stops
#: it); a single power x^k is k products in one node.  The catalog has no power.
POWER_GATE = 1 << 8

#: the degree of the graph's products (:func:`product_degree`) up to which the structural degree bound is not computed
#: either: forty products x = x * x make u^(2^40) without a power, whose value at a rational point (one big
#: integer squared by flint, which no deadline interrupts) ran the exact method 207 s past its 120 s, and its
#: command-line child out of memory
PRODUCT_GATE = 1 << 16


def _beyond_expansion(claim: Claim, n: int, r: int, method: str, seed: int | None, func: Callable) -> Result | None:
    """An ``inconclusive`` record for a claim whose structural degree bound (:func:`degree_bound`, degree markers:
    no value is expanded) exceeds :data:`EXPANDABLE_DEGREE`; None otherwise, where the graph's powers are within
    :data:`POWER_GATE`, and where the bound is not found (the method itself then says what is wrong with the
    claim)."""
    try:
        cons = REALIZATIONS[claim.realization or "standard"]
        g = _claim_graph(func, n, r, (cons.name, cons.build))
        if power_exponents(g) <= POWER_GATE and product_degree(g) <= PRODUCT_GATE:
            return None
        bound = degree_bound(claim, n, r, func)
    except Expired:
        raise
    except Exception:   # noqa: BLE001 - a claim that does not trace or reads values: the run says why
        return None
    # a value on the way is written out as well, whether or not the residuals keep its degree (u^(2^40) in
    # (u^(2^40))^0 = 1 or in 0 * u^(2^40))
    deg, what = ((bound.numerator, "its residuals") if bound.numerator >= bound.peak else
                 (bound.peak, "a value it computes (a numerator or a denominator on the way to its residuals)"))
    if deg <= EXPANDABLE_DEGREE:
        return None
    res = _base_result(claim, n, r, method, seed)
    res.verdict = "inconclusive"
    res.message = (f"the structural degree bound of {what} is {deg}, beyond the {EXPANDABLE_DEGREE} that the "
                   f"{method} method writes out (its {'terms' if method == 'exact' else 'numbers'} grow with the "
                   f"degree); the modular method evaluates any degree")
    return res


@_quoting
def run_exact(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
              time_budget: float | None = EXACT_TIME_LIMIT) -> Result:
    func = func or claim.func
    refused = _refused_nonzero(claim, n, r, "exact", None, func)
    if refused is None:
        refused = _beyond_expansion(claim, n, r, "exact", None, func)
    if refused is not None:
        return refused
    whole = _CHECKS.get() is None
    # a graph proved by the symbolic charts in this process replays its compiled plan (a proof: no point refutes it)
    if PLANS and _LOAN is None and not _MUTATION_ANALYSIS and whole:
        plan = _PLANS.get((id(claim), id(func), n, r))
        if plan is not None and plan.claim is claim and plan.func is func and plan.state == _plan_state(claim):
            fast = plan.run(seed, time_budget)
            if fast is not None:
                return fast
    t0 = time.perf_counter()
    # a claims file's claim is evaluated at the seed's first exact rational point of T*V before any symbolic chart
    # (the Cayley chart does so for every claim, below), also where its checks are decided group by group: a false
    # statement's symbolic residual can swell far beyond the true one's (on a complex point of W(3, 2): out of
    # memory after 74 s, refuted at the point in a fraction of a second)
    early_point: Result | None = None
    early_tried = False
    if whole and not claim.reviewed:
        try:
            with time_limit(time_budget):
                cons = REALIZATIONS[claim.realization or "standard"]
                early_point = _refuting_point(claim, n, r, seed, func, _claim_graph(func, n, r, (cons.name, cons.build)))
            early_tried = True
        except ExactTimeout:
            res = _base_result(claim, n, r, "exact", None)
            res.verdict = "inconclusive"
            res.message = f"the exact rational point tried first exceeded the budget of {time_budget:.0f} s"
            res.seconds = time.perf_counter() - t0
            return res
        except Expired:
            raise
        except Exception:   # noqa: BLE001 - the claim's graph: what is wrong with it is the run's to say (below)
            early_tried = False
    if whole:
        groups = _check_groups(claim, n, r, func)
        if groups is not None:
            if early_point is not None:
                return _refuted_result(_base_result(claim, n, r, "exact", None), early_point, seed,
                                       RuntimeError("its checks are decided group by group"), t0,
                                       "the symbolic residuals of its groups of checks were not written out")
            return _run_check_groups(claim, n, r, seed, func, time_budget, *groups)
    res = _base_result(claim, n, r, "exact", None)
    if not early_tried:
        t0 = time.perf_counter()
    calls: list = []        # the charts evaluated, each (key, its program or None)
    refuted: Result | None = None     # a rational point that refuted the claim before the Cayley chart (below)
    tried_point = False               # whether that point was evaluated (a budget met later does not repeat it)
    graph: Any = None
    early = contextlib.ExitStack()    # the capped attempt after a claims file's claim was refuted at the point
    left = None if time_budget is None else max(time_budget - (time.perf_counter() - t0), 0.1)
    try:
        with time_limit(left), early:
            cons = REALIZATIONS[claim.realization or "standard"]
            graph = _claim_graph(func, n, r, (cons.name, cons.build))
            if early_tried:
                # (a claims file's claim, evaluated at the point above): a refuted claim's symbolic residual is
                # written out only within a short capped attempt
                tried_point, refuted = True, early_point
                if refuted is not None:
                    early.enter_context(_capped_refutation(time_budget, USER_REFUTED_SECONDS))
            key = draw_key(claim, n, r, seed, func, graph)
            randomized = _RandomizedRank()
            charts: list[tuple[Scene, str]] = []
            # the standard realization's chart reduces by O(r) acting on the right as well (A11
            # diagonal) when the claim's graph reads no coordinates; otherwise by O(n) alone.  The
            # metric realization's chart always reduces by O(r): a graph that reads coordinates
            # goes to the Cayley chart (below)
            visible = _reads_coordinates(claim, n, r, func, graph)
            # a graph that reads no point of T*V spends the O(n) reduction on A alone (A diagonal):
            # tried first where the graph names no point; a point read while evaluating (through an
            # engine step) or a coordinate read sends it on to the charts that fix the point
            attempts: tuple = ((True, False) if claim.realization == "standard" and not visible else (False,))
            # a graph covariant under U(r) on the right of the complex point: that point with S11 = 0
            unitary = complex_right.applies(graph, claim.realization, n, r)
            if claim.realization == "standard" and not visible and _point_free(claim, n, r, func, graph):
                attempts = ("diagonal",) + attempts
            # the variables the flint ring of an evaluation of this graph reached: the next chart's ring starts
            # that wide (the same values, without carrying its polynomials to a wider context as it grows)
            width = [0]
            unconstrained = None      # the unconstrained chart's proof, where it gives one (below)
            for right in attempts:
                if claim.realization == "metric" and visible:
                    scene, coords, missing = None, list(visible), True
                    break
                if right is False and _equivariant_chart_unused(claim, n, r, func, graph, unitary):
                    # the chart records these looks before it evaluates anything, and no reason of equivariance
                    # can be relied on: its evaluation would be dropped for the charts below (tangency at
                    # (7, 4): 10 s of the 25 s, the same products as the unconstrained chart's)
                    scene, coords, missing = None, list(visible), True
                    break
                def build(right=right) -> tuple:
                    f = SymbolicField(width[0])
                    return f, Scene(n, r, f, chart="equivariant", realization=claim.realization,
                                    right_reduction=right is True, diagonal_A=right == "diagonal",
                                    unitary_right=unitary)
                missing = False   # the equivariant chart cannot provide an object (a_i, a second point)
                try:
                    field, scene, checks = _chart_checks(
                        (claim.id, claim.realization, "exact", n, r, "equivariant", right)
                        + (("unitary",) if unitary else ()), build, func, graph, calls)
                    coords = list(scene.tracker.used)
                    width[0] = max(width[0], _ring_width(field))
                except PointRead:
                    continue      # only the diagonal chart raises it: the next chart fixes the point
                except CoordinateAccess as exc:
                    field, scene = exc.chart
                    coords = list(scene.tracker.used) or ["coordinates"]
                    missing = True
                    width[0] = max(width[0], _ring_width(field))
                except SymbolicBudget:
                    # a graph that reads nothing of R^r: where the equivariant chart's evaluation is
                    # beyond budget (a symbolic inverse of a generic symmetric A + lambda I), the
                    # right-reduced Cayley chart (A diagonal, one point per O(r)-orbit) is tried
                    # instead of giving up; it is a chart for every such graph, covariant or not
                    if not cayley_right.applies(graph, claim.realization, n, r):
                        # or the unconstrained chart, for a graph that holds without the constraints
                        unconstrained = _unconstrained_chart(claim, n, r, func, graph, key, calls, width, time_budget)
                        if unconstrained is None:
                            raise
                    scene, coords, missing = None, list(visible) or ["the equivariant chart beyond budget"], True
                    break
                if right == "diagonal" and (coords or missing):
                    continue      # the diagonal chart is used for a graph that reads no coordinates
                if not (coords or missing):
                    break
            # a stated reason is relied on only for the reviewed catalog: a user's claims file
            # cannot buy the reduction with a sentence.  It was reviewed for the claim's own function
            # and its registered corrections: a mutant (another function) reads other coordinates
            reviewed = claim.reviewed and bool(claim.equivariance)
            reason = claim.equivariance if reviewed and _reviewed_function(claim, func) else ""
            if scene is None or scene.tracker.spaces != ("n",):
                reason = reviewed = ""   # a stated reason speaks of O(n); this chart also reduces by O(r)
            if reviewed and not reason and coords and not missing and _MUTATION_ANALYSIS:
                # another function of a catalog claim whose own function reads these coordinates under
                # a reviewed reason (a mutant): the printed claim's chart is not lent to it, and in the
                # mutation analysis the Cayley chart of such a claim (ranks of Jacobians in coordinates)
                # is beyond its budget (outside it, the function goes to the Cayley chart below)
                res.verdict = "inconclusive"
                res.message = (f"the function reads {', '.join(coords)}; the reviewed reason of equivariance of "
                               f"claim {claim.id} holds for its own function and registered corrections only, "
                               "and in the mutation analysis the symbolic Cayley chart is not tried for another "
                               "function of it")
                res.seconds = time.perf_counter() - t0
                res.rerun = ""
                return res
            if not missing and (not coords or reason):
                why = (covariant_by_construction(scene.tracker.spaces) if not coords else
                       f"(the claim reads {', '.join(coords)}) {reason}")
                stated = scene.equivariant_reduction() or EQUIVARIANT_REDUCTION
                second = scene.second_point_text()
                charts.append((scene, stated.format(why=why) + second))
                evaluations = [_evaluate(checks, field, lambda R: _exact_rank(
                    R, field, randomized, lambda: degree_bound(claim, n, r, func).numerator, key))]
                if scene.second_point_read and n == r:
                    # Y on the other component of O(n): the same chart, Y times diag(-1, 1, .., 1)
                    f1 = SymbolicField(_ring_width(field))
                    sc1 = Scene(n, r, f1, chart="equivariant", realization=claim.realization,
                                right_reduction=scene.right_reduction, component=1, unitary_right=unitary)
                    ch1 = call_claim(func, sc1)
                    if list(sc1.tracker.used) != coords:
                        raise DegenerateError("the two components of the second point read different coordinates")
                    evaluations.append(_evaluate(ch1, f1, lambda R, f1=f1: _exact_rank(
                        R, f1, randomized, lambda: degree_bound(claim, n, r, func).numerator, key)))
                    charts.append((sc1, stated.format(why=why) + sc1.second_point_text()))
            else:
                # a graph that holds without the constraints: proved on the unconstrained chart (polynomial in
                # X, P), without the Cayley chart's inverse; otherwise the Cayley chart decides (a graph the
                # right-reduced Cayley chart applies to goes there: X = I at r = n, S11 = 0 below)
                if unconstrained is None and not cayley_right.applies(graph, claim.realization, n, r):
                    unconstrained = _unconstrained_chart(claim, n, r, func, graph, key, calls, width, time_budget)
                if unconstrained is not None:
                    charts.append(unconstrained[0])
                elif n > EXACT_CAYLEY_MAX_N:
                    if refuted is not None:         # (a claims file's claim, refuted at the point already)
                        return _refuted_result(res, refuted, seed, RuntimeError(
                            f"the symbolic Cayley chart is limited to n <= {EXACT_CAYLEY_MAX_N}"), t0)
                    res.verdict = "inconclusive"
                    unrelied = (" (a stated reason is relied on only for the reviewed catalog's claims and "
                                "their registered corrections)"
                                if claim.equivariance and not (claim.reviewed and _reviewed_function(claim, func))
                                else "")
                    res.message = (f"the claim reads {', '.join(coords)}, so the equivariance reduction does not "
                                   f"apply{unrelied}, and the symbolic Cayley chart is limited to "
                                   f"n <= {EXACT_CAYLEY_MAX_N}")
                    res.seconds = time.perf_counter() - t0
                    res.rerun = ""
                    return res
                evaluations = [] if unconstrained is None else [unconstrained[1]]
                # r = n: both components of O(n) for X (bit 0 of comp); with a second point (Y, Q),
                # read on the first evaluation, both for Y as well (bit 1): the four combinations
                # a graph that reads nothing of R^r: the chart reduced by O(r) on the right (S11 = 0; at
                # r = n, X = I, whose orbit under O(n) on the right is both components)
                right = cayley_right.applies(graph, claim.realization, n, r)
                comps = [] if unconstrained is not None else [0, 1] if r == n and not right else [0]
                # a residual already nonzero at an exact rational point of T*V is refuted: the symbolic
                # Cayley chart then only writes the residual out, within a capped attempt (below)
                if comps and not tried_point:
                    refuted = _refuting_point(claim, n, r, seed, func, graph)
                tried_point = tried_point or bool(comps)
                try:
                    with _capped_refutation(time_budget) if refuted is not None else contextlib.nullcontext():
                        for comp in comps:
                            f2, sc, ch = _cayley_chart(claim, n, r, func, graph, calls, width, comp, right, unitary)
                            evaluations.append(_evaluate(ch, f2, lambda R, f2=f2: _exact_rank(
                                R, f2, randomized, lambda: degree_bound(claim, n, r, func).numerator, key)))
                            if r == n and sc.second_point_read and len(comps) == 2:
                                comps += [2, 3]
                            charts.append((sc, _cayley_text(n, r, comp, right, claim.realization)
                                           + sc.second_point_text()))
                except (SymbolicBudget, _RefutedTimeout) as exc:
                    if refuted is None:
                        raise
                    return _refuted_result(res, refuted, seed, exc, t0)
    except _RefutedTimeout as exc:
        # (only where the point refuted the claim: a claims file's claim, before the symbolic charts)
        return _refuted_result(res, refuted, seed, exc, t0)
    except ExactTimeout as exc:
        if refuted is not None:
            return _refuted_result(res, refuted, seed, exc, t0)
        res.verdict = "inconclusive"
        res.message = (str(exc) if str(exc).startswith("the function-field rank") else
                       f"symbolic computation exceeded its budget of {time_budget:.0f} s")
        if not tried_point and time_budget is not None:
            after = _refuted_after_the_attempt(claim, n, r, seed, func, t0, time_budget)
            if after is not None:
                return after
        res.seconds = time.perf_counter() - t0
        return res
    except RankNotDecided as exc:
        res.verdict = "undecided"
        res.message = str(exc)
        res.seconds = time.perf_counter() - t0
        return res
    except SymbolicBudget as exc:
        if refuted is not None:
            return _refuted_result(res, refuted, seed, exc, t0)
        full = _decided_at_points(claim, n, r, seed, func, graph, exc, t0, tried_point)
        if full is not None:
            return full
        res.verdict = "inconclusive"
        res.message = (f"{exc} is beyond the symbolic method's budget (the randomized exact methods "
                       f"decide this size: --method modular, or auto)")
        res.seconds = time.perf_counter() - t0
        return res
    except MemoryError:
        if refuted is not None:
            return _refuted_result(res, refuted, seed, RuntimeError("out of memory"), t0)
        if not tried_point and time_budget is not None:
            after = _refuted_after_the_attempt(claim, n, r, seed, func, t0, time_budget)
            if after is not None:
                return after
        res.verdict = "inconclusive"
        res.message = "the symbolic computation exceeded the memory budget"
        res.seconds = time.perf_counter() - t0
        return res
    except DegenerateError as exc:
        res.verdict = "error"
        res.message = f"degenerate: {exc}"
        res.seconds = time.perf_counter() - t0
        return res
    res.seconds = time.perf_counter() - t0
    res.reductions = [d for _, d in charts]
    res.checks = [o for e in evaluations for o in e.outcomes]
    # (check, position, value, field of the value)
    nonzero = [z + (sc._field,) for (sc, _), e in zip(charts, evaluations) for z in e.nonzero]
    problems = [p for e in evaluations for p in e.rank_problems + e.count_problems]
    # the probe precedes every proof, every refutation by a rank or count, and every verdict a residual that
    # is not a finite function decides: a division by an identically zero expression leaves an infinity or
    # nan (1/0 · 0 is nan, no nonzero function; a matrix [[nan]] "has rank 1") or 0 (1/(1/0), no vanishing
    # one): the statement is undefined there, an error
    if claim.expect == "nonzero" or not nonzero or any(_not_finite(z[2]) for z in nonzero):
        why = division_probe(claim, n, r, func, seed)
        res.seconds = time.perf_counter() - t0       # the probe is part of the method's work
        if why:
            res.verdict, res.message = "error", why
            return res
    if claim.expect == "nonzero":
        if nonzero:
            res.verdict = "proved"
            res.certificate = (f"the residual is not identically zero: {nonzero[0][1]} = "
                               f"{_short(_exact_text(nonzero[0][3], nonzero[0][2], SHORT + 1))}")
        else:
            res.verdict = "fails"
            res.certificate = "the residual vanishes identically on the chart"
        return res
    if refuted is not None and not (nonzero or problems):
        # a rational point of T*V refuted the claim and the symbolic chart finds it identically 0: two evaluations
        # of one graph disagree, which no claim can cause (an engine defect): neither verdict is given
        res.verdict = "error"
        res.message = ("the claim's residual is nonzero at an exact rational point of T*V and identically 0 on the "
                       "symbolic chart: the two evaluations of its graph disagree (an engine defect; please report it)")
        return res
    if nonzero or problems:
        res.verdict = "fails"
        if nonzero:
            res.residual = f"{nonzero[0][1]} = {_short(_exact_text(nonzero[0][3], nonzero[0][2], SHORT + 1))}"
            res.certificate = "the residual is a nonzero function on the chart"
            witness = refuted.witness if refuted is not None else _rational_witness(claim, n, r, seed, func)
            if witness:
                res.witness, res.seed = witness, seed
                res.certificate += "; exact rational witness point attached"
        else:
            res.certificate = "; ".join(problems)
        return res
    res.certificate = "; ".join(o.detail for o in res.checks if o.detail) or "every residual entry is identically 0"
    if randomized.bounds:
        # every residual is identically zero and every lower bound exact; an upper bound on a rank
        # was taken at random points: randomized exact
        res.verdict = "checked"
        res.false_pass_bound = min(1.0, sum(randomized.bounds))
        res.seed = seed      # the points were drawn from the seed: the rerun line and a check need it
        return res
    res.verdict = "proved"
    if randomized.drew:
        res.seed = seed      # a rank at a point drawn from the seed: the proof holds for every seed, the point is the seed's
    if whole:
        _plan(claim, func, n, r, calls, res)
    return res


def _check_groups(claim: Claim, n: int, r: int, func: Callable) -> tuple[list[str], list[frozenset[str]]] | None:
    """(the names of the checks, the groups to prove apart) where a claim's checks are better proved in two
    groups than together: the graph reads coordinates of ℝⁿ, so the whole claim goes to the unconstrained or
    the Cayley chart, while some of its checks read none (their slice of the graph), and these go to the
    equivariant chart (which each group's own run still decides from what its evaluation reads).  A claim holds when each of its checks does, so each group is proved on the chart
    its own slice of the graph allows, with the reduction stated for it.  None: the claim is proved whole
    (one check, a claim said not to vanish, a graph that reads no coordinate or whose every check reads
    some, a stated reason of equivariance that covers the whole)."""
    if claim.expect == "nonzero" or claim.realization != "standard":
        return None

    try:
        cons = REALIZATIONS[claim.realization]
        graph = _claim_graph(func, n, r, (cons.name, cons.build))
        names = graph.output_keys()
        if names is None or len(names) < 2 or not _reads_rn(graph):
            return None
        if claim.reviewed and claim.equivariance and _reviewed_function(claim, func):
            return None
        free = graph.cache.get("checks_reading_no_rn")     # (a pass over the graph: kept with it)
        if free is None:
            free = graph.cache["checks_reading_no_rn"] = frozenset(
                k for k in names if not _reads_rn(graph.checks_slice(frozenset((k,)))))
    except Expired:
        raise
    except Exception:       # noqa: BLE001 - the claim's graph is refused: the whole run reports it
        return None
    if not free or len(free) == len(names):
        return None
    return list(names), [free, frozenset(names) - free]


#: the order in which the verdict of a claim proved in groups is taken from its groups' verdicts
_GROUP_VERDICTS = ("fails", "error", "undecided", "inconclusive", "checked", "proved")


def _run_check_groups(claim: Claim, n: int, r: int, seed: int, func: Callable, time_budget: float | None,
                      names: list[str], groups: list[frozenset[str]]) -> Result:
    """The exact method on each group of checks (:func:`_check_groups`) in turn, within the one time
    budget, and the claim's record from theirs: it fails when a group fails (the later groups are not
    run), it is proved when every group is, otherwise it has the first group's verdict in the order
    fails, error, undecided, inconclusive, checked.  Each reduction is stated with the checks it is used
    for."""
    t0 = time.perf_counter()
    subs: list[tuple[frozenset[str], Result]] = []
    if _LOAN is not None and not _LOAN.recording:
        # a mutant the rational method refuted on these lent points: the group of the check its witness
        # names first (it fails there, and the group that holds is not proved in full for nothing)
        hit = _LOAN.witnesses.get((claim.id, claim.realization, n, r, seed, id(func)))
        failing = hit[1].get("check") if hit is not None and hit[0] is func and hit[1] else None
        groups = sorted(groups, key=lambda keys: failing not in keys)
    for keys in groups:
        left = None if time_budget is None else max(time_budget - (time.perf_counter() - t0), 1e-3)
        token = _CHECKS.set((func, keys))
        try:
            sub = run_exact(claim, n, r, seed, func, left)
        finally:
            _CHECKS.reset(token)
        subs.append((keys, sub))
        if sub.verdict == "fails":
            break
    rank = {v: i for i, v in enumerate(_GROUP_VERDICTS)}
    pick = min((s for _k, s in subs), key=lambda s: rank.get(s.verdict, 0))
    res = dataclasses.replace(pick, reductions=[], checks=[])
    place = {k: i for i, k in enumerate(names)}
    for keys, sub in subs:
        which = ", ".join(repr(k) for k in sorted(keys, key=place.__getitem__))
        res.reductions += [f"for the checks {which}: {d}" for d in sub.reductions]
    res.checks = sorted((o for _k, s in subs for o in s.checks), key=lambda o: place.get(o.name, len(place)))
    unrun = [k for keys in groups[len(subs):] for k in sorted(keys, key=place.__getitem__)]
    if unrun:
        note = (f"the checks {', '.join(map(repr, unrun))} were not evaluated: the group of checks evaluated "
                "before them fails")
        res.message = "; ".join(m for m in (res.message, note) if m)
    if res.verdict in ("proved", "checked"):
        res.certificate = ("; ".join(o.detail for o in res.checks if o.detail)
                           or "every residual entry is identically 0")
        bounds = [s.false_pass_bound for _k, s in subs if s.false_pass_bound is not None]
        res.false_pass_bound = min(1.0, sum(bounds)) if bounds else None
        if any(s.seed is not None for _k, s in subs):
            res.seed = seed
    res.seconds = time.perf_counter() - t0
    return res


class _Plan:
    """How the exact method proved a claim's function at a size, for its next runs in the process: the
    one chart it evaluated (the first it tried, through that chart's straight-line program
    ``straight``, kept in :data:`_STRAIGHT` under ``skey``) and what the record says of the chart and
    of the checks.  Which chart the method takes is a function of the graph (the looks at coordinates
    its evaluation on a chart makes are the same at every run), as is the record's text; the values
    are not: :meth:`run` runs the program, and gives the verdict ``proved`` only when every
    coefficient of every entry of every check it computed at this run is 0 (any other run, and every
    other verdict, goes the whole way)."""

    __slots__ = ("claim", "func", "n", "r", "skey", "straight", "reductions", "outcomes", "certificate", "seconds",
                 "state")

    def __init__(self, claim, func, n, r, skey, straight, reductions, outcomes, certificate, seconds) -> None:
        self.claim, self.func, self.n, self.r, self.skey, self.straight = claim, func, n, r, skey, straight
        self.reductions, self.outcomes, self.certificate, self.seconds = reductions, outcomes, certificate, seconds
        #: what the whole method reads of the claim besides its function (a Claim is frozen, but
        #: object.__setattr__ still writes it): a plan made under other values is not this claim's
        self.state = _plan_state(claim)

    def run(self, seed: int, time_budget: float | None) -> Result | None:
        """The record of this run, or None where the whole method must run (the program was dropped, a
        value is not 0, the program is too slow to run without the time limit)."""
        st = self.straight
        if st is None or _STRAIGHT.get(self.skey) is not st:
            self.straight = None        # dropped from its memo: not kept alive by the plan
            return None
        if time_budget is not None and self.seconds * PLAN_RATIO > time_budget:
            return None         # the time limit of the whole method applies
        claim, n, r = self.claim, self.n, self.r
        # the function's graph at this run: the whole method compiles the function again (a graph dropped
        # from the cache of graphs is traced again, and a function that reads state changed since gives
        # another graph), so the program of the plan is this run's only while the digest is the same
        try:
            cons = REALIZATIONS[claim.realization or "standard"]
            if _claim_graph(self.func, n, r, (cons.name, cons.build)).digest() != self.skey[0]:
                return None
        except Exception:       # noqa: BLE001 - the whole method reports the refusal
            return None
        res = _base_result(claim, n, r, "exact", None)
        t0 = time.perf_counter()
        verify_engine("before an evaluation")
        if not st.all_zero(st.fn(st.inputs)):
            return None
        res.seconds = time.perf_counter() - t0
        res.reductions = list(self.reductions)
        res.checks = [CheckOutcome(name, "zero", detail) for name, detail in self.outcomes]
        why = division_probe(claim, n, r, self.func, seed)
        res.seconds = time.perf_counter() - t0
        if why:
            res.verdict, res.message = "error", why
            return res
        res.certificate = self.certificate
        res.verdict = "proved"
        return res


def _plan_state(claim: Claim) -> tuple:
    """What :func:`run_exact` reads of a claim besides its function: its realization (the graph and the
    chart), its expected verdict (a claim said not to vanish is never planned), the review of its reason
    of equivariance and its corrections (the functions the reason holds for)."""
    from stiefelsym.claims import reviewed_functions
    return (claim.id, claim.realization, claim.expect, reviewed_functions(claim), claim.equivariance,
            tuple(c.func for c in claim.corrections))


#: the plans of the exact method, per (claim, function, n, r) (see :class:`_Plan`)
_PLANS: dict[tuple, _Plan] = {}
#: whether proofs are planned (False: every run goes the whole way, as the benchmarks' previous path)
PLANS = True
#: a plan runs its program without the time limit of the method only when the program took at most
#: this fraction of the time budget when the plan was made (a straight-line program does the same
#: operations on the same inputs at every run)
PLAN_RATIO = 1000


def _plan(claim: Claim, func: Callable, n: int, r: int, calls: list, res: Result) -> None:
    """Keep a plan of a proof (:class:`_Plan`) whose only chart evaluation (``calls``) was a run of a
    straight-line program, every check's entries 0; outside the mutation analysis and the lent charts."""
    if not PLANS or _LOAN is not None or _MUTATION_ANALYSIS or len(calls) != 1 or len(res.reductions) != 1 \
            or claim.expect == "nonzero" or any(o.status != "zero" for o in res.checks):
        return
    skey, st = calls[0]
    if type(st) is not _Straight or _STRAIGHT.get(skey) is not st:
        return
    t0 = time.perf_counter()
    zero = st.all_zero(st.fn(st.inputs))
    seconds = time.perf_counter() - t0
    if not zero:
        return
    _keep(_PLANS, (id(claim), id(func), n, r),
          _Plan(claim, func, n, r, skey, st, tuple(res.reductions), tuple((o.name, o.detail) for o in res.checks),
                res.certificate, seconds))


#: the straight-line programs of the exact method (:mod:`stiefelsym.ir.straightline`): per digest of the
#: graph, realization, size and chart, a :class:`_Straight`, or the reason the graph was not compiled
_STRAIGHT: dict[tuple, Any] = {}
#: how many times the interpreter evaluated each (digest, chart) before it is compiled: a graph
#: evaluated once (a mutant of the mutation analysis) is never compiled
_STRAIGHT_SEEN: dict[tuple, int] = {}
STRAIGHT_AFTER = 1
#: at most this many graphs and charts are kept (compiled or not; the oldest goes first)
STRAIGHT_KEEP = 256
#: a program over Z[x] runs at the level of coefficients where that takes at most this many integer
#: operations per operation of the ring (:func:`stiefelsym.ir.straightline.coefficient_program`)
COEFFICIENT_OPS = 20


class _Straight:
    """A graph compiled for one chart of the exact method: the program, the chart it was compiled
    on (its own field and scene, kept: the chart has no random draw, and its coordinates are the
    program's inputs), the tags of the checks and the record of looks at coordinates that the
    evaluation of the graph on the chart made (the same at every run: a function of the graph and
    the chart), replayed into the scene's record at every run.  ``fn(inputs)`` is the program that
    runs: over the ring (its outputs the entries), or over Z at the level of coefficients
    (``entries``: where each output entry's coefficients are in its values, see
    :func:`stiefelsym.ir.straightline.coefficient_program`)."""

    __slots__ = ("fn", "field", "scene", "inputs", "outputs", "log", "ctx", "operations", "back", "zero", "ring",
                 "version", "entries", "constant_terms")

    def __init__(self, fn, field, scene, inputs, outputs, log, ctx, operations, back, coefficients=None) -> None:
        self.fn, self.field, self.scene, self.inputs, self.outputs = fn, field, scene, inputs, outputs
        self.log, self.ctx, self.operations = log, ctx, operations
        #: an output entry of the program's ring as a polynomial of the field's (None: the same ring)
        self.back = back
        self.ring = backend(field).ring
        self.zero, self.version = self.ring.zero, self.ring.version
        self.entries, self.constant_terms = None, False
        if coefficients is not None:
            prog, cin = coefficients

            def exact(c: Any) -> Any:       # a rational factor as flint's rational (an int stays an int)
                return flint.fmpq(c.numerator, c.denominator) if type(c) is Fraction else c
            self.entries = tuple(tuple(tuple((tuple((m, exact(c)) for m, c in consts),
                                              tuple((k, m, exact(c)) for k, m, c in slots)) for consts, slots in row)
                                       for row in out) for out in prog.entries)
            self.fn, self.inputs = prog.function, cin
            self.constant_terms, self.operations = prog.constant_terms, prog.operations

    def all_zero(self, values: Any) -> bool:
        """Whether every entry of every check is 0 in the program's outputs ``values`` (of ``fn``)."""
        if self.entries is not None:
            return not self.constant_terms and not any(values)
        return not any(x for m in values for row in m for x in row)

    def values(self) -> tuple:
        """The program's outputs at this run, as rows of entries of the field's ring per check."""
        values = self.fn(self.inputs)
        if self.entries is None:
            back, zero = self.back, self.zero
            return tuple(values) if back is None else \
                tuple(tuple(tuple(back(x) if x else zero for x in row) for row in m) for m in values)
        zero, from_dict = self.zero, self.ctx.from_dict
        out = []
        for m in self.entries:
            rows = []
            for row in m:
                got = []
                for consts, slots in row:
                    d = {mono: c * values[k] for k, mono, c in slots if values[k]}
                    d.update(consts)
                    got.append(from_dict(d) if d else zero)
                rows.append(tuple(got))
            out.append(tuple(rows))
        return tuple(out)

    def run(self) -> dict[str, Any]:
        """The checks, computed by the program from the chart's coordinates."""
        from stiefelsym.backends.polyfield import PolyMat, _RF
        verify_engine("before an evaluation")
        tracker = self.scene.tracker
        tracker.restart()
        tracker.replay(self.log)
        checks = {}
        field, ctx, wrap = self.field, self.ctx, Mat._wrap_native
        for (name, (m, k), tags), rows in zip(self.outputs, self.values()):
            if tags is None:        # a check that is a number: the exact backend's scalar
                x = _RF(self.ring, (rows[0][0], ()))
                x.v = self.version
                checks[name] = x
                continue
            a = np.empty((m, k), dtype=object)
            for i, row in enumerate(rows):
                for j, x in enumerate(row):
                    a[i, j] = x
            checks[name] = wrap(PolyMat(a, (), ctx), field, tags, tracker)
        return checks


def _chart_checks(key: tuple, build: Callable[[], tuple], func: Callable, graph: Any = None,
                  calls: list | None = None) -> tuple:
    """(field, scene, checks) of the claim's graph on a chart of the exact method (``key``: the claim,
    realization, method, size, chart and its variant; ``build``: the chart's field and scene).

    A graph evaluated on the same chart before is run as its straight-line program
    (:mod:`stiefelsym.ir.straightline`), compiled on the second evaluation from the graph and the
    pattern of the chart's coordinates, and shared by every claim (or mutant) with the same graph
    through the graph's digest only; the program recomputes every entry of every check at every
    run.  A graph the compiler does not handle, a chart whose coordinates are not polynomials, and
    the lent charts of the mutation analysis are evaluated by the interpreter.  A chart that cannot
    provide an object the claim reads raises its CoordinateAccess (``graph``: the claim's graph at the size,
    when the caller has it), with the chart (``chart``: the field
    and the scene).  ``calls``: a list to which the chart's key in :data:`_STRAIGHT` and the program
    that ran (None: the interpreter) are appended."""
    if _LOAN is None:
        g = graph
        if g is None:
            cons = REALIZATIONS[key[1] or "standard"]
            g = _claim_graph(func, key[3], key[4], (cons.name, cons.build))
        skey = (g.digest(), *key[1:])
        hit = _STRAIGHT.get(skey)
        if calls is not None:
            calls.append((skey, hit if type(hit) is _Straight else None))
        if type(hit) is _Straight:
            return hit.field, hit.scene, hit.run()
        if hit is None:
            seen = _STRAIGHT_SEEN.get(skey, 0)
            if seen >= STRAIGHT_AFTER:
                return _compile_straight(skey, g, build, func)
            _keep(_STRAIGHT_SEEN, skey, seen + 1)
    elif calls is not None:
        calls.append((None, None))
    field, scene = _symbolic_chart(key, build)
    try:
        return field, scene, call_claim(func, scene)
    except CoordinateAccess as exc:
        exc.chart = (field, scene)
        raise


def _compile_straight(skey: tuple, g: Any, build: Callable[[], tuple], func: Callable) -> tuple:
    """Evaluate the graph on a chart of its own by the interpreter, recording the looks at
    coordinates, and compile it for that chart (kept in :data:`_STRAIGHT`); the interpreter's checks,
    which the program must reproduce entry by entry, are this run's."""
    from stiefelsym.ir.straightline import NotCompiled, compile_graph
    field, scene = build()
    tracker = scene.tracker
    tracker._log = []
    try:
        checks = call_claim(func, scene)
    except CoordinateAccess as exc:
        _keep(_STRAIGHT, skey, "the chart cannot provide an object the claim reads")
        exc.chart = (field, scene)
        raise
    finally:
        log, tracker._log = tuple(tracker._log or ()), None
    try:
        _keep(_STRAIGHT, skey, _straight(g, field, scene, checks, log, compile_graph))
    except NotCompiled as exc:
        _keep(_STRAIGHT, skey, str(exc))
    return field, scene, checks


def _keep(memo: dict, key: tuple, value: Any) -> None:
    """memo[key] = value, the oldest entry dropped beyond STRAIGHT_KEEP entries."""
    memo[key] = value
    if len(memo) > STRAIGHT_KEEP:
        del memo[next(iter(memo))]


def _straight(g: Any, field: Any, scene: Any, checks: dict, log: tuple, compile_graph: Callable) -> _Straight:
    """The compiled program of the graph on the chart of ``scene`` (see :func:`_compile_straight`)."""
    from stiefelsym.ir.straightline import Leaf, NotCompiled, coefficient_program
    from stiefelsym.backends.polyfield import PolyBackend, PolyMat, NotRational, _RF
    be = backend(field)
    if type(be) is not PolyBackend:
        raise NotCompiled("a field without the polynomial backend")
    R = be.ring
    coords: dict[int, list] = {}

    def entries(v: Any) -> tuple[list, bool]:
        if isinstance(v, Mat):
            s = v._nat()
            if type(s) is not PolyMat or s.den:
                raise NotCompiled("a matrix of the chart that is not polynomial")
            return be._fix(s).a.tolist(), False
        if isinstance(v, bool) or not isinstance(v, (int, _se_basic())):
            raise NotCompiled(f"a number of the chart of type {type(v).__name__}")
        try:
            num, den = R.from_se(v)
        except NotRational:
            raise NotCompiled("a number of the chart that is not a rational function") from None
        if den:
            raise NotCompiled("a number of the chart that is not a polynomial")
        return [[num]], True

    keys: dict[Any, Any] = {}

    def pattern(x: Any) -> Any:
        """An entry of the chart as the compiler's pattern: an integer constant, or (sign, key) with one
        key for the entries equal up to sign."""
        c = _constant(x)
        if c is not None:
            return c
        text = str(x)       # the ring's canonical text of the polynomial (polynomials do not hash)
        k = keys.get(text)
        if k is not None:
            return (1, k)
        k = keys.get(str(-x))
        if k is not None:
            return (-1, k)
        k = keys[text] = len(keys)
        return (1, k)

    def leaf(i: int, name: Any) -> Leaf:
        v = getattr(scene, name) if type(name) is str else getattr(scene, name[0])(*name[1])
        rows, scalar = entries(v)
        if i >= 0:
            coords[i] = rows
        return Leaf([[pattern(x) for x in row] for row in rows], scalar)

    from stiefelsym.ir.derivative import derivatives as _derived
    h = _derived(g, scene_flows(scene))
    if type(scene)._tangent_vector is not Scene._tangent_vector and "prim" in h.ops:
        raise NotCompiled("a scene whose tangent vectors are its own")
    prog = compile_graph(h, leaf, lambda d: getattr(scene, d))
    inputs = [coords[i][a][b] for i, a, b in prog.inputs]
    if any(x.context() is not R.ctx for x in inputs):
        raise NotCompiled("coordinates of the chart in another context of the ring")
    back = None
    terms = None        # the terms of the inputs where their coefficients are integers
    if not prog.constants and all(c.q == 1 for x in inputs for c in x.to_dict().values()):
        # a chart of integer polynomials: the program runs over Z[x] (flint's integer polynomials
        # skip the rational content of every operation) and its outputs come back to Q[x] exactly
        zctx, zero = _integer_ring(R.ctx)
        inputs = [zctx.from_dict({e: int(c.p) for e, c in x.to_dict().items()}) for x in inputs]
        terms = [[(m, int(c)) for m, c in x.to_dict().items()] for x in inputs]
        fn = prog.function(zero)
        qzero, from_dict = R.zero, R.ctx.from_dict
        back = lambda x: from_dict(x.to_dict()) if x else qzero  # noqa: E731
        got = [[[back(x) for x in row] for row in m] for m in fn(inputs)]
    else:
        fn = prog.function(R.zero, flint.fmpq)
        got = fn(inputs)
        if all(c.q == 1 for x in inputs for c in x.to_dict().values()):
            # integer coordinates, rational constants of the program: at the level of coefficients too
            terms = [[(m, int(c.p)) for m, c in x.to_dict().items()] for x in inputs]
    outputs = []
    if list(prog.outputs) != list(checks):
        raise NotCompiled("the program's checks are not the interpreter's")
    for (name, shape), rows in zip(prog.outputs.items(), got):
        want = checks[name]
        if name in prog.scalars:
            rf = want.rf() if type(want) is _RF and want.R is R else None
            if rf is None or rf[1] or rf[0].context() is not R.ctx:
                raise NotCompiled("a check that is a number but not a polynomial of the chart's ring")
            if rows[0][0] != rf[0]:
                raise NotCompiled("the program disagrees with the interpreter (a defect of the compiler)")
            outputs.append((name, shape, None))
            continue
        if not isinstance(want, Mat):
            raise NotCompiled("a check that is not a matrix")
        s = want._nat()
        if type(s) is not PolyMat or s.den or s.a.shape != shape:
            raise NotCompiled("a check that is not a polynomial matrix")
        s = be._fix(s)
        if any(x != y for row, wrow in zip(rows, s.a.tolist()) for x, y in zip(row, wrow)):
            raise NotCompiled("the program disagrees with the interpreter (a defect of the compiler)")
        outputs.append((name, shape, want.tags))
    st = _Straight(fn, field, scene, inputs, outputs, log, R.ctx, prog.operations, back)
    if terms is not None:
        # with integer coordinates, the same program at the level of coefficients where it takes at most
        # COEFFICIENT_OPS integer operations per operation of the ring (a call of the polynomial
        # library costs about as much as that many integer operations); its values must be the
        # ring program's (the interpreter's) entry by entry, or the graph stays with the interpreter
        try:
            cp = coefficient_program(prog, terms, R.ctx.nvars(), COEFFICIENT_OPS * max(prog.operations, 1))
        except NotCompiled:
            return st
        cst = _Straight(fn, field, scene, inputs, outputs, log, R.ctx, prog.operations, back,
                        (cp, [c for tt in terms for _, c in tt]))
        if [[list(row) for row in m] for m in cst.values()] != [[list(row) for row in m] for m in got]:
            raise NotCompiled("the coefficient program disagrees with the interpreter (a defect of the compiler)")
        return cst
    return st


def _integer_ring(ctx: Any) -> tuple:
    """flint's integer polynomials in the variables of a context of rational ones, and their 0."""
    zctx = flint.fmpz_mpoly_ctx.get(tuple(str(x) for x in ctx.gens()), "degrevlex")
    return zctx, zctx.from_dict({})


def _constant(x: Any) -> int | None:
    """An entry of the chart as the compiler's pattern: an integer constant, or None (an input)."""
    if not x:
        return 0
    if x.is_constant():
        c = x.leading_coefficient()
        if c.q == 1:
            return int(c.p)
    return None


def _ring_width(field: Any) -> int:
    """The variables the flint ring of a chart's field holds (0 for another field, or before its ring is used)."""
    f = getattr(field, "ring_width", None)
    return f() if f is not None else 0


def _symbolic_chart(key: tuple, build: Callable[[], tuple]) -> tuple:
    """``build()``'s (field, scene) of a chart of the symbolic method; in the mutation analysis, the
    chart of the claim as printed with its node values, lent (:meth:`PointLoan.chart`)."""
    if _LOAN is None:
        return build()
    return _LOAN.chart(key, build)


def _cayley_chart(claim: Claim, n: int, r: int, func: Callable, graph: Any, calls: list, width: list, comp: int,
                  right: bool, unitary: bool) -> tuple:
    """The claim's checks on the symbolic Cayley chart (component ``comp`` of O(n) at r = n; reduced by O(r) on the
    right where ``right``): (field, scene, checks); ``width`` (the widest ring met so far) is updated."""
    def build() -> tuple:
        f = SymbolicField(width[0])
        return f, Scene(n, r, f, chart="cayley", component=comp, realization=claim.realization,
                        cayley_right=right, unitary_right=unitary)
    f2, sc, ch = _chart_checks((claim.id, claim.realization, "exact", n, r, "cayley", comp)
                               + (("right",) if right else ()) + (("unitary",) if unitary else ()),
                               build, func, graph, calls)
    width[0] = max(width[0], _ring_width(f2))
    return f2, sc, ch


def _cayley_text(n: int, r: int, comp: int, right: bool, realization: str = "standard") -> str:
    """The reduction the Cayley chart of component ``comp`` states."""
    if right:
        return cayley_right.reduction(n, r)
    if r < n:
        return in_realization(REDUCED_CAYLEY_REDUCTION, realization)
    return in_realization(CAYLEY_REDUCTION.format(D=" D", comp=f"; component {comp % 2 + 1} of O(n) (D = "
                                                                f"{'I' if comp % 2 == 0 else 'diag(-1,1,..,1)'})"),
                          realization)


def in_realization(text: str, realization: str) -> str:
    """A Cayley chart's words for the claim's realization of T*V: in the metric one the covector of the chart is A
    times the standard one (:meth:`stiefelsym.scene.Scene._cayley_point`), so that XᵀA⁻¹P is skew."""
    if realization != "metric":
        return text
    return (text.replace("P = XW + (I - XX^T)Z", "P = A(XW + (I - XX^T)Z)", 1)
            .replace("dense in T*V(n, r)", "dense in T*V(n, r) = {X^T X = I, X^T A^{-1} P + P^T A^{-1} X = 0} "
                     "(the metric realization)", 1))


#: where a rational point has refuted a claim already, the symbolic Cayley chart that writes its residual out
#: stops at a product (or inverse step) of more than this many term products, the same step on every machine
#: (the mutation analysis's cap for its mutants; the largest step of a catalog run that finishes takes 1.3·10⁷),
#: or at REFUTED_SHARE of the time budget
REFUTED_TERM_PRODUCTS = 3 * 10 ** 7
REFUTED_SHARE = 0.25


class _RefutedTimeout(Exception):
    """The capped symbolic attempt after a refutation at a rational point ran out of its share of the time."""


#: seconds of the capped symbolic attempt after a claims file's claim was refuted at the point (at most)
USER_REFUTED_SECONDS = 5.0


@contextmanager
def _capped_refutation(time_budget: float | None, most: float | None = None) -> Iterator[None]:
    from stiefelsym.backends.polyfield import term_cap, _TERM_CAP as current
    limit = REFUTED_TERM_PRODUCTS if current is None else min(current, REFUTED_TERM_PRODUCTS)
    seconds = REFUTED_SHARE * time_budget if time_budget is not None else UNCONSTRAINED_SECONDS
    if most is not None:
        seconds = min(seconds, most)
    with term_cap(limit), deadline(seconds, "the symbolic residual of a refuted claim",
                                   lambda message: _RefutedTimeout(message)):
        yield


def _refuting_point(claim: Claim, n: int, r: int, seed: int, func: Callable, graph: Any) -> Result | None:
    """A one-point rational run (the seed's first rational point of T*V) that refutes the claim's residuals, or
    None: a claim said not to vanish, a rank or a count (a point bounds those from one side only), a run that
    does not fail with a witness.  A residual entry that is a nonzero rational number at an exact point of T*V
    where the claim's computation divides by nothing that vanishes refutes the identity for certain (the exact
    method's ``fails`` needs a witness of that kind, not the symbolic residual); the symbolic Cayley chart of a
    false claim can swell far beyond that of the true one (a determinant identity with a sign wrong: 0.07 s
    proved, over 120 s and out of memory refuted)."""
    if claim.expect == "nonzero" or "rank" in graph.ops or "count" in graph.ops:
        return None
    try:
        if _LOAN is not None and not _LOAN.recording:
            witness = _rational_witness(claim, n, r, seed, func)
            if not witness:
                return None
            point = _base_result(claim, n, r, "rational", seed)
            point.verdict, point.witness = "fails", witness
            return point
        point = run_points(claim, n, r, "rational", seed, func, trials=1)
    except Expired:
        raise
    except Exception:       # noqa: BLE001 - a degenerate point, anything: the symbolic chart decides as before
        return None
    return point if point.verdict == "fails" and point.witness else None


def _decided_at_points(claim: Claim, n: int, r: int, seed: int, func: Callable, graph: Any, why: Exception,
                       t0: float, tried_point: bool = False) -> Result | None:
    """Where a symbolic chart is beyond budget, what exact points of T*V still decide for certain.  A claim whose
    every check is a generic rank equal to its matrix's full size is proved: a nonzero maximal minor at an exact
    rational point (on each component of O(n) at r = n) is a nonzero rational function, and no rank exceeds the
    full size (the rational method's proof, run here).  A claim the rational method refutes for certain (a rank
    above the printed one or above the full size, a nonzero residual at an exact point) fails.  None for any other
    outcome (the budget's verdict stands).  ``tried_point``: the rational point was evaluated before the Cayley
    chart already and did not refute the claim (it is not evaluated again)."""
    if graph is None or claim.expect == "nonzero":
        return None
    try:
        if "rank" not in graph.ops and "count" not in graph.ops:
            point = None if tried_point else _refuting_point(claim, n, r, seed, func, graph)
            if point is None:
                return None
            res = _base_result(claim, n, r, "exact", seed)
            return _refuted_result(res, point, seed, why, t0, "the symbolic chart is beyond budget")
        point = run_points(claim, n, r, "rational", seed, func)
    except Expired:
        raise
    except Exception:       # noqa: BLE001 - the symbolic budget's verdict stands
        return None
    if point.verdict not in ("proved", "fails"):
        return None      # a rank below the printed one at a point (a special point?), a bound too weak: as before
    point.method = "exact"
    point.reductions = [f"exact rational points of T*V drawn from the seed (the rational method's points; the "
                        f"symbolic chart is beyond budget: {why})"] + list(point.reductions or [])
    point.seconds = time.perf_counter() - t0
    return point


def _refuted_result(res: Result, point: Result, seed: int, why: Exception, t0: float,
                    what: str = "the residual as a function on the symbolic chart was not written out") -> Result:
    """The exact method's ``fails`` from a refuting rational point, where the symbolic residual is beyond its
    capped attempt (or a symbolic chart beyond budget)."""
    res.verdict = "fails"
    res.witness, res.seed = point.witness, seed
    res.residual = point.residual
    res.reductions = ["an exact rational point of T*V drawn from the seed (the rational method's first point: "
                      "the Cayley chart at rational parameters)"]
    res.certificate = (f"a residual entry is a nonzero rational number at an exact point of T*V (the witness); "
                       f"{what} ({why})")
    res.seconds = time.perf_counter() - t0
    return res


def _rational_witness(claim: Claim, n: int, r: int, seed: int, func: Callable) -> dict | None:
    """The witness of a one-point rational run (``run_points(..., trials=1)``), for the exact method's
    refutations.  On lent points (the mutation analysis) the rational run of the same function at
    the same size has evaluated those very points, each a copy of the same snapshot, and kept what
    they gave (:attr:`PointLoan.witnesses`): taken from there, not computed twice."""
    if _LOAN is not None and not _LOAN.recording:
        hit = _LOAN.witnesses.get((claim.id, claim.realization, n, r, seed, id(func)))
        if hit is not None and hit[0] is func:
            return hit[1]
    return run_points(claim, n, r, "rational", seed, func, trials=1).witness


#: the probe's points, each over its own prime drawn from the run's :func:`draw_key` (a divisor that is not
#: identically zero vanishes at a random point modulo all of them with negligible probability; drawn, not
#: fixed, so that no claim can be written with a divisor that is a nonzero multiple of the probe's primes)
PROBE_POINTS = 3


def _digest_now(claim: Claim, n: int, r: int, func: Callable) -> str | None:
    """The digest of the graph ``func`` has at (n, r) at this call (None: it is refused; the caller's
    run reports it).  What is memoized per function is memoized per graph as well: the cache of graphs
    keeps a few dozen, and a function traced again may read state that changed since."""
    try:
        cons = REALIZATIONS[claim.realization or "standard"]
        return _claim_graph(func, n, r, (cons.name, cons.build)).digest()
    except Expired:
        raise
    except Exception:       # noqa: BLE001 - the claim's graph is refused: the run reports it
        return None


#: the outcome of the division probe per claim function and (claim, realization, size, seed, strict):
#: a pure function of these (its points come from the seed and the claim's graph: draw_key), so it
#: runs once per claim function, like the cached degree bound of the randomized methods
_PROBES: "weakref.WeakKeyDictionary[Callable, dict]" = weakref.WeakKeyDictionary()


def division_probe(claim: Claim, n: int, r: int, func: Callable | None = None, seed: int = 0,
                   strict: bool = False) -> str:
    """The division probe of the claim at (n, r) (see :func:`_division_probe`), memoized."""
    func = func or claim.func
    # the graph's digest too: a function whose graph left the cache of graphs is traced again, and a
    # function that reads state changed since has another graph (and maybe another divisor)
    key = (claim.id, claim.realization, n, r, seed, strict, _digest_now(claim, n, r, func))
    try:
        memo = _PROBES.setdefault(func, {})
    except TypeError:   # a callable without weak references: no memo
        memo = {}
    why = memo.get(key)
    if why is None:
        why = memo[key] = _division_probe(claim, n, r, func, seed, strict)
    return why


def _division_probe(claim: Claim, n: int, r: int, func: Callable | None = None, seed: int = 0,
                    strict: bool = False) -> str:
    """"" when the claim evaluates at a random point of T*V (over a prime field) without dividing by zero;
    otherwise the reason.

    Symbolic arithmetic does not raise on a division by an identically zero expression: it makes
    an infinity that a later division turns into 0.  So every symbolic proof is preceded by this
    probe; a division by zero at each of three random points means a divisor that vanishes
    identically (or at a pole the claim put itself on).  Any other exception is the symbolic
    run's to report (it meets the same code), except with ``strict`` (a caller that does not run
    the claim at this size itself, such as the dimension-free method): then the probe did not
    take place, and that is the reason."""
    func = func or claim.func
    last: BaseException | None = None
    try:
        key = draw_key(claim, n, r, seed, func)
    except Expired:
        raise
    except Exception as exc:   # noqa: BLE001 - the claim's graph is refused: the symbolic run reports it
        if strict:
            return (f"the division probe could not trace the claim at (n={n}, r={r}) ({type(exc).__name__}: "
                    f"{exc}), so a division by an identically zero expression cannot be excluded")
        return ""
    for attempt in range(PROBE_POINTS):
        p = random_prime(random.Random(f"{key}|division-probe|prime|{attempt}"))
        rng = random.Random(f"{key}|division-probe|{attempt}")
        scene = Scene(n, r, ModularField(p), chart="cayley", rng=rng, component=attempt % 2 if r == n else 0,
                      realization=claim.realization)
        try:
            call_claim(func, scene)
            return ""
        except (DegenerateError, ZeroDivisionError) as exc:
            last = exc
        except Expired:
            raise       # stopped, not evaluated: no answer (the probe's answers are memoized)
        except Exception as exc:   # noqa: BLE001 - anything else is the symbolic run's to report
            if strict:
                return (f"the division probe could not evaluate the claim at a point of T*V(n={n}, r={r}) "
                        f"over GF(p) ({type(exc).__name__}: {exc}), so a division by an identically zero "
                        "expression cannot be excluded")
            return ""
    return (f"the claim divides by zero at every one of 3 random points of T*V(n={n}, r={r}) over GF(p) "
            f"({type(last).__name__}: {last}): a divisor that vanishes identically, so a symbolic "
            "'proof' would only have divided by zero")


def _not_finite(x: Any) -> bool:
    """Whether a symbolic residual entry holds an infinity or nan (symengine's value of a division by an
    identically zero expression; the flint types raise instead)."""
    has = getattr(x, "has", None)
    if has is None:
        return False
    import symengine as se
    try:
        return bool(has(se.nan) or has(se.zoo) or has(se.oo))
    except Exception:   # noqa: BLE001 - not a symengine expression
        return False


#: the characters of a residual's text a result keeps (:func:`_short`)
SHORT = 160


def _short(x: Any, limit: int = SHORT) -> str:
    s = str(x)
    return s if len(s) <= limit else s[: limit - 3] + "..."


def _exact_text(field: Any, x: Any, width: int | None = None) -> str:
    """An exact residual entry as text, the same in every run: through the flint ring in its
    canonical term order where the entry is a rational function there (a symengine expression
    orders its terms by hashes that differ between processes), else symengine's text.  ``width``: only
    its first characters are wanted (a prefix of the text, of at least that many characters, in the
    ring: the terms of a refuted residual that are not printed are not ordered)."""
    ring = field.poly_ring() if getattr(field, "native", False) and hasattr(field, "poly_ring") else None
    if ring is not None:
        from stiefelsym.backends.polyfield import _RF, NotRational
        if type(x) is _RF:
            if x.R is ring:
                return ring.text(x.rf(), width)
            x = x.to_se()          # a scalar of another chart's ring: through its expression
        try:
            return ring.text(ring.from_se(x), width, reduced=True)
        except NotRational:
            pass
    return str(x)


# ---------------------------------------------------------------------------
# degree and height bounds (for Schwartz-Zippel and the choice of primes)

@dataclass
class DegreeBound:
    numerator: int          # max numerator degree over residual entries / rank minors
    denominator: int        # total degree of all denominators met (for resampling)
    height: float = 0.0     # max log2 of the L1 norm of an integer numerator polynomial (entries, minors)
    constant_bits: float = 0.0   # sum of log2|a| + log2 b over the constants a/b of the claim
    peak: int = 0           # max degree of a numerator or denominator of any value computed, residual or not


#: degree bounds computed in this process, per (claim, function, size): a claim's bound is
#: computed once however many methods, points or components use it
_DEGREE_CACHE: dict[tuple, DegreeBound] = {}


def degree_bound(claim: Claim, n: int, r: int, func: Callable | None = None) -> DegreeBound:
    """Bounds on the degree and height of the numerators of a claim's residuals at size (n, r),
    from the structure of its expressions: the claim runs once over degree markers, one marker
    per matrix (see :class:`~stiefelsym.backends.native.DegreeBackend`); cached."""
    from stiefelsym.backends import native
    key = (claim.id, func or claim.func, claim.realization, n, r, native.ENABLED,
           _digest_now(claim, n, r, func or claim.func))
    if key not in _DEGREE_CACHE:
        _DEGREE_CACHE[key] = _degree_bound(claim, n, r, func)
    return _DEGREE_CACHE[key]


def _degree_bound(claim: Claim, n: int, r: int, func: Callable | None = None) -> DegreeBound:
    field = DegreeField()
    # with a generator the scene draws its parameter matrices as blocks, one marker each (the
    # markers ignore the draws): O(1) per parameter matrix instead of one marker per entry
    scene = Scene(n, r, field, chart="cayley", realization=claim.realization, rng=random.Random(0))
    checks = call_claim(func or claim.func, scene)
    one = lambda v: v._n.d if isinstance(v, Mat) and type(v._n) is DegMat and all(v._shape()) else None
    return _read_bound(checks, field, field._lift, one)


def _paired_bound(checks: dict[str, Any], field: PairField) -> DegreeBound:
    """The degree and height bounds of what one sampled evaluation computed: the markers its
    numbers carried (see :mod:`.paired`), read as a structural pass is read."""
    return _read_bound(checks, field.degrees, field.marker, lambda v: marker_of(v, field))


def _read_bound(checks: dict[str, Any], deg: DegreeField, marker: Callable, matrix_marker: Callable) -> DegreeBound:
    """Degree and height bounds of a claim's residuals and rank minors from their markers:
    ``marker`` gives an entry's, ``matrix_marker`` the one marker bounding every entry of a matrix
    held natively (or None: its entries are read)."""
    num, height = 0, 0.0
    for name, value in checks.items():
        if isinstance(value, Count):
            continue
        if isinstance(value, Rank):
            d, h = _rank_minor_bound(value, deg, marker)
            num, height = max(num, d), max(height, h)
            continue
        one = matrix_marker(value)
        markers = [one] if one is not None else [marker(x) for _pos, x in _entries(value, name)]
        for x in markers:
            if not x.zero:
                num, height = max(num, x.num), max(height, x.h)
    return DegreeBound(num, sum(deg.factor_degree.values()), height, deg.constant_bits, deg.peak)


def _rank_minor_bound(R: Rank, field: DegreeField, marker: Callable) -> tuple[int, float]:
    """Degree and height bounds of the (k+1)-minors of the matrix, k the printed rank: a sampled
    rank k is the generic rank unless such a minor, a nonzero polynomial, vanishes at the point."""
    rows = [[marker(x) for x in row] for row in R.matrix._a.tolist()]
    if not rows or not rows[0] or R.expected + 1 > min(len(rows), len(rows[0])):
        return 0, 0.0      # no (k+1)-minor: rank <= k holds everywhere
    _common, cleared = field.cleared(rows)
    return field.minor_bound(cleared, R.expected + 1)


# ---------------------------------------------------------------------------
# randomized exact methods

POINTS_TARGET = 1e-30     # `checked` needs a false-pass probability at most this
class PointLoan:
    """The points of a claim as printed, lent to its mutants (the mutation analysis only).

    While :attr:`recording`, every scene a point method builds (the baseline's) is kept, keyed by
    everything that chose it: the claim, the method, the size, the seed, the point's number, the
    attempt and the prime.  Afterwards a run that asks for the same point gets a copy of that scene
    in the state the baseline left it (its parameters, its built objects), with the node values of
    the baseline's graph keyed by the structure of their subgraphs (:func:`.ir.evaluate.node_keys`):
    a mutant's graph recomputes only the nodes its change reaches.  Parameters the baseline did not
    draw come from a copy of its generator: the point is as random as a fresh one, and the same
    whatever other mutants ran before (each copy starts from the same snapshot).  Hard cases and
    the exact method never borrow."""

    def __init__(self, exact_seconds: float | None = None) -> None:
        self.recording = False
        self._points: dict[tuple, list] = {}
        #: the symbolic method's time budget per run while lending (None: its own, EXACT_TIME_LIMIT)
        self.exact_seconds = exact_seconds
        #: the most term products of one symbolic product in the symbolic run under way while lending (None: no
        #: cap; :class:`stiefelsym.backends.polyfield.term_cap`), set by the mutation analysis per run
        self.term_products: int | None = None
        #: (claim, realization, n, r, seed, id of the function) -> (function, witness): the witness of
        #: the first point (of each component) of a rational run on lent points, which is what the
        #: exact method's one-point rational run for its witness computes, on the same lent points
        #: (see :func:`_rational_witness`)
        self.witnesses: dict[tuple, tuple] = {}
        #: (claim, n, r) -> seconds of the symbolic run of the claim as printed there: its mutants' symbolic runs
        #: are forked (killable) where it took MUTANT_ISOLATE_SECONDS or more (see :func:`isolates`)
        self.exact_cost: dict[tuple, float] = {}
        #: (claim, realization, n, r, seed, id of the function) -> (function, evaluations): the checks of
        #: a run no parameter entered, evaluated over Q (the same for its rational and modular runs, see
        #: :func:`_constant_evaluations`)
        self.constants: dict[tuple, tuple] = {}

    def scene(self, key: tuple, build: Callable[[], tuple]) -> tuple:
        """``build()``'s (fields..., scene) for this key: built and kept while recording, lent (a copy
        of the kept scene's state when its run was over) otherwise."""
        hit = self._points.get(key)
        if hit is not None and not self.recording:
            if hit[-1] is None:
                # the first loan: the state in which the baseline's run left the scene and its
                # fields, taken once (later runs may reach the kept scene through its objects)
                hit[-1] = (hit[-3]._lent(), [(f, _field_state(f)) for f in hit[:-3]])
            snapshot, states = hit[-1]
            for f, state in states:
                _restore_field(f, state)      # what the fields counted so far: the baseline's only
            lent = snapshot._lent()
            lent._node_memo = dict(hit[-2])
            return (*hit[:-3], lent)
        out = build()
        if self.recording:
            memo: dict = {}
            out[-1]._node_memo = memo
            self._points[key] = [*out, memo, None]
        return out

    def chart(self, key: tuple, build: Callable[[], tuple]) -> tuple:
        """``build()``'s (field, scene) for the symbolic method: built and kept while recording, lent
        otherwise (a scene of the same chart over the same field, with the same symbols).

        The chart has no random draw, so the printed claim's node values are the values of the same
        subgraphs in a mutant's graph.  A lent scene builds its objects again from the shared symbols
        (a build records its own looks at coordinates) and records its looks at coordinates in the
        kept scene's record, emptied first: the matrices of earlier evaluations (the shared node
        values) record into that very object, and a shared value records again what its computation
        recorded (:meth:`.ir.evaluate.Evaluator.run`).  So the lent scene's record, from which the
        method decides its chart, is that of a run on a scene of its own."""
        hit = self._points.get(key)
        if hit is not None and not self.recording:
            field, scene, memo, snapshot = hit
            if snapshot is None:
                snapshot = hit[-1] = scene._lent()     # the symbols the printed claim's run drew
            lent = snapshot._lent()
            lent._cache = {}
            lent._tracker = scene._tracker
            lent._tracker.restart()
            lent._node_memo = dict(memo)
            return field, lent
        out = build()
        if self.recording:
            memo = {}
            out[-1]._node_memo = memo
            self._points[key] = [*out, memo, None]
        return out


    def forget(self, claim_id: str) -> None:
        """Drop the points kept for one claim (its mutants are done)."""
        for key in [k for k in self._points if k[0] == claim_id]:
            del self._points[key]
        for key in [k for k in self.witnesses if k[0] == claim_id]:
            del self.witnesses[key]
        for key in [k for k in self.constants if k[0] == claim_id]:
            del self.constants[key]
        for key in [k for k in self.exact_cost if k[0] == claim_id]:
            del self.exact_cost[key]


def _field_state(f: Any) -> tuple | None:
    """The mutable record of a field (a paired field's degree markers: the denominators and constants
    met, and the constants it made), copied; None for a field that keeps none."""
    record = getattr(f, "record", None)
    return record() if record is not None else None


def _restore_field(f: Any, state: tuple | None) -> None:
    if state is not None:
        f.restore(state)


_LOAN: PointLoan | None = None


class lending_points:
    """A context in which the point methods borrow the points of :class:`PointLoan` (mutation
    analysis)."""

    def __init__(self, loan: PointLoan) -> None:
        self.loan = loan

    def __enter__(self) -> PointLoan:
        global _LOAN
        self._old, _LOAN = _LOAN, self.loan
        return self.loan

    def __exit__(self, *exc: Any) -> None:
        global _LOAN
        _LOAN = self._old


#: whether a mutation analysis (or a correction search) runs, lent points or not (:class:`mutation_analysis`)
_MUTATION_ANALYSIS = False


class mutation_analysis:
    """A context in which the exact method leaves another function of a catalog claim that reads
    coordinates under a reviewed reason inconclusive (a mutant: see :func:`run_exact`), whether or
    not the points are lent."""

    def __enter__(self) -> None:
        global _MUTATION_ANALYSIS
        self._old, _MUTATION_ANALYSIS = _MUTATION_ANALYSIS, True

    def __exit__(self, *exc: Any) -> None:
        global _MUTATION_ANALYSIS
        _MUTATION_ANALYSIS = self._old


POINTS_MIN = 2            # points per component, at least
POINTS_CAP = 24           # points per component, at most
RATIONAL_BOUND = 2**62    # rational points: integers uniform in [-B, B] (fewest points for the target)
PRIME_RANGE_TEXT = f"[2^{PRIME_BITS}, 2^{PRIME_BITS + 1})"
PRIME_BOUND_TEXT = (f"K >= {PRIMES_IN_RANGE_LOWER:.2g} primes in [2^{PRIME_BITS}, 2^{PRIME_BITS + 1}) (Rosser-Schoenfeld: "
                    "x/ln x < pi(x) < 1.25506 x/ln x)")


def _per_point_bound(kind: str, deg: DegreeBound) -> float:
    """The probability that one point passes a false claim.

    rational: Schwartz-Zippel over S = [-B, B], conditioned on the point avoiding the denominators:
    d/(|S| - d_den).  modular: a fresh prime p, uniform among the primes of [2^62, 2^63), then a
    uniform point of GF(p)^k.  The integer numerator N != 0 vanishes mod p only if p divides its
    content; a nonzero coefficient c has |c| <= ||N||_1 <= 2^h, so at most floor(h/62) primes >= 2^62
    divide it, out of K_eff >= K - floor(constant bits/62) admissible primes (a prime dividing a
    constant of the claim is redrawn).  Otherwise N mod p is a nonzero polynomial of degree <= d:
    Schwartz-Zippel d/(p - d_den) <= d/(2^62 - d_den)."""
    d = max(deg.numerator, 0)
    if kind == "rational":
        S = 2 * RATIONAL_BOUND + 1
        return 0.0 if d == 0 else min(1.0, d / max(S - deg.denominator, 1))
    k_eff = PRIMES_IN_RANGE_LOWER - math.floor(deg.constant_bits / PRIME_BITS)
    content = math.floor(deg.height / PRIME_BITS) / k_eff
    zippel = 0.0 if d == 0 else d / max(PRIME_LOW - deg.denominator, 1)
    return min(1.0, content + zippel)


def _points_needed(eps: float, target: float = POINTS_TARGET, least: int = POINTS_MIN) -> int | None:
    """The least number of independent points (>= ``least``) whose joint bound eps^k is at most
    ``target``; None when POINTS_CAP points cannot reach it."""
    if eps <= 0:
        return least
    if eps >= 1:
        return None
    k = max(least, math.ceil(math.log(target) / math.log(eps)))
    while k > least and eps ** (k - 1) <= target:
        k -= 1
    while eps ** k > target:
        k += 1
    return k if k <= POINTS_CAP else None


def _point_rank(R: Rank, field: Field, bound_text: str) -> tuple[str, str]:
    rk = field.rank(R.matrix._a.tolist())
    exact = field.name == "rational"
    where = "at this exact point" if exact else f"at this point mod p = {field.p}"
    if rk > R.expected:
        return f"rank {rk} {where} exceeds {_who()}'s {R.expected} (certain: generic rank >= {rk})", "certain"
    if rk < R.expected:
        size = min(R.matrix._a.shape)
        if R.expected > size:
            # no matrix of this size has a larger rank, at any point: refuted whatever the point
            return (f"rank {rk} {where}; the matrix is {R.matrix._a.shape[0]}x{R.matrix._a.shape[1]}: no rank "
                    f"exceeds its full size {size} < {R.expected} (certain)"), "certain"
        if exact and not R.generic:
            return (f"rank {rk} {where} of T*V, below the rank {R.expected} {_who()} states at every point "
                    f"(certain)"), "certain"
        if exact and _constant_entries(R, field):
            # a matrix of constants (no parameter entered any entry, numerator or denominator) has one rank over Q,
            # this one, at every point (mod p it could drop where p divides its minors: not decided there)
            return (f"rank {rk} {where}; every entry of the matrix is a constant (no parameter of the point entered "
                    f"it), so its rank is {rk} at every point, below {R.expected} (certain)"), "certain"
        return f"rank {rk} {where} ({_stated(R.expected)}); a special point or a wrong count", "mismatch"
    generic = (f"rank {rk} {where}: generic rank >= {rk} (certain); generic rank <= {rk} "
               f"unless a ({rk + 1})-minor ({bound_text}) vanishes here")
    if not R.generic:
        return (generic + f"; rank {rk} at EVERY point does not follow from sampled points "
                          "(needs the exact method)"), "every-point"
    if rk == min(R.matrix._a.shape):
        # a nonzero rk-minor at this point is the value of a nonzero rational function of the chart's
        # parameters (mod p: its numerator's reduction is not 0, so the numerator is not 0 over Q), and no
        # matrix of this size has a larger rank: the generic rank is rk, both sides, no probability
        return (f"rank {rk} {where}, the matrix's full size ({R.matrix._a.shape[0]}x{R.matrix._a.shape[1]}): a nonzero "
                f"{rk}-minor there is a nonzero rational function of the chart's parameters, so the generic rank "
                f"is {rk} (two-sided, certain)"), "full"
    return generic, "ok"


def _constant_rank(R: Rank) -> tuple[str, str]:
    rk = RationalField().rank(R.matrix._a.tolist())
    return (f"the matrix is constant (no parameter enters); its exact rank over Q is {rk} at every point "
            f"({_stated(R.expected)})", "ok" if rk == R.expected else "certain")


def _prepare(options: dict | None) -> dict | None:
    if options and options.get("hard"):
        options.setdefault("hard_hits", [])   # the scene appends the parameters a hard case rewrites
        # ... and those of the momentum P once a scene (or one lifted from it: each copies the options, sharing
        # these) reads P (see Scene._param)
        options.setdefault("hard_momenta", {"read": False, "pending": []})
    return options


def _untouched(options: dict | None) -> bool:
    """A hard case was asked for and changed no parameter of the claim (after a run with it)."""
    return bool(options and options.get("hard") and not options.get("hard_hits"))


def _hard_or_random(run: Callable[[dict | None], Result], options: dict | None) -> Result:
    """The run at the hard case; when the case changed no parameter of the claim, its point was an
    ordinary random point, so the claim is verified as without the case (random points, with their
    bounds and verdicts), and the result says so."""
    res = run(options)
    if not _untouched(options):
        return res
    plain = {k: v for k, v in options.items() if k not in ("hard", "hard_hits", "hard_momenta")} or None
    res = run(plain)
    note = (f"the hard case {options['hard'].name} changed no parameter of this claim: verified at random "
            f"points as without it")
    res.message = f"{res.message}; {note}" if res.message else note
    return res


#: how the message of a point method whose every sampled point was degenerate begins
DEGENERATE_POINTS = "every one of"


@_quoting
def run_points(claim: Claim, n: int, r: int, kind: str, seed: int, func: Callable | None = None,
               trials: int | None = None, options: dict | None = None, target: float = POINTS_TARGET,
               least: int = POINTS_MIN) -> Result:
    """Exact evaluation at seeded random points (kind "rational" or "modular").

    The number of points per component is chosen so that the false-pass bound is at most
    ``target`` (POINTS_TARGET for a `checked`; a weaker target with ``least`` = 1 for the confirmation
    of a float verdict), at least ``least`` of them (``trials`` fixes the number instead: a witness
    search, whose passes claim no more than their bound).  Hard cases are evaluated at POINTS_MIN
    points (or ``trials``), with no bound."""
    refused = _refused_nonzero(claim, n, r, kind, seed, func)
    if refused is None and kind == "rational":
        refused = _beyond_expansion(claim, n, r, kind, seed, func or claim.func)
    if refused is not None:
        return refused
    options = _prepare(options)
    with spaced_collections():
        return _hard_or_random(lambda o: _run_points(claim, n, r, kind, seed, func or claim.func, trials, o,
                                                     target, least), options)


def _prime_field(key: str, t: int, attempt: int) -> ModularField:
    """The prime of point ``t`` (its ``attempt``-th draw), from the run's :func:`draw_key`."""
    rng = random.Random(f"{key}|modular|{t}|prime|{attempt}")
    return ModularField(random_prime(rng))


def _run_points(claim: Claim, n: int, r: int, kind: str, seed: int, func: Callable,
                trials: int | None, options: dict | None, target: float = POINTS_TARGET,
                least: int = POINTS_MIN) -> Result:
    res = _base_result(claim, n, r, kind, seed)
    t0 = time.perf_counter()
    key = draw_key(claim, n, r, seed, func)
    hard = bool(options and options.get("hard"))
    deg, eps = None, 1.0
    if hard:
        # a hard point is chosen, not random: no bound is claimed; the structural pass still
        # refuses a claim that reads values and describes the degree in the report
        try:
            deg = degree_bound(claim, n, r, func)
        except CoordinateAccess as exc:
            res.verdict, res.message = "error", str(exc)
            return res
        eps = _per_point_bound(kind, deg)
    # the number of points: at least ``least`` per component (or ``trials``; a hard case POINTS_MIN),
    # then more while the product of the points' own bounds is above the target and the cap can
    # still reach it
    points = trials if trials is not None else POINTS_MIN if hard else least
    res.reductions = [in_realization(CAYLEY_REDUCTION.format(D=" D" if r == n else "",
                                                             comp="; both components of O(n) alternate" if r == n
                                                             else ""), claim.realization)]
    if hard:
        res.reductions.append(f"hard case: {options['hard'].description} (not uniform: no Schwartz-Zippel bound)")
    evaluations, resampled, primes_redrawn = [], 0, 0
    witness, primes = None, []
    where = ""      # the node of the last degenerate point's division, in the paper's notation
    rational = RationalField(RATIONAL_BOUND)
    # for r = n the constraint set has two components (det X = +-1): each gets ``points`` points
    components = 2 if r == n else 1
    # each point's own bound: its numbers carry degree markers (paired), so the degree bound is
    # that of the very expression evaluated there, whatever the claim did on other calls
    per_point: list[list[float]] = [[] for _ in range(components)]
    point_degs: list[DegreeBound] = []
    scene = None
    full_proof = False
    t = 0
    while t < points * components or (
            trials is None and not hard and t < POINTS_CAP * components
            and max(math.prod(p) for p in per_point) > target
            and _points_needed(max(e for p in per_point for e in p), target, least) is not None):
        comp = t % components
        prime_attempt = 0
        value_field = rational if kind == "rational" else _prime_field(key, t, prime_attempt)
        for attempt in range(MAX_RESAMPLE):
            def build(value_field=value_field, attempt=attempt) -> tuple:
                rng = random.Random(f"{key}|{kind}|{t}|{attempt}")
                field = value_field if hard else PairField(value_field)
                return value_field, field, Scene(n, r, field, chart="cayley", rng=rng, component=comp,
                                                 realization=claim.realization, options=options)
            if _LOAN is not None and not options:
                value_field, field, scene = _LOAN.scene(
                    (claim.id, claim.realization, kind, n, r, seed, t, attempt, prime_attempt, comp), build)
            else:
                value_field, field, scene = build()
            try:
                checks = call_claim(func, scene)
                point_deg = deg if hard else _paired_bound(checks, field)
                bound_text = _bound_text(kind, point_deg)
                ev = _evaluate(checks, field, lambda R: _point_rank(R, field, bound_text))
                break
            except ConstantDegenerate:
                # a constant of the claim vanishes mod p: this prime is not admissible, draw another
                primes_redrawn += 1
                prime_attempt += 1
                value_field = _prime_field(key, t, prime_attempt)
                continue
            except (DegenerateError, ZeroDivisionError) as exc:
                resampled += 1
                where = getattr(exc, "node_text", "") or where
                continue
        else:
            res.verdict = "inconclusive"
            res.message = (f"{DEGENERATE_POINTS} {MAX_RESAMPLE} sampled points was degenerate (a pole or singular system"
                           + (f"; the last at {where})" if where else ")"))
            res.seconds = time.perf_counter() - t0
            return res
        # no parameter entered the checks (on a lent point, whose parameters the printed claim drew,
        # the markers of the checks say it: all of degree 0, the entries of every rank's matrix too)
        if t == 0 and (_lent_constant(checks, field, point_deg) if getattr(scene, "_loaned", False) and not hard
                       else not scene._has_params()):
            return _run_constant(claim, n, r, seed, func, options, res, t0)
        if components == 2 and scene.second_point_read:
            # the second point (Y, Q) on each component of O(n) with each of X's: four components
            components = 4
            per_point += [[], []]
        if not hard:
            point_degs.append(point_deg)
            per_point[comp].append(_per_point_bound(kind, point_deg))
        evaluations.append(ev)
        if kind == "modular":
            primes.append(field.p)
        if ev.nonzero and witness is None:
            check, pos, val = _telling_entry(ev.nonzero, field)
            witness = {"seed": seed, "trial": t, "attempt": attempt, "component": comp, "field": field.name,
                       "check": check, "entry": pos, "value": field.describe(val),
                       "point": {k: field.describe(v) for k, v in scene._point_values().items()}}
            if kind == "modular":
                witness["prime"] = field.p
        t += 1
        if t == components and kind == "rational" and trials is None and not options \
                and _LOAN is not None and not _LOAN.recording:
            # the first point of each component is done: what a one-point run on these lent points
            # (the exact method's witness) would find
            _LOAN.witnesses[(claim.id, claim.realization, n, r, seed, id(func))] = (func, witness)
        if t == components and not hard and trials is None and _full_ranks(checks, evaluations):
            full_proof = True      # every check a generic rank of full size, on each component: proved
            break
    points = min(len(p) for p in per_point) if point_degs else points
    if point_degs:
        deg = DegreeBound(max(d.numerator for d in point_degs), max(d.denominator for d in point_degs),
                          max(d.height for d in point_degs), max(d.constant_bits for d in point_degs))
        eps = max(e for p in per_point for e in p)
    res.seconds = time.perf_counter() - t0
    res.checks = [o for e in evaluations for o in e.outcomes]
    nonzero = [z for e in evaluations for z in e.nonzero]
    rank_mismatch = list(dict.fromkeys(p for e in evaluations for p in e.rank_problems))
    rank_certain = list(dict.fromkeys(p for e in evaluations for p in e.rank_certain))
    count_bad = list(dict.fromkeys(p for e in evaluations for p in e.count_problems))
    every_point = list(dict.fromkeys(p for e in evaluations for p in e.every_point))
    for o in res.checks:
        o.degree = deg.numerator
    notes = []
    if resampled:
        notes.append(f"{resampled} degenerate samples redrawn")
    if primes_redrawn:
        notes.append(f"{primes_redrawn} primes dividing a constant of the claim redrawn")
    if len({d.numerator for d in point_degs}) > 1:
        notes.append(f"the points' own degree bounds differ, from {min(d.numerator for d in point_degs)} to "
                     f"{deg.numerator}: each point's bound is that of its own evaluation")
    note = f" ({'; '.join(notes)})" if notes else ""
    per = (f" on each of the {components} components of T*V" if components == 2 else
           f" on each of the {components} pairs of components of (X, Y) in O(n) x O(n)" if components == 4 else "")
    joint = max(math.prod(p) for p in per_point) if point_degs else eps ** points
    if kind == "modular":
        how = (f"each point over its own prime p, drawn uniformly from the primes in {PRIME_RANGE_TEXT} by the seed "
               f"(uniform odd integers until one is prime), parameters uniform in GF(p); primes: "
               f"{', '.join(str(p) for p in primes)}; numerator degree <= d = {deg.numerator}, log2 of its L1 norm "
               f"<= h = {deg.height:.1f}; per point: a false pass needs p | N (at most floor(h/{PRIME_BITS}) of the "
               f"{PRIME_BOUND_TEXT}) or N(x) = 0 mod p (Schwartz-Zippel): <= floor(h/{PRIME_BITS})/K + d/(2^{PRIME_BITS} - d_den) "
               f"= {power_of_ten(eps)}")
    else:
        how = (f"parameters uniform integers in [-2^{RATIONAL_BOUND.bit_length() - 1}, "
               f"2^{RATIONAL_BOUND.bit_length() - 1}] (|S| = {_size(2 * RATIONAL_BOUND + 1)}); numerator degree "
               f"<= d = {deg.numerator}; per point (Schwartz-Zippel) d/(|S| - d_den) = {power_of_ten(eps)}")
    if claim.expect == "nonzero":
        if nonzero:
            res.verdict = "proved"
            res.witness = witness
            res.certificate = (f"nonzero value at a seeded point{' mod p' if kind == 'modular' else ''}: "
                               f"{witness['entry']} = {witness['value']}{note}")
        elif hard or joint > target:
            res.verdict = "inconclusive"
            res.message = (f"vanished at {points * components} points, but that does not bound the chance that a "
                           f"nonzero residual vanished there ({'hard points are not uniform' if hard else _cap_text(eps, target)})")
        else:
            res.verdict = "fails"
            res.false_pass_bound = joint
            res.certificate = f"vanished at {points} random points{per}; {how}; probability <= {power_of_ten(joint)}{note}"
        return res
    if nonzero or count_bad or rank_certain:
        res.verdict = "fails"
        res.witness = witness
        if nonzero:
            res.residual = f"{witness['entry']} = {witness['value']}"
            modnote = (f" (mod p = {witness['prime']}: the numerator polynomial is nonzero)"
                       if kind == "modular" else "")
            res.certificate = f"exact nonzero residual at a seeded point of T*V{modnote}{note}"
        else:
            res.certificate = "; ".join(count_bad + rank_certain)
        return res
    if rank_mismatch:
        res.verdict = "inconclusive"
        res.message = "; ".join(rank_mismatch)
        return res
    if full_proof:
        res.verdict = "proved"
        where = "at a point" if components == 1 else f"at a point of each of the {components} components"
        res.certificate = (f"every check is a generic rank equal to its matrix's full size {where}"
                           f"{' (mod p: ' + ', '.join(str(p) for p in primes) + ')' if primes else ''}: "
                           + "; ".join(dict.fromkeys(o.detail for o in res.checks if o.detail)) + note)
        return res
    established = "every residual vanishes" + (" and the generic ranks are as printed" if any(
        o.status == "rank" for o in res.checks) else "")
    if hard:
        # a hard point is chosen, not random: vanishing there says nothing of the statement's truth
        res.verdict = "undecided"
        res.message = (f"not applicable: {established} exactly at the {points * components} hard points; "
                       f"they are chosen, not random, so no verdict on the statement follows{note}")
    elif joint > target:
        res.verdict = "inconclusive"
        res.message = (f"{established} at {points} points{per}, but the false-pass bound is too weak: "
                       f"{_cap_text(eps, target)}; {how}{note}")
        return res
    else:
        res.verdict = "checked"
        res.false_pass_bound = joint
        res.certificate = (f"{points} independent points{per} (chosen so that the bound is <= {power_of_ten(target)}); "
                           f"{how}; false-pass probability <= {_joint_text(per_point, eps, points, joint)}{note}")
    if every_point:
        res.verdict = "undecided"
        res.message = (f"not applicable: {', '.join(every_point)}: a rank at every point of T*V does not follow "
                       f"from sampled points; it needs the exact method (a constant nonzero maximal minor). "
                       f"Established here: {res.certificate}")
        res.false_pass_bound = None
    return res


def _constant_entries(R: Rank, field: Any) -> bool:
    """Whether every entry of the rank's matrix, evaluated over a field with degree markers, is a constant of
    the point: numerator of degree 0 and no factor in its denominator (the rank of [[1/x, 1/y], [1/y, 1/x]]
    drops where x = ±y)."""
    marker = getattr(field, "marker", None)
    if marker is None:
        return False
    return all(m.num <= 0 and not any(m.f.factor_degree[k] for k in m.den)
               for m in map(marker, R.matrix._a.flat))


def _lent_constant(checks: dict[str, Any], field: PairField, deg: DegreeBound) -> bool:
    """Whether no parameter entered the checks evaluated on a lent point: the residuals' numerators (``deg``,
    the point's bound: a residual c/D with c a constant is 0 at a point only if it is 0) are of degree 0, and
    every entry of every rank's matrix is a constant (numerator and denominator of degree 0: the rank of
    [[1/x, 1/y], [1/y, 1/x]] drops where x = ±y).  The bound alone does not say it for a rank: it is the
    degree of the (k+1)-minors, and a rank of its matrix's full size has none (bound 0 whatever its entries),
    so such a rank, of parameters, was taken for a constant matrix: its rank at one point read as its rank at
    every point."""
    if deg.numerator != 0:
        return False
    return all(_constant_entries(v, field) for v in checks.values() if isinstance(v, Rank))


def _full_ranks(checks: dict[str, Any], evaluations: list[Evaluation]) -> bool:
    """Whether every check is a rank stated generically (or a count, exact) and, at every evaluation so far,
    each rank was its matrix's full size, with no count wrong: then the generic ranks are proved (a nonzero
    maximal minor at a point is a nonzero rational function, and no rank exceeds the full size)."""
    ranks = [k for k, v in checks.items() if isinstance(v, Rank)]
    if not ranks or any(not isinstance(v, (Rank, Count)) for v in checks.values()) \
            or any(not v.generic for v in checks.values() if isinstance(v, Rank)):
        return False
    return bool(evaluations) and all(set(e.full) == set(ranks) and not e.count_problems and not e.nonzero
                                     and not e.rank_certain for e in evaluations)


def _bound_text(kind: str, deg: DegreeBound) -> str:
    return (f"degree <= {deg.numerator}" if kind == "rational"
            else f"degree <= {deg.numerator}, log2 height <= {deg.height:.0f}")


def _joint_text(per_point: list[list[float]], eps: float, points: int, joint: float) -> str:
    """The joint bound: eps^k when every point has the same bound, else the product per component."""
    if all(len(p) == points and all(e == eps for e in p) for p in per_point):
        return f"({power_of_ten(eps)})^{points} = {power_of_ten(joint)}"
    return (f"{power_of_ten(joint)} (the product over each component's points of their own bounds, the largest "
            f"{power_of_ten(eps)})")


def _cap_text(eps: float, target: float = POINTS_TARGET) -> str:
    if eps >= 1:
        return f"the per-point bound is {eps:g} >= 1"
    return (f"the per-point bound {power_of_ten(eps)} would need more than {POINTS_CAP} points per component to "
            f"reach {power_of_ten(target)} ({POINTS_CAP} points give {power_of_ten(eps ** POINTS_CAP)})")


def _constant_evaluations(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None,
                          field: RationalField) -> list[tuple[int, Evaluation]]:
    """The checks of a run that no parameter entered, evaluated over Q at the point the seed gives (one
    per component).  A pure function of the function, the size and the seed: on lent points (the
    mutation analysis) the rational and the modular run of the same mutant at the same size both come
    here, and the second takes the first one's evaluations (:attr:`PointLoan.constants`, keyed by the
    function's identity) instead of computing them again; each run gets copies of the outcomes."""
    loan = _LOAN if not options else None
    key = (claim.id, claim.realization, n, r, seed, id(func))
    hit = loan.constants.get(key) if loan is not None else None
    if hit is None or hit[0] is not func:
        evaluations = []
        for comp in ((0, 1) if r == n else (0,)):
            scene = Scene(n, r, field, chart="cayley", rng=random.Random(seed), component=comp,
                          realization=claim.realization, options=options)
            evaluations.append((comp, _evaluate(call_claim(func, scene), field, _constant_rank)))
        hit = (func, evaluations)
        if loan is not None:
            loan.constants[key] = hit
    return [(comp, dataclasses.replace(e, outcomes=[dataclasses.replace(o) for o in e.outcomes]))
            for comp, e in hit[1]]


def _run_constant(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None,
                  res: Result, t0: float) -> Result:
    """No parameter entered the checks: they are constants, decided exactly over Q (no probability), so the
    verdict is proved or fails whichever method drew the point (a constant is the same at every point)."""
    field = RationalField(RATIONAL_BOUND)
    # the chart's point was drawn but nothing of it was read: the reductions are not used (h1 M3 of stop 87)
    res.reductions = ["none: no parameter of the chart enters the checks (they are constants, the same at every "
                      "point of T*V)"]
    evaluations = _constant_evaluations(claim, n, r, seed, func, options, field)
    res.seconds = time.perf_counter() - t0
    res.checks = [o for _, e in evaluations for o in e.outcomes]
    nonzero = [(comp, z) for comp, e in evaluations for z in e.nonzero]
    problems = list(dict.fromkeys(p for _, e in evaluations for p in e.count_problems + e.rank_problems))
    if nonzero:
        comp, (check, pos, val) = nonzero[0]
        res.witness = {"seed": seed, "trial": 0, "attempt": 0, "component": comp, "field": field.name,
                       "check": check, "entry": pos, "value": field.describe(val), "point": {}}
    if claim.expect == "nonzero":
        res.verdict = "proved" if nonzero else "fails"
        res.certificate = ("no parameter enters the checks: " +
                           (f"the constant {res.witness['entry']} = {res.witness['value']} is not zero" if nonzero
                            else "every entry is the constant 0 (exact over Q)"))
        return res
    if nonzero or problems:
        res.verdict = "fails"
        if nonzero:
            res.residual = f"{res.witness['entry']} = {res.witness['value']}"
        res.certificate = "no parameter enters the checks; exact over Q: " + (
            "a nonzero constant residual" if nonzero else "; ".join(problems))
        return res
    # exact over Q and the same at every point: a proof, as the exact method's of the same checks (h1 M3 of
    # stop 87: a constant count was "checked p=0" here and "proved" there)
    res.verdict = "proved"
    res.certificate = ("no parameter enters the checks: they are constants, evaluated exactly over Q, every "
                       "residual 0 (ranks of constant matrices hold at every point); no probability involved")
    return res


def _size(S: int) -> str:
    if S > 10**6:
        return f"{S:.3g}"
    return str(S)


# ---------------------------------------------------------------------------
# floating point with error model and escalation

@_quoting
def run_float(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
              options: dict | None = None) -> Result:
    """float64 with a running error bound; mpmath at 30, 60, 120 digits when float64 cannot decide.
    When r = n both components of O(n) are evaluated."""
    refused = _refused_nonzero(claim, n, r, "float", seed, func)
    if refused is not None:
        return refused
    options = _prepare(options)
    with one_blas_thread(), quiet_numpy():
        res = _hard_or_random(lambda o: _run_float(claim, n, r, seed, func or claim.func, o), options)
    if res.verdict == "numeric":
        res = _confirm_numeric(res, claim, n, r, seed, func, options)
    return _at_the_hard_point(res, options)


#: a `numeric` verdict is confirmed at exact random points mod p, at every size: a residual far below
#: the scale of the terms (a term absorbed by a much larger one) passes float64's relative tolerance,
#: and only exact arithmetic sees it.  As many points per component as make the chance that a residual
#: which is not identically 0 vanishes at all of them at most CONFIRM_TARGET (Schwartz-Zippel with each
#: point's own prime and degree bound, as for `checked`): one point per component wherever its bound
#: is below 2^-40 (every claim of the catalog, up to n = 200 at least: LA1 at (200,100) has degree
#: <= 1205 and a bound of 6e-15 per point), more where it is not
CONFIRM_TARGET = 2.0 ** -40
#: a hard case (chosen, not random, points: no bound) is confirmed at this many points per component
CONFIRM_POINTS = POINTS_MIN


def _confirm_numeric(res: Result, claim: Claim, n: int, r: int, seed: int, func: Callable | None,
                     options: dict | None, method: str = "float") -> Result:
    """The float or ball run's ``numeric``, confirmed at exact points modulo primes (of the hard case, at
    its exact parameters, when one was asked for and changed a parameter; random points otherwise).  A
    nonzero residual there refutes the claim; where no exact point can be evaluated the float verdict
    is not a pass (``inconclusive``, with the reason)."""
    what = "float64" if method == "float" else "the ball enclosure"
    hard = {k: v for k, v in options.items() if k not in ("hard_hits", "hard_momenta")} if options else None
    if hard and _untouched(options):
        # the case changed no parameter of the claim: the float run was redone at random points as without it
        # (_hard_or_random), and so is its confirmation, with the bound a pass at random points needs
        hard = {k: v for k, v in hard.items() if k != "hard"} or None
    if hard and hard.get("hard"):
        exact = run_points(claim, n, r, "modular", seed, func, trials=CONFIRM_POINTS, options=hard)
    else:
        exact = run_points(claim, n, r, "modular", seed, func, options=hard, target=CONFIRM_TARGET, least=1)
    res.seconds += exact.seconds           # the record's time is the whole check's, confirmation included
    if exact.checks and (exact.verdict in ("checked", "proved") if not (hard and hard.get("hard"))
                         else exact.verdict not in ("fails", "error")):
        # the residuals vanished at the exact points (a nonzero residual below float64's resolution
        # is what the confirmation looks for); at random points the chance that one which is not
        # identically 0 did is bounded (checked, not an `inconclusive` whose bound is too weak); at a
        # hard case's chosen points there is no such bound (the verdict is modular's "not applicable")
        res.certificate = (res.certificate + "; " if res.certificate else "") + _confirm_text(exact)
        return res
    if exact.verdict != "fails":
        res.verdict = "inconclusive"
        res.message = (f"{what} passed within its tolerance relative to the terms' scale, but the confirmation "
                       f"at exact points mod p could not decide ({exact.verdict}"
                       + (f": {exact.message}" if exact.message else "") +
                       "), and a residual below float64's resolution of the terms is seen only there")
        return res
    exact.method, exact.seconds = method, res.seconds
    exact.message = (f"{what} passed within its tolerance relative to the terms' scale, but the residual is "
                     "not 0 at exact points mod p: it lies below float64's resolution of those terms"
                     + (f" ({exact.message})" if exact.message else ""))
    return exact


def _at_the_hard_point(res: Result, options: dict | None) -> Result:
    """A float or ball pass, confirmed at the exact points of a hard case that reached the claim: the points are
    chosen, not random, so it says nothing of the statement (``undecided``); a residual not 0 at the hard case's
    exact points mod p was refuted by the confirmation already (:func:`_confirm_numeric`)."""
    if res.verdict in ("numeric", "proved") and options and options.get("hard") and not _untouched(options):
        res.verdict = "undecided"
        res.message = ("not applicable: resolved at the hard point, which is chosen, not random, so no verdict on "
                       "the statement follows; " + (res.message or res.certificate))
    return res


def _confirm_text(exact: Result) -> str:
    """What the exact confirmation of a float verdict established, with its false-pass bound."""
    if exact.verdict == "checked" and exact.false_pass_bound is not None:
        m = re.match(r"(\d+) independent points( on each of the \d+ (?:pairs of )?components[^;]*)?",
                     exact.certificate)
        where = (f"{m.group(1)} random point{'s' if m.group(1) != '1' else ''} mod p"
                 f"{' per component' if m.group(2) else ''}" if m else "random points mod p")
        if exact.false_pass_bound == 0 and not m:
            return f"confirmed exactly: {exact.certificate}"
        degree = max((o.degree for o in exact.checks if o.degree is not None), default=None)
        return (f"confirmed exactly: every residual is 0 at {where} (a point over its own prime in {PRIME_RANGE_TEXT}); "
                f"a residual that is not identically 0 vanishes there with probability <= "
                f"{exact.false_pass_bound:.1e} <= 2^{math.log2(CONFIRM_TARGET):.0f} (Schwartz-Zippel with each "
                f"point's own bound{f', numerator degree <= {degree}' if degree is not None else ''})")
    return (f"the exact confirmation mod p did not bound the chance of a missed residual "
            f"({exact.verdict}: {_short(exact.message or exact.certificate, 240)})")


@dataclass
class _FloatRun:
    status: str                 # "pass", "bad", "nonzero", "zero", "unresolved", "empty", "pole"
    field: str = ""
    log: list[str] = dc_field(default_factory=list)
    entry: tuple[str, Any] | None = None
    worst_e: Any = 0.0
    worst_m: Any = 0.0
    ranks: list[str] = dc_field(default_factory=list)
    count_problems: list[str] = dc_field(default_factory=list)
    #: the evaluation read the second point (Y, Q): at r = n its components are sampled as well
    second: bool = False


def _resolves(x: ErrNum) -> bool:
    """The bound e could see a residual far below the scale of the terms (e <= 1e-8 m, all finite)."""
    return _finite(x) and x.e <= FLOAT_RESOLUTION * x.m


def _finite(x: ErrNum) -> bool:
    if type(x.v) is float and type(x.e) is float and type(x.m) is float:
        return math.isfinite(x.v) and math.isfinite(x.e) and math.isfinite(x.m)
    try:
        return all(mpmath.isfinite(y) for y in (x.v, x.e, x.m))
    except (TypeError, ValueError):
        return False


def _pole_everywhere(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None) -> str | None:
    """After float64 met a division by a number indistinguishable from 0: the modular method's account when
    its exact points (every one it samples, each at its own prime) are poles too, so that the divisor
    vanishes wherever the claim is evaluated (a constant of the size that is 0, say) and the precision ladder
    could only spend its time (minutes at n = 100) to the same end; None when an exact point is no pole (the
    float64 division was a matter of precision: the ladder goes on)."""
    probe = run_points(claim, n, r, "modular", seed, func, trials=1, options=options)
    if probe.verdict == "inconclusive" and (probe.message or "").startswith(DEGENERATE_POINTS):
        return f"exact points modulo primes: {probe.message}"
    return None


def _float_component(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None,
                     comp: int, ladder: tuple = FLOAT_LADDER) -> _FloatRun:
    run = _FloatRun("unresolved")
    nonzero_claim = claim.expect == "nonzero"
    cons = REALIZATIONS[claim.realization]
    wide = outside_float_range(_claim_graph(func, n, r, (cons.name, cons.build)))
    key = draw_key(claim, n, r, seed, func)
    for dps in ladder:
        if dps is None and wide:
            run.log.append(f"float64 skipped: the constant {short_value(str(wide[0]), where='exact in the claim')} is outside its range "
                           f"(2^-{FLOAT_EXPONENT_LIMIT}, 2^{FLOAT_EXPONENT_LIMIT})")
            continue
        def build(dps=dps) -> tuple:
            field = FloatField(dps)
            rng = random.Random(f"{key}|float" + (f"|component {comp}" if comp else ""))
            return field, Scene(n, r, field, chart="cayley", rng=rng, component=comp,
                                realization=claim.realization, options=options)
        if _LOAN is not None and not options and dps is None:
            field, scene = _LOAN.scene((claim.id, claim.realization, "float", n, r, seed, comp), build)
        else:
            field, scene = build()        # (a scene builds its objects when they are first asked for)
        ctx = mpmath.workdps(dps) if dps else np.errstate(over="ignore", invalid="ignore")
        try:
            with ctx:
                checks = call_claim(func, scene)
                run.second = run.second or scene.second_point_read
                entries, ranks, counts = [], [], []
                for name, value in checks.items():
                    if isinstance(value, Rank):
                        ranks.append(name)
                    elif isinstance(value, Count):
                        if value.value != value.expected:
                            counts.append(f"{name}: {value.meaning + ': ' if value.meaning else ''}"
                                          f"{value.value} ({_stated(value.expected)})")
                    else:
                        for pos, x in _float_entries(value, name, field.u):
                            if not isinstance(x, ErrNum):
                                x = field.const(x)       # an exact int or Fraction
                            entries.append((pos, x))
        except OverflowError as exc:
            run.log.append(f"{field.name}: unresolved ({exc})")
            continue
        except DegenerateError as exc:
            run.log.append(f"{field.name}: {exc}")
            if dps is None:
                pole = _pole_everywhere(claim, n, r, seed, func, options)
                if pole is not None:        # no precision at this point can resolve it: the ladder stops
                    run.status = "pole"
                    run.log.append(pole)
                    return run
            continue
        finally:
            release = getattr(field.__dict__.get("_backend"), "release", None)
            if release is not None:      # the evaluation is over: its remembered products may go
                release()
        run.ranks, run.count_problems, run.field = ranks, counts, field.name
        if not entries:
            run.status = "empty"
            return run
        finite = all(_finite(x) for _, x in entries)
        if not finite:   # never a pass: nan or inf anywhere voids the error model
            run.log.append(f"{field.name}: unresolved (a non-finite value, error bound or term scale: overflow)")
            continue
        worst = max(entries, key=lambda px: abs(px[1].v))[1]
        ratio = max(entries, key=lambda px: (px[1].e / px[1].m) if px[1].m else (0 if px[1].e == 0 else math.inf))[1]
        run.worst_e, run.worst_m = ratio.e, ratio.m
        run.log.append(f"{field.name}: max |residual| {_sci(abs(worst.v), 2)}, error bound up to "
                       f"{_sci(max(x.e for _, x in entries), 2)}, worst resolution e = {_sci(ratio.e, 1)} at "
                       f"term scale m = {_sci(ratio.m, 1)}")
        clear = [(pos, x) for pos, x in entries if abs(x.v) > x.e]
        if nonzero_claim:
            hit = [(pos, x) for pos, x in clear if _resolves(x)]
            if hit:
                run.status, run.entry = "nonzero", hit[0]
                return run
            if not clear and all(_resolves(x) for _, x in entries):
                run.status = "zero"
                return run
            continue
        if clear:
            run.status, run.entry = "bad", clear[0]
            return run
        if all(_resolves(x) for _, x in entries):
            run.status = "pass"
            return run
    run.status = "unresolved"
    return run


def _sci(x: Any, digits: int) -> str:
    """``x`` in scientific notation with ``digits`` decimals, also beyond float64's range (a high-precision value
    of 2⁻²⁰⁰⁰ is not printed as 0, nor one of 2³⁰⁰⁰ as inf)."""
    f = float(x)
    if (f == 0.0 and x != 0) or math.isinf(f):
        import mpmath
        return mpmath.nstr(mpmath.mpf(x), digits + 1, min_fixed=1, max_fixed=0)
    return f"{f:.{digits}e}"


def _run_float(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None) -> Result:
    res = _base_result(claim, n, r, "float", seed)
    t0 = time.perf_counter()
    # no separate structural pass: a claim that reads the values of the scene's numbers is refused
    # (on record) in this very run, every number it gets being an opaque Scalar
    comps = (0, 1) if r == n else (0,)
    res.reductions = [in_realization(CAYLEY_REDUCTION.format(
        D=" D" if r == n else "", comp="; both components of O(n)" if r == n else ""), claim.realization)
        + "; running error analysis of every operation"]
    if options and options.get("hard"):
        res.reductions.append(f"hard case: {options['hard'].description}")
    identity = claim.expect != "nonzero"
    first = FLOAT_LADDER[:1] if identity else FLOAT_LADDER
    runs = [_float_component(claim, n, r, seed, func, options, c, first) for c in comps]
    if r == n and any(run.second for run in runs):
        # the second point (Y, Q) on each component of O(n) with each of X's (Scene._component_of)
        comps = (0, 1, 2, 3)
        runs += [_float_component(claim, n, r, seed, func, options, c, first) for c in comps[2:]]
    log = "; ".join((f"component {c + 1}: " if len(comps) > 1 else "") + "; ".join(run.log)
                    for c, run in zip(comps, runs))
    if any(run.status == "pole" for run in runs):
        res.message = ("a pole wherever the claim is evaluated: float64 met a division by a number "
                       "indistinguishable from 0, and so did the exact points modulo primes; more precision "
                       "cannot resolve it (" + log + ")")
        res.verdict, res.seconds = "inconclusive", time.perf_counter() - t0
        return res
    decided = None
    if identity and any(run.status == "unresolved" for run in runs) and not any(run.status == "bad" for run in runs):
        ball = _run_ball(claim, n, r, seed, func, options)
        if ball.verdict in ("numeric", "fails"):
            for k in ("certificate", "residual", "witness", "false_pass_bound"):
                setattr(res, k, getattr(ball, k))
            res.reductions += [x for x in ball.reductions if x not in res.reductions]
            res.message = (f"float64 could not resolve the residual ({log}); ball arithmetic at the same exact "
                           f"point decided: {ball.message or ball.certificate}")
            decided = ball.verdict
        else:
            runs = [_float_component(claim, n, r, seed, func, options, c, FLOAT_LADDER[1:]) for c in comps]
            log += (f"; ball arithmetic: {ball.verdict} ({ball.message}); "
                    + "; ".join((f"component {c + 1}: " if len(comps) > 1 else "") + "; ".join(run.log)
                                for c, run in zip(comps, runs)))

    def done(verdict: str) -> Result:
        res.verdict = verdict
        res.seconds = time.perf_counter() - t0
        return res

    if decided is not None:
        return done(decided)
    counts = list(dict.fromkeys(p for run in runs for p in run.count_problems))
    if counts:
        res.certificate = "; ".join(counts) + " (integers, exact)"
        return done("fails")
    if any(run.status == "empty" for run in runs):
        res.message = "not applicable: no residuals to evaluate in floating point (ranks are decided exactly)"
        return done("inconclusive")
    ranks = list(dict.fromkeys(name for run in runs for name in run.ranks))

    if claim.expect == "nonzero":
        hit = next(((c, run) for c, run in zip(comps, runs) if run.status == "nonzero"), None)
        res.message = log
        if hit is not None:
            c, run = hit
            pos, x = run.entry
            res.residual = f"{pos} = {x!r}"
            res.certificate = (f"{run.field}{f' (component {c + 1})' if len(comps) > 1 else ''}: {pos} = {x!r}, "
                               f"|value| > its error bound, which resolves 1e-8 of the term scale")
            return done("numeric")
        ex = run_points(claim, n, r, "rational", seed, func, options=options)
        if ex.verdict == "proved":
            res.witness = ex.witness
            res.certificate = ("not clearly nonzero in floating point; an exact rational point confirms it: "
                               f"{ex.certificate}")
            return done("numeric")
        if ex.verdict == "fails":
            res.witness, res.false_pass_bound = ex.witness, ex.false_pass_bound
            res.certificate = f"no entry is nonzero in floating point; exact rational points: {ex.certificate}"
            return done("fails")
        res.message = f"neither floating point nor exact rational points decide ({ex.verdict}: {ex.message}) | {log}"
        return done("inconclusive")

    bad = next(((c, run) for c, run in zip(comps, runs) if run.status == "bad"), None)
    if bad is not None:
        c, run = bad
        pos, x = run.entry
        res.residual = f"{pos} = {x!r}"
        ex = run_points(claim, n, r, "rational", seed, func, trials=1, options=options)
        if ex.verdict == "inconclusive":
            # the rational point not evaluated (a degree beyond what it writes out): a point modulo a prime is,
            # at any degree, and its nonzero residual is as certain a witness
            mod = run_points(claim, n, r, "modular", seed, func, trials=1, options=options)
            if mod.verdict == "fails":
                ex = mod
        if ex.verdict == "fails":
            res.witness = ex.witness
            res.certificate = (f"{run.field} residual exceeds its error bound; confirmed by an exact "
                               f"{'rational' if ex.method == 'rational' else 'modular'} witness")
            res.message = log
            return done("fails")
        if ex.verdict == "inconclusive":
            res.message = ("the floating-point residual exceeds its first-order error bound, and neither an exact "
                           f"rational point nor a point modulo a prime decides ({ex.message}) | {log}")
            return done("inconclusive")
        res.message = ("the floating-point residual exceeds its first-order error bound but the exact "
                       f"check passed ({ex.verdict}): the bound is too optimistic here | {log}")
        return done("inconclusive")
    if any(run.status != "pass" for run in runs):
        res.message = "precision ladder exhausted without a resolving bound: " + log
        return done("inconclusive")
    res.false_pass_bound = None
    res.residual = None
    res.certificate = "; ".join(
        f"{f'component {c + 1}, ' if len(comps) > 1 else ''}{run.field}: every residual entry |v| <= its error "
        f"bound e, and e <= 1e-8 x its term scale m (worst e = {_sci(run.worst_e, 1)} at m = "
        f"{_sci(run.worst_m, 1)}); so |exact residual| <= 2e at this point" for c, run in zip(comps, runs))
    res.message = log
    if ranks:
        res.message = (f"not applicable: {', '.join(ranks)}: ranks are decided by exact arithmetic (methods exact, "
                       f"rational, modular); floating point cannot. The residuals pass numerically: "
                       f"{res.certificate} | {log}")
        return done("undecided")
    return done("numeric")


# ---------------------------------------------------------------------------
# ball arithmetic: rigorous enclosures at the float method's exact points

BALL_CERTIFICATE = (
    "ball arithmetic (float64 midpoint-radius pairs with a-priori rounding bounds, then arb): every residual "
    "entry is enclosed in a ball that contains its exact value at this exact point of T*V (parameters k/2^40, exact constants), by the inclusion property of the balls")


@_quoting
def run_ball(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
             options: dict | None = None) -> Result:
    """Rigorous ball arithmetic at the exact point the float method draws: float64 midpoint-radius
    matrices first from n = 32 on (:mod:`stiefelsym.backends.midrad`), then arb at 53, 106, 212 and 424
    bits, until the enclosures decide: one that excludes 0 is a certified nonzero residual
    (``fails``); all within 1e-8 of their term scales is ``numeric`` with the rigorous bound.
    When r = n both components of O(n) are evaluated."""
    refused = _refused_nonzero(claim, n, r, "ball", seed, func)
    if refused is not None:
        return refused
    options = _prepare(options)
    with one_blas_thread(), quiet_numpy():
        res = _hard_or_random(lambda o: _run_ball(claim, n, r, seed, func or claim.func, o), options)
    if res.verdict == "numeric":
        res = _confirm_numeric(res, claim, n, r, seed, func, options, "ball")
    return _at_the_hard_point(res, options)


class _Enclosures:
    """The enclosures of one check's residual entries, as the ball method reads them: ``ups``, an
    upper bound of |x| for every x in each ball (float64, rounded up; 0 only for a ball that is
    exactly 0), ``scales`` (their term scales), ``excludes()`` (where a ball excludes 0, computed
    when asked), ``ball(i)`` (one enclosure as text) and ``pos(i)`` (the entry's position)."""

    def __init__(self, pos: Callable[[int], str], ups: np.ndarray, scales: np.ndarray,
                 excludes: Callable[[], np.ndarray], ball: Callable[[int], str], zero: bool) -> None:
        self.pos, self.ups, self.scales, self.excludes, self.ball = pos, ups, scales, excludes, ball
        #: every ball contains 0 (one native test), so none excludes it
        self.zero = zero


def _arb_enclosures(pos: Callable[[int], str], balls: list, scales: np.ndarray, zero: bool) -> _Enclosures:
    # the upper end of |x| rounded up by one ulp of float64 (0 for the ball that is exactly 0); a
    # ball excludes 0 where it does not contain 0, decided in arb (a ball of 2^-2000 excludes 0, though the lower
    # end of its |x| is 0 in float64)
    raw = np.array([float(b.abs_upper()) for b in balls])
    ups = np.nextafter(raw, math.inf)
    for i in np.flatnonzero(raw == 0).tolist():
        if balls[i].is_zero():
            ups[i] = 0.0
    return _Enclosures(pos, ups, scales, lambda: np.array([not b.contains(0) for b in balls], dtype=bool),
                       lambda i: balls[i].str(17, radius=True), zero)


def _ball_entries(value: Any, name: str, field: Any) -> _Enclosures:
    """The enclosures of a residual over a ball field (arb balls, or float64 midpoint-radius
    pairs read as whole arrays) with their term scales."""
    from stiefelsym.backends.ball import Balls, entries_of
    from stiefelsym.backends.midrad import MidRad
    if isinstance(value, Mat) and 0 in value._shape():
        _entries(value, name)    # a vacuous check: the error every method gives (TypeError)
    if isinstance(value, Mat) and isinstance(value._n, MidRad):
        s = backend(field)._forced(value._n)
        cols = s.shape()[1]
        return _Enclosures(lambda i: f"{name}[{i // cols + 1},{i % cols + 1}]", s.upper_abs().ravel(),
                           s.m.ravel(), lambda: s.excludes_zero().ravel(),
                           lambda i: s.ball(i).str(17, radius=True), backend(field).is_zero(s))
    if isinstance(value, Mat) and isinstance(value._n, Balls):
        balls, scales = entries_of(value._n)
        cols = value._n.shape()[1]
        return _arb_enclosures(lambda i: f"{name}[{i // cols + 1},{i % cols + 1}]", balls, np.array(scales),
                               backend(field).is_zero(value._n))
    pairs = _entries(value, name)
    for pos, x in pairs:
        if not hasattr(x, "b"):
            raise TypeError(f"check {pos}: not a number of the ball field ({type(x).__name__})")
    return _arb_enclosures(lambda i: pairs[i][0], [x.b for _, x in pairs],
                           np.array([float(x.m) for _, x in pairs], dtype=float), False)


@dataclass
class _BallDecision:
    status: str                  # "pass", "bad", "nonzero", "zero", "unresolved", "empty"
    field: str = ""
    log: list[str] = dc_field(default_factory=list)
    entry: tuple[str, str] | None = None          # (position, enclosure) of the deciding entry
    worst: tuple[float, float] = (0.0, 0.0)       # the bound e and scale m of the worst e/m
    bound: float = 0.0                            # the largest bound over all entries
    ranks: list[str] = dc_field(default_factory=list)
    count_problems: list[str] = dc_field(default_factory=list)
    point: dict[str, str] = dc_field(default_factory=dict)
    #: the evaluation read the second point (Y, Q): at r = n its components are sampled as well
    second: bool = False


def _ball_rng(seed: int, claim: Claim, n: int, r: int, comp: int, func: Callable) -> random.Random:
    """The float method's random source: the ball method evaluates at the float method's point."""
    return random.Random(f"{draw_key(claim, n, r, seed, func)}|float" + (f"|component {comp}" if comp else ""))


def _ball_component(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None,
                    comp: int) -> _BallDecision:
    from stiefelsym.backends.ball import BALL_LADDER, BallField, working_precision
    from stiefelsym.backends.midrad import MIDRAD_MIN_N, MidRadField
    run = _BallDecision("unresolved")
    nonzero_claim = claim.expect == "nonzero"
    # float64 midpoint-radius pairs first (numpy, a-priori rounding bounds) where matrices are large
    # enough for numpy to pay, then arb up the ladder
    first = [MidRadField()] if n >= MIDRAD_MIN_N else []
    for field in first + [BallField(prec) for prec in BALL_LADDER]:
        with working_precision(field.prec):
            try:
                scene = Scene(n, r, field, chart="cayley", rng=_ball_rng(seed, claim, n, r, comp, func),
                              component=comp, realization=claim.realization, options=options)
                checks = call_claim(func, scene)
                run.second = run.second or scene.second_point_read
                encs: list[_Enclosures] = []
                ranks, counts = [], []
                for name, value in checks.items():
                    if isinstance(value, Rank):
                        ranks.append(name)
                    elif isinstance(value, Count):
                        if value.value != value.expected:
                            counts.append(f"{name}: {value.meaning + ': ' if value.meaning else ''}"
                                          f"{value.value} ({_stated(value.expected)})")
                    else:
                        encs.append(_ball_entries(value, name, field))
            except DegenerateError as exc:
                run.log.append(f"{field.name}: {exc}")
                continue
            finally:
                release = getattr(field.__dict__.get("_backend"), "release", None)
                if release is not None:      # the evaluation is over: its remembered products may go
                    release()
            run.ranks, run.count_problems, run.field = ranks, counts, field.name
            if not encs or not sum(len(x.ups) for x in encs):
                run.status = "empty"
                return run
            ups = np.concatenate([x.ups for x in encs])
            scales = np.concatenate([x.scales for x in encs]).astype(float)
            # the first enclosure (check, index) that excludes 0, if any
            clear = next(((x, int(ix[0])) for x in encs if not x.zero
                          for ix in [np.flatnonzero(x.excludes())] if len(ix)), None)
            total = len(ups)
            with np.errstate(all="ignore"):
                resolves = np.isfinite(ups) & np.isfinite(scales) & (ups <= FLOAT_RESOLUTION * scales)
                ratio = np.where(scales > 0, ups / np.where(scales > 0, scales, 1.0),
                                 np.where(ups == 0, 0.0, math.inf))
            k = int(np.argmax(ratio))
            run.worst, run.bound = (float(ups[k]), float(scales[k])), float(np.max(ups))
            excluded = sum(int(np.count_nonzero(x.excludes())) for x in encs if not x.zero) if clear else 0
            run.log.append(f"{field.name}: {excluded} of {total} enclosures exclude 0; largest bound "
                           f"{run.bound:.2e}, worst resolution e = {ups[k]:.1e} at term scale m = {scales[k]:.1e}"
                           + ("" if np.all(np.isfinite(scales)) else
                              " (a term scale overflows float64: the resolution test cannot be made)"))
            if clear:
                enc, i = clear
                run.entry = (enc.pos(i), enc.ball(i))
                run.point = {name: field.describe(v) for name, v in scene._point_values().items()}
                run.status = "nonzero" if nonzero_claim else "bad"
                return run
            if bool(np.all(resolves)):
                run.status = "zero" if nonzero_claim else "pass"
                return run
    run.status = "unresolved"
    return run


def _run_ball(claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None) -> Result:
    res = _base_result(claim, n, r, "ball", seed)
    t0 = time.perf_counter()
    comps = (0, 1) if r == n else (0,)
    res.reductions = [in_realization(CAYLEY_REDUCTION.format(
        D=" D" if r == n else "", comp="; both components of O(n)" if r == n else ""), claim.realization)
        + "; the float method's exact point (parameters k/2^40); rigorous ball arithmetic (arb)"]
    if options and options.get("hard"):
        res.reductions.append(f"hard case: {options['hard'].description} (the hard value's ball midpoint, "
                              f"taken as an exact input)")
    runs = [_ball_component(claim, n, r, seed, func, options, c) for c in comps]
    if r == n and any(run.second for run in runs):
        # the second point (Y, Q) on each component of O(n) with each of X's (Scene._component_of)
        comps = (0, 1, 2, 3)
        runs += [_ball_component(claim, n, r, seed, func, options, c) for c in comps[2:]]
    log = "; ".join((f"component {c + 1}: " if len(comps) > 1 else "") + "; ".join(run.log)
                    for c, run in zip(comps, runs))
    where = lambda c: f" (component {c + 1})" if len(comps) > 1 else ""  # noqa: E731

    def done(verdict: str) -> Result:
        res.verdict = verdict
        res.seconds = time.perf_counter() - t0
        return res

    def witness(c: int, run: _BallDecision) -> dict[str, Any]:
        pos, ball = run.entry
        return {"seed": seed, "trial": 0, "attempt": 0, "component": c, "field": run.field,
                "check": pos.split("[")[0], "entry": pos, "value": ball, "point": run.point}

    counts = list(dict.fromkeys(p for run in runs for p in run.count_problems))
    if counts:
        res.certificate = "; ".join(counts) + " (integers, exact)"
        return done("fails")
    if any(run.status == "empty" for run in runs):
        res.message = "not applicable: no residuals to enclose (ranks are decided exactly)"
        return done("inconclusive")
    ranks = list(dict.fromkeys(name for run in runs for name in run.ranks))
    res.message = log
    if claim.expect == "nonzero":
        hit = next(((c, run) for c, run in zip(comps, runs) if run.status == "nonzero"), None)
        if hit is not None:
            c, run = hit
            res.witness = witness(c, run)
            res.residual = f"{run.entry[0]} in {run.entry[1]}"
            res.certificate = (f"{BALL_CERTIFICATE}; {run.field}{where(c)}: {run.entry[0]} lies in "
                               f"{run.entry[1]}, which excludes 0: the residual is not identically zero "
                               f"(certified at this point)")
            return done(_exact_agrees(res, claim, n, r, seed, func, options, "proved", log))
        ex = run_points(claim, n, r, "rational", seed, func, options=options)
        if ex.verdict in ("proved", "fails"):
            res.witness, res.false_pass_bound = ex.witness, ex.false_pass_bound
            res.certificate = f"no enclosure excludes 0; exact rational points: {ex.certificate}"
            return done(ex.verdict)
        res.message = f"neither the enclosures nor exact rational points decide ({ex.verdict}: {ex.message}) | {log}"
        return done("inconclusive")
    bad = next(((c, run) for c, run in zip(comps, runs) if run.status == "bad"), None)
    if bad is not None:
        c, run = bad
        res.witness = witness(c, run)
        res.residual = f"{run.entry[0]} in {run.entry[1]}"
        res.certificate = (f"{BALL_CERTIFICATE}; {run.field}{where(c)}: the enclosure {run.entry[1]} of "
                           f"{run.entry[0]} excludes 0, so the exact residual is nonzero at this point "
                           f"(a certified witness)")
        return done(_exact_agrees(res, claim, n, r, seed, func, options, "fails", log))
    if any(run.status != "pass" for run in runs):
        res.message = "precision ladder (float64 midpoint-radius, then arb at 53, 106, 212, 424 bits) exhausted without resolving enclosures: " + log
        return done("inconclusive")
    res.certificate = BALL_CERTIFICATE + "; " + "; ".join(
        f"{f'component {c + 1}, ' if len(comps) > 1 else ''}{run.field}: every enclosure contains 0 and "
        f"lies in [-e, e] with e <= 1e-8 x its term scale (largest e = {run.bound:.1e}; worst e/m: "
        f"{run.worst[0]:.1e} at m = {run.worst[1]:.1e}); so |exact residual| <= {run.bound:.1e} at this point"
        for c, run in zip(comps, runs))
    if ranks:
        res.message = (f"not applicable: {', '.join(ranks)}: ranks are decided by exact arithmetic (methods exact, "
                       f"rational, modular); balls cannot. The residuals are enclosed: {res.certificate} | {log}")
        return done("undecided")
    return done("numeric")


def _exact_agrees(res: Result, claim: Claim, n: int, r: int, seed: int, func: Callable, options: dict | None,
                  verdict: str, log: str) -> str:
    """``verdict`` (fails, or proved for a claim said not to vanish) of certified enclosures, kept when an exact
    point agrees (a nonzero residual there, modulo a large prime: exact, and as fast at the large sizes balls are
    for as the float method's confirmation).  An enclosure bounds the value the balls computed, and a step of the
    engine may compute it otherwise on an approximating field (a closed form, a degree decided within an error
    bound): the exact evaluation is the statement's.  An exact run that refuses the claim makes the verdict
    ``error``; one that finds the residual zero leaves it ``inconclusive``."""
    ex = run_points(claim, n, r, "modular", seed, func, trials=1, options=options)
    if ex.verdict == verdict:
        res.certificate += "; confirmed by an exact point mod p: " + (ex.certificate or (
            f"its residual is not 0 there ({ex.residual})" if ex.residual else "its residual is not 0 there"))
        return verdict
    if ex.verdict == "error":
        res.message = f"the exact evaluation refuses the claim: {ex.message} | {log}"
        res.witness = res.residual = None
        return "error"
    res.message = (f"an enclosure excludes 0 ({res.residual}), but an exact point mod p does not confirm it "
                   f"({ex.verdict}: {ex.message or ex.certificate}): no verdict from the balls | {log}")
    res.witness = res.residual = res.certificate = None
    return "inconclusive"


#: in a worker, a symbolic attempt runs in its own forked child when the cost model predicts at least
#: ISOLATE_SECONDS, or (from ISOLATE_MIN_N on) a peak memory above ISOLATE_MEMORY_FRACTION of the worker's
#: memory budget, or when n is beyond every size the model measured the symbolic method at: a heavy attempt
#: must not leave the long-lived worker bloated (native memory that fragments and grows) or dead.  A fork
#: costs CPU in proportion to the memory the worker has mapped (measured: 4-5 ms at 77 MiB, 20-60 ms at
#: 0.2-0.9 GiB, parent and child together): the runs below these thresholds take milliseconds to a few
#: seconds and stay in the worker, which retires once it has grown (:data:`stiefelsym.run.pool.RECYCLE_GROWTH`)
ISOLATE_MIN_N = 6
ISOLATE_SECONDS = 0.5
ISOLATE_MEMORY_FRACTION = 1 / 16


def _memory_budget() -> float:
    """The bytes this process may use: its address-space limit (a worker's is the run's memory budget),
    else the machine's memory."""
    try:
        import resource
        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
        if soft != resource.RLIM_INFINITY and soft > 0:
            return float(soft)
    except (ImportError, OSError, ValueError):
        pass
    try:
        return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):
        return float(4 << 30)


#: a symbolic run of the claim as printed that took this many seconds has its mutants' symbolic runs forked
MUTANT_ISOLATE_SECONDS = 1.0
#: in a worker, a claim the cost model was never measured on (a user's) has its symbolic attempt forked from this n
#: on: a complex claim of W(3, r) ran flint out of memory at n = 3 inside the worker, which took the run with it
#: (error, where auto would have gone on with the modular method); a fork of a small worker costs a few ms
USER_ISOLATE_MIN_N = 2


def isolates(claim: Claim, n: int, r: int, in_worker: bool = False) -> bool:
    """Whether the symbolic attempt at (n, r) runs in its own forked child.  Outside a worker: from
    n = 4 on (n = 5 while lending points to the mutation analysis, :class:`PointLoan`, whose thousands
    of small runs at n <= 4 would spend more time forking than computing, and there also for the mutants of
    a claim whose own symbolic run at (n, r) took MUTANT_ISOLATE_SECONDS or more), for the hard time limit.
    In a worker (the worker is killable, but must survive a heavy attempt): from n = USER_ISOLATE_MIN_N on for
    a claim the cost model was not measured on (a user's claim), when the cost model predicts at least ISOLATE_SECONDS,
    and from n = ISOLATE_MIN_N on also when it predicts a peak memory above ISOLATE_MEMORY_FRACTION of the
    worker's memory budget or n lies beyond the sizes the model measured the symbolic method at."""
    if not hasattr(os, "fork"):
        return False
    if not in_worker:
        if _LOAN is not None:
            # a mutant can cost far more than its claim (a change that breaks a cancellation), and one flint
            # product is not interrupted by the signal-based limit: forked where the claim itself was costly
            return n > 4 or _LOAN.exact_cost.get((claim.id, n, r), 0.0) >= MUTANT_ISOLATE_SECONDS
        return n > 3
    model = costmodel.model()
    family = model.family_of(claim)
    if n >= USER_ISOLATE_MIN_N and family is None and not model.factors.get(getattr(claim, "id", None)):
        # a claim the cost model was never measured on (a user's): its prediction is a guess, and a
        # symbolic blow-up in the worker (flint aborts when an allocation fails) would take the whole
        # run with it instead of leaving auto its modular fallback
        return True
    try:
        if costmodel.predict("exact", claim, n, r) >= ISOLATE_SECONDS:
            return True
        if n < ISOLATE_MIN_N:
            return False
        measured = model.measured.get("exact", {})
        top = measured.get(family or "") or min(measured.values(), default=0)
        return n > top or model.predict_memory("exact", claim, n, r) > ISOLATE_MEMORY_FRACTION * _memory_budget()
    except (ValueError, SizeError):
        return n >= ISOLATE_MIN_N


def run_exact_isolated(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
                       time_budget: float = EXACT_TIME_LIMIT, in_worker: bool = False) -> Result:
    """run_exact in a forked child (see :func:`isolates`) that is killed when it exceeds its budget
    (no hang, ever); the child inherits the memory budget (RLIMIT_AS) of the process it is forked
    from, a worker's is the run's.  A child that runs out of memory or dies gives ``inconclusive``
    with how it ended (``auto`` then goes on with the modular method), the parent is untouched.
    In-process, the budget is the deadline of :func:`time_limit`."""
    if _LOAN is not None and _LOAN.exact_seconds is not None:
        time_budget = min(time_budget, _LOAN.exact_seconds)
    if _LOAN is not None and _LOAN.term_products is not None:
        from stiefelsym.backends.polyfield import term_cap
        with term_cap(_LOAN.term_products):
            return _run_exact_isolated(claim, n, r, seed, func, time_budget, in_worker)
    return _run_exact_isolated(claim, n, r, seed, func, time_budget, in_worker)


def _run_exact_isolated(claim: Claim, n: int, r: int, seed: int, func: Callable | None, time_budget: float,
                        in_worker: bool) -> Result:
    if not isolates(claim, n, r, in_worker):
        if not in_worker:
            res = run_exact(claim, n, r, seed, func, time_budget)
            if _LOAN is not None and _LOAN.recording:
                _LOAN.exact_cost[(claim.id, n, r)] = res.seconds or 0.0
            return res
        # in the worker, whose heap (graphs of millions of nodes) every full collection scans again,
        # where a forked child's collections see only its own objects (the worker's are frozen for it)
        with spaced_collections():
            return run_exact(claim, n, r, seed, func, time_budget)
    from stiefelsym.run.isolate import ChildDied, HardTimeout, run_isolated
    t0 = time.perf_counter()
    res = _base_result(claim, n, r, "exact", None)
    res.verdict = "inconclusive"
    try:
        return run_isolated(lambda: _in_attempt_child(claim, n, r, seed, func, time_budget),
                            1.1 * time_budget + 1, _describe)
    except HardTimeout:
        res.message = f"symbolic computation exceeded its budget of {time_budget:.0f} s (stopped)"
    except ChildDied as exc:
        res.message = f"the symbolic attempt ended without a verdict: {exc}"
    refuted = _refuted_after_the_attempt(claim, n, r, seed, func, t0, time_budget)
    if refuted is not None:
        return refuted
    res.seconds = time.perf_counter() - t0
    return res


def _in_attempt_child(claim: Claim, n: int, r: int, seed: int, func: Callable | None, time_budget: float) -> Result:
    """run_exact in the forked child of :func:`run_exact_isolated`, which its parent stops at 1.1 times the budget
    and a second: a point tried after its own deadline ends half a second before that."""
    _ATTEMPT_ENDS.append(time.perf_counter() + 1.1 * time_budget + 0.5)
    try:
        return run_exact(claim, n, r, seed, func, time_budget)
    finally:
        _ATTEMPT_ENDS.pop()     # (where there is no fork, the attempt runs in this process)


#: seconds of the rational point tried after a symbolic attempt that ran out of time or memory (at most)
AFTER_ATTEMPT_SECONDS = 30.0
#: ... and it ends by this multiple of the attempt's own budget, counted from the attempt's start (the exact
#: method's budget is 0.7 of the run's under ``--method exact``, half of it at most under ``auto``: the point fits)
AFTER_ATTEMPT_END = 4 / 3
#: in a forked child of the attempt: when the point it may try must end (its parent stops it then), or None
_ATTEMPT_ENDS: list[float] = []


def _refuted_after_the_attempt(claim: Claim, n: int, r: int, seed: int, func: Callable | None, t0: float,
                               time_budget: float) -> Result | None:
    """The exact method's ``fails`` from the seed's first exact rational point of T*V, where the symbolic attempt
    ran out of its time or memory (a native abort, a stop by the parent) before the point was tried: a chart that
    tries the point first (the Cayley chart, and every chart for a claims file's claim) has done so inside the
    attempt, the others (the equivariant chart, the complex point's) had not.  None where the point does not refute
    the claim (a rank, a count, a nonvanishing claim, a residual that vanishes there, anything that goes wrong) or
    no time is left: the attempt's verdict stands.  The point is evaluated in a child of its own, within
    :data:`AFTER_ATTEMPT_SECONDS`, until :data:`AFTER_ATTEMPT_END` times the attempt's budget (``auto`` goes on
    with the modular method after it).  Its certificate does not name the budget (a record checked again under
    another budget says the same)."""
    from stiefelsym.run.isolate import ChildDied, HardTimeout, run_isolated
    if claim.expect == "nonzero":
        return None
    now = time.perf_counter()
    seconds = min(AFTER_ATTEMPT_SECONDS, AFTER_ATTEMPT_END * time_budget - (now - t0))
    if _ATTEMPT_ENDS:
        seconds = min(seconds, _ATTEMPT_ENDS[-1] - now)
    if seconds < 0.2:
        return None
    fn = func or claim.func

    def point() -> Result | None:
        cons = REALIZATIONS[claim.realization or "standard"]
        return _refuting_point(claim, n, r, seed, fn, _claim_graph(fn, n, r, (cons.name, cons.build)))
    try:
        found = run_isolated(point, seconds, _describe)
    except (HardTimeout, ChildDied):
        return None
    except Exception:   # noqa: BLE001 - the point decides nothing: the attempt's verdict stands
        return None
    if not isinstance(found, Result) or found.verdict != "fails" or not found.witness:
        return None
    res = _base_result(claim, n, r, "exact", seed)
    return _refuted_result(res, found, seed, RuntimeError("it ran out of its time or memory"), t0,
                           "the symbolic attempt ended without a verdict, and the point was evaluated after it")


def _describe(exc: BaseException) -> str:
    import traceback
    from stiefelsym.ir.seal import sealed
    where = ""
    # the innermost frame outside the engine (the claim's line); walk_tb reads each frame's file and line only,
    # where extract_tb also works out every frame's columns
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        name = frame.f_code.co_filename
        if "/stiefelsym/" not in name and not name.startswith("<"):
            # a claims file's code (run here after the seal, or in its tracing interpreter, which recorded the
            # place) can give its code objects any file name, a catalog module's too
            named_by_file = sealed() or getattr(exc, "_recorded_at", None) is not None
            where = (f" (at {name}:{lineno}, as the code names its file)" if named_by_file
                     else f" (at {_shown_path(name)}:{lineno})")
    text = str(exc)
    if type(exc) is RecursionError:         # Python's own message says neither whose frames nor what to do
        from stiefelsym.ir import recursion_text
        text = recursion_text()
    return f"{type(exc).__name__}: {text}{where}"


def _shown_path(name: str) -> str:
    """A claim's file as a message names it, where no claims file has been imported into the process (before the
    seal only the engine's, the catalog's and the caller's own code ran): a file of the catalog as proofs/<file>
    (the same text in every clone and installation), another file relative to the working directory when it is
    inside it."""
    import stiefelsym.proofs as catalog
    path = os.path.realpath(name)
    for folder in map(os.path.realpath, catalog.__path__):
        if os.path.dirname(path) == folder:
            return "proofs/" + os.path.basename(path)
    rel = os.path.relpath(path)
    return name if rel.startswith("..") else rel


METHOD_RUNNERS = {
    "exact": lambda c, n, r, seed, func=None, options=None: run_exact_isolated(c, n, r, seed, func),
    "rational": lambda c, n, r, seed, func=None, options=None: run_points(c, n, r, "rational", seed, func,
                                                                          options=options),
    "modular": lambda c, n, r, seed, func=None, options=None: run_points(c, n, r, "modular", seed, func,
                                                                         options=options),
    "float": lambda c, n, r, seed, func=None, options=None: run_float(c, n, r, seed, func, options),
    "ball": lambda c, n, r, seed, func=None, options=None: run_ball(c, n, r, seed, func, options),
}
