# ruff: noqa: E702 (a scratch script of the review: several statements on a line)
"""Independent numpy checks of claims.py (true) and negatives.py (false twins) at random points.
Run: /work/main/.venv/bin/python indep.py   (prints max |residual| per statement and twin)."""
import itertools
import numpy as np

rng = np.random.default_rng(61)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    W = rng.standard_normal((n, r))
    M = X.T @ W
    P = W - X @ (M + M.T) / 2
    A = np.diag(np.sort(rng.standard_normal(n)) + np.arange(n))  # distinct
    return X, P, A


def skew(m):
    G = rng.standard_normal((m, m)); return G - G.T


def sym(m):
    G = rng.standard_normal((m, m)); return G + G.T


def kil(a, b):
    return -0.5 * np.trace(a @ b)


def comm(a, b):
    return a @ b - b @ a


def so_basis(n):
    B = []
    for i in range(n):
        for j in range(i + 1, n):
            E = np.zeros((n, n)); E[i, j] = 1; E[j, i] = -1; B.append(E)  # <E,E> = 1
    return B


def sym_operator(n):
    B = so_basis(n); S = sym(len(B))
    def AA(xi):
        c = np.array([kil(E, xi) for E in B])
        return sum(ci * E for ci, E in zip(S @ c, B)) if B else 0 * xi
    return AA


def num_grad(f, M, h=1e-6):
    G = np.zeros_like(M)
    for idx in np.ndindex(M.shape):
        E = np.zeros_like(M); E[idx] = h
        G[idx] = (f(M + E) - f(M - E)) / (2 * h)
    return G


def Phi(X, P): return P @ X.T - X @ P.T
def Psi(X, P): return X.T @ P - P.T @ X


def res(*ms): return max(float(np.max(np.abs(np.atleast_1d(m)))) for m in ms)


SIZES = [(n, r) for n in range(1, 5) for r in range(1, n + 1)]
out = {}


def record(name, n, r, val):
    out.setdefault(name, []).append(((n, r), val))


