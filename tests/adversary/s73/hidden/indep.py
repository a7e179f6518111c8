# ruff: noqa: E701, E702, F841 - a numpy check written compactly, kept as its author wrote it
"""s73: independent plain-numpy evaluation of every statement of claims.py and negatives.py (no stiefelsym).

For each claim id and size: 3 random points of T*V(n, r) (XᵀX = I, XᵀP + PᵀX = 0; at r = n both components of
O(n)), random values of the free parameters (λ, μ, κ, ε, η, S), and the residual's largest entry relative to the
scale of its terms.  Prints `id n r TRUE|FALSE value` lines (for ranks and counts the value is the rank found).
Usage: indep.py [--big] [--seed N]."""
import sys
import numpy as np

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from indep_core import point, A_of, grad, dirv, dirac_data, bracket, flow, phi, psi, jac, mrank, can  # noqa

TOL = 1e-7
F2 = np.array([[0., 1.], [-1., 0.]])


def pts(n, r, rng, k=3):
    comps = [0, 1] if r == n else [0]
    out = []
    for i in range(k):
        out.append(point(n, r, rng, comps[i % len(comps)]))
    return out


def rel(res, scale):
    return float(np.max(np.abs(res))) / max(1.0, float(scale))


# --- helpers ---------------------------------------------------------------------------------------
def uhl_F(X, P, a):
    n = len(a); e = X[:, 0]; Ph = phi(X, P)
    return [e[i] ** 2 + sum(Ph[i, j] ** 2 / (a[i] - a[j]) for j in range(n) if j != i) for i in range(n)]


def sphere_flow(X, P, A):
    return P, -A @ X + X @ (X.T @ A @ X - P.T @ P)


def H_quartic(A):
    def H(X, P):
        M = X.T @ A @ X
        return 0.5 * np.trace(P.T @ P) + np.trace(X.T @ A @ A @ X) - np.trace(M @ M)
    return H


def L_dual(X, P, A, lam):
    n, r = X.shape
    R = np.linalg.inv(lam * np.eye(n) - A)
    return np.block([[-X.T @ R @ P, -X.T @ R @ X], [np.eye(r) + P.T @ R @ P, P.T @ R @ X]])


def tr_pow(M, k):
    return np.trace(np.linalg.matrix_power(M, k))


def cay(M):
    I = np.eye(M.shape[0])
    return (I - M) @ np.linalg.inv(I + M)


def H_neum(A, kappa):
    def H(X, P):
        K = X.T @ P
        return 0.5 * np.trace(P.T @ P) - (0.5 + kappa) * np.trace(K @ K) + 0.5 * np.trace(X.T @ A @ X)
    return H


# twisted bracket and its Dirac flow: {f, g}_ε = f_X·g_P − f_P·g_X − ε tr(f_Pᵀ g_P F)
def can_eps(eps):
    return lambda gf, gg: np.sum(gf[0] * gg[1]) - np.sum(gf[1] * gg[0]) - eps * np.trace(gf[1].T @ gg[1] @ F2)


def twisted_flow(H, X, P, eps):
    from indep_core import constraints
    cb = can_eps(eps)
    gF = [grad(F, X, P) for F in constraints(X, P)]
    C = np.array([[cb(a, b) for b in gF] for a in gF])
    gH = grad(H, X, P)
    w = np.linalg.solve(C, np.array([cb(a, gH) for a in gF]))
    # X_g with df(X_g) = {f, g}_ε: Ẋ = g_P, Ṗ = −g_X − ε g_P F
    vec = lambda g: (g[1], -g[0] - eps * g[1] @ F2)
    VX, VP = vec(gH)
    for wi, a in zip(w, gF):
        ax, ap = vec(a); VX = VX - wi * ax; VP = VP - wi * ap
    return VX, VP


# coupled: stacked (X|Y), (P|Q), constraints on each block
def pair_constraints(r):
    iu = np.triu_indices(r)
    out = []
    for b in (slice(0, r), slice(r, 2 * r)):
        for k in range(len(iu[0])):
            i, j = iu[0][k], iu[1][k]
            out.append(lambda X, P, b=b, i=i, j=j: (X[:, b].T @ X[:, b])[i, j])
            out.append(lambda X, P, b=b, i=i, j=j: (X[:, b].T @ P[:, b] + P[:, b].T @ X[:, b])[i, j])
    return out


