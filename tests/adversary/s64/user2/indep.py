# ruff: noqa
"""Independent numpy checks of the v64-/w64- statements at random points of T*V(n, r).

No stiefelsym import.  The Dirac bracket is computed from its definition via the
Lagrange-multiplier form (dot_XP): the Hamiltonian vector field of g on T*V is
  Xdot = g_P - X Pi,  Pdot = -g_X + X Lam + P Pi,
with Lam, Pi symmetric chosen so that the constraints (cond_XP) are preserved
(solved by least squares); then {f, g} = <f_X, Xdot> + <f_P, Pdot>.
Gradients by the complex-step method (exact to rounding for the polynomial /
rational functions used here).

Run:  /work/main/.venv/bin/python indep.py
"""
import itertools
import numpy as np

rng = np.random.default_rng(64)


def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, r)))
    W = rng.standard_normal((r, r)); W = W - W.T
    Z = rng.standard_normal((n, r))
    P = X @ W + (np.eye(n) - X @ X.T) @ Z
    a = np.sort(rng.standard_normal(n)) * 2
    return X, P, np.diag(a)


def skew(m):
    M = rng.standard_normal((m, m)); return M - M.T


def sym(m):
    M = rng.standard_normal((m, m)); return M + M.T


def grad(f, X, P, h=1e-30):
    gX = np.zeros_like(X); gP = np.zeros_like(P)
    for i, j in itertools.product(range(X.shape[0]), range(X.shape[1])):
        E = np.zeros(X.shape, dtype=complex); E[i, j] = 1j * h
        gX[i, j] = np.imag(f(X + E, P.astype(complex))) / h
        gP[i, j] = np.imag(f(X.astype(complex), P + E)) / h
    return gX, gP


def sym_basis(r):
    B = []
    for i in range(r):
        for j in range(i, r):
            E = np.zeros((r, r)); E[i, j] = E[j, i] = 1; B.append(E)
    return B


def dirac_field(g, X, P):
    gX, gP = grad(g, X, P)
    r = X.shape[1]
    SB = sym_basis(r)
    # unknowns: Lam (sym), Pi (sym); constraints' derivatives are linear in them
    def cons(Lam, Pi, homog):
        Xd = (0 if homog else gP) - X @ Pi
        Pd = (0 if homog else -gX) + X @ Lam + P @ Pi
        c1 = X.T @ Xd + Xd.T @ X
        c2 = Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd
        return np.concatenate([c1.ravel(), c2.ravel()])
    b = cons(np.zeros((r, r)), np.zeros((r, r)), False)
    cols = [cons(E, np.zeros((r, r)), True) for E in SB] + [cons(np.zeros((r, r)), E, True) for E in SB]
    M = np.array(cols).T
    sol, *_ = np.linalg.lstsq(M, -b, rcond=None)
    k = len(SB)
    Lam = sum(c * E for c, E in zip(sol[:k], SB)); Pi = sum(c * E for c, E in zip(sol[k:], SB))
    assert np.linalg.norm(M @ sol + b) < 1e-8 * (1 + np.linalg.norm(b))
    return gP - X @ Pi, -gX + X @ Lam + P @ Pi


def bracket(f, g, X, P):
    fX, fP = grad(f, X, P)
    Xd, Pd = dirac_field(g, X, P)
    return np.sum(fX * Xd) + np.sum(fP * Pd)


def ddt(F, field, X, P, h=1e-30):
    Xd, Pd = field
    return np.imag(F(X + 1j * h * Xd, P + 1j * h * Pd)) / h


def kil(a, b):
    return -0.5 * np.trace(a @ b)


Phi = lambda X, P: P @ X.T - X @ P.T
Psi = lambda X, P: X.T @ P - P.T @ X

results = []


def report(name, val, scale=1.0):
    rel = abs(val) / max(scale, 1e-300)
    verdict = "TRUE (=0)" if rel < 1e-9 else "FALSE (!=0)"
    results.append((name, verdict, rel))
    print(f"{name:58s} {verdict:12s} |res|/scale = {rel:.2e}")


