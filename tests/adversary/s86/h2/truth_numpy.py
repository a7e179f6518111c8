# ruff: noqa: E702, M
"""Independent truth for /tmp/s86h2/out/claims.py: numpy only (no stiefelsym).

Dirac flows are computed from scratch: ambient Poisson tensor (canonical, or twisted by ε de1∧de2 at r = 2),
constraint gradients and Hamiltonian gradients by complex-step differentiation, Π_D = Π − ΠGᵀ(GΠGᵀ)⁻¹GΠ.
The double system is solved from its Lagrangian (KKT system of the Euler–Lagrange equations with multipliers).
Derivatives of derived quantities along flows: central differences (h = 1e-5).
Prints, per claim and size, the max |residual| relative to the scale of the terms; TRUE should be ~1e-8 or less,
FALSE ~1e-1 or more."""
import sys
import numpy as np

SIZES = [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3), (4, 2), (5, 2), (5, 5), (6, 3)]


def skew(M):
    return M - M.T


def killing(a, b):
    return -0.5 * np.trace(a @ b)


def comm(a, b):
    return a @ b - b @ a


class Ctx:
    def __init__(self, n, r, rng, metric=False):
        self.n, self.r, self.rng = n, r, rng
        self.a = rng.uniform(0.5, 3.0, n)
        self.A = np.diag(self.a)
        X, _ = np.linalg.qr(rng.standard_normal((n, r)))
        W = skew(rng.standard_normal((r, r)))
        Z = rng.standard_normal((n, r))
        V = X @ W + (np.eye(n) - X @ X.T) @ Z
        self.X = X
        self.P = self.A @ V if metric else V
        self.metric = metric

    def point(self):
        return self.X.copy(), self.P.copy()


def vec(*Ms):
    return np.concatenate([M.ravel() for M in Ms])


def unvec(z, shapes):
    out, k = [], 0
    for sh in shapes:
        m = sh[0] * sh[1]
        out.append(z[k:k + m].reshape(sh))
        k += m
    return out


def cgrad(f, z):
    """Gradient of a real-analytic scalar function by complex step."""
    h = 1e-30
    g = np.zeros(len(z))
    for i in range(len(z)):
        zz = z.astype(complex)
        zz[i] += 1j * h
        g[i] = np.imag(f(zz)) / h
    return g


def cjac(f, z):
    h = 1e-30
    cols = []
    for i in range(len(z)):
        zz = z.astype(complex)
        zz[i] += 1j * h
        cols.append(np.imag(f(zz)) / h)
    return np.array(cols).T


def upper(M):
    i, j = np.triu_indices(M.shape[0])
    return M[i, j]


def dirac_flow(H, z, shapes, constraints, Pi):
    G = cjac(constraints, z)
    gH = cgrad(H, z)
    C = G @ Pi @ G.T
    PiD = Pi - Pi @ G.T @ np.linalg.solve(C, G @ Pi)
    return PiD @ gH


def canonical_pi(shapes_pairs, n, r, eps=0.0):
    """Π for pairs (x, p) of n×r blocks in the order x1, p1, x2, p2, ...; ε: the twisted form at r = 2."""
    m = n * r
    k = len(shapes_pairs)
    Pi = np.zeros((2 * m * k, 2 * m * k))
    for j in range(k):
        x0, p0 = 2 * m * j, 2 * m * j + m
        Pi[x0:x0 + m, p0:p0 + m] = np.eye(m)
        Pi[p0:p0 + m, x0:x0 + m] = -np.eye(m)
    if eps:
        # ṗ gets + ε H_P Jt, Jt = [[0, -1], [1, 0]]  (ṗ1 = ... + ε p2, ṗ2 = ... − ε p1 as (mag-euk))
        Jt = np.array([[0.0, -1.0], [1.0, 0.0]])
        B = np.zeros((m, m))
        for i in range(m):
            E = np.zeros(m); E[i] = 1
            B[:, i] = (E.reshape(n, r) @ Jt).ravel()
        Pi[m:2 * m, m:2 * m] = eps * B
    return Pi