def pair_flow(H, X2, P2, r):
    gF = [grad(F, X2, P2) for F in pair_constraints(r)]
    C = np.array([[can(a, b) for b in gF] for a in gF])
    gH = grad(H, X2, P2)
    w = np.linalg.solve(C, np.array([can(a, gH) for a in gF]))
    VX = gH[1] - sum(wi * a[1] for wi, a in zip(w, gF))
    VP = -gH[0] + sum(wi * a[0] for wi, a in zip(w, gF))
    return VX, VP


def H_coupled(A, kappa, r):
    def H(X2, P2):
        X, Y, P, Q = X2[:, :r], X2[:, r:], P2[:, :r], P2[:, r:]
        c = 0.5 + kappa; K, L = X.T @ P, Y.T @ Q
        return (0.5 * np.trace(P.T @ P) - c * np.trace(K @ K) + 0.5 * np.trace(Q.T @ Q) - c * np.trace(L @ L)
                + np.trace(X.T @ A @ Y))
    return H


# complex W(n, r)
def cpoint(n, r, rng):
    G = rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n))
    Q, _ = np.linalg.qr(G)
    Z = Q[:, :r]
    W = rng.standard_normal((r, r)) + 1j * rng.standard_normal((r, r)); W = W - W.conj().T
    Y = rng.standard_normal((n, r)) + 1j * rng.standard_normal((n, r))
    Zd = Z @ W + (np.eye(n) - Z @ Z.conj().T) @ Y
    return Z, Zd


