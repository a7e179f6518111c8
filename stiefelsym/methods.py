"""Verification methods: each turns (claim, n, r, seed) into one Result.

* ``exact``    symbolic (symengine): the residual is identically zero on a chart
               of the constraint set; the reduction used is stated.
* ``rational`` exact rationals at seeded random points of the Cayley chart,
               with the Schwartz-Zippel false-pass bound from a degree bound.
* ``modular``  the same over GF(p), p = 2^61 - 1.
* ``float``    float64 with a running error bound; mpmath escalation.
"""
from __future__ import annotations

import random
import signal
import time
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, Callable, Iterator

import mpmath

from .claims import Claim, Count, Rank
from .fields import (DegenerateError, Deg, DegreeField, ErrNum, Field, FloatField,
                     ModularField, RationalField, SymbolicBudget, SymbolicField)
from .matrix import Mat
from .results import CheckOutcome, Result
from .scene import CoordinateAccess, Scene, SizeError

EXACT_CAYLEY_MAX_N = 3       # the symbolic Cayley chart (used when coordinates are read)
EXACT_TIME_LIMIT = 120.0      # seconds per (claim, size) for the symbolic method
BUDGET = {"exact": 8, "rational": 10, "modular": 12, "float": 16, "auto": 12}
TRIALS = {"rational": 3, "modular": 2}
MAX_RESAMPLE = 8
FLOAT_RESOLUTION = 1e-8       # a pass must be able to see a relative residual this small
FLOAT_LADDER = (None, 30, 60, 120)


class BudgetError(ValueError):
    """A size beyond what a method is allowed to attempt."""


class ExactTimeout(Exception):
    pass


def check_budget(method: str, n: int, r: int) -> None:
    if r < 1:
        raise SizeError(f"r = {r} < 1: a Stiefel variety V(n, r) needs r >= 1")
    if r > n:
        raise SizeError(f"r = {r} > n = {n}: V(n, r) needs r <= n")
    limit = BUDGET.get(method)
    if limit is not None and n > limit:
        raise BudgetError(f"n = {n} is beyond the {method} method's budget (n <= {limit})")


@contextmanager
def time_limit(seconds: float) -> Iterator[None]:
    """Interrupt a symbolic computation that exceeds its budget (main thread only)."""
    if seconds is None or not hasattr(signal, "SIGALRM"):
        yield
        return
    try:
        old = signal.signal(signal.SIGALRM, _raise_timeout)
    except ValueError:  # not in the main thread
        yield
        return
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def _raise_timeout(signum, frame):
    raise ExactTimeout()


# ---------------------------------------------------------------------------
# flattening checks

def _entries(value: Any, prefix: str = "") -> list[tuple[str, Any]]:
    """(position, scalar) pairs of a residual: a Mat, a scalar, or a list/tuple/dict of them."""
    if isinstance(value, Mat):
        return [(f"{prefix}[{i + 1},{j + 1}]", value._a[i, j])
                for i in range(value.shape[0]) for j in range(value.shape[1])]
    if isinstance(value, dict):
        out = []
        for k, v in value.items():
            out.extend(_entries(v, f"{prefix}.{k}"))
        return out
    if isinstance(value, (list, tuple)):
        out = []
        for k, v in enumerate(value):
            out.extend(_entries(v, f"{prefix}#{k + 1}"))
        return out
    if isinstance(value, (str, bytes, float, complex, bool)) or value is None:
        raise TypeError(f"check {prefix or 'value'}: a residual must be a matrix or a scalar of the scene "
                        f"(use s.q(num, den) for constants), not {type(value).__name__}")
    return [(prefix or "value", value)]


def call_claim(func: Callable, scene: Any) -> dict[str, Any]:
    checks = func(scene)
    if not isinstance(checks, dict) or not checks:
        raise TypeError("a claim must return a non-empty dict of named checks")
    for k in checks:
        if not isinstance(k, str):
            raise TypeError("check names must be strings")
    return checks


@dataclass
class Evaluation:
    outcomes: list[CheckOutcome]
    nonzero: list[tuple[str, str, Any]]   # (check, position, value) of failing residual entries
    rank_problems: list[str]
    count_problems: list[str]


