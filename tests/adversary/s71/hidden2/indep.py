# ruff: noqa
"""Independent numpy truth for claims.py and negatives.py (imports nothing of stiefelsym).

Random points of T*V (XᵀX = I, XᵀP + PᵀX = 0; for the metric realization XᵀA⁻¹P + PᵀA⁻¹X = 0), A = diag(a)
distinct (positive for the metric realization), gradients by central differences, Dirac flows from scratch
({F_i, F_j}_0 solved).  Prints per claim and size T/F and the largest |residual| over 3 points (T: < 1e-6),
and for the ranks and counts the computed against the claimed values."""
import numpy as np

rng = np.random.default_rng(712)
import sys
SIZES = [(6, 3), (7, 2), (6, 2)] if "--big" in sys.argv else [(n, r) for n in range(1, 6) for r in range(1, n + 1)]


def skew(m):
    M = rng.normal(size=(m, m)); return M - M.T


def sym(m):
    M = rng.normal(size=(m, m)); return M + M.T


def cay(M):
    I = np.eye(len(M)); return (I - M) @ np.linalg.inv(I + M)


_flip = [0]


def point(n, r, metric=False):
    """at r = n the two components of O(n) alternate (det X = +1, −1, +1, …)."""
    X = np.linalg.qr(rng.normal(size=(n, n)))[0][:, :r]
    if r == n:
        _flip[0] += 1
        if np.linalg.det(X) * (-1) ** _flip[0] < 0:
            X = X @ np.diag([-1] + [1] * (r - 1))
    W = skew(r)
    Z = rng.normal(size=(n, r))
    a = np.sort(rng.uniform(0.5, 2, size=n)) + np.arange(n)
    A = np.diag(a)
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    if metric:
        P = A @ P                      # XᵀA⁻¹P = W skew
    return X, P, A


def mx(x):
    return float(np.max(np.abs(x))) if np.size(x) else 0.0


kil = lambda a, b: -0.5 * np.trace(a @ b)
comm = lambda a, b: a @ b - b @ a
Phi = lambda X, P: P @ X.T - X @ P.T
Psi = lambda X, P: X.T @ P - P.T @ X
sk = lambda M: (M - M.T) / 2
sy = lambda M: (M + M.T) / 2


def L1(x, a, b):
    xi, eta, ze, th = sk(a), sy(a), sk(b), sy(b)
    return kil(x, comm(xi, ze) + comm(xi, th) + comm(eta, ze))


def L2(x, A, a, b):
    return kil(x - A, comm(a, b))


def grad(f, z, h=1e-5):
    g = np.zeros_like(z)
    for i in range(len(z)):
        e = np.zeros_like(z); e[i] = h
        g[i] = (f(z + e) - f(z - e)) / (2 * h)
    return g


def split(z, n, r):
    return z[:n * r].reshape(n, r), z[n * r:].reshape(n, r)


def join(X, P):
    return np.concatenate([X.ravel(), P.ravel()])


def dirac_field(H, X, P, A, metric=False):
    n, r = X.shape
    Ai = np.linalg.inv(A)
    def cons(z):
        Xz, Pz = split(z, n, r)
        C2 = Xz.T @ (Ai if metric else np.eye(n)) @ Pz
        C2 = C2 + C2.T
        C1 = Xz.T @ Xz
        return [C1[i, j] for i in range(r) for j in range(i, r)] + [C2[i, j] for i in range(r) for j in range(i, r)]
    z = join(X, P)
    m = n * r
    Jv = lambda g: np.concatenate([g[m:], -g[:m]])
    k = r * (r + 1)
    G = [grad(lambda w, i=i: cons(w)[i], z) for i in range(k)]
    gH = grad(lambda w: H(*split(w, n, r)), z)
    C = np.array([[Gi @ Jv(Gj) for Gj in G] for Gi in G])
    b = np.array([Gj @ Jv(gH) for Gj in G])
    w = np.linalg.solve(C, b)
    v = Jv(gH)
    for wi, Gi in zip(w, G):
        v = v - wi * Jv(Gi)
    return split(v, n, r)


def blocks(n, r):
    P1, P2 = skew(r), rng.normal(size=(n - r, r))
    X0 = np.eye(n)[:, :r]
    return P1, P2, X0, np.vstack([P1, P2])


