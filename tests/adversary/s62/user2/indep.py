# ruff: noqa: F841, E702, F401
"""Independent numpy check of claims.py / negatives.py (no stiefelsym import).

Random points of T*V(n, r): X from QR, P = XW + (I - XX^T)Z, W skew.  A random symmetric
(non-diagonal) A, random c.  The Dirac flow is computed from scratch: ambient gradients of H by
central finite differences, then the symmetric multipliers (Lambda, Pi) of (dot_XP) by a linear
least-squares solve of the tangency conditions.  Derivatives along the flow by central differences.
Run: .venv/bin/python tests/adversary/s62/user2/indep.py
"""
import itertools
import numpy as np

rng = np.random.default_rng(1)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    B = rng.standard_normal((n, n)); A = (B + B.T) / 2
    return X, P, A


def H(X, P, A, c):
    K = X.T @ P; M = X.T @ A @ X
    return 0.5 * np.trace(P.T @ P) + c * np.trace(K @ K) + 0.25 * np.trace(M @ M)


def grad(f, Y, h=1e-6):
    G = np.zeros_like(Y)
    for idx in np.ndindex(Y.shape):
        E = np.zeros_like(Y); E[idx] = h
        G[idx] = (f(Y + E) - f(Y - E)) / (2 * h)
    return G


def sym_basis(r):
    out = []
    for i in range(r):
        for j in range(i, r):
            E = np.zeros((r, r)); E[i, j] = 1; E[j, i] = 1; out.append(E)
    return out


def dirac_flow(X, P, A, c):
    HX = grad(lambda Y: H(Y, P, A, c), X)
    HP = grad(lambda Y: H(X, Y, A, c), P)
    r = X.shape[1]
    basis = sym_basis(r)
    # unknowns: Lambda (coeffs), Pi (coeffs); flow linear in them
    def flow(lam, pi):
        L = sum(a * E for a, E in zip(lam, basis)); Pm = sum(a * E for a, E in zip(pi, basis))
        return HP - X @ Pm, -HX + X @ L + P @ Pm
    def cons(Xd, Pd):
        a = Xd.T @ X + X.T @ Xd
        b = Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd
        return np.concatenate([a.ravel(), b.ravel()])
    m = len(basis)
    z = np.zeros(m)
    base = cons(*flow(z, z))
    cols = []
    for k in range(2 * m):
        e = np.zeros(2 * m); e[k] = 1
        cols.append(cons(*flow(e[:m], e[m:])) - base)
    sol, *_ = np.linalg.lstsq(np.array(cols).T, -base, rcond=None)
    Xd, Pd = flow(sol[:m], sol[m:])
    Lam = sum(a * E for a, E in zip(sol[:m], basis)); Pi = sum(a * E for a, E in zip(sol[m:], basis))
    return Xd, Pd, Lam, Pi


def hand(X, P, A, c):
    M = X.T @ A @ X
    return P - 2 * c * X @ X.T @ P, -A @ X @ M + X @ M @ M - X @ P.T @ P - 2 * c * P @ X.T @ P


def ddt(F, X, P, Xd, Pd, h=1e-5):
    return (F(X + h * Xd, P + h * Pd) - F(X - h * Xd, P - h * Pd)) / (2 * h)


def comm(a, b):
    return a @ b - b @ a


def nrm(x):
    return float(np.max(np.abs(x)))


def ad_psi_rank(X, P):
    r = X.shape[1]
    Psi = X.T @ P - P.T @ X
    cols = []
    for i, j in itertools.combinations(range(r), 2):
        E = np.zeros((r, r)); E[i, j] = 1; E[j, i] = -1
        cols.append(comm(E, Psi).ravel())
    return np.linalg.matrix_rank(np.array(cols).T, tol=1e-9) if cols else 0


def main():
    rows = []
    for n in range(1, 5):
        for r in range(1, n + 1):
            X, P, A = point(n, r); c = rng.standard_normal()
            Xd, Pd, Lam, Pi = dirac_flow(X, P, A, c)
            hX, hP = hand(X, P, A, c)
            M = X.T @ A @ X
            Phi = P @ X.T - X @ P.T
            L = X @ X.T
            Ht = lambda Y, Q: H(Y, Q, A, c)
            res = {
                "u2-flow": max(nrm(Xd - hX), nrm(Pd - hP)),
                "u2-multipliers": max(nrm(Pi), nrm(Lam - (M @ M - P.T @ P))),
                "u2-conserved": max(abs(ddt(Ht, X, P, Xd, Pd)), nrm(ddt(lambda Y, Q: Y.T @ Q - Q.T @ Y, X, P, Xd, Pd))),
                "u2-phi-dot": nrm(ddt(lambda Y, Q: Q @ Y.T - Y @ Q.T, X, P, Xd, Pd) - comm(L @ A @ L, A)),
                "u2-lax": nrm(ddt(lambda Y, Q: Y @ Y.T, X, P, Xd, Pd) - comm(Phi, L)),
                # negatives (only meaningful for 2 <= r < n)
                "u2-neg-sign": nrm(Xd - (P + 2 * c * X @ X.T @ P)),
                "u2-neg-missing": nrm(Pd - (hP - X @ M @ M)),
                "u2-neg-lax-order": nrm(ddt(lambda Y, Q: Y @ Y.T, X, P, Xd, Pd) - comm(L, Phi)),
                "u2-neg-phi-neumann": nrm(ddt(lambda Y, Q: Q @ Y.T - Y @ Q.T, X, P, Xd, Pd) - comm(L, A)),
                "u2-neg-phi-conserved": nrm(ddt(lambda Y, Q: Q @ Y.T - Y @ Q.T, X, P, Xd, Pd)),
                "u2-neg-lambda": nrm(Lam - (M @ M + P.T @ P)),
            }
            rk_phi = np.linalg.matrix_rank(Phi, tol=1e-9)
            rk_ad = ad_psi_rank(X, P)
            rows.append((n, r, res, rk_phi, rk_ad))
            print(f"(n,r)=({n},{r})  rank Phi={rk_phi} (claim {min(2*r, 2*(n//2))}, false variant {min(2*r, n)})  "
                  f"rank ad_Psi={rk_ad} (claim {r*(r-1)//2 - r//2}, false {r*(r-1)//2})")
            for k, v in res.items():
                neg = k.startswith("u2-neg")
                tag = "ZERO" if v < 1e-6 else "NONZERO"
                if neg and not (2 <= r < n):
                    tag += " (outside stated sizes)"
                print(f"    {k:22s} {v:.2e} {tag}")
    bad = [(n, r, k) for n, r, res, *_ in rows for k, v in res.items()
           if (not k.startswith("u2-neg") and v > 1e-6) or (k.startswith("u2-neg") and 2 <= r < n and v < 1e-6)]
    print("INDEPENDENT TRUTH:", "all true claims vanish, all negatives nonzero at 2<=r<n" if not bad else bad)


if __name__ == "__main__":
    main()