def _evaluate(checks: dict[str, Any], field: Field, rank_fn: Callable[[Rank], tuple[str, bool]] | None) -> Evaluation:
    outcomes, nonzero, rank_problems, count_problems = [], [], [], []
    for name, value in checks.items():
        if isinstance(value, Count):
            ok = value.value == value.expected
            detail = f"{value.meaning + ': ' if value.meaning else ''}{value.value} (paper: {value.expected})"
            outcomes.append(CheckOutcome(name, "count" if ok else "count-mismatch", detail))
            if not ok:
                count_problems.append(f"{name}: {detail}")
            continue
        if isinstance(value, Rank):
            if rank_fn is None:
                outcomes.append(CheckOutcome(name, "skipped", "ranks are decided by exact methods"))
                rank_problems.append(f"{name}: rank not decided by this method")
                continue
            detail, ok = rank_fn(value)
            outcomes.append(CheckOutcome(name, "rank" if ok else "rank-mismatch", detail))
            if not ok:
                rank_problems.append(f"{name}: {detail}")
            continue
        bad = [(pos, x) for pos, x in _entries(value, name) if not field.is_zero(x)]
        if bad:
            nonzero.extend((name, pos, x) for pos, x in bad)
            outcomes.append(CheckOutcome(name, "nonzero", f"{len(bad)} nonzero entries"))
        else:
            outcomes.append(CheckOutcome(name, "zero"))
    return Evaluation(outcomes, nonzero, rank_problems, count_problems)


def _base_result(claim: Claim, n: int | None, r: int | None, method: str, seed: int | None) -> Result:
    return Result(claim=claim.id, paper=list(claim.paper), section=claim.section, kind=claim.kind,
                  title=claim.title, statement=claim.statement, n=n, r=r, method=method,
                  verdict="error", expected=False, seconds=0.0, seed=seed)


def expected_verdict(claim: Claim, verdict: str, variant: str | None = None,
                     n: int | None = None, r: int | None = None) -> bool:
    """Whether a verdict is the one the catalog expects (documented errata fail)."""
    if variant is None and claim.expects_failure(n, r):
        return verdict == "fails"
    return verdict in ("proved", "checked", "numeric")


# ---------------------------------------------------------------------------
# the symbolic method

def _sympy_rows(M: Mat):
    import sympy
    return [[sympy.sympify(x) for x in row] for row in M._a.tolist()]


def _function_field_rank(M: Mat) -> int:
    dM = _domain_matrix(M)
    return 0 if dM is None else len(dM.rref_den()[2])   # fraction-free: pivots of the reduced form


def _domain_matrix(M: Mat):
    from sympy.polys.matrices import DomainMatrix
    rows = _sympy_rows(M)
    if not rows or not rows[0]:
        return None
    return DomainMatrix.from_list_sympy(len(rows), len(rows[0]), rows)


def _kernel_certificate(M: Mat, limit: int = 3) -> str:
    """Explicit kernel vectors over the function field, each checked to be annihilated by M."""
    dM = _domain_matrix(M)
    if dM is None:
        return ""
    K = dM.to_field().nullspace()
    vecs = K.to_Matrix().tolist() if K.shape[0] else []
    for v in vecs:
        import sympy
        if any(sympy.simplify(x) != 0 for x in (dM.to_Matrix() * sympy.Matrix(v))):
            return ""
    shown = "; ".join("(" + ", ".join(str(x) for x in v) + ")" for v in vecs[:limit])
    more = f" and {len(vecs) - limit} more" if len(vecs) > limit else ""
    return f"; explicit kernel ({len(vecs)} vectors, each checked M v = 0): {_short(shown + more, 400)}"


def _constant_minor_rank(M: Mat, field: Field) -> int:
    """Elimination using only nonzero numeric pivots: the product of the pivots is a
    constant (hence everywhere nonzero) minor of the returned size."""
    import symengine as se
    rows = [list(r) for r in M._a.tolist()]
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


def _exact_rank(R: Rank, field: Field) -> tuple[str, bool]:
    if R.generic:
        generic = _function_field_rank(R.matrix)
        ok = generic == R.expected
        kernel = _kernel_certificate(R.matrix) if generic < R.expected else ""
        return (f"rank over the function field Q(chart parameters) = {generic} "
                f"(paper: {R.expected}); two-sided: exact rank of the generic matrix{kernel}", ok)
    const = _constant_minor_rank(R.matrix, field)
    if const == R.expected == min(R.matrix.shape):
        return (f"a constant nonzero {const}x{const} minor: rank {const} at every point (full rank); "
                f"paper: {R.expected}", True)
    generic = _function_field_rank(R.matrix)
    ok = generic == R.expected and const == R.expected
    kernel = _kernel_certificate(R.matrix) if generic < R.expected else ""
    return (f"a constant nonzero {const}x{const} minor (rank >= {const} at every point) and rank "
            f"{generic} over the function field (rank <= {generic} at every point); paper: {R.expected}{kernel}", ok)