# --- the statements -------------------------------------------------------------------------------
def run(cid, n, r, rng):
    """Returns (holds: bool, value) at this size (all points)."""
    A = A_of(n, rng); a = np.diag(A)
    worst = 0.0; vals = []
    plist = pts(n, r, rng)
    if cid in ("h73-coupled-prep", "n73-coupled-prep-projectors") and r == n:
        # T*V × T*V at r = n has four components: X and Y each on either component of O(n)
        plist = [point(n, r, rng, c) for c in (0, 0, 1, 1)]
    for k, (X, P) in enumerate(plist):
        lam, mu, kappa, eps = rng.uniform(-2, 2, 4)
        if cid in ("h73-uhlenbeck-sums", "n73-uhlenbeck-sums-minus"):
            F = uhl_F(X, P, a); e, p = X[:, 0], P[:, 0]
            Ai = np.linalg.inv(A); Ph = phi(X, P)
            sc = sum(abs(f) for f in F) * max(abs(a)) + 10
            if cid.startswith("h"):
                res = [sum(F) - 1, np.dot(a, F) - e @ A @ e - p @ p,
                       sum(F[i] / a[i] for i in range(n)) - e @ Ai @ e - 0.5 * np.trace(Ai @ Ph @ Ai @ Ph)]
            else:
                res = [np.dot(a, F) - e @ A @ e + p @ p]
            worst = max(worst, rel(res, sc))
        elif cid in ("h73-uhlenbeck-neumann-flow", "n73-uhlenbeck-flow-factor"):
            fac = 0.5 if cid.startswith("h") else 1.0
            H = lambda X_, P_: fac * sum(ai * f for ai, f in zip(a, uhl_F(X_, P_, a)))
            VX, VP = flow(H, X, P); RX, RP = sphere_flow(X, P, A)
            worst = max(worst, rel(np.concatenate([np.ravel(VX - RX), np.ravel(VP - RP)]), 10))
        elif cid in ("h73-quartic-flow", "n73-quartic-lambda-sign"):
            H = H_quartic(A); M = X.T @ A @ X
            gX, gP = grad(H, X, P); VX, VP = flow(H, X, P)
            sgn = -1 if cid.startswith("h") else 1
            Lam = 2 * X.T @ A @ A @ X - 4 * M @ M + sgn * P.T @ P
            Pd = -2 * A @ A @ X + 4 * A @ X @ M + X @ Lam
            if cid.startswith("h"):
                dpsi = dirv(lambda X_, P_: psi(X_, P_), X, P, (VX, VP))
                res = np.concatenate([np.ravel(gX - (2 * A @ A @ X - 4 * A @ X @ M)), np.ravel(gP - P),
                                      np.ravel(VX - P), np.ravel(VP - Pd), np.ravel(dpsi)])
            else:
                res = np.ravel(VP - Pd)
            worst = max(worst, rel(res, 100))
        elif cid in ("h73-so2-wedge-invariant", "n73-wedge-reflection"):
            eta = rng.standard_normal(); E = np.array([[0, eta], [-eta, 0]])
            h = cay(E) if cid.startswith("h") else np.diag([1., -1.])
            W = lambda X_: X_ @ F2 @ X_.T
            Xh, Ph = X @ h, P @ h
            if cid.startswith("h"):
                res = np.concatenate([np.ravel(W(Xh) - W(X)), np.ravel(A @ W(Xh) + W(Xh) @ A - A @ W(X) - W(X) @ A),
                                      np.ravel(W(Ph) - W(P)),
                                      [np.trace(Xh.T @ A @ Xh - Ph.T @ Ph) - np.trace(X.T @ A @ X - P.T @ P)],
                                      np.ravel(h.T @ h - np.eye(2))])
            else:
                res = np.ravel(W(Xh) - W(X))
            worst = max(worst, rel(res, 10))
        elif cid in ("h73-psi-zero-regular", "n73-psi-zero-rank-high"):
            J = jac(lambda X_, P_: np.concatenate([np.ravel(X_.T @ X_), np.ravel(X_.T @ P_)]), X, P)
            vals.append(mrank(J))
        elif cid in ("h73-mag0-rank", "n73-mag0-rank-plus-one"):
            Fc = lambda X_, P_: np.concatenate([np.ravel(X_.T @ X_), np.ravel(X_.T @ P_ + P_.T @ X_)])
            Ff = lambda X_, P_: np.concatenate([np.ravel(phi(X_, P_)), np.ravel(X_ @ X_.T)])
            vals.append(mrank(np.vstack([jac(Fc, X, P), jac(Ff, X, P)])))
        elif cid in ("h73-dual-big-commute", "n73-dual-big-plus-a"):
            sg = -1 if cid.startswith("h") else 1
            Lb = lambda X_, P_: mu * phi(X_, P_) + X_ @ X_.T + sg * mu * mu * A
            f2 = lambda X_, P_: tr_pow(L_dual(X_, P_, A, lam), 2)
            b1 = bracket(f2, lambda X_, P_: tr_pow(Lb(X_, P_), 2), X, P)
            sc = 1 + abs(f2(X, P)) * abs(tr_pow(Lb(X, P), 2))
            res = [b1]
            if cid.startswith("h"):
                res.append(bracket(lambda X_, P_: tr_pow(L_dual(X_, P_, A, lam), 4),
                                   lambda X_, P_: tr_pow(Lb(X_, P_), 3), X, P))
                sc = max(sc, 1 + abs(tr_pow(L_dual(X, P, A, lam), 4) * tr_pow(Lb(X, P), 3)))
            worst = max(worst, rel(res, sc))
        elif cid in ("h73-invariants-noncommutative", "n73-invariants-trace-commutes-not",
                     "n73-invariants-noncommutative-2-2"):
            S = rng.standard_normal((r, r)); S = S + S.T
            et = rng.standard_normal((r, r)); et = et - et.T
            f = (lambda X_, P_: np.trace(S @ P_.T @ P_)) if "noncomm" in cid else (lambda X_, P_: np.trace(P_.T @ P_))
            b = bracket(f, lambda X_, P_: np.trace(et @ psi(X_, P_)), X, P)
            vals.append(abs(b))
        elif cid in ("h73-dual-det-r-n", "n73-dual-det-no-a"):
            aa = np.prod(lam - a) if cid.startswith("h") else 1.0
            worst = max(worst, rel([aa * np.linalg.det(L_dual(X, P, A, lam)) - 1], 1))
        elif cid in ("h73-twisted-psi12-any-kappa", "n73-twisted-p1p2"):
            H = H_neum(A, kappa)
            VX, VP = twisted_flow(H, X, P, eps)
            if cid.startswith("h"):
                Hq = H_quartic(A); QX, QP = twisted_flow(Hq, X, P, eps)
                res = [dirv(lambda X_, P_: psi(X_, P_)[0, 1], X, P, (VX, VP)), dirv(H, X, P, (VX, VP)),
                       dirv(lambda X_, P_: psi(X_, P_)[0, 1], X, P, (QX, QP))]
            else:
                res = [dirv(lambda X_, P_: (P_.T @ P_)[0, 1], X, P, (VX, VP))]
            worst = max(worst, rel(res, 10))
        elif cid in ("h73-coupled-prep", "n73-coupled-prep-projectors"):
            Y, Q = point(n, r, rng, (k % 2) if r == n else 0)
            X2, P2 = np.hstack([X, Y]), np.hstack([P, Q])
            VX, VP = pair_flow(H_coupled(A, kappa, r), X2, P2, r)
            d = dirv(lambda U, V: phi(U[:, :r], V[:, :r]) + phi(U[:, r:], V[:, r:]), X2, P2, (VX, VP))
            M = X @ Y.T + Y @ X.T if cid.startswith("h") else X @ X.T + Y @ Y.T
            worst = max(worst, rel(d - (M @ A - A @ M), 10))
        elif cid in ("h73-complex-u-r-symmetry", "n73-complex-lambda-order"):
            Z, Zd = cpoint(n, r, rng)
            et = rng.standard_normal((r, r)); et = et - et.T
            S = rng.standard_normal((r, r)); S = S + S.T
            K = et + 1j * S; U = (np.eye(r) - K) @ np.linalg.inv(np.eye(r) + K)
            st = lambda M: M.conj().T
            Lag = lambda Z_, Zd_: 0.5 * np.trace(Zd_.T @ Zd_.conj()) - 0.5 * np.trace(Z_.T @ A @ Z_.conj())
            Lm = lambda Z_, Zd_: st(Z_) @ A @ Z_ - st(Zd_) @ Zd_
            ps = lambda Z_, Zd_: Z_.T @ Zd_.conj() - Zd_.T @ Z_.conj()
            ZU, ZdU = Z @ U, Zd @ U
            if cid.startswith("h"):
                res = np.concatenate([np.ravel(st(U) @ U - np.eye(r)), np.ravel(st(ZU) @ ZU - np.eye(r)),
                                      np.ravel(st(ZU) @ ZdU + st(ZdU) @ ZU), [Lag(ZU, ZdU) - Lag(Z, Zd)],
                                      np.ravel(Lm(ZU, ZdU) - st(U) @ Lm(Z, Zd) @ U),
                                      np.ravel(ps(ZU, ZdU) - U.T @ ps(Z, Zd) @ U.conj())])
            else:
                res = np.ravel(Lm(ZU, ZdU) - U @ Lm(Z, Zd) @ st(U))
            worst = max(worst, rel(res, 10))
        else:
            raise KeyError(cid)
    if cid in ("h73-psi-zero-regular", "n73-psi-zero-rank-high"):
        exp = r * (r + 1) // 2 + r * r if cid.startswith("h") else r * (r + 1) + r * r
        return max(vals) == exp, max(vals)
    if cid in ("h73-mag0-rank", "n73-mag0-rank-plus-one"):
        exp = r * (r + 1) + n * (n - 1) // 2 + (n - 1) + (0 if cid.startswith("h") else 1)
        return max(vals) == exp, max(vals)
    if cid in ("h73-invariants-noncommutative", "n73-invariants-trace-commutes-not",
               "n73-invariants-noncommutative-2-2"):
        return max(vals) > 1e-6, max(vals)        # a `not` statement: true iff the bracket is nonzero
    return worst < TOL, worst


