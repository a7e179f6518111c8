# ruff: noqa: E701, E702
"""Independent numpy derivation of the truth of every h2 statement (no stiefelsym).
Random points on T*V (QR), generic diagonal A; Dirac flows solved from the multiplier form
Xd = H_P - X Pi, Pd = -H_X - eps Xd F + X Lam + P Pi with symmetric Lam, Pi by least squares on the
linearised constraints; gradients by central differences."""
import itertools
import sys
import numpy as np
rng = np.random.default_rng(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
h = 1e-5

def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, r)))[0]
    W = rng.standard_normal((r, r)); W = W - W.T
    P = (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r)) + X @ W
    return X, P

def grad(H, X, P):
    GX = np.zeros_like(X); GP = np.zeros_like(P)
    for idx in np.ndindex(X.shape):
        E = np.zeros_like(X); E[idx] = h
        GX[idx] = (H(X + E, P) - H(X - E, P)) / (2 * h)
        GP[idx] = (H(X, P + E) - H(X, P - E)) / (2 * h)
    return GX, GP

def sym_basis(r):
    out = []
    for i in range(r):
        for j in range(i, r):
            E = np.zeros((r, r)); E[i, j] = 1; E[j, i] = 1; out.append(E)
    return out

def cons_rate(X, P, Xd, Pd):
    return np.concatenate([(Xd.T @ X + X.T @ Xd).ravel(), (Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd).ravel()])

def flow(H, X, P, eps=0.0, F=None):
    n, r = X.shape
    HX, HP = grad(H, X, P)
    if F is None: F = np.zeros((r, r))
    def vf(L, Pi):
        Xd = HP - X @ Pi
        return Xd, -HX - eps * Xd @ F + X @ L + P @ Pi
    B = sym_basis(r); Z = np.zeros((r, r))
    base = cons_rate(X, P, *vf(Z, Z))
    cols = []
    for E in B:
        cols.append(cons_rate(X, P, *vf(E, Z)) - base)
    for E in B:
        cols.append(cons_rate(X, P, *vf(Z, E)) - base)
    c = np.linalg.lstsq(np.array(cols).T, -base, rcond=None)[0]
    m = len(B)
    L = sum(ci * E for ci, E in zip(c[:m], B)); Pi = sum(ci * E for ci, E in zip(c[m:], B))
    Xd, Pd = vf(L, Pi)
    assert np.abs(cons_rate(X, P, Xd, Pd)).max() < 1e-6
    return Xd, Pd, L, Pi

def deriv(G, X, P, Xd, Pd):
    return (G(X + h * Xd, P + h * Pd) - G(X - h * Xd, P - h * Pd)) / (2 * h)

tr = np.trace
def Phi(X, P): return P @ X.T - X @ P.T
def Psi(X, P): return X.T @ P - P.T @ X
def kil(a, b): return -0.5 * tr(a @ b)
def nrm(M): return float(np.abs(np.asarray(M)).max())

res = {}
def rec(name, n, r, v):
    res.setdefault(name, []).append((n, r, v))