def stiefel_constraints(n, r, k=1, metric_Ainv=None):
    def F(z):
        out = []
        Ms = unvec(z, [(n, r)] * (2 * k))
        for j in range(k):
            X, P = Ms[2 * j], Ms[2 * j + 1]
            out.append(upper(X.T @ X - np.eye(r)))
            if metric_Ainv is None:
                out.append(upper(X.T @ P + P.T @ X))
            else:
                out.append(upper(X.T @ metric_Ainv @ P + P.T @ metric_Ainv @ X))
        return np.concatenate(out)
    return F


def flow_XP(ctx, H, X, P, eps=0.0, metric=False):
    n, r = ctx.n, ctx.r
    z = vec(X, P)
    Hz = lambda zz: H(*unvec(zz, [(n, r), (n, r)]))
    F = stiefel_constraints(n, r, 1, np.diag(1 / ctx.a) if metric else None)
    v = dirac_flow(Hz, z, None, F, canonical_pi([0], n, r, eps))
    return unvec(v, [(n, r), (n, r)])


def rel(res, *terms):
    scale = max([1.0] + [np.max(np.abs(t)) for t in terms if np.size(t)])
    return float(np.max(np.abs(res))) / scale if np.size(res) else 0.0


def Phi_(X, P):
    return P @ X.T - X @ P.T


def Psi_(X, P):
    return X.T @ P - P.T @ X


# ---------------------------------------------------------------- §3
def jensen(ctx, kap):
    def H(X, P):
        return killing(Phi_(X, P), Phi_(X, P)) / 2 + kap * killing(Psi_(X, P), Psi_(X, P)) / 2
    return H


def t_jensen(ctx):
    kap = ctx.rng.uniform(-1, 1)
    X, P = ctx.point()
    H = jensen(ctx, kap)
    Xd, Pd = flow_XP(ctx, H, X, P)
    Phi, Psi = Phi_(X, P), Psi_(X, P)
    out = {}
    out["s86h2-jensen-pdot"] = rel(Pd - (Phi @ P + kap * P @ Psi), Pd)
    out["s86h2-jensen-pdot-twin"] = rel(Pd - (Phi @ P - kap * P @ Psi), Pd)
    h = 1e-5
    Xd_p = flow_XP(ctx, H, X + h * Xd, P + h * Pd)[0]
    Xd_m = flow_XP(ctx, H, X - h * Xd, P - h * Pd)[0]
    Xdd = (Xd_p - Xd_m) / (2 * h)
    true = Phi @ Phi @ X + 2 * kap * Phi @ X @ Psi + kap ** 2 * X @ Psi @ Psi
    twin = Phi @ Phi @ X + kap * Phi @ X @ Psi + kap ** 2 * X @ Psi @ Psi
    out["s86h2-jensen-accel"] = rel(Xdd - true, Xdd, true)
    out["s86h2-jensen-accel-twin"] = rel(Xdd - twin, Xdd, twin)
    G, K = P.T @ P, X.T @ P
    dG = Pd.T @ P + P.T @ Pd
    out["s86h2-jensen-ptp"] = rel(dG - 2 * kap * comm(G, K), dG, G @ K)
    out["s86h2-jensen-ptp-twin"] = rel(dG - 2 * kap * comm(K, G), dG, G @ K)
    return out


def t_metric(ctx):
    X, P = ctx.point()
    Ainv = np.diag(1 / ctx.a)
    H = lambda X, P: np.trace(P.T @ Ainv @ P) / 2
    lam = lambda X, P: X.T @ flow_XP(ctx, H, X, P, metric=True)[1]
    eta = skew(ctx.rng.standard_normal((ctx.r, ctx.r)))
    L = lam(X, P)
    h = 1e-5
    dL = (lam(X + h * X @ eta, P + h * P @ eta) - lam(X - h * X @ eta, P - h * P @ eta)) / (2 * h)
    # sanity: the printed Λ equation of (A_XP)
    M = X.T @ Ainv @ X
    chk = L @ M + M @ L + 2 * P.T @ Ainv @ Ainv @ P
    return {"s86h2-metric-lambda-equivariant": rel(dL - (L @ eta - eta @ L), dL, L),
            "s86h2-metric-lambda-equivariant-twin": rel(dL - (eta @ L - L @ eta), dL, L),
            "(sanity) A_XP Lambda equation": rel(chk, L)}