EQUIVARIANT_REDUCTION = (
    "equivariance: X = X0 = (E_1..E_r), P = (W; Z) with W skew, A generic symmetric; O(n) moves X0 to "
    "every point of V(n, r), and the residuals are covariant under (X, P, A) -> (gX, gP, gAg^T), g in O(n), "
    "because {why}")
COVARIANT_BY_CONSTRUCTION = "the claim read no coordinates of R^n (recorded by the engine)"
CAYLEY_REDUCTION = (
    "rational parametrization: X = first r columns of (I - S)(I + S)^{{-1}}{D}, P = XW + (I - XX^T)Z "
    "(S, W skew, Z arbitrary), A = diag(a); dense in T*V(n, r){comp}")


def run_exact(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
              time_budget: float | None = EXACT_TIME_LIMIT) -> Result:
    func = func or claim.func
    res = _base_result(claim, n, r, "exact", None)
    t0 = time.perf_counter()
    try:
        with time_limit(time_budget):
            field = SymbolicField()
            scene = Scene(n, r, field, chart="equivariant", realization=claim.realization)
            charts: list[tuple[Scene, str]] = []
            try:
                checks = call_claim(func, scene)
                coords = list(scene.tracker.used)
            except CoordinateAccess:
                coords = list(scene.tracker.used) or ["coordinates"]
            if not coords or claim.equivariance:
                why = (COVARIANT_BY_CONSTRUCTION if not coords else
                       f"(the claim reads {', '.join(coords)}) {claim.equivariance}")
                charts.append((scene, EQUIVARIANT_REDUCTION.format(why=why)))
                evaluations = [_evaluate(checks, field, lambda R: _exact_rank(R, field))]
            else:
                if n > EXACT_CAYLEY_MAX_N:
                    res.verdict = "inconclusive"
                    res.message = (f"the claim reads {', '.join(coords)}, so the equivariance reduction does not "
                                   f"apply, and the symbolic Cayley chart is limited to n <= {EXACT_CAYLEY_MAX_N}")
                    res.seconds = time.perf_counter() - t0
                    res.rerun = ""
                    return res
                evaluations = []
                for comp in ((0, 1) if r == n else (0,)):
                    f2 = SymbolicField()
                    sc = Scene(n, r, f2, chart="cayley", component=comp, realization=claim.realization)
                    ch = call_claim(func, sc)
                    evaluations.append(_evaluate(ch, f2, lambda R, f2=f2: _exact_rank(R, f2)))
                    desc = CAYLEY_REDUCTION.format(
                        D=" D" if r == n else "",
                        comp=(f"; component {comp + 1} of O(n) (D = {'I' if comp == 0 else 'diag(-1,1,..,1)'})"
                              if r == n else ""))
                    charts.append((sc, desc))
    except ExactTimeout:
        res.verdict = "inconclusive"
        res.message = f"symbolic computation exceeded its budget of {time_budget:.0f} s"
        res.seconds = time.perf_counter() - t0
        return res
    except SymbolicBudget as exc:
        res.verdict = "inconclusive"
        res.message = f"{exc} is beyond the symbolic method's budget"
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
    nonzero = [z for e in evaluations for z in e.nonzero]
    problems = [p for e in evaluations for p in e.rank_problems + e.count_problems]
    if claim.expect == "nonzero":
        if nonzero:
            res.verdict = "proved"
            res.certificate = f"the residual is not identically zero: {nonzero[0][1]} = {_short(nonzero[0][2])}"
        else:
            res.verdict = "fails"
            res.certificate = "the residual vanishes identically on the chart"
        return res
    if nonzero or problems:
        res.verdict = "fails"
        if nonzero:
            res.residual = f"{nonzero[0][1]} = {_short(nonzero[0][2])}"
            res.certificate = "the residual is a nonzero function on the chart"
            point = run_points(claim, n, r, "rational", seed, func, trials=1)
            if point.witness:
                res.witness, res.seed = point.witness, seed
                res.certificate += "; exact rational witness point attached"
        else:
            res.certificate = "; ".join(problems)
        return res
    res.verdict = "proved"
    res.certificate = "; ".join(o.detail for o in res.checks if o.detail) or "every residual entry expands to 0"
    return res