sizes = [(n, r) for n in range(1, 5) for r in range(1, n + 1)]
for n, r in sizes:
    A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
    X, P = point(n, r)
    K = X.T @ P
    # C1 Jensen multipliers
    HJ = lambda X, P: 0.5 * tr(P.T @ P) - (0.5 + kap) * tr((X.T @ P) @ (X.T @ P))
    Xd, Pd, L, Pi = flow(HJ, X, P)
    rec("C1 true Lam=-PtP, Pi=0", n, r, max(nrm(L + P.T @ P), nrm(Pi)))
    rec("C1 twin Lam=-XdtXd", n, r, nrm(L + Xd.T @ Xd))
    # C2 general multipliers
    U = rng.standard_normal((n, r)); V = rng.standard_normal((n, r)); B = rng.standard_normal((n, n))
    HG = lambda X, P: tr(U.T @ X) + tr(V.T @ P) + tr(P.T @ B @ X) + 0.5 * tr(P.T @ P) * tr(X.T @ A @ X)
    Xd, Pd, L, Pi = flow(HG, X, P)
    GX, GP = grad(HG, X, P)
    sy = lambda M: (M + M.T) / 2
    Pi_f = sy(X.T @ GP)
    rec("C2 true", n, r, max(nrm(Pi - Pi_f), nrm(L - (sy(X.T @ GX - GP.T @ P) + Pi_f @ K - K @ Pi_f))))
    rec("C2 twin comm sign", n, r, nrm(L - (sy(X.T @ GX - GP.T @ P) + K @ Pi_f - Pi_f @ K)))
    # C3 quartic
    HQ = lambda X, P: 0.5 * tr(P.T @ P) + tr(X.T @ A @ A @ X) - tr(X.T @ A @ X @ X.T @ A @ X)
    Xd, Pd, L, Pi = flow(HQ, X, P)
    S = X.T @ A @ X
    rec("C3 true", n, r, max(nrm(Pi), nrm(L - (2 * X.T @ A @ A @ X - 4 * S @ S - P.T @ P))))
    rec("C3 twin factor 2", n, r, nrm(L - (2 * X.T @ A @ A @ X - 2 * S @ S - P.T @ P)))
    # C7 tr L^3 expansion and the lambda^4 coefficient
    lam = rng.standard_normal(); Vv = X @ X.T; F_ = Phi(X, P)
    Lx = lam * F_ + Vv - lam ** 2 * A
    expn = r + lam**2 * (3 * tr(F_ @ F_ @ Vv) - 3 * tr(A @ Vv)) + lam**4 * (3 * tr(Vv @ A @ A) - 3 * tr(F_ @ F_ @ A)) - lam**6 * tr(A @ A @ A)
    expt = r + lam**2 * (3 * tr(F_ @ F_ @ Vv) - 3 * tr(A @ Vv)) + lam**4 * (3 * tr(Vv @ A @ A) + 3 * tr(F_ @ F_ @ A)) - lam**6 * tr(A @ A @ A)
    HN = lambda X, P: 0.5 * tr(P.T @ P) - (0.5 + kap) * tr((X.T @ P) @ (X.T @ P)) + 0.5 * tr(X.T @ A @ X)
    Xd, Pd, L, Pi = flow(HN, X, P)
    c4 = lambda X, P: tr(X.T @ A @ A @ X) - tr(Phi(X, P) @ Phi(X, P) @ A)
    c4t = lambda X, P: tr(X.T @ A @ A @ X) + tr(Phi(X, P) @ Phi(X, P) @ A)
    rec("C7 true expansion", n, r, abs(tr(Lx @ Lx @ Lx) - expn))
    rec("C7 true conserved", n, r, abs(deriv(c4, X, P, Xd, Pd)))
    rec("C7 twin expansion", n, r, abs(tr(Lx @ Lx @ Lx) - expt))
    rec("C7 twin conserved", n, r, abs(deriv(c4t, X, P, Xd, Pd)))
    # C8 {H_kappa, H_kappa'} = 0
    k2 = rng.standard_normal()
    HN2 = lambda X, P: 0.5 * tr(P.T @ P) - (0.5 + k2) * tr((X.T @ P) @ (X.T @ P)) + 0.5 * tr(X.T @ A @ X)
    HNt = lambda X, P: 0.5 * tr(P.T @ P) + tr(X.T @ A @ X)
    rec("C8 true", n, r, abs(deriv(HN2, X, P, Xd, Pd)))
    rec("C8 twin", n, r, abs(deriv(HNt, X, P, Xd, Pd)))
    # C6 rank of pr_e on so(n)
    e = X[:, :1]
    basis = []
    for i, j in itertools.combinations(range(n), 2):
        E = np.zeros((n, n)); E[i, j] = 1; E[j, i] = -1; basis.append(E)
    if basis:
        M = np.array([(xi @ e @ e.T + e @ e.T @ xi).ravel() for xi in basis]).T
        rk = np.linalg.matrix_rank(M, tol=1e-9)
    else:
        rk = 0
    rec("C6 rank pr_e (expect n-1)", n, r, rk)

    # C4 / C5 coupled
    Y, Q = point(n, r)
    def Hc(kk):
        return lambda Z: (0.5 * tr(Z[1].T @ Z[1]) - (0.5 + kk) * tr((Z[0].T @ Z[1]) @ (Z[0].T @ Z[1]))
                          + 0.5 * tr(Z[3].T @ Z[3]) - (0.5 + kk) * tr((Z[2].T @ Z[3]) @ (Z[2].T @ Z[3]))
                          + tr(Z[0].T @ A @ Z[2]))
    def coupled_flow(H, Z):
        G = []
        for i in range(4):
            g = np.zeros_like(Z[i])
            for idx in np.ndindex(g.shape):
                E = np.zeros_like(g); E[idx] = h
                Zp = list(Z); Zm = list(Z); Zp[i] = Z[i] + E; Zm[i] = Z[i] - E
                g[idx] = (H(Zp) - H(Zm)) / (2 * h)
            G.append(g)
        out = []
        for (x, p) in ((0, 1), (2, 3)):
            X_, P_ = Z[x], Z[p]; HX, HP = G[x], G[p]
            Bs = sym_basis(r); Zr = np.zeros((r, r))
            def vf(L, Pi):
                Xd = HP - X_ @ Pi
                return Xd, -HX + X_ @ L + P_ @ Pi
            base = cons_rate(X_, P_, *vf(Zr, Zr))
            cols = [cons_rate(X_, P_, *vf(E, Zr)) - base for E in Bs] + [cons_rate(X_, P_, *vf(Zr, E)) - base for E in Bs]
            c = np.linalg.lstsq(np.array(cols).T, -base, rcond=None)[0]
            m = len(Bs)
            out += list(vf(sum(ci * E for ci, E in zip(c[:m], Bs)), sum(ci * E for ci, E in zip(c[m:], Bs))))
        return out
    D = coupled_flow(Hc(kap), [X, P, X, P])
    cc = 1 + 2 * kap
    NoX = P - cc * X @ P.T @ X; NoP = -A @ X - X @ P.T @ P + cc * P @ X.T @ P + X @ X.T @ A @ X
    rec("C4 true diag = (No)", n, r, max(nrm(D[0] - NoX), nrm(D[1] - NoP), nrm(D[2] - D[0]), nrm(D[3] - D[1])))
    c4k = 1 + 4 * kap
    rec("C4 twin 1+4k", n, r, max(nrm(D[0] - (P - c4k * X @ P.T @ X)), nrm(D[1] - (-A @ X - X @ P.T @ P + c4k * P @ X.T @ P + X @ X.T @ A @ X))))
    D1 = coupled_flow(Hc(kap), [X, P, Y, Q]); D0 = coupled_flow(Hc(0.0), [X, P, Y, Q])
    rec("C5 kappa flows coincide (true iff r=1)", n, r, max(nrm(a - b) for a, b in zip(D1, D0)))

