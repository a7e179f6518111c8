"""§4 Integrability of geodesic flows: the dimensions of the invariant tori (bols-jov), the
Manakov metrics (Manakov), (Manakov*), their flow (dot_XP3*), Lax pairs and integrals (man), the
dual Lax pair (MAN-LA) with the reflections, and the Jensen flows with their integrals (ET)."""
from __future__ import annotations

from stiefelsym import Count, Rank, admissible, block, claim, comm, twisted

from .sec2_hamiltonian_flows import (ad_matrix, ad_phi_kernel, ddim_printed, dim_so, dim_V,
                                     psi_and_gram_give_ddim_functions, two_l_printed)

SECTION = "4"


def H_jensen(s):
    """(EM) H_kappa = 1/2 <Phi, Phi> + kappa/2 <Psi, Psi>."""
    return s.killing(s.Phi, s.Phi) / 2 + s.kappa * s.killing(s.Psi, s.Psi) / 2


@claim("jensen-integrals", paper=("ET", "so(n)+so(r)"), kind="pb",
       statement=r"\tfrac{d}{dt}\Phi=0,\quad \tfrac{d}{dt}\Psi=0\ \text{along the geodesic flow of } H_\kappa")
def momentum_maps_are_integrals_of_the_jensen_flows(s):
    """Theorem ET: Φ and Ψ are first integrals of the geodesic flows of the Jensen metrics H_κ, so Φ*(C∞(so(n))) and Ψ*(C∞(so(r))) lie in the algebra (so(n)+so(r)) of integrals."""
    flow = s.dirac_flow(H_jensen)
    return {
        "dPhi/dt": s.d(lambda t: t.Phi, flow),
        "dPsi/dt": s.d(lambda t: t.Psi, flow),
    }


# -- dimensions of the invariant tori ------------------------------------------------

def delta0_printed(n, r):
    """The closed form of δ₀ after Theorem bols-jov."""
    if n >= 2 * r:
        return r
    return dim_V(n, r) + dim_so(n - r) - dim_so(n) + n // 2


@claim("invariant-tori-dimensions", paper=("bols-jov", "ddim", "2l"), kind="dim", exact_max_n=7,
       equivariance="the ranks do not depend on the bases of so(n) and of the fibre and are invariant under O(n)",
       statement=r"\delta_0=2\dim V_{n,r}-\ddim C^\infty(T^*V_{n,r})^{SO(n)}-2l=\begin{cases}r,&n\ge2r\\"
                 r"\dim V_{n,r}+\dim SO(n-r)-\dim SO(n)+\rank SO(n),&n<2r\end{cases};\quad "
                 r"\delta=2\dim V_{n,r}-\ddim-l=r(n-r),\ n\ge2r")
def invariant_tori_dimensions(s):
    """With ddim and 2l computed at this size (the ranks of Lemma 2l and (ddim)), δ₀ = 2dim V − ddim − 2l of Theorem bols-jov has the printed closed form, and for the Manakov metrics δ = 2dim V − ddim − l = r(n − r) when n ≥ 2r."""
    n, r = s.n, s.r
    ddim, two_l = ddim_printed(n, r), two_l_printed(n, r)
    checks = {
        "2l": Rank(ad_matrix(s, s.Phi), two_l, generic=True, meaning="2l, the dimension of a generic orbit in Phi(T*V)",
                   kernel=ad_phi_kernel(s)),
        "ddim": psi_and_gram_give_ddim_functions(s)["rank on the fibre"],
        "delta_0": Count(2 * dim_V(n, r) - ddim - two_l, delta0_printed(n, r),
                         "2 dim V - ddim - 2l against the closed form"),
    }
    if n >= 2 * r:
        checks["delta (Manakov)"] = Count(2 * dim_V(n, r) - ddim - two_l // 2, r * (n - r),
                                          "2 dim V - ddim - l against r(n - r)")
    return checks


# -- Manakov metrics ----------------------------------------------------------------

#: the powers k of the integrals tr(Φ + λA)^k of (man) checked (the paper: k = 1, ..., n)
POWERS = (1, 2, 3)


def power_trace(s, M, k):
    """tr M^k."""
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return s.tr(acc)


def b_eigenvalues(s):
    """The eigenvalues b_1, ..., b_n of a generic diagonal B: fresh parameters of the claim."""
    return [s.scalar(f"b_{i + 1}") for i in range(s.n)]


