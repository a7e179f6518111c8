"""The benchmark targets of the engine, measured side by side in one run.

Every target is printed with its measured value, its goal and the ratio measured/goal, and
written to ``reports/bench.json`` and ``reports/bench.md``.  The engine is reached through its
public entry points only (``stiefelsym.run.runner``: ``run_one`` in this process, ``verify`` in
budgeted worker processes; the ``stiefelsym`` command in subprocesses), so the numbers follow
the engine as it improves.  A target the engine cannot run yet (a size refused by the current
size caps, a run past its time budget) is reported as "not yet" with the reason, never a crash.

Baseline: naive sympy -- substitute the Cayley parametrization of T*V(n, r) into the residual
dL/dt - [M, L] of the big Lax equation LA1 along the printed flow (No) and call ``simplify``
on every entry.  Against it, in the same run: the engine's exact, rational, modular and float
methods and the dimension-free proof.

    python bench/bench.py                  # every target (make verify at n <= 6 included: minutes)
    python bench/bench.py --quick          # without the make verify run (and its peak memory)
    python bench/bench.py --sizes 2,1 3,1  # sizes of the side-by-side LA1 table
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import re
import resource
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from stiefelsym import admissible, comm  # noqa: E402
from stiefelsym.claims import Claim, Size  # noqa: E402
from stiefelsym.run.runner import run_one  # noqa: E402

GIB = 1 << 30
#: the targets that run the whole catalog (minutes each; skipped by --quick, run by --only when named)
CATALOG_TARGETS = ("make verify, n <= 6, 2 jobs (wall)", "make verify peak memory (max RSS)",
                   "verify, n <= 7, 2 jobs (wall)", "n <= 7: records proved exactly, of proved or checked",
                   "mutation analysis of the catalog, 2 jobs (wall)")
#: the §3 claims that are flows (derived Dirac flow against the printed one) or their multipliers
SEC3_FLOWS = ("euclidean-flow", "euclidean-multipliers", "submersion-flow", "normal-flow", "metric-flow")
STIEFELSYM = str(Path(sys.executable).with_name("stiefelsym"))


def neumann_flow(s):
    """The printed Neumann flow (No)."""
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    return {"X": P - k * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}


def la1_residual(s):
    """dL/dt - [M, L] for L = lambda Phi + X X^T - lambda^2 A, M = Phi - lambda A."""
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    M = s.Phi - s.lam * s.A
    return {"LA1": s.d(L, neumann_flow(s)) - comm(M, L(s))}


LA1 = Claim(id="LA1", paper=("LA1",), kind="lax", section="5", func=la1_residual,
            sizes=admissible(5), title="The big Lax equation along the printed Neumann flow.")


def naive_sympy(n: int, r: int) -> float:
    """CPU seconds of the naive sympy proof of LA1 at (n, r)."""
    import sympy as sp
    t0 = time.process_time()
    S = sp.zeros(n, n)
    for i in range(n):
        for j in range(i + 1, n):
            x = sp.Symbol(f"s{i}{j}")
            S[i, j], S[j, i] = x, -x
    W = sp.zeros(r, r)
    for i in range(r):
        for j in range(i + 1, r):
            x = sp.Symbol(f"w{i}{j}")
            W[i, j], W[j, i] = x, -x
    Z = sp.Matrix(n, r, lambda i, j: sp.Symbol(f"z{i}{j}"))
    A = sp.diag(*[sp.Symbol(f"a{i}") for i in range(n)])
    lam, kap = sp.symbols("lambda kappa")
    I = sp.eye(n)
    Q = (I - S) * (I + S).inv()
    X = Q[:, :r]
    P = X * W + (I - X * X.T) * Z
    k = 1 + 2 * kap
    Xd = P - k * X * P.T * X
    Pd = -A * X - X * P.T * P + k * P * X.T * P + X * X.T * A * X
    Phi = P * X.T - X * P.T
    L = lam * Phi + X * X.T - lam**2 * A
    M = Phi - lam * A
    dL = lam * (Pd * X.T + P * Xd.T - Xd * P.T - X * Pd.T) + Xd * X.T + X * Xd.T
    R = dL - (M * L - L * M)
    for i in range(n):
        for j in range(n):
            if sp.simplify(R[i, j]) != 0:
                raise AssertionError("naive baseline: nonzero residual")
    return time.process_time() - t0


def la1_numpy(n: int, r: int, rng: Any) -> Any:
    """The residual of LA1 at a random point of the Cayley chart in plain numpy: the products the float
    check evaluates, with no error bounds, no term scales and no verdict (the baseline of its overhead)."""
    import numpy as np
    S = np.triu(rng.standard_normal((n, n)), 1)
    S = S - S.T
    W = np.triu(rng.standard_normal((r, r)), 1)
    W = W - W.T
    Z = rng.standard_normal((n, r))
    a = rng.standard_normal(n)
    lam, kappa = rng.standard_normal(2)
    E = np.eye(n, r)
    X = 2 * np.linalg.solve(np.eye(n) + S, E) - E
    P = X @ W + Z - X @ (X.T @ Z)
    k = 1 + 2 * kappa
    Xd = P - k * (X @ (P.T @ X))
    Pd = -(a[:, None] * X) - X @ (P.T @ P) + k * (P @ (X.T @ P)) + X @ ((X.T * a) @ X)
    Phi = P @ X.T - X @ P.T
    XXt = X @ X.T
    L = lam * Phi + XXt - lam * lam * np.diag(a)
    M = Phi - lam * np.diag(a)
    dL = lam * (Pd @ X.T + P @ Xd.T - Xd @ P.T - X @ Pd.T) + Xd @ X.T + X @ Xd.T
    return dL - (M @ L - L @ M)


def la1_flint(n: int, r: int, p: int, rng: Any) -> Any:
    """The residual of LA1 at a random point of the Cayley chart over GF(p), written by hand with flint's
    ``nmod_mat``: the products of :func:`la1_numpy` (the Cayley point, the flow, the residual), with no degree
    markers, no scene and no verdict (the baseline of the modular method's overhead per point).  The
    parameters are drawn as the engine draws them, a block at a time by a numpy generator (``rng``), and
    enter flint as lists of Python ints."""
    import numpy as np
    from flint import nmod, nmod_mat

    def rand(m: int, k: int) -> Any:
        return nmod_mat(m, k, rng.integers(0, p, size=m * k).tolist(), p)

    def skew(m: int) -> Any:
        U = np.zeros((m, m), dtype=np.int64)
        U[np.triu_indices(m, 1)] = rng.integers(0, p, size=m * (m - 1) // 2)
        return nmod_mat(m, m, np.where(U.T > 0, p - U.T, U).ravel().tolist(), p)

    def diag(m: int, k: int, xs: list[int]) -> Any:
        M = nmod_mat(m, k, p)
        for i, x in enumerate(xs):
            M[i, i] = x
        return M

    S, W, Z = skew(n), skew(r), rand(n, r)
    A = diag(n, n, rng.integers(0, p, size=n).tolist())
    lam, kappa = (nmod(int(x), p) for x in rng.integers(0, p, size=2))
    E = diag(n, r, [1] * min(n, r))
    X = (diag(n, n, [1] * n) + S).solve(E) * 2 - E
    XT = X.transpose()
    P = X * W + Z - X * (XT * Z)
    PT = P.transpose()
    k = 1 + 2 * kappa
    Xd = P - X * (PT * X) * k
    Pd = -(A * X) - X * (PT * P) + P * (XT * P) * k + X * ((XT * A) * X)
    Phi = P * XT - X * PT
    XXt = X * XT
    L = Phi * lam + XXt - A * (lam * lam)
    M = Phi - A * lam
    dL = (Pd * XT + P * Xd.transpose() - Xd * PT - X * Pd.transpose()) * lam + Xd * XT + X * Xd.transpose()
    return dL - (M * L - L * M)


# --------------------------------------------------------------------------- helpers

class NotYet(Exception):
    """The engine cannot run this target yet (a size cap, a time budget); the reason."""


def _catalog():
    from stiefelsym.claims import load_catalog
    return load_catalog()


def _budgeted(claim: Claim, n: int, r: int | None, method: str, timeout: float) -> Any:
    """One run in a budgeted worker (runner.verify); NotYet when refused or not decided in time."""
    from stiefelsym.run.runner import BudgetError, verify
    from stiefelsym.scene import SizeError
    try:
        results = verify([claim], sizes=None if r is None else [Size(n, r)], methods=(method,), timeout=timeout)
    except (BudgetError, SizeError) as exc:
        raise NotYet(f"refused by the engine: {exc}") from None
    res = next((x for x in results if x.variant is None and (r is None or (x.n, x.r) == (n, r))), None)
    if res is None:
        raise NotYet("no result")
    if res.verdict in ("inconclusive", "error"):
        raise NotYet(f"{res.verdict}: {(res.message or '')[:160]}")
    return res


def _points(res: Any) -> int:
    """The number of random points a randomized check used (from its certificate)."""
    m = re.search(r"(\d+) independent points", res.certificate or "")
    k = int(m.group(1)) if m else 1
    return k * (2 if "2 components" in (res.certificate or "") else 1)


def _bare_modular(n: int, r: int, repeat: int = 3) -> str:
    """One evaluation of LA1 at one point over GF(p), nothing else (a scene and the claim)."""
    try:
        import random as _random
        from stiefelsym import Scene
        from stiefelsym.backends.fields import ModularField
        best = None
        for k in range(repeat):
            t0 = time.perf_counter()
            la1_residual(Scene(n, r, ModularField(2**61 - 1), rng=_random.Random(k)))
            t = time.perf_counter() - t0
            best = t if best is None else min(best, t)
        return f"{best * 1e3:.3f} ms"
    except Exception as exc:  # noqa: BLE001 - a side measurement only
        return f"not measured ({type(exc).__name__})"


def _float_evaluation(claim: Claim, n: int, r: int, seed: int = 0) -> Any:
    """The float method's float64 evaluation alone (its values, error bounds and term scales, and the
    verdict they support), without the exact confirmation of a `numeric` that ``run_one(..., "float")``
    adds: a private entry of the engine, used for the side-by-side measure of the evaluation only."""
    from stiefelsym.methods.fixed_size import _run_float
    from stiefelsym.backends.native import one_blas_thread, quiet_numpy
    with one_blas_thread(), quiet_numpy():
        return _run_float(claim, n, r, seed, claim.func, None)


def _wall(cmd: list[str], repeat: int = 3) -> tuple[float, subprocess.CompletedProcess]:
    best, out = None, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    return best, out


def _warm_best(run: Callable[[], Any], warm: int, runs: int) -> tuple[float, float, Any]:
    """Best wall and best CPU seconds of ``runs`` calls after ``warm`` calls (the interpreter's
    specialization and the memos of pure functions warm up over the first few runs), and the last
    result."""
    for _ in range(warm):
        run()
    wall = cpu = math.inf
    res = None
    for _ in range(runs):
        t0, c0 = time.perf_counter(), time.process_time()
        res = run()
        wall, cpu = min(wall, time.perf_counter() - t0), min(cpu, time.process_time() - c0)
    return wall, cpu, res


# --------------------------------------------------------------------------- the targets

class Bench:
    def __init__(self, only: list[str] | None = None) -> None:
        self.rows: list[dict[str, Any]] = []
        #: measure only the targets whose name contains one of these (None: every target)
        self.only = only

    def wanted(self, name: str) -> bool:
        return not self.only or any(w in name for w in self.only)

    def target(self, name: str, goal: float, unit: str, better: str, fn: Callable[[], tuple[float, str]]) -> None:
        """Measure one target: fn() -> (value, note); ``better`` is "lower" or "higher"."""
        if not self.wanted(name):
            return
        t0 = time.perf_counter()
        try:
            value, note = fn()
            status = "met" if (value <= goal if better == "lower" else value >= goal) else "not met"
        except NotYet as exc:
            value, note, status = None, str(exc), "not yet"
        except Exception as exc:  # noqa: BLE001 - a benchmark never crashes: it says what happened
            value, note, status = None, f"{type(exc).__name__}: {exc}", "not yet"
        row = {"target": name, "measured": value, "goal": goal, "unit": unit, "better": better,
               "ratio": None if value is None else value / goal, "status": status, "note": note,
               "bench_seconds": round(time.perf_counter() - t0, 2)}
        self.rows.append(row)
        print(_line(row), flush=True)


def _fmt(v: float | None, unit: str) -> str:
    if v is None:
        return "-"
    if unit == "x":
        return f"{v:,.0f}x" if v >= 100 else f"{v:.1f}x"
    if unit == "GiB":
        return f"{v:.3f} GiB"
    if unit == "share":
        return f"{v:.4f}"
    if unit == "ms":
        return f"{v:.3f} ms"
    return f"{v:.3f} s"


def _line(row: dict[str, Any]) -> str:
    op = "<=" if row["better"] == "lower" else ">="
    ratio = "-" if row["ratio"] is None else f"{row['ratio']:.3g}"
    return (f"{row['target']:<52} {_fmt(row['measured'], row['unit']):>14}  goal {op} "
            f"{_fmt(row['goal'], row['unit']):>12}  ratio {ratio:>9}  {row['status']:<8} {row['note']}")


def _timed_command(cmd: list[str], timeout: float) -> tuple[float, subprocess.CompletedProcess]:
    """Wall seconds and the completed process of one command run from the repository's root."""
    t0 = time.perf_counter()
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise NotYet(f"did not finish within {timeout:.0f} s") from None
    return time.perf_counter() - t0, out