def count(cid, n, r):
    dimV = n * r - r * (r + 1) // 2
    lhs = 2 * dimV - r * (r - 1) // 2
    rhs = n * (n - 1) // 2 + (n - 1) + (0 if cid.startswith("h") else 1)
    return lhs == rhs, lhs


SIZES = {
    "r1": [(n, 1) for n in (2, 3, 4)],
    "all": [(n, r) for n in range(1, 5) for r in range(1, n + 1)],
    "r2": [(2, 2), (3, 2), (4, 2)],
    "n-1": [(n, n - 1) for n in (2, 3, 4, 5)],
    "n-1c": [(n, n - 1) for n in (2, 3, 4, 5, 6)],
    "r>=2": [(n, r) for n in range(2, 5) for r in range(2, n + 1)],
    "r>=2not22": [(n, r) for n in range(3, 5) for r in range(2, n + 1)],
    "rn": [(n, n) for n in range(1, 5)],
    "22": [(2, 2)],
    "n3": [(n, r) for n in range(1, 4) for r in range(1, n + 1)],
    "c": [(n, r) for n in range(1, 4) for r in range(1, min(n, 2) + 1)],
}
CLAIMS = [("h73-uhlenbeck-sums", "r1"), ("n73-uhlenbeck-sums-minus", "r1"),
          ("h73-uhlenbeck-neumann-flow", "r1"), ("n73-uhlenbeck-flow-factor", "r1"),
          ("h73-quartic-flow", "all"), ("n73-quartic-lambda-sign", "all"),
          ("h73-so2-wedge-invariant", "r2"), ("n73-wedge-reflection", "r2"),
          ("h73-psi-zero-regular", "all"), ("n73-psi-zero-rank-high", "all"),
          ("h73-mag0-rank", "n-1"), ("n73-mag0-rank-plus-one", "n-1"),
          ("h73-mag0-count", "n-1c"), ("n73-mag0-count-n", "n-1c"),
          ("h73-dual-big-commute", "all"), ("n73-dual-big-plus-a", "all"),
          ("h73-invariants-noncommutative", "r>=2not22"), ("n73-invariants-trace-commutes-not", "r>=2"),
          ("n73-invariants-noncommutative-2-2", "22"),
          ("h73-dual-det-r-n", "rn"), ("n73-dual-det-no-a", "rn"),
          ("h73-complex-u-r-symmetry", "c"), ("n73-complex-lambda-order", "c"),
          ("h73-coupled-prep", "n3"), ("n73-coupled-prep-projectors", "n3"),
          ("h73-twisted-psi12-any-kappa", "r2"), ("n73-twisted-p1p2", "r2")]
