# ruff: noqa: F841, E702, F401, E731, E741
"""False twins of claims.py: each must NOT be passed (fails, or for kind='not', proved)."""
from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

from common import H_0, H_E, H_cubic, H_neum0, H_neum0_theta, L_dual, killing, manakov_cubic

ALWAYS = dict(fails_at=lambda n, r: True)


@claim("n63-phi-acts", paper="dot_X3", kind="id", section="3", sizes=admissible(n_max=5, r_min=2, condition="r >= 2 (X^TP = 0 at r = 1)"), erratum="sign of XP^TX flipped", **ALWAYS)
def phi_acts_neg(s):
    """FALSE: Phi X = P + X P^T X."""
    X, P, Phi = s.X, s.P, s.Phi
    return {"PhiX": Phi @ X - (P + X @ P.T @ X)}


@claim("n63-euclid-accel", paper="Euclidean", kind="id", section="3", sizes=admissible(n_max=5), erratum="Lambda = +Xdot^T Xdot", **ALWAYS)
def euclid_neg(s):
    """FALSE: Pdot = X Xdot^T Xdot."""
    f = s.dirac_flow(H_E)
    V = f["X"]
    return {"Xddot": f["P"] - s.X @ V.T @ V}


@claim("n63-jensen-kappa", paper="EM", kind="id", section="3", sizes=admissible(n_max=5, r_min=2, condition="r >= 2"), erratum="(1/2 - kappa)", **ALWAYS)
def jensen_neg(s):
    """FALSE: H_kappa = 1/2 tr P^TP - (1/2 - kappa) tr (X^TP)^2."""
    k = s.scalar("k")
    X, P = s.X, s.P
    H = killing(s, s.Phi, s.Phi) / 2 + k * killing(s, s.Psi, s.Psi) / 2
    return {"H": H - (s.tr(P.T @ P) / 2 - (s.q(1, 2) - k) * s.tr(X.T @ P @ X.T @ P))}


@claim("n63-manakov-cubic-flow", paper=("Manakov", "dot_XP2"), kind="id", section="4", sizes=admissible(n_max=4), erratum="AxiA sign", **ALWAYS)
def manakov_flow_neg(s):
    """FALSE: Xdot = (A^2 Phi - A Phi A + Phi A^2) X."""
    f = s.dirac_flow(H_cubic)
    A, Phi = s.A, s.Phi
    M = A @ A @ Phi - A @ Phi @ A + Phi @ A @ A
    return {"X": f["X"] - M @ s.X}


@claim("n63-manakov-cubic-lax", paper=("Manakov", "man"), kind="lax", section="4", sizes=admissible(n_max=4), erratum="-lam B", **ALWAYS)
def manakov_lax_neg(s):
    """FALSE: d/dt (Phi + lam A) = [AA(Phi) - lam A^3, Phi + lam A]."""
    f = s.dirac_flow(H_cubic)
    A, lam = s.A, s.lam
    L = s.Phi + lam * A
    M = manakov_cubic(s, s.Phi) - lam * (A @ A @ A)
    return {"lax": s.d(lambda t: t.Phi + lam * t.A, f) - comm(M, L)}