def _catalog_run(max_n: int, timeout: float) -> tuple[float, float, list[dict[str, Any]], str]:
    """`stiefelsym verify --max-n max_n` over the catalog with JOBS workers (2 by default), as `make verify`
    runs it: wall seconds, peak RSS (GiB) of the process tree so far, the records and a summary of them."""
    with tempfile.TemporaryDirectory() as d:
        cmd = [STIEFELSYM, "verify", "--jobs", os.environ.get("JOBS", "2"), "--max-n", str(max_n), "--report-dir", d,
               "--format", "json"]
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        wall, out = _timed_command(cmd, timeout)
        peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        if out.returncode == 2:
            raise NotYet(f"refused: {out.stderr.strip().splitlines()[-1] if out.stderr.strip() else '?'}")
        try:
            doc = json.loads(out.stdout)
            results = doc["results"]
        except (ValueError, KeyError):
            raise NotYet(f"no results (exit {out.returncode})") from None
    grades: dict[str, int] = {}
    for r in results:
        grades[r["verdict"]] = grades.get(r["verdict"], 0) + 1
    unexpected = sum(1 for r in results if not r.get("expected"))
    note = (f"{len(results)} runs: " + ", ".join(f"{k} {v}" for k, v in sorted(grades.items()))
            + f"; {unexpected} unexpected; exit {out.returncode}")
    peak = max(peak_kib, before) * 1024 / GIB
    return wall, peak, results, note


