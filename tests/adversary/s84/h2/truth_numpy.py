# ruff: noqa: E701,E702
"""Independent numerical truth for h2's claims (numpy only, no stiefelsym).
Random points of T*V: X = QR columns, P = Z - X sym(X^T Z)  (so X^T P + P^T X = 0).
Flows are computed from the Lagrange form by hand-derived formulas or by finite differences of
Hamiltonians + solving for multipliers (Dirac flow), independently of the printed formulas."""
import numpy as np
rng = np.random.default_rng(1)

def point(n, r):
    X, _ = np.linalg.qr(rng.standard_normal((n, n)))
    X = X[:, :r]
    Z = rng.standard_normal((n, r))
    S = X.T @ Z
    P = Z - X @ (S + S.T) / 2
    return X, P

def kill(a, b): return -0.5 * np.trace(a @ b)
def comm(a, b): return a @ b - b @ a
def skew(m): return (m - m.T) / 2
def symm(m): return (m + m.T) / 2

def grad(H, X, P, h=1e-6):
    gX = np.zeros_like(X); gP = np.zeros_like(P)
    for idx in np.ndindex(X.shape):
        E = np.zeros_like(X); E[idx] = h
        gX[idx] = (H(X + E, P) - H(X - E, P)) / (2 * h)
        gP[idx] = (H(X, P + E) - H(X, P - E)) / (2 * h)
    return gX, gP

def dirac_flow(H, X, P):
    """Xdot = H_P - X Pi, Pdot = -H_X + X Lam + P Pi; solve for sym Lam, Pi from the linearized constraints."""
    n, r = X.shape
    HX, HP = grad(H, X, P)
    symb = [(i, j) for i in range(r) for j in range(i, r)]
    def E(i, j):
        M = np.zeros((r, r)); M[i, j] = 1; M[j, i] = 1; return M
    def residual(Lam, Pi):
        Xd = HP - X @ Pi; Pd = -HX + X @ Lam + P @ Pi
        c1 = Xd.T @ X + X.T @ Xd
        c2 = Xd.T @ P + X.T @ Pd + Pd.T @ X + P.T @ Xd
        return np.concatenate([[c1[i, j] for i, j in symb], [c2[i, j] for i, j in symb]])
    Z = np.zeros((r, r))
    b0 = residual(Z, Z)
    cols = []
    for (i, j) in symb: cols.append(residual(E(i, j), Z) - b0)
    for (i, j) in symb: cols.append(residual(Z, E(i, j)) - b0)
    M = np.array(cols).T
    sol = np.linalg.solve(M, -b0)
    m = len(symb)
    Lam = sum(sol[k] * E(*symb[k]) for k in range(m)); Pi = sum(sol[m + k] * E(*symb[k]) for k in range(m))
    return HP - X @ Pi, -HX + X @ Lam + P @ Pi

def dd(F, X, P, V, h=1e-6):
    return (F(X + h * V[0], P + h * V[1]) - F(X - h * V[0], P - h * V[1])) / (2 * h)

def bracket(F, G, X, P):
    return dd(F, X, P, dirac_flow(G, X, P))

def Phi(X, P): return P @ X.T - X @ P.T
def Psi(X, P): return X.T @ P - P.T @ X

out = []
def rep(name, val, expect_zero=True):
    v = float(np.max(np.abs(val))) if np.size(val) else 0.0
    ok = (v < 1e-5) if expect_zero else (v > 1e-4)
    out.append((name, v, "TRUE" if ok == expect_zero else "FALSE"))
    print(f"{name:55s} |res|={v:.2e}  -> {'vanishes' if v < 1e-5 else 'NONZERO'}")

