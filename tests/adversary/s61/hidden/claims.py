"""Nine statements of Fedorov & Jovanovic that the catalog and examples/paper_extra*.py do not state
(or state only in another form): steps inside proofs of Sections 3, 4, 6, 8 and Appendix 2.

    stiefelsym verify --claims tests/adversary/s61/hidden/claims.py --method auto --jobs 1 --no-report

Only the public API (stiefelsym's exports, stiefelsym.systems, the scene s).
"""
from itertools import combinations

from stiefelsym import Count, admissible, claim, comm, det
from stiefelsym.systems import derivative, double_point

SMALL = admissible(n_max=4)
R_BELOW_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")
N_GE_3 = admissible(n_max=4, n_min=3, condition="n >= 3")


# --------------------------------------------------------------------------------------------
def H_AA(t):
    """(submersion_metric): H_AA = 1/2 <AA(Phi), Phi>."""
    AA = t.sym_operator("AA")
    return t.killing(AA(t.Phi), t.Phi) / 2


@claim("h-submersion-gradient", paper=("dot_XP2", "submersion_metric"), kind="id", section="3", sizes=SMALL,
       statement=r"\partial H_{\mathbb A}/\partial P=\mathbb A(\Phi)X,\ -\partial H_{\mathbb A}/\partial X=\mathbb A(\Phi)P")
def submersion_gradient(s):
    """Proof of the Proposition giving (dot_XP2), Section 3: by the chain rule dH = dh_AA o dPhi the derivatives of (submersion_metric) with respect to P and -X are AA(Phi) X and AA(Phi) P (on the whole ambient space)."""
    HX, HP = s.gradient(H_AA)
    AA = s.sym_operator("AA")
    return {"dH/dP - AA(Phi) X": HP - AA(s.Phi) @ s.X,
            "-dH/dX - AA(Phi) P": -HX - AA(s.Phi) @ s.P}


# --------------------------------------------------------------------------------------------
def cayley(s):
    """Q = (I - eta)(I + eta)^{-1} in SO(r), eta in so(r)."""
    return (s.Ir - s.eta) @ (s.Ir + s.eta).inv()


def H_kappa_at(s, X, P):
    """(EM) evaluated at an arbitrary pair (X, P): 1/2 tr(P^T P) - (1/2 + kappa) tr((X^T P)^2)."""
    K = X.T @ P
    return s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(K @ K)


@claim("h-isotropy-invariance", paper=("EM", "P-neutral", "SO(n-r)-action"), kind="id", section="4", sizes=SMALL,
       statement=r"P'=XQ^TX^TPQ+(I-XX^T)PQ:\ X^TP'+P'^TX=0,\ X^TP'=Q^TX^TPQ,\ H_\kappa(X,P')=H_\kappa(X,P)")
def isotropy_invariance(s):
    """Proof of the Proposition after the Remark to Theorem ET (Section 4): on T*_X V the transformation P1 -> Q^{-1} P1 Q, P2 -> P2 Q (P1 = X^T P, P2 = (I - XX^T)P, Q in SO(r), here a Cayley transform) maps the fibre into itself and leaves H_kappa (EM) invariant for every kappa."""
    X, P = s.X, s.P
    Q = cayley(s)
    P2 = X @ Q.T @ X.T @ P @ Q + (s.In - X @ X.T) @ P @ Q
    return {"Q^T Q - I": Q.T @ Q - s.Ir,
            "X^T P' + P'^T X": X.T @ P2 + P2.T @ X,
            "X^T P' - Q^T X^T P Q": X.T @ P2 - Q.T @ X.T @ P @ Q,
            "H_kappa(X, P') - H_kappa(X, P)": H_kappa_at(s, X, P2) - H_kappa_at(s, X, P)}


# --------------------------------------------------------------------------------------------
def lambda1(t, x, xi, eta, zeta, theta):
    """(LAMBDA12): Lambda_1(xi + eta, zeta + theta)|_x."""
    return t.killing(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))


