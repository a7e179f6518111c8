"""Singular as the reference: the LA1 residual reduced modulo the constraints, side by side.

Singular (Debian's ``singular`` package) proves LA1 at (n, r) by commutative Gröbner
reduction: in ℚ[X, P, a, λ, κ] it builds the residual dL/dt − [M, L] of the big Lax
equation along the printed Neumann flow (No), computes a standard basis of the ideal of
XᵀX − I and XᵀP + PᵀX, and reduces every entry of the residual to 0.  The engine's exact
method proves the same statement at the same size on the Cayley chart of T*V(n, r).

Both are timed in one run of this script, warm and in-process, best of several repeats:

* Singular: ``std`` + ``reduce`` (its ``rtimer`` in µs), and the time it took to build the
  residual before that;
* stiefelsym: ``run_exact`` in this process (the residual computed on the chart the method
  takes, the verdict and its record), warm: the claim's graph (traced on the first run), its
  straight-line program for the chart (compiled on the second run; over Z[x], at the level of the
  coefficients of the chart's coordinates) and the plan of the proof (which chart, the record's
  text: made on the third run) are kept in the process; at every timed run the program computes
  every coefficient of every entry of the residual from the chart's coordinates and the verdict is
  decided on those values.  Beside it, in the same run: the first run at that size (cold: the
  trace and the interpreter), the path before coefficient programs and plans (the program over
  flint's polynomials, the whole method at every run), and ``run_one`` as the CLI runs it (n >= 4
  in a forked child with a hard time limit, whose fork is part of the wall time).

Where Singular is not installed, the script says so and exits 0.  Writes
``reports/bench-singular.{json,md}`` (timings: not part of the reproducible reports).

    python bench/singular.py                      # the sizes of the issue's table
    python bench/singular.py --sizes 3,1 5,2 --timeout 30
"""
from __future__ import annotations

import argparse
import json
import math
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

from bench import LA1, _commit, _warm_best, neumann_flow  # noqa: E402
from stiefelsym import comm  # noqa: E402
from stiefelsym.claims import Size  # noqa: E402
from stiefelsym.methods import fixed_size as fs  # noqa: E402
from stiefelsym.methods.fixed_size import run_exact  # noqa: E402
from stiefelsym.run.runner import run_one  # noqa: E402

SIZES = ((3, 1), (4, 2), (5, 2), (6, 2), (4, 4))

#: the LA1 residual of bench.la1_residual, written in Singular's language (the same formulas:
#: L = λΦ + XXᵀ − λ²A, M = Φ − λA, Φ = PXᵀ − XPᵀ, the flow (No) with k = 1 + 2κ)
SCRIPT = """\
int n = {n}; int r = {r}; int reps = {reps};
system("--ticks-per-sec", 1000000);
ring R = 0, (x(1..n)(1..r), p(1..n)(1..r), a(1..n), lam, kap), dp;
matrix X[n][r]; matrix P[n][r]; matrix A[n][n]; matrix Ir[r][r];
int i; int j;
for (i = 1; i <= n; i++) {{ for (j = 1; j <= r; j++) {{ X[i,j] = x(i)(j); P[i,j] = p(i)(j); }} A[i,i] = a(i); }}
for (i = 1; i <= r; i++) {{ Ir[i,i] = 1; }}
poly k = 1 + 2*kap;
matrix Xd; matrix Pd; matrix Phi; matrix L; matrix M; matrix dL; matrix Res;
int best = -1; int tbuild = -1; int t; ideal G; ideal red;
for (i = 1; i <= reps; i++) {{
  t = rtimer;
  Xd = P - k*X*transpose(P)*X;
  Pd = -A*X - X*transpose(P)*P + k*P*transpose(X)*P + X*transpose(X)*A*X;
  Phi = P*transpose(X) - X*transpose(P);
  L = lam*Phi + X*transpose(X) - lam^2*A;
  M = Phi - lam*A;
  dL = lam*(Pd*transpose(X) + P*transpose(Xd) - Xd*transpose(P) - X*transpose(Pd)) + Xd*transpose(X) + X*transpose(Xd);
  Res = dL - (M*L - L*M);
  t = rtimer - t;
  if (tbuild < 0 or t < tbuild) {{ tbuild = t; }}
}}
ideal I = ideal(transpose(X)*X - Ir) + ideal(transpose(X)*P + transpose(P)*X);
for (i = 1; i <= reps; i++) {{
  t = rtimer; G = std(I); red = reduce(ideal(Res), G); t = rtimer - t;
  if (best < 0 or t < best) {{ best = t; }}
}}
print("RESULT " + string(best) + " " + string(size(red)) + " " + string(tbuild));
quit;
"""

