# ruff: noqa: E701, E702, E731, E741
"""Independent numpy truth for sec8_claims.py and adv_claims.py (no stiefelsym import).
Random points of T*V(n, r): X orthonormal columns via QR, P = X K + (I - X Xᵀ) G with K skew."""
import itertools
import numpy as np
rng = np.random.default_rng(7)

def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    K = rng.standard_normal((r, r)); K = K - K.T
    P = X @ K + (np.eye(n) - X @ X.T) @ rng.standard_normal((n, r))
    return X, P

def Ld(X, P, A, lam):
    n, r = X.shape; R = np.linalg.inv(lam * np.eye(n) - A)
    return np.block([[-X.T @ R @ P, -X.T @ R @ X], [np.eye(r) + P.T @ R @ P, P.T @ R @ X]])

def flow(X, P, A, H):
    # Dirac flow on T*V via numeric projection: use formula for Euclidean and normal Neumann
    n, r = X.shape
    if H == "euc":   # H = ½trPᵀP + ½trXᵀAX: Ẋ = P, Ṗ = -AX + XΛ, Λ = XᵀAX - PᵀP (Λ sym)
        return P, -A @ X + X @ (X.T @ A @ X - P.T @ P)
    # normal: H = ½<Φ,Φ> + ½trXᵀAX; Ẋ = ΦX = P - X PᵀX ... use numeric Dirac via finite diffs of constrained gradients
    raise NotImplementedError

def deriv(f, X, P, Xd, Pd, h=1e-6):
    return (f(X + h * Xd, P + h * Pd) - f(X - h * Xd, P - h * Pd)) / (2 * h)

res = {}
def rec(name, n, r, val):
    res.setdefault(name, {})[(n, r)] = abs(val)