BIG = [(5, 2), (6, 3), (5, 5)]


def applies(cid, n, r, group):
    if group == "r1": return r == 1 and n >= 2
    if group == "r2": return r == 2
    if group in ("n-1", "n-1c"): return r == n - 1 and n >= 2
    if group == "r>=2": return r >= 2
    if group == "r>=2not22": return r >= 2 and (n, r) != (2, 2)
    if group == "rn": return r == n
    if group == "22": return (n, r) == (2, 2)
    if group == "c": return r <= 2
    return True


def main():
    seed = int(sys.argv[sys.argv.index("--seed") + 1]) if "--seed" in sys.argv else 0
    rng = np.random.default_rng(seed)
    # sanity: the twisted flow against the printed (mag-euk) (κ = −½)
    n = 4; A = A_of(n, rng); X, P = point(n, 2, rng); eps = 0.7
    VX, VP = twisted_flow(H_neum(A, -0.5), X, P, eps)
    e1, e2, p1, p2 = X[:, 0], X[:, 1], P[:, 0], P[:, 1]
    pd1 = -A @ e1 + (e1 @ A @ e1 - p1 @ p1 - eps * e1 @ p2) * e1 + (e1 @ A @ e2 - p1 @ p2) * e2 + eps * p2
    pd2 = -A @ e2 + (e1 @ A @ e2 - p1 @ p2) * e1 + (e2 @ A @ e2 - p2 @ p2 + eps * e2 @ p1) * e2 - eps * p1
    print(f"# sanity twisted flow vs printed (mag-euk): {np.max(np.abs(np.column_stack([pd1, pd2]) - VP)):.1e}"
          f" {np.max(np.abs(VX - P)):.1e}")
    for cid, group in CLAIMS:
        sizes = BIG if "--big" in sys.argv else SIZES[group]
        for (n, r) in sizes:
            if not applies(cid, n, r, group):
                continue
            if cid.endswith("count") or cid.endswith("count-n"):
                ok, v = count(cid, n, r)
            else:
                ok, v = run(cid, n, r, rng)
            print(f"{cid} {n} {r} {'TRUE' if ok else 'FALSE'} {v:.3g}" if isinstance(v, float)
                  else f"{cid} {n} {r} {'TRUE' if ok else 'FALSE'} {v}", flush=True)


if __name__ == "__main__":
    main()