# ---------------------------------------------------------------- Appendix 1
def t_rigid(ctx):
    if ctx.r != ctx.n or ctx.n < 2:
        return {}
    X, P = ctx.point()
    A = ctx.A

    def H(X, P):
        en = X[:, -1]
        return killing(Phi_(X, P), Phi_(X, P)) / 2 + (np.trace(A) - en @ A @ en) / 2
    Xd, Pd = flow_XP(ctx, H, X, P)
    Phi, Psi = Phi_(X, P), Psi_(X, P)
    out = {"s86h2-rigid-body-velocities": max(rel(Xd @ X.T - Phi, Phi), rel(X.T @ Xd - Psi, Psi)),
           "s86h2-rigid-body-velocities-twin": rel(Xd.T @ X - Psi, Psi)}
    n = ctx.n
    D = np.diag([1.0] * (n - 1) + [0.0])
    eta = skew(ctx.rng.standard_normal((n, n)))
    z = vec(X, P)
    g = cgrad(lambda zz: H(*unvec(zz, [(n, n), (n, n)])), z)
    e = D @ eta @ D
    out["s86h2-hcp-right-invariant"] = abs(g @ vec(X @ e, P @ e)) / max(1, np.abs(g).max())
    out["s86h2-hcp-right-invariant-twin"] = abs(g @ vec(X @ eta, P @ eta)) / max(1, np.abs(g).max())
    return out


def t_magnetic(ctx):
    if ctx.r != 2:
        return {}
    X, P = ctx.point()
    A = ctx.A
    eps = ctx.rng.uniform(0.5, 2)
    Hn = lambda X, P: killing(Phi_(X, P), Phi_(X, P)) / 2 + np.trace(X.T @ A @ X) / 2
    He = lambda X, P: np.trace(P.T @ P) / 2 + np.trace(X.T @ A @ X) / 2
    Xn, Pn = flow_XP(ctx, Hn, X, P, eps=eps)
    Xe, Pe = flow_XP(ctx, He, X, P, eps=eps)
    e1, e2, p1, p2 = X[:, 0], X[:, 1], P[:, 0], P[:, 1]
    # sanity: the printed (mag-euk)
    pd1 = -A @ e1 + (e1 @ A @ e1 - p1 @ p1 - eps * (e1 @ p2)) * e1 + (e1 @ A @ e2 - p1 @ p2) * e2 + eps * p2
    pd2 = -A @ e2 + (e1 @ A @ e2 - p1 @ p2) * e1 + (e2 @ A @ e2 - p2 @ p2 + eps * (e2 @ p1)) * e2 - eps * p1
    sanity = rel(Pe - np.stack([pd1, pd2], 1), Pe) + rel(Xe - P, P)
    J = np.array([[0.0, 1.0], [-1.0, 0.0]])   # E1E2ᵀ − E2E1ᵀ
    psi12 = Psi_(X, P)[0, 1]
    out = {}
    for name, sg in (("s86h2-magnetic-nor-minus-euk", 1), ("s86h2-magnetic-nor-minus-euk-twin", -1)):
        c = sg * psi12 / 2
        out[name] = max(rel(Xn - Xe - c * X @ J, Xn, Xe), rel(Pn - Pe - c * P @ J, Pn, Pe))
    out["(sanity) printed mag-euk"] = sanity
    return out


# ---------------------------------------------------------------- Appendix 2: double
def double_point(ctx):
    n, r, rng = ctx.n, ctx.r, ctx.rng
    X = rng.standard_normal((n, r))
    G = np.linalg.inv(X.T @ X)
    Pr = np.eye(n) - X @ G @ X.T
    Y = X @ G + Pr @ rng.standard_normal((n, r))
    Xd = rng.standard_normal((n, r))
    C = -(Xd.T @ Y)
    Yd = X @ G @ C + Pr @ rng.standard_normal((n, r))
    return X, Y, Xd, Yd


