# ruff: noqa
"""Independent numpy check of every statement of claims_s65.py and of its twin, at random points of
T*V(n, r) (X^T X = I, X^T P + P^T X = 0), A symmetric (diagonal and also a full symmetric A where the
statement allows), in float64.  No import of stiefelsym.

Prints, per claim id, the sizes checked and the largest residual (identities) or the ranks found.
"""
import itertools
import sys

import numpy as np

rng = np.random.default_rng(65)
TOL = 1e-8


def point(n, r):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    return X, P


def skew(m):
    M = rng.standard_normal((m, m)); return M - M.T


def sym(m):
    M = rng.standard_normal((m, m)); return M + M.T


def cayley(K):
    I = np.eye(len(K)); return (I - K) @ np.linalg.inv(I + K)


def so_basis(m):
    out = []
    for i in range(m):
        for j in range(i + 1, m):
            E = np.zeros((m, m)); E[i, j] = 1; E[j, i] = -1; out.append(E)
    return out


def rank(cols):
    M = np.array([np.ravel(c) for c in cols]).T
    return np.linalg.matrix_rank(M, tol=1e-9 * max(1, np.abs(M).max()))


def dso(m):
    return m * (m - 1) // 2 if m > 1 else 0


def comm(a, b):
    return a @ b - b @ a


Phi = lambda X, P: P @ X.T - X @ P.T
Psi = lambda X, P: X.T @ P - P.T @ X
kil = lambda a, b: -np.trace(a @ b) / 2

results = {}


def record(cid, size, value, kind="res"):
    results.setdefault(cid, []).append((size, value, kind))


def sizes(nmax=5, nmin=1, cond=lambda n, r: True):
    return [(n, r) for n in range(nmin, nmax + 1) for r in range(1, n + 1) if cond(n, r)]


def num_grad(f, X, P, h=1e-6):
    GX = np.zeros_like(X); GP = np.zeros_like(P)
    for idx in itertools.product(range(X.shape[0]), range(X.shape[1])):
        E = np.zeros_like(X); E[idx] = h
        GX[idx] = (f(X + E, P) - f(X - E, P)) / (2 * h)
        GP[idx] = (f(X, P + E) - f(X, P - E)) / (2 * h)
    return GX, GP


def deriv(f, X, P, dX, dP, h=1e-6):
    return (f(X + h * dX, P + h * dP) - f(X - h * dX, P - h * dP)) / (2 * h)


def sym_operator(n):
    B = so_basis(n); C = sym(len(B))
    def AA(xi):
        xi = (xi - xi.T) / 2
        coords = np.array([kil(xi, b) for b in B])
        return sum(c * b for c, b in zip(C @ coords, B)) if B else 0 * xi
    return AA