def diagonal(s, entries):
    """diag(entries) as an n x n matrix."""
    n = s.n
    return s.mat([[entries[i] if i == j else s.q(0) for j in range(n)] for i in range(n)], ("n", "n"))


def manakov_operator(s, b):
    """(Manakov): 𝔸(E_i ∧ E_j) = (b_i − b_j)/(a_i − a_j) E_i ∧ E_j, extended linearly to so(n)
    (entry (i, j) of 𝔸(ξ) is (b_i − b_j)/(a_i − a_j) ξ_ij)."""
    a, n = s.a, s.n

    def apply(xi):
        return s.mat([[(b[i] - b[j]) / (a[i] - a[j]) * xi[i, j] if i != j else s.q(0) for j in range(n)]
                      for i in range(n)], ("n", "n"))
    return apply


def H_manakov(s):
    """(submersion_metric) H_𝔸 = ½<𝔸Φ, Φ> with the Manakov operator (Manakov) of a generic diagonal B."""
    return s.killing(manakov_operator(s, b_eigenvalues(s))(s.Phi), s.Phi) / 2


def matrix_power(M, k):
    """M^k, k >= 1."""
    out = M
    for _ in range(k - 1):
        out = out @ M
    return out


def manakov_power_operator(s, k):
    """The Manakov operator (Manakov) of B = A^k, k >= 1, without its entries: 𝔸_k(ξ) = Σ_{m<k} A^m ξ A^{k−1−m},
    whose entry (i, j) at A = diag(a) is (a_i^k − a_j^k)/(a_i − a_j) ξ_ij (claim manakov-operator).  Every
    diagonal B is a polynomial Σ_k β_k A^k in A = diag(a) with distinct a_i (Vandermonde), and (Manakov) is linear
    in B, so the operators 𝔸_k, k = 1, …, n − 1, span the Manakov operators (A^0 = I gives 𝔸 = 0)."""
    def apply(xi):
        acc = None
        for m in range(k):
            term = xi if m == 0 else matrix_power(s.A, m) @ xi
            term = term if m == k - 1 else term @ matrix_power(s.A, k - 1 - m)
            acc = term if acc is None else acc + term
        return acc
    return apply


def H_manakov_power(k):
    """H_𝔸 = ½<𝔸_kΦ, Φ> for the Manakov operator of B = A^k (see :func:`manakov_power_operator`)."""
    def H(s):
        return s.killing(manakov_power_operator(s, k)(s.Phi), s.Phi) / 2
    H.__name__ = f"H_manakov_A{k}"
    return H


def manakov_square(s, xi):
    """(Manakov*): 𝔸(ξ) = Aξ + ξA, the Manakov operator for B = A²."""
    return s.A @ xi + xi @ s.A


def H_manakov_square(s):
    """H_𝔸 = ½<𝔸Φ, Φ> with 𝔸(ξ) = Aξ + ξA."""
    return s.killing(manakov_square(s, s.Phi), s.Phi) / 2


def flow_XP3_at(s, X, P):
    """(dot_XP3*) at the point (X, P): Ẋ = A(PXᵀ − XPᵀ)X + (PXᵀ − XPᵀ)AX, Ṗ = A(PXᵀ − XPᵀ)P + (PXᵀ − XPᵀ)AP."""
    A = s.A
    Phi = P @ X.T - X @ P.T
    return {"X": A @ Phi @ X + Phi @ A @ X, "P": A @ Phi @ P + Phi @ A @ P}


def flow_XP3(s):
    """(dot_XP3*) at the point (X, P) of the scene."""
    return flow_XP3_at(s, s.X, s.P)


@claim("manakov-operator", paper=("Manakov", "Manakov*"), kind="id", exact_max_n=7,
       statement=r"\mathbb A(E_i\wedge E_j)=\tfrac{b_i-b_j}{a_i-a_j}E_i\wedge E_j\iff\mathbb A(\xi)=\ad_A^{-1}\ad_B\xi;"
                 r"\quad B=A^2:\ \mathbb A(\xi)=A\xi+\xi A")
