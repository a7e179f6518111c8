# ruff: noqa: E702, F821
"""Independent numpy truth for h2_claims_b.py (no stiefelsym); reuses the solver of indep.py."""
import sys
import numpy as np
sys.argv = sys.argv[:1] + ["3"]
exec(open("/tmp/h2/out/indep.py").read().split("res = {}")[0])
res = {}
def rec(name, n, r, v): res.setdefault(name, []).append((n, r, v))
for n in range(1, 6):
    for r in range(1, n + 1):
        A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
        X, P = point(n, r)
        xi = rng.standard_normal((n, n)); xi -= xi.T; ze = rng.standard_normal((n, n)); ze -= ze.T
        et = rng.standard_normal((r, r)); et -= et.T; th = rng.standard_normal((r, r)); th -= th.T
        f1 = lambda X, P: tr(Phi(X, P) @ xi); f2 = lambda X, P: tr(Phi(X, P) @ ze)
        g1 = lambda X, P: tr(Psi(X, P) @ et); g2 = lambda X, P: tr(Psi(X, P) @ th)
        Xd, Pd, _, _ = flow(f2, X, P)       # {f1, f2} = d f1 / dt along the flow of f2 (dot f = {f, H})
        br = deriv(f1, X, P, Xd, Pd)
        Ph = Phi(X, P); Ps = Psi(X, P)
        rec("B4 true {trPhi xi, trPhi zeta} = -2 tr(Phi[xi,zeta])", n, r, abs(br + 2 * tr(Ph @ (xi @ ze - ze @ xi))))
        rec("B4 twin = +2 tr(Phi[xi,zeta])", n, r, abs(br - 2 * tr(Ph @ (xi @ ze - ze @ xi))))
        Xd, Pd, _, _ = flow(g2, X, P)
        br = deriv(g1, X, P, Xd, Pd)
        rec("B4b true {trPsi eta, trPsi theta} = +2 tr(Psi[eta,theta])", n, r, abs(br - 2 * tr(Ps @ (et @ th - th @ et))))
        rec("B4b twin = -2 tr(Psi[eta,theta])", n, r, abs(br + 2 * tr(Ps @ (et @ th - th @ et))))
        HN = lambda X, P: 0.5 * tr(P.T @ P) - (0.5 + kap) * tr((X.T @ P) @ (X.T @ P)) + 0.5 * tr(X.T @ A @ X)
        Xd, Pd, _, _ = flow(HN, X, P)
        lam = rng.standard_normal()
        Lp = lambda X, P: Phi(X, P) + X @ X.T / lam - lam * A
        Lt = lambda X, P: Phi(X, P) + X @ X.T / lam + lam * A
        Aa = Ph - lam * A
        dL = deriv(Lp, X, P, Xd, Pd)
        rec("B10 true d(L/lam) = [Phi - lam A, L/lam]", n, r, np.abs(dL - (Aa @ Lp(X, P) - Lp(X, P) @ Aa)).max())
        dL = deriv(Lt, X, P, Xd, Pd)
        rec("B10 twin +lam A", n, r, np.abs(dL - (Aa @ Lt(X, P) - Lt(X, P) @ Aa)).max())
for k, v in res.items():
    print(k); print("   " + "  ".join(f"({n},{r}):{x:.1e}" for n, r, x in v))
