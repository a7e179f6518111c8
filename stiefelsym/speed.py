"""Speed against error: what each method costs and what the float method's error model predicts.

For one representative catalog claim per family (flows, big Lax, dual Lax, brackets,
dimensions; :data:`stiefelsym.costmodel.FAMILIES`):

* **time against n** for every method (the cost model's measurements, in budgeted workers);
* **residual against n** in float64: the largest observed |residual| of the claim at the float
  method's own point, next to the error model's predicted bound e (every entry must have
  |residual| <= e: for a true statement the exact residual is 0, so |residual| is the rounding
  error, and e is the model's bound on it);
* **residual against precision** at one size: float64, mpmath at 30, 50 and 100 digits, and the
  exact evaluation (rational points: residual exactly 0), with times.

A point where an observed residual exceeds its predicted bound is a bug of the error model:
``violations`` lists them and the tests require it to be empty.

The hard cases (:mod:`stiefelsym.hard`) are tabulated by :func:`hard_table`: each case at
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

from .costmodel import FAMILIES, UNKNOWN_CLAIM_FACTOR

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


def _float_point_field() -> Any:
    """Exact rationals at the float method's own points (the same draws: k / 2^40)."""
    import flint
    from .fields import RationalField

    class FloatPointRationals(RationalField):
        name = "rational (at the float point)"

        def param(self, name, rng):
            return flint.fmpq(rng.randint(-2**40, 2**40), 2**40)
    return FloatPointRationals()


def exact_entries(claim: Any, n: int, r: int, seed: int = 0, hard: str | None = None,
                  component: int = 0) -> list[Fraction]:
    """The claim's residual entries, exactly, at the very point the float method evaluates."""
    from .claims import Count, Rank
    from .methods import _entries, call_claim
    from .scene import Scene
    field = _float_point_field()
    rng = random.Random(f"{seed}|{claim.id}|{n}|{r}|float" + (f"|component {component}" if component else ""))
    options = None
    if hard:
        from .hard import hard_case
        options = {"hard": hard_case(hard), "hard_hits": []}
    scene = Scene(n, r, field, chart="cayley", rng=rng, component=component, realization=claim.realization,
                  options=options)
    out = []
    for name, value in call_claim(claim.func, scene).items():
        if isinstance(value, (Rank, Count)):
            continue
        out += [_exact_fraction(x) for _, x in _entries(value, name)]
    return out