def manakov_operator_is_ad_inverse(s):
    """The operator (Manakov) defined on the basis E_i ∧ E_j satisfies ad_A 𝔸(ξ) = ad_B ξ (so 𝔸 = ad_A⁻¹ad_B on so(n)), for B = A² it is 𝔸(ξ) = Aξ + ξA (Manakov*), and for B = A^k it is Σ_{m<k} A^m ξ A^{k−1−m} (the form in which the Manakov flows are checked, k = 1, …, n − 1)."""
    b = b_eigenvalues(s)
    B = diagonal(s, b)
    AA = manakov_operator(s, b)
    AA_square = manakov_operator(s, [x * x for x in s.a])
    checks = {
        "ad_A AA(xi) = ad_B xi": comm(s.A, AA(s.xi)) - comm(B, s.xi),
        "B = A^2: AA(xi) = A xi + xi A": AA_square(s.xi) - manakov_square(s, s.xi),
    }
    for k in range(1, s.n):
        powers = [s.q(1)] * s.n
        for _ in range(k):
            powers = [x * a for x, a in zip(powers, s.a)]
        checks[f"B = A^{k}: AA(xi) = sum_m A^m xi A^({k - 1} - m)"] = (
            manakov_operator(s, powers)(s.xi) - manakov_power_operator(s, k)(s.xi))
    return checks


@claim("manakov-square", paper=("Manakov*",), kind="id",
       statement=r"A\xi+\xi A\in so(n),\quad \ad_A(A\xi+\xi A)=\ad_{A^2}\xi,\quad \xi\in so(n)")
def manakov_operator_for_a_squared(s):
    """For B = A², 𝔸(ξ) = Aξ + ξA maps so(n) to so(n) and ad_A 𝔸(ξ) = ad_{A²} ξ, so it is the Manakov operator ad_A⁻¹ad_B wherever ad_A is invertible on so(n)."""
    AA = manakov_square(s, s.xi)
    return {
        "AA(xi) skew": AA + AA.T,
        "ad_A AA(xi) = ad_{A^2} xi": comm(s.A, AA) - comm(s.A @ s.A, s.xi),
    }


@claim("manakov-square-flow", paper=("Manakov*", "dot_XP3*", "dot_XP2"), kind="id",
       statement=r"\dot X=\{X,H_{\mathbb A}\}=A(PX^T-XP^T)X+(PX^T-XP^T)AX,\ "
                 r"\dot P=\{P,H_{\mathbb A}\}=A(PX^T-XP^T)P+(PX^T-XP^T)AP,\quad \mathbb A(\xi)=A\xi+\xi A")
def manakov_flow_for_a_squared(s):
    """The Dirac flow of H_𝔸 = ½<𝔸Φ, Φ> with 𝔸(ξ) = Aξ + ξA is the printed (dot_XP3*), which is (dot_XP2) Ẋ = 𝔸(Φ)X, Ṗ = 𝔸(Φ)P and is tangent to T*V."""
    flow = s.dirac_flow(H_manakov_square)
    printed = flow_XP3(s)
    omega = manakov_square(s, s.Phi)
    kept = s.d(lambda t: [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X], printed)
    return {
        "dX/dt": flow.Xdot - printed["X"],
        "dP/dt": flow.Pdot - printed["P"],
        "(dot_XP2) X": printed["X"] - omega @ s.X,
        "(dot_XP2) P": printed["P"] - omega @ s.P,
        "d(X^T X)/dt along (dot_XP3*)": kept[0],
        "d(X^T P + P^T X)/dt along (dot_XP3*)": kept[1],
    }


@claim("manakov-lax", paper=("Manakov", "dot_XP2", "man"), unlabelled=("Theorem 4.3",), kind="lax", exact_max_n=6, exact_max_r={7: 2},
       exact_corank={7: 0},
       statement=r"\tfrac{d}{dt}\mathcal L_{man}(\lambda)=[\mathcal A_{man}(\lambda),\mathcal L_{man}(\lambda)],\quad "
                 r"\mathcal L_{man}=\Phi+\lambda A,\ \mathcal A_{man}=\mathbb A(\Phi)+\lambda B;\quad "
                 r"\tfrac{d}{dt}\tr\big(\lambda A+\textstyle\sum_i p_i\wedge e_i\big)^k=0,\ k=1,2,3")
