# ruff: noqa
"""Self-test of numpy_check.py's Dirac-flow solver against the printed (No) (verified by the catalog)."""
import numpy as np
import runpy
ns = runpy.run_path("numpy_check.py", run_name="selftest")
rng = np.random.default_rng(1)
for n, r in [(3, 2), (4, 2), (4, 3)]:
    X, P = ns["point"](n, r)
    A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
    Xd, Pd = ns["single_flow"](ns["H_neum"](kap, A), X, P, n, r)
    c = 1 + 2 * kap
    Xd0 = P - c * X @ P.T @ X
    Pd0 = -A @ X - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A @ X
    print(n, r, np.abs(Xd - Xd0).max(), np.abs(Pd - Pd0).max())
