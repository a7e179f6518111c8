# ruff: noqa
"""s80 hidden round (h2): helpers shared by claims.py and negatives.py (no claims here)."""
from stiefelsym import comm, elementary
from stiefelsym.bases import matrix_of


def sym(M):
    return (M + M.T) / 2


def H_kappa_of(kappa):
    """(EM): H_κ = ½tr PᵀP − (½ + κ)tr (XᵀP)²."""
    def H(t):
        K = t.X.T @ t.P
        return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa) * t.tr(K @ K)
    return H


def H_neum_of(kappa):
    """(neumann): H_κ + ½tr XᵀAX."""
    def H(t):
        return H_kappa_of(kappa)(t) + t.tr(t.X.T @ t.A @ t.X) / 2
    return H


def H_E(t):
    """(Euclidean): ½tr PᵀP."""
    return t.tr(t.P.T @ t.P) / 2


def H_sub(t):
    """(submersion_metric): ½⟨𝔸Φ, Φ⟩, 𝔸 a generic symmetric operator on so(n)."""
    return t.killing(t.sym_operator("AA")(t.Phi), t.Phi) / 2


def H_metric(t):
    """H_A = ½tr(PᵀA⁻¹P) (metric realization (cond_XP2))."""
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


def H_psphere(t):
    """Manakov Hamiltonian with B = −A⁻¹: ½⟨Φ, A⁻¹ΦA⁻¹⟩."""
    return t.killing(t.Phi, t.Ainv @ t.Phi @ t.Ainv) / 2


def lam1(x, y, z):
    """(LAMBDA12) Λ1(y, z)|_x = ⟨x, [ξ,ζ] + [ξ,θ] + [η,ζ]⟩, y = ξ + η, z = ζ + θ (so + sym parts)."""
    xi, eta = (y - y.T) / 2, (y + y.T) / 2
    ze, th = (z - z.T) / 2, (z + z.T) / 2
    w = comm(xi, ze) + comm(xi, th) + comm(eta, ze)
    return -(x @ w).trace() / 2


def lam2(x, A, y, z):
    """(LAMBDA12) Λ2(y, z)|_x = ⟨x − A, [y, z]⟩."""
    return -((x - A) @ comm(y, z)).trace() / 2


def lam1_vec(x, y):
    """The matrix M with Λ1(y, z)|_x = ⟨M, z⟩ for all z: [x, y] − sym([x, η]), η = sym(y)."""
    eta = (y + y.T) / 2
    return comm(x, y) - sym(comm(x, eta))


def lam2_vec(x, A, y):
    """Λ2(y, z)|_x = ⟨[x − A, y], z⟩."""
    return comm(x - A, y)


def dual_L(t, lam):
    """(LA3) 𝓛*_neum(λ), R = (λI − A)⁻¹ (as a 2r×2r block matrix)."""
    from stiefelsym import block
    R = t.resolvent(lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])