#: a corrupted residual (the sign of XXᵀ in L flipped): Singular must not reduce it to 0
CORRUPT = ("L = lam*Phi + X*transpose(X) - lam^2*A;", "L = lam*Phi - X*transpose(X) - lam^2*A;")


def la1_corrupted(s):
    """LA1 with the sign of XXᵀ in L flipped (the corruption CORRUPT makes in Singular's script)."""
    L = lambda t: t.lam * t.Phi - t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    M = s.Phi - s.lam * s.A
    return {"LA1": s.d(L, neumann_flow(s)) - comm(M, L(s))}


def singular(exe: str, n: int, r: int, reps: int, timeout: float, corrupt: bool = False) -> dict[str, Any]:
    """Singular's best std + reduce time (s), whether the residual reduced to 0, and the time it took
    to build the residual; or why it did not finish."""
    text = SCRIPT.format(n=n, r=r, reps=reps)
    if corrupt:
        if CORRUPT[0] not in text:
            raise RuntimeError("the corruption does not apply to Singular's script")
        text = text.replace(*CORRUPT)
    with tempfile.NamedTemporaryFile("w", suffix=".sing", delete=False) as f:
        f.write(text)
    t0 = time.perf_counter()
    try:
        out = subprocess.run([exe, "-q", f.name], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "note": f"over {timeout:.0f} s (stopped)"}
    finally:
        Path(f.name).unlink(missing_ok=True)
    m = re.search(r"RESULT (\d+) (\d+) (\d+)", out.stdout)
    if not m:
        return {"status": "error", "note": (out.stderr or out.stdout).strip()[:200]}
    best, nonzero, build = (int(x) for x in m.groups())
    return {"status": "ok", "seconds": best * 1e-6, "build_seconds": build * 1e-6, "nonzero_entries": nonzero,
            "process_seconds": time.perf_counter() - t0}


def _fresh_memos() -> None:
    """Forget the exact method's programs and plans (not the traced graphs)."""
    fs._STRAIGHT.clear()
    fs._STRAIGHT_SEEN.clear()
    fs._PLANS.clear()


def _program(n: int, r: int) -> str:
    """What the warm runs ran at (n, r): the program's kind and its operations per run."""
    progs = [v for k, v in fs._STRAIGHT.items() if type(v) is fs._Straight and k[3:5] == (n, r)]
    plans = [p for p in fs._PLANS.values() if p.n == n and p.r == r]
    if not progs:
        return "interpreter"
    kind = ", ".join(f"{p.operations} integer operations on coefficients" if p.entries is not None else
                     f"{p.operations} operations of the polynomial ring" for p in progs)
    return kind + ("; planned" if plans else "")