def evaluate(claim: Any, n: int, r: int, dps: int | None = None, seed: int = 0, hard: str | None = None,
             component: int = 0, exact: bool = False) -> dict[str, Any]:
    """The claim's residual entries at the float method's own point, at one precision.

    Returns the largest |residual|, the largest predicted bound e, the number of entries with
    |residual| > e (``exceed``: must be 0 for a true claim), whether every bound resolves 1e-8 of
    its term scale, whether anything overflowed, and the time.  With ``exact`` the residual is
    also computed exactly at the same point, and ``exceed_exact`` counts the entries whose actual
    rounding error |computed - exact| exceeds the bound e (must be 0 for every claim, true or
    false: that is what the bound claims)."""
    import mpmath
    import numpy as np
    from .claims import Count, Rank
    from .fields import ErrNum, FloatField
    from .methods import _entries, call_claim
    from .scene import Scene
    field = FloatField(dps)
    rng = random.Random(f"{seed}|{claim.id}|{n}|{r}|float" + (f"|component {component}" if component else ""))
    options = None
    if hard:
        from .hard import hard_case
        options = {"hard": hard_case(hard), "hard_hits": []}
    t0 = time.perf_counter()
    out: dict[str, Any] = {"claim": claim.id, "n": n, "r": r, "precision": _label(dps),
                           "digits": 15.95 if dps is None else dps}
    try:
        ctx = mpmath.workdps(dps) if dps else np.errstate(over="ignore", invalid="ignore")
        with ctx:
            scene = Scene(n, r, field, chart="cayley", rng=rng, component=component,
                          realization=claim.realization, options=options)
            checks = call_claim(claim.func, scene)
            entries = []
            for name, value in checks.items():
                if isinstance(value, (Rank, Count)):
                    continue
                for _, x in _entries(value, name):
                    entries.append(x if isinstance(x, ErrNum) else field.const(x))
    except Exception as exc:  # noqa: BLE001 - a degenerate point, an overflow: reported, not raised
        out.update(status="error", message=f"{type(exc).__name__}: {exc}", seconds=time.perf_counter() - t0)
        return out
    seconds = time.perf_counter() - t0
    if not entries:
        out.update(status="no residuals", seconds=seconds, entries=0)
        return out
    if exact and all(_finite(x) for x in entries):
        try:
            ex = exact_entries(claim, n, r, seed, hard, component)
        except Exception as exc:  # noqa: BLE001 - a degenerate point for exact arithmetic
            out["exact_error"] = f"{type(exc).__name__}: {exc}"
        else:
            if len(ex) == len(entries):
                errs = [abs(_exact_fraction(x.v) - q) for x, q in zip(entries, ex)]
                out["exceed_exact"] = sum(1 for x, err in zip(entries, errs) if err > _exact_fraction(x.e))
                out["max_exact_residual"] = _number(max(abs(q) for q in ex))
                out["max_actual_error"] = _number(max(errs))
            else:
                out["exact_error"] = "the exact evaluation has another number of entries"
    finite = all(_finite(x) for x in entries)
    vals = [_clip(abs(x.v)) if _finite(x) else math.inf for x in entries]
    bounds = [_clip(x.e) if _finite(x) else math.inf for x in entries]
    scales = [_clip(x.m) if _finite(x) else math.inf for x in entries]
    exceed = sum(1 for x in entries if _finite(x) and abs(x.v) > x.e)
    resolved = finite and all(x.e <= 1e-8 * x.m for x in entries)
    out.update(status="ok" if finite else "overflow", seconds=seconds, entries=len(entries),
               max_residual=max(vals), max_bound=max(bounds), max_scale=max(scales),
               exceed=exceed, resolved=resolved,
               worst_ratio=max((v / b) if b > 0 else (0.0 if v == 0 else math.inf) for v, b in zip(vals, bounds)))
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

def residual_against_n(claim: Any, ns: Sequence[int], cap: float = 10.0, total: float = 30.0,
                       seed: int = 0, exact_n: int = 6) -> list[dict[str, Any]]:
    """float64 residual and bound against n (r = ceil(n/2)), until one evaluation takes ``cap``
    seconds or the series ``total``; past an overflow in float64 the float method escalates, and so
    does this series (the first precision of the ladder that stays finite)."""
    out, spent = [], 0.0
    for n in ns:
        r = (n + 1) // 2
        rec = evaluate(claim, n, r, None, seed, exact=n <= exact_n)
        if rec.get("status") == "overflow":
            for dps in (30, 60, 120):
                esc = evaluate(claim, n, r, dps, seed, exact=n <= exact_n)
                esc["seconds"] += rec["seconds"]
                esc["escalated_from"] = "float64 (overflow)"
                rec = esc
                if rec.get("status") == "ok":
                    break
        out.append(rec)
        spent += rec.get("seconds", 0.0)
        if rec.get("status") in ("error", "no residuals") or rec.get("seconds", 0) > cap or spent > total:
            break
    return out


def residual_against_precision(claim: Any, n: int, r: int, seed: int = 0,
                               precisions: Iterable[int | None] = PRECISIONS) -> list[dict[str, Any]]:
    """float64, mpmath at 30, 50, 100 digits and the exact evaluation, at one size."""
    out = [evaluate(claim, n, r, dps, seed, exact=True) for dps in precisions]
    from .claims import Size
    from .runner import run_one
    t0 = time.perf_counter()
    res = run_one(claim, Size(n, r), "rational", seed)
    out.append({"claim": claim.id, "n": n, "r": r, "precision": "exact", "digits": math.inf,
                "status": "ok" if res.verdict in ("checked", "proved") else res.verdict,
                "verdict": res.verdict, "seconds": time.perf_counter() - t0,
                "max_residual": 0.0 if res.verdict in ("checked", "proved") else None,
                "max_bound": 0.0, "exceed": 0,
                "note": "exact rational points: the residual is exactly 0 at each (the time is that of the "
                        "whole randomized check, with its Schwartz-Zippel bound)"})
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
    from .claims import Claim, admissible
    from .matrix import comm

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


