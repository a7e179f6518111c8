"""Speed against error: what each method costs and what the float method's error model predicts.

For one representative catalog claim per family (flows, big Lax, dual Lax, brackets,
dimensions; :data:`stiefelsym.methods.costmodel.FAMILIES`):

* **time against n** for every method (the cost model's measurements, in budgeted workers);
* **residual against n** in float64: the largest observed |residual| of the claim at the float
  method's own point, next to the error model's predicted bound e (every entry must have
  |residual| <= e: for a true statement the exact residual is 0, so |residual| is the rounding
  error, and e is the model's bound on it);
* **residual against precision** at one size: float64, mpmath at 30, 50 and 100 digits, and the
  exact evaluation (rational points: residual exactly 0), with times.

A point where an observed residual exceeds its predicted bound is a bug of the error model:
``violations`` lists them and the tests require it to be empty.

The hard cases (:mod:`stiefelsym.methods.hard`) are tabulated by :func:`hard_table`: each case at
several sizes (r = n and r = n - 1 included) with the float and modular methods, verdict,
precision reached and time; a true claim must never get ``fails`` and a corrupted one must never
pass (``undecided`` at a hard point means "resolved there").
"""
from __future__ import annotations

import math
import random
import re
import time
from fractions import Fraction
from pathlib import Path
from typing import Any, Iterable, Sequence

from stiefelsym.methods.costmodel import UNKNOWN_CLAIM_FACTOR

PRECISIONS = (None, 30, 50, 100)          # None: float64


def _label(dps: int | None) -> str:
    return "float64" if dps is None else f"mpmath{dps}"


# --------------------------------------------------------------------------- one float evaluation

def _exact_fraction(x: Any) -> Fraction:
    """A float, mpf or fmpq as an exact Fraction."""
    if isinstance(x, float):
        return Fraction(x)
    if hasattr(x, "man_exp"):
        man, exp = x.man_exp
        return Fraction(int(man)) * (Fraction(2) ** int(exp))
    if hasattr(x, "p") and hasattr(x, "q"):
        return Fraction(int(x.p), int(x.q))
    return Fraction(x)


def _float_point_field(dps: int | None = None) -> Any:
    """Exact rationals at the float method's own points at precision ``dps``: the same draws,
    k / 2^40 (float64 draws a block of parameters at once from a numpy generator seeded by ``rng``,
    mpmath one at a time from ``rng``, as :class:`stiefelsym.backends.fields.FloatField` does)."""
    import flint
    from stiefelsym.backends.fields import FloatField, RationalField
    from stiefelsym.backends.native import RationalBackend

    class FloatPointRationals(RationalField):
        name = "rational (at the float point)"

        def param(self, name, rng):
            return flint.fmpq(rng.randint(-2**40, 2**40), 2**40)

        def param_values(self, rng, count):
            vals = FloatField(dps).param_values(rng, count)
            return None if vals is None else (vals * 2.0**40).astype("int64")

        def param_from_raw(self, x):
            return flint.fmpq(int(x), 2**40)

    class FloatPointBackend(RationalBackend):
        def from_consts(self, a):
            return RationalBackend.from_array(self, a)       # integer constants, unscaled

        def from_array(self, a):
            """A block of parameters k / 2^40, from the integers k."""
            m, k = a.shape
            return flint.fmpq_mat(m, k, [flint.fmpq(int(x), 2**40) for x in a.ravel().tolist()]) \
                if m and k else self.zeros(m, k)
    field = FloatPointRationals()
    field.__dict__["_backend"] = FloatPointBackend(field)   # the backend cache of native.backend
    return field


def exact_entries(claim: Any, n: int, r: int, seed: int = 0, hard: str | None = None,
                  component: int = 0, dps: int | None = None) -> list[Fraction]:
    """The claim's residual entries, exactly, at the very point the float method evaluates (at
    precision ``dps``: float64 and mpmath draw their points differently)."""
    from stiefelsym.claims import Count, Rank
    from stiefelsym.methods.fixed_size import _entries, call_claim, draw_key
    from stiefelsym.scene import Scene
    field = _float_point_field(dps)
    rng = random.Random(f"{draw_key(claim, n, r, seed)}|float" + (f"|component {component}" if component else ""))
    options = None
    if hard:
        from stiefelsym.methods.hard import hard_case
        options = {"hard": hard_case(hard), "hard_hits": []}
    scene = Scene(n, r, field, chart="cayley", rng=rng, component=component, realization=claim.realization,
                  options=options)
    out = []
    for name, value in call_claim(claim.func, scene).items():
        if isinstance(value, (Rank, Count)):
            continue
        out += [_exact_fraction(x) for _, x in _entries(value, name)]
    return out


def _residual_arrays(checks: dict[str, Any], field: Any) -> tuple[Any, Any, Any, bool]:
    """(v, e, m, native): the values, error bounds and term scales of every residual entry, in the
    order of ``methods._entries``.  A matrix in native float64 storage is read as whole arrays (its
    bound e is normwise: one bound for every entry of the matrix); anything else (mpmath, scalars)
    entry by entry, as lists."""
    import numpy as np
    from stiefelsym.claims import Count, Rank
    from stiefelsym.backends.fields import ErrNum
    from stiefelsym.backends.matrix import Mat
    from stiefelsym.methods.fixed_size import _entries
    from stiefelsym.backends.native import F64
    parts: list[tuple[Any, Any, Any]] = []
    native = True
    for name, value in checks.items():
        if isinstance(value, (Rank, Count)):
            continue
        s = value._n if isinstance(value, Mat) else None
        if s is not None and type(s) is F64 and all(value._shape()):
            parts.append((s.v.ravel(), np.full(s.v.size, float(s.e)), s.m.ravel()))
            continue
        native = False
        for _, x in _entries(value, name):
            if not isinstance(x, ErrNum):
                x = field.const(x)           # an exact int or Fraction
            parts.append(([x.v], [x.e], [x.m]))
    if native:
        if not parts:
            return np.zeros(0), np.zeros(0), np.zeros(0), True
        return tuple(np.concatenate([p[k] for p in parts]) for k in range(3)) + (True,)
    flat = [[y for p in parts for y in (p[k].tolist() if hasattr(p[k], "tolist") else p[k])] for k in range(3)]
    return flat[0], flat[1], flat[2], False


