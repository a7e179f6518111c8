"""False twins of the statements in claims.py: each changes one sign, factor or transpose.
Every one must be refuted (`fails` for kind id/dim; for the not-claim twin, `fails` as well).

    stiefelsym verify --claims tests/adversary/s61/hidden/negatives.py --method auto --jobs 1 --no-report
"""
from itertools import combinations

from stiefelsym import Count, admissible, claim, comm, det
from stiefelsym.systems import derivative, double_point

SMALL = admissible(n_max=4)
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2")
R_GE_2_BELOW_N = admissible(n_max=4, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n")
N_GE_3 = admissible(n_max=4, n_min=3, condition="n >= 3")


def H_AA(t):
    AA = t.sym_operator("AA")
    return t.killing(AA(t.Phi), t.Phi) / 2


@claim("hn-submersion-gradient-sign", paper=("dot_XP2",), kind="id", section="3", sizes=SMALL)
def submersion_gradient_sign(s):
    """FALSE twin: -dH/dX = -AA(Phi) P (sign flipped)."""
    HX, HP = s.gradient(H_AA)
    AA = s.sym_operator("AA")
    return {"dH/dP - AA(Phi) X": HP - AA(s.Phi) @ s.X,
            "-dH/dX + AA(Phi) P": -HX + AA(s.Phi) @ s.P}


def cayley(s):
    return (s.Ir - s.eta) @ (s.Ir + s.eta).inv()


def H_kappa_at(s, X, P):
    K = X.T @ P
    return s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(K @ K)


@claim("hn-isotropy-no-transpose", paper=("EM", "P-neutral"), kind="id", section="4", sizes=R_GE_2)
def isotropy_no_transpose(s):
    """FALSE twin: P1 -> Q P1 Q (Q in place of Q^{-1} = Q^T) keeps the fibre and H_kappa."""
    X, P = s.X, s.P
    Q = cayley(s)
    P2 = X @ Q @ X.T @ P @ Q + (s.In - X @ X.T) @ P @ Q
    return {"X^T P' + P'^T X": X.T @ P2 + P2.T @ X,
            "H_kappa(X, P') - H_kappa(X, P)": H_kappa_at(s, X, P2) - H_kappa_at(s, X, P)}


def lambda1(t, x, xi, eta, zeta, theta):
    return t.killing(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))


def lambda2(t, x, xi, eta, zeta, theta):
    return t.killing(x - t.A, comm(xi + eta, zeta + theta))


@claim("hn-pencil-isomorphism-no-square", paper=("LAMBDA12", "central"), kind="id", section="6", sizes=SMALL)
def pencil_isomorphism_no_square(s):
    """FALSE twin: y = s h + v - s A (s in place of s^2)."""
    sc, c = s.scalar("s"), s.scalar("c")
    h = s.generic("h", "n", "n", "skew")
    v = s.generic("v", "n", "n", "sym")
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta_n", "n", "n", "sym"), s.generic("theta_n", "n", "n", "sym")
    x = h + v
    l1, l2 = c * (1 - sc * sc), c * sc * sc
    pencil = l1 * lambda1(s, x, xi, eta, zeta, theta) + l2 * lambda2(s, x, xi, eta, zeta, theta)
    y = sc * h + v - sc * s.A
    return {"residual": sc * pencil - c * s.killing(y, comm(xi + sc * eta, zeta + sc * theta))}


@claim("hn-lema1-eta3-sign", paper=("LEMA1", "L2"), kind="id", section="6", sizes=R_GE_2)
def lema1_eta3_sign(s):
    """FALSE twin: eta = +Q[xi,h]v - v[xi,h]Q + ... (sign of the eta_3 block flipped)."""
    X, h = s.X, s.Phi
    v = X @ X.T
    Q = s.In - v
    xi = X @ s.Psi @ X.T + Q @ s.zeta @ Q
    C = comm(xi, h)
    S1 = s.generic("S1", "r", "r", "sym")
    S2 = s.generic("S2", "n", "n", "sym")
    eta = Q @ C @ v - v @ C @ Q + X @ S1 @ X.T + Q @ S2 @ Q
    return {"(L2) [xi, h] + [eta, v]": C + comm(eta, v)}


def diag_of(s, G):
    n = s.n
    return s.mat([[G[i, j] if i == j else 0 for j in range(n)] for i in range(n)])


@claim("hn-lema2-kernel-sign", paper=("LEMA2", "L4"), kind="id", section="6", sizes=admissible(n_max=4, n_min=2),
       exact_max_n=3)
def lema2_kernel_sign(s):
    """FALSE twin: xi_ij = [eta, h]_ij/(a_i - a_j) (sign flipped)."""
    n, a = s.n, s.a
    h = s.Phi
    eta = diag_of(s, s.generic("G", "n", "n", "sym"))
    C = comm(eta, h)
    xi = s.mat([[0 if i == j else C[i, j] / (a[i] - a[j]) for j in range(n)] for i in range(n)])
    return {"(L4) [xi, A] - [eta, h]": comm(xi, s.A) - comm(eta, h)}


def script_V(s):
    n, r = s.n, s.r
    rows = [[s.X[i, j] for j in range(r)] + [s.P[i, j] for j in range(r)] for i in range(n)]
    rows += [[0] * r + [1 if j == k else 0 for j in range(r)] for k in range(r)]
    return rows