for n in range(1, 6):
    for r in range(1, n + 1):
        X, P = point(n, r)
        a = rng.standard_normal(n); A = np.diag(a)
        lam, mu = 0.37 + 3.1, -1.9
        R = np.linalg.inv(lam * np.eye(n) - A); Rm = np.linalg.inv(mu * np.eye(n) - A)
        L = Ld(X, P, A, lam); Z = np.zeros((r, r)); I = np.eye(r)
        N = np.block([[Z, Z], [I, Z]]); J = np.block([[Z, I], [-I, Z]])
        lt = lambda s: np.vstack([s * X.T, P.T]); rt = np.hstack([P, X])
        Phi = P @ X.T - X @ P.T; K = X.T @ P
        rec("factor", n, r, np.abs(L - N - lt(-1) @ R @ rt).max())
        rec("factor-twin", n, r, np.abs(L - N - lt(1) @ R @ rt).max())
        for sg, nm in ((-1, "lambda-expansion"), (1, "lambda-expansion-twin")):
            M1 = np.block([[sg * K, -I], [P.T @ P, P.T @ X]])
            rec(nm, n, r, np.abs(lam * (L - N) - M1 - lt(-1) @ A @ R @ rt).max())
        f = lambda X_, P_, sg=-1: np.trace(Phi_(X_, P_) @ R @ Phi_(X_, P_) @ R) + sg * 2 * np.trace(X_.T @ R @ X_)
        Phi_ = lambda X_, P_: P_ @ X_.T - X_ @ P_.T
        rec("trace-square", n, r, np.trace(L @ L) - f(X, P))
        rec("trace-square-twin", n, r, np.trace(L @ L) - f(X, P, 1))
        if r == 1:
            x, p = X[:, 0], P[:, 0]
            d1 = (x @ R @ x) * (1 + p @ R @ p) - (x @ R @ p) ** 2
            rec("det-r1", n, r, max(abs(np.linalg.det(L) - d1), abs(np.linalg.det(L) + np.trace(L @ L) / 2)))
            rec("det-r1-twin", n, r, np.linalg.det(L) - ((x @ R @ x) * (1 + p @ R @ p) + (x @ R @ p) ** 2))
            V = np.block([[X, P], [np.zeros((1, 1)), np.eye(1)]]); B = np.block([[R, np.zeros((n, 1))], [np.zeros((1, n)), np.eye(1)]])
            M = V.T @ B @ V; adj = np.array([[M[1, 1], -M[0, 1]], [-M[1, 0], M[0, 0]]])
            w = V @ adj @ np.array([1.0, 0]); dM = np.linalg.det(M)
            rec("tangent-vector-r1", n, r, max(np.abs(V.T @ B @ w - dM * np.array([1, 0])).max(), abs(w @ B @ w - dM * adj[0, 0])))
            rec("tangent-vector-r1-twin", n, r, np.abs(V.T @ B @ w - dM * np.array([0, 1])).max())
            F = [x[i] ** 2 + sum((x[i] * p[j] - x[j] * p[i]) ** 2 / (a[i] - a[j]) for j in range(n) if j != i) for i in range(n)]
            rec("uhlenbeck-sums", n, r, max(abs(sum(F) - 1), abs(sum(a[i] * F[i] for i in range(n)) - (x @ A @ x + p @ p))))
            rec("uhlenbeck-sums-twin", n, r, sum(a[i] * F[i] for i in range(n)) - (x @ A @ x + p @ p / 2))
        if 2 * r <= n:
            e2r = sum(np.linalg.det(Phi[np.ix_(I_, I_)]) for I_ in itertools.combinations(range(n), 2 * r))
            rec("cauchy-binet", n, r, e2r - np.linalg.det(P.T @ P + K @ K))
            rec("cauchy-binet-twin", n, r, e2r - np.linalg.det(P.T @ P - K @ K))
        rec("symplectic", n, r, np.abs(L.T @ J + J @ L).max())
        rec("symplectic-twin", n, r, np.abs(L.T @ J - J @ L).max())
        Xd, Pd = flow(X, P, A, "euc")
        rec("trace-conserved(NE)", n, r, deriv(lambda a_, b_: f(a_, b_), X, P, Xd, Pd))
        rec("trace-conserved-twin", n, r, deriv(lambda a_, b_: f(a_, b_, 1), X, P, Xd, Pd))
        Lm = Ld(X, P, A, mu)
        rec("resolvent", n, r, np.abs(L - Lm - (mu - lam) * lt(-1) @ R @ Rm @ rt).max())
        rec("resolvent-twin", n, r, np.abs(L - Lm - (lam - mu) * lt(-1) @ R @ Rm @ rt).max())
        rec("rank-C", n, r, np.linalg.matrix_rank(L - N) - min(n, 2 * r))
        V = np.block([[X, P], [np.zeros((r, r)), np.eye(r)]])
        rec("rank-V", n, r, np.linalg.matrix_rank(V) - 2 * r)
        eta = rng.standard_normal((r, r)); eta = eta - eta.T
        Q = (I - eta) @ np.linalg.inv(I + eta)
        Vq = np.block([[X @ Q, P @ Q], [np.zeros((r, r)), np.eye(r)]])
        lhs = Vq @ np.block([[Q.T, Z], [Z, Q.T]])
        rec("rotation", n, r, np.abs(lhs - np.block([[np.eye(n), np.zeros((n, r))], [np.zeros((r, n)), Q.T]]) @ V).max())
        rec("rotation-twin", n, r, np.abs(lhs - np.block([[np.eye(n), np.zeros((n, r))], [np.zeros((r, n)), Q]]) @ V).max())
        Bl = np.block([[R, np.zeros((n, r))], [np.zeros((r, n)), np.eye(r)]])
        rec("rotation-det", n, r, np.linalg.det(Vq.T @ Bl @ Vq) - np.linalg.det(V.T @ Bl @ V))
        # 2r-integrals sanity: a(λ) det L* = I_2r, and det L* = det(VᵀBV)
        rec("detL=detM", n, r, np.linalg.det(L) - np.linalg.det(V.T @ Bl @ V))
        # not-conserved check: tr(L(λ)L(μ)) along NE flow
        g = lambda X_, P_: np.trace(Ld(X_, P_, A, lam) @ Ld(X_, P_, A, mu))
        rec("tr L(l)L(m) conserved?", n, r, deriv(g, X, P, Xd, Pd))

for k, v in res.items():
    print(f"{k:28s}", " ".join(f"{n},{r}:{x:.1e}" for (n, r), x in sorted(v.items())))