def _stats(v: Any, e: Any, m: Any, native: bool) -> dict[str, Any]:
    """Largest |residual|, bound and scale; entries over their bound; resolution; finiteness."""
    import numpy as np
    if native:
        with np.errstate(all="ignore"):
            fin = np.isfinite(v) & np.isfinite(e) & np.isfinite(m)
            av = np.where(fin, np.abs(v), np.inf)
            be = np.where(fin, e, np.inf)
            ms = np.where(fin, m, np.inf)
            ratio = np.where(be > 0, av / np.where(be > 0, be, 1.0), np.where(av == 0, 0.0, np.inf))
            res = np.where(ms > 0, be / np.where(ms > 0, ms, 1.0), np.where(be == 0, 0.0, np.inf))
            return {"finite": bool(fin.all()), "max_residual": float(av.max()), "max_bound": float(be.max()),
                    "max_scale": float(ms.max()), "exceed": int(np.count_nonzero(fin & (np.abs(v) > e))),
                    "resolved": bool(fin.all() and np.all(e <= 1e-8 * m)), "worst_ratio": float(ratio.max()),
                    "worst_resolution": float(res.max())}
    fin = [_finite3(a, b, c) for a, b, c in zip(v, e, m)]
    vals = [_clip(abs(a)) if f else math.inf for a, f in zip(v, fin)]
    bounds = [_clip(b) if f else math.inf for b, f in zip(e, fin)]
    scales = [_clip(c) if f else math.inf for c, f in zip(m, fin)]
    return {"finite": all(fin), "max_residual": max(vals), "max_bound": max(bounds), "max_scale": max(scales),
            "exceed": sum(1 for a, b, f in zip(v, e, fin) if f and abs(a) > b),
            "resolved": all(fin) and all(b <= 1e-8 * c for b, c in zip(e, m)),
            "worst_resolution": max(_clip(b / c) if f and c > 0 else (0.0 if f and b == 0 else math.inf)
                                    for b, c, f in zip(e, m, fin)),
            "worst_ratio": max((a / b) if b > 0 else (0.0 if a == 0 else math.inf) for a, b in zip(vals, bounds))}


def _finite3(*xs: Any) -> bool:
    import mpmath
    try:
        return all(mpmath.isfinite(y) for y in xs)
    except (TypeError, ValueError):
        return False


def evaluate(claim: Any, n: int, r: int, dps: int | None = None, seed: int = 0, hard: str | None = None,
             component: int = 0, exact: bool = False) -> dict[str, Any]:
    """The claim's residual entries at the float method's own point, at one precision.

    Returns the largest |residual|, the largest predicted bound e, the number of entries with
    |residual| > e (``exceed``: must be 0 for a true claim), whether every bound resolves 1e-8 of
    its term scale, whether anything overflowed, and the time (of the claim's evaluation: the
    scene, the residuals and their bounds).  With ``exact`` the residual is also computed exactly
    at the same point, and ``exceed_exact`` counts the entries whose actual rounding error
    |computed - exact| exceeds the bound e (must be 0 for every claim, true or false: that is what
    the bound claims); ``exact_seconds`` is the time of that exact evaluation."""
    import mpmath
    import numpy as np
    from stiefelsym.backends.fields import FloatField
    from stiefelsym.methods.fixed_size import call_claim, draw_key
    from stiefelsym.scene import Scene
    field = FloatField(dps)
    rng = random.Random(f"{draw_key(claim, n, r, seed)}|float" + (f"|component {component}" if component else ""))
    options = None
    if hard:
        from stiefelsym.methods.hard import hard_case
        options = {"hard": hard_case(hard), "hard_hits": []}
    t0 = time.perf_counter()
    out: dict[str, Any] = {"claim": claim.id, "n": n, "r": r, "precision": _label(dps),
                           "digits": 15.95 if dps is None else dps}
    try:
        ctx = mpmath.workdps(dps) if dps else np.errstate(over="ignore", invalid="ignore")
        with ctx:
            scene = Scene(n, r, field, chart="cayley", rng=rng, component=component,
                          realization=claim.realization, options=options)
            v, e, m, native = _residual_arrays(call_claim(claim.func, scene), field)
            seconds = time.perf_counter() - t0
            stats = _stats(v, e, m, native) if len(v) else None
    except Exception as exc:  # noqa: BLE001 - a degenerate point, an overflow: reported, not raised
        out.update(status="error", message=f"{type(exc).__name__}: {exc}", seconds=time.perf_counter() - t0)
        return out
    if stats is None:
        out.update(status="no residuals", seconds=seconds, entries=0)
        return out
    finite = stats.pop("finite")
    if exact and finite:
        t1 = time.perf_counter()
        try:
            ex = exact_entries(claim, n, r, seed, hard, component, dps)
        except Exception as exc:  # noqa: BLE001 - a degenerate point for exact arithmetic
            out["exact_error"] = f"{type(exc).__name__}: {exc}"
        else:
            out["exact_seconds"] = round(time.perf_counter() - t1, 6)
            if len(ex) == len(v):
                vv = v.tolist() if native else v
                ee = e.tolist() if native else e
                errs = [abs(_exact_fraction(a) - q) for a, q in zip(vv, ex)]
                out["exceed_exact"] = sum(1 for b, err in zip(ee, errs) if err > _exact_fraction(b))
                out["max_exact_residual"] = _number(max(abs(q) for q in ex))
                out["max_actual_error"] = _number(max(errs))
            else:
                out["exact_error"] = "the exact evaluation has another number of entries"
    out.update(status="ok" if finite else "overflow", seconds=seconds, entries=len(v), **stats)
    return out


def _clip(x: Any) -> float:
    """float(x), inf beyond float64's range (an mpf does not overflow)."""
    try:
        return float(x)
    except OverflowError:
        return math.inf


def _number(q: Any) -> float | str:
    """A float, or (beyond float64's range) its value in words, e.g. "9.4e+320"."""
    try:
        return float(q)
    except OverflowError:
        import mpmath
        return mpmath.nstr(mpmath.mpf(q.numerator) / q.denominator, 3) if isinstance(q, Fraction) else str(q)


def _finite(x: Any) -> bool:
    import mpmath
    try:
        return all(mpmath.isfinite(y) for y in (x.v, x.e, x.m))
    except (TypeError, ValueError):
        return False


# --------------------------------------------------------------------------- sweeps

def _stop_predicted(series: list[dict[str, Any]], n: int, cap: float, stops: list[str] | None,
                    what: str) -> tuple[bool, float | None]:
    """Whether a series stops before n (its fit so far predicts more than cap seconds), recording
    why in stops; and the prediction."""
    guess = _predicted(series, n)
    if guess is not None and guess > cap:
        if stops is not None:
            stops.append(f"{what}: stopped before n = {n} (predicted {guess:.3g} s > {cap:g} s per evaluation)")
        return True, guess
    return False, guess


def _predicted(series: Sequence[dict[str, Any]], n: int, key: str = "seconds") -> float | None:
    """The next evaluation's time, from the series so far: the cost model's power law (an upper
    envelope of the measured points, :func:`stiefelsym.methods.costmodel.fit`) at n; None without data."""
    from stiefelsym.methods.costmodel import fit
    pts = [(x["n"], float(x[key])) for x in series if x.get(key) is not None and x.get("status") == "ok"]
    coef = fit(pts) if pts else None
    if coef is None:
        return None
    a, b = coef
    return math.exp(a) * n ** b


