# ruff: noqa: E702, E731, E741
"""Independent truth for s88h1 claims (numpy only, no stiefelsym). Residual max-abs at random points of T*V."""
import numpy as np
rng = np.random.default_rng(1)

def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    A = np.diag(rng.standard_normal(n))
    return X, P, A

def skew(m):
    M = rng.standard_normal((m, m)); return M - M.T

def tr(M): return np.trace(M)
def kil(a, b): return -0.5 * tr(a @ b)
def comm(a, b): return a @ b - b @ a
def Phi(X, P): return P @ X.T - X @ P.T
def Psi(X, P): return X.T @ P - P.T @ X
def sym(M): return (M + M.T) / 2

def grad(f, X, P):
    h = 1e-30
    gX = np.zeros_like(X); gP = np.zeros_like(P)
    for i in range(X.shape[0]):
        for j in range(X.shape[1]):
            E = np.zeros_like(X, dtype=complex); E[i, j] = 1j * h
            gX[i, j] = np.imag(f(X + E, P)) / h
            gP[i, j] = np.imag(f(X, P + E)) / h
    return gX, gP

def dirac(Hf, X, P):
    HX, HP = grad(Hf, X, P)
    K = X.T @ P
    Pi = sym(X.T @ HP)
    Lam = sym(X.T @ HX) - sym(P.T @ HP) + Pi @ K - K @ Pi
    return HP - X @ Pi, -HX + X @ Lam + P @ Pi

def dd(f, X, P, dX, dP):
    h = 1e-30
    return np.imag(f(X + 1j * h * dX, P + 1j * h * dP)) / h

def bracket(f, g, X, P):
    fX, fP = grad(f, X, P)
    Xd, Pd = dirac(g, X, P)
    return np.sum(fX * Xd) + np.sum(fP * Pd)

# transpose that does not conjugate (for complex-step)
def T(M): return M.T

def Hneum(k, A):
    def H(X, P):
        K = X.T @ P
        return tr(P.T @ P) / 2 - (0.5 + k) * tr(K @ K) + tr(X.T @ A @ X) / 2
    return H

def No(X, P, A, k):
    c = 1 + 2 * k
    return P - c * X @ P.T @ X, -A @ X - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A @ X

def dso(m): return m * (m - 1) // 2 if m > 1 else 0

