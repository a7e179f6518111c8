# ruff: noqa: E702
"""Independent truth for s87h1's claims: numpy only (no stiefelsym).

Dirac flows and brackets on T*V(n, r) computed from scratch: complex-step gradients of the
Hamiltonian and of the constraints XᵀX − I, XᵀP + PᵀX (entries i ≤ j), canonical tensor with
{x, p} = 1, Dirac correction.  Prints, per statement and size, the max residual of the TRUE
statement and of its FALSE twin (a twin 'false' when its residual is > 1e-6 relative).
"""
import itertools
import numpy as np

rng = np.random.default_rng(1)


def skew(m):
    w = rng.standard_normal((m, m))
    return w - w.T


def sym(m):
    w = rng.standard_normal((m, m))
    return w + w.T


def point(n, r, psi_zero=False):
    X = np.linalg.qr(rng.standard_normal((n, n)))[0][:, :r]
    W = skew(r)
    Z = rng.standard_normal((n, r))
    P = (np.eye(n) - X @ X.T) @ Z
    if not psi_zero:
        P = P + X @ W
    return X, P


def split(z, n, r):
    return z[:n * r].reshape(n, r), z[n * r:].reshape(n, r)


def grad(f, z):
    """Complex-step gradient of a real-analytic scalar function f(z)."""
    g = np.zeros(len(z))
    h = 1e-30
    for i in range(len(z)):
        zz = z.astype(complex)
        zz[i] += 1j * h
        g[i] = f(zz).imag / h
    return g


def constraints(n, r):
    cs = []
    for i, j in itertools.combinations_with_replacement(range(r), 2):
        cs.append(lambda z, i=i, j=j: (split(z, n, r)[0].T @ split(z, n, r)[0])[i, j] - (i == j))
        cs.append(lambda z, i=i, j=j: (lambda X, P: (X.T @ P + P.T @ X)[i, j])(*split(z, n, r)))
    return cs


def J(n, r):
    m = n * r
    return np.block([[np.zeros((m, m)), np.eye(m)], [-np.eye(m), np.zeros((m, m))]])


def dirac(n, r, z):
    Jm = J(n, r)
    C = np.array([grad(c, z) for c in constraints(n, r)])
    M = C @ Jm @ C.T
    Minv = np.linalg.inv(M)
    return Jm, C, Minv


def flow(H, n, r, z):
    Jm, C, Minv = dirac(n, r, z)
    gH = grad(H, z)
    return Jm @ gH - Jm @ C.T @ Minv @ (C @ Jm @ gH)


def bracket(F, G, n, r, z):
    Jm, C, Minv = dirac(n, r, z)
    gF, gG = grad(F, z), grad(G, z)
    return gF @ Jm @ gG - (gF @ Jm @ C.T) @ Minv @ (C @ Jm @ gG)


def dmat(F, n, r, z, zdot):
    """Derivative of a matrix function F(X, P) along zdot (complex step)."""
    h = 1e-30
    X, P = split(z.astype(complex) + 1j * h * zdot, n, r)
    return F(X, P).imag / h


def tr(m):
    return np.trace(m)


def kill(a, b):
    return -tr(a @ b) / 2


def comm(a, b):
    return a @ b - b @ a


def Phi(X, P):
    return P @ X.T - X @ P.T


def Psi(X, P):
    return X.T @ P - P.T @ X


results = []


def report(name, size, true_res, twin_res):
    results.append((name, size, true_res, twin_res))
    print(f"{name:28s} {str(size):7s} TRUE res={true_res:.2e}   TWIN res={twin_res:.2e} "
          f"-> twin {'FALSE' if twin_res > 1e-6 else 'true here'}")


SIZES = [(1, 1), (2, 1), (2, 2), (3, 1), (3, 2), (3, 3), (4, 1), (4, 2), (4, 3), (4, 4), (5, 2), (5, 3)]

