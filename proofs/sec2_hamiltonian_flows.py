"""§2 Hamiltonian flows on Stiefel varieties: the constraints of T*V(n, r), the
Dirac bracket, the momentum maps Φ and Ψ, SO(n)-invariant functions and the
chain algebra."""
from __future__ import annotations

from itertools import combinations

from stiefelsym import Count, Inverse, Rank, RightInverse, admissible, claim, comm

SECTION = "2"


# -- dimensions printed in the section -----------------------------------------

def dim_so(m):
    """dim SO(m) = m(m-1)/2 (0 for m <= 1)."""
    return m * (m - 1) // 2 if m > 1 else 0


def dim_V(n, r):
    """§2: dim V(n, r) = N = rn - r(r+1)/2."""
    return r * n - r * (r + 1) // 2


def ddim_printed(n, r):
    """(ddim): the differential dimension of the SO(n)-invariant functions."""
    if n <= 2 * r:
        return dim_V(n, r) - dim_so(n - r)
    return dim_V(n, r) - dim_so(n - r) + dim_so(n - 2 * r)


def two_l_printed(n, r):
    """Lemma (2l): the dimension 2l of a generic adjoint orbit in Φ(T*V)."""
    if n <= 2 * r + 1:
        return n * (n - 1) // 2 - n // 2
    return 2 * r * (n - r - 1)


# -- small constructions ---------------------------------------------------------

def Phi_xi(t):
    """Φ_ξ = <Φ, ξ>."""
    return t.killing(t.Phi, t.xi)


def Phi_zeta(t):
    """Φ_ζ = <Φ, ζ>."""
    return t.killing(t.Phi, t.zeta)


def Psi_eta(t):
    """Ψ_η = <Ψ, η>."""
    return t.killing(t.Psi, t.eta)


def Psi_theta(t):
    """Ψ_θ = <Ψ, θ>."""
    return t.killing(t.Psi, t.theta)


def H_linear(t):
    """H = tr(U^T X) + tr(V^T P) with generic U, V: its differential at a point is arbitrary."""
    return t.tr(t.generic("U", "n", "r").T @ t.X) + t.tr(t.generic("V", "n", "r").T @ t.P)


def upper(M):
    """The upper triangle (diagonal included) of a symmetric r x r matrix, as scalars."""
    m = M.shape[0]
    return [M[i, j] for i in range(m) for j in range(i, m)]


def cond_XP(t):
    """(cond_XP): the matrix constraints X^T X - I_r and X^T P + P^T X."""
    return [t.X.T @ t.X - t.Ir, t.X.T @ t.P + t.P.T @ t.X]


def unit(s, m, k, a, b):
    """The m x k matrix unit E_ab."""
    return s.mat([[s.q(1) if (i, j) == (a, b) else s.q(0) for j in range(k)] for i in range(m)])


def wedge_basis(s, m):
    """The orthonormal basis E_i ∧ E_j (i < j) of so(m) for <,>."""
    return [unit(s, m, m, i, j) - unit(s, m, m, j, i) for i in range(m) for j in range(i + 1, m)]


def vertical_directions(s):
    """Tangent vectors (0, δP) spanning the fibre T(T*_X V) = {X^T δP + δP^T X = 0}:
    δP = X ω (ω in a basis of so(r)) and δP = (I - X X^T) E_ab (all matrix units)."""
    n, r = s.n, s.r
    zero = s.zeros(n, r, ("n", "r"))
    dirs = [{"X": zero, "P": s.X @ w} for w in wedge_basis(s, r)]
    horizontal = s.In - s.X @ s.X.T
    dirs += [{"X": zero, "P": horizontal @ unit(s, n, r, a, b)} for a in range(n) for b in range(r)]
    return dirs


def lower_block(s, m):
    """The projector diag(0, ..., 0, 1, ..., 1) onto the last m coordinates of R^n."""
    n = s.n
    return s.mat([[s.q(1) if i == j and i >= n - m else s.q(0) for j in range(n)] for i in range(n)])


