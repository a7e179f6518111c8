# ruff: noqa
"""s79 hidden round: helpers shared by claims.py and negatives.py (no claims here)."""
from stiefelsym import comm, elementary
from stiefelsym import twisted
from stiefelsym.bases import so_basis, matrix_units


def wedge(x, y):
    """x ∧ y = x yᵀ − y xᵀ."""
    return x @ y.T - y @ x.T


def pr_e(xi, e):
    """(OD): pr_e(ξ) = ξ e⊗e + e⊗e ξ."""
    return xi @ e @ e.T + e @ e.T @ xi


def F_Omega(Om, e):
    """(mag6): F_Ω = pr_{e⊥}(Ω) = Ω − pr_e(Ω)."""
    return Om - pr_e(Om, e)


def euler_ss_point(s):
    """A generic point (Ω, e) of so(n) × S^{n−1} (mag0) on the scene r = 1: Ω = ξ, e = X."""
    return {"Om": s.xi, "e": s.X}


def euler_ss_tangent(s, z):
    """(Euler**): Ω̇ = [A, e⊗e], ė = Ωe."""
    e = z["e"]
    return {"Om": comm(s.A, e @ e.T), "e": z["Om"] @ e}


def H_neum(kappa):
    def H(t):
        K = t.X.T @ t.P
        return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2
    return H


def H_neum_k(t):
    return H_neum(t.kappa)(t)


def flow_No(t, kappa):
    """(No): Ẋ = P − (1+2κ)XPᵀX, Ṗ = −AX − XPᵀP + (1+2κ)PXᵀP + XXᵀAX."""
    X, P, A = t.X, t.P, t.A
    c = 1 + 2 * kappa
    return {"X": P - c * (X @ P.T @ X), "P": -(A @ X) - X @ P.T @ P + c * (P @ X.T @ P) + X @ X.T @ A @ X}


def yang_mills_field(t):
    """F_Ω on T*V written with π = XXᵀ: Ω − pr_{e⊥}... = πΦ + Φπ − Φ (= Φ − pr with e⊗e = I − π at r = n − 1)."""
    pi = t.X @ t.X.T
    return pi @ t.Phi + t.Phi @ pi - t.Phi


def col(s, i):
    return s.X @ twisted.basis_vector(s, i)


def pcol(s, i):
    return s.P @ twisted.basis_vector(s, i)


def cross(s, a, b):
    """a × b for columns of ℝ³ (coordinates read)."""
    x = [a[i, 0] for i in range(3)]
    y = [b[i, 0] for i in range(3)]
    return s.mat([[x[1] * y[2] - x[2] * y[1]], [x[2] * y[0] - x[0] * y[2]], [x[0] * y[1] - x[1] * y[0]]], ("n", "?"))


def dot(s, x, y):
    return s.tr(x.T @ y)


LAMS = ((1, 2), (3, 2), (5, 2))


def perelomov_functions(t, X, P):
    """tr 𝓛(λ)^k, 𝓛 = λΦ + XXᵀ − λ²A, k = 2..n, λ ∈ {1/2, 3/2, 5/2} (k = 1 is the constant r − λ² tr A)."""
    n = int(t.n)
    Phi = P @ X.T - X @ P.T
    out = []
    for (a, b) in LAMS:
        lam = t.q(a, b)
        L = lam * Phi + X @ X.T - lam * lam * t.A
        M = L
        for k in range(2, n + 1):
            M = M @ L
            out.append(t.tr(M))
    return out


def tangent_spanning_set(s):
    """Tangent vectors spanning T(T*V) at (X, P): (ξX, ξP) for ξ ∈ so(n), (0, Xη) for η ∈ so(r),
    (0, (I − XXᵀ)Z) for the matrix units Z."""
    vs = []
    for xi in so_basis(s, "n"):
        vs.append({"X": xi @ s.X, "P": xi @ s.P})
    if int(s.r) >= 2:
        for eta in so_basis(s, "r"):
            vs.append({"P": s.X @ eta})
    Q = s.In - s.X @ s.X.T
    for Z in matrix_units(s, "n", "r"):
        vs.append({"P": Q @ Z})
    return vs


def jacobian_along(s, F, vs):
    """The matrix (dF_i(v_j)) for a list-valued F of the scene."""
    cols = [s.d(F, v) for v in vs]
    nrows = len(cols[0])
    return s.mat([[cols[j][i] for j in range(len(vs))] for i in range(nrows)], ("?", "?"))


def dim_V(n, r):
    return n * r - r * (r + 1) // 2

def e3_of(t):
    return cross(t, col(t, 0), col(t, 1))

def e3dot_of(t):
    """ė₃ = ė₁ × e₂ + e₁ × ė₂ with ė_i = p_i (mag-euk)."""
    return cross(t, pcol(t, 0), col(t, 1)) + cross(t, col(t, 0), pcol(t, 1))

def monopole(s, sign):
    """(neum-gras-mag) at n = 3 through e3 = e1 x e2, Lorentz force sign*eps*e3 x de3/dt."""
    X = s.X
    Ph = (s.In - X @ X.T) @ s.P
    h = twisted.at_point(s, X, Ph)
    flow = twisted.flow(h, H_neum(h.q(-1, 2)))
    e3, e3d = e3_of(h), e3dot_of(h)
    e3dd = h.d(e3dot_of, flow)
    A = h.A
    rhs = A @ e3 - (dot(h, e3, A @ e3) + dot(h, e3d, e3d)) * e3 + sign * h.eps * cross(h, e3, e3d)
    return {"de/dt = p on Psi = 0": flow.Xdot - Ph, "d(e1 x e2)/dt": h.d(e3_of, flow) - e3d,
            "monopole": e3dd - rhs}

def L_reduced(t, w, lam_sign=1):
    lam = t.lam
    N = w["e"] @ w["e"].T
    return lam * w["Om"] + t.In - N - lam_sign * lam * lam * t.A

def quartic_potential(t, pi):
    return t.tr(pi @ t.A @ t.A) - t.tr(pi @ t.A @ pi @ t.A)