def half(n: int) -> int:
    """r = ceil(n/2), the middle of the range of r."""
    return (n + 1) // 2


def two(n: int) -> int:
    """r = 2 (r = 1 at n = 1): the small-r series, which reaches n = 200."""
    return min(2, n)


def residual_against_n(claim: Any, ns: Sequence[int], cap: float = 10.0, total: float = 30.0,
                       seed: int = 0, exact_n: int = 6, r_of: Any = half, dps: int | None = None,
                       stops: list | None = None) -> list[dict[str, Any]]:
    """Residual and predicted bound against n at one precision (float64 by default), r = r_of(n).

    Before each size the time is predicted from the series so far (the cost model's power law,
    an upper envelope of the measured times); the series stops at the first size predicted
    beyond ``cap`` seconds, at an evaluation that took more than ``cap``, or once it has spent
    ``total`` (the reason goes to ``stops``).  Up to ``exact_n`` the residual is also computed
    exactly at the same point (the actual error against the bound).  In float64, past an
    overflow, the series escalates as the float method does (the first precision of the ladder
    that stays finite)."""
    out: list[dict[str, Any]] = []
    spent = 0.0
    for n in ns:
        r = r_of(n)
        stop, guess = _stop_predicted(out, n, cap, stops, f"{_label(dps)}, r = {_r_text(r_of)}")
        if stop:
            break
        rec = evaluate(claim, n, r, dps, seed, exact=n <= exact_n)
        if guess is not None:
            rec["predicted_seconds"] = round(guess, 6)
        if dps is None and rec.get("status") == "overflow":
            for dps2 in (30, 60, 120):
                esc = evaluate(claim, n, r, dps2, seed, exact=n <= exact_n)
                esc["seconds"] += rec["seconds"]
                esc["escalated_from"] = "float64 (overflow)"
                rec = esc
                if rec.get("status") == "ok":
                    break
        out.append(rec)
        spent += rec.get("seconds", 0.0) + rec.get("exact_seconds", 0.0)
        if rec.get("status") in ("error", "no residuals") or rec.get("seconds", 0) > cap or spent > total:
            if stops is not None and n != ns[-1]:
                why = rec.get("message") or ("the series' time" if spent > total else "the evaluation's time")
                stops.append(f"{_label(dps)}, r = {_r_text(r_of)}: stopped after n = {n} ({why}: "
                             f"{spent:.3g} s spent, cap {cap:g} s per evaluation, {total:g} s per series)")
            break
    return out


def _r_text(r_of: Any) -> str:
    return {"half": "ceil(n/2)", "two": "2"}.get(getattr(r_of, "__name__", ""), "r(n)")


def evaluate_exact(claim: Any, n: int, r: int, seed: int = 0, hard: str | None = None) -> dict[str, Any]:
    """The residual computed exactly (rational arithmetic) at the float method's own point: the
    "infinite precision" end of the precision axis; the residual is exactly 0 for a true claim."""
    t0 = time.perf_counter()
    out: dict[str, Any] = {"claim": claim.id, "n": n, "r": r, "precision": "exact", "digits": math.inf}
    try:
        ex = exact_entries(claim, n, r, seed, hard)
    except Exception as exc:  # noqa: BLE001 - reported, not raised
        out.update(status="error", message=f"{type(exc).__name__}: {exc}", seconds=time.perf_counter() - t0)
        return out
    res = max((abs(q) for q in ex), default=Fraction(0))
    out.update(status="ok", seconds=time.perf_counter() - t0, entries=len(ex), max_residual=_number(res),
               max_bound=0.0, exceed=0 if res == 0 else len([q for q in ex if q]), resolved=True,
               note="rational arithmetic at the float method's point: no rounding, the bound is 0")
    return out


def evaluate_ball(claim: Any, n: int, r: int, seed: int = 0) -> dict[str, Any]:
    """The ball method's evaluation at the float method's own point: the precision of its ladder that
    decided, and the rigorous bound of every residual entry (its largest: |exact residual| <= bound)."""
    from stiefelsym.methods.fixed_size import _ball_component
    t0 = time.perf_counter()
    out: dict[str, Any] = {"claim": claim.id, "n": n, "r": r, "precision": "ball"}
    try:
        run = _ball_component(claim, n, r, seed, claim.func, None, 0)
    except Exception as exc:  # noqa: BLE001 - reported, not raised
        out.update(status="error", message=f"{type(exc).__name__}: {exc}", seconds=time.perf_counter() - t0)
        return out
    ok = run.status in ("pass", "zero")
    out.update(status="ok" if ok else run.status, seconds=time.perf_counter() - t0, bits=run.field,
               max_bound=run.bound, max_residual=None, exceed=0, resolved=ok,
               note="rigorous enclosures (midpoint-radius or arb): every |exact residual| <= the bound")
    return out


def residual_against_precision(claim: Any, ns: Sequence[int] | int, r: Any = None, seed: int = 0,
                               precisions: Iterable[int | str | None] = PRECISIONS + ("exact",),
                               cap: float = 3.0, total: float = 8.0, exact_n: int = 8,
                               stops: list | None = None) -> list[dict[str, Any]]:
    """float64, mpmath at 30, 50, 100 digits and the exact evaluation, each against n (r = r(n),
    default 2) as far as the cost model's prediction stays within ``cap`` seconds per evaluation
    and the series within ``total``.  ``residual_against_precision(claim, n, r)`` (two integers)
    evaluates at that one size only."""
    if isinstance(ns, int):
        size_r = r
        ns, r_of = [ns], (lambda n: size_r)
    else:
        r_of = r or two
    out: list[dict[str, Any]] = []
    for dps in precisions:
        if dps in ("exact", "ball"):
            series: list[dict[str, Any]] = []
            spent = 0.0
            for n in ns:
                if _stop_predicted(series, n, cap, stops, f"{dps}, r = {_r_text(r_of)}")[0]:
                    break
                rec = (evaluate_exact if dps == "exact" else evaluate_ball)(claim, n, r_of(n), seed)
                series.append(rec)
                spent += rec["seconds"]
                if rec["status"] != "ok" or spent > total:
                    break
            out += series
            continue
        out += residual_against_n(claim, ns, cap=cap, total=total, seed=seed, exact_n=exact_n, r_of=r_of,
                                  dps=dps, stops=stops)
    return out


def violations(records: Iterable[dict[str, Any]]) -> list[dict[str, Any]]:
    """Records in which an observed residual, or the actual error against the exact value at the
    same point, exceeded its predicted bound (bugs of the error model)."""
    return [r for r in records if r.get("exceed") or r.get("exceed_exact")]