def _short(x: Any, limit: int = 160) -> str:
    s = str(x)
    return s if len(s) <= limit else s[: limit - 3] + "..."


# ---------------------------------------------------------------------------
# degree bounds (for Schwartz-Zippel)

@dataclass
class DegreeBound:
    numerator: int          # max numerator degree over residual entries / rank minors
    denominator: int        # total degree of all denominators met (for resampling)


def degree_bound(claim: Claim, n: int, r: int, func: Callable | None = None) -> DegreeBound:
    field = DegreeField()
    scene = Scene(n, r, field, chart="cayley", realization=claim.realization)
    checks = call_claim(func or claim.func, scene)
    num = 0
    for name, value in checks.items():
        if isinstance(value, Count):
            continue
        if isinstance(value, Rank):
            num = max(num, _rank_minor_degree(value, field))
            continue
        for _pos, x in _entries(value, name):
            if isinstance(x, Deg) and not x.zero:
                num = max(num, x.num)
    den = sum(field.factor_degree.values())
    return DegreeBound(num, den)


def _rank_minor_degree(R: Rank, field: DegreeField) -> int:
    cells = [x for x in R.matrix._a.flat if isinstance(x, Deg) and not x.zero]
    if not cells:
        return 0
    common: dict[int, int] = {}
    for x in cells:
        for k, e in x.den.items():
            common[k] = max(common.get(k, 0), e)
    dd = lambda den: sum(field.factor_degree[k] * e for k, e in den.items())
    top = max(x.num + dd({k: common[k] - x.den.get(k, 0) for k in common}) for x in cells)
    return (R.expected + 1) * top


# ---------------------------------------------------------------------------
# randomized exact methods

def _point_field(kind: str) -> Field:
    return RationalField() if kind == "rational" else ModularField()


def _point_rank(R: Rank, field: Field, bound_text: str) -> tuple[str, bool]:
    rk = field.rank(R.matrix._a.tolist())
    where = "at this exact point" if field.name == "rational" else "at this point mod p"
    if rk > R.expected:
        return f"rank {rk} {where} exceeds the paper's {R.expected} (certain: generic rank >= {rk})", False
    if rk < R.expected:
        return f"rank {rk} {where} (paper: {R.expected}); a special point or a wrong count", False
    return (f"rank {rk} {where}: generic rank >= {rk} (certain); generic rank <= {rk} "
            f"unless a ({rk + 1})-minor of degree <= {bound_text} vanishes here"), True


def _constant_rank(R: Rank) -> tuple[str, bool]:
    rk = RationalField().rank(R.matrix._a.tolist())
    return (f"the matrix is constant (no parameter enters); its exact rank over Q is {rk} "
            f"(paper: {R.expected})", rk == R.expected)


