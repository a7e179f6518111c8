"""s63 user claims: statements of §3, §4, §6, §8 of Fedorov-Jovanovic, in my own words."""
from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, so_basis

from common import H_0, H_E, H_cubic, H_neum0, H_neum0_theta, L_dual, killing, manakov_cubic


@claim("u63-phi-acts", paper="dot_X3", kind="id", section="3", sizes=admissible(n_max=5))
def phi_acts_on_x_and_p(s):
    """On T*V: Phi X = P - X P^T X and Phi P = -X P^T P + P X^T P (right-hand sides of dot_X3, dot_P3)."""
    X, P, Phi = s.X, s.P, s.Phi
    return {"PhiX": Phi @ X - (P - X @ P.T @ X), "PhiP": Phi @ P - (-(X @ P.T @ P) + P @ X.T @ P)}


@claim("u63-euclid-accel", paper="Euclidean", kind="id", section="3", sizes=admissible(n_max=5))
def euclidean_acceleration(s):
    """Euclidean geodesic: Xdot = P and Pdot = X Lambda with Lambda = -Xdot^T Xdot."""
    f = s.dirac_flow(H_E)
    V = f["X"]
    return {"Xdot": V - s.P, "Xddot": f["P"] + s.X @ V.T @ V}


@claim("u63-jensen-kappa", paper="EM", kind="id", section="3", sizes=admissible(n_max=5))
def jensen_family(s):
    """H_kappa = 1/2<Phi,Phi> + kappa/2 <Psi,Psi> equals 1/2 tr P^TP - (1/2+kappa) tr (X^TP)^2 on T*V,
    and its Dirac flow has Xdot = P - (1 + 2 kappa) X P^T X."""
    k = s.scalar("k")

    def H(t):
        return killing(t, t.Phi, t.Phi) / 2 + k * killing(t, t.Psi, t.Psi) / 2
    X, P = s.X, s.P
    closed = s.tr(P.T @ P) / 2 - (s.q(1, 2) + k) * s.tr(X.T @ P @ X.T @ P)
    f = s.dirac_flow(H)
    return {"H": H(s) - closed, "Xdot": f["X"] - (P - (1 + 2 * k) * (X @ P.T @ X))}


@claim("u63-manakov-cubic-flow", paper=("Manakov", "dot_XP2"), kind="id", section="4", sizes=admissible(n_max=4))
def manakov_cubic_flow(s):
    """With B = A^3 the Manakov operator is AA(xi) = A^2 xi + A xi A + xi A^2; the Dirac flow of
    1/2<AA Phi, Phi> is Xdot = AA(Phi) X, Pdot = AA(Phi) P (zero multipliers)."""
    f = s.dirac_flow(H_cubic)
    M = manakov_cubic(s, s.Phi)
    return {"X": f["X"] - M @ s.X, "P": f["P"] - M @ s.P}


@claim("u63-manakov-cubic-lax", paper=("Manakov", "man"), kind="lax", section="4", sizes=admissible(n_max=4))
def manakov_cubic_lax(s):
    """Manakov Lax pair with B = A^3: d/dt (Phi + lam A) = [AA(Phi) + lam A^3, Phi + lam A]."""
    f = s.dirac_flow(H_cubic)
    A, lam = s.A, s.lam
    L = s.Phi + lam * A
    M = manakov_cubic(s, s.Phi) + lam * (A @ A @ A)
    return {"lax": s.d(lambda t: t.Phi + lam * t.A, f) - comm(M, L)}


@claim("u63-gram-normal-vs-euclid", paper=("bols-jov", "so(n)+so(r)"), kind="id", section="4", sizes=admissible(n_max=5))
def gram_along_flows(s):
    """The Gram matrix P^TP (SO(n)-invariant) is conserved by the normal geodesic flow; along the
    Euclidean flow d/dt P^TP = [X^TP, P^TP] (so it is not conserved for r >= 2)."""
    g = lambda t: t.P.T @ t.P
    K = s.X.T @ s.P
    G = s.P.T @ s.P
    return {"normal": s.d(g, s.dirac_flow(H_0)), "euclid": s.d(g, s.dirac_flow(H_E)) - comm(K, G)}


@claim("u63-theta-hamiltonian", paper=("CPB", "N0_XP2"), kind="id", section="6", sizes=admissible(n_max=5))
def theta_hamiltonian(s):
    """H_neum,0 = H o Theta with H = 1/2<h,h> - <A, v>; and Theta = Phi + XX^T evolves along (N0_XP2)
    by (CPB): hdot = [v, A], vdot = [h, v]."""
    f = s.dirac_flow(H_neum0)
    v = s.X @ s.X.T
    return {"H": H_neum0_theta(s) - H_neum0(s),
            "hdot": s.d(lambda t: t.Phi, f) - comm(v, s.A),
            "vdot": s.d(lambda t: t.X @ t.X.T, f) - comm(s.Phi, v)}


@claim("u63-l1-rank", paper=("L1", "LEMA1"), kind="dim", section="6", sizes=admissible(n_max=5))
def l1_rank(s):
    """(L1): [xi, XX^T] = 0 iff xi in so(r) + so(n-r); so xi -> [xi, XX^T] has rank r(n-r) on so(n)."""
    n, r = int(s.n), int(s.r)
    v = s.X @ s.X.T
    M = matrix_of(s, lambda xi: xi @ v - v @ xi, so_basis(s, "n"), "sym")
    return {"rank": Rank(M, r * (n - r))}


@claim("u63-r-equals-n", paper=("Yuri", "N0_XP2", "dot_X3"), kind="id", section="8",
       sizes=admissible(n_max=5, where=lambda n, r: r == n, condition="r = n"))
def neumann_is_geodesic_at_r_n(s):
    """For r = n the potential is constant (tr X^TAX = tr A) and the Neumann flow (N0_XP2) is the
    normal geodesic flow (dot_X3, dot_P3)."""
    fN = s.dirac_flow(H_neum0)
    f0 = s.dirac_flow(H_0)
    return {"V": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A), "X": fN["X"] - f0["X"], "P": fN["P"] - f0["P"]}


@claim("u63-dual-curve-so-r", paper=("2r-integrals", "LA3"), kind="id", section="8", sizes=admissible(n_max=4))
def dual_curve_so_r_invariant(s):
    """The spectral curve of L*_neum is SO(r)-invariant: tr L*^2 and tr L*^4 do not change along the
    infinitesimal right action (X, P) -> (X eta, P eta), eta in so(r)."""
    eta = s.eta
    tangent = {"X": s.X @ eta, "P": s.P @ eta}
    def trk(k):
        def f(t):
            L = L_dual(t)
            M = L
            for _ in range(k - 1):
                M = M @ L
            return t.tr(M)
        return f
    return {"tr2": s.d(trk(2), tangent), "tr4": s.d(trk(4), tangent)}


@claim("u63-count-N", paper="2r-integrals", kind="dim", section="8", sizes=admissible(n_max=6))
def count_N(s):
    """N = (n-1) + ... + (n-r) = r(n-r) + r(r-1)/2 = dim V."""
    n, r = int(s.n), int(s.r)
    return {"N": Count(sum(n - l for l in range(1, r + 1)), r * (n - r) + r * (r - 1) // 2)}
