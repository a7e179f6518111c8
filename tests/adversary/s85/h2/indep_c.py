# ruff: noqa: E702, F821
"""numpy truth for h2_claims_c.py: at r = n along (No), Xdot = (1 + κ)ΦX and dΦ/dt = 0; twin (1 + 2κ)."""
import sys
import numpy as np
sys.argv = sys.argv[:1] + ["5"]
exec(open("/tmp/h2/out/indep.py").read().split("res = {}")[0])
for n in range(1, 6):
    for r in range(1, n + 1):
        A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
        X, P = point(n, r)
        HN = lambda X, P: 0.5 * tr(P.T @ P) - (0.5 + kap) * tr((X.T @ P) @ (X.T @ P)) + 0.5 * tr(X.T @ A @ X)
        Xd, Pd, _, _ = flow(HN, X, P)
        F = Phi(X, P)
        t = max(nrm(Xd - (1 + kap) * F @ X), nrm(deriv(lambda X, P: Phi(X, P), X, P, Xd, Pd)))
        w = nrm(Xd - (1 + 2 * kap) * F @ X)
        a = nrm(Xd - (F @ X + kap * X @ Psi(X, P)))
        print(f"({n},{r}) true(r=n):{t:.1e}  twin:{w:.1e}  all-r form Xdot=ΦX+κXΨ:{a:.1e}")