@claim("n63-gram-euclid", paper=("so(n)+so(r)",), kind="id", section="4",
       sizes=admissible(n_max=5, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n"), erratum="commutator order", **ALWAYS)
def gram_neg(s):
    """FALSE (r >= 2): along the Euclidean flow d/dt P^TP = [P^TP, X^TP]."""
    K = s.X.T @ s.P
    G = s.P.T @ s.P
    return {"euclid": s.d(lambda t: t.P.T @ t.P, s.dirac_flow(H_E)) - comm(G, K)}


@claim("n63-gram-not-conserved", paper=("so(n)+so(r)",), kind="not", expect="nonzero", section="4",
       sizes=admissible(n_max=5, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n"))
def gram_not(s):
    """TRUE 'not' statement (Remark after so(n)+so(r)): P^TP is not conserved by the Euclidean flow (r >= 2)."""
    return {"euclid": s.d(lambda t: t.P.T @ t.P, s.dirac_flow(H_E))}


@claim("n63-gram-not-normal", paper=("bols-jov",), kind="not", expect="nonzero", section="4",
       sizes=admissible(n_max=5, r_min=2, condition="r >= 2"), erratum="P^TP is conserved by the normal flow", **ALWAYS)
def gram_not_normal(s):
    """FALSE 'not' statement: P^TP is not conserved by the normal flow (it is: must fail)."""
    return {"normal": s.d(lambda t: t.P.T @ t.P, s.dirac_flow(H_0))}


@claim("n63-theta-hamiltonian", paper=("CPB",), kind="id", section="6", sizes=admissible(n_max=5), erratum="+<A,v>", **ALWAYS)
def theta_neg(s):
    """FALSE: H_neum,0 = 1/2<h,h> + <A, v> on Theta."""
    H = killing(s, s.Phi, s.Phi) / 2 + killing(s, s.A, s.X @ s.X.T)
    return {"H": H - H_neum0(s)}


@claim("n63-cpb-vdot", paper=("CPB",), kind="id", section="6", sizes=admissible(n_max=5, where=lambda n, r: r < n, condition="r < n"), erratum="[v,h]", **ALWAYS)
def cpb_neg(s):
    """FALSE: vdot = [v, h] along (N0_XP2)."""
    f = s.dirac_flow(H_neum0)
    v = s.X @ s.X.T
    return {"vdot": s.d(lambda t: t.X @ t.X.T, f) - comm(v, s.Phi)}


@claim("n63-l1-rank", paper=("L1",), kind="dim", section="6", sizes=admissible(n_max=5), erratum="rank r(n-r)+1", **ALWAYS)
def l1_neg(s):
    """FALSE: rank r(n-r) + 1."""
    n, r = int(s.n), int(s.r)
    v = s.X @ s.X.T
    M = matrix_of(s, lambda xi: xi @ v - v @ xi, so_basis(s, "n"), "sym")
    return {"rank": Rank(M, r * (n - r) + 1)}


@claim("n63-r-equals-n", paper=("N0_XP2",), kind="id", section="8",
       sizes=admissible(n_max=5, where=lambda n, r: r == n, condition="r = n"), erratum="extra -AX", **ALWAYS)
def r_n_neg(s):
    """FALSE: at r = n the Neumann P-flow is the geodesic one minus A X."""
    fN = s.dirac_flow(H_neum0)
    f0 = s.dirac_flow(H_0)
    return {"P": fN["P"] - (f0["P"] - s.A @ s.X)}


@claim("n63-r-lt-n-geodesic", paper=("N0_XP2",), kind="id", section="8",
       sizes=admissible(n_max=5, where=lambda n, r: r < n, condition="r < n"), erratum="only at r = n", **ALWAYS)
def r_lt_n_neg(s):
    """FALSE for r < n: the Neumann flow is the normal geodesic flow."""
    fN = s.dirac_flow(H_neum0)
    f0 = s.dirac_flow(H_0)
    return {"P": fN["P"] - f0["P"]}


@claim("n63-dual-curve-so-r", paper=("2r-integrals",), kind="id", section="8",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"), erratum="P eta sign", **ALWAYS)
def dual_neg(s):
    """FALSE: tr L*^2 invariant under (X, P) -> (X eta, -P eta)."""
    eta = s.eta
    def f(t):
        L = L_dual(t)
        return t.tr(L @ L)
    return {"tr2": s.d(f, {"X": s.X @ eta, "P": -(s.P @ eta)})}


@claim("n63-dual-matrix-not-invariant", paper=("2r-integrals",), kind="not", expect="nonzero", section="8",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"))
def dual_not(s):
    """TRUE 'not': the matrix L*_neum itself is not SO(r)-invariant (r >= 2)."""
    eta = s.eta
    return {"L": s.d(L_dual, {"X": s.X @ eta, "P": s.P @ eta})}


@claim("n63-count-N", paper="2r-integrals", kind="dim", section="8", sizes=admissible(n_max=6), erratum="r(r+1)/2", **ALWAYS)
def count_neg(s):
    """FALSE: N = r(n-r) + r(r+1)/2."""
    n, r = int(s.n), int(s.r)
    return {"N": Count(sum(n - l for l in range(1, r + 1)), r * (n - r) + r * (r + 1) // 2)}