def ours(n: int, r: int, runs: int) -> dict[str, Any]:
    _fresh_memos()
    c0 = time.process_time()
    first = run_exact(LA1, n, r, 0)
    cold = time.process_time() - c0
    # the previous path: the program over flint's polynomials, the whole method at every run
    coefficient_ops, fs.COEFFICIENT_OPS, fs.PLANS = fs.COEFFICIENT_OPS, 0, False
    try:
        _fresh_memos()
        _wall, cpu_before, res_before = _warm_best(lambda: run_exact(LA1, n, r, 0), 5, runs)
        before = _program(n, r)
    finally:
        fs.COEFFICIENT_OPS, fs.PLANS = coefficient_ops, True
    _fresh_memos()
    _wall, cpu, res = _warm_best(lambda: run_exact(LA1, n, r, 0), 5, runs)
    wall_cli, _cpu, res_cli = _warm_best(lambda: run_one(LA1, Size(n, r), "exact", seed=0), 2, max(5, runs // 4))
    return {"verdict": res.verdict, "seconds": cpu, "program": _program(n, r), "chart": res.reductions[0][:60],
            "cold_verdict": first.verdict, "cold_seconds": cold,
            "before_verdict": res_before.verdict, "before_seconds": cpu_before, "before_program": before,
            "cli_verdict": res_cli.verdict, "cli_seconds": wall_cli}


def _ms(x: float | None) -> str:
    if x is None or not math.isfinite(x):
        return "-"
    return f"{1e3 * x:.3f} ms" if x < 1 else f"{x:.2f} s"


def markdown(doc: dict[str, Any]) -> str:
    lines = ["# Singular as the reference: LA1 by Gröbner reduction against the exact method", "",
             f"Generated {doc['generated']} by `{doc['command']}` (commit {doc['commit']}) on {doc['platform']}; "
             f"{doc['singular']}.", "",
             "Singular: a standard basis of the ideal of XᵀX − I, XᵀP + PᵀX in ℚ[X, P, a, λ, κ] and the reduction of "
             "every entry of the LA1 residual by it (`std` + `reduce`, best of the repeats, its own timer); the "
             "column 'build' is the time it took to form the residual before that (best of the repeats).  "
             "stiefelsym: `run_exact` in this process (the residual computed on the chart the method takes, the "
             "verdict and its record; CPU, best of the repeats after 5 warm runs).  Warm in the process: the "
             "claim's graph (traced on the first run), its straight-line program for the chart (compiled on the "
             "second run; over Z[x] at the level of the coefficients of the chart's coordinates, the monomials "
             "compiled in) and the plan of the proof (the chart and the record's text, made on the third run); "
             "at every timed run the program computes every coefficient of every entry of the residual from the "
             "chart's coordinates, and the verdict is decided on those values.  'first run' is the first run at "
             "that size in the process (CPU: the trace and the interpreter); 'previous path' the same warm runs "
             "with the program over flint's polynomials and no plan (the whole method at every run); 'with the "
             "fork' `run_one` as the CLI runs it (wall; for n ≥ 4 in a forked child with a hard time limit).  "
             "ratio = Singular std+reduce / stiefelsym run_exact (above 1: stiefelsym is ahead); since run_exact "
             "forms the residual as well as deciding it, the last column compares it with Singular's build + "
             "std + reduce.", "",
             "| (n, r) | Singular std+reduce | Singular build | Singular: residual in the ideal | "
             "stiefelsym exact (warm) | verdict | first run | previous path | with the fork (CLI) | ratio | "
             "ratio with build |",
             "| --- | ---: | ---: | --- | ---: | --- | ---: | ---: | ---: | ---: | ---: |"]
    for row in doc["rows"]:
        s, o = row["singular"], row["stiefelsym"]
        if s["status"] == "ok":
            sing, build = _ms(s["seconds"]), _ms(s["build_seconds"])
            member = "yes (every entry reduces to 0)" if s["nonzero_entries"] == 0 else \
                f"no ({s['nonzero_entries']} entries do not reduce to 0)"
            ratio = f"{s['seconds'] / o['seconds']:.2f}"
            ratio_all = f"{(s['seconds'] + s['build_seconds']) / o['seconds']:.2f}"
        else:
            sing, build, member, ratio = s["note"], "-", s["status"], "> " + f"{row['timeout'] / o['seconds']:,.0f}"
            ratio_all = ratio
        lines.append(f"| ({row['n']},{row['r']}) | {sing} | {build} | {member} | {_ms(o['seconds'])} | "
                     f"{o['verdict']} | {_ms(o['cold_seconds'])} | {_ms(o['before_seconds'])} | "
                     f"{_ms(o['cli_seconds'])} | {ratio} | {ratio_all} |")
    lines += ["", "What the warm runs ran, per size (the previous path in brackets):", ""]
    lines += [f"* ({row['n']},{row['r']}): {row['stiefelsym']['program']} [{row['stiefelsym']['before_program']}]; "
              f"chart: {row['stiefelsym']['chart']}.." for row in doc["rows"]]
    c = doc.get("control")
    if c:
        lines += ["", f"Negative control: with the sign of XXᵀ in L flipped, at (3,1) Singular leaves "
                  f"{c['nonzero_entries']} entries of the residual nonzero, and the exact method says "
                  f"`{c['verdict']}` at each of {c['runs']} runs (the runs after the second through its "
                  f"program: {c['program']})."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", nargs="*", default=None, help="sizes n,r (default: the issue's table)")
    ap.add_argument("--timeout", type=float, default=120.0, help="Singular's time limit per size (s)")
    ap.add_argument("--runs", type=int, default=20, help="timed runs of the exact method (best kept)")
    ap.add_argument("--report-dir", default=str(ROOT / "reports"), help="where bench-singular.{json,md} go")
    args = ap.parse_args(argv)
    exe = shutil.which("Singular")
    if exe is None:
        print("Singular is not installed (Debian: apt-get install singular): the reference comparison is skipped")
        return 0
    version = subprocess.run([exe, "-v", "-c", "quit;"], capture_output=True, text=True).stdout
    vm = re.search(r"Singular for .*?version ([0-9.\-]+)", version) or re.search(r"version ([0-9][0-9.\-]*)", version)
    sizes = [tuple(int(x) for x in s.split(",")) for s in args.sizes] if args.sizes else list(SIZES)
    rows = []
    print("timed: Singular std + reduce (its build of the residual apart); stiefelsym run_exact warm (graph, "
          "program and plan kept; every coefficient of the residual computed from the chart at every run), "
          "the first run at the size (cold), and the previous path (flint's polynomials, no plan)")
    print(f"{'(n, r)':<8} {'Singular':>14} {'build':>10} {'stiefelsym':>12} {'first run':>11} {'previous':>10} "
          f"{'ratio':>8} {'w/ build':>9}")
    for n, r in sizes:
        s = singular(exe, n, r, 20 if n <= 3 else 5, args.timeout)
        o = ours(n, r, args.runs)
        rows.append({"n": n, "r": r, "singular": s, "stiefelsym": o, "timeout": args.timeout})
        ok = s["status"] == "ok"
        ratio = f"{s['seconds'] / o['seconds']:.2f}" if ok else "-"
        ratio_all = f"{(s['seconds'] + s['build_seconds']) / o['seconds']:.2f}" if ok else "-"
        print(f"({n},{r}){'':<3} {_ms(s.get('seconds')) if ok else s['note']:>14} "
              f"{_ms(s.get('build_seconds')) if ok else '-':>10} {_ms(o['seconds']):>12} {_ms(o['cold_seconds']):>11} "
              f"{_ms(o['before_seconds']):>10} {ratio:>8} {ratio_all:>9}")
    bad = singular(exe, 3, 1, 1, args.timeout, corrupt=True)
    _fresh_memos()
    corrupted = replace(LA1, func=la1_corrupted)
    verdicts = {run_exact(corrupted, 3, 1, 0).verdict for _ in range(5)}
    control = {"nonzero_entries": bad.get("nonzero_entries"), "runs": 5,
               "verdict": verdicts.pop() if len(verdicts) == 1 else " / ".join(sorted(verdicts)),
               "program": _program(3, 1)}
    print(f"negative control at (3,1), the sign of XXᵀ in L flipped: Singular leaves {control['nonzero_entries']} "
          f"entries nonzero; run_exact says {control['verdict']} at each of 5 runs ({control['program']})")
    doc = {"generated": datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC"),
           "command": "python bench/singular.py" + (" " + " ".join(argv) if argv else ""),
           "commit": _commit(), "platform": platform.platform(),
           "singular": f"Singular {vm.group(1)}" if vm else "Singular", "rows": rows, "control": control}
    out = Path(args.report_dir)
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench-singular.json").write_text(json.dumps(doc, indent=1) + "\n")
    (out / "bench-singular.md").write_text(markdown(doc))
    print(f"wrote {out / 'bench-singular.md'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