def claims(n, r):
    X, P, A = point(n, r)
    U = rng.standard_normal((n, r)); Wm = rng.standard_normal((n, r))
    xi = skew(n); eta = skew(r); B = rng.standard_normal((r, r))
    k = rng.standard_normal(); lam = rng.standard_normal()
    out = {}
    out["base-commute"] = bracket(lambda x, p: tr(U.T @ x), lambda x, p: tr(Wm.T @ x), X, P)
    out["base-commute-twin"] = bracket(lambda x, p: tr(U.T @ p), lambda x, p: tr(Wm.T @ p), X, P)
    b = bracket(lambda x, p: tr(U.T @ x), lambda x, p: tr(Wm.T @ p), X, P)
    out["xp-bracket"] = b - (tr(U.T @ Wm) - 0.5 * tr(U.T @ X @ (X.T @ Wm + Wm.T @ X)))
    out["xp-bracket-twin"] = b - (tr(U.T @ Wm) - 1.0 * tr(U.T @ X @ (X.T @ Wm + Wm.T @ X)))
    b = bracket(lambda x, p: kil(Phi(x, p), xi), lambda x, p: tr(U.T @ x), X, P)
    out["phi-x-bracket"] = b + tr(U.T @ xi @ X)
    out["phi-x-bracket-twin"] = b - tr(U.T @ xi @ X)
    b = bracket(lambda x, p: kil(Psi(x, p), eta), lambda x, p: tr(B @ p.T @ p), X, P)
    G = P.T @ P
    out["psi-gram-bracket"] = b - tr(B @ comm(eta, G))
    out["psi-gram-bracket-twin"] = b - tr(B @ comm(G, eta))
    cols = []
    for i in range(n):
        for j in range(i + 1, n):
            E = np.zeros((n, n)); E[i, j] = 1; E[j, i] = -1
            cols.append(np.concatenate([(E @ X).ravel(), (E @ P).ravel()]))
    rk = np.linalg.matrix_rank(np.array(cols).T) if cols else 0
    out["left-orbit-rank"] = rk - (dso(n) - dso(n - min(n, 2 * r)))
    out["left-orbit-rank-twin"] = rk - (dso(n) - dso(n - r))
    Ph, Ps = Phi(X, P), Psi(X, P)
    out["casimir-invariants"] = kil(Ph, Ph) - tr(P.T @ P) - kil(Ps, Ps) / 2
    out["casimir-invariants-twin"] = kil(Ph, Ph) - tr(P.T @ P) + kil(Ps, Ps) / 2
    out["phi-psi-restrict"] = np.abs(X.T @ Ph @ X - Ps).max()
    out["phi-psi-restrict-twin"] = np.abs(X.T @ Ph @ X + Ps).max()
    # constraint bracket matrix: rank of {F_i,F_j}_0 for upper-triangle constraints
    cons = []
    for i in range(r):
        for j in range(i, r):
            cons.append(lambda x, p, i=i, j=j: (x.T @ x)[i, j])
    for i in range(r):
        for j in range(i, r):
            cons.append(lambda x, p, i=i, j=j: (x.T @ p + p.T @ x)[i, j])
    grads = [grad(c, X, P) for c in cons]
    M = np.array([[np.sum(a[0] * b[1]) - np.sum(a[1] * b[0]) for b in grads] for a in grads])
    rk = np.linalg.matrix_rank(M)
    out["constraint-matrix-rank"] = rk - r * (r + 1)
    out["constraint-matrix-rank-twin"] = rk - (r * (r + 1) - 1)
    # §5
    f1 = dirac(Hneum(k, A), X, P); f0 = dirac(Hneum(0, A), X, P)
    dX = f1[0] - f0[0]; dP = f1[1] - f0[1]
    out["kappa-difference"] = max(np.abs(dX - k * X @ Ps).max(), np.abs(dP - k * P @ Ps).max())
    out["kappa-difference-twin"] = max(np.abs(dX - 2 * k * X @ Ps).max(), np.abs(dP - 2 * k * P @ Ps).max())
    no = No(X, P, A, k)
    dV = dd(lambda x, p: tr(x.T @ A @ x) / 2, X, P, *no)
    out["potential-rate"] = dV - tr(X.T @ A @ P)
    out["potential-rate-twin"] = dV - 2 * tr(X.T @ A @ P)
    K = X.T @ P
    out["xt-pdot"] = np.abs(X.T @ f1[1] - (-G + (1 + 2 * k) * K @ K)).max()
    out["xt-pdot-twin"] = np.abs(X.T @ f1[1] - (-G + (1 + k) * K @ K)).max()
    cub = lambda s_: (lambda x, p: tr(Phi(x, p) @ Phi(x, p) @ x @ x.T) + s_ * tr(A @ x @ x.T))
    out["cubic-integral"] = dd(cub(-1), X, P, *f1)
    out["cubic-integral-twin"] = dd(cub(1), X, P, *f1)
    L = lambda s_: (lambda x, p: lam * Phi(x, p) + x @ x.T + s_ * lam * lam * A)
    out["quartic-spectral"] = dd(lambda x, p: tr(np.linalg.matrix_power(L(-1)(x, p), 4)), X, P, *f1)
    out["quartic-spectral-twin"] = dd(lambda x, p: tr(np.linalg.matrix_power(L(1)(x, p), 2)), X, P, *f1)
    out["potential-constant(r=n)/twin(r=n-1)"] = tr(X.T @ A @ X) - tr(A)
    out["energy-printed"] = dd(Hneum(k, A), X, P, *no)
    out["energy-printed-twin"] = dd(lambda x, p: tr(p.T @ p) / 2 - (0.5 + k) * tr((x.T @ p) @ (x.T @ p)), X, P, *no)
    out["phi-projector"] = np.abs(comm(Ph, X @ X.T) - (P @ X.T + X @ P.T)).max()
    out["phi-projector-twin"] = np.abs(comm(X @ X.T, Ph) - (P @ X.T + X @ P.T)).max()
    return out

