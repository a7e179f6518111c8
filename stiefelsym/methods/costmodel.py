"""The cost model: how long a (claim, n, r, method) run takes, and how much memory it holds, predicted
before it starts.

Time and peak memory are measured for each method on one representative claim per family of
claims (flows, big Lax, dual Lax, brackets, dimensions), at r = 2 and at r = ceil(n/2), from n = 4
up to the largest n each method reaches within a cap (:mod:`.costfit`).  Each (method, family)
is fitted by a sum of monomials in n and r with nonnegative coefficients,

    t(n, r) = sum_k c_k n^i_k r^j_k          (c_k >= 0, so t never decreases in n or in r)

whose terms are what a run does: a fixed cost per run (tracing, the scene, the verdict), O(n r)
and O(n r^2) products of n x r blocks, O(n^2) entries of n x n matrices (memory traffic, the
per-entry work of the bound and of the exact confirmations) and O(n^2 r), O(n^3) products of
n x n matrices; the symbolic methods get monomials up to degree 8.  The coefficients minimize
the relative error sum ((t_fit - t) / t)^2 (nonnegative least squares), so a run of 5 ms and
one of 15 s weigh the same, then are reweighted (Lawson) towards the least worst ratio
max |log(t_fit / t)|.  Peak memory (bytes above the worker's own) is fitted the same way
with the terms 1, n r, n^2.

The fitted coefficients and the measurements are stored in ``costmodel.json`` next to this
module (package data, read-only); ``stiefelsym speed`` measures again and writes the user's own
fit to the user cache folder (``measure``, ``fit``, :func:`user_model_file`), which is then used.

``check(method, claim, n, r, budget)`` is what the engine calls instead of fixed size
caps: it returns the predicted seconds, or raises ``BudgetError`` (exit status 2 on the
command line) with the prediction and a faster method to try; ``check_memory`` does the same
with the predicted peak memory against ``--memory``.  Only the size checks of the Stiefel
variety (1 <= r <= n) are absolute; everything else is a question of time and memory.
"""
from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any, Iterable, Sequence

#: seconds a single run may be predicted to take before the command line refuses it
DEFAULT_BUDGET = 3600.0
#: the package's fit (package data, read-only: ``stiefelsym speed`` never writes it)
MODEL_FILE = Path(__file__).with_name("costmodel.json")
#: the environment variable naming a cost model file to use instead of the user's or the package's
MODEL_ENV = "STIEFELSYM_COSTMODEL"
#: the form of the model files this module reads (older ones are fitted again by ``stiefelsym speed``)
MODEL_VERSION = 3
#: the methods the model covers (``auto`` and ``free`` are derived from them)
METHODS = ("exact", "rational", "modular", "float", "ball")
#: one representative catalog claim per family of claims
FAMILIES = {
    "flows": "neumann-flow",
    "lax": "neumann-lax",
    "dual-lax": "neumann-dual-lax-normal",
    "brackets": "momentum-maps-poisson",
    "dimensions": "adjoint-orbit-dimension",
}
#: the fastest to the slowest kind of answer: which method to suggest first
SUGGEST_ORDER = ("modular", "float", "ball", "rational", "exact")
#: what a verdict of each suggested method is worth, said with the suggestion
GRADES = {"modular": "randomized exact", "rational": "randomized exact", "float": "numerical evidence, not proof",
          "ball": "rigorous enclosures at a point, not proof", "exact": "symbolic proof"}
#: a dimension-free run does not depend on n; its time is below this (measured: milliseconds)
FREE_SECONDS = 5.0
#: a prediction for a claim the model did not measure is the largest of the families' times this
#: many times over (claims of one family differ by small constant factors)
UNKNOWN_CLAIM_FACTOR = 3.0
#: measured times below this are dominated by fixed overheads (the calibration's floor)
TIME_FLOOR = 2e-3
#: the small-r series is measured at this r
SMALL_R = 2

#: the ball method's predicted time over the float method's, where a model has no ball fit of its own
BALL_OVER_FLOAT = 40.0