for n, r in SIZES:
    X, P, A = point(n, r)
    a = np.diag(A)
    kappa = rng.standard_normal()
    # 1 submersion gradient
    AA = sym_operator(n)
    H = lambda X_, P_: kil(AA(Phi(X_, P_)), Phi(X_, P_)) / 2
    HX = num_grad(lambda M: H(M, P), X); HP = num_grad(lambda M: H(X, M), P)
    M = AA(Phi(X, P))
    record("h-submersion-gradient", n, r, res(HP - M @ X, -HX - M @ P))
    record("hn-submersion-gradient-sign", n, r, res(HP - M @ X, -HX + M @ P))
    # 2 isotropy
    eta = skew(r); I = np.eye(r); Q = (I - eta) @ np.linalg.inv(I + eta)
    Hk = lambda X_, P_: 0.5 * np.trace(P_.T @ P_) - (0.5 + kappa) * np.trace((X_.T @ P_) @ (X_.T @ P_))
    Pp = X @ Q.T @ X.T @ P @ Q + (np.eye(n) - X @ X.T) @ P @ Q
    record("h-isotropy-invariance", n, r, res(Q.T @ Q - I, X.T @ Pp + Pp.T @ X, X.T @ Pp - Q.T @ X.T @ P @ Q,
                                              Hk(X, Pp) - Hk(X, P)))
    Pq = X @ Q @ X.T @ P @ Q + (np.eye(n) - X @ X.T) @ P @ Q
    record("hn-isotropy-no-transpose", n, r, res(X.T @ Pq + Pq.T @ X, Hk(X, Pq) - Hk(X, P)))
    # 3 pencil
    h, v, xi, ze, et, th = skew(n), sym(n), skew(n), skew(n), sym(n), sym(n)
    s_, c_ = rng.standard_normal(), rng.standard_normal()
    L1 = lambda x, xi, et, ze, th: kil(x, comm(xi, ze) + comm(xi, th) + comm(et, ze))
    L2 = lambda x, xi, et, ze, th: kil(x - A, comm(xi + et, ze + th))
    pen = c_ * (1 - s_**2) * L1(h + v, xi, et, ze, th) + c_ * s_**2 * L2(h + v, xi, et, ze, th)
    y = s_ * h + v - s_**2 * A
    record("h-pencil-isomorphism", n, r, res(s_ * pen - c_ * kil(y, comm(xi + s_ * et, ze + s_ * th))))
    y2 = s_ * h + v - s_ * A
    record("hn-pencil-isomorphism-no-square", n, r, res(s_ * pen - c_ * kil(y2, comm(xi + s_ * et, ze + s_ * th))))
    # 4 lema1
    hh, vv = Phi(X, P), X @ X.T; Qp = np.eye(n) - vv
    xi1 = X @ Psi(X, P) @ X.T + Qp @ skew(n) @ Qp
    C = comm(xi1, hh)
    base = X @ sym(r) @ X.T + Qp @ sym(n) @ Qp
    eta1 = -Qp @ C @ vv + vv @ C @ Qp + base
    record("h-lema1-eta3", n, r, res(eta1 - eta1.T, comm(xi1, vv), C + comm(eta1, vv),
                                     L1(hh + vv, xi1, eta1, skew(n), sym(n))))
    eta1n = Qp @ C @ vv - vv @ C @ Qp + base
    record("hn-lema1-eta3-sign", n, r, res(C + comm(eta1n, vv)))
    # 5 lema2
    etad = np.diag(rng.standard_normal(n)); Cd = comm(etad, hh)
    D = a[None, :] - a[:, None]; np.fill_diagonal(D, 1)
    xid = Cd / D; np.fill_diagonal(xid, 0)
    z2, t2 = skew(n), sym(n)
    record("h-lema2-kernel", n, r, res(comm(etad, A), comm(xid, A) - comm(etad, hh), xid + xid.T,
                                       L1(hh + vv, xid, etad, z2, t2) - L2(hh + vv, xid, etad, z2, t2)))
    xin = -Cd / D; np.fill_diagonal(xin, 0)
    record("hn-lema2-kernel-sign", n, r, res(comm(xin, A) - comm(etad, hh)))
    # 6 pluecker
    if r < n:
        V = np.block([[X, P], [np.zeros((r, r)), np.eye(r)]])
        vals, valsn = [], []
        for Ir in itertools.combinations(range(n), r):
            vals.append(np.linalg.det(V[list(Ir) + list(range(n, n + r))]) - np.linalg.det(X[list(Ir)]))
        for Ir in itertools.combinations(range(n), r + 1):
            for k in range(r):
                idx = list(Ir) + [b for b in range(n, n + r) if b != n + k]
                Mk = np.column_stack([X[list(Ir)], P[list(Ir), k]])
                vals.append(np.linalg.det(V[idx]) - (-1) ** k * np.linalg.det(Mk))
                if k == 1:
                    valsn.append(np.linalg.det(V[idx]) - np.linalg.det(Mk))
        record("h-plucker-V", n, r, res(np.array(vals)))
        if r >= 2:
            record("hn-plucker-V-unsigned", n, r, res(np.array(valsn)))
    # 7 double
    Xd0 = rng.standard_normal((n, r)); Xq = Xd0
    G = np.linalg.inv(Xq.T @ Xq)
    Y = Xq @ G + (np.eye(n) - Xq @ G @ Xq.T) @ rng.standard_normal((n, r))
    Xdot = rng.standard_normal((n, r)); W = rng.standard_normal((n, r))
    Ydot = W + Xq @ G @ (-Xdot.T @ Y - Xq.T @ W)
    Lam = Xq.T @ A @ Y - Xdot.T @ Ydot
    Xdd, Ydd = -A @ Xq + Xq @ Lam.T, -A @ Y + Y @ Lam
    record("h-double-xydot", n, r, res(Xq.T @ Y - np.eye(r), Xdot.T @ Ydot + Xq.T @ Ydd,
                                       (Xq.T @ Ydot - Y.T @ Xdot) - (Xq.T @ Ydot + Ydot.T @ Xq)))
    record("hn-double-xdot-ydot", n, r, res(Xdd.T @ Ydot + Xdot.T @ Ydd))
    # 8 submersion not left invariant (true claim: nonzero) ; twin: == 0
    xi8 = skew(n); e = 1e-6
    dH = (H(X + e * xi8 @ X, P + e * xi8 @ P) - H(X - e * xi8 @ X, P - e * xi8 @ P)) / (2 * e)
    if n >= 3:
        record("h-submersion-not-left-invariant (|d|, must be >0)", n, r, abs(dH))
        record("hn-submersion-left-invariant", n, r, abs(dH))
    # 9 counts
    m = n - r
    ker = r // 2 + m * (m - 1) // 2 + r * (r + 1) // 2 + m * (m + 1) // 2
    record("h-proof-counts", n, r, abs(n * n - ker - (2 * r * m + r * (r - 1) // 2 - r // 2))
           + abs((n * n - r * r - m * m) // 2 - r * m))
    if r >= 2:
        ker2 = ker - r // 2
        record("hn-proof-counts-no-rank", n, r, abs(n * n - ker2 - (2 * r * m + r * (r - 1) // 2 - r // 2)))

for name, vals in out.items():
    mx = max(v for _, v in vals); mn = min(v for _, v in vals)
    print(f"{name:55s} max {mx:.2e} min {mn:.2e}  sizes {[s for s, _ in vals]}")

print("\nsizes where a false twin nevertheless holds (|residual| < 1e-8):")
for name, vals in out.items():
    if name.startswith("hn-"):
        print(f"  {name}: {[s for s, v in vals if v < 1e-8]}")

# extra probe: n = 2, H_AA is left-invariant (so(2) is abelian), so the kind-not claim at n = 2 is false
for n, r in [(2, 1), (2, 2)]:
    X, P, A = point(n, r)
    AA = sym_operator(n)
    H = lambda X_, P_: kil(AA(Phi(X_, P_)), Phi(X_, P_)) / 2
    xi8 = skew(n); e = 1e-6
    dH = (H(X + e * xi8 @ X, P + e * xi8 @ P) - H(X - e * xi8 @ X, P - e * xi8 @ P)) / (2 * e)
    print(f"hn-submersion-not-left-invariant-n2 ({n},{r}): |dH| = {abs(dH):.1e} (0 => the 'not' claim is false)")