# magnetic r = 2
for n in (2, 3, 4):
    r = 2
    A = np.diag(rng.standard_normal(n)); eps = rng.standard_normal()
    X, P = point(n, r)
    F = np.array([[0., 1.], [-1., 0.]])
    HE = lambda X, P: 0.5 * tr(P.T @ P) + 0.5 * tr(X.T @ A @ X)
    Xd, Pd, L, Pi = flow(HE, X, P, eps, F)
    psi12 = Psi(X, P)[0, 1]
    # paper's (mag-euk) as a cross-check of the convention
    e1, e2, p1, p2 = X[:, 0], X[:, 1], P[:, 0], P[:, 1]
    pd1 = -A @ e1 + ((e1 @ A @ e1) - p1 @ p1 - eps * (e1 @ p2)) * e1 + ((e1 @ A @ e2) - p1 @ p2) * e2 + eps * p2
    pd2 = -A @ e2 + ((e1 @ A @ e2) - p1 @ p2) * e1 + ((e2 @ A @ e2) - p2 @ p2 + eps * (e2 @ p1)) * e2 - eps * p1
    rec("M0 (mag-euk) matches my twisted flow", n, r, max(nrm(Pd[:, 0] - pd1), nrm(Pd[:, 1] - pd2), nrm(Xd - P)))
    rec("C10 true Lam = XtAX - PtP - eps/2 Psi12 I", n, r, max(nrm(L - (X.T @ A @ X - P.T @ P - eps / 2 * psi12 * np.eye(2))), nrm(Pi)))
    rec("C10 twin factor", n, r, nrm(L - (X.T @ A @ X - P.T @ P - eps * psi12 * np.eye(2))))
    we = lambda X: np.outer(X[:, 0], X[:, 1]) - np.outer(X[:, 1], X[:, 0])
    Ie = lambda X, P: kil(Phi(X, P) + eps * we(X), Phi(X, P) + eps * we(X)) + tr(X.T @ A @ X)
    It = lambda X, P: kil(Phi(X, P) + eps * we(X), Phi(X, P) + eps * we(X)) - tr(X.T @ A @ X)
    rec("C9 true", n, r, abs(deriv(Ie, X, P, Xd, Pd)))
    rec("C9 twin", n, r, abs(deriv(It, X, P, Xd, Pd)))

for k, v in res.items():
    print(k)
    print("   " + "  ".join(f"({n},{r}):{x:.1e}" if isinstance(x, float) else f"({n},{r}):{x}" for n, r, x in v))