#: the terms n^i r^j of a numeric method's time: a fixed cost, n x r blocks (n r, n r^2), the entries
#: of n x n matrices (n^2: memory traffic and per-entry work), n x n products (n^2 r, n^3)
NUMERIC_TERMS = ((0, 0), (1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (3, 0))
#: a symbolic method's time: polynomials whose size grows with every parameter, monomials to degree 8
SYMBOLIC_TERMS = ((0, 0),) + tuple((d - j, j) for d in range(1, 9) for j in (0, 1, 2) if d - j >= 1)
#: the terms of a run's peak memory: a fixed part, n x r blocks, n x n matrices
MEMORY_TERMS = ((0, 0), (1, 1), (2, 0))
TERMS = {"float": NUMERIC_TERMS, "ball": NUMERIC_TERMS, "modular": NUMERIC_TERMS,
         "rational": SYMBOLIC_TERMS, "exact": SYMBOLIC_TERMS}

#: used when costmodel.json is missing or unreadable: generous power laws (seconds)
_FALLBACK = {"exact": (math.log(1e-3), 6.0), "rational": (math.log(1e-3), 4.5),
             "modular": (math.log(1e-3), 4.0), "float": (math.log(1e-3), 4.5),
             "ball": (math.log(4e-2), 4.5)}


#: the extra power of n/n_measured of an exact prediction beyond the measured sizes
EXACT_EXTRAPOLATION_EXTRA = 2.0

#: rounds of Lawson's reweighting of a fit towards the least worst ratio (see :func:`fit_terms`)
MINIMAX_ROUNDS = 30

Poly = tuple[tuple[tuple[int, int], ...], tuple[float, ...]]


def poly_value(poly: Poly, n: int, r: int) -> float:
    """sum_k c_k n^i_k r^j_k."""
    terms, coefs = poly
    return sum(c * float(n) ** i * float(r) ** j for (i, j), c in zip(terms, coefs))


class BudgetError(ValueError):
    """A size beyond what a method is allowed to attempt."""


class CostModel:
    """Fitted sums of monomials in (n, r) per (method, family), for time and for peak memory, with
    the measurements they came from."""

    def __init__(self, data: dict[str, Any] | None = None) -> None:
        self.data = data or {}
        self.fits: dict[str, dict[str, Poly]] = {}
        self.memory: dict[str, dict[str, Poly]] = {}
        #: the largest n each (method, family) fit was measured at
        self.measured: dict[str, dict[str, int]] = {}
        for key, into in (("fits", self.fits), ("memory", self.memory)):
            for method, fams in (self.data.get(key) or {}).items():
                for fam, f in fams.items():
                    if "terms" not in f:          # a fit of an older form: not used
                        continue
                    into.setdefault(method, {})[fam] = (tuple((int(i), int(j)) for i, j in f["terms"]),
                                                        tuple(float(c) for c in f["coef"]))
                    if key == "fits" and f.get("n_max_measured"):
                        self.measured.setdefault(method, {})[fam] = int(f["n_max_measured"])
        self.claim_family: dict[str, str] = dict(self.data.get("claim_family") or {})
        #: per claim and method: its measured times over its family's prediction (the worst ratio)
        self.factors: dict[str, dict[str, Any]] = {
            cid: dict(fs) for cid, fs in (self.data.get("claim_factors") or {}).items()}

    @classmethod
    def load(cls, path: Path | str | None = None) -> "CostModel":
        """The model in ``path`` (default: :func:`model_file`); generous defaults, with a warning,
        when that file is missing or unreadable."""
        p = Path(path) if path is not None else model_file()
        try:
            data = json.loads(p.read_text(encoding="utf-8"))
            if not isinstance(data, dict):
                raise ValueError("not a JSON object")
            if data.get("version", 0) < MODEL_VERSION and p != MODEL_FILE:
                import warnings
                warnings.warn(f"stiefelsym: the cost model {p} is of an older form (version "
                              f"{data.get('version', 0)}); the package's is used (`stiefelsym speed` fits a new one)",
                              RuntimeWarning, stacklevel=2)
                return cls.load(MODEL_FILE)
            return cls(data)
        except (OSError, ValueError) as exc:
            import warnings
            warnings.warn(f"stiefelsym: the cost model {p} cannot be read ({exc}); predictions use rough "
                          "defaults", RuntimeWarning, stacklevel=2)
            return cls({})

    # -- prediction

    def family_of(self, claim: Any) -> str | None:
        """The family a claim represents (None for the others)."""
        cid = getattr(claim, "id", claim)
        if cid in self.claim_family:
            return self.claim_family[cid]
        for fam, rep in FAMILIES.items():
            if rep == cid:
                return fam
        return None

    def _calibrated(self, method: str, claim: Any, n: int, r: int) -> float | None:
        """A claim calibrated on the catalog's own runs: its kind's family times its factor at (n, r)."""
        cid = getattr(claim, "id", None)
        fs = self.factors.get(cid, {}) if cid else {}
        stairs = fs.get(method, fs.get("float") if method == "ball" else None)   # ball: as costly as float, relatively
        if not stairs:
            return None
        return _step_factor(stairs, n, r) * max(self._power(method, fam, n, r)
                                                for fam in kind_families(getattr(claim, "kind", "")))

    def _power(self, method: str, fam: str | None, n: int, r: int | None = None) -> float:
        """The family's fitted time at (n, r) (r = None: ceil(n/2)); a family the model did not
        measure gets the slowest family's time UNKNOWN_CLAIM_FACTOR times over."""
        r = max(1, (n + 1) // 2) if r is None else r
        fams = self.fits.get(method)
        if not fams:
            a, b = _FALLBACK.get(method, _FALLBACK["exact"])
            return math.exp(a + b * math.log(max(n, 1)))
        if fam in fams:
            t = poly_value(fams[fam], n, r)
        else:
            t = UNKNOWN_CLAIM_FACTOR * max(poly_value(p, n, r) for p in fams.values())
        if method == "exact":
            # beyond the sizes it was measured at, a symbolic run grows faster than its fit: the
            # generic objects alone (a symmetric A, an operator on so(n)) add O(n^2) parameters to
            # every polynomial; n = 300 was predicted at 3 s from n <= 8 and died of memory at 73 s
            top = self.measured.get(method, {}).get(fam or "") or min(self.measured.get(method, {}).values(),
                                                                      default=8)
            if n > top:
                t *= (n / top) ** EXACT_EXTRAPOLATION_EXTRA
        return t

    def predict(self, method: str, claim: Any, n: int, r: int) -> float:
        """Predicted wall seconds of one run (claim, n, r, method); r = n counts both components."""
        if method == "free":
            return FREE_SECONDS
        if method == "auto":
            # the exact attempt with its modular fallback up to the claim's symbolic budget, modular
            # beyond; kept monotone in n (a size beyond the budget is never predicted cheaper)
            k = min(n, getattr(claim, "exact_max_n", 5), _exact_cap())
            if n > k and n <= _exact_cap() and getattr(claim, "exact_at", lambda n, r: False)(n, r):
                k = n        # within the claim's symbolic budget in r (exact_max_r)
            below = self.predict("exact", claim, k, min(r, k)) + self.predict("modular", claim, k, min(r, k))
            return max(below, self.predict("modular", claim, n, r))
        if method == "ball" and not self.fits.get("ball"):
            # a model without a ball fit of its own: the float method's prediction times the measured
            # ratio of a ball check to a float64 check (bench/bench.py)
            return BALL_OVER_FLOAT * self.predict("float", claim, n, r)
        if method not in METHODS:
            raise ValueError(f"unknown method {method!r}")
        kind = getattr(claim, "kind", None)
        if method in ("float", "ball") and kind == "dim":
            return 0.0       # dimensions are integers: the numeric methods are not run on them
        fam = self.family_of(claim)
        t = self._calibrated(method, claim, n, r) if fam is None else None
        if t is None:
            t = self._power(method, fam, n, r)
        if r == n and n > 1:
            t *= 2.0         # both components of O(n) are sampled (V(1, 1) is two points: as cheap as V(2, 1))
        if method == "exact" and fam is None:
            # a claim timed on the catalog's runs (or a user's): its exact runs were all within its symbolic budget
            # (auto runs modular beyond it); the family representatives are timed at every size, so their fits hold
            t = max(t, beyond_symbolic_budget(claim, n, r))
        return t

    def predict_memory(self, method: str, claim: Any, n: int, r: int) -> float:
        """Predicted peak memory of one run in bytes (above the worker's own): the fit of the claim's
        family (a claim the model did not measure: the largest of its kind's families), never below
        _SQUARE_MATRICES n x n matrices of the method's entries."""
        if method == "free":
            return 0.0
        if method == "auto":
            k = min(n, getattr(claim, "exact_max_n", 5), _exact_cap())
            if n > k and n <= _exact_cap() and getattr(claim, "exact_at", lambda n, r: False)(n, r):
                k = n
            return max(self.predict_memory("exact", claim, k, min(r, k)), self.predict_memory("modular", claim, n, r))
        floor = float(_SQUARE_MATRICES * n * n * _ENTRY_BYTES.get(method, 8))
        fits = self.memory.get(method) or {}
        fam = self.family_of(claim)
        fams = [fam] if fam in fits else [f for f in kind_families(getattr(claim, "kind", "")) if f in fits]
        fitted = max((poly_value(fits[f], n, r) for f in fams), default=0.0)
        return max(fitted, floor)

    def largest_n(self, method: str, claim: Any, budget: float, r_of=lambda n: max(1, n // 2),
                  limit: int = 100000) -> int:
        """The largest n whose predicted time is within the budget (0 if none)."""
        lo = 0
        n = 1
        while n <= limit and self.predict(method, claim, n, r_of(n)) <= budget:
            lo, n = n, n * 2
        hi = min(n, limit + 1)
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if self.predict(method, claim, mid, r_of(mid)) <= budget:
                lo = mid
            else:
                hi = mid
        return lo

    def suggest(self, method: str, claim: Any, n: int, r: int, budget: float) -> str:
        """What to do instead of a run predicted to exceed the budget."""
        options = []
        for m in SUGGEST_ORDER:
            if m == method or (method == "auto" and m == "exact"):
                continue
            if m in ("float", "ball") and getattr(claim, "kind", None) == "dim":
                continue        # the numeric methods are not run on dimensions (integers)
            if n > _engine_cap(m):
                continue
            options.append((self.predict(m, claim, n, r), m))
        parts = []
        if options:
            t, m = min(options)
            grade = GRADES[m]
            within = "" if t <= budget else ", also beyond the budget"
            parts.append(f"try --method {m} (predicted {format_seconds(t)}, {grade}{within})")
        k = self.largest_n(method, claim, budget, r_of=lambda m: max(1, min(m, round(m * r / n))))
        if 0 < k < n:
            parts.append(f"with --method {method}, sizes up to n = {k} at the same r/n fit the budget")
        parts.append("--method free (every n, r at once, when the claim needs no coordinates)")
        parts.append("or a larger --budget")
        return "; ".join(parts)


#: the least predicted seconds of a symbolic run beyond its claim's symbolic budget (exact_max_n, exact_max_r,
#: exact_corank): the catalog's runs just beyond it took 19 s (2r-integrals at (4, 3), 2r-integrals-explicit at
#: (3, 3)) to over 45 s (2r-integrals at (5, 3)), where the fits made inside the budget predicted hundredths
BEYOND_BUDGET_SECONDS = 10.0


def beyond_symbolic_budget(claim: Any, n: int, r: int) -> float:
    """The least predicted seconds of a symbolic run of the claim at (n, r): 0 within its symbolic budget
    (``claim.exact_at``), else BEYOND_BUDGET_SECONDS times the square of n·r over the largest n·r of the budget
    (at least once).  A budget marks where the symbolic expansion stops being cheap, so no fit made inside it
    predicts beyond it: 2r-integrals at (9, 9) was predicted at 0.14 s and ran out of memory after 79 s."""
    exact_at = getattr(claim, "exact_at", None)
    if exact_at is None or exact_at(n, r):
        return 0.0
    top = getattr(claim, "exact_max_n", 5)
    largest = max([top * top] + [a * b for a, b in getattr(claim, "exact_max_r", ())]
                  + [a * a for a, _k in getattr(claim, "exact_corank", ())])
    return BEYOND_BUDGET_SECONDS * max(1.0, n * r / max(largest, 1)) ** 2


def kind_families(kind: str) -> tuple[str, ...]:
    """The measured families a claim of this kind is compared with."""
    return {"lax": ("lax", "dual-lax"), "pb": ("brackets",), "not": ("brackets",),
            "dim": ("dimensions",)}.get(kind, ("flows",))


def calibrate(doc: dict[str, Any], results: Iterable[Any], registry: Any = None) -> dict[str, Any]:
    """Per-claim factors from result records of catalog runs (``results.json`` entries: claim, kind, n,
    r, method, seconds, verdict): each run's ratio of its measured time (at least TIME_FLOOR) to its
    kind's prediction (at least 1/UNKNOWN_CLAIM_FACTOR, so that a claim timed only at tiny sizes keeps
    a margin), kept as a staircase [[n, r, ratio], ...]: a claim is predicted at (n, r) with the worst
    ratio of its runs at sizes n' <= n, r' <= r (never below what a smaller run took, relatively, and
    never decreasing in n or r).  Stored in ``doc['claim_factors']``."""
    cm = CostModel(doc)
    points: dict[str, dict[str, dict[tuple[int, int], float]]] = {}
    for r in results:
        get = r.get if isinstance(r, dict) else (lambda k, _r=r: getattr(_r, k, None))
        n, rr, method, secs = get("n"), get("r"), get("method"), get("seconds")
        if n is None or method not in METHODS or secs is None or get("verdict") in ("inconclusive", "error"):
            continue
        base = max(cm._power(method, fam, n, rr) for fam in kind_families(get("kind") or ""))
        if rr == n and n > 1:
            base *= 2.0              # as predict does: both components of O(n) are sampled
        ratio = max(float(secs), TIME_FLOOR) / base
        cur = points.setdefault(get("claim"), {}).setdefault(method, {})
        cur[(n, rr)] = max(cur.get((n, rr), 1.0 / UNKNOWN_CLAIM_FACTOR), ratio)
    doc["claim_factors"] = {c: {m: _staircase(p) for m, p in sorted(fs.items())} for c, fs in sorted(points.items())}
    return doc


def _staircase(pts: dict[tuple[int, int], float]) -> list[list[float]]:
    """The points (n, r, ratio) no other point makes redundant (one at n' <= n, r' <= r with a ratio at
    least as large), sorted."""
    keep = []
    for (n, r), f in sorted(pts.items()):
        if not any(n2 <= n and r2 <= r and f2 >= f and (n2, r2) != (n, r) for (n2, r2), f2 in pts.items()):
            keep.append([n, r, round(f, 4)])
    return keep


def _step_factor(stairs: Any, n: int, r: int) -> float:
    """A claim's factor at (n, r): the worst ratio of its runs at n' <= n, r' <= r (the smallest of its
    ratios below every run it has; a plain number is the factor everywhere)."""
    if isinstance(stairs, (int, float)):
        return float(stairs)
    below = [f for n2, r2, f in stairs if n2 <= n and r2 <= r]
    return max(below) if below else min(f for _, _, f in stairs)


def catalog_accuracy(doc: dict[str, Any], results: Iterable[Any], registry: Any,
                     floor: float = 0.05) -> dict[str, dict[str, Any]]:
    """Per method, over the catalog's own decided runs of at least ``floor`` seconds (``results.json``
    records): how many are predicted within a factor 3, how many below a third of their time, and the
    extreme and median ratios predicted / measured."""
    cost = CostModel(doc)
    ratios: dict[str, list[float]] = {}
    for r in results:
        n, method, secs = r.get("n"), r.get("method"), r.get("seconds")
        if n is None or method not in METHODS or secs is None or secs < floor or r.get("claim") not in registry \
                or r.get("verdict") in ("inconclusive", "error"):
            continue
        ratios.setdefault(method, []).append(cost.predict(method, registry.get(r["claim"]), n, r["r"]) / secs)
    out = {}
    for m in METHODS:
        xs = sorted(ratios.get(m, []))
        if xs:
            out[m] = {"runs": len(xs), "within_3x": sum(1 / 3 <= x <= 3 for x in xs),
                      "under_a_third": sum(x < 1 / 3 for x in xs), "min_ratio": round(xs[0], 3),
                      "median_ratio": round(xs[len(xs) // 2], 3), "max_ratio": round(xs[-1], 3)}
    return out


def format_seconds(t: float) -> str:
    if t >= 86400:
        return f"{t / 86400:.3g} days"
    if t >= 3600:
        return f"{t / 3600:.3g} h"
    if t >= 60:
        return f"{t / 60:.3g} min"
    return f"{t:.3g} s"


def _engine_cap(method: str) -> int:
    """A method's fixed size cap (none: the cost model decides)."""
    return 10**9


def _exact_cap() -> int:
    return _engine_cap("exact")


_MODEL: CostModel | None = None


def user_model_file() -> Path:
    """Where ``stiefelsym speed`` writes a user's own fit: the user cache folder (platformdirs)."""
    import platformdirs
    return Path(platformdirs.user_cache_dir("stiefelsym")) / "costmodel.json"


def model_file() -> Path:
    """The cost model in use: $STIEFELSYM_COSTMODEL if set, else the user's own fit if there is one
    (``stiefelsym speed``), else the package's."""
    env = os.environ.get(MODEL_ENV)
    if env:
        return Path(env)
    user = user_model_file()
    return user if user.is_file() else MODEL_FILE


def model() -> CostModel:
    """The cost model in use (:func:`model_file`: the user's own fit, else the package's), loaded once."""
    global _MODEL
    if _MODEL is None:
        _MODEL = CostModel.load()
    return _MODEL


def predict(method: str, claim: Any, n: int, r: int) -> float:
    return model().predict(method, claim, n, r)


def check(method: str, claim: Any, n: int, r: int, budget: float | None = DEFAULT_BUDGET,
          cost: CostModel | None = None) -> float:
    """The predicted seconds of a run; ``BudgetError`` (with the prediction and a faster method)
    if it exceeds ``budget`` (None: no budget).  ``SizeError`` if (n, r) is not a Stiefel variety.

    This replaces ``methods.check_budget`` (fixed caps on n): the engine calls it per planned
    (claim, size, method) with the run's budget."""
    from stiefelsym.scene import SizeError
    if r < 1:
        raise SizeError(f"r = {r} < 1: a Stiefel variety V(n, r) needs r >= 1")
    if r > n:
        raise SizeError(f"r = {r} > n = {n}: V(n, r) needs r <= n")
    cost = cost or model()
    t = cost.predict(method, claim, n, r)
    if budget is not None and t > budget and method in ("exact", "auto", "rational", "modular") \
            and _counts_of_integers(claim):
        return 0.0      # counts of plain integers: evaluated exactly at any size, whatever the model says
    if budget is not None and t > budget:
        cid = getattr(claim, "id", str(claim))
        raise BudgetError(f"{cid} ({n},{r}) with --method {method}: predicted {format_seconds(t)}, "
                          f"beyond the budget of {format_seconds(budget)} (--budget); "
                          f"{cost.suggest(method, claim, n, r, budget)}")
    return t


def _counts_of_integers(claim: Any) -> bool:
    """Whether the claim's checks are counts of plain integers (:func:`stiefelsym.ir.numbers_only`), judged at its
    smallest stated size (tracing it at the size asked could take as long as the run the budget refuses; a
    prediction, not a verdict: the run decides at its own size, within its own time budget)."""
    from stiefelsym.ir import numbers_only
    try:
        low = min(claim.sizes, key=lambda s: (s.n, s.r))
    except (AttributeError, TypeError, ValueError):
        return False
    return numbers_only(claim, low.n, low.r)


#: a lower bound of the n x n matrices a run holds at once, and of the bytes of one entry per method
_SQUARE_MATRICES = 4
_ENTRY_BYTES = {"float": 8, "modular": 8, "rational": 16, "exact": 16, "auto": 8, "ball": 56}


def format_bytes(x: float) -> str:
    if x >= 1 << 30:
        return f"{x / (1 << 30):.3g} GiB"
    if x >= 1 << 20:
        return f"{x / (1 << 20):.3g} MiB"
    return f"{x / 1024:.3g} KiB"


def check_memory(method: str, claim: Any, n: int, r: int, memory_gib: float | None,
                 cost: CostModel | None = None) -> float:
    """The predicted peak memory of a run in bytes; ``BudgetError`` (exit status 2 on the command
    line) if it exceeds the memory budget in GiB (None: no budget): refused up front instead of
    dying of memory, with the largest n at the same r/n that fits."""
    cost = cost or model()
    need = cost.predict_memory(method, claim, n, r)
    if memory_gib is None or method == "free":
        return need
    limit = memory_gib * (1 << 30)
    if need > limit and method in ("exact", "auto", "rational", "modular") and _counts_of_integers(claim):
        return 0.0      # counts of plain integers: a few integers at any size
    if need > limit:
        cid = getattr(claim, "id", str(claim))
        hint = ""
        k, hi = 0, n
        while hi - k > 1:                  # the predicted memory grows with n: bisect
            mid = (k + hi) // 2
            if cost.predict_memory(method, claim, mid, max(1, min(mid, round(mid * r / n)))) <= limit:
                k = mid
            else:
                hi = mid
        hint = (f"sizes up to n = {k} at the same r/n fit it, or a larger --memory" if k >= 1
                else "only a larger --memory fits it")
        raise BudgetError(f"{cid} ({n},{r}) with --method {method}: predicted peak memory {format_bytes(need)}, "
                          f"beyond the memory budget of {memory_gib:g} GiB (--memory); {hint}")
    return need


# --------------------------------------------------------------------------- measuring and fitting

def fit(points: Sequence[tuple[int, float]]) -> tuple[float, float] | None:
    """(a, b) with t <= exp(a) n**b at every measured point, b >= 0; None without data.  (A single
    power law: what a speed series uses to predict its next size from the sizes so far, and the
    cost model's earlier form, which fitted at small n and extrapolated, under-predicted at scale.)

    Least squares of log t against log n (points above TIME_FLOOR), then a raised to the
    upper envelope of all points."""
    pts = [(n, max(t, 1e-6)) for n, t in points if n >= 1 and t is not None]
    if not pts:
        return None
    big = [(n, t) for n, t in pts if t >= TIME_FLOOR and n >= 2]
    b = 0.0
    if len({n for n, _ in big}) >= 2:
        xs = [math.log(n) for n, _ in big]
        ys = [math.log(t) for _, t in big]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        sxx = sum((x - mx) ** 2 for x in xs)
        sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
        b = max(0.0, sxy / sxx) if sxx > 0 else 0.0
    a = max(math.log(t) - b * math.log(n) for n, t in pts)
    return a, b


def fit_terms(points: Sequence[tuple[int, int, float]], terms: Sequence[tuple[int, int]],
              rounds: int = MINIMAX_ROUNDS) -> list[float]:
    """Nonnegative c_k making sum_k c_k n^i_k r^j_k close to y at every point (n, r, y) in ratio.

    First the least relative error, sum ((fit - y) / y)^2 (nonnegative least squares, each column
    scaled to its largest entry), so that small and large values weigh the same; then Lawson's
    reweighting towards the least worst ratio: each round weighs every point by its share of
    |log(fit / y)|, and the coefficients with the smallest max |log(fit / y)| are kept."""
    import numpy as np
    from scipy.optimize import nnls
    pts = [(n, r, y) for n, r, y in points if y and y > 0]
    if not pts:
        return [0.0] * len(terms)
    A = np.array([[float(n) ** i * float(r) ** j / y for i, j in terms] for n, r, y in pts])
    scale = A.max(axis=0)
    scale[scale == 0] = 1.0
    A = A / scale
    w = np.ones(len(pts))
    best, best_err = None, math.inf
    for _ in range(rounds + 1):
        sq = np.sqrt(w)
        c, _ = nnls(A * sq[:, None], sq, maxiter=50 * len(terms))
        fitted = A @ c
        if not np.all(fitted > 0):
            break
        err = np.abs(np.log(fitted))
        worst = float(err.max())
        if worst < best_err - 1e-12:
            best, best_err = c, worst
        if worst == 0.0:
            break
        w = w * err
        w = w / w.sum()
        w = np.maximum(w, 1e-12)
    if best is None:
        best = c
    return [float(x) for x in best / scale]


def _fit_doc(points: list[tuple[int, int, float]], terms: Sequence[tuple[int, int]]) -> dict[str, Any]:
    coef = fit_terms(points, terms)
    used = [(t, c) for t, c in zip(terms, coef) if c > 0]
    return {"terms": [list(t) for t, _ in used], "coef": [float(f"{c:.6g}") for _, c in used],
            "n_max_measured": max(n for n, _, _ in points), "points": [list(p) for p in points]}


def build(records: Sequence[dict[str, Any]], note: str = "") -> dict[str, Any]:
    """The JSON document of a cost model from measurement records (family, claim, method, n, r,
    seconds, verdict, peak_bytes): per method and family, the time fit (``fits``) and the peak
    memory fit (``memory``) over every decided run, whatever its r."""
    fits: dict[str, dict[str, Any]] = {}
    memory: dict[str, dict[str, Any]] = {}
    groups: dict[tuple[str, str], list[tuple[int, int, float, float | None]]] = {}
    for rec in records:
        if rec.get("verdict") in ("inconclusive", "error") or rec.get("seconds") is None:
            continue            # a run stopped by its budget only bounds the time from below
        groups.setdefault((rec["method"], rec["family"]), []).append(
            (rec["n"], rec["r"], float(rec["seconds"]), float(rec["peak_bytes"]) if rec.get("peak_bytes") else None))
    for (method, fam), g in sorted(groups.items()):
        # every run is a point (n = 4, r = 2 is in both series: both are fitted)
        g = sorted(g, key=lambda p: (p[0], p[1], p[2]))
        fits.setdefault(method, {})[fam] = _fit_doc([(n, r, t) for n, r, t, _ in g], TERMS.get(method, SYMBOLIC_TERMS))
        mpts = [(n, r, m) for n, r, _, m in g if m]
        if mpts:
            memory.setdefault(method, {})[fam] = _fit_doc(mpts, MEMORY_TERMS)
    return {
        "version": MODEL_VERSION,
        "model": ("t(n, r) = sum_k c_k n^i r^j seconds and peak memory m(n, r) = sum_k d_k n^i r^j bytes, "
                  "c_k, d_k >= 0 minimizing the relative error over the runs at r = 2 and r = ceil(n/2) "
                  "from n = 4 up to the largest n within the cap; r = n: twice (two components)"),
        "note": note,
        "families": dict(FAMILIES),
        "claim_family": {cid: fam for fam, cid in FAMILIES.items()},
        "fits": fits,
        "memory": memory,
        "records": list(records),
    }


def save(doc: dict[str, Any], path: Path | str | None = None) -> Path:
    """Write a fit to ``path`` (default: the user's cache folder, :func:`user_model_file`)."""
    from stiefelsym.results import write_atomic
    p = Path(path) if path is not None else user_model_file()
    p.parent.mkdir(parents=True, exist_ok=True)
    write_atomic(p, json.dumps(doc, indent=1, sort_keys=False) + "\n")
    global _MODEL
    _MODEL = None
    return p


def save_figure(fig: Any, out_dir: Path, stem: str) -> list[Path]:
    """``stem``.png and ``stem``.pdf, with no date or producer in the files (the same data give the
    same bytes); the figure is closed."""
    import matplotlib.pyplot as plt
    paths = []
    for ext in ("png", "pdf"):
        p = out_dir / f"{stem}.{ext}"
        fig.savefig(p, dpi=110, metadata={"CreationDate": None, "Creator": None, "Producer": None}
                    if ext == "pdf" else {"Software": None})
        paths.append(p)
    plt.close(fig)
    return paths


_COLORS = {"exact": "C0", "rational": "C1", "modular": "C2", "float": "C3", "ball": "C4"}


def plot(doc: dict[str, Any], out_dir: Path | str) -> list[Path]:
    """Time against n with the fitted model at r = 2 and r = ceil(n/2), one panel per family (PNG
    and PDF)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    cost = CostModel(doc)
    fams = list(doc.get("families") or FAMILIES)
    # a grid three panels wide, legible at the page's width
    cols = min(3, len(fams))
    rows = -(-len(fams) // cols)
    fig, grid_axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows + 0.6), sharey=True, squeeze=False)
    axes = [ax for row in grid_axes for ax in row]
    for ax in axes[len(fams):]:
        ax.set_visible(False)
    for ax, fam in zip(axes, fams):
        for method, fits in (doc.get("fits") or {}).items():
            f = fits.get(fam)
            if not f:
                continue
            for small, marker, style in ((True, "^", ":"), (False, "o", "-")):
                pts = [(n, t) for n, r, t in f["points"] if (r == SMALL_R) == small and (small or r != SMALL_R or n <= 4)]
                if not pts:
                    continue
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-5) for p in pts], marker, color=_COLORS.get(method),
                          ms=4, mfc="none" if small else None, label=f"{method} r={'2' if small else 'n/2'}")
                top = max(p[0] for p in pts)
                grid = sorted({max(4, round(4 * (top / 4) ** (k / 40))) for k in range(41)})
                ax.loglog(grid, [cost._power(method, fam, x, SMALL_R if small else (x + 1) // 2) for x in grid],
                          style, color=_COLORS.get(method), lw=1, alpha=0.7)
        ax.set_title(f"{fam} ({doc.get('families', FAMILIES).get(fam, '')})", fontsize=10)
        ax.set_xlabel("n")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
    for row in grid_axes:
        row[0].set_ylabel("seconds per run")
    axes[0].legend(fontsize=7, ncol=2)
    fig.suptitle("Cost model: time against n per method; r = ceil(n/2) (filled, solid), r = 2 (open, dotted);\n"
                 "lines: the fitted sums of monomials in n and r", fontsize=11)
    fig.tight_layout()
    return save_figure(fig, out_dir, "costmodel")


def _terms_text(f: dict[str, Any]) -> str:
    parts = []
    for (i, j), c in zip(f["terms"], f["coef"]):
        mono = "".join(x for x in ("n" if i == 1 else f"n^{i}" if i else "", "r" if j == 1 else f"r^{j}" if j else ""))
        parts.append(f"{c:.2g}" + (f" {mono}" if mono else ""))
    return " + ".join(parts) or "0"


def table(doc: dict[str, Any]) -> str:
    """The fitted time and memory models as a Markdown table."""
    cost = CostModel(doc)
    lines = ["| method | family | t(n, r) seconds | measured up to n | (100,2) | (100,50) | (1000,2) "
             "| peak memory (1000,2) |",
             "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |"]
    for method, fits in sorted((doc.get("fits") or {}).items()):
        for fam, f in sorted(fits.items()):
            mem = cost.memory.get(method, {}).get(fam)
            lines.append(f"| {method} | {fam} | {_terms_text(f)} | {f['n_max_measured']} | "
                         + " | ".join(format_seconds(cost._power(method, fam, n, r))
                                      for n, r in ((100, 2), (100, 50), (1000, 2)))
                         + f" | {'-' if mem is None else format_bytes(poly_value(mem, 1000, 2))} |")
    return "\n".join(lines) + "\n"


def accuracy(doc: dict[str, Any], registry: Any) -> list[dict[str, Any]]:
    """Predicted against measured seconds (and peak memory) for every decided run of the fit
    (``doc["records"]``, n >= 4): one row per record, with the ratios predicted / measured."""
    cost = CostModel(doc)
    rows = []
    for rec in doc.get("records") or []:
        if rec["claim"] not in registry or rec.get("seconds") is None or rec["seconds"] <= 0 or rec["n"] < 4 \
                or rec.get("verdict") in ("inconclusive", "error"):
            continue
        claim = registry.get(rec["claim"])
        pred = cost.predict(rec["method"], claim, rec["n"], rec["r"])
        row = dict(rec, predicted=pred, ratio=pred / rec["seconds"])
        if rec.get("peak_bytes"):
            row["memory_ratio"] = cost.predict_memory(rec["method"], claim, rec["n"], rec["r"]) / rec["peak_bytes"]
        rows.append(row)
    return rows


def plot_accuracy(rows: list[dict[str, Any]], out_dir: Path | str) -> list[Path]:
    """Predicted against measured seconds, per method, with the band of a factor 3 (PNG and PDF)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    out_dir = Path(out_dir)
    fig, ax = plt.subplots(figsize=(6.4, 5.4))
    lo = min([r["seconds"] for r in rows] + [r["predicted"] for r in rows] + [1e-3]) / 2
    hi = max([r["seconds"] for r in rows] + [r["predicted"] for r in rows] + [1.0]) * 2
    grid = [lo, hi]
    ax.fill_between(grid, [g / 3 for g in grid], [g * 3 for g in grid], color="0.85", alpha=0.6, lw=0,
                    label="within a factor 3")
    ax.loglog(grid, grid, "k-", lw=1, label="predicted = measured")
    for method, color in _COLORS.items():
        pts = [(r["seconds"], r["predicted"]) for r in rows if r["method"] == method]
        if pts:
            inside = sum(1 / 3 <= p / s <= 3 for s, p in pts)
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o", ms=3.5, color=color, alpha=0.8,
                      label=f"{method} ({inside}/{len(pts)} within 3x)")
    ax.set_xlim(*grid)
    ax.set_ylim(*grid)
    ax.set_xlabel("measured seconds")
    ax.set_ylabel("predicted seconds")
    ax.set_title("Cost model: predicted against measured, r = 2 and r = ceil(n/2), n >= 4", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    return save_figure(fig, out_dir, "costmodel-accuracy")


def accuracy_summary(rows: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """Per method: the measurements, how many are predicted within a factor 3 (time, and peak memory),
    the largest n, and the extreme ratios predicted / measured (below 1: predicted too fast, the case
    a budget must not meet)."""
    out: dict[str, dict[str, Any]] = {}
    for m in METHODS:
        sel = [r for r in rows if r["method"] == m]
        if sel:
            rs = [r["ratio"] for r in sel]
            ms = [r["memory_ratio"] for r in sel if "memory_ratio" in r]
            out[m] = {"runs": len(rs), "within_3x": sum(1 / 3 <= x <= 3 for x in rs),
                      "min_ratio": round(min(rs), 3), "max_ratio": round(max(rs), 3),
                      "largest_n": max(r["n"] for r in sel),
                      "memory_within_3x": sum(1 / 3 <= x <= 3 for x in ms), "memory_runs": len(ms)}
    return out