def lambda2(t, x, xi, eta, zeta, theta):
    """(LAMBDA12): Lambda_2(xi + eta, zeta + theta)|_x."""
    return t.killing(x - t.A, comm(xi + eta, zeta + theta))


@claim("h-pencil-isomorphism", paper=("LAMBDA12", "central"), kind="id", section="6", sizes=SMALL,
       statement=r"s\,\Lambda_{c(1-s^2),cs^2}(\xi+\eta,\zeta+\theta)|_{h+v}=c\langle sh+v-s^2A,[\xi+s\eta,\zeta+s\theta]\rangle")
def pencil_isomorphism(s):
    """Section 6, proof of Theorem NEUMANN: for lambda_2 != 0 the bracket Lambda_{lambda1,lambda2} is isomorphic to the Lie-Poisson bracket of gl(n): with lambda1 + lambda2 = c, lambda2 = c s^2 (s^2 = lambda2/(lambda1+lambda2)), it is the Lie-Poisson tensor at y = s h + v - s^2 A composed with xi + eta -> xi + s eta (which is why its Casimirs are tr(s h + v - s^2 A)^k)."""
    sc, c = s.scalar("s"), s.scalar("c")
    h = s.generic("h", "n", "n", "skew")
    v = s.generic("v", "n", "n", "sym")
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta_n", "n", "n", "sym"), s.generic("theta_n", "n", "n", "sym")
    x = h + v
    l1, l2 = c * (1 - sc * sc), c * sc * sc
    pencil = l1 * lambda1(s, x, xi, eta, zeta, theta) + l2 * lambda2(s, x, xi, eta, zeta, theta)
    y = sc * h + v - sc * sc * s.A
    return {"s Lambda_{l1,l2} - c <y, [.,.]>": sc * pencil - c * s.killing(y, comm(xi + sc * eta, zeta + sc * theta))}


# --------------------------------------------------------------------------------------------
@claim("h-lema1-eta3", paper=("LEMA1", "L1", "L2"), kind="id", section="6", sizes=SMALL,
       statement=r"\xi=X\Psi X^T+Q\zeta Q,\ \eta=-Q[\xi,h]v+v[\xi,h]Q+XS_1X^T+QS_2Q:\ [\xi,v]=0,\ [\xi,h]+[\eta,v]=0")
def lema1_eta3(s):
    """Proof of Lemma LEMA1: at h = Phi, v = XX^T (Q = I - v), for xi = X Psi X^T + Q zeta Q (xi_1 = Psi commutes with h_1 = Psi, xi_2 arbitrary) and arbitrary eta_1, eta_2, the block eta_3 is determined by (L2): eta = -Q[xi,h]v + v[xi,h]Q + X S1 X^T + Q S2 Q solves (L1), (L2), so xi + eta is in ker Lambda_1(h + v)."""
    X, h = s.X, s.Phi
    v = X @ X.T
    Q = s.In - v
    xi = X @ s.Psi @ X.T + Q @ s.zeta @ Q
    C = comm(xi, h)
    S1 = s.generic("S1", "r", "r", "sym")
    S2 = s.generic("S2", "n", "n", "sym")
    eta = -(Q @ C @ v) + v @ C @ Q + X @ S1 @ X.T + Q @ S2 @ Q
    z2 = s.generic("z2", "n", "n", "skew")
    th = s.generic("th", "n", "n", "sym")
    return {"eta - eta^T": eta - eta.T,
            "(L1) [xi, v]": comm(xi, v),
            "(L2) [xi, h] + [eta, v]": C + comm(eta, v),
            "Lambda_1(xi + eta, z + th)": lambda1(s, h + v, xi, eta, z2, th)}


# --------------------------------------------------------------------------------------------
def diag_of(s, G):
    n = s.n
    return s.mat([[G[i, j] if i == j else 0 for j in range(n)] for i in range(n)])