for (n, r) in SIZES:
    a = np.sort(rng.standard_normal(n))
    A = np.diag(a)
    X, P = point(n, r)
    z = np.concatenate([X.ravel(), P.ravel()])
    Xz = lambda z: split(z, n, r)
    kappa = 0.37

    # ---- §4 Manakov B = A²: H = ½<𝔸Φ, Φ>, 𝔸ξ = Aξ + ξA
    AA = lambda xi: A @ xi + xi @ A
    HM = lambda z: kill(AA(Phi(*Xz(z))), Phi(*Xz(z))) / 2
    zd = flow(HM, n, r, z)
    Ph = Phi(X, P)
    dPhi = dmat(Phi, n, r, z, zd)
    report("T1 manakov-euler", (n, r), np.abs(dPhi - comm(AA(Ph), Ph)).max(), np.abs(dPhi - comm(Ph, AA(Ph))).max())
    f_true = lambda X, P: 2 * tr(A @ A @ Phi(X, P) @ Phi(X, P)) + tr(A @ Phi(X, P) @ A @ Phi(X, P))
    f_twin = lambda X, P: tr(A @ A @ Phi(X, P) @ Phi(X, P)) + tr(A @ Phi(X, P) @ A @ Phi(X, P))
    report("T2 manakov-quartic", (n, r), abs(dmat(f_true, n, r, z, zd)), abs(dmat(f_twin, n, r, z, zd)))

    # ---- §4 remark: {tr(G PᵀP), <Ψ,Ψ>} = c tr(G [PᵀP, Ψ])
    G = rng.standard_normal((r, r))
    b = bracket(lambda z: tr(G @ Xz(z)[1].T @ Xz(z)[1]), lambda z: kill(Psi(*Xz(z)), Psi(*Xz(z))), n, r, z)
    base = tr(G @ comm(P.T @ P, Psi(X, P)))
    c3 = b / base if abs(base) > 1e-9 else float('nan')
    report("T3 gram-psi c=" + (f"{c3:+.4f}" if np.isfinite(c3) else "n/a"), (n, r), abs(b - 1 * base), abs(b + 1 * base))

    # ---- §6 (LAMBDA): Λ1 − Λ2 at x = h + v
    h, v = skew(n), sym(n)
    xi, ze, et, th = skew(n), skew(n), sym(n), sym(n)
    x = h + v
    L1 = lambda x, xi, et, ze, th: kill(x, comm(xi, ze) + comm(xi, th) + comm(et, ze))
    L2 = lambda x, xi, et, ze, th: kill(x - A, comm(xi + et, ze + th))
    lhs = L1(x, xi, et, ze, th) - L2(x, xi, et, ze, th)
    rhs = -kill(h, comm(et, th)) + kill(A, comm(xi, th) + comm(et, ze))
    rhs_twin = +kill(h, comm(et, th)) + kill(A, comm(xi, th) + comm(et, ze))
    report("T5 lambda(1,-1)", (n, r), abs(lhs - rhs), abs(lhs - rhs_twin))

    # ---- §6 (L3),(L4): η = A², ξ = −(Ah + hA) ∈ ker Λ_{1,−1}(h + v), h = Φ, v = XXᵀ
    hh, vv = Ph, X @ X.T
    et_k = A @ A
    res_t = L1(hh + vv, -(A @ hh + hh @ A), et_k, ze, th) - L2(hh + vv, -(A @ hh + hh @ A), et_k, ze, th)
    res_f = L1(hh + vv, (A @ hh + hh @ A), et_k, ze, th) - L2(hh + vv, (A @ hh + hh @ A), et_k, ze, th)
    report("T6 ker-lambda(1,-1)", (n, r), abs(res_t), abs(res_f))

    # ---- §6 CIF/COM: along H_𝔹, H_neum,𝔹: Ψ̇ = c[Ψ, 𝔹Ψ]
    B = sym(r)
    BB = lambda xi: B @ xi + xi @ B
    HB = lambda z: tr(Xz(z)[1].T @ Xz(z)[1]) / 2 - tr(Psi(*Xz(z)) @ BB(Psi(*Xz(z)))) / 4
    HNB = lambda z: HB(z) + tr(Xz(z)[0].T @ A @ Xz(z)[0]) / 2
    Ps = Psi(X, P)
    for name, H in (("T7 hb-euler", HB), ("T8 neum-b-euler", HNB)):
        zd = flow(H, n, r, z)
        dPsi = dmat(Psi, n, r, z, zd)
        base = comm(Ps, BB(Ps))
        if np.abs(base).max() > 1e-9:
            c = np.sum(dPsi * base) / np.sum(base * base)
        else:
            c = float('nan')
        if name.startswith("T7"):
            report(name + f" c={c:+.4f}", (n, r), np.abs(dPsi - comm(Ps, BB(Ps))).max(), np.abs(dPsi + comm(Ps, BB(Ps))).max())
        else:
            report(name + f" c={c:+.4f}", (n, r), np.abs(dPsi - comm(Ps, BB(Ps))).max(),
                   np.abs(dPsi - comm(Ps, BB(Ps)) - comm(Ps, X.T @ A @ X)).max())

    # ---- §6 LEMA1 / §7 NEUMANN2: rank of u ↦ [v, u] + [h, (u − uᵀ)/2] on gl(n)
    def rank_map(X, P):
        hh, vv = Phi(X, P), X @ X.T
        cols = []
        for i in range(n):
            for j in range(n):
                u = np.zeros((n, n)); u[i, j] = 1
                cols.append((comm(vv, u) + comm(hh, (u - u.T) / 2)).ravel())
        s = np.linalg.svd(np.array(cols).T, compute_uv=False)
        return int(np.sum(s > 1e-9 * max(1, s[0])))
    two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
    rk = rank_map(X, P)
    report(f"T9 lema1-rank rk={rk} 2l={two_l}", (n, r), abs(rk - two_l), abs(rk - (2 * r * (n - r) + r * (r - 1) // 2 + r // 2)))
    X0, P0 = point(n, r, psi_zero=True)
    rk0 = rank_map(X0, P0)
    report(f"T11 neumann2-rank rk={rk0}", (n, r), abs(rk0 - 2 * r * (n - r)), abs(rk0 - two_l))
    # every-point trick K3: rank at Ψ = 0 vs generic
    # ---- §6 LEMA1 count
    rank_so = lambda m: m // 2
    dso = lambda m: m * (m - 1) // 2
    dsym = lambda m: m * (m + 1) // 2
    report("T10 lema1-count", (n, r), abs(n * n - (rank_so(r) + dso(n - r) + dsym(r) + dsym(n - r)) - two_l),
           abs(n * n - (rank_so(r) + dso(n - r) + dso(r) + dsym(n - r)) - two_l))

    # ---- §4 Manakov δ (n ≥ 2r)
    dimV = n * r - r * (r + 1) // 2
    ddim = dimV - dso(n - r) + (dso(n - 2 * r) if n > 2 * r else 0)
    tl = (n * (n - 1) // 2 - n // 2) if n <= 2 * r + 1 else 2 * r * (n - r - 1)
    delta = 2 * dimV - ddim - tl / 2
    report(f"T4 manakov-delta n>=2r:{n>=2*r}", (n, r), abs(delta - r * (n - r)) if n >= 2 * r else 0.0, abs(delta - r * (n - r)))

    # ---- Neumann κ: XᵀẊ = (1 + κ)Ψ ; multiplier Λ
    HK = lambda z: (tr(Xz(z)[1].T @ Xz(z)[1]) / 2 - (0.5 + kappa) * tr(Xz(z)[0].T @ Xz(z)[1] @ Xz(z)[0].T @ Xz(z)[1])
                    + tr(Xz(z)[0].T @ A @ Xz(z)[0]) / 2)
    HE = lambda z: tr(Xz(z)[1].T @ Xz(z)[1]) / 2 + tr(Xz(z)[0].T @ A @ Xz(z)[0]) / 2
    zd = flow(HK, n, r, z)
    Xd, Pd = split(zd, n, r)
    report("T12 xtxdot=(1+k)Psi", (n, r), np.abs(X.T @ Xd - (1 + kappa) * Ps).max(), np.abs(X.T @ Xd - (1 + 2 * kappa) * Ps).max())

    def multipliers(H, zd):
        g = grad(H, z)
        HX, HP = split(g, n, r)
        Xd, Pd = split(zd, n, r)
        Pi = X.T @ (HP - Xd)
        Lam = X.T @ (Pd + HX - P @ Pi)
        return Pi, Lam, Xd
    PiK, LamK, XdK = multipliers(HK, zd)
    zdE = flow(HE, n, r, z)
    PiE, LamE, XdE = multipliers(HE, zdE)
    report("T13 ne-multiplier", (n, r), max(np.abs(LamE - (X.T @ A @ X - XdE.T @ XdE)).max(), np.abs(PiE).max()),
           np.abs(LamK - (X.T @ A @ X - XdK.T @ XdK)).max())

    # ---- tricks (truth only)
    print(f"   K1 PᵀP+Ψ²/4: {np.abs(P.T @ P + Ps @ Ps / 4).max():.2e}  K2 XPᵀX: {np.abs(X @ P.T @ X).max():.2e}"
          f"  K7 XXᵀ−I: {np.abs(X @ X.T - np.eye(n)).max():.2e}  K4 (XᵀAX)[0,1]: "
          f"{abs((X.T @ A @ X)[0, 1]) if r >= 2 else float('nan'):.2e}")