def double_acc(ctx, X, Y, Xd, Yd):
    """KKT: M q̈ = −∇U + Jᵀμ, J q̈ = −D²g(q̇, q̇); q = (X, Y), T = tr(ẊᵀẎ) = ½q̇ᵀMq̇, U = tr(XᵀAY), g = XᵀY − I."""
    n, r, A = ctx.n, ctx.r, ctx.A
    m = n * r
    M = np.zeros((2 * m, 2 * m))
    M[:m, m:] = np.eye(m)
    M[m:, :m] = np.eye(m)
    gradU = vec(A @ Y, A @ X)
    g = lambda zz: (lambda X_, Y_: (X_.T @ Y_).ravel())(*unvec(zz, [(n, r), (n, r)]))
    J = cjac(g, vec(X, Y))
    h2 = (2 * Xd.T @ Yd).ravel()
    K = np.block([[M, -J.T], [J, np.zeros((r * r, r * r))]])
    sol = np.linalg.solve(K, np.concatenate([-gradU, -h2]))
    Xdd, Ydd = unvec(sol[:2 * m], [(n, r), (n, r)])
    return Xdd, Ydd


def t_double(ctx):
    X, Y, Xd, Yd = double_point(ctx)
    A = ctx.A
    Xdd, Ydd = double_acc(ctx, X, Y, Xd, Yd)
    Xdd_s, Ydd_s = double_acc(ctx, Y, X, Yd, Xd)
    lam = lambda X, Y, Xd, Yd: X.T @ A @ Y - Xd.T @ Yd
    L, Ls = lam(X, Y, Xd, Yd), lam(Y, X, Yd, Xd)
    out = {"s86h2-double-swap": max(rel(Xdd_s - Ydd, Ydd), rel(Ydd_s - Xdd, Xdd), rel(Ls - L.T, L)),
           "s86h2-double-swap-twin": rel(Ls - L, L)}
    # sanity: (D-eq)
    out["(sanity) D-eq"] = rel(Xdd - (-A @ X + X @ L.T), Xdd) + rel(Ydd - (-A @ Y + Y @ L), Ydd)
    E = np.zeros((ctx.n, ctx.n))
    E[0, 0] = 1.0          # E = (I - S1)/2, S1 = diag(-1, 1, ..., 1)
    for name, sg in (("s86h2-double-diagonal-momenta", -1), ("s86h2-double-diagonal-momenta-twin", 1)):
        d = np.trace(E @ (Xd @ Yd.T + X @ Ydd.T + sg * (Yd @ Xd.T + Y @ Xdd.T)))
        scale = max(1, np.abs(Xd @ Yd.T).max(), np.abs(X @ Ydd.T).max())
        out[name] = abs(d) / scale
    return out


# ---------------------------------------------------------------- Appendix 2: so(n,n), coupled
def t_sonn(ctx):
    n, rng = ctx.n, ctx.rng
    X, P = ctx.point()
    c2 = Ctx(n, ctx.r, rng)
    Y, Q = c2.point()
    nu = rng.uniform(0.5, 2)
    O = np.zeros((n, n))
    A = ctx.A
    L = nu * np.block([[O, A], [A, O]]) + np.block([[Phi_(X, P), O], [O, Phi_(Y, Q)]]) + \
        np.block([[O, X @ Y.T], [Y @ X.T, O]]) / nu
    Ap = nu * np.block([[O, A], [A, O]]) + np.block([[Phi_(X, P), O], [O, Phi_(Y, Q)]])
    J = np.block([[np.eye(n), O], [O, -np.eye(n)]])
    return {"s86h2-big-lax-so-n-n": max(rel(L.T @ J + J @ L, L), rel(Ap.T @ J + J @ Ap, Ap)),
            "s86h2-big-lax-so-n-n-twin": rel(L + L.T, L)}


def coupled_flow(ctx, H, z):
    n, r = ctx.n, ctx.r
    F = stiefel_constraints(n, r, 2)
    Hz = lambda zz: H(*unvec(zz, [(n, r)] * 4))
    return unvec(dirac_flow(Hz, z, None, F, canonical_pi([0, 1], n, r)), [(n, r)] * 4)