def lema2_xi(s, eta, h, sign=1):
    """xi_ij = [eta, h]_ij / (a_j - a_i) (i != j), xi_ii = 0."""
    n, a = s.n, s.a
    C = comm(eta, h)
    return s.mat([[0 if i == j else sign * C[i, j] / (a[j] - a[i]) for j in range(n)] for i in range(n)])


@claim("h-lema2-kernel", paper=("LEMA2", "LAMBDA", "L3", "L4"), kind="id", section="6", sizes=SMALL,
       exact_max_n=3,
       statement=r"\eta\ \text{diagonal},\ \xi_{ij}=\frac{[\eta,h]_{ij}}{a_j-a_i}:\ [\eta,A]=0,\ [\xi,A]-[\eta,h]=0,\ "
                 r"\Lambda_{1,-1}(\xi+\eta,\cdot)|_{h+v}=0")
def lema2_kernel(s):
    """Proof of Lemma LEMA2: the solutions of (L3) are the diagonal matrices eta, and for each of them (L4) determines xi uniquely, xi_ij = [eta, h]_ij/(a_j - a_i): an n-dimensional kernel of Lambda_{1,-1} = Lambda_1 - Lambda_2 at h + v = Theta(X, P) (the number n is missing in the printed sentence)."""
    h, v = s.Phi, s.X @ s.X.T
    eta = diag_of(s, s.generic("G", "n", "n", "sym"))
    xi = lema2_xi(s, eta, h)
    z2 = s.generic("z2", "n", "n", "skew")
    th = s.generic("th", "n", "n", "sym")
    x = h + v
    return {"(L3) [eta, A]": comm(eta, s.A),
            "(L4) [xi, A] - [eta, h]": comm(xi, s.A) - comm(eta, h),
            "xi + xi^T": xi + xi.T,
            "Lambda_{1,-1}(xi + eta, z + th)": lambda1(s, x, xi, eta, z2, th) - lambda2(s, x, xi, eta, z2, th)}


# --------------------------------------------------------------------------------------------
def script_V(s):
    """(VV): the (n + r) x 2r matrix [[X, P], [0, I_r]]."""
    n, r = s.n, s.r
    rows = [[s.X[i, j] for j in range(r)] + [s.P[i, j] for j in range(r)] for i in range(n)]
    rows += [[0] * r + [1 if j == k else 0 for j in range(r)] for k in range(r)]
    return rows


def minor(s, rows, idx):
    return det(s, s.mat([rows[i] for i in idx]))


def plucker_checks(s, signed=True):
    n, r = s.n, s.r
    V = script_V(s)
    bottom = list(range(n, n + r))
    checks = {}
    for I in combinations(range(n), r):
        XI = s.mat([[s.X[i, j] for j in range(r)] for i in I])
        checks[f"minor{I}+I_r - det X_I"] = minor(s, V, list(I) + bottom) - det(s, XI)
    for I in list(combinations(range(n), r + 1))[:3]:
        for k in range(r):
            M = s.mat([[s.X[i, j] for j in range(r)] + [s.P[i, k]] for i in I])
            sign = (-1) ** k if signed else 1
            idx = list(I) + [b for b in bottom if b != n + k]
            checks[f"minor{I} w/o y{k} - (e1..er p{k})_I"] = minor(s, V, idx) - sign * det(s, M)
    return checks


@claim("h-plucker-V", paper=("VV", "forms", "2r-integrals"), kind="id", section="8", sizes=R_BELOW_N,
       statement=r"|\mathcal V|_{I_r\cup\{y\}}=(e_1\wedge\dots\wedge e_r)_{I_r},\ "
                 r"|\mathcal V|_{I_{r+1}\cup\{y\}\setminus y_k}=(-1)^{k-1}(e_1\wedge\dots\wedge e_r\wedge p_k)_{I_{r+1}}")