def run(n, r):
    print(f"--- (n, r) = ({n}, {r})")
    X, P, A = point(n, r)
    I = np.eye(n)
    xi, ze = skew(n), skew(n)
    et, th = skew(r), skew(r)
    # 1. Phi is a Poisson map to so(n)+, Psi to so(r)-
    b = bracket(lambda x, p: kil(Phi(x, p), xi), lambda x, p: kil(Phi(x, p), ze), X, P)
    report("v64-phi-poisson {Phi_xi,Phi_ze} - <Phi,[xi,ze]>", b - kil(Phi(X, P), xi @ ze - ze @ xi), abs(b) + 1)
    report("w64-phi-poisson {Phi_xi,Phi_ze} + <Phi,[xi,ze]>", b + kil(Phi(X, P), xi @ ze - ze @ xi), abs(b) + 1)
    b = bracket(lambda x, p: kil(Psi(x, p), et), lambda x, p: kil(Psi(x, p), th), X, P)
    report("v64-psi-antipoisson {Psi_et,Psi_th} + <Psi,[et,th]>", b + kil(Psi(X, P), et @ th - th @ et), abs(b) + 1)
    report("w64-psi-antipoisson {Psi_et,Psi_th} - <Psi,[et,th]>", b - kil(Psi(X, P), et @ th - th @ et), abs(b) + 1)
    # 3. Noether: H0 commutes with tr(S P^T P); the Euclidean H does not (r >= 2)
    S = sym(r)
    H0 = lambda x, p: 0.5 * np.trace(p.T @ p) - 0.5 * np.trace((x.T @ p) @ (x.T @ p))
    HE = lambda x, p: 0.5 * np.trace(p.T @ p)
    F = lambda x, p: np.trace(S @ p.T @ p)
    report("v64-normal-noether {H0, tr S PtP}", bracket(H0, F, X, P), 1 + abs(F(X, P)))
    report("w64-euclid-noether {HE, tr S PtP}", bracket(HE, F, X, P), 1 + abs(F(X, P)))
    # 4. orbit dimension 2l: rank of ad_Phi on so(n)
    basis = []
    for i in range(n):
        for j in range(i + 1, n):
            E = np.zeros((n, n)); E[i, j] = 1; E[j, i] = -1; basis.append(E)
    Ph = Phi(X, P)
    M = np.array([(E @ Ph - Ph @ E).ravel() for E in basis]).T
    rk = np.linalg.matrix_rank(M, tol=1e-9)
    two_l = n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)
    print(f"    rank ad_Phi = {rk}; Lemma 2l gives {two_l}; twin 2r(n-r) = {2*r*(n-r)}")
    # 5. Manakov flow, A(xi) = A xi + xi A
    def man_flow(x, p, op):
        M = op(Phi(x, p)); return M @ x, M @ p
    lam = 0.7
    L3 = lambda x, p: np.trace(np.linalg.matrix_power(Phi(x, p) + lam * A, 3))
    L3m = lambda x, p: np.trace(np.linalg.matrix_power(Phi(x, p) - lam * A, 3))
    fl = man_flow(X, P, lambda m: A @ m + m @ A)
    report("v64-manakov-integral d/dt tr(Phi+lam A)^3", ddt(L3, fl, X, P), 1 + abs(L3(X, P)))
    report("v64-manakov-sign-trap d/dt tr(Phi-lam A)^3", ddt(L3m, fl, X, P), 1 + abs(L3(X, P)))
    fl2 = man_flow(X, P, lambda m: A @ A @ m + m @ A @ A)
    report("w64-manakov-integral (op A^2 xi + xi A^2)", ddt(L3, fl2, X, P), 1 + abs(L3(X, P)))
    # 6. Theta = Phi + X X^T is Poisson into (gl(n), Lambda_1)
    u, w = rng.standard_normal((n, n)), rng.standard_normal((n, n))
    us, uy = (u - u.T) / 2, (u + u.T) / 2
    ws, wy = (w - w.T) / 2, (w + w.T) / 2
    Th = lambda x, p: Phi(x, p) + x @ x.T
    b = bracket(lambda x, p: kil(Th(x, p), u), lambda x, p: kil(Th(x, p), w), X, P)
    c = lambda a, bb: a @ bb - bb @ a
    T0 = Th(X, P)
    report("v64-theta-poisson {Theta_u,Theta_w} - Lambda1", b - kil(T0, c(us, ws) + c(us, wy) + c(uy, ws)), abs(b) + 1)
    report("w64-theta-poisson {Theta_u,Theta_w} - <Theta,[u,w]>", b - kil(T0, c(u, w)), abs(b) + 1)
    # 7. leaf dimension: rank of u -> [x, us] + skew([x, uy]) on gl(n)
    cols = []
    for i, j in itertools.product(range(n), range(n)):
        E = np.zeros((n, n)); E[i, j] = 1
        Es, Ey = (E - E.T) / 2, (E + E.T) / 2
        Y = c(T0, Es) + c(T0, Ey)
        # the covector of Lambda1(u, .) : <[x,xi],zeta> + <[x,xi],theta> + <[x,eta],zeta>
        img = c(T0, Es) + (c(T0, Ey) - c(T0, Ey).T) / 2
        cols.append(img.ravel())
    rk = np.linalg.matrix_rank(np.array(cols).T, tol=1e-9)
    f = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
    print(f"    rank Lambda1 at Theta = {rk}; (dimension) gives {f}; twin without [r/2] = {f + r//2}")
    # 8. Perelomov integrals in involution
    mu = -1.3
    L = lambda x, p, l: l * Phi(x, p) + x @ x.T - l * l * A
    Lw = lambda x, p, l: l * Phi(x, p) + x @ x.T - l * A
    f2 = lambda x, p: np.trace(np.linalg.matrix_power(L(x, p, lam), 2))
    g3 = lambda x, p: np.trace(np.linalg.matrix_power(L(x, p, mu), 3))
    report("v64-perelomov-involution {trL(l)^2,trL(m)^3}", bracket(f2, g3, X, P), 1 + abs(g3(X, P)))
    f2w = lambda x, p: np.trace(np.linalg.matrix_power(Lw(x, p, lam), 2))
    g3w = lambda x, p: np.trace(np.linalg.matrix_power(Lw(x, p, mu), 3))
    report("w64-perelomov-involution (lam A instead of lam^2 A)", bracket(f2w, g3w, X, P), 1 + abs(g3w(X, P)))
    # 9-11. dual Lax pair (Euclidean Neumann flow NE_XP)
    R = np.linalg.inv(lam * I - A)
    Ir = np.eye(r)
    def Lst(x, p, R=R):
        return np.block([[-x.T @ R @ p, -x.T @ R @ x], [Ir + p.T @ R @ p, p.T @ R @ x]])
    Lam = X.T @ A @ X - P.T @ P
    Xd = P; Pd = -A @ X - X @ P.T @ P + X @ X.T @ A @ X
    dL = (Lst(X + 1j * 1e-30 * Xd, P + 1j * 1e-30 * Pd).imag) / 1e-30
    L0 = Lst(X, P)
    Ast = np.block([[np.zeros((r, r)), Ir], [Lam - lam * Ir, np.zeros((r, r))]])
    Astw = np.block([[np.zeros((r, r)), Ir], [Lam + lam * Ir, np.zeros((r, r))]])
    report("v64-dual-lax-euclid dL*/dt - [L*,A*]", np.linalg.norm(dL - (L0 @ Ast - Ast @ L0)), np.linalg.norm(dL) + 1)
    report("w64-dual-lax-euclid (Lam + lam I)", np.linalg.norm(dL - (L0 @ Astw - Astw @ L0)), np.linalg.norm(dL) + 1)
    report("v64-dual-odd-traces tr L*^3", np.trace(L0 @ L0 @ L0), np.linalg.norm(L0) ** 3)
    Lt = np.block([[-X.T @ R @ P, -X.T @ R @ X], [Ir + P.T @ R @ P, X.T @ R @ P]])
    report("w64-dual-odd-traces (d block X^T R P) tr^3", np.trace(Lt @ Lt @ Lt), np.linalg.norm(Lt) ** 3)
    rhs = np.trace(R @ X @ X.T) - 0.5 * np.trace(R @ Ph @ R @ Ph)
    lhs = -0.5 * np.trace(L0 @ L0)
    report("v64-dual-I2 -1/2 tr L*^2 - I2/a", lhs - rhs, abs(lhs) + 1)
    rhsw = np.trace(R @ X @ X.T) + 0.5 * np.trace(R @ Ph @ R @ Ph)
    report("w64-dual-I2 (+1/2 tr RPhiRPhi)", lhs - rhsw, abs(lhs) + 1)


if __name__ == "__main__":
    for n, r in [(3, 1), (3, 2), (4, 2), (5, 2), (4, 3), (5, 3), (3, 3)]:
        run(n, r)