def t_coupled(ctx, lax=True):
    n, r, rng, A = ctx.n, ctx.r, ctx.rng, ctx.A
    X, P = ctx.point()
    c2 = Ctx(n, r, rng)
    c2.a, c2.A = ctx.a, ctx.A
    Y, Q = c2.point()
    kap = rng.uniform(-1, 1)

    def Hc(X, P, Y, Q):
        K1, K2 = X.T @ P, Y.T @ Q
        return (np.trace(P.T @ P) / 2 - (0.5 + kap) * np.trace(K1 @ K1) + np.trace(Q.T @ Q) / 2
                - (0.5 + kap) * np.trace(K2 @ K2) + np.trace(X.T @ A @ Y))
    z = vec(X, P, Y, Q)
    Xd, Pd, Yd, Qd = coupled_flow(ctx, Hc, z)
    rate = skew(Xd.T @ P + X.T @ Pd)
    out = {"s86h2-coupled-torque": rel(rate - (Y.T @ A @ X - X.T @ A @ Y), rate),
           "s86h2-coupled-torque-twin": rel(rate - (X.T @ A @ Y - Y.T @ A @ X), rate)}
    if not lax or n > 5:
        return out

    def Hp(X, P, Y, Q):
        return (np.trace(P.T @ P) / 2 + np.trace(Q.T @ Q) / 2 + np.trace(X.T @ A @ Y)
                + np.trace(X.T @ P @ Y.T @ Q))
    lam = rng.uniform(0.1, 0.4) + max(ctx.a) + 0.3   # not ± an eigenvalue of A
    R = np.linalg.inv(A @ A - lam ** 2 * np.eye(n))
    I, O = np.eye(r), np.zeros((r, r))

    def Ld(X, P, Y, Q):
        F = lambda U, V: U.T @ R @ V
        return np.block([
            [lam * F(P, X), lam * F(P, P), F(A @ P, Y), -I + F(A @ P, Q)],
            [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
            [F(A @ Q, X), -I + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
            [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])
    S = (X.T @ A @ Y + Y.T @ A @ X) / 2
    Lam, Pi = S - P.T @ P, S - Q.T @ Q

    def Ad(d1, d2):
        return np.block([[d1, Lam, O, -lam * I], [I, d1, O, O], [O, -lam * I, d2, Pi], [O, O, I, d2]])
    v = coupled_flow(ctx, Hp, z)
    h = 1e-5
    zp, zm = z + h * vec(*v), z - h * vec(*v)
    dL = (Ld(*unvec(zp, [(n, r)] * 4)) - Ld(*unvec(zm, [(n, r)] * 4))) / (2 * h)
    L0 = Ld(X, P, Y, Q)
    XP, YQ = X.T @ P, Y.T @ Q
    for name, (d1, d2) in (("s86h2-perturbed-euclid-dual-lax", (-YQ, -XP)),
                           ("s86h2-perturbed-euclid-dual-lax-twin", (XP, YQ))):
        res = dL - comm(L0, Ad(d1, d2))
        out[name] = rel(res, dL)
    return out


def main(seed):
    rows = {}
    for (n, r) in SIZES:
        rng = np.random.default_rng(1000 * seed + 10 * n + r)
        ctx = Ctx(n, r, rng)
        res = {}
        res.update(t_jensen(ctx))
        res.update(t_metric(Ctx(n, r, rng, metric=True)))
        res.update(t_rigid(ctx))
        res.update(t_magnetic(ctx))
        res.update(t_double(ctx))
        res.update(t_sonn(ctx))
        res.update(t_coupled(ctx))
        for k, v in res.items():
            rows.setdefault(k, {})[(n, r)] = v
    print(f"seed {seed}: relative residuals")
    hdr = "claim".ljust(42) + "".join(f"{n},{r}".rjust(9) for n, r in SIZES)
    print(hdr)
    for k in sorted(rows):
        print(k.ljust(42) + "".join((f"{rows[k][s]:9.1e}" if s in rows[k] else "        -") for s in SIZES))


if __name__ == "__main__":
    for sd in map(int, sys.argv[1:] or ["1"]):
        main(sd)
