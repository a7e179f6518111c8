# ruff: noqa
"""Helpers shared by claims.py and negatives.py of s75 (no claims here)."""
from stiefelsym import comm


def killing(t, a, b):
    """<a, b> = −½tr(ab) (killing)."""
    return -t.tr(a @ b) / 2


def H_normal(t):
    """(normal_metric): ½<Φ, Φ>."""
    return killing(t, t.Phi, t.Phi) / 2


def H_submersion(t):
    """(submersion_metric) with a generic symmetric operator 𝔸 on so(n): ½<𝔸Φ, Φ>."""
    return killing(t, t.sym_operator("AA")(t.Phi), t.Phi) / 2


def H_B(t):
    """(HB): ½tr(PᵀP) − ¼tr(Ψ𝔹(Ψ)), 𝔹 a generic symmetric operator on so(r)."""
    return t.tr(t.P.T @ t.P) / 2 - t.tr(t.Psi @ t.sym_operator("BB")(t.Psi)) / 4


def block_projectors(s):
    """D₁, D₂: the projectors of ℝʳ = ℝ^{r₁} ⊕ ℝ^{r₂} onto its blocks, r₁ = ⌈r/2⌉ (fixed sizes)."""
    r = int(s.r)
    r1 = (r + 1) // 2
    D1 = s.mat([[1 if (i == j and i < r1) else 0 for j in range(r)] for i in range(r)], ("r", "r"))
    D2 = s.mat([[1 if (i == j and i >= r1) else 0 for j in range(r)] for i in range(r)], ("r", "r"))
    return D1, D2


def H_K_of(D1, D2):
    """(EM2), (EM3) with two blocks: ½<Φ,Φ> + κ₀/2<Ψ,Ψ> + κ₁/2<Ψ₁,Ψ₁> + κ₂/2<Ψ₂,Ψ₂>, Ψᵢ = DᵢΨDᵢ."""
    def H(t):
        Psi = t.Psi
        P1, P2 = D1 @ Psi @ D1, D2 @ Psi @ D2
        return (killing(t, t.Phi, t.Phi) / 2 + t.scalar("kappa_0") * killing(t, Psi, Psi) / 2
                + t.scalar("kappa_1") * killing(t, P1, P1) / 2 + t.scalar("kappa_2") * killing(t, P2, P2) / 2)
    return H


def repeated_A(s):
    """A' = diag(α, α, b₃, …, bₙ): a₁ = a₂ (so(n)_A ∋ E₁∧E₂)."""
    n = int(s.n)
    al = s.scalar("alpha")
    d = [al, al] + [s.scalar(f"b{i}") for i in range(3, n + 1)]
    return s.mat([[d[i] if i == j else 0 for j in range(n)] for i in range(n)], ("n", "n"))


def H_neum_kappa_A(Ap):
    """(neumann), (No) with the scene's κ and the potential ½tr(XᵀA'X)."""
    def H(t):
        K = t.X.T @ t.P
        return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ Ap @ t.X) / 2
    return H


def lambda1_op(x, u):
    """The Poisson tensor Λ₁ of (LAMBDA12) at x as an operator: <Λ₁(u), w> = Λ₁(u, w) for u = ξ + η:
    Λ₁(u) = [x, ξ] + pr_so[x, η]."""
    xi = (u - u.T) / 2
    eta = (u + u.T) / 2
    c = comm(x, eta)
    return comm(x, xi) + (c - c.T) / 2


def lambda1_form(t, x, xi, eta, zeta, theta):
    """(LAMBDA12): Λ₁(ξ + η, ζ + θ)|ₓ = <x, [ξ, ζ] + [ξ, θ] + [η, ζ]>."""
    return killing(t, x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))


def dim_fol(n, r):
    """(dim_fol): ½(2r(n − r) + r(r − 1)/2 − [r/2]) + [r/2]."""
    two_l = 2 * r * (n - r) + r * (r - 1) // 2 - r // 2
    return two_l // 2 + r // 2


def coupled_T(t, z):
    K, M = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    return t.tr(z["P"].T @ z["P"]) / 2 - t.tr(K @ K) / 2 + t.tr(z["Q"].T @ z["Q"]) / 2 - t.tr(M @ M) / 2


def H_coupled0(t, z):
    """(C-neumann), κ = 0: T₀ + tr(XᵀAY)."""
    return coupled_T(t, z) + t.tr(z["X"].T @ t.A @ z["Y"])


def cross3(s, u, v):
    """u × v for two 3 × 1 columns (n = 3)."""
    return s.mat([[u[1, 0] * v[2, 0] - u[2, 0] * v[1, 0]],
                  [u[2, 0] * v[0, 0] - u[0, 0] * v[2, 0]],
                  [u[0, 0] * v[1, 0] - u[1, 0] * v[0, 0]]], ("n", "r"))


def H_sp1(t):
    """(sp1) as the Manakov Hamiltonian with B = −A⁻¹: −¼tr(A⁻¹ΦA⁻¹Φ)."""
    return -t.tr(t.Ainv @ t.Phi @ t.Ainv @ t.Phi) / 4


def pf4(K):
    """The Pfaffian of a 4 × 4 skew matrix: K₁₂K₃₄ − K₁₃K₂₄ + K₁₄K₂₃."""
    return K[0, 1] * K[2, 3] - K[0, 2] * K[1, 3] + K[0, 3] * K[1, 2]


def H_kappa_of(s, X, P):
    """(EM) at a point (X, P) of one's own: ½tr(PᵀP) − (½ + κ)tr((XᵀP)²)."""
    K = X.T @ P
    return s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(K @ K)