def make_verify(timeout: float = 1800.0) -> tuple[float, float, str]:
    """`make verify` restricted to n <= 6: wall seconds and peak RSS (GiB) of the process tree."""
    wall, peak, _results, note = _catalog_run(6, timeout)
    return wall, peak, note


def proved_share(results: list[dict[str, Any]], top: int = 6) -> tuple[float, str]:
    """Of the records at a size that the exact or a randomized exact method decided true (`proved` or `checked`),
    the share proved exactly, and the claims with the most records only `checked`."""
    sized = [r for r in results if r.get("n") is not None]
    proved = sum(1 for r in sized if r["verdict"] == "proved")
    checked: dict[str, int] = {}
    for r in sized:
        if r["verdict"] == "checked":
            checked[r["claim"]] = checked.get(r["claim"], 0) + 1
    total = proved + sum(checked.values())
    if not total:
        raise NotYet("no record proved or checked")
    most = sorted(checked.items(), key=lambda kv: (-kv[1], kv[0]))
    note = (f"{proved} proved, {sum(checked.values())} checked (randomized exact) of {total}"
            + ("; checked most: " + ", ".join(f"{c} {k}" for c, k in most[:top]) if most else ""))
    return proved / total, note


def mutation_run(timeout: float) -> tuple[float, str]:
    """`stiefelsym mutate` over the catalog with JOBS workers, as `make mutate` runs it (its reports to a
    temporary directory): wall seconds, with its survivors and mutants in the note."""
    with tempfile.TemporaryDirectory() as d:
        cmd = [STIEFELSYM, "mutate", "--jobs", os.environ.get("JOBS", "2"), "--report-dir", d]
        wall, out = _timed_command(cmd, timeout)
        try:
            totals = json.loads(Path(d, "mutation.json").read_text())["totals"]
        except (OSError, ValueError, KeyError):
            raise NotYet(f"no mutation.json (exit {out.returncode})") from None
    survived = sum(t["survived"] for t in totals)
    mutants = max(t["total"] for t in totals)
    equivalent = max(t["equivalent"] for t in totals)
    return wall, (f"{mutants} mutants, {equivalent} equivalent, {survived} survivors over the methods "
                  f"{', '.join(t['method'] for t in totals)}; exit {out.returncode}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="skip the catalog runs (minutes): make verify (n <= 6) and its peak memory, n <= 7, mutation analysis")
    ap.add_argument("--sizes", nargs="*", default=None, help="sizes n,r of the side-by-side LA1 table (2,1 3,1)")
    ap.add_argument("--no-baseline", action="store_true", help="skip the naive sympy baseline")
    ap.add_argument("--repeat", type=int, default=3, help="timed engine runs after 10 warm ones, at least 20 (the best is kept)")
    ap.add_argument("--report-dir", default=None,
                    help="where bench.json and bench.md go (default reports/; with --only, nowhere unless given)")
    ap.add_argument("--per-run", type=float, default=20.0, help="time budget of one run at the large sizes (s)")
    ap.add_argument("--verify-timeout", type=float, default=1800.0, help="time budget of the make verify run (s)")
    ap.add_argument("--only", nargs="*", default=None,
                    help="measure only the targets whose name contains one of these words (e.g. --only ball)")
    args = ap.parse_args(argv)
    started = datetime.now(timezone.utc)
    bench = Bench(args.only)
    if args.only:
        args.quick = True
    print(f"{'target':<52} {'measured':>14}  {'goal':>15}  {'ratio':>15}  status   note")

    # 1. make verify (n <= 6) and its peak memory: first, so that RUSAGE_CHILDREN is its own
    if args.only and not any(bench.wanted(name) for name in CATALOG_TARGETS):
        pass
    elif args.quick and not args.only:
        bench.rows.append({"target": "make verify, n <= 6, 2 jobs (wall)", "measured": None, "goal": 60.0,
                           "unit": "s", "better": "lower", "ratio": None, "status": "skipped",
                           "note": "--quick", "bench_seconds": 0})
        bench.rows.append({"target": "make verify peak memory (max RSS)", "measured": None, "goal": 2.0,
                           "unit": "GiB", "better": "lower", "ratio": None, "status": "skipped",
                           "note": "--quick", "bench_seconds": 0})
        for name, goal, unit, better in (("verify, n <= 7, 2 jobs (wall)", 180.0, "s", "lower"),
                                         ("n <= 7: records proved exactly, of proved or checked", 1.0, "share", "higher"),
                                         ("mutation analysis of the catalog, 2 jobs (wall)", 240.0, "s", "lower")):
            bench.rows.append({"target": name, "measured": None, "goal": goal, "unit": unit, "better": better,
                               "ratio": None, "status": "skipped", "note": "--quick", "bench_seconds": 0})
        for row in bench.rows:
            print(_line(row))
    else:
        holder: dict[str, Any] = {}

        def mv() -> tuple[float, str]:
            wall, peak, note = make_verify(args.verify_timeout)
            holder.update(peak=peak, note=note)
            return wall, note
        bench.target("make verify, n <= 6, 2 jobs (wall)", 60.0, "s", "lower", mv)
        bench.target("make verify peak memory (max RSS)", 2.0, "GiB", "lower",
                     lambda: (holder["peak"], "getrusage(RUSAGE_CHILDREN).ru_maxrss") if "peak" in holder
                     else (_ for _ in ()).throw(NotYet("make verify did not run")))

        # the catalog at n <= 7 (every claim built from matrix products proved exactly there, within 3 minutes),
        # and the mutation analysis of the catalog (within 4 minutes), both with 2 jobs
        at7: dict[str, Any] = {}

        def verify7() -> tuple[float, str]:
            wall, _peak, results, note = _catalog_run(7, args.verify_timeout)
            at7["results"] = results
            return wall, note
        bench.target("verify, n <= 7, 2 jobs (wall)", 180.0, "s", "lower", verify7)
        bench.target("n <= 7: records proved exactly, of proved or checked", 1.0, "share", "higher",
                     lambda: proved_share(at7["results"]) if "results" in at7
                     else (_ for _ in ()).throw(NotYet("the n <= 7 run did not finish")))
        bench.target("mutation analysis of the catalog, 2 jobs (wall)", 240.0, "s", "lower",
                     lambda: mutation_run(args.verify_timeout))

    # 2. LA1 exact at (3,1) against the naive sympy baseline (CPU time)
    base: dict[tuple[int, int], float] = {}
    #: the engine's exact (3,1) measurement of this target, which the side-by-side table quotes (one measurement,
    #: one ratio)
    engine: dict[tuple[int, int], tuple[float, str]] = {}

    def speedup() -> tuple[float, str]:
        if args.no_baseline:
            raise NotYet("--no-baseline")
        base[(3, 1)] = naive_sympy(3, 1)
        _wall_s, best, res = _warm_best(lambda: run_one(LA1, Size(3, 1), "exact", seed=0), 10, max(20, args.repeat))
        if res.verdict != "proved":
            raise NotYet(f"exact LA1 (3,1): {res.verdict} {res.message[:120]}")
        engine[(3, 1)] = (best, res.verdict)
        return base[(3, 1)] / max(best, 1e-9), (f"sympy {base[(3, 1)]:.2f} s CPU, engine {best * 1e3:.3f} ms CPU "
                                                 "(best of 20 warm runs after 10)")
    bench.target("LA1 exact (3,1): speed-up over naive sympy (CPU)", 100000.0, "x", "higher", speedup)

    # 3. exact LA1 and every §3 flow claim at n = 12, every r
    catalog = _catalog()

    def exact12(claim: Claim) -> Callable[[], tuple[float, str]]:
        def cpu_of_run(r: int) -> tuple[float, Any]:
            # run_one runs the symbolic method at n = 12 in a forked child: its CPU seconds are the
            # parent's and the reaped child's (RUSAGE_CHILDREN), fork included
            t0 = time.process_time()
            c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            res = run_one(claim, Size(12, r), "exact", seed=0)
            c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            return (time.process_time() - t0 + c1.ru_utime - c0.ru_utime + c1.ru_stime - c0.ru_stime), res

        def run() -> tuple[float, str]:
            worst, where, wall = 0.0, None, 0.0
            for r in range(1, 13):
                if not claim.sizes.admits(12, r):
                    continue
                res = _budgeted(claim, 12, r, "exact", args.per_run)
                if res.verdict != "proved":
                    raise NotYet(f"(12,{r}): {res.verdict}")
                # CPU seconds, best of 2 (a wall time on a shared machine measures its load)
                cpu = min(cpu_of_run(r)[0] for _ in range(2))
                if cpu >= worst:
                    worst, where, wall = cpu, r, res.seconds
            return worst, (f"CPU seconds of the run (best of 2, fork included); slowest r = {where} (wall "
                           f"{wall:.3f} s in a budgeted worker); all proved")
        return run
    bench.target("exact LA1 at n = 12, slowest r", 1.0, "s", "lower", exact12(LA1))
    for cid in SEC3_FLOWS:
        try:
            c = catalog.get(cid)
        except KeyError:
            continue
        bench.target(f"exact {cid} at n = 12, slowest r", 1.0, "s", "lower", exact12(c))

    # 4. a modular evaluation of a Lax claim, per point, at n = 8 and n = 100
    def modular(n: int, r: int) -> Callable[[], tuple[float, str]]:
        def run() -> tuple[float, str]:
            cold = _budgeted(LA1, n, r, "modular", args.per_run if n <= 12 else 4 * args.per_run)
            # every point carries its own degree markers beside its values (stiefelsym/backends/paired.py):
            # nothing is cached between runs but the interpreter's warm state.  CPU seconds, best of
            # 20 warm runs after 10 as in the other in-process targets: a wall time over 3 runs on a
            # shared machine measured the machine's load (1.06 to 1.6 ms at unchanged code)
            runs = max(20, args.repeat)
            wall, cpu, best = _warm_best(lambda: run_one(LA1, Size(n, r), "modular", seed=0), 10, runs)
            k = _points(best)
            return 1e3 * cpu / k, (f"{best.verdict}, {k} points in {cpu:.4f} s CPU (best of {runs} warm runs; "
                                   f"wall {wall:.4f} s), each with its own degree bound (values paired with degree "
                                   f"markers); a run in a fresh worker took {cold.seconds:.3f} s; one bare "
                                   f"evaluation without markers: {_bare_modular(n, r)}")
        return run
    bench.target("modular LA1 per point, (8,4)", 1.0, "ms", "lower", modular(8, 4))
    bench.target("modular LA1 per point, (100,50)", 50.0, "ms", "lower", modular(100, 50))

    # 4b. the modular point of LA1 against the same products written by hand with flint's nmod_mat
    def modular_over_flint(n: int, r: int) -> Callable[[], tuple[float, str]]:
        def run() -> tuple[float, str]:
            import random as _random
            import numpy as np
            from stiefelsym.backends.fields import random_prime
            size = Size(n, r)
            p = random_prime(_random.Random(0))
            rng = np.random.default_rng(0)
            for _ in range(2):
                run_one(LA1, size, "modular", seed=0)
                la1_flint(n, r, p, rng)
            k = max(5, args.repeat)
            cpu = {"modular": math.inf, "flint": math.inf}
            for _ in range(k):
                c0 = time.process_time()
                res = run_one(LA1, size, "modular", seed=0)
                cpu["modular"] = min(cpu["modular"], (time.process_time() - c0) / _points(res))
                c0 = time.process_time()
                la1_flint(n, r, p, rng)
                cpu["flint"] = min(cpu["flint"], time.process_time() - c0)
            if res.verdict != "checked":
                raise NotYet(f"modular {res.verdict}: {(res.message or '')[:120]}")
            return cpu["modular"] / cpu["flint"], (
                f"CPU per point: modular {1e3 * cpu['modular']:.1f} ms (a whole run over its {_points(res)} points), "
                f"hand-written nmod_mat {1e3 * cpu['flint']:.1f} ms (the Cayley point, the flow and the residual of "
                f"LA1 at a prime of [2^62, 2^63); best of {k} interleaved warm runs)")
        return run
    bench.target("modular LA1 point / hand-written flint, (100,50)", 1.5, "x", "lower", modular_over_flint(100, 50))

    # 5. the float64 evaluation of a Lax claim at n = 200 (its products with their error bounds, without
    # the exact confirmation of its `numeric`; the whole check is in 5d)
    def float200() -> tuple[float, str]:
        cold = _budgeted(LA1, 200, 100, "float", 4 * args.per_run)
        for _ in range(2):
            _float_evaluation(LA1, 200, 100)
        k = max(10, args.repeat)
        best = min((_float_evaluation(LA1, 200, 100) for _ in range(k)), key=lambda x: x.seconds)
        return 1e3 * best.seconds, (f"{best.verdict} before the exact confirmation, best of {k} warm runs after 2; "
                                    f"the whole check in a fresh worker (confirmation included) took "
                                    f"{1e3 * cold.seconds:.0f} ms; {(best.certificate or '')[:100]}")
    bench.target("float64 LA1 evaluation, (200,100)", 10.0, "ms", "lower", float200)

    # 5b. the ball check of LA1 against the float64 check, side by side (interleaved warm runs)
    def ball_over_float(n: int, r: int) -> Callable[[], tuple[float, str]]:
        def run() -> tuple[float, str]:
            size = Size(n, r)
            for _ in range(2):
                run_one(LA1, size, "float", seed=0)
                run_one(LA1, size, "ball", seed=0)
            k = max(5, args.repeat)
            cpu: dict[str, float] = {"float": math.inf, "ball": math.inf}
            last: dict[str, Any] = {}
            for _ in range(k):
                for m in ("float", "ball"):
                    c0 = time.process_time()
                    last[m] = run_one(LA1, size, m, seed=0)
                    cpu[m] = min(cpu[m], time.process_time() - c0)
            f, b = last["float"], last["ball"]
            if b.verdict != "numeric" or f.verdict != "numeric":
                raise NotYet(f"float {f.verdict}, ball {b.verdict}: {(b.message or '')[:120]}")
            bound = re.search(r"\|exact residual\| <= ([0-9.e+-]+)", b.certificate or "")
            return cpu["ball"] / cpu["float"], (
                f"CPU: ball {1e3 * cpu['ball']:.0f} ms, float64 {1e3 * cpu['float']:.1f} ms (best of {k} interleaved "
                f"warm runs after 2, one BLAS thread); ball: rigorous |residual| <= {bound.group(1) if bound else '?'}")
        return run
    bench.target("ball / float64 LA1 check, (200,100)", 20.0, "x", "lower", ball_over_float(200, 100))
    bench.target("ball / float64 LA1 check, (40,20)", 20.0, "x", "lower", ball_over_float(40, 20))

    # 5c. the float64 evaluation of LA1 against plain numpy doing the same products (no bounds, no verdict)
    def float_over_numpy(n: int, r: int) -> Callable[[], tuple[float, str]]:
        def run() -> tuple[float, str]:
            import numpy as np
            from stiefelsym.backends.blas import one_blas_thread
            rng = np.random.default_rng(0)
            with one_blas_thread():
                for _ in range(2):
                    _float_evaluation(LA1, n, r)
                    la1_numpy(n, r, rng)
                k = max(10, args.repeat)
                cpu = {"float": math.inf, "numpy": math.inf}
                for _ in range(k):
                    c0 = time.process_time()
                    res = _float_evaluation(LA1, n, r)
                    cpu["float"] = min(cpu["float"], time.process_time() - c0)
                    c0 = time.process_time()
                    la1_numpy(n, r, rng)
                    cpu["numpy"] = min(cpu["numpy"], time.process_time() - c0)
            if res.verdict != "numeric":
                raise NotYet(f"float {res.verdict}: {(res.message or '')[:120]}")
            return cpu["float"] / cpu["numpy"], (
                f"CPU: float64 evaluation {1e3 * cpu['float']:.1f} ms (values, error bounds and term scales, "
                f"without the exact confirmation), plain numpy {1e3 * cpu['numpy']:.1f} ms (the Cayley point, the "
                f"flow and the residual of LA1, no bounds); best of {k} interleaved warm runs, one BLAS thread")
        return run
    bench.target("float64 LA1 evaluation / plain numpy, (200,100)", 1.5, "x", "lower", float_over_numpy(200, 100))

    # 5d. the whole float64 check of LA1 (the evaluation and the exact confirmation of its `numeric` at
    # random points mod p) against the same products written by hand: numpy, then flint's nmod_mat at
    # as many points as the confirmation used
    def check_over_hand(n: int, r: int) -> Callable[[], tuple[float, str]]:
        def run() -> tuple[float, str]:
            import numpy as np
            import random as _random
            from stiefelsym.backends.blas import one_blas_thread
            from stiefelsym.backends.fields import random_prime
            size = Size(n, r)
            rng = np.random.default_rng(0)
            p = random_prime(_random.Random(0))
            res = run_one(LA1, size, "float", seed=0)
            if res.verdict != "numeric":
                raise NotYet(f"float {res.verdict}: {(res.message or '')[:120]}")
            m = re.search(r"confirmed exactly: every residual is 0 at (\d+) random points? mod p( per component)?",
                          res.certificate or "")
            if m is None:
                raise NotYet("the float check's certificate names no exact confirmation")
            points = int(m.group(1)) * (2 if m.group(2) else 1)

            def hand() -> None:
                la1_numpy(n, r, rng)
                for _ in range(points):
                    la1_flint(n, r, p, rng)
            with one_blas_thread():
                for _ in range(2):
                    run_one(LA1, size, "float", seed=0)
                    hand()
                k = max(5, args.repeat)
                cpu = {"float": math.inf, "hand": math.inf}
                for _ in range(k):
                    c0 = time.process_time()
                    run_one(LA1, size, "float", seed=0)
                    cpu["float"] = min(cpu["float"], time.process_time() - c0)
                    c0 = time.process_time()
                    hand()
                    cpu["hand"] = min(cpu["hand"], time.process_time() - c0)
            return cpu["float"] / cpu["hand"], (
                f"CPU: the float64 check {1e3 * cpu['float']:.1f} ms (evaluation and exact confirmation at {points} "
                f"point{'s' if points > 1 else ''} mod p), by hand {1e3 * cpu['hand']:.1f} ms (la1_numpy, then "
                f"la1_flint's nmod_mat products at {points} point{'s' if points > 1 else ''}); best of {k} interleaved "
                f"warm runs, one BLAS thread; {m.group(0)}")
        return run
    bench.target("float64 LA1 check / numpy + nmod_mat by hand, (200,100)", 1.5, "x", "lower",
                 check_over_hand(200, 100))

    # 6. the dimension-free proof of LA1, warm
    def free() -> tuple[float, str]:
        res = run_one(LA1, None, "free", seed=0)
        if res.verdict != "proved":
            raise NotYet(f"free LA1: {res.verdict} {res.message[:120]}")
        best, cpu, _res = _warm_best(lambda: run_one(LA1, None, "free", seed=0), 10, max(50, args.repeat))
        return 1e3 * best, (f"proved for all n, r; wall, best of 50 warm runs after 10 (CPU best "
                            f"{1e3 * cpu:.3f} ms; certificate check included)")
    bench.target("dimension-free proof of LA1, warm", 0.3, "ms", "lower", free)

    # 7. start-up
    def startup_list() -> tuple[float, str]:
        t, out = _wall([STIEFELSYM, "list"])
        if out.returncode:
            raise NotYet(f"exit {out.returncode}")
        return t, "wall time of the whole command, best of 3"
    bench.target("start-up: stiefelsym list", 0.3, "s", "lower", startup_list)

    def startup_run() -> tuple[float, str]:
        t, out = _wall([STIEFELSYM, "verify", "neumann-flow", "--size", "2,1", "--method", "modular",
                        "--no-report", "--format", "json"])
        if out.returncode:
            raise NotYet(f"exit {out.returncode}")
        ran = sum(r["seconds"] for r in json.loads(out.stdout)["results"])
        return t - ran, f"wall {t:.3f} s minus the run's own {ran:.3f} s, best of 3"
    bench.target("start-up: a one-claim run", 0.3, "s", "lower", startup_run)

    # side by side: LA1 under every method against the baseline, in this run
    sizes = [tuple(map(int, s.split(","))) for s in args.sizes] if args.sizes else [(2, 1), (3, 1)]
    if args.only:
        sizes = []
    side: list[dict[str, Any]] = []
    print("\nLA1 side by side (CPU seconds, best of %d warm runs after 10 for the engine); ratio = baseline / method"
          % max(20, args.repeat))
    print(f"{'size':>7} {'method':>9} {'verdict':>12} {'seconds':>10} {'ratio':>12}")
    for n, r in sizes:
        b = None if args.no_baseline else base.get((n, r)) or naive_sympy(n, r)
        if b is not None:
            print(f"{f'({n},{r})':>7} {'sympy':>9} {'proved':>12} {b:>10.3f} {'1':>12}")
            side.append({"size": f"({n},{r})", "method": "naive sympy", "verdict": "proved", "seconds": b,
                         "ratio": 1.0})
        for m in ("exact", "modular", "rational", "float", "ball", "free"):
            size = None if m == "free" else Size(n, r)
            if m == "exact" and (n, r) in engine:
                best, verdict = engine[(n, r)]        # the target's own measurement, not a second one
            else:
                _wall_s, best, res = _warm_best(lambda: run_one(LA1, size, m, seed=0), 10, max(20, args.repeat))
                verdict = res.verdict
            ratio = b / best if b is not None and best > 0 else None
            side.append({"size": f"({n},{r})", "method": m, "verdict": verdict, "seconds": best, "ratio": ratio})
            print(f"{f'({n},{r})':>7} {m:>9} {verdict:>12} {best:>10.5f} "
                  f"{('%.0fx' % ratio) if ratio else '-':>12}")

    doc = {"generated": started.strftime("%Y-%m-%d %H:%M:%S UTC"), "platform": platform.platform(terse=True),
           "python": platform.python_version(), "cpus": os.cpu_count(), "quick": args.quick,
           "command": "python bench/bench.py" + (" --quick" if args.quick else ""),
           "commit": _commit(), "targets": bench.rows, "side_by_side": side}
    if args.only and args.report_dir is None:
        met = sum(1 for r in bench.rows if r["status"] == "met")
        print(f"\n{met} of {len(bench.rows)} targets met (--only: no report written)")
        return 0
    out_dir = Path(args.report_dir or ROOT / "reports")
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "bench.json").write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
    (out_dir / "bench.md").write_text(markdown(doc), encoding="utf-8")
    met = sum(1 for r in bench.rows if r["status"] == "met")
    print(f"\n{met} of {len(bench.rows)} targets met; {out_dir / 'bench.json'}, {out_dir / 'bench.md'}")
    return 0