def hard_table(cases: Sequence[str] | None = None, claims: Sequence[Any] | None = None,
               sizes: Sequence[tuple[int, int]] = HARD_SIZES, methods: Sequence[str] = ("float", "modular"),
               timeout: float = 60.0, seed: int = 0, large: tuple[int, int] | None = HARD_LARGE,
               registry: Any = None, exact_check_n: int = 6) -> list[dict[str, Any]]:
    """Every hard case x claim x size x method: verdict, precision reached, time, judged."""
    from .claims import Size, load_catalog
    from .hard import HARD_CASES
    from .runner import verify
    cases = list(cases or HARD_CASES)
    if claims is None:
        registry = registry or load_catalog("proofs")
        claims = [registry.get(c) for c in HARD_CLAIMS] + [control_claim()]
    rows = []
    for case in cases:
        for c in claims:
            truth = "false" if c.id == "corrupted-LA1" else "true"
            plan = [Size(n, r) for n, r in sizes if c.sizes.admits(n, r)]
            if large and c.sizes.admits(*large):
                plan.append(Size(*large))
            for m in methods:
                results = verify([c], sizes=plan, methods=(m,), seed=seed, hard=case, timeout=timeout)
                for res in results:
                    if res.variant is not None:
                        continue
                    text = " ".join(x for x in (res.message, res.certificate) if x)
                    untouched = "changed no parameter" in text
                    label = _precision_reached(text) if m == "float" else "exact"
                    check = None
                    if m == "float" and res.verdict in ("undecided", "numeric") and label != "-" \
                            and (truth == "false" or res.n <= exact_check_n):
                        try:
                            check = _exact_check(c, res.n, res.r, seed, case, label)
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


def _short(text: str, k: int) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= k else text[: k - 3] + "..."