@claim("hn-plucker-V-unsigned", paper=("VV", "forms"), kind="id", section="8", sizes=R_GE_2_BELOW_N)
def plucker_V_unsigned(s):
    """FALSE twin: the minors omitting y_k equal (e1..er p_k)_I without the sign (-1)^{k-1} (wrong for k = 2)."""
    n, r = s.n, s.r
    V = script_V(s)
    bottom = list(range(n, n + r))
    checks = {}
    I = tuple(range(r + 1))
    k = 1
    M = s.mat([[s.X[i, j] for j in range(r)] + [s.P[i, k]] for i in I])
    idx = list(I) + [b for b in bottom if b != n + k]
    checks["minor w/o y1 - (e1..er p1)_I"] = det(s, s.mat([V[i] for i in idx])) - det(s, M)
    return checks


def Lambda_double(t, z):
    return z["X"].T @ t.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]


def flow_double(t, z):
    Lam = Lambda_double(t, z)
    return {"X": z["Xdot"], "Y": z["Ydot"],
            "Xdot": -(t.A @ z["X"]) + z["X"] @ Lam.T, "Ydot": -(t.A @ z["Y"]) + z["Y"] @ Lam}


@claim("hn-double-xdot-ydot", paper=("D-eq",), kind="id", section="A2", sizes=SMALL)
def double_xdot_ydot(s):
    """FALSE twin: Xdot^T Ydot (instead of X^T Ydot) is conserved along (D-eq)."""
    z = double_point(s)
    return {"d/dt Xdot^T Ydot": derivative(s, lambda t, w: w["Xdot"].T @ w["Ydot"], z, flow_double(s, z))}


@claim("hn-submersion-left-invariant", paper=("submersion_metric",), kind="id", section="3", sizes=N_GE_3)
def submersion_left_invariant(s):
    """FALSE twin: a generic submersion metric H_AA is left SO(n)-invariant."""
    return {"d H_AA along (xi X, xi P)": s.d(H_AA, {"X": s.xi @ s.X, "P": s.xi @ s.P})}


@claim("hn-proof-counts-no-rank", paper=("LEMA1", "dimension"), kind="dim", section="6", sizes=R_GE_2)
def proof_counts_no_rank(s):
    """FALSE twin: dim ker Lambda_1(h+v) without the rank so(r) term."""
    n, r = s.n, s.r
    m = n - r
    ker = m * (m - 1) // 2 + r * (r + 1) // 2 + m * (m + 1) // 2
    return {"2l": Count(n * n - ker, 2 * r * m + r * (r - 1) // 2 - r // 2)}


@claim("hn-plucker-V-sign-k2", paper=("VV", "forms"), kind="id", section="8",
       sizes=admissible(n_max=4, r_min=3, where=lambda n, r: r < n, condition="3 <= r < n"))
def plucker_V_sign_k2(s):
    """FALSE twin (only where k = 3 exists, r >= 3): sign (-1)^{(k-1)(k-2)/2} in place of (-1)^{k-1}; it agrees for k = 1, 2."""
    n, r = s.n, s.r
    V = script_V(s)
    bottom = list(range(n, n + r))
    checks = {}
    for I in combinations(range(n), r + 1):
        for k in range(r):
            M = s.mat([[s.X[i, j] for j in range(r)] + [s.P[i, k]] for i in I])
            idx = list(I) + [b for b in bottom if b != n + k]
            checks[f"minor{I} w/o y{k}"] = det(s, s.mat([V[i] for i in idx])) - (-1) ** (k * (k - 1) // 2) * det(s, M)
    return checks


@claim("hn-pencil-tiny-offset", paper=("LAMBDA12",), kind="id", section="6", sizes=SMALL)
def pencil_tiny_offset(s):
    """FALSE twin: the pencil identity with a residual offset 10^-20 * c (a tiny nonzero constant); float must not pass it."""
    sc, c = s.scalar("s"), s.scalar("c")
    h = s.generic("h", "n", "n", "skew")
    v = s.generic("v", "n", "n", "sym")
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta_n", "n", "n", "sym"), s.generic("theta_n", "n", "n", "sym")
    x = h + v
    l1, l2 = c * (1 - sc * sc), c * sc * sc
    pencil = l1 * lambda1(s, x, xi, eta, zeta, theta) + l2 * lambda2(s, x, xi, eta, zeta, theta)
    y = sc * h + v - sc * sc * s.A
    return {"residual": sc * pencil - c * s.killing(y, comm(xi + sc * eta, zeta + sc * theta)) + s.q(1, 10 ** 20) * c}


@claim("hn-submersion-not-left-invariant-n2", paper=("submersion_metric",), kind="not", expect="nonzero",
       section="3", sizes=admissible(n_max=2, n_min=2, condition="n = 2"))
def submersion_not_left_invariant_n2(s):
    """FALSE (kind not): for n = 2, so(2) is 1-dimensional, AA is a scalar and H_AA IS left-invariant."""
    return {"d H_AA along (xi X, xi P)": s.d(H_AA, {"X": s.xi @ s.X, "P": s.xi @ s.P})}