def manakov_lax_pair(s):
    """The Dirac flow of H_𝔸 with the Manakov operator (Manakov) of generic diagonal A, B implies d𝓛/dt = [𝓐, 𝓛] for 𝓛 = Φ + λA, 𝓐 = 𝔸(Φ) + λB, and the integrals tr(λA + Σ p_i ∧ e_i)^k of (man) (Σ p_i ∧ e_i = PXᵀ − XPᵀ) are conserved, checked for k = 1, 2, 3.  Both statements are linear in B, because the flow of H_𝔸 and the matrix 𝓐 both are, and every diagonal B is Σ_k β_k A^k (distinct a_i), so they are checked for B = A^k, k = 1, …, n − 1, with 𝔸(ξ) = Σ_{m<k} A^m ξ A^{k−1−m}, the entries (Manakov) of claim manakov-operator (B = I gives 𝔸 = 0 and a trivial statement)."""
    L = s.Phi + s.lam * s.A
    checks = {}
    for k in range(1, max(s.n, 2)):         # at n = 1 every B is a multiple of A
        flow = s.dirac_flow(H_manakov_power(k))
        M = manakov_power_operator(s, k)(s.Phi) + s.lam * matrix_power(s.A, k)
        checks[f"Lax (B = A^{k})"] = s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(M, L)
        for j in POWERS:
            checks[f"d tr L^{j}/dt (B = A^{k})"] = s.d(
                lambda t, j=j: power_trace(t, t.lam * t.A + t.P @ t.X.T - t.X @ t.P.T, j), flow)
    return checks


@claim("manakov-square-lax", paper=("Manakov*", "dot_XP3*"), kind="lax",
       statement=r"\tfrac{d}{dt}(\Phi+\lambda A)=[A\Phi+\Phi A+\lambda A^2,\Phi+\lambda A]\ \text{along (5) of Section 4}")
def manakov_lax_pair_for_a_squared(s):
    """For B = A², the Dirac flow of H_𝔸 (the flow (dot_XP3*)) implies d𝓛/dt = [𝓐, 𝓛] with 𝓛 = Φ + λA, 𝓐 = 𝔸(Φ) + λB = AΦ + ΦA + λA²."""
    flow = s.dirac_flow(H_manakov_square)
    L = s.Phi + s.lam * s.A
    M = manakov_square(s, s.Phi) + s.lam * (s.A @ s.A)
    return {"Lax": s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(M, L)}


@claim("manakov-integrals", paper=("man", "SO(n)-inv"), unlabelled=("Remark 4.1",), kind="pb",
       statement=r"\{\tr(\lambda A+\Phi)^k,\tr(\mu A+\Phi)^m\}=0,\ k,m=1,2,3;\quad "
                 r"\tfrac{d}{dt}\tr(\lambda A+\Phi)^k=\tfrac{d}{dt}\Psi=\tfrac{d}{dt}P^TP=0\ \text{along (5) of Section 4}")
def manakov_integrals_commute(s):
    """The integrals tr(λA + Σ p_i ∧ e_i)^k of (man), k = 1, 2, 3, Poisson-commute for two values λ, μ, and together with the SO(n)-invariant Ψ and PᵀP they are conserved by the Manakov flow (dot_XP3*) (B = A²)."""
    flow = s.dirac_flow(H_manakov_square)

    def f(t, mu, k):
        return power_trace(t, mu * t.A + t.P @ t.X.T - t.X @ t.P.T, k)
    checks = {}
    for k in POWERS:
        for m in POWERS:
            if m >= k:   # the pairs m < k are these with λ and μ exchanged
                checks[f"{{tr L(lambda)^{k}, tr L(mu)^{m}}}"] = s.bracket(
                    lambda t, k=k: f(t, t.lam, k), lambda t, m=m: f(t, t.scalar("mu"), m))
    for k in POWERS:
        checks[f"d tr L(lambda)^{k}/dt"] = s.d(lambda t, k=k: f(t, t.lam, k), flow)
    checks["dPsi/dt"] = s.d(lambda t: t.Psi, flow)
    checks["d(P^T P)/dt"] = s.d(lambda t: t.P.T @ t.P, flow)
    return checks


# -- the dual Lax pair for the Manakov flows ------------------------------------------

