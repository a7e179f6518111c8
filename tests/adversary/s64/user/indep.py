# ruff: noqa
"""Independent numpy checks (s64) of claims.py / negatives.py at random points of T*V.
Derivatives along flows by central differences (h = 1e-5) of polynomial functions; flows from the
paper's printed formulas or from a Dirac flow whose multipliers are solved numerically here."""
import numpy as np

rng = np.random.default_rng(64)
h = 1e-5


def sym(M): return (M + M.T) / 2
def comm(a, b): return a @ b - b @ a
def wedge(a, b): return np.outer(a, b) - np.outer(b, a)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    Z = rng.standard_normal((n, r))
    P = Z - X @ sym(X.T @ Z)
    A = np.diag(rng.standard_normal(n))
    return X, P, A


def dirac(X, P, HX, HP):
    """ẋ = H_P − XΠ, ṗ = −H_X + XΛ + PΠ with Λ, Π symmetric solved from the constraints."""
    n, r = X.shape
    idx = [(i, j) for i in range(r) for j in range(i, r)]
    def S(i, j):
        E = np.zeros((r, r)); E[i, j] = E[j, i] = 1; return E
    def cons(Lam, Pi):
        Xd = HP - X @ Pi; Pd = -HX + X @ Lam + P @ Pi
        return np.concatenate([(Xd.T @ X + X.T @ Xd).ravel(), (Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd).ravel()])
    z = np.zeros((r, r)); b = cons(z, z)
    cols = [cons(S(i, j), z) - b for i, j in idx] + [cons(z, S(i, j)) - b for i, j in idx]
    c = np.linalg.lstsq(np.array(cols).T, -b, rcond=None)[0]
    m = len(idx)
    Lam = sum(c[k] * S(*idx[k]) for k in range(m)); Pi = sum(c[m + k] * S(*idx[k]) for k in range(m))
    return HP - X @ Pi, -HX + X @ Lam + P @ Pi


def flow_kappa(X, P, A, k):
    c = 1 + 2 * k
    return dirac(X, P, A @ X - c * P @ X.T @ P, P - c * X @ P.T @ X)


def ddt(F, z, v):
    zp = [a + h * b for a, b in zip(z, v)]; zm = [a - h * b for a, b in zip(z, v)]
    return (F(*zp) - F(*zm)) / (2 * h)


def rel(res, scale): return np.max(np.abs(res)) / max(1.0, np.max(np.abs(scale)))


out = {}
def record(name, true_val, false_val):
    out.setdefault(name, []).append((true_val, false_val))


