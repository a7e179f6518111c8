# ruff: noqa
"""s78 hidden round: helpers shared by claims.py and negatives.py (no claims here)."""
from stiefelsym import block, comm, det


def killing(t, a, b):
    """<a, b> = -1/2 tr(ab) (killing)."""
    return -t.tr(a @ b) / 2


def pi(t):
    return t.X @ t.X.T


def H_neum(kappa):
    """(neumann): H_neum,kappa = 1/2 tr PᵀP - (1/2 + kappa) tr (XᵀP)² + 1/2 tr XᵀAX."""
    def H(t):
        K = t.X.T @ t.P
        return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2
    return H


def H_neum_k(t):
    return H_neum(t.kappa)(t)


def H_man_a2(t):
    """Manakov Hamiltonian for B = A² (Manakov*): 1/2<𝔸Φ, Φ>, 𝔸ξ = Aξ + ξA, = -1/2 tr(AΦ²)."""
    return -t.tr(t.A @ t.Phi @ t.Phi) / 2


def fibre_lift(t, xi):
    """The inverse of (iso): ξ ↦ ξX − ½XXᵀξX (a covector in the fibre T*_X V)."""
    return xi @ t.X - t.X @ t.X.T @ xi @ t.X / 2


def phi_of(t, X, P):
    return P @ X.T - X @ P.T


def thimm_gradient(t, F):
    """∇f̃ ∈ so(n) for f̃(ξ) = F(X, ξX − ½XXᵀξX), w.r.t. <a, b> = −½tr(ab):
    df̃[ζ] = tr(F_Pᵀ(I − ½π)ζX) = tr(M ζ), M = X F_Pᵀ(I − ½π), so ∇f̃ = Mᵀ − M."""
    FP = t.gradient(F)[1]
    J = t.In - t.X @ t.X.T / 2
    M = t.X @ FP.T @ J
    return M.T - M


def phi0(t, V):
    """(Phi_0): Φ₀(X, Ẋ) = ẊXᵀ − XẊᵀ − ½X(XᵀẊ − ẊᵀX)Xᵀ."""
    X = t.X
    return V @ X.T - X @ V.T - X @ (X.T @ V - V.T @ X) @ X.T / 2


def L_dual(t, X, P, lam):
    """(LA3): 𝓛*(λ) = [[−XᵀRP, −XᵀRX], [I + PᵀRP, PᵀRX]], R = (λI − A)⁻¹."""
    R = t.resolvent(lam)
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def eta_hat(t, eta):
    Z = t.zeros(t.r, t.r, ("r", "r"))
    return block([[eta, Z], [Z, eta]])


def normal_gram(t):
    """Pᵀ(I − XXᵀ)P (= det[X P]² under det at n = 2r)."""
    return t.P.T @ (t.In - t.X @ t.X.T) @ t.P


def dim_so(m):
    return m * (m - 1) // 2


def dim_V(n, r):
    return n * r - r * (r + 1) // 2


def ddim_printed(n, r):
    """(ddim)."""
    return dim_V(n, r) - dim_so(n - r) + (dim_so(n - 2 * r) if n > 2 * r else 0)


def two_l_printed(n, r):
    """Lemma 2l."""
    return n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)