def L_man_dual_at(s, X, P):
    """(MAN-LA2) at the point (X, P): the 2r x 2r matrix 𝓛*_man(λ) with R = (λI_n − A)⁻¹."""
    R = s.resolvent(s.lam)
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)],
                  [P.T @ R @ P, P.T @ R @ X]])


def A_man_dual_at(s, X, P, S):
    """(LA-MAN3) at the point (X, P), with the n x n matrix S in the place of (A + λI_n)⁻¹."""
    return block([[X.T @ S @ P, X.T @ S @ X],
                  [-(P.T @ S @ P), -(P.T @ S @ X)]])


def inverse_of_A_plus_lambda(s):
    """(A + λI_n)⁻¹ = −((−λ)I_n − A)⁻¹, as printed in (LA-MAN3)."""
    return -s.resolvent(-s.lam)


def L_man_dual(s):
    """(MAN-LA2): 𝓛*_man(λ)."""
    return L_man_dual_at(s, s.X, s.P)


def A_man_dual(s):
    """(LA-MAN3): 𝓐*_man(λ) as printed."""
    return A_man_dual_at(s, s.X, s.P, inverse_of_A_plus_lambda(s))


@claim("manakov-dual-lax", nature="formula", paper=("man-dual", "MAN-LA", "MAN-LA2", "LA-MAN3"), kind="lax", exact_max_n=2, exact_max_r={3: 2, 4: 1, 5: 1, 6: 1},
       fails_at=lambda n, r: n >= 2,
       place="the matrix 𝓐*_man(λ) of (9) §4, in Theorem 4.4",
       erratum="""Theorem 4.4: with the printed (9) §4, whose entries contain (A + λI_n)^{-1}, the
       flow (5) §4 does not imply (7) §4.  It does with (A + λI_n) in place of (A + λI_n)^{-1}:
       𝓐*_man(λ) = J Uᵀ(A + λI_n)U for U = (P, X), J = [[0, I_r], [−I_r, 0]], while 𝓛*_man(λ) = −J UᵀRU;
       then d𝓛*/dt = [𝓛*, 𝓐*] follows from d(UᵀRU)/dt = Uᵀ[R, AΦ + ΦA]U and Φ = UJUᵀ.""",
       statement=r"\tfrac{d}{dt}\mathcal L^*_{man}(\lambda)=[\mathcal L^*_{man}(\lambda),\mathcal A^*_{man}(\lambda)]\ "
                 r"\text{along (5) of Section 4},\quad \mathcal L^*_{man}=\begin{pmatrix}-X^TR_\lambda P&-X^TR_\lambda X\\"
                 r"P^TR_\lambda P&P^TR_\lambda X\end{pmatrix},\ \mathcal A^*_{man}=\begin{pmatrix}X^T(A+\lambda\mathbf I)^{-1}P&"
                 r"X^T(A+\lambda\mathbf I)^{-1}X\\-P^T(A+\lambda\mathbf I)^{-1}P&-P^T(A+\lambda\mathbf I)^{-1}X\end{pmatrix},"
                 r"\ R_\lambda=(\lambda\mathbf I_n-A)^{-1}")
def manakov_dual_lax_pair(s):
    """Theorem man-dual: the Manakov flow (dot_XP3*), derived from H_𝔸 with 𝔸(ξ) = Aξ + ξA, implies the 2r×2r Lax equation (MAN-LA) with the printed 𝓛*_man(λ) (MAN-LA2) and 𝓐*_man(λ) (LA-MAN3)."""
    flow = s.dirac_flow(H_manakov_square)
    return {"d𝓛*_man/dt − [𝓛*_man, 𝓐*_man]": s.d(L_man_dual, flow) - comm(L_man_dual(s), A_man_dual(s))}


@manakov_dual_lax_pair.claim.correction("(9) §4: A + λI_n in place of (A + λI_n)^{-1}",
                                        exact_max_r={3: 3, 4: 4, 5: 5, 6: 4, 7: 3},
                                        blocks_of="𝓐*_man(λ) in (9) §4")
def manakov_dual_lax_pair_corrected(s):
    flow = s.dirac_flow(H_manakov_square)
    M = A_man_dual_at(s, s.X, s.P, s.A + s.lam * s.In)
    return {"d𝓛*_man/dt − [𝓛*_man, 𝓐*_man]": s.d(L_man_dual, flow) - comm(L_man_dual(s), M)}


