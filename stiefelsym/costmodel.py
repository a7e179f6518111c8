"""The cost model: how long a (claim, n, r, method) run takes, predicted before it starts.

Time against n is measured for each method on one representative claim per family
of claims (flows, big Lax, dual Lax, brackets, dimensions) and fitted per method and
family by a power law

    t(n) = exp(a) * n**b          (b >= 0, so the prediction never decreases with n)

whose constant ``a`` is then raised until the curve lies above every measured point
(an upper envelope: the prediction is never below what was seen).  The fitted
coefficients and the measurements are stored in ``costmodel.json`` next to this
module (package data, read-only); ``stiefelsym speed`` measures again and writes the user's own
fit to the user cache folder (``measure``, ``fit``, :func:`user_model_file`), which is then used.

``check(method, claim, n, r, budget)`` is what the engine calls instead of fixed size
caps: it returns the predicted seconds, or raises ``BudgetError`` (exit status 2 on the
command line) with the prediction and a faster method to try.  Only the size checks of
the Stiefel variety (1 <= r <= n) are absolute; everything else is a question of time.
"""
from __future__ import annotations

import json
import math
import os
import platform
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Iterable, Sequence

#: seconds a single run may be predicted to take before the command line refuses it
DEFAULT_BUDGET = 3600.0
#: the package's fit (package data, read-only: ``stiefelsym speed`` never writes it)
MODEL_FILE = Path(__file__).with_name("costmodel.json")
#: the environment variable naming a cost model file to use instead of the user's or the package's
MODEL_ENV = "STIEFELSYM_COSTMODEL"
#: the methods the model covers (``auto`` and ``free`` are derived from them)
METHODS = ("exact", "rational", "modular", "float")
#: one representative catalog claim per family of claims
FAMILIES = {
    "flows": "neumann-flow",
    "lax": "neumann-lax",
    "dual-lax": "neumann-dual-lax-normal",
    "brackets": "momentum-maps-poisson",
    "dimensions": "adjoint-orbit-dimension",
}
#: the fastest to the slowest kind of answer: which method to suggest first
SUGGEST_ORDER = ("modular", "float", "rational", "exact")
#: a dimension-free run does not depend on n; its time is below this (measured: milliseconds)
FREE_SECONDS = 5.0
#: a prediction for a claim the model did not measure is the largest of the families' times this
#: many times over (claims of one family differ by small constant factors)
UNKNOWN_CLAIM_FACTOR = 3.0
#: measured times below this are dominated by fixed overheads and are not fitted as a power of n
TIME_FLOOR = 2e-3
#: the small-r series is measured at this r (``fits_small``), to n = 200
SMALL_R = 2
#: the methods and sizes of the small-r series (the methods that reach n = 200 at r = 2)
SMALL_NS = {"float": [4, 8, 16, 32, 64, 100, 200], "modular": [4, 8, 16, 32, 64, 100, 200]}

#: the ball method's predicted time over the float method's (the ball check of LA1 against the float64
#: check at n = 16 .. 200 in bench/bench.py, rounded up: the ball method is not fitted on its own yet)
BALL_OVER_FLOAT = 40.0

#: used when costmodel.json is missing or unreadable: generous power laws (seconds)
_FALLBACK = {"exact": (math.log(1e-3), 6.0), "rational": (math.log(1e-3), 4.5),
             "modular": (math.log(1e-3), 4.0), "float": (math.log(1e-3), 4.5)}


#: the extra power of n/n_measured of an exact prediction beyond the measured sizes
EXACT_EXTRAPOLATION_EXTRA = 2.0


class BudgetError(ValueError):
    """A size beyond what a method is allowed to attempt."""


