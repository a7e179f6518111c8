# ruff: noqa: F841, E702, F401, E731, E741
"""Independent numpy evaluation of the claims of claims.py / negatives.py (no stiefelsym import).

Dirac flow: Xdot = H_P - X Pi, Pdot = -H_X + X Lam + P Pi with Lam, Pi symmetric solved from the
time derivatives of X^TX = I, X^TP + P^TX = 0.  Gradients and directional derivatives by the
complex step (exact to rounding for these polynomial/rational functions)."""
import itertools
import sys

import numpy as np

rng = np.random.default_rng(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
H_STEP = 1e-30


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    Z = rng.standard_normal((n, r))
    S = X.T @ Z
    P = Z - X @ ((S + S.T) / 2)
    A = np.diag(np.sort(rng.standard_normal(n)) + np.arange(n))
    return X, P, A


def tr(M):
    return np.trace(M)


def kil(a, b):
    return -tr(a @ b) / 2


def Phi(X, P):
    return P @ X.T - X @ P.T


def Psi(X, P):
    return X.T @ P - P.T @ X


def dd(F, X, P, dX, dP):
    """directional derivative by the complex step."""
    return np.imag(F(X + 1j * H_STEP * dX, P + 1j * H_STEP * dP)) / H_STEP


def grad(H, X, P):
    GX = np.zeros_like(X)
    GP = np.zeros_like(P)
    for i, j in itertools.product(range(X.shape[0]), range(X.shape[1])):
        E = np.zeros_like(X)
        E[i, j] = 1
        GX[i, j] = dd(H, X, P, E, 0 * E)
        GP[i, j] = dd(H, X, P, 0 * E, E)
    return GX, GP


def sym_basis(r):
    out = []
    for i in range(r):
        for j in range(i, r):
            E = np.zeros((r, r))
            E[i, j] = E[j, i] = 1
            out.append(E)
    return out


def dirac(H, X, P):
    HX, HP = grad(H, X, P)
    r = X.shape[1]
    B = sym_basis(r)

    def tangent(Lam, Pi):
        return HP - X @ Pi, -HX + X @ Lam + P @ Pi

    def cons(dX, dP):
        c1 = dX.T @ X + X.T @ dX
        c2 = dX.T @ P + X.T @ dP + dP.T @ X + P.T @ dX
        iu = np.triu_indices(r)
        return np.concatenate([c1[iu], c2[iu]])
    Z = np.zeros((r, r))
    b0 = cons(*tangent(Z, Z))
    cols = [cons(*tangent(E, Z)) - b0 for E in B] + [cons(*tangent(Z, E)) - b0 for E in B]
    M = np.array(cols).T
    sol = np.linalg.solve(M, -b0)
    m = len(B)
    Lam = sum(c * E for c, E in zip(sol[:m], B))
    Pi = sum(c * E for c, E in zip(sol[m:], B))
    return tangent(Lam, Pi)


def H_E(X, P):
    return tr(P.T @ P) / 2


def H_0(X, P):
    return kil(Phi(X, P), Phi(X, P)) / 2


def cubic(A, xi):
    return A @ A @ xi + A @ xi @ A + xi @ A @ A


def L_dual(X, P, A, lam):
    n, r = X.shape
    R = np.linalg.inv(lam * np.eye(n) - A)
    return np.block([[-(X.T @ R @ P), -(X.T @ R @ X)], [np.eye(r) + P.T @ R @ P, P.T @ R @ X]])


def rank_L1(X):
    n = X.shape[0]
    v = X @ X.T
    cols = []
    for i in range(n):
        for j in range(i + 1, n):
            E = np.zeros((n, n))
            E[i, j], E[j, i] = 1, -1
            cols.append((E @ v - v @ E).ravel())
    if not cols:
        return 0
    return np.linalg.matrix_rank(np.array(cols).T, tol=1e-9)


def norm(x):
    return float(np.max(np.abs(np.atleast_1d(x)))) if np.size(x) else 0.0


def evaluate(n, r):
    X, P, A = point(n, r)
    lam = 0.37 + rng.standard_normal()
    k = rng.standard_normal()
    eta = rng.standard_normal((r, r))
    eta = eta - eta.T
    Ph, Ps = Phi(X, P), Psi(X, P)
    K, G = X.T @ P, P.T @ P
    comm = lambda a, b: a @ b - b @ a
    fE, f0 = dirac(H_E, X, P), dirac(H_0, X, P)
    Hk = lambda X_, P_: kil(Phi(X_, P_), Phi(X_, P_)) / 2 + k * kil(Psi(X_, P_), Psi(X_, P_)) / 2
    fk = dirac(Hk, X, P)
    Hc = lambda X_, P_: kil(cubic(A, Phi(X_, P_)), Phi(X_, P_)) / 2
    fc = dirac(Hc, X, P)
    HN = lambda X_, P_: tr(P_.T @ P_) / 2 - tr(X_.T @ P_ @ X_.T @ P_) / 2 + tr(X_.T @ A @ X_) / 2
    fN = dirac(HN, X, P)
    gram = lambda X_, P_: P_.T @ P_
    v = X @ X.T
    Mc = cubic(A, Ph)
    dPhi_c = dd(lambda X_, P_: Phi(X_, P_), X, P, *fc)
    tr2 = lambda X_, P_: tr(L_dual(X_, P_, A, lam) @ L_dual(X_, P_, A, lam))
    tr4 = lambda X_, P_: tr(np.linalg.matrix_power(L_dual(X_, P_, A, lam), 4))
    closedk = tr(G) / 2 - (0.5 + k) * tr(K @ K)
    res = {
        "u63-phi-acts": max(norm(Ph @ X - (P - X @ P.T @ X)), norm(Ph @ P - (-X @ P.T @ P + P @ X.T @ P))),
        "n63-phi-acts": norm(Ph @ X - (P + X @ P.T @ X)),
        "u63-euclid-accel": max(norm(fE[0] - P), norm(fE[1] + X @ fE[0].T @ fE[0])),
        "n63-euclid-accel": norm(fE[1] - X @ fE[0].T @ fE[0]),
        "u63-jensen-kappa": max(norm(Hk(X, P) - closedk), norm(fk[0] - (P - (1 + 2 * k) * X @ P.T @ X))),
        "n63-jensen-kappa": norm(Hk(X, P) - (tr(G) / 2 - (0.5 - k) * tr(K @ K))),
        "u63-manakov-cubic-flow": max(norm(fc[0] - Mc @ X), norm(fc[1] - Mc @ P)),
        "n63-manakov-cubic-flow": norm(fc[0] - (A @ A @ Ph - A @ Ph @ A + Ph @ A @ A) @ X),
        "u63-manakov-cubic-lax": norm(dPhi_c - comm(Mc + lam * A @ A @ A, Ph + lam * A)),
        "n63-manakov-cubic-lax": norm(dPhi_c - comm(Mc - lam * A @ A @ A, Ph + lam * A)),
        "u63-gram-normal-vs-euclid": max(norm(dd(gram, X, P, *f0)), norm(dd(gram, X, P, *fE) - comm(K, G))),
        "n63-gram-euclid": norm(dd(gram, X, P, *fE) - comm(G, K)),
        "n63-gram-not-conserved (nonzero wanted)": norm(dd(gram, X, P, *fE)),
        "n63-gram-not-normal (nonzero wanted)": norm(dd(gram, X, P, *f0)),
        "u63-theta-hamiltonian": max(norm(kil(Ph, Ph) / 2 - kil(A, v) - HN(X, P)),
                                     norm(dd(lambda X_, P_: Phi(X_, P_), X, P, *fN) - comm(v, A)),
                                     norm(dd(lambda X_, P_: X_ @ X_.T, X, P, *fN) - comm(Ph, v))),
        "n63-theta-hamiltonian": norm(kil(Ph, Ph) / 2 + kil(A, v) - HN(X, P)),
        "n63-cpb-vdot": norm(dd(lambda X_, P_: X_ @ X_.T, X, P, *fN) - comm(v, Ph)),
        "u63-l1-rank (rank - r(n-r))": rank_L1(X) - r * (n - r),
        "u63-r-equals-n": max(norm(tr(X.T @ A @ X) - tr(A)), norm(fN[0] - f0[0]), norm(fN[1] - f0[1])),
        "n63-r-equals-n": norm(fN[1] - (f0[1] - A @ X)),
        "n63-r-lt-n-geodesic": norm(fN[1] - f0[1]),
        "u63-dual-curve-so-r": max(norm(dd(tr2, X, P, X @ eta, P @ eta)), norm(dd(tr4, X, P, X @ eta, P @ eta))),
        "n63-dual-curve-so-r": norm(dd(tr2, X, P, X @ eta, -P @ eta)),
        "n63-dual-matrix-not-invariant (nonzero wanted)": norm(dd(lambda X_, P_: L_dual(X_, P_, A, lam), X, P, X @ eta, P @ eta)),
    }
    return res


if __name__ == "__main__":
    sizes = [(3, 1), (4, 2), (3, 3), (4, 3), (5, 2), (5, 5)]
    table = {sz: evaluate(*sz) for sz in sizes}
    names = list(table[sizes[0]])
    print(f"{'residual (max abs)':48s}" + "".join(f"{str(sz):>11s}" for sz in sizes))
    for nm in names:
        print(f"{nm:48s}" + "".join(f"{table[sz][nm]:11.2e}" for sz in sizes))