def chain_generators(n, r):
    """(m, k) with tr(ξ_(m)^{2k}) a generator of 𝔄: n - r < m <= n, 2k <= m."""
    return [(m, k) for m in range(n - r + 1, n + 1) for k in range(1, m // 2 + 1)]


def chain_gradient(s, xi, m, k):
    """∇f = Σ_{i<j} ∂f/∂ξ_ij E_i∧E_j for f(ξ) = tr(ξ_(m)^{2k}); ∂f/∂ξ_ij = 2k tr(ξ_(m)^{2k-1} (E_i∧E_j)_(m))."""
    Pm = lower_block(s, m)
    block_xi = Pm @ xi @ Pm
    power = s.In
    for _ in range(2 * k - 1):
        power = power @ block_xi
    grad = s.zeros(s.n, s.n, ("n", "n"))
    for e in wedge_basis(s, s.n):
        grad = grad + e * (s.tr(power @ Pm @ e @ Pm) * (2 * k))
    return grad


# -- the cotangent bundle as a constraint set -------------------------------------

@claim("constraints-independent", paper=("cond_XP", "scalar"), kind="dim", exact_max_n=7,
       equivariance="the differential of the constraint map (cond_XP) is a matrix expression in X, P, "
                    "and its right inverse too (O(n)-covariant)",
       statement=r"d(F_1,F_2)\ \text{maps } \mathbb R^{n\times r}\times\mathbb R^{n\times r} \text{ onto "
                 r"Sym}(r)\times\text{Sym}(r) \text{ on } T^*V_{n,r}:\ \rank\frac{\partial(F_{ij},G_{ij})}"
                 r"{\partial(X,P)}=r(r+1),\quad \dim V_{n,r}=rn-\tfrac{r(r+1)}{2}")
def constraints_are_independent(s):
    """The r(r+1) scalar constraints (scalar) have independent differentials at every point of T*V (dF maps onto Sym(r) × Sym(r), of dimension r(r+1): it has a right inverse), and X^T X = I_r cuts out V(n, r) of dimension rn − r(r+1)/2 (d(XᵀX) maps onto Sym(r) at every point of V)."""
    def dF(t, dX, dP):      # (δX, δP) ↦ (δXᵀX + XᵀδX, δXᵀP + XᵀδP + δPᵀX + PᵀδX), into Sym(r) × Sym(r)
        return tuple(t.d(cond_XP, {"X": dX, "P": dP}))

    def dF_right(t, a, b):  # on T*V, with K = XᵀP: aK − Ka is symmetric and dF(δX, δP) = (a, b)
        K = t.X.T @ t.P
        return t.X @ a / 2, t.X @ (b / 2 - (a @ K - K @ a) / 4)

    def dG(t, dX):          # d(XᵀX): δX ↦ δXᵀX + XᵀδX, into Sym(r)
        return t.d(lambda u: u.X.T @ u.X, {"X": dX, "P": t.zeros(t.n, t.r, ("n", "r"))})

    def dG_right(t, a):
        return t.X @ a / 2

    return {
        "rank d(F, G)": RightInverse(dF, dF_right, on=("R^{n×r}", "R^{n×r}"), to=("Sym(r)", "Sym(r)"),
                                     meaning="the constraints (scalar) are independent on T*V"),
        "dim V": RightInverse(dG, dG_right, on="R^{n×r}", to="Sym(r)",
                              meaning="X^T X = I_r is a regular level: nr - dim V = dim Sym(r) = r(r+1)/2"),
    }


# -- the Dirac bracket and the Lagrange-multiplier form -----------------------------

def constraint_brackets(s, S, T):
    """{F_i, F_j}_0 as an operator on Sym(r) × Sym(r): (S, T) ↦ ({F_1, h}_0, {F_2, h}_0) = dF(X⁰_h) for
    h = tr(S F_1) + tr(T F_2), the matrix {F_i, F_j}_0 applied to the coefficients of h."""
    def h(t):
        F1, F2 = cond_XP(t)
        return t.tr(S @ F1) + t.tr(T @ F2)
    return tuple(s.d(cond_XP, s.canonical_flow(h)))


def constraint_brackets_inverse(s, a, b):
    """Its inverse on T*V: T = a/4, S = (aK − Ka − b)/4 with K = XᵀP (the operator is (4T, 4(TK − KT) − 4S) there)."""
    K = s.X.T @ s.P
    return (a @ K - K @ a - b) / 4, a / 4


def multiplier_system(s, Lam, Pi):
    """(Λ, Π) ↦ the derivative of the constraints (F_1, F_2) along the multiplier directions
    (δX, δP) = (−XΠ, XΛ + PΠ) of (dot_XP): the linear system the multipliers solve."""
    return tuple(s.d(cond_XP, {"X": -(s.X @ Pi), "P": s.X @ Lam + s.P @ Pi}))


def multiplier_system_inverse(s, a, b):
    """Its inverse on T*V: Π = −a/2, Λ = (b + Ka − aK)/2 with K = XᵀP (the system is (−2Π, 2Λ + 2(KΠ − ΠK)) there)."""
    K = s.X.T @ s.P
    return (b + K @ a - a @ K) / 2, -a / 2


@claim("dirac-bracket-multipliers", paper=("Dirac_bracket", "dot_XP"), kind="pb",
       equivariance="the operators {F_i, F_j}_0 and the multiplier system act on Sym(r) x Sym(r) (O(n)-invariant); "
                    "their inverses are matrix expressions in X, P; the flows are covariant",
       statement=r"\det\big(\{F_i,F_j\}_0\big)\ne0 \text{ on } T^*V_{n,r};\quad \dot f=\{f,H\}\iff "
                 r"\dot X=\tfrac{\partial H}{\partial P}-X\Pi,\ \dot P=-\tfrac{\partial H}{\partial X}+X\Lambda+P\Pi,"
                 r"\ \Lambda^T=\Lambda,\ \Pi^T=\Pi \text{ unique}")
def dirac_flow_is_the_multiplier_form(s):
    """The matrix {F_i, F_j}_0 is invertible on T*V, and the Dirac flow of any H is (dot_XP) with unique symmetric multipliers Λ, Π (both sides depend linearly on dH at the point, so H = tr(UᵀX) + tr(VᵀP) with generic U, V suffices)."""
    dirac = s.dirac_flow(H_linear)
    mult = s.multiplier_flow(H_linear)
    Lam, Pi = mult["Lambda"], mult["Pi"]
    HX, HP = s.gradient(H_linear)
    return {
        "{F_i, F_j}_0 invertible": Inverse(constraint_brackets, constraint_brackets_inverse, on=("Sym(r)", "Sym(r)"),
                                           meaning="the Dirac bracket is defined on T*V"),
        "Lambda, Pi unique": Inverse(multiplier_system, multiplier_system_inverse, on=("Sym(r)", "Sym(r)"),
                                     meaning="the multipliers are determined by the constraints"),
        "dX/dt": dirac.Xdot - (HP - s.X @ Pi),
        "dP/dt": dirac.Pdot - (-HX + s.X @ Lam + s.P @ Pi),
        "constraints kept by the Dirac flow": s.d(s.constraints.build, dirac),
    }


# -- momentum maps -------------------------------------------------------------------

def momentum_map_checks(s, H, action, name, x_text, p_text, equivariance):
    """H generates the action: {H, F_i}_0 = 0 on T*V, its Dirac and canonical flows agree and
    equal the infinitesimal action, and the momentum map is equivariant."""
    canonical = s.canonical_flow(H)
    dirac = s.dirac_flow(H)
    return {
        f"{{{name}, F_i}}_0 on T*V": [-dF for dF in s.d(cond_XP, canonical)],
        "Dirac flow = canonical flow (X)": dirac.Xdot - canonical.Xdot,
        "Dirac flow = canonical flow (P)": dirac.Pdot - canonical.Pdot,
        f"dX/dt = {x_text}": dirac.Xdot - action["X"],
        f"dP/dt = {p_text}": dirac.Pdot - action["P"],
        "equivariance": equivariance,
    }


@claim("left-momentum-map", paper=("Phi", "momentum_map", "zero", "left_action"), kind="pb",
       equivariance="the matrix units only span the tangent directions of the fibre; the checks are covariant",
       statement=r"\{\Phi_\xi,F_i\}_0=0,\quad X_{\Phi_\xi}=X^0_{\Phi_\xi}=(\xi X,\xi P),\quad "
                 r"\tfrac{d}{ds}\Phi(e^{s\xi}X,e^{s\xi}P)\big|_{s=0}=[\xi,\Phi],\quad \Phi=PX^T-XP^T")
def phi_is_the_left_momentum_map(s):
    """Φ = PXᵀ − XPᵀ is the momentum map of the left SO(n) action: {Φ_ξ, F_i}_0 = −dF_i(X⁰_{Φ_ξ}) = 0, the Dirac and canonical flows of Φ_ξ are both (ξX, ξP), and Φ is equivariant."""
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    return momentum_map_checks(s, Phi_xi, left, "Phi_xi", "xi X", "xi P",
                               s.d(lambda t: t.Phi, left) - comm(s.xi, s.Phi))


@claim("right-momentum-map", paper=("momentum_right_map", "right_action"), kind="pb",
       equivariance="the matrix units only span the tangent directions of the fibre; the checks are covariant",
       statement=r"\{\Psi_\eta,F_i\}_0\big|_{T^*V}=0,\quad X_{\Psi_\eta}=X^0_{\Psi_\eta}=(X\eta,P\eta),\quad "
                 r"\tfrac{d}{ds}\Psi(Xe^{s\eta},Pe^{s\eta})\big|_{s=0}=[\Psi,\eta],\quad \Psi=X^TP-P^TX")
def psi_is_the_right_momentum_map(s):
    """Ψ = XᵀP − PᵀX is the momentum map of the right SO(r) action: {Ψ_η, F_i}_0 = 0 on T*V, the Dirac and canonical flows of Ψ_η are both (Xη, Pη), and Ψ(XQ, PQ) = QᵀΨQ infinitesimally."""
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    return momentum_map_checks(s, Psi_eta, right, "Psi_eta", "X eta", "P eta",
                               s.d(lambda t: t.Psi, right) - comm(s.Psi, s.eta))


@claim("momentum-maps-poisson", paper=("Phi", "momentum_map", "momentum_right_map"), kind="pb",
       statement=r"\{\Phi_\xi,\Phi_\zeta\}=\langle\Phi,[\xi,\zeta]\rangle,\quad "
                 r"\{\Psi_\eta,\Psi_\theta\}=-\langle\Psi,[\eta,\theta]\rangle,\quad \{\Phi_\xi,\Psi_\eta\}=0")
def momentum_maps_are_poisson(s):
    """For the Dirac bracket, Φ is Poisson for the (+) Lie–Poisson bracket on so(n), Ψ for the (−) bracket on so(r), and Φ, Ψ commute (linear functions h(μ) = <μ, ξ> suffice by the Leibniz rule)."""
    return {
        "{Phi_xi, Phi_zeta} (+)": s.bracket(Phi_xi, Phi_zeta) - s.killing(s.Phi, comm(s.xi, s.zeta)),
        "{Psi_eta, Psi_theta} (-)": s.bracket(Psi_eta, Psi_theta) + s.killing(s.Psi, comm(s.eta, s.theta)),
        "{Phi_xi, Psi_eta}": s.bracket(Phi_xi, Psi_eta),
    }


# -- SO(n)-invariant functions ----------------------------------------------------------

@claim("invariants-differential-dimension", paper=("ddim", "SO(n-r)-action", "P-neutral"), kind="dim", exact_max_n=7,
       equivariance="the statement is about the fibre T*_{X0}V itself (P2 is a fresh generic matrix)",
       statement=r"\ddim C^\infty(T^*V_{n,r})^{SO(n)}=\dim T^*_{X_0}V_{n,r}-\dim SO(n-r)\cdot P_0"
                 r"=\begin{cases}\dim V_{n,r}-\dim SO(n-r),&n\le2r\\ "
                 r"\dim V_{n,r}-\dim SO(n-r)+\dim SO(n-2r),&n>2r\end{cases}")
def differential_dimension_of_invariants(s):
    """The codimension of a generic SO(n−r)-orbit P₂ ↦ BP₂ in the fibre T*_{X₀}V equals the printed (ddim) in both cases n ≤ 2r and n > 2r."""
    n, r = s.n, s.r
    P2 = s.general_params("P2", n - r, r, ("n-r", "r"))
    targets = [unit(s, n - r, r, a, c) for a in range(n - r) for c in range(r)]
    # the matrix of b -> b P2, so(n-r) -> M_{n-r,r}, in the bases E_i∧E_j and E_ac (trace pairing)
    orbit_map = s.mat([[s.tr(E.T @ b @ P2) for E in targets] for b in wedge_basis(s, n - r)])
    fibre = dim_so(r) + (n - r) * r   # P1 skew, P2 arbitrary
    zero = s.zeros(n, r, ("n", "r"))
    columns = [upper(s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, {"X": zero, "P": unit(s, n, r, a, c)}))
               for a in range(n) for c in range(r)]
    fibre_equations = s.mat([list(row) for row in zip(*columns)], ("cond", "coord"))
    return {
        "dim of the fibre": Rank(fibre_equations, n * r - fibre, generic=True,
                                 meaning="nr - dim T*_{X0}V: the fibre {X^T P + P^T X = 0} has the dimension "
                                         "dim so(r) + (n-r)r = dim V of the parametrization (P1, P2)"),
        "generic orbit dimension": Rank(orbit_map, fibre - ddim_printed(n, r), generic=True,
                                        meaning="dim SO(n-r)·P0 = dim V - ddim"),
    }


@claim("invariants-so-n", paper=("SO(n)-inv",), kind="id",
       statement=r"\tfrac{d}{ds}\Psi(e^{s\xi}X,e^{s\xi}P)=0,\quad \tfrac{d}{ds}(P^TP)(e^{s\xi}X,e^{s\xi}P)=0")
def psi_and_gram_are_invariant(s):
    """Ψ_ij and (PᵀP)_ij are SO(n)-invariant: their derivatives along the left action (ξX, ξP) vanish."""
    left = {"X": s.xi @ s.X, "P": s.xi @ s.P}
    return {
        "d Psi": s.d(lambda t: t.Psi, left),
        "d(P^T P)": s.d(lambda t: t.P.T @ t.P, left),
    }


def fibre_kernel(s):
    """Kernel vectors of the differentials of Ψ_ij, (PᵀP)_ij along :func:`vertical_directions` (the columns
    of :func:`psi_and_gram_give_ddim_functions`), as coefficients of those directions: the r² relations
    among the directions ((I − XXᵀ)XB = 0, B ∈ gl(r)), and the infinitesimal action δP = ξP of the
    stabilizer so(X^⊥) = Q so(n) Q of X (Q = I − XXᵀ), which moves in the fibre and leaves the SO(n)-invariant
    Ψ and PᵀP fixed (§2, (ddim): its generic orbit in the fibre has dimension dim so(n − r), less
    dim so(n − 2r) for n > 2r)."""
    n, r = s.n, s.r
    zero_w = [s.q(0)] * (r * (r - 1) // 2)
    Q = s.In - s.X @ s.X.T

    def coefficients(C):   # the direction (0, (I − XXᵀ)C) as coefficients of the matrix units
        return zero_w + [C[a, b] for a in range(n) for b in range(r)]
    vectors = [coefficients(s.X @ unit(s, r, r, c, d)) for c in range(r) for d in range(r)]
    vectors += [coefficients(Q @ e @ Q @ s.P) for e in wedge_basis(s, n)]
    return kernel_matrix(s, vectors)


@claim("invariants-complete", paper=("SO(n)-inv", "ddim"), kind="dim", exact_max_n=7,
       equivariance="the statement is about the fibre T*_{X0}V itself",
       statement=r"\rank d\big(\Psi_{ij},(P^TP)_{ij}\big)\big|_{T^*_{X_0}V_{n,r}}=\ddim C^\infty(T^*V_{n,r})^{SO(n)}")
def psi_and_gram_give_ddim_functions(s):
    """Restricted to the fibre T*_{X₀}V, the functions Ψ_ij and (PᵀP)_ij have ddim independent differentials (any spanning set of the fibre directions gives the same rank)."""
    n, r = s.n, s.r
    columns = []
    for v in vertical_directions(s):
        dPsi = s.d(lambda t: t.Psi, v)
        dG = s.d(lambda t: t.P.T @ t.P, v)
        columns.append([dPsi[i, j] for i in range(r) for j in range(i + 1, r)] + upper(dG))
    jac = s.mat([list(row) for row in zip(*columns)])
    return {
        "rank on the fibre": Rank(jac, ddim_printed(n, r), generic=True,
                                  meaning="independent SO(n)-invariant functions", kernel=fibre_kernel(s)),
    }


def ad_matrix(s, mu):
    """The matrix <e_l, [mu, e_k]> of ad_mu on so(n) in the orthonormal basis e_k = E_i∧E_j."""
    basis = wedge_basis(s, s.n)
    return s.mat([[s.killing(e_l, comm(mu, e_k)) for e_k in basis] for e_l in basis])


def kernel_matrix(s, vectors):
    """The matrix whose columns are ``vectors`` (lists of scalars of one length): a kernel certificate."""
    return s.mat([list(row) for row in zip(*vectors)])


def so_coordinates(xi):
    """The coordinates <ξ, E_i∧E_j> = ξ_ij (i < j) of ξ ∈ so(m) in the basis :func:`wedge_basis`."""
    m = xi.shape[0]
    return [xi[i, j] for i in range(m) for j in range(i + 1, m)]


def cofactor_det(s, rows):
    """The determinant of a small square list of lists of scalars, by the Laplace expansion."""
    m = len(rows)
    if m == 0:
        return s.q(1)
    acc = s.q(0)
    for c in range(m):
        term = rows[0][c] * cofactor_det(s, [row[:c] + row[c + 1:] for row in rows[1:]])
        acc = acc - term if c % 2 else acc + term
    return acc


def adjugate(s, G):
    """(adj G, det G) for a small square matrix G, by cofactors: G adj G = det G · I, no division."""
    m = G.shape[0]
    rows = [[G[i, j] for j in range(m)] for i in range(m)]

    def minor(i, j):    # rows without i, columns without j
        return [row[:j] + row[j + 1:] for k, row in enumerate(rows) if k != i]
    adj = s.mat([[cofactor_det(s, minor(j, i)) * (-1 if (i + j) % 2 else 1) for j in range(m)]
                 for i in range(m)])
    return adj, cofactor_det(s, rows)


def annihilator_of_point(s):
    """Q = det G·(I − XXᵀ) − P₁ adj(G) P₁ᵀ with P₁ = (I − XXᵀ)P, G = P₁ᵀP₁: symmetric, polynomial, QX = QP = 0
    on T*V, and det G times the projector onto span(X, P)^⊥ (the kernel of Φ at a generic point)."""
    pi_perp = s.In - s.X @ s.X.T
    P1 = pi_perp @ s.P
    adj, det = adjugate(s, P1.T @ P1)
    return det * pi_perp - P1 @ adj @ P1.T


def ad_phi_kernel(s):
    """The centralizer of Φ in so(n), the kernel of ad_Φ (Lemma 2l: dim so(n) − 2l), in the coordinates of
    :func:`ad_matrix`'s columns: the odd powers Φ, Φ³, … (the Cartan subalgebra through a generic Φ of rank
    min(2r, n), [n/2] of them for n ≤ 2r + 1, r otherwise) and, for n > 2r + 1, so(ker Φ) = Q so(n) Q,
    Q = :func:`annihilator_of_point` (Φ = PXᵀ − XPᵀ vanishes on span(X, P)^⊥)."""
    n, r = s.n, s.r
    Phi = s.Phi
    square = Phi @ Phi
    powers, acc = [], Phi
    for _ in range(n // 2 if n <= 2 * r + 1 else r):
        powers.append(acc)
        acc = acc @ square
    vectors = [so_coordinates(xi) for xi in powers]
    if n > 2 * r + 1:
        Q = annihilator_of_point(s)
        vectors += [so_coordinates(Q @ e @ Q) for e in wedge_basis(s, n)]
    return kernel_matrix(s, vectors)


@claim("adjoint-orbit-dimension", paper=("2l",), kind="dim", exact_max_n=7,
       equivariance="the rank of ad_Phi does not depend on the basis of so(n) and is invariant under Phi -> g Phi g^T",
       statement=r"\dim\big(\Ad_{SO(n)}\Phi(X_0,P_0)\big)=2l=\begin{cases}\tfrac{n(n-1)}2-\left[\tfrac n2\right],"
                 r"&n\le2r+1\\ 2r(n-r-1),&n>2r+1\end{cases}")
def generic_adjoint_orbit_dimension(s):
    """A generic adjoint orbit in Φ(T*V) = Ad Φ(T*_{X₀}V) has the dimension 2l printed in Lemma 2l."""
    return {"rank of ad Φ": Rank(ad_matrix(s, s.Phi), two_l_printed(s.n, s.r), generic=True, meaning="2l",
                                  kernel=ad_phi_kernel(s))}


@claim("adjoint-orbit-regularity", nature="range", paper=("2l",), kind="dim", exact_max_n=7,
       fails_at=lambda n, r: n == 2 * r + 2,
       place="the paragraph before Lemma 2.5",
       erratum="""The paragraph before Lemma 2.5 says that the generic orbit in Φ(T*V) is regular for
       n ≤ 2r + 1 and singular otherwise.  For n = 2r + 2 the generic orbit is regular as well (there the second
       case of Lemma 2.5, 2r(n − r − 1) = 2r(r + 1), equals the regular dimension n(n − 1)/2 − [n/2]); the orbit is regular iff n ≤ 2r + 2.  The
       witness codes the answer as a number: 1 for regular, 0 for singular; at n = 2r + 2 it computes 1, where the
       printed statement gives 0.""",
       equivariance="the rank of ad_Phi does not depend on the basis of so(n) and is invariant under Phi -> g Phi g^T",
       statement=r"\Ad_{SO(n)}\Phi(X_0,P_0)\ \text{regular}\iff n\le 2r+1,\qquad "
                 r"\text{regular: }\dim=\tfrac{n(n-1)}2-\left[\tfrac n2\right]")
def generic_adjoint_orbit_is_regular_iff(s):
    """The generic adjoint orbit in Φ(T*V) is regular for n ≤ 2r + 1 and singular otherwise (the remark before Lemma 2l)."""
    n, r = s.n, s.r
    regular = n * (n - 1) // 2 - n // 2
    return {
        "rank of ad Φ": Rank(ad_matrix(s, s.Phi), two_l_printed(n, r), generic=True, meaning="2l",
                             kernel=ad_phi_kernel(s)),
        "regular iff n ≤ 2r + 1": Count(int(two_l_printed(n, r) == regular), int(n <= 2 * r + 1),
                                       "the generic orbit is regular (1) or singular (0)"),
    }


@generic_adjoint_orbit_is_regular_iff.claim.correction("regular iff n <= 2r + 2")
def generic_adjoint_orbit_is_regular_iff_corrected(s):
    n, r = s.n, s.r
    regular = n * (n - 1) // 2 - n // 2
    return {
        "rank of ad Φ": Rank(ad_matrix(s, s.Phi), two_l_printed(n, r), generic=True, meaning="2l",
                             kernel=ad_phi_kernel(s)),
        "regular iff n ≤ 2r + 2": Count(int(two_l_printed(n, r) == regular), int(n <= 2 * r + 2),
                                       "the generic orbit is regular (1) or singular (0)"),
    }


@claim("chain-algebra-commutative", paper=("com", "hat", "hat2", "iso"), kind="pb", exact_max_n=6,
       exact_max_r={7: 4}, exact_corank={7: 2},
       equivariance="the statement is about a generic element of the subspace v of so(n); no point of T*V enters",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2 (so(1) = 0 has no invariants)"),
       statement=r"\{\tr\xi_{(m)}^{2k},\tr\xi_{(m')}^{2k'}\}_{\mathfrak v}(\xi)="
                 r"-\langle\xi,[\nabla\tr\xi_{(m)}^{2k},\nabla\tr\xi_{(m')}^{2k'}]\rangle=0,\quad "
                 r"\xi\in\mathfrak v,\ n-r<m,m'\le n")
def chain_algebra_commutes(s):
    """The generators tr ξ_{(m)}^{2k} (n − r < m ≤ n) of 𝔄 = 𝔄₁ + … + 𝔄_r pairwise commute for {f, g}_𝔳(ξ) = −<ξ, [∇f, ∇g]> at a generic ξ ∈ 𝔳 (gradients taken on so(n))."""
    n, r = s.n, s.r
    xi = s.xi - lower_block(s, n - r) @ s.xi @ lower_block(s, n - r)   # zero lower-right block: ξ ∈ 𝔳
    gens = chain_generators(n, r)
    grads = {g: chain_gradient(s, xi, *g) for g in gens}
    checks = {f"{{tr xi_({m})^{2 * k}, tr xi_({m2})^{2 * k2}}}":
              -s.killing(xi, comm(grads[(m, k)], grads[(m2, k2)]))
              for (m, k), (m2, k2) in combinations(gens, 2)}
    for m, k in gens:   # each generator is an invariant of so(m): [∇f, ξ_(m)] = 0
        checks[f"tr xi_({m})^{2 * k} is so({m})-invariant"] = comm(
            grads[(m, k)], lower_block(s, m) @ xi @ lower_block(s, m))
    return checks


# -- the momentum maps as Poisson maps, for functions that are not linear -----------------

def _so_n_functions():
    """Functions on so(n): h₁ = ½<μ, 𝔸μ> (𝔸 a generic symmetric operator), h₂ = tr(μ + λA)³, h₃ = tr μ⁴."""
    from stiefelsym.brackets import quadratic, trace_power
    return [("1/2<mu, AA mu>", quadratic(lambda t, mu: t.sym_operator("AA")(mu))),
            ("tr(mu + lambda A)^3", trace_power(3, shift=lambda t: t.lam * t.A)),
            ("tr mu^4", trace_power(4))]


def _so_r_functions():
    """Functions on so(r): f₁ = ½<η, θ>², f₂ = tr(η + μB)³ (B generic symmetric), f₃ = tr η⁴."""
    from stiefelsym.brackets import linear, trace_power
    lin = linear(lambda t: t.theta, "<eta, theta>")
    B = lambda t: t.generic("B", "r", "r") + t.generic("B", "r", "r").T   # noqa: E731
    return [("<eta, theta>^2", lin * lin),
            ("tr(eta + mu B)^3", trace_power(3, shift=lambda t: t.scalar("mu") * B(t))),
            ("tr eta^4", trace_power(4))]


@claim("momentum-maps-poisson-nonlinear", paper=("Phi", "momentum_map", "momentum_right_map"), kind="pb",
       exact_max_n=5, exact_max_r={6: 4, 7: 4},
       statement=r"\{h_1\circ\Phi,h_2\circ\Phi\}=\{h_1,h_2\}^+_{so(n)}(\Phi),\ "
                 r"\{f_1\circ\Psi,f_2\circ\Psi\}=\{f_1,f_2\}^-_{so(r)}(\Psi),\ \{h\circ\Phi,f\circ\Psi\}=0,\ "
                 r"\{h_1,h_2\}^\pm(\mu)=\pm\langle\mu,[\nabla h_1,\nabla h_2]\rangle")
def momentum_maps_are_poisson_for_nonlinear_functions(s):
    """As printed after Proposition Phi, for functions that are not linear: Φ is Poisson for the (+) and Ψ for the (−) Lie–Poisson bracket, and Φ*(C∞(so(n))) commutes with Ψ*(C∞(so(r))) (h = ½<μ, 𝔸μ>, tr(μ + λA)³, tr μ⁴ on so(n); f = <η, θ>², tr(η + μB)³, tr η⁴ on so(r))."""
    from stiefelsym.brackets import SO_N, SO_R, lie_poisson
    plus, minus = lie_poisson(SO_N, 1), lie_poisson(SO_R, -1)
    Phi, Psi = (lambda t: t.Phi), (lambda t: t.Psi)
    hs, fs = _so_n_functions(), _so_r_functions()
    checks = {}
    for i, (n1, h1) in enumerate(hs):
        for n2, h2 in hs[i + 1:]:
            checks[f"{{{n1}, {n2}}} (+)"] = (s.bracket(h1.pullback(Phi), h2.pullback(Phi))
                                            - plus.bracket(s, h1, h2, s.Phi))
    for i, (n1, f1) in enumerate(fs):
        for n2, f2 in fs[i + 1:]:
            checks[f"{{{n1}, {n2}}} (-)"] = (s.bracket(f1.pullback(Psi), f2.pullback(Psi))
                                            - minus.bracket(s, f1, f2, s.Psi))
    for n1, h in hs:
        for n2, f in fs:
            checks[f"{{{n1} o Phi, {n2} o Psi}}"] = s.bracket(h.pullback(Phi), f.pullback(Psi))
    return checks