class CostModel:
    """Fitted power laws per (method, family), with the measurements they came from."""

    def __init__(self, data: dict[str, Any] | None = None) -> None:
        self.data = data or {}
        self.fits: dict[str, dict[str, tuple[float, float]]] = {}
        self.square: dict[str, dict[str, tuple[float, float]]] = {}
        self.small: dict[str, dict[str, tuple[float, float]]] = {}
        #: the largest n each (method, family) fit was measured at
        self.measured: dict[str, dict[str, int]] = {}
        for key, into in (("fits", self.fits), ("fits_square", self.square), ("fits_small", self.small)):
            for method, fams in (self.data.get(key) or {}).items():
                for fam, coef in fams.items():
                    into.setdefault(method, {})[fam] = (float(coef["a"]), float(coef["b"]))
                    if key == "fits" and coef.get("n_max_measured"):
                        self.measured.setdefault(method, {})[fam] = int(coef["n_max_measured"])
        self.claim_family: dict[str, str] = dict(self.data.get("claim_family") or {})
        #: per claim and method: its measured times over its family's prediction (the worst ratio)
        self.factors: dict[str, dict[str, float]] = {
            cid: {m: float(f) for m, f in fs.items()} for cid, fs in (self.data.get("claim_factors") or {}).items()}

    @classmethod
    def load(cls, path: Path | str | None = None) -> "CostModel":
        """The model in ``path`` (default: :func:`model_file`); generous defaults, with a warning,
        when that file is missing or unreadable."""
        p = Path(path) if path is not None else model_file()
        try:
            return cls(json.loads(p.read_text(encoding="utf-8")))
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
        """A claim calibrated on the catalog's own runs: its kind's family times its factor."""
        cid = getattr(claim, "id", None)
        f = self.factors.get(cid, {}).get(method) if cid else None
        if f is None:
            return None
        return f * max(self._power(method, fam, n, r) for fam in kind_families(getattr(claim, "kind", "")))

    def _power(self, method: str, fam: str | None, n: int, r: int | None = None) -> float:
        """r = n: the square fit; n//2 <= r <= n/2: the fit at r = ceil(n/2); between n/2 and n:
        log-linear in r from one to the other; r <= SMALL_R: the small-r fit (measured at r = 2,
        never above the r = n/2 fit); between SMALL_R and n//2: log-linear in r from it to the
        r = n/2 fit (so the prediction never decreases in r either)."""
        half = self._power1(self.fits, method, fam, n)
        if r is not None and n > 2 * SMALL_R and r < max(n // 2, SMALL_R + 1) and self.small.get(method) \
                and (fam in self.small[method] or fam is None):
            # never below the r = ceil(n/2) fit at n = 2 SMALL_R (where r = SMALL_R is that series),
            # never above the r = ceil(n/2) fit at n: monotone in n and in r
            floor = self._power1(self.fits, method, fam, 2 * SMALL_R)
            small = min(half, max(self._power1(self.small, method, fam, n), floor))
            if r <= SMALL_R:
                return small
            w = (r - SMALL_R) / (n // 2 - SMALL_R)
            return math.exp((1 - w) * math.log(small) + w * math.log(half))
        if r is None or not self.square.get(method):
            return half
        full = max(self._power1(self.square, method, fam, n), half)
        w = max(0.0, (r - n / 2) / (n / 2)) if n > 1 else 0.0     # V(1, 1): no fit of its own
        return math.exp((1 - w) * math.log(half) + w * math.log(full))

    def _power1(self, table: dict, method: str, fam: str | None, n: int) -> float:
        t = self._power1_fit(table, method, fam, n)
        if method == "exact":
            # beyond the sizes it was measured at, a symbolic run grows faster than its fit: the
            # generic objects alone (a symmetric A, an operator on so(n)) add O(n^2) parameters to
            # every polynomial; n = 300 was predicted at 3 s from n <= 8 and died of memory at 73 s
            top = self.measured.get(method, {}).get(fam) or min(self.measured.get(method, {}).values(), default=8)
            if n > top:
                t *= (n / top) ** EXACT_EXTRAPOLATION_EXTRA
        return t

    def _power1_fit(self, table: dict, method: str, fam: str | None, n: int) -> float:
        fams = table.get(method)
        if not fams:
            a, b = _FALLBACK.get(method, _FALLBACK["exact"])
            return math.exp(a + b * math.log(max(n, 1)))
        if fam in fams:
            a, b = fams[fam]
            return math.exp(a + b * math.log(max(n, 1)))
        # not a measured claim: the slowest family, with a margin
        return UNKNOWN_CLAIM_FACTOR * max(math.exp(a + b * math.log(max(n, 1))) for a, b in fams.values())

    def predict(self, method: str, claim: Any, n: int, r: int) -> float:
        """Predicted wall seconds of one run (claim, n, r, method); r = n counts both components."""
        if method == "free":
            return FREE_SECONDS
        if method == "auto":
            # the exact attempt with its modular fallback up to the claim's symbolic budget, modular
            # beyond; kept monotone in n (a size beyond the budget is never predicted cheaper)
            k = min(n, getattr(claim, "exact_max_n", 5), _exact_cap())
            below = self.predict("exact", claim, k, min(r, k)) + self.predict("modular", claim, k, min(r, k))
            return max(below, self.predict("modular", claim, n, r))
        if method == "ball":
            # not fitted yet: the float method's prediction times the measured ratio of a ball check
            # to a float64 check (bench/bench.py), with the float method's own kind rules
            return BALL_OVER_FLOAT * self.predict("float", claim, n, r)
        if method not in METHODS:
            raise ValueError(f"unknown method {method!r}")
        kind = getattr(claim, "kind", None)
        if method == "float" and kind == "dim":
            return 0.0       # dimensions are integers: the float method is not run on them
        fam = self.family_of(claim)
        t = self._calibrated(method, claim, n, r) if fam is None else None
        if t is None:
            t = self._power(method, fam, n, r)
        if r == n and not self.square.get(method):
            t *= 2.0         # both components of O(n) are sampled
        return t

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
            if m == "float" and getattr(claim, "kind", None) == "dim":
                continue
            if n > _engine_cap(m):
                continue
            options.append((self.predict(m, claim, n, r), m))
        parts = []
        if options:
            t, m = min(options)
            grade = {"modular": "randomized exact", "rational": "randomized exact",
                     "float": "numerical evidence, not proof", "exact": "symbolic proof"}[m]
            within = "" if t <= budget else ", also beyond the budget"
            parts.append(f"try --method {m} (predicted {format_seconds(t)}, {grade}{within})")
        k = self.largest_n(method, claim, budget, r_of=lambda m: max(1, min(m, round(m * r / n))))
        if 0 < k < n:
            parts.append(f"with --method {method}, sizes up to n = {k} at the same r/n fit the budget")
        parts.append("--method free (every n, r at once, when the claim needs no coordinates)")
        parts.append("or a larger --budget")
        return "; ".join(parts)


def kind_families(kind: str) -> tuple[str, ...]:
    """The measured families a claim of this kind is compared with."""
    return {"lax": ("lax", "dual-lax"), "pb": ("brackets",), "not": ("brackets",),
            "dim": ("dimensions",)}.get(kind, ("flows",))


def calibrate(doc: dict[str, Any], results: Iterable[Any], registry: Any = None) -> dict[str, Any]:
    """Per-claim factors from result records of catalog runs (``results.json`` entries: claim, kind, n,
    r, method, seconds, verdict): the worst ratio of a claim's measured time to its kind's prediction,
    over its runs that took at least TIME_FLOOR (at least 1/UNKNOWN_CLAIM_FACTOR, so that a claim
    timed only at tiny sizes keeps a margin).  Stored in ``doc['claim_factors']``."""
    cm = CostModel(doc)
    ratios: dict[str, dict[str, float]] = {}
    for r in results:
        get = r.get if isinstance(r, dict) else (lambda k, _r=r: getattr(_r, k, None))
        n, rr, method, secs = get("n"), get("r"), get("method"), get("seconds")
        if n is None or method not in METHODS or secs is None or get("verdict") in ("inconclusive", "error"):
            continue
        base = max(cm._power(method, fam, n, rr) for fam in kind_families(get("kind") or ""))
        ratio = max(float(secs), TIME_FLOOR) / base
        cur = ratios.setdefault(get("claim"), {})
        cur[method] = max(cur.get(method, 1.0 / UNKNOWN_CLAIM_FACTOR), ratio)
    doc["claim_factors"] = {c: {m: round(f, 4) for m, f in fs.items()} for c, fs in sorted(ratios.items())}
    return doc


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
    from .scene import SizeError
    if r < 1:
        raise SizeError(f"r = {r} < 1: a Stiefel variety V(n, r) needs r >= 1")
    if r > n:
        raise SizeError(f"r = {r} > n = {n}: V(n, r) needs r <= n")
    cost = cost or model()
    t = cost.predict(method, claim, n, r)
    if budget is not None and t > budget:
        cid = getattr(claim, "id", str(claim))
        raise BudgetError(f"{cid} ({n},{r}) with --method {method}: predicted {format_seconds(t)}, "
                          f"beyond the budget of {format_seconds(budget)} (--budget); "
                          f"{cost.suggest(method, claim, n, r, budget)}")
    return t


#: a lower bound of the n x n matrices a run holds at once, and of the bytes of one entry per method
_SQUARE_MATRICES = 4
_ENTRY_BYTES = {"float": 8, "modular": 8, "rational": 16, "exact": 16, "auto": 8, "ball": 56}


def check_memory(method: str, claim: Any, n: int, r: int, memory_gib: float | None) -> None:
    """``BudgetError`` if a run's n x n matrices alone (a lower bound of what it holds) exceed the
    memory budget in GiB (None: no budget): refused up front instead of dying of memory."""
    if memory_gib is None or method == "free":
        return
    need = _SQUARE_MATRICES * n * n * _ENTRY_BYTES.get(method, 8)
    if need > memory_gib * (1 << 30):
        cid = getattr(claim, "id", str(claim))
        raise BudgetError(f"{cid} ({n},{r}) with --method {method}: its {n} x {n} matrices alone need more than "
                          f"{need / (1 << 30):.3g} GiB, beyond the memory budget of {memory_gib:g} GiB (--memory)")


# --------------------------------------------------------------------------- measuring and fitting

def fit(points: Sequence[tuple[int, float]]) -> tuple[float, float] | None:
    """(a, b) with t <= exp(a) n**b at every measured point, b >= 0; None without data.

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


def _default_ns(method: str) -> list[int]:
    return {"exact": [2, 3, 4, 5, 6, 7, 8], "rational": [2, 3, 4, 5, 6, 8, 10],
            "modular": [2, 3, 4, 5, 6, 8, 10, 12], "float": [2, 3, 4, 5, 6, 8, 10, 12, 16]}.get(
        method, [2, 3, 4, 5])


def build(records: Sequence[dict[str, Any]], note: str = "") -> dict[str, Any]:
    """The JSON document of a cost model from measurement records: one power law per method and
    family at r = ceil(n/2) (``fits``), one at r = n (``fits_square``: both components of O(n))."""
    out: dict[str, dict[str, dict[str, Any]]] = {"fits": {}, "fits_square": {}, "fits_small": {}}
    groups: dict[tuple[str, str, str], dict[int, float]] = {}
    for rec in records:
        # a run stopped by its budget still bounds the time from below: kept as a point
        n, r = rec["n"], rec["r"]
        if rec.get("series") == "small":
            kinds = ["fits_small"]
        else:
            kinds = (["fits"] if r == (n + 1) // 2 else []) + (["fits_square"] if r == n else [])
        for kind in kinds:
            g = groups.setdefault((kind, rec["method"], rec["family"]), {})
            g[n] = max(g.get(n, 0.0), float(rec["seconds"]))
    for (kind, method, fam), g in sorted(groups.items()):
        coef = fit(sorted(g.items()))
        if coef is None:
            continue
        a, b = coef
        out[kind].setdefault(method, {})[fam] = {"a": round(a, 6), "b": round(b, 6),
                                                 "n_max_measured": max(g), "points": sorted(g.items())}
    return {
        "version": 2,
        "model": ("t(n, r) = exp(a) * n^b seconds, upper envelopes of the measured points: 'fits' at "
                  "r = ceil(n/2), 'fits_square' at r = n, 'fits_small' at r = 2 (float and modular, to "
                  "n = 200); log-linear in r between them"),
        "generated": datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC"),
        "platform": platform.platform(terse=True),
        "python": platform.python_version(),
        "note": note,
        "families": dict(FAMILIES),
        "claim_family": {cid: fam for fam, cid in FAMILIES.items()},
        "fits": out["fits"],
        "fits_square": out["fits_square"],
        "fits_small": out["fits_small"],
        "records": list(records),
    }


def save(doc: dict[str, Any], path: Path | str | None = None) -> Path:
    """Write a fit to ``path`` (default: the user's cache folder, :func:`user_model_file`)."""
    from .results import write_atomic
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


def plot(doc: dict[str, Any], out_dir: Path | str) -> list[Path]:
    """Time against n with the fitted power laws, one panel per family (PNG and PDF)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    fams = list(doc.get("families") or FAMILIES)
    # a grid three panels wide, legible at the page's width
    cols = min(3, len(fams))
    rows = -(-len(fams) // cols)
    fig, grid_axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows + 0.6), sharey=True, squeeze=False)
    axes = [ax for row in grid_axes for ax in row]
    for ax in axes[len(fams):]:
        ax.set_visible(False)
    colors = {"exact": "C0", "rational": "C1", "modular": "C2", "float": "C3"}
    for ax, fam in zip(axes, fams):
        for key, marker, style, suffix in (("fits", "o", "-", " r=n/2"), ("fits_square", "s", "--", " r=n"),
                                           ("fits_small", "^", ":", " r=2")):
            for method, fits in (doc.get(key) or {}).items():
                f = fits.get(fam)
                if not f:
                    continue
                ns = [p[0] for p in f["points"]]
                ts = [max(p[1], 1e-5) for p in f["points"]]
                ax.loglog(ns, ts, marker, color=colors.get(method), label=method + suffix, ms=4,
                          mfc="none" if key != "fits" else None)
                grid = [2 + k * (max(ns) * 2 - 2) / 50 for k in range(51)]
                ax.loglog(grid, [math.exp(f["a"]) * x ** f["b"] for x in grid], style, color=colors.get(method),
                          lw=1, alpha=0.7)
        ax.set_title(f"{fam} ({doc.get('families', FAMILIES).get(fam, '')})", fontsize=10)
        ax.set_xlabel("n")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
    for row in grid_axes:
        row[0].set_ylabel("seconds per run")
    axes[0].legend(fontsize=8, ncol=2)
    fig.suptitle("Cost model: time against n per method; r = ceil(n/2) (filled, solid), r = n (open, dashed),\n"
                 "r = 2 (triangles, dotted); lines: the fitted upper envelopes",
                 fontsize=11)
    fig.tight_layout()
    return save_figure(fig, out_dir, "costmodel")


def table(doc: dict[str, Any]) -> str:
    """The fitted coefficients as a Markdown table."""
    lines = ["| method | family | r | a | b (exponent of n) | measured up to n | predicted at n = 12 | n = 100 "
             "| n = 200 |",
             "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for key, rtext in (("fits", "n/2"), ("fits_square", "n"), ("fits_small", "2")):
        for method, fits in sorted((doc.get(key) or {}).items()):
            for fam, f in fits.items():
                t12 = math.exp(f["a"]) * 12 ** f["b"]
                t100 = math.exp(f["a"]) * 100 ** f["b"]
                t200 = math.exp(f["a"]) * 200 ** f["b"]
                lines.append(f"| {method} | {fam} | {rtext} | {f['a']:.2f} | {f['b']:.2f} | {f['n_max_measured']} | "
                             f"{format_seconds(t12)} | {format_seconds(t100)} | {format_seconds(t200)} |")
    return "\n".join(lines) + "\n"


def accuracy(doc: dict[str, Any], registry: Any) -> list[dict[str, Any]]:
    """Predicted against measured seconds for every measurement of the fit (``doc["records"]``):
    one row per record, with the ratio predicted / measured."""
    cost = CostModel(doc)
    rows = []
    for rec in doc.get("records") or []:
        if rec["claim"] not in registry or rec.get("seconds") is None or rec["seconds"] <= 0:
            continue
        claim = registry.get(rec["claim"])
        pred = cost.predict(rec["method"], claim, rec["n"], rec["r"])
        rows.append(dict(rec, predicted=pred, ratio=pred / rec["seconds"]))
    return rows


def plot_accuracy(rows: list[dict[str, Any]], out_dir: Path | str) -> list[Path]:
    """Predicted against measured seconds, per method, with the bands of a factor 3 (PNG and PDF)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    out_dir = Path(out_dir)
    fig, ax = plt.subplots(figsize=(6.4, 5.2))
    colors = {"exact": "C0", "rational": "C1", "modular": "C2", "float": "C3"}
    for method in colors:
        pts = [(r["seconds"], r["predicted"]) for r in rows if r["method"] == method]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o", ms=4, color=colors[method], label=method,
                      alpha=0.8)
    lo = min([r["seconds"] for r in rows] + [r["predicted"] for r in rows] + [1e-3])
    hi = max([r["seconds"] for r in rows] + [r["predicted"] for r in rows] + [1.0])
    grid = [lo / 2, hi * 2]
    ax.loglog(grid, grid, "k-", lw=1, label="predicted = measured")
    for f, style in ((3, "--"), (1 / 3, "--")):
        ax.loglog(grid, [g * f for g in grid], "k" + style, lw=0.8, alpha=0.6)
    ax.set_xlabel("measured seconds")
    ax.set_ylabel("predicted seconds")
    ax.set_title("Cost model: predicted against measured (dashed: a factor 3)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return save_figure(fig, out_dir, "costmodel-accuracy")


def accuracy_summary(rows: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """Per method: the measurements, how many are predicted within a factor 3, and the extreme ratios
    predicted / measured (below 1: predicted too fast, the case a budget must not meet)."""
    out: dict[str, dict[str, Any]] = {}
    for m in METHODS:
        rs = [r["ratio"] for r in rows if r["method"] == m]
        if rs:
            out[m] = {"runs": len(rs), "within_3x": sum(1 / 3 <= x <= 3 for x in rs),
                      "min_ratio": round(min(rs), 3), "max_ratio": round(max(rs), 3)}
    return out