def reflection(s, i):
    """(reflections): S_i = diag(1, ..., −1, ..., 1), the reflection in the i-th coordinate hyperplane."""
    return diagonal(s, [s.q(-1) if j == i else s.q(1) for j in range(s.n)])


@claim("manakov-reflections", paper=("reflections", "man-dual"), kind="id", exact_max_n=2,
       exact_max_r={3: 3, 4: 1, 5: 1, 6: 1, 7: 1}, exact_corank={4: 1, 5: 1, 6: 0, 7: 0},
       statement=r"(X,P)\mapsto(S_iX,S_iP):\quad (\text{dot\_XP3*})\ \text{is equivariant},\quad "
                 r"\mathcal L^*_{man}(\lambda),\ \mathcal A^*_{man}(\lambda)\ \text{are invariant},\quad i=1,\dots,n")
def reflections_are_symmetries_of_the_dual_pair(s):
    """The reflections (reflections) S_i of the coordinate hyperplanes (A diagonal) map the Manakov flow (dot_XP3*) to itself and leave the dual Lax matrices 𝓛*_man(λ), 𝓐*_man(λ) unchanged, so the dual Lax pair can determine the flow only up to the group ℤ₂ⁿ they generate.  Checked for S = S₁ at fixed sizes (every S_i is S₁ up to a relabelling of the coordinates) and, dimension-free, for every S = Sᵀ with S² = I and SA = AS (every element of ℤ₂ⁿ at once)."""
    X, P, Sinv = s.X, s.P, inverse_of_A_plus_lambda(s)
    V = flow_XP3(s)
    S = twisted.reflection(s)
    W = flow_XP3_at(s, S @ X, S @ P)
    return {
        "S: dX/dt": W["X"] - S @ V["X"],
        "S: dP/dt": W["P"] - S @ V["P"],
        "S: L*": L_man_dual_at(s, S @ X, S @ P) - L_man_dual(s),
        "S: A*": A_man_dual_at(s, S @ X, S @ P, Sinv) - A_man_dual(s),
    }


# -- the remark after Theorem ET --------------------------------------------------------

def bracket_gram_psi(s):
    """{tr(G PᵀP), ⟨Ψ, Ψ⟩} for a generic r x r matrix G: all the brackets {(p_i, p_j), ⟨Ψ, Ψ⟩} at once."""
    gram = lambda t: t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P)
    return s.bracket(gram, lambda t: t.killing(t.Psi, t.Psi))


@claim("gram-not-in-involution-with-psi", nature="literal", paper=("so(n)+so(r)", "SO(n)-inv"), unlabelled=("Remark 4.2",), kind="not", expect="nonzero",
       fails_at=lambda n, r: r in (1, n),
       place="Remark 4.2, after Theorem 4.5",
       erratum="""Remark 4.2 after Theorem 4.5 (the functions (p_i, p_j) do not Poisson-commute with ⟨Ψ, Ψ⟩,
       so the SO(n)-invariant functions are not conserved by the Euclidean geodesic flow) fails for r = 1, where
       Ψ = 0, and for r = n, where P = XW with W = XᵀP skew, Ψ = 2W and PᵀP = −Ψ²/4 is a function of
       Ψ, which commutes with the Casimir ⟨Ψ, Ψ⟩ of so(r) (verified by the claim
       gram-commutes-with-psi-if-r-is-1-or-n).  It holds for 2 ≤ r ≤ n − 1.  A reader may take 2 ≤ r ≤ n − 1 as the
       remark's tacit hypothesis: at r = 1 (XᵀP = 0) and at r = n (H_κ = −(1 + κ) tr W² with P = XW) the metrics
       ds²_κ all coincide up to a factor, so the Euclidean flow is the normal one there, up to a constant factor
       of time.""",
       statement=r"\{(p_i,p_j),\langle\Psi,\Psi\rangle\}\not\equiv0")
def gram_does_not_commute_with_psi_squared(s):
    """The remark after Theorem ET: the SO(n)-invariant functions (p_i, p_j) do not Poisson-commute with ⟨Ψ, Ψ⟩ (tested on Σ g_ij (p_i, p_j) = tr(G PᵀP) with generic G), so, as they commute with ⟨Φ, Φ⟩, they are not conserved by the Euclidean geodesic flow."""
    return {"{tr(G PᵀP), ⟨Ψ, Ψ⟩}": bracket_gram_psi(s)}


