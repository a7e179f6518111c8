# ruff: noqa
"""s76 hidden round: helpers shared by claims.py and negatives.py (no claims here)."""
from stiefelsym import comm, elementary


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
    """H_neum,kappa with the scene's generic kappa."""
    return H_neum(t.kappa)(t)


def H_man_a2(t):
    """Manakov Hamiltonian for B = A²: 1/2<Φ, AΦ + ΦA> = -1/2 tr(AΦ²)."""
    return -t.tr(t.A @ t.Phi @ t.Phi) / 2


def H_man_ainv(t):
    """Manakov Hamiltonian for B = -A⁻¹: 1/2<Φ, A⁻¹ΦA⁻¹> = -1/4 tr(A⁻¹ΦA⁻¹Φ)."""
    return -t.tr(t.Ainv @ t.Phi @ t.Ainv @ t.Phi) / 4


def H_not_manakov(t):
    """-1/4 tr(AΦAΦ): ξ -> AξA is not a Manakov operator (n >= 3)."""
    return -t.tr(t.A @ t.Phi @ t.A @ t.Phi) / 4


def e_rphi(t, k, lam=None):
    """e_k(RΦ), R = (λ - A)⁻¹: Σ_I Π_{i∈I} 1/(λ - a_i) |Φ|^I_I; for k = 2r it is J_2r(λ)/a(λ)."""
    lam = t.lam if lam is None else lam
    return elementary(t, t.resolvent(lam) @ t.Phi, k)[k]


def L_big(t, lam=None):
    lam = t.lam if lam is None else lam
    return t.Phi * lam + t.X @ t.X.T - t.A * (lam * lam)


def L_dual(t):
    """(LA3): [[-XᵀRP, -XᵀRX], [I + PᵀRP, PᵀRX]]."""
    from stiefelsym import block
    R = t.resolvent(t.lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def coupled_H_kappa(t, z):
    """App. 2: H_kappa = T_kappa + tr(XᵀAY) - 2 kappa tr(XᵀP YᵀQ)."""
    X, P, Y, Q = z["X"], z["P"], z["Y"], z["Q"]
    k = t.kappa
    K1, K2 = X.T @ P, Y.T @ Q
    T = (t.tr(P.T @ P) / 2 - (t.q(1, 2) + k) * t.tr(K1 @ K1)
         + t.tr(Q.T @ Q) / 2 - (t.q(1, 2) + k) * t.tr(K2 @ K2))
    return T + t.tr(X.T @ t.A @ Y) - 2 * k * t.tr(K1 @ K2)