# --------------------------------------------------------------------------- hard cases

#: the hard cases of the table and the sizes each is evaluated at
HARD_SIZES = ((4, 2), (4, 3), (4, 4), (6, 3))
HARD_LARGE = (12, 6)
HARD_CLAIMS = ("neumann-lax", "manakov-lax", "neumann-flow")


def control_claim() -> Any:
    """A corrupted big Lax equation (M = Φ + λA instead of Φ − λA): false for every n, r, so no
    method may pass it at any hard point."""
    from stiefelsym.claims import Claim, admissible
    from stiefelsym.backends.matrix import comm

    def flow(s):
        k = 1 + 2 * s.kappa
        X, P, A = s.X, s.P, s.A
        return {"X": P - k * (X @ P.T @ X),
                "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}

    def corrupted(s):
        def L(t):
            return t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
        M = s.Phi + s.lam * s.A
        return {"LA1 (sign of lambda A flipped in M)": s.d(L, flow(s)) - comm(M, L(s))}

    return Claim(id="corrupted-LA1", paper=("LA1",), kind="lax", section="5", func=corrupted,
                 sizes=admissible(8), title="A corrupted big Lax equation (negative control).")


def _precision_reached(text: str) -> str:
    hits = re.findall(r"(float64|mpmath\d+): max \|residual\|", text or "")
    if hits:
        return hits[-1]
    balls = re.findall(r"\b(midrad53|arb\d+)\b", text or "")       # the ball method's last rung
    if balls:
        return balls[-1]
    if "exactly" in (text or "") or "vanishes" in (text or ""):
        return "exact"
    return "-"


def _judge(truth: str, verdict: str, check: dict[str, Any] | None) -> str:
    """ok, or WRONG: a false ``fails`` of a true claim, a pass of a false claim, or a float evaluation
    whose actual error (against the exact value at the same point) exceeds its bound."""
    if check and check.get("exceed_exact"):
        return "WRONG (error bound exceeded)"
    if truth == "true":
        return "WRONG (false fails)" if verdict == "fails" else "ok"
    if verdict in ("numeric", "checked", "proved"):
        return "WRONG (false pass)"
    if verdict == "undecided" and check is not None:
        # resolved at the hard point: no verdict on the statement; the point's exact residual is
        # within the certified 2e, below what this precision resolves
        ex = check.get("max_exact_residual", 0)
        return "ok (residual below resolution)" if isinstance(ex, str) or ex > 0 else "ok"
    return "ok"


def _dps(label: str) -> int | None:
    m = re.fullmatch(r"mpmath(\d+)", label or "")
    return int(m.group(1)) if m else None


def _magnitude(x: Any) -> float:
    return math.inf if isinstance(x, str) else float(x or 0)


def _exact_check(claim: Any, n: int, r: int, seed: int, hard: str, label: str) -> dict[str, Any] | None:
    """The float evaluation at the precision reached, against the exact value at the same point,
    on every component; the worst of them."""
    worst: dict[str, Any] | None = None
    for comp in ((0, 1) if r == n else (0,)):
        rec = evaluate(claim, n, r, _dps(label), seed, hard, component=comp, exact=True)
        if "exceed_exact" not in rec:
            continue
        if worst is None or rec["exceed_exact"] > worst["exceed_exact"] or \
                _magnitude(rec.get("max_exact_residual", 0)) > _magnitude(worst.get("max_exact_residual", 0)):
            worst = rec
    return worst


def _hard_rows(case: str, hard: str | None, c: Any, plan: Sequence[Any], m: str, timeout: float, seed: int,
               exact_check_n: int) -> list[dict[str, Any]]:
    """The rows of one (case, claim, method) over its sizes: verdict, precision reached, time, judged."""
    from stiefelsym.run.runner import verify
    truth = "false" if c.id == "corrupted-LA1" else "true"
    rows = []
    if not plan:
        return rows
    results = verify([c], sizes=list(plan), methods=(m,), seed=seed, hard=hard, timeout=timeout)
    for res in results:
        if res.variant is not None:
            continue
        text = " ".join(x for x in (res.message, res.certificate) if x)
        untouched = hard is not None and "changed no parameter" in text
        label = _precision_reached(text) if m in ("float", "ball") else "exact"
        check = None
        if m == "float" and res.verdict in ("undecided", "numeric") and label != "-" \
                and res.n <= (max(exact_check_n, 12) if truth == "false" else exact_check_n):
            try:
                check = _exact_check(c, res.n, res.r, seed, hard, label)
            except Exception as exc:  # noqa: BLE001 - reported in the row, never a crash
                check = {"exact_error": f"{type(exc).__name__}: {exc}"}
        rows.append({"case": case, "claim": c.id, "truth": truth, "n": res.n, "r": res.r,
                     "method": m, "verdict": res.verdict, "precision": label,
                     "escalated": "mpmath" in label,
                     "seconds": round(res.seconds, 4),
                     "touched": not untouched,
                     "exact_residual": None if check is None else check.get("max_exact_residual"),
                     "actual_error": None if check is None else check.get("max_actual_error"),
                     "bound": None if check is None else check.get("max_bound"),
                     "judgement": _judge(truth, res.verdict, check),
                     "reason": _short(text, 160)})
    return rows


def hard_table(cases: Sequence[str] | None = None, claims: Sequence[Any] | None = None,
               sizes: Sequence[tuple[int, int]] = HARD_SIZES, methods: Sequence[str] = ("float", "ball", "modular"),
               timeout: float = 60.0, seed: int = 0, large: tuple[int, int] | None = HARD_LARGE,
               registry: Any = None, exact_check_n: int = 6) -> list[dict[str, Any]]:
    """Every hard case x claim x size x method: verdict, precision reached, time, judged."""
    from stiefelsym.claims import Size, load_catalog
    from stiefelsym.methods.hard import HARD_CASES
    cases = list(cases or HARD_CASES)
    if claims is None:
        registry = registry or load_catalog()
        claims = [registry.get(c) for c in HARD_CLAIMS] + [control_claim()]
    rows = []
    for case in cases:
        for c in claims:
            plan = [Size(n, r) for n, r in sizes if c.sizes.admits(n, r)]
            if large and c.sizes.admits(*large):
                plan.append(Size(*large))
            for m in methods:
                rows += _hard_rows(case, case, c, plan, m, timeout, seed, exact_check_n)
    return rows


#: the hard sizes: (label, hard case or None, claims, sizes, methods, seconds per run)
HARD_SIZE_PLAN = (
    ("n = 200", None, HARD_CLAIMS, ((200, 1), (200, 2)), ("float", "ball", "modular"), 15.0),
    # a float64 failure is confirmed by an exact rational evaluation, out of reach at n = 200 (inconclusive)
    ("n = 200", None, ("corrupted-LA1",), ((200, 2),), ("float", "ball", "modular"), 15.0),
    # every hard point at n = 200 (huge-momenta: float64 overflows and the mpmath ladder at n = 200 is
    # beyond the run's budget, so inconclusive with that reason)
    *((f"n = 200 + {case}", case, ("neumann-lax", "manakov-lax"), ((200, 2),), ("float",), 15.0)
      for case in ("near-equal-a", "near-equal-a-1e-3", "near-equal-a-1e-6", "near-equal-a-1e-12", "near-pole",
                   "near-pole-1e-8", "manakov-0/0", "large-momenta", "far-chart")),
    ("n = 200 + huge-momenta", "huge-momenta", ("neumann-lax",), ((200, 2),), ("float",), 15.0),
    *((f"n = 200 + {case}", case, ("corrupted-LA1",), ((200, 2),), ("modular",), 15.0)
      for case in ("near-equal-a-1e-12", "near-pole-1e-8", "large-momenta", "far-chart")),
    ("r = n", None, HARD_CLAIMS + ("corrupted-LA1",), ((6, 6), (8, 8), (10, 10), (12, 12)),
     ("float", "modular", "exact"), 30.0),
    ("r = n - 1", None, HARD_CLAIMS + ("corrupted-LA1",), ((6, 5), (8, 7), (10, 9), (12, 11)),
     ("float", "modular", "exact"), 30.0),
    ("r = n + near-pole-1e-8", "near-pole-1e-8", ("neumann-lax", "manakov-lax", "corrupted-LA1"), ((8, 8),),
     ("float", "modular"), 30.0),
)


def hard_sizes_table(plan: Sequence[tuple] = HARD_SIZE_PLAN, seed: int = 0, registry: Any = None,
                     exact_check_n: int = 8, share: float = 0.5) -> list[dict[str, Any]]:
    """The hard sizes: n = 200 (r = 1, 2), r = n and r = n - 1, at plain random points and with
    some hard cases.  A size whose predicted time (the cost model) exceeds ``share`` of the run's
    budget is not run; its row says so (verdict ``refused``, never a wrong verdict)."""
    from stiefelsym.claims import Size, load_catalog
    from stiefelsym.methods.costmodel import format_seconds, predict
    registry = registry or load_catalog()
    rows: list[dict[str, Any]] = []
    for label, hard, cids, sizes, methods, timeout in plan:
        for cid in cids:
            c = control_claim() if cid == "corrupted-LA1" else registry.get(cid)
            for m in methods:
                run = []
                for n, r in sizes:
                    if not c.sizes.admits(n, r):
                        continue
                    # the control is timed as the big Lax equation it corrupts
                    t = predict(m, registry.get("neumann-lax") if cid == "corrupted-LA1" else c, n, r)
                    if t > share * timeout:
                        rows.append({"case": label, "claim": c.id, "truth": "false" if cid == "corrupted-LA1"
                                     else "true", "n": n, "r": r, "method": m, "verdict": "refused",
                                     "precision": "-", "escalated": False, "seconds": 0.0, "touched": True,
                                     "exact_residual": None, "actual_error": None, "bound": None,
                                     "judgement": "ok", "predicted": t,
                                     "reason": f"not run: the cost model predicts {format_seconds(t)}, beyond "
                                               f"{share:g} x the run's budget of {timeout:g} s"})
                        continue
                    run.append(Size(n, r))
                rows += _hard_rows(label, hard, c, run, m, timeout, seed, exact_check_n)
    return rows


def _short(text: str, k: int) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= k else text[: k - 3] + "..."


def hard_markdown(rows: Sequence[dict[str, Any]], size_rows: Sequence[dict[str, Any]] = ()) -> str:
    from stiefelsym.methods.hard import HARD_CASES
    wrong = [r for r in list(rows) + list(size_rows) if r["judgement"].startswith("WRONG")]
    lines = ["# Hard numerical cases", "",
             "Each case rewrites the sampled parameters (`stiefelsym verify --hard CASE`); a hard point is "
             "chosen, not random, so a pass there is `undecided` (\"resolved at the hard point\"), a failure a "
             "certain `fails` with an exact witness.  The rule checked here: a true claim never gets `fails`, "
             "and the corrupted control (`corrupted-LA1`, M = Φ + λA in the big Lax equation) never gets a "
             "passing verdict.  "
             "`precision` is the last precision of the float method's ladder that resolved the point "
             "(float64, then ball arithmetic and mpmath: escalation happens by itself), or for the ball method "
             "the rung whose enclosures decided (midrad53: float64 midpoint-radius pairs; arb53 to arb424).  "
             "Where the float "
             "method resolved a hard point, the same point is also evaluated exactly (rational arithmetic at the "
             "float method's own parameters): `actual error` = max |computed − exact| must stay below the "
             "predicted bound `e`, for the true claims and for the control alike; `exact residual` is the "
             "value the statement really has there (0 for a true claim).  The control can vanish to within "
             "float64's resolution at a hard point: with eigenvalue gaps of 1e-12, A = a₁I + O(1e-12) commutes "
             "with everything up to O(1e-12), and so does the corruption 2λ[A, L]; there the verdict is "
             "`undecided` (no verdict on the statement), never a pass, and the certified bound still holds "
             "(the modular method, exact at the same kind of point, refutes it).", "",
             "Cases:", ""]
    for k, v in HARD_CASES.items():
        lines.append(f"- `{k}`: {v.description}")
    runs = [r for r in list(rows) + list(size_rows) if r["verdict"] != "refused"]
    lines += ["", f"**{len(runs)} runs, {len(wrong)} wrong verdicts.**", ""]
    if size_rows:
        lines += _hard_size_summary(size_rows)
    if rows:
        lines += ["## Hard points", ""]
    lines += _hard_lines(rows)
    return "\n".join(lines) + "\n"


def _hard_size_summary(rows: Sequence[dict[str, Any]]) -> list[str]:
    """The hard sizes: n = 200 with r = 1, 2, and r = n, r = n - 1, as a section of its own."""
    lines = ["## Hard sizes: n = 200, r = n, r = n − 1", "",
             "The same rule at sizes that stress the engine rather than the point: n = 200 with r = 1, 2 "
             "(whole-matrix float64; the normwise bound grows with n), r = n (both components of O(n) "
             "sampled) and r = n − 1, at plain random points (a pass there is a real verdict: `numeric`, "
             "`checked`, `proved`) and combined with hard points (a pass is `undecided`).  Where the float "
             "method's float64 bound does not resolve the point it escalates to mpmath by itself; a float64 "
             "failure is a `fails` only once an exact rational evaluation confirms it, which at n = 200 does "
             "not finish within the run's budget: the verdict is then `inconclusive` with that reason, never "
             "a guess (the modular method refutes the control there in under a second).  Sizes the cost "
             "model predicts beyond half the run's budget are not run (`refused`, with the prediction).", ""]
    counts: dict[tuple[str, str], dict[str, int]] = {}
    for r in rows:
        key = (r["case"], r["method"])
        counts.setdefault(key, {}).setdefault(r["verdict"], 0)
        counts[key][r["verdict"]] += 1
    lines += ["| sizes | method | verdicts |", "| --- | --- | --- |"]
    for (case, m), v in counts.items():
        lines.append(f"| {case} | {m} | " + ", ".join(f"{k} {x}" for k, x in sorted(v.items())) + " |")
    lines.append("")
    return lines + _hard_lines(rows) + [""]


def _hard_lines(rows: Sequence[dict[str, Any]]) -> list[str]:
    if not rows:
        return []
    lines = ["| case | claim | (n,r) | method | verdict | precision | s | exact residual | actual error | bound e "
             "| judgement | note |",
             "| --- | --- | --- | --- | --- | --- | ---: | ---: | ---: | ---: | --- | --- |"]
    for r in rows:
        note = "case does not touch this claim" if not r["touched"] else (
            r["reason"] if r["verdict"] in ("inconclusive", "fails", "error", "refused") else "")
        lines.append(f"| {r['case']} | {r['claim']} | ({r['n']},{r['r']}) | {r['method']} | {r['verdict']} | "
                     f"{r['precision']} | {r['seconds']:.3f} | {_fmt(r.get('exact_residual'))} | "
                     f"{_fmt(r.get('actual_error'))} | {_fmt(r.get('bound'))} | {r['judgement']} | "
                     f"{note.replace('|', '/')} |")
    return lines


# --------------------------------------------------------------------------- plots and report

PREC_STYLE = {"float64": "C3", "mpmath30": "C0", "mpmath50": "C1", "mpmath100": "C2", "ball": "C4", "exact": "k"}


def plot_family(fam: str, claim_id: str, times: Sequence[dict[str, Any]], against_n: Sequence[dict[str, Any]],
                against_p: Sequence[dict[str, Any]], out_dir: Path,
                against_n2: Sequence[dict[str, Any]] = ()) -> list[Path]:
    """Four panels: time against n per method; float64 residual and bound against n (r = 2 to
    n = 200, r = ceil(n/2)); residual and bound against n per precision; error against time."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    ax = axes[0][0]
    for method in ("exact", "rational", "modular", "float", "ball"):
        for rkind, style in (("half", "o-"), ("two", "s:")):
            pts = {}
            for rec in times:
                if rec["method"] == method and rec["r"] == (2 if rkind == "two" else (rec["n"] + 1) // 2):
                    pts[rec["n"]] = max(pts.get(rec["n"], 0.0), rec["seconds"])
            if pts:
                ns = sorted(pts)
                ax.loglog(ns, [max(pts[n], 1e-5) for n in ns], style, ms=3, color=_MCOL[method],
                          mfc="none" if rkind == "two" else None,
                          label=f"{method} run, r = {'2' if rkind == 'two' else 'ceil(n/2)'}")
    for prec in ("float64", "ball", "exact"):
        pts = [x for x in against_p if x["precision"] == prec and x.get("status") == "ok"]
        if pts:
            ax.loglog([x["n"] for x in pts], [max(x["seconds"], 1e-5) for x in pts], "^--", ms=3, lw=0.8,
                      color=PREC_STYLE[prec], label=f"{prec} evaluation, r = 2")
    ax.set_xlabel("n")
    ax.set_ylabel("seconds")
    ax.set_title("time against n: whole runs per method, one evaluation per precision", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=6, ncol=2)
    ax = axes[0][1]
    for series, rtext, color in ((against_n2, "r = 2", "C3"), (against_n, "r = ceil(n/2)", "C4")):
        ok = [x for x in series if x.get("status") == "ok"]
        if ok:
            ns = [x["n"] for x in ok]
            ax.loglog(ns, [max(x["max_residual"], 1e-300) for x in ok], "o-", ms=3, color=color,
                      label=f"observed |residual|, {rtext}")
            ax.loglog(ns, [x["max_bound"] for x in ok], "s--", ms=3, color=color, mfc="none",
                      label=f"predicted bound e, {rtext}")
            act = [x for x in ok if isinstance(x.get("max_actual_error"), float)]
            if act:
                ax.loglog([x["n"] for x in act], [max(x["max_actual_error"], 1e-300) for x in act], "x", ms=5,
                          color=color, label=f"|computed - exact|, {rtext}")
            for x in ok:
                if x.get("escalated_from"):
                    ax.annotate(x["precision"], (x["n"], x["max_bound"]), fontsize=6)
    ax.set_xlabel("n")
    ax.set_title("float64: observed residual and the error model's bound against n", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=6)
    ax = axes[1][0]
    for prec in ("float64", "mpmath30", "mpmath50", "mpmath100"):
        pts = [x for x in against_p if x["precision"] == prec and x.get("status") == "ok"]
        if pts:
            ns = [x["n"] for x in pts]
            ax.loglog(ns, [max(x["max_residual"], 1e-300) for x in pts], "o-", ms=3, color=PREC_STYLE[prec],
                      label=f"{prec} |residual|")
            ax.loglog(ns, [max(x["max_bound"], 1e-300) for x in pts], "s--", ms=3, mfc="none",
                      color=PREC_STYLE[prec], label=f"{prec} bound e")
    ax.set_xlabel("n (r = 2)")
    ax.set_title("residual and bound against n, per precision (exact: residual 0)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=6, ncol=2)
    ax = axes[1][1]
    # float64, ball and exact side by side: the bound each certifies against the seconds it took
    floor = None
    # (mpmath's bounds, 1e-30 and below, are in the panel to the left)
    for prec, label in (("float64", "float64: error model's bound e"), ("ball", "ball: rigorous enclosure bound")):
        pts = [x for x in against_p if x["precision"] == prec and x.get("status") == "ok"]
        if pts:
            ys = [max(x["max_bound"], 1e-300) for x in pts]
            floor = min(ys + ([floor] if floor else []))
            ax.loglog([max(x["seconds"], 1e-5) for x in pts], ys, "s-", ms=3, lw=0.8, color=PREC_STYLE[prec],
                      label=label + " (points: n = 2 to 200)")
            for x, y in zip(pts, ys):
                if x["n"] in (16, 64) or x is pts[-1]:
                    ax.annotate(f"n={x['n']}", (max(x["seconds"], 1e-5), y), fontsize=6, color=PREC_STYLE[prec])
    exact = [x for x in against_p if x["precision"] == "exact" and x.get("status") == "ok"]
    if exact:
        y0 = (floor or 1e-16) / 100
        ax.loglog([max(x["seconds"], 1e-5) for x in exact], [y0] * len(exact), "D-", ms=3, color=PREC_STYLE["exact"],
                  label="exact: error 0 (drawn at the bottom)")
        ax.annotate(f"n={exact[-1]['n']}", (max(exact[-1]["seconds"], 1e-5), y0), fontsize=6)
    ax.set_xlabel("seconds per evaluation")
    ax.set_ylabel("certified error")
    ax.set_title("error against time: float64, ball and exact side by side (r = 2)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=6)
    fig.suptitle(f"{fam}: {claim_id}", fontsize=10)
    fig.tight_layout()
    from stiefelsym.methods.costmodel import save_figure
    return save_figure(fig, out_dir, f"speed-{fam}")


_MCOL = {"exact": "C0", "rational": "C1", "modular": "C2", "float": "C3", "ball": "C4"}


def _fmt(x: Any) -> str:
    if x is None:
        return "-"
    if isinstance(x, float):
        if math.isinf(x):
            return "inf"
        return f"{x:.2e}"
    return str(x)


def _accuracy_lines(acc: dict[str, Any] | None) -> list[str]:
    """The cost model's predictions against its own measurements, per method."""
    if not acc:
        return []
    out = ["Predicted against measured, over every decided run of the fit (n >= 4; a ratio below 1: predicted "
           "too fast):", "",
           "![predicted against measured](costmodel-accuracy.png)", "",
           "| method | runs | largest n | time within a factor 3 | min predicted/measured | max predicted/measured "
           "| peak memory within a factor 3 |",
           "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for m, a in acc.items():
        mem = f"{a['memory_within_3x']}/{a['memory_runs']}" if "memory_runs" in a else "-"
        out.append(f"| {m} | {a['runs']} | {a.get('largest_n', '-')} | {a['within_3x']}/{a['runs']} | {a['min_ratio']} "
                   f"| {a['max_ratio']} | {mem} |")
    return out + [""]


def _catalog_accuracy_lines(acc: dict[str, Any] | None) -> list[str]:
    """The calibrated predictions against the catalog's own runs (reports/results.json), per method."""
    if not acc:
        return []
    out = ["Predicted against measured over the catalog's own runs of at least 0.05 s (`reports/all/results.json`, "
           "`reports/results.json`, n <= 6; the calibration's data, so a calibrated claim is never predicted below "
           "its time there, only the five measured claims can be, by their own fits; above 3x where a claim's "
           "time grows more slowly than its family's):", "",
           "| method | runs | within a factor 3 | below a third | min predicted/measured | median | max |",
           "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for m, a in acc.items():
        out.append(f"| {m} | {a['runs']} | {a['within_3x']}/{a['runs']} | {a['under_a_third']} | {a['min_ratio']} | "
                   f"{a['median_ratio']} | {a['max_ratio']} |")
    return out + [""]


def _yes_no(x: Any) -> str:
    return "yes" if x is True else "no" if x is False else str(x)


def _residual_table(records: Sequence[dict[str, Any]]) -> list[str]:
    lines = ["| n | r | precision | max \\|residual\\| | max bound e | \\|computed − exact\\| | entries over bound "
             "| resolves 1e-8 of scale | predicted s | s |",
             "| ---: | ---: | --- | ---: | ---: | ---: | ---: | --- | ---: | ---: |"]
    for x in records:
        over = x.get("exceed", "-") if "exceed_exact" not in x else x["exceed"] + x["exceed_exact"]
        pred = x.get("predicted_seconds")
        lines.append(f"| {x['n']} | {x['r']} | {x['precision']} | {_fmt(x.get('max_residual'))} | "
                     f"{_fmt(x.get('max_bound'))} | {_fmt(x.get('max_actual_error'))} | {over} | "
                     f"{_yes_no(x.get('resolved', '-'))} | {'-' if pred is None else f'{pred:.3g}'} | "
                     f"{x.get('seconds', 0):.3f} |")
    return lines + [""]


def tradeoffs(doc: dict[str, Any]) -> list[dict[str, Any]]:
    """Per family and precision: the largest n reached (r = 2) and, there and at n = 16, the
    residual, the bound and the seconds of one evaluation; certified digits per second =
    -log10(bound / term scale) / seconds (the exact evaluation: residual 0, digits unbounded)."""
    out = []
    for fam, sec in doc["families"].items():
        for prec in ("float64", "ball", "mpmath30", "mpmath50", "mpmath100", "exact"):
            pts = [x for x in sec.get("against_precision", []) if x["precision"] == prec and x.get("status") == "ok"]
            if not pts:
                continue
            for tag, x in (("n = 16", next((y for y in pts if y["n"] == 16), None)), ("largest n", pts[-1])):
                if x is None:
                    continue
                bound = x.get("max_bound") or 0.0
                # absolute digits; the relative column is the float64 method's own resolution test
                digits = _digits(bound, 1.0)
                rel = _digits(x["worst_resolution"], 1.0) if prec == "float64" and "worst_resolution" in x else None
                out.append({"family": fam, "precision": prec, "at": tag, "n": x["n"], "r": x["r"],
                            "relative_digits": rel,
                            "max_residual": x.get("max_residual"), "max_bound": bound, "seconds": x["seconds"],
                            "certified_digits": digits,
                            "digits_per_second": digits / max(x["seconds"], 1e-6) if math.isfinite(digits) else None})
    return out


def _digits(bound: Any, scale: Any) -> float:
    """-log10(bound / scale): the digits of the terms' scale the bound guarantees (inf: bound 0)."""
    try:
        bound, scale = float(bound), float(scale)
    except (TypeError, ValueError, OverflowError):
        return 0.0
    if bound <= 0:
        return math.inf
    if not (math.isfinite(bound) and math.isfinite(scale)) or scale <= 0:
        return 0.0
    return max(0.0, math.log10(scale) - math.log10(bound))


def markdown(doc: dict[str, Any]) -> str:
    from stiefelsym.methods.costmodel import table
    lines = ["# Speed against error", "",
             f"Generated {doc['generated']} by `{doc['command']}` on {doc['platform']} "
             f"({doc.get('seconds', '?')} s).", "",
             "For one representative claim per family: time against n for every method (each run in a budgeted "
             "worker), the observed residual against n up to n = 200 next to the error model's predicted bound "
             "e, at float64, mpmath with 30, 50 and 100 digits, in ball arithmetic (the ball method: arb at 53 to 424 "
             "bits, a rigorous bound of every entry at the same exact point) and exactly (rational arithmetic at "
             "the same point); the error-against-time panel puts float64, ball and exact side by side.  For a true statement the exact residual is 0, so the observed |residual| is the rounding "
             "error and must never exceed its bound; up to the size where the exact evaluation is affordable "
             "the computed residual is also compared entry by entry with the exact one (|computed − exact| ≤ e). "
             f"**{len(doc['violations'])} evaluations exceeded their bound** (any would be a bug of the error "
             "model; `tests/test_speed.py` fails on it, on fresh data and on this report's `speed.json`).", "",
             "Sizes: float64 reaches n = 200 at r = 2 in every family; r = ceil(n/2) and the mpmath and exact "
             "series go as far as their caps allow (mpmath arithmetic is entry by entry: about 30 to 200 times "
             "float64's time at n = 16, and the cut is where each series stopped, listed per family).  "
             "Before each size the "
             "time is predicted from the series so far by the cost model's power law (an upper envelope of the "
             "measured times), and a size predicted beyond the cap is not started; the `predicted s` column "
             "shows that prediction next to the measured time.", ""]
    for fam, sec in doc["families"].items():
        lines += [f"## {fam}: `{sec['claim']}`", "", f"![{fam}](speed-{fam}.png)", "",
                  f"([PDF](speed-{fam}.pdf))", ""]
        if sec.get("note"):
            lines += [sec["note"], ""]
        if sec.get("against_n2"):
            lines += ["float64: residual against n, r = 2", ""] + _residual_table(sec["against_n2"])
        if sec["against_n"]:
            lines += ["float64: residual against n, r = ceil(n/2)", ""] + _residual_table(sec["against_n"])
        if sec["against_precision"]:
            lines += ["residual against precision and n (r = 2)", ""] + _residual_table(sec["against_precision"])
        if sec.get("stops"):
            lines += ["where each series stopped:", ""] + [f"- {s}" for s in sec["stops"]] + [""]
        if sec["times"]:
            ns = sorted({rec["n"] for rec in sec["times"]})
            lines += ["time against n, seconds per run (r = 2 / r = ceil(n/2); the cost model's series)", "",
                      "| method | " + " | ".join(f"n = {n}" for n in ns) + " |",
                      "| --- | " + " | ".join("---:" for _ in ns) + " |"]
            for method in ("exact", "rational", "modular", "float", "ball"):
                cells = []
                for n in ns:
                    two_ = [x for x in sec["times"] if x["method"] == method and x["n"] == n and x["r"] == 2]
                    half_ = [x for x in sec["times"] if x["method"] == method and x["n"] == n
                             and x["r"] == (n + 1) // 2 and x["r"] != 2]
                    text = "/".join(f"{x[0]['seconds']:.3g}" + ("" if x[0]["verdict"] not in ("inconclusive", "error")
                                                                 else "!") if x else "-" for x in (two_, half_))
                    cells.append("-" if text == "-/-" else text)
                if any(c != "-" for c in cells):
                    lines.append(f"| {method} | " + " | ".join(cells) + " |")
            lines += ["", "(! : not decided within the run's cap)", ""]
        reach = {}
        for rec in sec["times"]:
            if rec["verdict"] not in ("inconclusive", "error"):
                reach[rec["method"]] = max(reach.get(rec["method"], 0), rec["n"])
        if reach:
            lines += ["largest n reached within the series' time: " +
                      ", ".join(f"{m} n = {k}" for m, k in sorted(reach.items())), ""]
    lines += ["## Error reached per second", "",
              "One evaluation of the claim at the float method's point (r = 2), per precision: at n = 16 and at "
              "the largest n the series reached within its budget.  `certified digits` = −log10 of the largest "
              "bound e: the absolute decimal digits to which every residual entry is guaranteed (the points "
              "have entries of size O(1)); the last column is −log10 max(e / m) over the entries, the float "
              "method's own resolution test (it needs 8; the term scales m grow with n, so this stays high "
              "where the absolute digits fall); it is shown for float64, the precision the verdicts rest on.  "
              "The exact evaluation has no rounding "
              "(its residual is exactly 0 for these true claims).", "",
              "| family | precision | at | n | max \\|residual\\| | bound e | s | certified digits | digits per second "
              "| digits relative to the terms' scale (float64) |",
              "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for t in doc.get("tradeoffs") or tradeoffs(doc):
        dps = t["digits_per_second"]
        digits = t["certified_digits"]
        dtext = "exact" if not math.isfinite(digits) else f"{digits:.1f}"
        ptext = "-" if dps is None else f"{dps:.3g}"
        lines.append(f"| {t['family']} | {t['precision']} | {t['at']} | {t['n']} | {_fmt(t['max_residual'])} | "
                     f"{_fmt(t['max_bound'])} | {t['seconds']:.4f} | {dtext} | {ptext} | "
                     f"{'-' if t.get('relative_digits') is None else format(t['relative_digits'], '.1f')} |")
    lines += ["", "## Cost model", "",
              "Measured per method and family on the family's representative claim, at r = 2 and r = ceil(n/2), "
              "from n = 4 up to the largest n each method reaches within the cap (each run in a fresh worker "
              "process with one BLAS thread; the cap is 20 s per run on this shared machine, against the 60 s "
              "the issue allows, and the sizes stop at n = 4096).  Fitted per method and family by a sum of "
              "monomials in n and r with nonnegative coefficients (a fixed cost, n r and n r² for n × r blocks, "
              "n² for the entries of n × n matrices, n² r and n³ for their products; the symbolic methods to "
              "degree 8) minimizing the relative error; the peak memory of a run likewise with the terms 1, "
              "n r, n² (`stiefelsym/methods/costmodel.json`; `verify --budget` and `verify --memory` refuse a run "
              "predicted beyond them).  The fit is reproducible from the stored measurements: `stiefelsym speed "
              "--cost-only --records stiefelsym/costmodel.json --report-dir reports/speed --model-file "
              "stiefelsym/costmodel.json`.", "",
              "![cost model](costmodel.png)", "", table(doc["costmodel"]), "",
              *_accuracy_lines(doc.get("accuracy")),
              f"Claims other than the five measured ones are predicted as their kind's family times a factor "
              f"calibrated on the catalog's own runs (`claim_factors`, "
              f"{len(doc['costmodel'].get('claim_factors') or {})} "
              f"claims: at (n, r), the worst ratio of the claim's time to its family's prediction over its runs at "
              f"n' <= n, r' <= r, so never below what a smaller run took, relatively); a claim never timed gets "
              f"{UNKNOWN_CLAIM_FACTOR:g} times the slowest family.", "",
              *_catalog_accuracy_lines(doc["costmodel"].get("catalog_accuracy")),
              "Hard cases: [hard.md](hard.md).", ""]
    return "\n".join(lines)