@claim("gram-commutes-with-psi-if-r-is-1-or-n", paper=("so(n)+so(r)", "SO(n)-inv"), kind="pb",
       sizes=admissible(5, where=lambda n, r: r in (1, n), condition="r = 1 or r = n", r_in=(1, "n")),
       statement=r"r=n:\ P^TP=-\tfrac14\Psi^2;\quad r=1:\ \Psi=0;\quad \{(p_i,p_j),\langle\Psi,\Psi\rangle\}=0")
def gram_commutes_with_psi_in_the_exceptional_cases(s):
    """For r = n, PᵀP = −Ψ²/4 on T*V, and for r = 1, Ψ = 0, so in both cases the functions (p_i, p_j) Poisson-commute with ⟨Ψ, Ψ⟩ (the sizes where the remark after Theorem ET fails)."""
    checks = {"P^T P + Psi^2/4": s.P.T @ s.P + s.Psi @ s.Psi / 4} if s.r == s.n else {"Psi (r = 1)": s.Psi}
    checks["{tr(G PᵀP), ⟨Ψ, Ψ⟩}"] = bracket_gram_psi(s)
    return checks


# -- Noether integrals ----------------------------------------------------------------------

def _phi_xi(t):
    """Φ_ξ = <Φ, ξ>."""
    return t.killing(t.Phi, t.xi)


def _psi_eta(t):
    """Ψ_η = <Ψ, η>."""
    return t.killing(t.Psi, t.eta)


def _gram(t):
    """Σ g_ij (p_i, p_j) = tr(G PᵀP) for a generic r x r matrix G: all the functions (p_i, p_j) at once."""
    return t.tr(t.generic("G", "r", "r") @ t.P.T @ t.P)


def H_normal(t):
    """(normal_metric) H₀ = ½<Φ, Φ> = h₀∘Φ, h₀ = ½<μ, μ>."""
    return t.killing(t.Phi, t.Phi) / 2


@claim("noether-normal-metric", paper=("bols-jov", "SO(n)-inv", "normal_metric", "man", "com"), unlabelled=("Remark 4.1",), kind="pb",
       statement=r"\{\Phi^*(C^\infty(so(n))),C^\infty(T^*V_{n,r})^{SO(n)}\}=0:\ \{\Phi_\xi,\Psi_\eta\}="
                 r"\{\Phi_\xi,(p_i,p_j)\}=\{\tr\Phi^4,(p_i,p_j)\}=\{\tr(\lambda A+\Phi)^3,(p_i,p_j)\}=0;\quad \{H_0,\Phi_\xi\}=\{H_0,\tr\Phi^4\}="
                 r"\{H_0,\Psi_\eta\}=\{H_0,(p_i,p_j)\}=0")
def noether_integrals_of_the_normal_metric(s):
    """The proof of Theorem bols-jov: by the Noether theorem Φ*(C∞(so(n))) (Φ_ξ, tr Φ⁴, and the integrals tr(λA + Φ)³ of (man), so that (man) and the SO(n)-invariant (com) commute, as the Remark after Theorem 4.2 says) commutes with the SO(n)-invariant functions Ψ_ij, (p_i, p_j), and H₀ = ½<Φ, Φ> commutes with both sets (with Φ*(C∞(so(n))) because h ↦ h∘Φ is a morphism of Poisson structures and ½<μ, μ> is a Casimir)."""
    trPhi4 = lambda t: power_trace(t, t.Phi, 4)   # noqa: E731
    man3 = lambda t: power_trace(t, t.lam * t.A + t.Phi, 3)   # noqa: E731
    return {
        "{tr(lambda A + Phi)^3, Psi_eta}": s.bracket(man3, _psi_eta),
        "{tr(lambda A + Phi)^3, (p_i, p_j)}": s.bracket(man3, _gram),
        "{Phi_xi, Psi_eta}": s.bracket(_phi_xi, _psi_eta),
        "{Phi_xi, (p_i, p_j)}": s.bracket(_phi_xi, _gram),
        "{tr Phi^4, Psi_eta}": s.bracket(trPhi4, _psi_eta),
        "{tr Phi^4, (p_i, p_j)}": s.bracket(trPhi4, _gram),
        "{H_0, Phi_xi}": s.bracket(H_normal, _phi_xi),
        "{H_0, tr Phi^4}": s.bracket(H_normal, trPhi4),
        "{H_0, Psi_eta}": s.bracket(H_normal, _psi_eta),
        "{H_0, (p_i, p_j)}": s.bracket(H_normal, _gram),
    }