def dg(a, b):
    n1, n2 = len(a), len(b)
    M = np.zeros((n1 + n2, n1 + n2)); M[:n1, :n1] = a; M[n1:, n1:] = b; return M


def so_basis(m):
    out = []
    for i in range(m):
        for j in range(i + 1, m):
            E = np.zeros((m, m)); E[i, j] = 1; E[j, i] = -1; out.append(E)
    return out


dso = lambda m: m * (m - 1) // 2 if m > 1 else 0

# ---------------------------------------------------------------------------------------------------------

def r_h_blocks(n, r, X, P, A, twin):
    if r == n: return None
    P1, P2, X0, P0 = blocks(n, r)
    h1, h2 = 2 * P1, -P2.T
    h = np.block([[h1, -h2 if twin else h2], [h2.T if twin else -h2.T, np.zeros((n - r, n - r))]])
    if twin: return mx(Phi(X0, P0) - h)
    g = dg(np.zeros((r, r)), skew(n - r))
    return max(mx(Phi(X0, P0) - h), mx(Psi(X0, P0) - h1), abs(kil(h, g)), mx(X0.T @ P0 + P0.T @ X0))


def r_iso(n, r, X, P, A, twin):
    if r == n: return None
    P1, P2, X0, P0 = blocks(n, r)
    B = cay(skew(n - r)); Bh = dg(np.eye(r), B)
    P0b = np.vstack([P1, B @ P2])
    if twin: return mx(Phi(X0, P0b) - Bh.T @ Phi(X0, P0) @ Bh)
    return max(mx(Phi(X0, P0b) - Bh @ Phi(X0, P0) @ Bh.T), mx(Bh @ X0 - X0))


def r_so_r(n, r, X, P, A, twin):
    if r == n: return None
    P1, P2, X0, P0 = blocks(n, r)
    Q = cay(skew(r)); R = dg(Q.T, np.eye(n - r)); k = rng.normal()
    Hk = lambda X, P: np.trace(P.T @ P) / 2 - (0.5 + k) * np.trace(X.T @ P @ X.T @ P)
    if twin == "order": return mx(R @ P0 @ Q - np.vstack([Q @ P1 @ np.linalg.inv(Q), P2 @ Q]))
    if twin == "factor": return abs(Hk(X0, P0) - (np.trace(P2.T @ P2) / 2 - (0.5 + k) * np.trace(P1 @ P1)))
    return max(mx(R @ X0 @ Q - X0), mx(R @ P0 @ Q - np.vstack([np.linalg.inv(Q) @ P1 @ Q, P2 @ Q])),
               abs(Hk(X0, P0) - (np.trace(P2.T @ P2) / 2 - (1 + k) * np.trace(P1 @ P1))),
               abs(Hk(X0, R @ P0 @ Q) - Hk(X0, P0)))


def r_ddim(n, r, X, P, A, twin):
    m = n - r
    if m < 2: return None
    P2 = rng.normal(size=(m, r))
    M = np.array([(b @ P2).ravel() for b in so_basis(m)]).T
    rk = np.linalg.matrix_rank(M)
    if twin: return ("rank", rk, dso(m))
    want = dso(m) - (dso(n - 2 * r) if n > 2 * r else 0)
    out = [rk == want]
    if n > 2 * r:
        E = np.eye(m)[:, :r]
        out.append(np.linalg.matrix_rank(np.array([(b @ E).ravel() for b in so_basis(m)]).T) == want)
    return ("rank", rk, want if all(out) else -1)


def r_lema1(n, r, X, P, A, twin):
    if r == n: return None
    P1, P2, X0, P0 = blocks(n, r)
    h = Phi(X0, P0); h1, h2 = 2 * P1, -P2.T; v = X0 @ X0.T
    xi1 = h1 @ h1 @ h1; xi2 = skew(n - r)
    eta3 = (h2 @ xi2 - xi1 @ h2) if twin else (xi1 @ h2 - h2 @ xi2)
    xi = dg(xi1, xi2); eta = np.block([[sym(r), eta3], [eta3.T, sym(n - r)]])
    Z = np.zeros((n - r, n - r))
    H2 = np.block([[np.zeros((r, r)), h2], [-h2.T, Z]]); E3 = np.block([[np.zeros((r, r)), -eta3], [eta3.T, Z]])
    if twin: return mx(comm(xi, H2) + E3)
    return max(mx(comm(xi, H2) + E3), mx(comm(eta, v) - E3), mx(comm(xi, v)), mx(comm(xi, h) + comm(eta, v)),
               abs(L1(h + v, xi + eta, skew(n) + sym(n))))