SIZES = [(n, r) for n in range(1, 6) for r in range(1, n + 1)]
for (n, r) in SIZES:
    print(f"==== n={n} r={r}")
    X, P = point(n, r)
    a = rng.standard_normal(n); A = np.diag(a)
    kap = 0.37
    R_lam = 0.7
    R = np.linalg.inv(R_lam * np.eye(n) - A)
    W = X.T @ P
    def Hk(k):
        return lambda X, P: 0.5*np.trace(P.T@P) - (0.5+k)*np.trace((X.T@P)@(X.T@P)) + 0.5*np.trace(X.T@A@X)
    # T1 sphere
    rep("T1 H_neum,kappa - H_neum,0 (kappa-dependence)", Hk(kap)(X, P) - Hk(0)(X, P))
    # T2
    f1 = dirac_flow(Hk(kap), X, P); f0 = dirac_flow(Hk(0), X, P)
    rep("T2 flow diff - 2k(XW,PW)", np.concatenate([(f1[0]-f0[0]) - 2*kap*X@W, (f1[1]-f0[1]) - 2*kap*P@W]))
    rep("T2 twin flow diff - 2k(XW,-PW)", np.concatenate([(f1[0]-f0[0]) - 2*kap*X@W, (f1[1]-f0[1]) + 2*kap*P@W]))
    Th = lambda X, P: Phi(X, P) + X @ X.T
    rep("T2 dTheta(XW,PW)", dd(Th, X, P, (X@W, P@W)))
    rep("T2 twin dTheta(XW,-PW)", dd(Th, X, P, (X@W, -P@W)))
    # T3 generic symmetric operator on so(n): AA(xi) = C xi C  with C sym? use random symmetric op in basis
    m = n*(n-1)//2
    basis = []
    for i in range(n):
        for j in range(i+1, n):
            E = np.zeros((n, n)); E[i, j] = 1; E[j, i] = -1; basis.append(E)
    G = rng.standard_normal((m, m)); G = G + G.T
    def coords(xi): return np.array([xi[i, j] for i in range(n) for j in range(i+1, n)])
    def AA(xi):
        c = G @ coords(skew(xi)); return sum(c[k]*basis[k] for k in range(m)) if m else 0*xi
    HA = lambda X, P: 0.5*kill(AA(Phi(X, P)), Phi(X, P))
    fA = dirac_flow(HA, X, P)
    Ph = Phi(X, P)
    dPhi = dd(Phi, X, P, fA)
    rep("T3 dPhi - [AA Phi, Phi]", dPhi - comm(AA(Ph), Ph))
    rep("T3 twin dPhi - [Phi, AA Phi]", dPhi - comm(Ph, AA(Ph)))
    rep("T3 dPsi, d(P^TP)", np.concatenate([dd(Psi, X, P, fA), dd(lambda X, P: P.T@P, X, P, fA)]))
    rep("T3 twin d(PP^T)", dd(lambda X, P: P@P.T, X, P, fA))
    rep("T3 Xdot - AA(Phi)X", fA[0] - AA(Ph)@X)
    # T4 B=A^3
    A3 = lambda xi: A@A@xi + A@xi@A + xi@A@A
    H3 = lambda X, P: 0.5*kill(A3(Phi(X, P)), Phi(X, P))
    f3 = dirac_flow(H3, X, P)
    lam = 0.9
    L = lambda X, P: Phi(X, P) + lam*A
    dL = dd(L, X, P, f3)
    rep("T4 dL - [A3 Phi + lam A^3, L]", dL - comm(A3(Ph) + lam*A@A@A, L(X, P)))
    rep("T4 twin dL - [A3 Phi - lam A^3, L]", dL - comm(A3(Ph) - lam*A@A@A, L(X, P)))
    rep("T4 twin2 dL - [A3 Phi + lam A^2, L]", dL - comm(A3(Ph) + lam*A@A, L(X, P)))
    # T5
    S = rng.standard_normal((r, r)); S = S + S.T
    man3 = lambda X, P: np.trace(np.linalg.matrix_power(Phi(X, P) + lam*A, 3))
    rep("T5 {tr(Phi+lA)^3, tr(S P^TP)}", bracket(man3, lambda X, P: np.trace(S@P.T@P), X, P))
    eta = rng.standard_normal((r, r)); eta = eta - eta.T
    rep("T5 {tr(Phi+lA)^2, Psi_eta}", bracket(lambda X, P: np.trace(np.linalg.matrix_power(Phi(X, P)+lam*A, 2)), lambda X, P: kill(Psi(X, P), eta), X, P))
    rep("T5 twin {tr(Phi+lA)^3, tr(S X^TAX)}", bracket(man3, lambda X, P: np.trace(S@X.T@A@X), X, P))
    # T6
    Mm = A@Ph + Ph@A
    Fx = (Mm@X, Mm@P)
    U = lambda X, P: np.hstack([P, X])
    Jm = np.block([[np.zeros((r, r)), np.eye(r)], [-np.eye(r), np.zeros((r, r))]])
    UR = lambda X, P: U(X, P).T@R@U(X, P)
    rep("T6 d(U^TRU) - U^T[R,M]U", dd(UR, X, P, Fx) - U(X, P).T@comm(R, Mm)@U(X, P))
    rep("T6 twin d(U^TRU) - U^T[M,R]U", dd(UR, X, P, Fx) - U(X, P).T@comm(Mm, R)@U(X, P))
    Lman = lambda X, P: np.block([[-X.T@R@P, -X.T@R@X], [P.T@R@P, P.T@R@X]])
    rep("T6 Lman = -J U^TRU", Lman(X, P) + Jm@UR(X, P))
    Acorr = Jm@U(X, P).T@(A + R_lam*np.eye(n))@U(X, P)
    rep("T6 corrected dLman - [Lman, J U^T(A+l)U]", dd(Lman, X, P, Fx) - comm(Lman(X, P), Acorr))
    Ri = np.linalg.inv(A + R_lam*np.eye(n))
    Apr = np.block([[X.T@Ri@P, X.T@Ri@X], [-P.T@Ri@P, -P.T@Ri@X]])
    rep("T6 printed (erratum) dLman - [Lman, A*printed]", dd(Lman, X, P, Fx) - comm(Lman(X, P), Apr))
    rep("T6 corrected A* = printed shape with (A+l)", Acorr - np.block([[X.T@(A+R_lam*np.eye(n))@P, X.T@(A+R_lam*np.eye(n))@X], [-P.T@(A+R_lam*np.eye(n))@P, -P.T@(A+R_lam*np.eye(n))@X]]))
    # T7
    Sr = np.eye(n); Sr[0, 0] = -1
    F3 = lambda X, P: ((A@Phi(X, P)+Phi(X, P)@A)@X, (A@Phi(X, P)+Phi(X, P)@A)@P)
    a1, b1 = F3(Sr@X, Sr@P); a0, b0 = F3(X, P)
    rep("T7 F(SX,SP) - S F(X,P)", np.concatenate([a1 - Sr@a0, b1 - Sr@b0]))
    rep("T7 twin F(SX,SP) - F(X,P)", np.concatenate([a1 - a0, b1 - b0]))
    rep("T7 Lman(SX,SP)-Lman", Lman(Sr@X, Sr@P) - Lman(X, P))
    # T8
    HJ = lambda X, P: 0.5*kill(Phi(X, P), Phi(X, P)) + kap/2*kill(Psi(X, P), Psi(X, P))
    rep("T8 {tr (P^TP)^2, H_k}", bracket(lambda X, P: np.trace((P.T@P)@(P.T@P)), HJ, X, P))
    rep("T8 {tr(P^TP Psi^2), H_k}", bracket(lambda X, P: np.trace(P.T@P@Psi(X, P)@Psi(X, P)), HJ, X, P))
    rep("T8 twin {tr(S P^TP), H_k}", bracket(lambda X, P: np.trace(S@P.T@P), HJ, X, P))
    # T9
    rep("T9 {tr(S P^TP), <Psi,Psi>} (not-claim)", bracket(lambda X, P: np.trace(S@P.T@P), lambda X, P: kill(Psi(X, P), Psi(X, P)), X, P))
    # T13 rank of Lambda1 at Theta, T12 rank of Lambda_{1,-1}
    h = Ph; v = X@X.T; x = h + v
    gl = []
    for i in range(n):
        for j in range(n):
            E = np.zeros((n, n)); E[i, j] = 1; gl.append(E)
    F1 = lambda y: comm(x, skew(y)) + comm(v, symm(y))
    M1 = np.array([F1(y).ravel() for y in gl]).T
    r1 = np.linalg.matrix_rank(M1, tol=1e-8)
    print(f"T13 rank Lambda1(Theta) = {r1}; printed 2l = {2*r*(n-r) + r*(r-1)//2 - r//2}; twin {2*r*(n-r)+r*(r-1)//2}")
    F2 = lambda y: comm(A, symm(y)) + comm(A, skew(y)) - comm(h, symm(y))
    M2 = np.array([F2(y).ravel() for y in gl]).T
    print(f"T12 rank Lambda_(1,-1)(Theta) = {np.linalg.matrix_rank(M2, tol=1e-8)}; n^2-n = {n*n-n}")
    # check my F2 against the definition Lambda1 - Lambda2 directly
    def L1(x, y, z): return kill(x, comm(skew(y), skew(z)) + comm(skew(y), symm(z)) + comm(symm(y), skew(z)))
    def L2(x, y, z): return kill(x - A, comm(y, z))
    y = rng.standard_normal((n, n)); z = rng.standard_normal((n, n))
    rep("T11 Lambda_{1,-1} printed formula", (L1(x, y, z) - L2(x, y, z)) - (-kill(h, comm(symm(y), symm(z))) + kill(A, comm(skew(y), symm(z)) + comm(symm(y), skew(z)))))
    rep("T11 twin +<h,[eta,theta]>", (L1(x, y, z) - L2(x, y, z)) - (kill(h, comm(symm(y), symm(z))) + kill(A, comm(skew(y), symm(z)) + comm(symm(y), skew(z)))))
    rep("T12 F2 represents Lambda_{1,-1}", (L1(x, y, z) - L2(x, y, z)) - kill(F2(y), z))
    rep("T13 F1 represents Lambda1", L1(x, y, z) - kill(F1(y), z))
    # T10 Casimirs
    xg = rng.standard_normal((n, n)); b = rng.standard_normal((n, n))
    for k in (2, 3):
        gv = -2*k*np.linalg.matrix_power(symm(xg), k-1)
        rep(f"T10 Lambda1(grad tr v^{k}, b)", L1(xg, gv, b))
        gA = -2*k*np.linalg.matrix_power(xg - A, k-1)
        rep(f"T10 Lambda2(grad tr(x-A)^{k}, b)", L2(xg, gA, b))
        gAp = -2*k*np.linalg.matrix_power(xg + A, k-1)
        rep(f"T10 twin Lambda2(grad tr(x+A)^{k}, b)", L2(xg, gAp, b))
    # T14 rank of dTheta on T*V
    def jac(F, X, P, h=1e-6):
        cols = []
        for idx in np.ndindex(X.shape):
            E = np.zeros_like(X); E[idx] = h
            cols.append(((F(X+E, P)-F(X-E, P))/(2*h)).ravel())
        for idx in np.ndindex(P.shape):
            E = np.zeros_like(P); E[idx] = h
            cols.append(((F(X, P+E)-F(X, P-E))/(2*h)).ravel())
        return np.array(cols).T
    cons = lambda X, P: np.concatenate([(X.T@X)[np.triu_indices(r)], (X.T@P+P.T@X)[np.triu_indices(r)]])
    Jt = np.vstack([jac(Th, X, P), jac(cons, X, P)])
    dimV = r*n - r*(r+1)//2
    print(f"T14 rank[dTheta;dF] = {np.linalg.matrix_rank(Jt, tol=1e-6)}; claim 2dimV - r(r-1)/2 + r(r+1) = {2*dimV - r*(r-1)//2 + r*(r+1)}; twin {2*dimV + r*(r+1)}")
    # T15 J_k
    Jk = lambda k: (lambda X, P: np.trace(np.linalg.matrix_power(Psi(X, P), 2*k)))
    rep("T15 {tr Psi^2, tr (P^TP)^2}", bracket(Jk(1), lambda X, P: np.trace((P.T@P)@(P.T@P)), X, P))
    per2 = lambda X, P: np.trace(np.linalg.matrix_power(lam*Phi(X, P) + X@X.T - lam*lam*A, 2))
    rep("T15 {tr Psi^2, perelomov_2}", bracket(Jk(1), per2, X, P))
    rep("T15 twin {tr Psi^2, tr(S P^TP)}", bracket(Jk(1), lambda X, P: np.trace(S@P.T@P), X, P))
    if r >= 2:
        kk = r//2
        JJ = lambda X, P: np.array([Jk(k)(X, P) for k in range(1, kk+2)])
        J1 = np.vstack([jac(lambda X, P: JJ(X, P)[:kk], X, P), jac(cons, X, P)])
        J2 = np.vstack([jac(JJ, X, P), jac(cons, X, P)])
        print(f"T15 rank J_1..J_[r/2] (+cons) = {np.linalg.matrix_rank(J1, tol=1e-6)} want {kk + r*(r+1)}; with J_[r/2]+1: {np.linalg.matrix_rank(J2, tol=1e-6)} twin-want {kk+1+r*(r+1)}")
    # T16
    Hc = lambda h, v: 0.5*kill(h, h) - kill(A, v)
    rep("T16 H_neum,k - H(Theta) - k/2<Psi,Psi>", Hk(kap)(X, P) - Hc(Ph, v) - kap/2*kill(Psi(X, P), Psi(X, P)))
    rep("T16 twin +<A,v>", Hk(kap)(X, P) - (0.5*kill(Ph, Ph) + kill(A, v)) - kap/2*kill(Psi(X, P), Psi(X, P)))
    # T17
    rep("T17 A R - (lam R - I)", A@R - (R_lam*R - np.eye(n)))
    rep("T17 twin A R - (lam R + I)", A@R - (R_lam*R + np.eye(n)))
    # T18 right action
    Ld = lambda X, P: np.block([[-X.T@R@P, -X.T@R@X], [np.eye(r)+P.T@R@P, P.T@R@X]])
    K = np.block([[eta, np.zeros((r, r))], [np.zeros((r, r)), eta]])
    dLr = dd(Ld, X, P, (X@eta, P@eta))
    rep("T18 dL* along (X eta,P eta) - [L*,K]", dLr - comm(Ld(X, P), K))
    rep("T18 twin - [K,L*]", dLr - comm(K, Ld(X, P)))
    # T19
    Lv = Ld(X, P)
    rep("T19 -1/2 tr L*^2 - (tr(R XX^T) - 1/2 tr(R Phi R Phi))", -0.5*np.trace(Lv@Lv) - (np.trace(R@X@X.T) - 0.5*np.trace(R@Ph@R@Ph)))
    rep("T19 twin +1/2", -0.5*np.trace(Lv@Lv) - (np.trace(R@X@X.T) + 0.5*np.trace(R@Ph@R@Ph)))
    # e2 via explicit I2 printed
    I2 = sum(X[i, :]@X[i, :]/(R_lam - a[i]) for i in range(n)) + sum(Ph[i, j]**2/((R_lam-a[i])*(R_lam-a[j])) for i in range(n) for j in range(i+1, n))
    rep("T19 (cross) e2 = printed I_2/a", -0.5*np.trace(Lv@Lv) - I2)
    # T20
    Lam = X.T@A@X - P.T@P
    FN = (P - X@P.T@X, -A@X + P@X.T@P - X@P.T@P + X@X.T@A@X)
    FE = (P, -A@X - X@P.T@P + X@X.T@A@X)
    AN = np.block([[X.T@P, np.eye(r)], [Lam - R_lam*np.eye(r), -P.T@X]])
    AE = np.block([[np.zeros((r, r)), np.eye(r)], [Lam - R_lam*np.eye(r), np.zeros((r, r))]])
    rep("T20 normal: dL*(N0_XP2) - [L*, A_N]", dd(Ld, X, P, FN) - comm(Lv, AN))
    rep("T20 twin normal flow with A_E", dd(Ld, X, P, FN) - comm(Lv, AE))
    rep("T20 euclid: dL*(NE_XP) - [L*, A_E]", dd(Ld, X, P, FE) - comm(Lv, AE))
    rep("T20 twin euclid with Lman (no I_r)", dd(Lman, X, P, FE) - comm(Lman(X, P), AE))
    # also check printed flows equal the Dirac flows
    rep("T20 (cross) N0_XP2 = Dirac flow H_neum,0", np.concatenate([FN[0]-f0[0], FN[1]-f0[1]]))
    fE = dirac_flow(Hk(-0.5), X, P)
    rep("T20 (cross) NE_XP = Dirac flow H_neum,-1/2", np.concatenate([FE[0]-fE[0], FE[1]-fE[1]]))
    if r == 1:
        e = X[:, 0]; p = P[:, 0]
        Fi = [e[i]**2 + sum((e[i]*p[j]-e[j]*p[i])**2/(a[i]-a[j]) for j in range(n) if j != i) for i in range(n)]
        rep("T21 sum F_i - 1", sum(Fi) - 1)
        rep("T21 sum a_i F_i - ((Ae,e)+(p,p))", sum(a[i]*Fi[i] for i in range(n)) - (e@A@e + p@p))
        rep("T21 twin sum a_i F_i - ((Ae,e)+2(p,p))", sum(a[i]*Fi[i] for i in range(n)) - (e@A@e + 2*p@p))
        Ai = np.linalg.inv(A)
        rep("T21 sum F_i/a_i", sum(Fi[i]/a[i] for i in range(n)) - ((e@Ai@e)*(1 - p@Ai@p) + (e@Ai@p)**2))
        rep("T21 twin sum F_i/a_i sign", sum(Fi[i]/a[i] for i in range(n)) - ((e@Ai@e)*(1 + p@Ai@p) + (e@Ai@p)**2))