def plucker_V(s):
    """Section 8 after (VV): the 2r x 2r minors of V that contain the whole block I_r are the Pluecker coordinates of span(e_1..e_r); those that omit one row y_k of I_r are (up to the sign (-1)^{k-1}) the coordinates of e_1 ^ ... ^ e_r ^ p_k."""
    return plucker_checks(s)


# --------------------------------------------------------------------------------------------
def Lambda_double(t, z):
    """(D-L)."""
    return z["X"].T @ t.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]


def flow_double(t, z):
    """(D-eq) as a first-order system."""
    Lam = Lambda_double(t, z)
    return {"X": z["Xdot"], "Y": z["Ydot"],
            "Xdot": -(t.A @ z["X"]) + z["X"] @ Lam.T, "Ydot": -(t.A @ z["Y"]) + z["Y"] @ Lam}


@claim("h-double-xydot", paper=("dual-D", "D-eq", "D-L", "D0"), kind="id", section="A2", sizes=SMALL,
       statement=r"\tfrac{d}{dt}(X^T\dot Y)=0,\quad X^T\dot Y-Y^T\dot X=X^T\dot Y+(X^T\dot Y)^T")
def double_xydot(s):
    """Appendix 2 after Theorem dual-D: the printed matrix integral X^T Y' - Y^T X' of the double Neumann system is X^T Y' + (X^T Y')^T on (D0), and X^T Y' itself is conserved along (D-eq) (the Noether integral of the GL(r) symmetry)."""
    z = double_point(s)
    fl = flow_double(s, z)
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    return {"d/dt X^T Y'": derivative(s, lambda t, w: w["X"].T @ w["Ydot"], z, fl),
            "printed integral - (X^T Y' + Y'^T X)": (X.T @ Yd - Y.T @ Xd) - (X.T @ Yd + Yd.T @ X)}


# --------------------------------------------------------------------------------------------
@claim("h-submersion-not-left-invariant", paper=("submersion_metric", "normal_metric"), kind="not",
       expect="nonzero", section="3", sizes=N_GE_3,
       statement=r"\tfrac{d}{ds}H_{\mathbb A}(e^{s\xi}X,e^{s\xi}P)|_{s=0}\ne0\ \text{for generic }\mathbb A")
def submersion_not_left_invariant(s):
    """Section 3, 'The normal metric': contrary to a generic submersion metric, the normal metric is SO(n)-invariant: for a generic symmetric operator AA on so(n), n >= 3, H_AA is not invariant under the left SO(n) action."""
    return {"d H_AA along (xi X, xi P)": s.d(H_AA, {"X": s.xi @ s.X, "P": s.xi @ s.P})}


# --------------------------------------------------------------------------------------------
@claim("h-proof-counts", paper=("LEMA1", "dimension", "NEUMANN2"), kind="dim", section="6", sizes=SMALL,
       statement=r"n^2-(\rank so(r)+\dim so(n-r)+\dim Sym(r)+\dim Sym(n-r))=2l,\ "
                 r"\tfrac12(n^2-r^2-(n-r)^2)=r(n-r)")
def proof_counts(s):
    """End of the proof of Lemma LEMA1: n^2 - dim ker Lambda_1(h+v) with dim ker = rank so(r) + dim so(n-r) + dim Sym(r) + dim Sym(n-r) equals (dimension); proof of Theorem NEUMANN2: 1/2(dim gl(n) - dim gl(r) - dim gl(n-r)) = r(n-r) = dim G_{n,r}."""
    n, r = s.n, s.r
    m = n - r
    ker = r // 2 + m * (m - 1) // 2 + r * (r + 1) // 2 + m * (m + 1) // 2
    return {"2l": Count(n * n - ker, 2 * r * m + r * (r - 1) // 2 - r // 2),
            "dim G": Count((n * n - r * r - m * m) // 2, r * m)}