def r_lambda(n, r, X, P, A, twin):
    h, v = Phi(X, P), X @ X.T
    xi, ze, eta, th = skew(n), skew(n), sym(n), sym(n)
    L = L1(h + v, xi + eta, ze + th) - L2(h + v, A, xi + eta, ze + th)
    pr = (1 if twin else -1) * kil(h, comm(eta, th)) + kil(A, comm(xi, th) + comm(eta, ze))
    if twin: return abs(L - pr)
    return max(abs(L - pr), abs(kil(xi, xi) - np.trace(xi.T @ xi) / 2), abs(kil(eta, eta) + np.trace(eta.T @ eta) / 2),
               abs(kil(xi, eta)))


def r_l3l4(n, r, X, P, A, twin):
    h, v = Phi(X, P), X @ X.T
    a = np.diag(A); eta = np.diag(rng.normal(size=n)); C = comm(eta, h)
    xi = np.array([[C[i, j] / ((a[i] - a[j]) if twin else (a[j] - a[i])) if i != j else 0 for j in range(n)]
                   for i in range(n)])
    if twin: return mx(comm(xi, A) - comm(eta, h))
    L = L1(h + v, xi + eta, skew(n) + sym(n)) - L2(h + v, A, xi + eta, skew(n) + sym(n))
    ze, th = skew(n), sym(n)
    L = L1(h + v, xi + eta, ze + th) - L2(h + v, A, xi + eta, ze + th)
    return max(mx(xi + xi.T), mx(comm(eta, A)), mx(comm(xi, A) - comm(eta, h)), abs(L))


def sym_operator(n):
    B = so_basis(n); k = len(B); S = rng.normal(size=(k, k)); S = S + S.T
    def op(M):
        Ms = sk(M); c = np.array([kil(Ms, b) * 2 for b in B])   # coordinates (kil(b,b) = 1/2·2)
        return sum(((S @ c)[i]) * B[i] for i in range(k)) if k else np.zeros((n, n))
    return op


def ambient_grads(H, X, P):
    n, r = X.shape
    g = grad(lambda w: H(*split(w, n, r)), join(X, P))
    return split(g, n, r)


def r_submersion(n, r, X, P, A, twin):
    op = sym_operator(n)
    H = lambda X, P: -np.trace(op(Phi(X, P)) @ Phi(X, P)) / 4
    HX, HP = ambient_grads(H, X, P)
    w = op(Phi(X, P))
    if twin: return mx(-HX + w @ P)
    return max(mx(HP - w @ X), mx(-HX - w @ P))


def r_neumann_grad(n, r, X, P, A, twin):
    k = rng.normal()
    H = lambda X, P: np.trace(P.T @ P) / 2 - (0.5 + k) * np.trace(X.T @ P @ X.T @ P) + np.trace(X.T @ A @ X) / 2
    HX, HP = ambient_grads(H, X, P)
    c = (1 + k) if twin else (1 + 2 * k)
    return max(mx(HP - (P - c * X @ P.T @ X)), mx(-HX - (-A @ X + c * P @ X.T @ P)))


def r_cp(n, r, X, P, A, twin):
    if r != n: return None
    H = lambda X, P: np.trace(P.T @ P) / 2 - np.trace(X.T @ P @ X.T @ P) / 2
    Xd, _ = dirac_field(H, X, P, A)
    M = Phi(X, P)
    if twin: return mx(X.T @ Xd + X.T @ M @ X)
    return max(mx(Xd @ X.T - M), mx(X.T @ Xd - X.T @ M @ X), mx(Xd - M @ X))


def r_vv(n, r, X, P, A, twin):
    out = []
    for I in ([*range(r)], [*range(n - r, n)]):
        V = np.block([[X[I], P[I]], [np.zeros((r, r)), np.eye(r)]])
        out.append(abs(np.linalg.det(V) - np.linalg.det((P if twin else X)[I])))
        if twin: return out[0]
    Vm = np.block([[X, P], [np.zeros((r, r)), np.eye(r)]]); c = np.concatenate([np.zeros(r), np.ones(r)])
    out.append(mx(Vm @ c - np.concatenate([P.sum(axis=1), np.ones(r)])))
    return max(out)