def _commit() -> str | None:
    try:
        out = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], capture_output=True, text=True, cwd=ROOT,
                             timeout=5)
        return out.stdout.strip() or None
    except (OSError, subprocess.SubprocessError):
        return None


def markdown(doc: dict[str, Any]) -> str:
    lines = ["# Benchmark: the engine's speed targets, measured side by side", "",
             f"Generated {doc['generated']} by `{doc['command']}` (commit {doc['commit']}) on {doc['platform']}, "
             f"{doc['cpus']} CPUs.  ratio = measured / goal (a time goal is met at ratio <= 1, the speed-up goal "
             "at ratio >= 1).", "",
             "| target | measured | goal | ratio | status | note |", "| --- | ---: | ---: | ---: | --- | --- |"]
    for r in doc["targets"]:
        op = "≤" if r["better"] == "lower" else "≥"
        ratio = "-" if r["ratio"] is None else f"{r['ratio']:.3g}"
        lines.append(f"| {r['target']} | {_fmt(r['measured'], r['unit'])} | {op} {_fmt(r['goal'], r['unit'])} | "
                     f"{ratio} | {r['status']} | {str(r['note']).replace('|', '/')} |")
    if doc["side_by_side"]:
        lines += ["", "## LA1 side by side", "", "CPU seconds in one process run; for the engine the best of 20 warm runs after 10, "
                  "as in the targets; ratio = naive sympy / method.", "", "| size | method | verdict | seconds | ratio |",
                  "| --- | --- | --- | ---: | ---: |"]
        for s in doc["side_by_side"]:
            ratio = "-" if s["ratio"] is None else f"{s['ratio']:,.0f}x"
            lines.append(f"| {s['size']} | {s['method']} | {s['verdict']} | {s['seconds']:.5f} | {ratio} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    raise SystemExit(main())