def hard_markdown(rows: Sequence[dict[str, Any]]) -> str:
    from .hard import HARD_CASES
    wrong = [r for r in rows if r["judgement"].startswith("WRONG")]
    lines = ["# Hard numerical cases", "",
             "Each case rewrites the sampled parameters (`stiefelsym verify --hard CASE`); a hard point is "
             "chosen, not random, so a pass there is `undecided` (\"resolved at the hard point\"), a failure a "
             "certain `fails` with an exact witness.  The rule checked here: a true claim never gets `fails`, "
             "and the corrupted control (`corrupted-LA1`, M = Φ + λA in the big Lax equation) never gets a "
             "passing verdict.  "
             "`precision` is the last precision of the float method's ladder that resolved the point "
             "(float64, then mpmath at 30, 60, 120 digits: escalation happens by itself).  Where the float "
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
    lines += ["", f"**{len(rows)} runs, {len(wrong)} wrong verdicts.**", "",
              "| case | claim | (n,r) | method | verdict | precision | s | exact residual | actual error | bound e "
              "| judgement | note |",
              "| --- | --- | --- | --- | --- | --- | ---: | ---: | ---: | ---: | --- | --- |"]
    for r in rows:
        note = "case does not touch this claim" if not r["touched"] else (
            r["reason"] if r["verdict"] in ("inconclusive", "fails", "error") else "")
        lines.append(f"| {r['case']} | {r['claim']} | ({r['n']},{r['r']}) | {r['method']} | {r['verdict']} | "
                     f"{r['precision']} | {r['seconds']:.3f} | {_fmt(r.get('exact_residual'))} | "
                     f"{_fmt(r.get('actual_error'))} | {_fmt(r.get('bound'))} | {r['judgement']} | "
                     f"{note.replace('|', '/')} |")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- plots and report

def plot_family(fam: str, claim_id: str, times: Sequence[dict[str, Any]], against_n: Sequence[dict[str, Any]],
                against_p: Sequence[dict[str, Any]], out_dir: Path) -> list[Path]:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.6))
    ax = axes[0]
    for method in ("exact", "rational", "modular", "float"):
        pts = {}
        for rec in times:
            if rec["method"] == method:
                pts[rec["n"]] = max(pts.get(rec["n"], 0.0), rec["seconds"])
        if pts:
            ns = sorted(pts)
            ax.loglog(ns, [max(pts[n], 1e-5) for n in ns], "o-", ms=3, label=method)
    ax.set_xlabel("n")
    ax.set_ylabel("seconds per run")
    ax.set_title("time against n (r = ceil(n/2), n)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
    ax = axes[1]
    ok = [x for x in against_n if x.get("status") == "ok"]
    if ok:
        ns = [x["n"] for x in ok]
        ax.semilogy(ns, [max(x["max_residual"], 1e-300) for x in ok], "o-", ms=3, label="observed |residual|")
        ax.semilogy(ns, [x["max_bound"] for x in ok], "s--", ms=3, label="predicted bound e")
        for x in ok:
            if x.get("escalated_from"):
                ax.annotate(x["precision"], (x["n"], x["max_bound"]), fontsize=6)
    ax.set_xlabel("n")
    ax.set_title("float: residual and predicted bound against n", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7)
    ax = axes[2]
    fin = [x for x in against_p if x.get("status") == "ok" and x["precision"] != "exact"]
    if fin:
        ds = [x["digits"] for x in fin]
        ax.semilogy(ds, [max(x["max_residual"], 1e-300) for x in fin], "o-", ms=3, label="observed |residual|")
        ax.semilogy(ds, [max(x["max_bound"], 1e-300) for x in fin], "s--", ms=3, label="predicted bound e")
        ax2 = ax.twinx()
        ax2.plot(ds, [x["seconds"] for x in fin], "^:", color="C3", ms=3, label="seconds")
        ax2.set_ylabel("seconds", fontsize=8)
    n0 = against_p[0]["n"] if against_p else "?"
    r0 = against_p[0]["r"] if against_p else "?"
    ax.set_xlabel("digits (float64 = 16)")
    ax.set_title(f"residual against precision at ({n0},{r0})", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=7, loc="lower left")
    fig.suptitle(f"{fam}: {claim_id}", fontsize=10)
    fig.tight_layout()
    paths = []
    for ext in ("png", "pdf"):
        p = out_dir / f"speed-{fam}.{ext}"
        fig.savefig(p, dpi=110)
        paths.append(p)
    plt.close(fig)
    return paths


def _fmt(x: Any) -> str:
    if x is None:
        return "-"
    if isinstance(x, float):
        if math.isinf(x):
            return "inf"
        return f"{x:.2e}"
    return str(x)


def markdown(doc: dict[str, Any]) -> str:
    from .costmodel import table
    lines = ["# Speed against error", "",
             f"Generated {doc['generated']} by `{doc['command']}` on {doc['platform']}.", "",
             "For one representative claim per family: time against n for every method (each run in a budgeted "
             "worker), the float method's observed residual against n next to the error model's predicted "
             "bound, and residual against precision at one size.  For a true statement the exact residual is "
             "0, so the observed |residual| is the rounding error and must never exceed its bound; "
             f"**{len(doc['violations'])} evaluations exceeded their bound** (any would be a bug of the error "
             "model).", ""]
    for fam, sec in doc["families"].items():
        lines += [f"## {fam}: `{sec['claim']}`", "", f"![{fam}](speed-{fam}.png)", ""]
        if sec["against_n"]:
            lines += ["float: residual against n (r = ceil(n/2))", "",
                      "| n | r | precision | max \\|residual\\| | max bound e | actual error vs exact "
                      "| entries over bound "
                      "| resolves 1e-8 of scale | s |",
                      "| ---: | ---: | --- | ---: | ---: | ---: | ---: | --- | ---: |"]
            for x in sec["against_n"]:
                over = x.get("exceed", "-") if "exceed_exact" not in x else x["exceed"] + x["exceed_exact"]
                lines.append(f"| {x['n']} | {x['r']} | {x['precision']} | {_fmt(x.get('max_residual'))} | "
                             f"{_fmt(x.get('max_bound'))} | {_fmt(x.get('max_actual_error'))} | {over} | "
                             f"{x.get('resolved', '-')} | {x.get('seconds', 0):.3f} |")
            lines.append("")
        if sec["against_precision"]:
            p0 = sec["against_precision"][0]
            lines += [f"residual against precision at ({p0['n']},{p0['r']})", "",
                      "| precision | max \\|residual\\| | max bound e | entries over bound | s |",
                      "| --- | ---: | ---: | ---: | ---: |"]
            for x in sec["against_precision"]:
                lines.append(f"| {x['precision']} | {_fmt(x.get('max_residual'))} | {_fmt(x.get('max_bound'))} | "
                             f"{x.get('exceed', '-')} | {x.get('seconds', 0):.4f} |")
            lines.append("")
        if sec["times"]:
            ns = sorted({rec["n"] for rec in sec["times"]})
            lines += ["time against n, seconds per run (r = ceil(n/2) / r = n)", "",
                      "| method | " + " | ".join(f"n = {n}" for n in ns) + " |",
                      "| --- | " + " | ".join("---:" for _ in ns) + " |"]
            for method in ("exact", "rational", "modular", "float"):
                cells = []
                for n in ns:
                    half = [x for x in sec["times"] if x["method"] == method and x["n"] == n and x["r"] == (n + 1) // 2]
                    full = [x for x in sec["times"] if x["method"] == method and x["n"] == n and x["r"] == n
                            and n > 1]
                    text = "/".join(f"{x[0]['seconds']:.3g}" + ("" if x[0]["verdict"] not in ("inconclusive", "error")
                                                                 else "!") for x in (half, full) if x)
                    cells.append(text or "-")
                if any(c != "-" for c in cells):
                    lines.append(f"| {method} | " + " | ".join(cells) + " |")
            lines += ["", "(! : not decided within the run's budget)", ""]
        reach = {}
        for rec in sec["times"]:
            if rec["verdict"] not in ("inconclusive", "error"):
                reach[rec["method"]] = max(reach.get(rec["method"], 0), rec["n"])
        if reach:
            lines += ["largest n reached within the series' time: " +
                      ", ".join(f"{m} n = {k}" for m, k in sorted(reach.items())), ""]
    lines += ["## Error reached per second", "",
              "| family | precision | n | max \\|residual\\| | s | digits of residual per second |",
              "| --- | --- | ---: | ---: | ---: | ---: |"]
    for fam, sec in doc["families"].items():
        for x in sec["against_precision"]:
            if x["precision"] == "exact" or x.get("status") != "ok":
                continue
            res = max(x["max_residual"], 1e-300)
            lines.append(f"| {fam} | {x['precision']} | {x['n']} | {_fmt(x['max_residual'])} | {x['seconds']:.4f} | "
                         f"{-math.log10(res) / max(x['seconds'], 1e-6):.3g} |")
    lines += ["", "## Cost model", "",
              "Fitted per method and family: t(n) = exp(a) n^b seconds, raised to lie above every measured point "
              "(`stiefelsym/costmodel.json`; `verify --budget` refuses a run predicted beyond it).", "",
              "![cost model](costmodel.png)", "", table(doc["costmodel"]), "",
              f"Claims other than the five measured ones are predicted as their kind's family times a factor "
              f"calibrated on the catalog's own runs (`claim_factors`, "
              f"{len(doc['costmodel'].get('claim_factors') or {})} "
              f"claims: the worst ratio of a claim's time to its family's prediction); a claim never timed gets "
              f"{UNKNOWN_CLAIM_FACTOR:g} times the slowest family.", "",
              "Hard cases: [hard.md](hard.md).", ""]
    return "\n".join(lines)