def r_a_metric(n, r, X, P, A, twin):
    X, P, A = point(n, r, metric=True)
    Ai = np.linalg.inv(A)
    H = lambda X, P: np.trace(P.T @ Ai @ P) / 2
    Xd, Pd = dirac_field(H, X, P, A, metric=True)
    if twin: return mx(Pd @ X.T + P @ Xd.T - Xd @ P.T - X @ Pd.T)
    Lam = X.T @ Pd
    return max(mx(Xd.T @ P + X.T @ Pd - Pd.T @ X - P.T @ Xd), mx(Xd.T @ P + X.T @ Pd - (P.T @ Ai @ P + Lam)))


def r_psi(n, r, X, P, A, twin):
    if twin: return mx(Psi(X, P) - X.T @ P)
    k = rng.normal()
    return max(mx(Psi(X, P) - 2 * X.T @ P), mx(Psi(X, P) + 2 * P.T @ X),
               abs(-k * np.trace(X.T @ P @ X.T @ P) + k * np.trace(Psi(X, P) @ Psi(X, P)) / 4))


CHECKS = [("h71b-lema1-h-blocks", "n71b-lema1-h2-sign", r_h_blocks, True),
          ("h71b-iso-adjoint", "n71b-iso-adjoint-transposed", r_iso, True),
          ("h71b-so-r-at-x0", "n71b-so-r-conjugation-order", r_so_r, "order"),
          (None, "n71b-so-r-h-kappa-factor", r_so_r, "factor"),
          ("h71b-ddim-isotropy", "n71b-ddim-isotropy-trivial", r_ddim, True),
          ("h71b-lema1-kernel-blocks", "n71b-lema1-eta3-sign", r_lema1, True),
          ("h71b-lambda-1m1", "n71b-lambda-sign", r_lambda, True),
          ("h71b-l3-l4-coordinates", "n71b-l4-denominator", r_l3l4, True),
          ("h71b-submersion-chain-rule", "n71b-submersion-gradient-sign", r_submersion, True),
          ("h71b-neumann-proof-gradients", "n71b-neumann-gradient-factor", r_neumann_grad, True),
          ("h71b-cp-frames", "n71b-cp-body-is-space", r_cp, True),
          ("h71b-vv-minors-with-identity", "n71b-vv-minor-p", r_vv, True),
          ("h71b-a-metric-psi-conserved", "n71b-a-metric-phi-conserved", r_a_metric, True),
          ("h71b-psi-zero-iff", "n71b-psi-is-xtp", r_psi, True)]


def counts():
    sym_ = lambda m: m * (m + 1) // 2
    for n, r in [(n, r) for n in range(1, 8) for r in range(1, n + 1)]:
        ok = (dso(r) + dso(n - r) + sym_(r) + sym_(n - r) == r * r + (n - r) ** 2
              and (n * n - r * r - (n - r) ** 2) == 2 * r * (n - r) and r * n - r * (r + 1) // 2 - dso(r) == r * (n - r))
        twin = r // 2 + dso(n - r) + sym_(r) + sym_(n - r) == r * r + (n - r) ** 2
        print(f"h71b-neumann2-counts ({n},{r}): {'T' if ok else 'F'};  n71b-neumann2-rank-so-r: {'T' if twin else 'F'}")


if __name__ == "__main__":
    for true_id, twin_id, f, twin_kind in CHECKS:
        for cid, twin in ((true_id, False), (twin_id, twin_kind)):
            if cid is None:
                continue
            line = []
            for n, r in SIZES:
                vals = [f(n, r, *point(n, r), twin) for _ in range(3)]
                if vals[0] is None:
                    continue
                if isinstance(vals[0], tuple):
                    ok = all(v[1] == v[2] for v in vals)
                    line.append(f"({n},{r}) {'T' if ok else 'F'}[{vals[0][1]} vs {vals[0][2]}]")
                    continue
                v = max(vals)
                line.append(f"({n},{r}) {'T' if v < 1e-6 else 'F'}{v:.0e}")
            print(cid + ": " + "  ".join(line))
    if "--big" not in sys.argv:
        counts()