for (n, r) in [(3, 1), (3, 2), (4, 2), (5, 3)]:
    for _ in range(3):
        X, P, A = point(n, r); k = rng.standard_normal(); lam = rng.standard_normal()
        Phi = lambda X, P: P @ X.T - X @ P.T
        # u64-prep-kappa (printed (No)) and its twin
        c = 1 + 2 * k
        No = (P - c * X @ P.T @ X, -A @ X - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A @ X)
        dXX = ddt(lambda X, P: X @ X.T, (X, P), No)
        record("prep-kappa", rel(dXX - comm(Phi(X, P), X @ X.T), dXX), rel(dXX - comm(X @ X.T, Phi(X, P)), dXX) if r < n else None)
        # Dirac flow of H_kappa equals printed (No)  (consistency of my flow)
        fk = flow_kappa(X, P, A, k)
        record("dirac==No", rel(fk[0] - No[0], No[0]) + rel(fk[1] - No[1], No[1]), None)
        # u64-lax-reciprocal
        Lh = lambda X, P: lam**2 * X @ X.T + lam * Phi(X, P) - A
        dL = ddt(Lh, (X, P), fk)
        record("lax-reciprocal", rel(lam * dL - comm(lam * Phi(X, P) - A, Lh(X, P)), dL),
               rel(lam * dL - comm(Lh(X, P), lam * Phi(X, P) - A), dL) if r < n else None)
        # u64-trL3-conserved
        L3 = lambda X, P: np.trace(np.linalg.matrix_power(lam * Phi(X, P) + X @ X.T - lam**2 * A, 3))
        L3f = lambda X, P: np.trace(np.linalg.matrix_power(lam * Phi(X, P) + X @ X.T + lam**2 * A, 3))
        record("trL3", abs(ddt(L3, (X, P), fk)), abs(ddt(L3f, (X, P), fk)) if r < n else None)
        # u64-flows-differ
        fe = flow_kappa(X, P, A, -0.5)
        record("flows-differ", rel(fk[0] - fe[0] + c * X @ P.T @ X, fk[0]) + rel(fk[1] - fe[1] - c * P @ X.T @ P, fk[1]),
               rel(fk[0] - fe[0] + (c + 1) * X @ P.T @ X, fk[0]) if r >= 2 else None)
        # u64-psi0-flows-coincide
        P0 = P - X @ X.T @ P
        fn0, fe0 = flow_kappa(X, P0, A, 0.0), flow_kappa(X, P0, A, -0.5)
        fn, fe_ = flow_kappa(X, P, A, 0.0), flow_kappa(X, P, A, -0.5)
        record("psi0-coincide", rel(fn0[0] - fe0[0], fn0[0]) + rel(fn0[1] - fe0[1], fn0[1]),
               rel(fn[0] - fe_[0], fn[0]) + rel(fn[1] - fe_[1], fn[1]) if r >= 2 else None)
        # u64-gras-r2
        if r == 2:
            wdot = lambda X, P: wedge(P[:, 0], X[:, 1]) + wedge(X[:, 0], P[:, 1])
            acc = ddt(wdot, (X, P), fe)
            e1, e2, p1, p2 = X[:, 0], X[:, 1], P[:, 0], P[:, 1]
            lm = np.trace(X.T @ A @ X - P.T @ P)
            base = -wedge(A @ e1, e2) - wedge(e1, A @ e2) + lm * wedge(e1, e2)
            record("gras-r2", rel(acc - base - 2 * wedge(p1, p2), acc), rel(acc - base - wedge(p1, p2), acc))
        # u64-sphere-n3
        if (n, r) == (3, 2):
            fe0 = flow_kappa(X, P0, A, -0.5)
            e3 = np.cross(X[:, 0], X[:, 1])
            e3d = lambda X, P: np.cross(P[:, 0], X[:, 1]) + np.cross(X[:, 0], P[:, 1])
            v3 = e3d(X, P0); acc = ddt(e3d, (X, P0), fe0)
            record("sphere-n3", rel(acc - (A @ e3 - (e3 @ A @ e3 + v3 @ v3) * e3), acc),
                   rel(acc - (-A @ e3 + (e3 @ A @ e3 - v3 @ v3) * e3), acc))

# the double system (D-eq): XᵀẎ conserved, XᵀẊ not
for (n, r) in [(3, 1), (3, 2), (4, 2), (5, 3)]:
    for _ in range(3):
        A = np.diag(rng.standard_normal(n)); X = rng.standard_normal((n, r))
        G = np.linalg.inv(X.T @ X)
        Y = X @ G + (np.eye(n) - X @ G @ X.T) @ rng.standard_normal((n, r))
        Xd = rng.standard_normal((n, r)); Zr = rng.standard_normal((n, r))
        Yd = Zr - X @ G @ (X.T @ Zr + Xd.T @ Y)
        Lam = X.T @ A @ Y - Xd.T @ Yd
        tan = (Xd, Yd, -A @ X + X @ Lam.T, -A @ Y + Y @ Lam)
        d1 = ddt(lambda X, Y, Xd, Yd: X.T @ Yd, (X, Y, Xd, Yd), tan)
        d2 = ddt(lambda X, Y, Xd, Yd: X.T @ Xd, (X, Y, Xd, Yd), tan)
        record("double-XtYdot", np.max(np.abs(d1)), np.max(np.abs(d2)))

# the coupled system: diagonal momentum conserved, a single one not
for (n, r) in [(3, 2), (4, 2), (5, 3)]:
    for _ in range(3):
        X, P, A = point(n, r); Y, Q, _ = point(n, r); k = rng.standard_normal(); c = 1 + 2 * k
        fx = dirac(X, P, A @ Y - c * P @ X.T @ P, P - c * X @ P.T @ X)
        fy = dirac(Y, Q, A @ X - c * Q @ Y.T @ Q, Q - c * Y @ Q.T @ Y)
        tan = (fx[0], fx[1], fy[0], fy[1])
        m = ddt(lambda X, P, Y, Q: X.T @ P - P.T @ X + Y.T @ Q - Q.T @ Y, (X, P, Y, Q), tan)
        m1 = ddt(lambda X, P, Y, Q: X.T @ P - P.T @ X, (X, P, Y, Q), tan)
        record("coupled-diag", np.max(np.abs(m)), np.max(np.abs(m1)))

print(f"{'statement':18s} {'max residual (true)':>20s} {'min residual (twin)':>20s}")
for name, vals in out.items():
    t = max(v[0] for v in vals); fs = [v[1] for v in vals if v[1] is not None]
    print(f"{name:18s} {t:20.2e} {min(fs) if fs else float('nan'):20.2e}")
