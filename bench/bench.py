"""Side-by-side timings on the big Lax equation LA1 (Theorem Neumann_LA).

Baseline: naive sympy -- substitute the Cayley parametrization of T*V(n, r)
into the residual dL/dt - [M, L] along the printed flow (No) and call
``simplify`` on every entry.  Against it, in the same process run: the
engine's exact (equivariance-reduced symbolic), rational, modular and float
methods, and the dimension-free rewriting backend when it is available.

    python bench/bench.py                 # (2,1) and (3,1)
    python bench/bench.py --large         # also (3,2) (the baseline needs minutes)
    python bench/bench.py --sizes 4,2 5,3 --no-baseline
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from stiefelsym import admissible, comm  # noqa: E402
from stiefelsym.claims import Claim, Size  # noqa: E402
from stiefelsym.runner import run_one  # noqa: E402


def neumann_flow(s):
    """The printed Neumann flow (No)."""
    k = 1 + 2 * s.kappa
    X, P, A = s.X, s.P, s.A
    return {"X": P - k * (X @ P.T @ X),
            "P": -(A @ X) - X @ P.T @ P + k * (P @ X.T @ P) + X @ X.T @ A @ X}


def la1_residual(s):
    """dL/dt - [M, L] for L = lambda Phi + X X^T - lambda^2 A, M = Phi - lambda A."""
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A
    M = s.Phi - s.lam * s.A
    return {"LA1": s.d(L, neumann_flow(s)) - comm(M, L(s))}


LA1 = Claim(id="LA1", paper=("LA1",), kind="lax", section="5", func=la1_residual,
            sizes=admissible(5), title="The big Lax equation along the printed Neumann flow.")


def naive_sympy(n: int, r: int) -> float:
    import sympy as sp
    t0 = time.perf_counter()
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
    return time.perf_counter() - t0


def engine(method: str, n: int, r: int) -> tuple[float, str]:
    res = run_one(LA1, Size(n, r), method, seed=0)
    return res.seconds, res.verdict


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", nargs="*", default=None, help="sizes n,r (default: 2,1 3,1)")
    ap.add_argument("--large", action="store_true", help="also (3,2): the sympy baseline takes minutes")
    ap.add_argument("--no-baseline", action="store_true", help="skip the naive sympy baseline")
    ap.add_argument("--repeat", type=int, default=3, help="engine runs per method (best time is kept)")
    args = ap.parse_args(argv)
    sizes = [tuple(map(int, s.split(","))) for s in args.sizes] if args.sizes else [(2, 1), (3, 1)]
    if args.large:
        sizes.append((3, 2))
    methods = ["exact", "modular", "rational", "float", "free"]
    print("LA1 residual, one process run; times in seconds (best of "
          f"{args.repeat} for the engine); ratio = baseline / method")
    print(f"{'size':>7} {'method':>9} {'verdict':>12} {'seconds':>10} {'ratio':>10}")
    for n, r in sizes:
        base = None if args.no_baseline else naive_sympy(n, r)
        if base is not None:
            print(f"{f'({n},{r})':>7} {'sympy':>9} {'proved':>12} {base:>10.3f} {'1':>10}")
        for m in methods:
            best, verdict = None, ""
            for _ in range(args.repeat):
                t, verdict = engine(m, n, r)
                best = t if best is None else min(best, t)
            ratio = f"{base / best:.0f}x" if base is not None and best > 0 else "-"
            print(f"{f'({n},{r})':>7} {m:>9} {verdict:>12} {best:>10.4f} {ratio:>10}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
