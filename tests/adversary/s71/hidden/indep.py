# ruff: noqa
"""Independent numpy truth for claims.py and negatives.py (imports nothing of stiefelsym).

Random points of T*V (XᵀX = I, XᵀP + PᵀX = 0), A = diag(a) distinct; Dirac flows and brackets are built
from scratch (central-difference gradients, the constraint matrix {F_i, F_j}_0 solved).  Prints, per
statement and size, the largest |residual| over 3 points: ~1e-7 or below = true, O(1) = false."""
import itertools
import numpy as np

rng = np.random.default_rng(71)
SIZES = [(n, r) for n in range(1, 5) for r in range(1, n + 1)]


def point(n, r):
    X = np.linalg.qr(rng.normal(size=(n, n)))[0][:, :r]
    W = rng.normal(size=(r, r)); W = W - W.T
    Z = rng.normal(size=(n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    a = np.sort(rng.uniform(-2, 2, size=n)) + np.arange(n)
    return X, P, np.diag(a)


def skew(m):
    M = rng.normal(size=(m, m)); return M - M.T


def sym(m):
    M = rng.normal(size=(m, m)); return M + M.T


def cay(M):
    I = np.eye(len(M)); return (I - M) @ np.linalg.inv(I + M)


def grad(f, z, h=1e-5):
    g = np.zeros_like(z)
    for i in range(len(z)):
        e = np.zeros_like(z); e[i] = h
        g[i] = (f(z + e) - f(z - e)) / (2 * h)
    return g


class Phase:
    """canonical pairs (positions, momenta) of shapes (n, r), flattened; constraints of cond_XP per pair."""

    def __init__(self, n, r, pairs=1):
        self.n, self.r, self.k = n, r, pairs

    def split(self, z):
        n, r = self.n, self.r
        m = n * r
        return [z[i * m:(i + 1) * m].reshape(n, r) for i in range(2 * self.k)]

    def join(self, *Ms):
        return np.concatenate([M.ravel() for M in Ms])

    def constraints(self):
        r = self.r
        out = []
        for p in range(self.k):
            for i in range(r):
                for j in range(i, r):
                    out.append(lambda z, p=p, i=i, j=j: (lambda M: (M[2 * p].T @ M[2 * p])[i, j] - (i == j))(self.split(z)))
                    out.append(lambda z, p=p, i=i, j=j: (lambda M: (M[2 * p].T @ M[2 * p + 1] + M[2 * p + 1].T @ M[2 * p])[i, j])(self.split(z)))
        return out

    def J(self, g):
        Ms = self.split(g)
        out = []
        for p in range(self.k):
            out += [Ms[2 * p + 1], -Ms[2 * p]]
        return self.join(*out)

    def can(self, f, g, z):
        return grad(f, z) @ self.J(grad(g, z))

    def dirac_field(self, H, z):
        F = self.constraints()
        C = np.array([[self.can(Fi, Fj, z) for Fj in F] for Fi in F])
        b = np.array([self.can(Fj, H, z) for Fj in F])
        w = np.linalg.solve(C, b)
        v = self.J(grad(H, z))
        for wi, Fi in zip(w, F):
            v = v - wi * self.J(grad(Fi, z))
        return v

    def dirac(self, f, g, z):
        return grad(f, z) @ self.dirac_field(g, z)

    def d(self, f, z, v, h=1e-5):
        return (f(z + h * v) - f(z - h * v)) / (2 * h)


def mx(x):
    return float(np.max(np.abs(x))) if np.size(x) else 0.0


Phi = lambda X, P: P @ X.T - X @ P.T
Psi = lambda X, P: X.T @ P - P.T @ X
wedge = lambda a, b: a @ b.T - b @ a.T


def res_momentum_finite(n, r, X, P, A, twin):
    Q, R = cay(skew(r)), cay(skew(n))
    if twin:
        return mx(Psi(X @ Q, P @ Q) - Q @ Psi(X, P) @ Q.T)
    return max(mx(Phi(X @ Q, P @ Q) - Phi(X, P)), mx(Psi(R @ X, R @ P) - Psi(X, P)),
               mx(Phi(R @ X, R @ P) - R @ Phi(X, P) @ R.T), mx(Psi(X @ Q, P @ Q) - Q.T @ Psi(X, P) @ Q))


def res_dirac_printed(n, r, X, P, A, twin):
    ph = Phase(n, r)
    z = ph.join(X, P)
    U, V = rng.normal(size=(n, r)), rng.normal(size=(n, r))
    kap = 0.37
    f1 = lambda z: (lambda M: np.trace(U.T @ M[0]) + np.trace(V.T @ M[1]))(ph.split(z))
    f2 = lambda z: (lambda M: np.trace(M[1].T @ M[1]) / 2 - (0.5 + kap) * np.trace(M[0].T @ M[1] @ M[0].T @ M[1])
                    + np.trace(M[0].T @ A @ M[0]) / 2)(ph.split(z))
    F = ph.constraints()
    C = np.linalg.inv(np.array([[ph.can(Fi, Fj, z) for Fj in F] for Fi in F]))
    b1 = np.array([ph.can(Fi, f1, z) for Fi in F]); b2 = np.array([ph.can(Fj, f2, z) for Fj in F])
    sgn = -1 if twin else 1
    printed = ph.can(f1, f2, z) + sgn * b1 @ C @ b2
    # reference Dirac bracket: the standard {f,g}_0 − {f,F}C{F,g}
    ref = ph.can(f1, f2, z) - np.array([ph.can(f1, Fi, z) for Fi in F]) @ C @ b2
    return abs(printed - ref)


def res_neumann_middle(n, r, X, P, A, twin):
    ph = Phase(n, r)
    z = ph.join(X, P)
    Lam = X.T @ A @ X - P.T @ P
    HE = lambda z: (lambda M: np.trace(M[1].T @ M[1]) / 2 + np.trace(M[0].T @ A @ M[0]) / 2)(ph.split(z))
    H0 = lambda z: (lambda M: np.trace(M[1].T @ M[1]) / 2 - 0.5 * np.trace(M[0].T @ M[1] @ M[0].T @ M[1])
                    + np.trace(M[0].T @ A @ M[0]) / 2)(ph.split(z))
    vE = ph.split(ph.dirac_field(HE, z)); v0 = ph.split(ph.dirac_field(H0, z))
    if twin:
        return mx(vE[1] - (-A @ X - X @ Lam))
    return max(mx(vE[1] - (-A @ X + X @ Lam)), mx(v0[1] - (-A @ X + P @ X.T @ P + X @ Lam)),
               mx(v0[0] - (P - X @ P.T @ X)))


def res_lema1(n, r, X, P, A, twin):
    v = X @ X.T; eta = sym(n); Qp = np.eye(n) - v
    if twin:
        return mx(eta @ v - v @ eta - (v @ eta @ Qp - Qp @ eta @ v))
    xi = X @ skew(r) @ X.T + Qp @ skew(n) @ Qp
    return max(mx(eta @ v - v @ eta - (Qp @ eta @ v - v @ eta @ Qp)), mx(xi @ v - v @ xi))


def res_dual_relations(n, r, X, P, A, twin):
    lam = 0.731
    I = np.eye(n)
    R = lambda mu: np.linalg.inv(mu * I - A)
    Lm = lambda mu: np.block([[-X.T @ R(mu) @ P, -X.T @ R(mu) @ X], [P.T @ R(mu) @ P, P.T @ R(mu) @ X]])
    Rp = np.linalg.inv(A + lam * I)
    Aman = np.block([[X.T @ Rp @ P, X.T @ Rp @ X], [-P.T @ Rp @ P, -P.T @ Rp @ X]])
    Ln = Lm(lam) + np.block([[np.zeros((r, r)), np.zeros((r, r))], [np.eye(r), np.zeros((r, r))]])
    if twin:
        return mx(Aman - Lm(lam))
    Ln_direct = np.block([[-X.T @ R(lam) @ P, -X.T @ R(lam) @ X], [np.eye(r) + P.T @ R(lam) @ P, P.T @ R(lam) @ X]])
    return max(mx(Ln - Ln_direct), mx(Aman - Lm(-lam)))


def res_manakov(n, r, X, P, A, twin):
    ph = Phase(n, r); z = ph.join(X, P)
    ph_ = lambda z: (lambda M: M[1] @ M[0].T - M[0] @ M[1].T)(ph.split(z))
    H2 = lambda z: (lambda F: -np.trace((A @ F + F @ A) @ F) / 4)(ph_(z))
    H3 = lambda z: (lambda F: -np.trace((A @ A @ F + A @ F @ A + F @ A @ A) @ F) / 4)(ph_(z))
    lam = 0.53
    I2 = lambda z: (lambda F: np.trace((F + lam * A) @ (F + lam * A)))(ph_(z))
    if twin:
        xi = skew(n)
        return abs(ph.dirac(lambda z: -np.trace(ph_(z) @ xi) / 2, H2, z))
    return max(abs(ph.dirac(H2, H3, z)), abs(ph.dirac(I2, H3, z)))


def res_ym(n, r, X, P, A, twin):
    if r != 1:
        return None
    e, ed = X, P
    lhs = (A @ e @ e.T - e @ e.T @ A) @ e + wedge(ed, e) @ ed
    s = (e.T @ A @ e + ed.T @ ed)[0, 0]
    if twin:
        return mx(lhs - (A @ e + s * e))
    Om = skew(n); edd = Om @ e; pr = Om @ e @ e.T + e @ e.T @ Om
    return max(mx(lhs - (A @ e - s * e)), mx(pr @ e - edd), mx(pr - wedge(edd, e)))


def res_coupled(n, r, X, P, A, twin):
    if n > 3:
        return None
    Y, Q, _ = point(n, r)
    ph = Phase(n, r, 2); z = ph.join(X, P, Y, Q)
    H = lambda z: (lambda M: np.trace(M[1].T @ M[1]) / 2 + np.trace(M[3].T @ M[3]) / 2 + np.trace(M[0].T @ A @ M[2])
                   + np.trace(M[0].T @ M[1] @ M[2].T @ M[3]))(ph.split(z))
    lam = 0.613
    I = np.eye(n); Ir = np.eye(r); O = np.zeros((r, r))
    R2 = np.linalg.inv(A @ A - lam ** 2 * I)

    def L(z):
        X, P, Y, Q = ph.split(z)
        F = lambda U, V: U.T @ R2 @ V
        return np.block([[lam * F(P, X), lam * F(P, P), F(A @ P, Y), -Ir + F(A @ P, Q)],
                         [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
                         [F(A @ Q, X), -Ir + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
                         [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])
    v = ph.dirac_field(H, z)
    Ld = ph.d(L, z, v)
    S = (X.T @ A @ Y + Y.T @ A @ X) / 2
    Lam, Pi = S - P.T @ P, S - Q.T @ Q
    d1, d2 = (-(X.T @ P), -(Y.T @ Q)) if twin else (-(Y.T @ Q), -(X.T @ P))
    Am = np.block([[d1, Lam, O, -lam * Ir], [Ir, d1, O, O], [O, -lam * Ir, d2, Pi], [O, O, Ir, d2]])
    Lz = L(z)
    return mx(Ld - (Lz @ Am - Am @ Lz))


def res_double_gl(n, r, X, P, A, twin):
    Xr = rng.normal(size=(n, r)); G = Xr.T @ Xr
    Yr = Xr @ np.linalg.inv(G) + (np.eye(n) - Xr @ np.linalg.inv(G) @ Xr.T) @ rng.normal(size=(n, r))
    Xd, Yd = rng.normal(size=(n, r)), rng.normal(size=(n, r))
    R = rng.normal(size=(r, r)); Ri = np.linalg.inv(R)
    if twin:
        return mx((Xr @ R).T @ (Yr @ Ri) - np.eye(r))
    L = lambda X, Y, Xd, Yd: np.trace(Xd.T @ Yd) - np.trace(X.T @ A @ Y)
    return max(mx((Xr @ R.T).T @ (Yr @ Ri) - np.eye(r)),
               abs(L(Xr @ R.T, Yr @ Ri, Xd @ R.T, Yd @ Ri) - L(Xr, Yr, Xd, Yd)))


def res_ellipsoid(n, r, X, P, A, twin):
    if r != 1:
        return None
    C = sym(n); Aown = C @ C; y, yd = C @ X, C @ P
    if twin:
        return mx(y.T @ Aown @ y - 1)
    return max(mx(y.T @ np.linalg.inv(Aown) @ y - 1), mx(yd.T @ yd - P.T @ Aown @ P))


def res_legendre(n, r, X, P, A, twin):
    Xd = P
    Pm = Xd - (X @ X.T @ Xd if twin else X @ X.T @ Xd / 2)
    if twin:
        return mx(Psi(X, Pm) - X.T @ Xd)
    return max(mx(X.T @ Pm + Pm.T @ X), mx(Psi(X, Pm) - X.T @ Xd))


def res_hb(n, r, X, P, A, twin):
    kap = 0.29
    c = kap if twin else 0.5 + kap
    HB = np.trace(P.T @ P) / 2 - np.trace(Psi(X, P) @ (c * Psi(X, P))) / 4
    Hk = np.trace(P.T @ P) / 2 - (0.5 + kap) * np.trace(X.T @ P @ X.T @ P)
    if twin:
        return abs(HB - Hk)
    # a generic symmetric operator on so(r): B(ξ) = Σ (matrix on the skew coordinates)
    iu = np.triu_indices(r, 1); m = len(iu[0]); S = sym(m) if m else np.zeros((0, 0))

    def BB(xi):
        c = xi[iu] @ S if m else np.zeros(0)
        out = np.zeros((r, r)); out[iu] = c; return out - out.T
    ph = Phase(n, r); z = ph.join(X, P)
    Hg = lambda z: (lambda M: np.trace(M[1].T @ M[1]) / 2 - np.trace(Psi(M[0], M[1]) @ BB(Psi(M[0], M[1]))) / 4)(ph.split(z))
    v = ph.dirac_field(Hg, z)
    dPhi = ph.d(lambda z: (lambda M: Phi(M[0], M[1]))(ph.split(z)), z, v)
    return max(abs(HB - Hk), mx(dPhi))


def res_jk(n, r, X, P, A, twin):
    if r < 2:
        return None
    ph = Phase(n, r); z = ph.join(X, P)
    k0 = r // 2
    rows = [grad(lambda z, k=k: (lambda M: np.trace(np.linalg.matrix_power(Psi(M[0], M[1]), 2 * k)))(ph.split(z)), z)
            for k in range(1, r + 1)]
    sv = lambda M: np.linalg.svd(np.array(M), compute_uv=False)
    s_half, s_all = sv(rows[:k0]), sv(rows)
    rank = lambda s: int(np.sum(s > 1e-6 * s[0]))
    if twin:
        return ("rank", rank(s_all), r)
    return ("rank", (rank(s_half), rank(s_all)), (k0, k0))


def res_pneutral(n, r, X, P, A, twin):
    if r >= n:
        return None
    W = skew(r); Z = rng.normal(size=(n - r, r))
    X0 = np.eye(n)[:, :r]; P0 = np.vstack([W, Z])
    if twin:
        return mx(Psi(X0, P0) - W)
    B = cay(skew(n - r)); P0b = np.vstack([W, B @ Z])
    return max(mx(X0.T @ P0 + P0.T @ X0), mx(X0.T @ P0b + P0b.T @ X0), mx(Psi(X0, P0) - 2 * W),
               mx(Psi(X0, P0b) - Psi(X0, P0)), mx(P0b.T @ P0b - P0.T @ P0))


CHECKS = [("h71-momentum-maps-finite", "n71-psi-equivariance-transposed", res_momentum_finite),
          ("h71-dirac-bracket-printed", "n71-dirac-bracket-sign", res_dirac_printed),
          ("h71-neumann-middle-forms", "n71-ne-lambda-sign", res_neumann_middle),
          ("h71-lema1-eta-v", "n71-lema1-eta-v-sign", res_lema1),
          ("h71-dual-lax-relations", "n71-a-man-equals-l-man", res_dual_relations),
          ("h71-manakov-flows-commute", "n71-manakov-not-so-n-invariant", res_manakov),
          ("h71-ym-proof-chain", "n71-ym-chain-sign", res_ym),
          ("h71-coupled-euclidean-interacting-dual", "n71-coupled-euclid-diagonal-swapped", res_coupled),
          ("h71-double-gl-symmetry", "n71-double-gl-no-transpose", res_double_gl),
          ("h71-a-metric-ellipsoid", "n71-ellipsoid-a-not-inverse", res_ellipsoid),
          ("h71-normal-legendre-constraints", "n71-normal-legendre-factor", res_legendre),
          ("h71-hb-jensen", "n71-hb-jensen-factor", res_hb),
          ("h71-jk-independent", "n71-jk-rank-r", res_jk),
          ("h71-p-neutral", "n71-p-neutral-psi-factor", res_pneutral)]


def counts():
    for n, r in [(n, r) for n in range(1, 7) for r in range(1, n + 1)]:
        so = lambda m: m * (m - 1) // 2
        dimV = r * n - r * (r + 1) // 2
        N = sum(n - l for l in range(1, r + 1))
        two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
        ok = (so(n) - so(n - r) == dimV and N == r * (n - r) + r * (r - 1) // 2 == dimV
              and dimV - so(r) == r * (n - r))
        print(f"h71-counts ({n},{r}): {'true' if ok else 'FALSE'};  2N > 2l: {2 * N > two_l} (2N={2*N}, 2l={two_l});"
              f"  twin N = r(n-r)+r(r+1)/2: {N == r * (n - r) + r * (r + 1) // 2}")


if __name__ == "__main__":
    for true_id, twin_id, f in CHECKS:
        for cid, twin in ((true_id, False), (twin_id, True)):
            line = []
            for n, r in SIZES:
                vals = []
                for _ in range(3):
                    X, P, A = point(n, r)
                    vals.append(f(n, r, X, P, A, twin))
                if vals[0] is None:
                    continue
                if isinstance(vals[0], tuple):
                    line.append(f"({n},{r}) {vals[0][1]} vs {vals[0][2]}")
                    continue
                v = max(vals)
                line.append(f"({n},{r}) {'T' if v < 1e-6 else 'F'}{v:.0e}")
            print(cid + ": " + "  ".join(line))
    counts()