@claim("jensen-invariants-conserved", paper=("ET", "so(n)+so(r)", "EM"), kind="pb",
       statement=r"f\in C^\infty(T^*V_{n,r})^{SO(n)\times SO(r)}:\ \{f,\Phi_\xi\}=\{f,\Psi_\eta\}=\{f,H_\kappa\}=0,"
                 r"\quad f=\tr(P^TP)^2,\ \tr(P^TP\Psi^2),\ \tr\Psi^4")
def jensen_flows_conserve_the_invariants(s):
    """Theorem ET: the SO(n)×SO(r)-invariant functions (here tr(PᵀP)², tr(PᵀPΨ²), tr Ψ⁴) commute with Φ*(C∞(so(n))) and Ψ*(C∞(so(r))) and are integrals of the geodesic flows of every Jensen metric H_κ, so the Euclidean and the normal metric share the integrals (so(n)+so(r))."""
    invariants = {
        "tr(P^T P)^2": lambda t: power_trace(t, t.P.T @ t.P, 2),
        "tr(P^T P Psi^2)": lambda t: t.tr(t.P.T @ t.P @ t.Psi @ t.Psi),
        "tr Psi^4": lambda t: power_trace(t, t.Psi, 4),
    }
    checks = {}
    for name, f in invariants.items():
        checks[f"{{{name}, Phi_xi}}"] = s.bracket(f, _phi_xi)
        checks[f"{{{name}, Psi_eta}}"] = s.bracket(f, _psi_eta)
        checks[f"{{{name}, H_kappa}}"] = s.bracket(f, H_jensen)
    return checks


@claim("euler-so-n", paper=("Euler-so(n)", "Manakov", "Manakov*"), kind="pb",
       equivariance="the Euler equations live on so(n): a generic ξ and a generic symmetric operator, no point of T*V; the basis of so(n) only writes the Hamiltonian vector field",
       statement=r"\dot f=\{f,h_{\mathbb A}\}^+_{so(n)}\iff\dot\xi=[\nabla h_{\mathbb A}(\xi),\xi]=[\mathbb A\xi,\xi];\quad "
                 r"\{\tr(\xi+\lambda A)^k,\tr(\xi+\mu A)^m\}^+=\{\tr(\xi+\lambda A)^k,h_{\mathbb A}\}^+=0,\ "
                 r"\mathbb A\xi=A\xi+\xi A")
def euler_equations_on_so_n(s):
    """(Euler-so(n)): the Hamiltonian vector field of h_𝔸 = ½<ξ, 𝔸ξ> for the (+) Lie–Poisson bracket on so(n) is ξ̇ = [𝔸ξ, ξ] (a generic symmetric 𝔸), and for the Manakov operator 𝔸ξ = Aξ + ξA the functions tr(ξ + λA)^k (k = 1, 2, 3) commute with each other and with h_𝔸."""
    from stiefelsym.brackets import SO_N, lie_poisson, quadratic, trace_power
    T = lie_poisson(SO_N, 1)
    xi = s.xi
    h_gen = quadratic(lambda t, x: t.sym_operator("AA")(x))
    h_man = quadratic(lambda t, x: manakov_square(t, x))
    fam = lambda k, nu: trace_power(k, shift=lambda t: nu(t) * t.A)   # noqa: E731
    checks = {"xi' - [AA xi, xi]": T.sharp(s, xi, h_gen.grad(s, xi)) - comm(s.sym_operator("AA")(xi), xi)}
    for k in POWERS:
        for m in POWERS:
            if m >= k:
                checks[f"{{tr(xi+lambda A)^{k}, tr(xi+mu A)^{m}}}+"] = T.bracket(
                    s, fam(k, lambda t: t.lam), fam(m, lambda t: t.scalar("mu")), xi)
        checks[f"{{tr(xi+lambda A)^{k}, h_AA}}+ (Manakov)"] = T.bracket(s, fam(k, lambda t: t.lam), h_man, xi)
    return checks