sizes = [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3), (4, 1), (4, 2), (4, 3), (4, 4), (5, 2), (5, 3)]
res = {sz: claims(*sz) for sz in sizes}
names = list(res[sizes[0]].keys())
print("claim".ljust(40), " ".join(f"{n},{r}".rjust(6) for n, r in sizes))
for nm in names:
    row = []
    for sz in sizes:
        v = abs(float(np.real(res[sz][nm])))
        row.append(("0" if v < 1e-8 else "X").rjust(6))
    print(nm.ljust(40), " ".join(row))
print("(0 = residual vanishes (TRUE at that size), X = nonzero (FALSE))")

# ---- claims2: Jacobi, Leibniz, restriction (nested brackets by central differences of the bracket function)
def claims2(n, r):
    X, P, A = point(n, r)
    U = rng.standard_normal((n, r)); Wm = rng.standard_normal((n, r)); B = rng.standard_normal((r, r))
    xi = skew(n); S = sym(rng.standard_normal((r, r))); Tm = sym(rng.standard_normal((r, r)))
    f = lambda x, p: kil(Phi(x, p), xi)
    g = lambda x, p: tr(B @ p.T @ p)
    h = lambda x, p: tr(U.T @ p)
    # nested bracket: {a,b} as a function on the ambient space (Dirac formula holds off T*V too), its gradient by
    # central finite differences (real arithmetic), step 1e-5
    def br_fun(a, b):
        def F(x, p):
            return bracket(a, b, x, p)
        return F
    def bracket_fd(F, b, x, p, hstep=1e-5):
        gX = np.zeros_like(x); gP = np.zeros_like(p)
        for i in range(x.shape[0]):
            for j in range(x.shape[1]):
                E = np.zeros_like(x); E[i, j] = hstep
                gX[i, j] = (F(x + E, p) - F(x - E, p)) / (2 * hstep)
                gP[i, j] = (F(x, p + E) - F(x, p - E)) / (2 * hstep)
        Xd, Pd = dirac(b, x, p)
        return np.sum(gX * Xd) + np.sum(gP * Pd)
    t1 = bracket_fd(br_fun(f, g), h, X, P)
    t2 = bracket_fd(br_fun(g, h), f, X, P)
    t3 = bracket_fd(br_fun(h, f), g, X, P)
    out = {"dirac-jacobi": t1 + t2 + t3, "dirac-jacobi-twin": t1 + t2 - t3}
    f = lambda x, p: tr(U.T @ p); g = lambda x, p: tr(Wm.T @ x); h = lambda x, p: tr(B @ p.T @ p)
    lhs = bracket(f, lambda x, p: g(x, p) * h(x, p), X, P)
    out["dirac-leibniz"] = lhs - bracket(f, g, X, P) * h(X, P) - g(X, P) * bracket(f, h, X, P)
    out["dirac-leibniz-twin"] = lhs - bracket(f, g, X, P) * h(X, P) + g(X, P) * bracket(f, h, X, P)
    f2 = lambda x, p: tr(U.T @ p) + tr(S @ (x.T @ x - np.eye(r))) + tr(Tm @ (x.T @ p + p.T @ x))
    gg = lambda x, p: tr(Wm.T @ p)
    out["dirac-restriction"] = bracket(f2, gg, X, P) - bracket(f, gg, X, P)
    def cbr(a, b):
        aX, aP = grad(a, X, P); bX, bP = grad(b, X, P)
        return np.sum(aX * bP) - np.sum(aP * bX)
    out["dirac-restriction-twin"] = cbr(f2, gg) - cbr(f, gg)
    return out

if __name__ == "__main__":
    sizes2 = [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3)]
    res2 = {sz: claims2(*sz) for sz in sizes2}
    print()
    print("claims2".ljust(40), " ".join(f"{n},{r}".rjust(6) for n, r in sizes2))
    for nm in res2[sizes2[0]]:
        print(nm.ljust(40), " ".join((("0" if abs(res2[sz][nm]) < 1e-5 else "X") + f"({abs(res2[sz][nm]):.0e})").rjust(10) for sz in sizes2))