for n, r in sizes(5, 2):
    X, P = point(n, r)
    M = [np.concatenate([(xi @ X).ravel(), (xi @ P).ravel()]) for xi in so_basis(n)]
    k = rank(M)
    record("s65-ddim-stabilizer", (n, r), (k, dso(n) - (dso(n - 2 * r) if n > 2 * r else 0)), "rank")
    if n - r >= 2:
        record("s65-ddim-stabilizer-twin", (n, r), (k, dso(n) - dso(n - r)), "rank")
    Q = np.eye(n) - X @ X.T
    basis = [X @ E for E in so_basis(r)] + [Q @ np.eye(n * r)[i].reshape(n, r) for i in range(n * r)]
    k = rank([d @ X.T - X @ d.T for d in basis])
    record("s65-iso-fibre", (n, r), (k, n * r - r * (r + 1) // 2), "rank")
    record("s65-iso-fibre", (n, r), np.abs(Q @ Phi(X, P) @ Q).max())
    if n - r >= 2:
        record("s65-iso-fibre-twin", (n, r), (k, dso(n)), "rank")

for n, r in sizes(4):
    X, P = point(n, r)
    kap = rng.standard_normal()
    A = sym(n)
    Hk = lambda X, P: np.trace(P.T @ P) / 2 - (0.5 + kap) * np.trace((X.T @ P) @ (X.T @ P))
    Qr = cayley(skew(r)); R = cayley(skew(n))
    X2, P2 = R @ X @ Qr, R @ P @ Qr
    v = max(np.abs(Phi(X @ Qr, P @ Qr) - Phi(X, P)).max(), np.abs(Psi(R @ X, R @ P) - Psi(X, P)).max(),
            abs(Hk(X2, P2) - Hk(X, P)), np.abs(X2.T @ X2 - np.eye(r)).max(), np.abs(X2.T @ P2 + P2.T @ X2).max())
    record("s65-finite-invariance", (n, r), v)
    if r >= 3:
        record("s65-finite-invariance-twin", (n, r), np.abs(Psi(X @ Qr, P @ Qr) - Psi(X, P)).max())
    if n >= 2:
        AA = sym_operator(n)
        H = lambda X, P: kil(AA(Phi(X, P)), Phi(X, P)) / 2
        GX, GP = num_grad(H, X, P)
        Mm = AA(Phi(X, P))
        record("s65-submersion-gradients", (n, r), max(np.abs(GP - Mm @ X).max(), np.abs(-GX - Mm @ P).max()) * 1e-3)
        record("s65-submersion-gradients-twin", (n, r), np.abs(GX - Mm @ P).max())
        eta = skew(r); xi = skew(n)
        H0 = lambda X, P: kil(Phi(X, P), Phi(X, P)) / 2
        record("s65-submersion-symmetry", (n, r), max(abs(deriv(H, X, P, X @ eta, P @ eta)), abs(deriv(H0, X, P, xi @ X, xi @ P))) * 1e-3)
        if n >= 3:
            record("s65-submersion-symmetry-twin", (n, r), abs(deriv(H, X, P, xi @ X, xi @ P)))
    # LAMBDA
    h, v_, xi, zeta, eta, theta = skew(n), sym(n), skew(n), skew(n), sym(n), sym(n)
    x = h + v_
    L1 = kil(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))
    L2 = kil(x - A, comm(xi + eta, zeta + theta))
    record("s65-lambda-1-minus-1", (n, r), abs(L1 - L2 - (-kil(h, comm(eta, theta)) + kil(A, comm(xi, theta) + comm(eta, zeta)))))
    if n >= 2:
        record("s65-lambda-1-minus-1-twin", (n, r), abs(L1 - L2 - (kil(h, comm(eta, theta)) + kil(A, comm(xi, theta) + comm(eta, zeta)))))
    # h blocks
    F = Phi(X, P); Q = np.eye(n) - X @ X.T
    record("s65-h-blocks", (n, r), max(np.abs(X.T @ F @ X - Psi(X, P)).max(), np.abs(X.T @ F @ Q + P.T @ Q).max(), np.abs(Q @ F @ Q).max()))
    if r >= 2:
        record("s65-h-blocks-twin", (n, r), np.abs(X.T @ F @ X + Psi(X, P)).max())
    # Psi = 2 X^T P
    record("s65-psi-zero", (n, r), np.abs(Psi(X, P) - 2 * X.T @ P).max())
    if r >= 2:
        record("s65-psi-zero-twin", (n, r), np.abs(Psi(X, P) - X.T @ P).max())
    # resolvent, A diagonal and general symmetric
    lam = rng.standard_normal() + 5
    Rs = np.linalg.inv(lam * np.eye(n) - A)
    record("s65-resolvent-identity", (n, r), max(np.abs(A @ Rs - (lam * Rs - np.eye(n))).max(), np.abs(Rs @ A - (lam * Rs - np.eye(n))).max()))
    record("s65-resolvent-identity-twin", (n, r), np.abs(A @ Rs - (lam * Rs + np.eye(n))).max())

for n, r in sizes(5, 1, lambda n, r: r < n):
    m = n - r
    e1, e2, e3 = sym(r), sym(m), rng.standard_normal((r, m))
    eta = np.block([[e1, e3], [e3.T, e2]])
    v = np.zeros((n, n)); v[:r, :r] = np.eye(r)
    good = np.block([[np.zeros((r, r)), -e3], [e3.T, np.zeros((m, m))]])
    bad = np.block([[np.zeros((r, r)), e3], [-e3.T, np.zeros((m, m))]])
    record("s65-lema1-eta-v", (n, r), np.abs(comm(eta, v) - good).max())
    record("s65-lema1-eta-v-twin", (n, r), np.abs(comm(eta, v) - bad).max())


def jac_rank(n, r, count):
    X, P = point(n, r)
    def F(z):
        X = z[:n * r].reshape(n, r); P = z[n * r:].reshape(n, r)
        C1 = X.T @ X; C2 = X.T @ P + P.T @ X
        iu = np.triu_indices(r)
        S = Psi(X, P)
        return np.concatenate([C1[iu], C2[iu]] + [[np.trace(np.linalg.matrix_power(S, 2 * k))] for k in range(1, count + 1)])
    z = np.concatenate([X.ravel(), P.ravel()]); h = 1e-6
    J = np.array([(F(z + h * e) - F(z - h * e)) / (2 * h) for e in np.eye(2 * n * r)]).T
    return np.linalg.matrix_rank(J, tol=1e-6)


for n, r in sizes(4, 2, lambda n, r: r >= 2):
    record("s65-jk-independent", (n, r), (jac_rank(n, r, r // 2), r * (r + 1) + r // 2), "rank")
    if r == 2:
        record("s65-jk-independent-twin", (n, r), (jac_rank(n, r, r // 2 + 1), r * (r + 1) + r // 2 + 1), "rank")

for n, r in sizes(5, 2):
    X, P = point(n, r)
    v = X @ X.T
    k = rank([comm(xi, v) for xi in so_basis(n)])
    record("s65-grassmannian-dimension", (n, r), (k, r * (n - r)), "rank")
    if r >= 2:
        record("s65-grassmannian-dimension-twin", (n, r), (k, n * r - r * (r + 1) // 2), "rank")
    N = sum(n - k for k in range(1, r + 1))
    k2 = rank([xi @ X for xi in so_basis(n)])
    record("s65-dual-count", (n, r), (k2, N), "rank")
    record("s65-dual-count", (n, r), (N, r * (n - r) + r * (r - 1) // 2), "rank")
    record("s65-dual-count-twin", (n, r), (N, r * (n - r) + r * (r + 1) // 2), "rank")

for n in range(2, 6):
    X, P = point(n, 1)
    e, ed = X, P
    A = np.diag(rng.standard_normal(n))
    pr = lambda xi: xi @ e @ e.T + e @ e.T @ xi
    perp = lambda m: m - pr(m)
    xi, zeta = skew(n), skew(n)
    v = max(np.abs(pr(pr(xi)) - pr(xi)).max(), np.abs(pr(xi) - ((xi @ e) @ e.T - e @ (xi @ e).T)).max(),
            np.abs(perp(xi) @ e).max(), abs(np.trace(pr(xi) @ perp(zeta))))
    record("s65-od-projection", (n, 1), v)
    B = so_basis(n)
    record("s65-od-projection", (n, 1), (rank([pr(b) for b in B]), n - 1), "rank")
    if n >= 3:
        record("s65-od-projection", (n, 1), (rank([perp(b) for b in B]), dso(n - 1)), "rank")
    record("s65-od-projection-twin", (n, 1), (rank([pr(b) for b in B]), n), "rank")
    lhs = (A @ e @ e.T - e @ e.T @ A) @ e + (ed @ e.T - e @ ed.T) @ ed
    record("s65-ym-proof-line", (n, 1), np.abs(lhs - (A @ e - e @ (e.T @ A @ e + ed.T @ ed))).max())
    record("s65-ym-proof-line-twin", (n, 1), np.abs(lhs - (A @ e - e @ (e.T @ A @ e - ed.T @ ed))).max())


# coupled flows: Dirac flow on T*V x T*V by solving for the multipliers numerically
def pair_flow(H, z, n, r):
    X, P, Y, Q = z
    def f(v):
        X, P, Y, Q = [v[i * n * r:(i + 1) * n * r].reshape(n, r) for i in range(4)]
        return H(X, P, Y, Q)
    v0 = np.concatenate([m.ravel() for m in z]); h = 1e-6
    g = np.array([(f(v0 + h * e) - f(v0 - h * e)) / (2 * h) for e in np.eye(len(v0))])
    HX, HP, HY, HQ = [g[i * n * r:(i + 1) * n * r].reshape(n, r) for i in range(4)]
    # unknowns: symmetric Lam1, Pi1, Lam2, Pi2: xdot = Hp - xPi, pdot = -Hx + xLam + pPi
    iu = np.triu_indices(r); m = len(iu[0])
    def symm(c):
        S = np.zeros((r, r)); S[iu] = c; return S + S.T - np.diag(np.diag(S))
    def flow(c):
        L1, P1, L2, P2 = [symm(c[i * m:(i + 1) * m]) for i in range(4)]
        return (HP - X @ P1, -HX + X @ L1 + P @ P1, HQ - Y @ P2, -HY + Y @ L2 + Q @ P2)
    def cons(c):
        Xd, Pd, Yd, Qd = flow(c)
        out = []
        for (x, p, xd, pd) in ((X, P, Xd, Pd), (Y, Q, Yd, Qd)):
            out += [(xd.T @ x + x.T @ xd)[iu], (xd.T @ p + x.T @ pd + pd.T @ x + p.T @ xd)[iu]]
        return np.concatenate(out)
    c0 = np.zeros(4 * m); b = cons(c0)
    Jm = np.array([cons(e) - b for e in np.eye(4 * m)]).T
    c = np.linalg.solve(Jm, -b)
    return flow(c)


def coupled(kap, A):
    def H(X, P, Y, Q):
        c = 0.5 + kap
        return (np.trace(P.T @ P) / 2 - c * np.trace((X.T @ P) @ (X.T @ P)) + np.trace(Q.T @ Q) / 2
                - c * np.trace((Y.T @ Q) @ (Y.T @ Q)) + np.trace(X.T @ A @ Y))
    return H


for n, r in [(2, 1), (3, 1), (4, 1), (2, 2), (3, 2), (4, 2)]:
    X, P = point(n, r); Y, Q = point(n, r)
    A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
    fk = pair_flow(coupled(kap, A), (X, P, Y, Q), n, r)
    f0 = pair_flow(coupled(0.0, A), (X, P, Y, Q), n, r)
    d = max(np.abs(a - b).max() for a, b in zip(fk, f0))
    record("s65-coupled-r1" if r == 1 else "s65-coupled-r1-twin", (n, r), d * (1e-3 if r == 1 else 1))



# Section 5: Dirac flows of H_neum,kappa for two kappa (numerical gradient, multipliers solved numerically)
def single_flow(H, X, P, n, r):
    Y, Q = point(n, r)
    H2 = lambda X, P, Y, Q: H(X, P)
    f = pair_flow(H2, (X, P, Y, Q), n, r)
    return f[0], f[1]


def H_neum(kap, A):
    return lambda X, P: (np.trace(P.T @ P) / 2 - (0.5 + kap) * np.trace((X.T @ P) @ (X.T @ P))
                         + np.trace(X.T @ A @ X) / 2)


for n, r in sizes(4):
    X, P = point(n, r)
    A = np.diag(rng.standard_normal(n)); kap = rng.standard_normal()
    fk = single_flow(H_neum(kap, A), X, P, n, r)
    f0 = single_flow(H_neum(0.0, A), X, P, n, r)
    d = max(np.abs(a - b).max() for a, b in zip(fk, f0))
    # "not" claims: the statement holds when the difference is nonzero
    if r >= 2:
        record("s65-kappa-flows-differ", (n, r), 0.0 if d > 1e-4 else 1.0)
    else:
        record("s65-kappa-flows-differ-twin", (n, r), 0.0 if d > 1e-4 else 1.0)

# report
bad = 0
for cid in sorted(results):
    twin = cid.endswith("-twin")
    verdicts = []
    for size, val, kind in results[cid]:
        if kind == "rank":
            holds = val[0] == val[1]
        else:
            holds = val < TOL
        verdicts.append(holds)
    holds_all, holds_none = all(verdicts), not any(verdicts)
    status = ("holds at every size" if holds_all else "fails at every size" if holds_none else "MIXED")
    expect = "fails at every size" if twin else "holds at every size"
    ok = status == expect
    bad += not ok
    print(f"{cid:36s} {status:22s} {'ok' if ok else 'UNEXPECTED'}  sizes={sorted({s for s, _, _ in results[cid]})}")
    for size, val, kind in results[cid]:
        if not ok or "-v" in sys.argv:
            print("   ", size, val)
print("numpy disagreements with the intended truth value:", bad)