def run_points(claim: Claim, n: int, r: int, kind: str, seed: int, func: Callable | None = None,
               trials: int | None = None, options: dict | None = None) -> Result:
    func = func or claim.func
    trials = trials or TRIALS[kind]
    res = _base_result(claim, n, r, kind, seed)
    t0 = time.perf_counter()
    try:
        deg = degree_bound(claim, n, r, func)
    except CoordinateAccess as exc:
        res.verdict, res.message = "error", str(exc)
        return res
    field = _point_field(kind)
    S = field.sample_size
    per_trial = min(1.0, deg.numerator / max(S - deg.denominator, 1))
    res.reductions = [CAYLEY_REDUCTION.format(D=" D" if r == n else "",
                                              comp="; both components of O(n) alternate" if r == n else "")]
    if options and options.get("hard"):
        res.reductions.append(f"hard case: {options['hard'].description} (not uniform: no Schwartz-Zippel bound)")
    evaluations, resampled = [], 0
    witness = None
    # for r = n the constraint set has two components (det X = +-1): each gets ``trials`` points
    components = 2 if r == n else 1
    for t in range(trials * components):
        comp = t % components
        for attempt in range(MAX_RESAMPLE):
            rng = random.Random(f"{seed}|{claim.id}|{n}|{r}|{kind}|{t}|{attempt}")
            scene = Scene(n, r, field, chart="cayley", rng=rng, component=comp, realization=claim.realization,
                          options=options)
            try:
                checks = call_claim(func, scene)
                ev = _evaluate(checks, field, lambda R: _point_rank(R, field, str(deg.numerator)))
                break
            except (DegenerateError, ZeroDivisionError):
                resampled += 1
                continue
        else:
            res.verdict = "inconclusive"
            res.message = f"every one of {MAX_RESAMPLE} sampled points was degenerate (a pole or singular system)"
            res.seconds = time.perf_counter() - t0
            return res
        evaluations.append(ev)
        if ev.nonzero and witness is None:
            check, pos, val = ev.nonzero[0]
            witness = {"seed": seed, "trial": t, "attempt": attempt, "component": comp, "field": field.name,
                       "check": check, "entry": pos, "value": field.describe(val),
                       "point": {k: field.describe(v) for k, v in scene.params.items()}}
    res.seconds = time.perf_counter() - t0
    res.checks = [o for e in evaluations for o in e.outcomes]
    nonzero = [z for e in evaluations for z in e.nonzero]
    rank_bad = list(dict.fromkeys(p for e in evaluations for p in e.rank_problems))
    count_bad = list(dict.fromkeys(p for e in evaluations for p in e.count_problems))
    for o in res.checks:
        o.degree = deg.numerator
    note = f" ({resampled} degenerate samples redrawn)" if resampled else ""
    if claim.expect == "nonzero":
        if nonzero:
            res.verdict = "proved"
            res.witness = witness
            res.certificate = (f"nonzero value at a seeded point{' mod p' if kind == 'modular' else ''}: "
                               f"{witness['entry']} = {witness['value']}{note}")
        else:
            res.verdict = "fails"
            res.false_pass_bound = per_trial ** trials
            res.certificate = f"vanished at {trials * components} random points{note}"
        return res
    if nonzero or count_bad or any("exceeds" in p for p in rank_bad):
        res.verdict = "fails"
        res.witness = witness
        if nonzero:
            res.residual = f"{witness['entry']} = {witness['value']}"
            modnote = " (mod p: the numerator polynomial is nonzero)" if kind == "modular" else ""
            res.certificate = f"exact nonzero residual at a seeded point of T*V{modnote}{note}"
        else:
            res.certificate = "; ".join(count_bad + rank_bad)
        return res
    if rank_bad and not scene.params:
        # no chart parameter entered: the matrices are constant, and their rank over Q is exact
        exact_scene = Scene(n, r, RationalField(), chart="cayley", rng=random.Random(seed),
                            realization=claim.realization)
        ev = _evaluate(call_claim(func, exact_scene), exact_scene.field, lambda R: _constant_rank(R))
        if ev.rank_problems:
            res.verdict = "fails"
            res.certificate = "; ".join(ev.rank_problems)
            return res
        rank_bad = []
    if rank_bad:
        res.verdict = "inconclusive"
        res.message = "; ".join(rank_bad)
        return res
    if options and options.get("hard"):
        res.verdict = "checked"
        res.certificate = f"the residual vanishes exactly at the {trials * components} hard points{note}"
        return res
    res.verdict = "checked"
    res.false_pass_bound = per_trial ** trials
    per = f" on each of the {components} components of T*V" if components == 2 else ""
    res.certificate = (f"{trials} independent points{per}, parameters uniform from a set of size {_size(S)}; "
                       f"numerator degree <= {deg.numerator}; false-pass probability <= "
                       f"(d/(|S| - d_den))^{trials} = {res.false_pass_bound:.1e}{note}")
    return res


def _size(S: int) -> str:
    if S == 2**61 - 1:
        return "p = 2^61-1"
    if S > 10**6:
        return f"{S:.3g}"
    return str(S)


# ---------------------------------------------------------------------------
# floating point with error model and escalation

def run_float(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
              options: dict | None = None) -> Result:
    func = func or claim.func
    res = _base_result(claim, n, r, "float", seed)
    t0 = time.perf_counter()
    res.reductions = [CAYLEY_REDUCTION.format(D="", comp="") + "; running error analysis of every operation"]
    if options and options.get("hard"):
        res.reductions.append(f"hard case: {options['hard'].description}")
    log = []
    for dps in FLOAT_LADDER:
        field = FloatField(dps)
        rng = random.Random(f"{seed}|{claim.id}|{n}|{r}|float")
        ctx = mpmath.workdps(dps) if dps else _null()
        try:
            with ctx:
                scene = Scene(n, r, field, chart="cayley", rng=rng, realization=claim.realization,
                              options=options)
                checks = call_claim(func, scene)
                entries = []
                for name, value in checks.items():
                    if isinstance(value, (Rank, Count)):
                        continue
                    entries.extend(_entries(value, name))
        except DegenerateError as exc:
            log.append(f"{field.name}: {exc}")
            continue
        if not entries:
            res.verdict = "inconclusive"
            res.message = "not applicable: no residuals to evaluate in floating point (ranks are decided exactly)"
            res.seconds = time.perf_counter() - t0
            return res
        vals = [x for _, x in entries if isinstance(x, ErrNum)]
        worst = max(vals, key=lambda x: float(abs(x.v))) if vals else None
        emax = max((float(x.e) for x in vals), default=0.0)
        mmax = max((float(x.m) for x in vals), default=0.0)
        resolution = emax / mmax if mmax > 0 else 0.0
        bad = [(pos, x) for pos, x in entries if isinstance(x, ErrNum) and abs(x.v) > x.e]
        log.append(f"{field.name}: max |residual| {float(abs(worst.v)) if worst else 0:.2e}, "
                   f"error bound {emax:.2e}, term scale {mmax:.2e}")
        if bad:
            ex = run_points(claim, n, r, "rational", seed, func, trials=1, options=options)
            res.seconds = time.perf_counter() - t0
            res.residual = f"{bad[0][0]} = {bad[0][1]!r}"
            if ex.verdict == "fails":
                res.verdict = "fails"
                res.witness = ex.witness
                res.certificate = (f"{field.name} residual exceeds its error bound; confirmed by an exact "
                                   f"rational witness")
            else:
                res.verdict = "inconclusive"
                res.message = ("the floating-point residual exceeds its first-order error bound but the exact "
                               f"check passed ({ex.verdict}): the bound is too optimistic here")
            res.message = (res.message + " | " if res.message else "") + "; ".join(log)
            return res
        if resolution <= FLOAT_RESOLUTION:
            res.verdict = "numeric"
            res.false_pass_bound = None
            res.residual = f"{float(abs(worst.v)) if worst else 0:.2e}"
            res.certificate = (f"{field.name}: |residual| <= error bound {emax:.1e} at terms of size {mmax:.1e} "
                               f"(resolution {resolution:.1e})")
            res.message = "; ".join(log)
            res.seconds = time.perf_counter() - t0
            return res
    res.verdict = "inconclusive"
    res.message = "precision ladder exhausted without a resolving bound: " + "; ".join(log)
    res.seconds = time.perf_counter() - t0
    return res


@contextmanager
def _null():
    yield


def run_exact_isolated(claim: Claim, n: int, r: int, seed: int, func: Callable | None = None,
                       time_budget: float = EXACT_TIME_LIMIT) -> Result:
    """run_exact in a child process that is killed when it exceeds its budget (no hang, ever).
    Sizes n <= 3 stay in-process: their symbolic work is small and the fork would dominate."""
    if n <= 3:
        return run_exact(claim, n, r, seed, func, time_budget)
    from .isolate import HardTimeout, run_isolated
    import sympy.polys.matrices  # noqa: F401 (imported once here, not in every child)
    t0 = time.perf_counter()
    try:
        return run_isolated(lambda: run_exact(claim, n, r, seed, func, time_budget),
                            1.1 * time_budget + 1, _describe)
    except HardTimeout:
        res = _base_result(claim, n, r, "exact", None)
        res.verdict = "inconclusive"
        res.message = f"symbolic computation exceeded its budget of {time_budget:.0f} s (stopped)"
        res.seconds = time.perf_counter() - t0
        return res


def _describe(exc: BaseException) -> str:
    import traceback
    frames = [f for f in traceback.extract_tb(exc.__traceback__) if "/stiefelsym/" not in f.filename]
    where = f" (at {frames[-1].filename}:{frames[-1].lineno})" if frames else ""
    return f"{type(exc).__name__}: {exc}{where}"


METHOD_RUNNERS = {
    "exact": lambda c, n, r, seed, func=None, options=None: run_exact_isolated(c, n, r, seed, func),
    "rational": lambda c, n, r, seed, func=None, options=None: run_points(c, n, r, "rational", seed, func,
                                                                          options=options),
    "modular": lambda c, n, r, seed, func=None, options=None: run_points(c, n, r, "modular", seed, func,
                                                                         options=options),
    "float": lambda c, n, r, seed, func=None, options=None: run_float(c, n, r, seed, func, options),
}
