"""§7 Reduction to Grassmannians: the Neumann flows on Ψ = 0, the reduced equation on e_1∧…∧e_r, the case r = n − 1 and the quartic Hamiltonian."""
from __future__ import annotations

from itertools import combinations

from stiefelsym import Count, Rank, admissible, claim, comm  # noqa: F401

from .determinants import det
from .sec5_neumann import H_neumann_euclidean, H_neumann_normal
from .sec6_dimension_lemmas import EQUIVARIANCE_X, lambda1

SECTION = "7"


# -- Plücker coordinates (coordinates of ℝⁿ; determinants: .determinants) --------------------------------

def columns(M, k):
    """The k columns of M (each a list of its entries)."""
    m = M.shape[0]
    return [[M[i, j] for i in range(m)] for j in range(k)]


def wedge(s, cols, I):
    """(v_1 ∧ … ∧ v_k)_I: the minor of the vectors ``cols`` (lists of entries) on the rows I."""
    return det(s, [[v[i] for v in cols] for i in I])


def plucker(s, cols, n):
    """All Plücker coordinates (v_1 ∧ … ∧ v_k)_I, I ⊂ {1..n}, |I| = k, in lexicographic order."""
    return [wedge(s, cols, I) for I in combinations(range(n), len(cols))]


def column(s, entries):
    """A column of scalars (Plücker coordinates and the like) as an untyped matrix."""
    return s.mat([[x] for x in entries], ("?", "?"))


def replaced(cols, changes):
    """The list of vectors ``cols`` with the vectors at the positions of ``changes`` replaced."""
    out = list(cols)
    for i, v in changes.items():
        out[i] = v
    return out


# -- Ψ = 0: the Neumann flows (N0_XP2) and (NE_XP) coincide ------------------------------------

def horizontal(s, X, P):
    """(I − XXᵀ)P: the momentum of a point of Ψ⁻¹(0) (XᵀP = 0) over X."""
    return P - X @ (X.T @ P)


def flow_NE_at(s, X, P):
    """(NE_XP) at the point (X, P): Ẋ = P, Ṗ = −AX − XPᵀP + XXᵀAX."""
    A = s.A
    return {"X": P, "P": -(A @ X) - X @ P.T @ P + X @ X.T @ A @ X}


def flow_N0_at(s, X, P):
    """(N0_XP2) at the point (X, P): Ẋ = P − XPᵀX, Ṗ = −AX + PXᵀP − XPᵀP + XXᵀAX."""
    A = s.A
    return {"X": P - X @ P.T @ X, "P": -(A @ X) + P @ X.T @ P - X @ P.T @ P + X @ X.T @ A @ X}


@claim("neumann-flows-coincide-on-psi-zero", paper=("grassmannian", "N0_XP2", "NE_XP"), kind="id",
       sizes=admissible(n_max=5),
       statement=r"(\dot X,\dot P)_{\kappa=0}-(\dot X,\dot P)_{\kappa=-\frac12}=\tfrac12(X\Psi,P\Psi),\qquad "
                 r"\text{(N0\_XP2)}=\text{(NE\_XP)}\ \text{on}\ \Psi^{-1}(0)=\{X^TP=0\}")
def neumann_flows_coincide_on_psi_zero(s):
    """The Dirac flows of H_neum,0 and H_neum,−½ differ by ½(XΨ, PΨ), so the Neumann systems (N0_XP2) and (NE_XP) coincide on Ψ⁻¹(0) = {XᵀP = 0}, where the printed right-hand sides agree at every point (X, (I − XXᵀ)P)."""
    normal, euclidean = s.dirac_flow(H_neumann_normal), s.dirac_flow(H_neumann_euclidean)
    X, Psi = s.X, s.Psi
    P0 = horizontal(s, X, s.P)
    n0, ne = flow_N0_at(s, X, P0), flow_NE_at(s, X, P0)
    return {
        "dX/dt (kappa=0) - dX/dt (kappa=-1/2) - X Psi/2": normal.Xdot - euclidean.Xdot - X @ Psi / 2,
        "dP/dt (kappa=0) - dP/dt (kappa=-1/2) - P Psi/2": normal.Pdot - euclidean.Pdot - s.P @ Psi / 2,
        "X^T P0 (a point of Psi^{-1}(0))": X.T @ P0,
        "(N0_XP2) - (NE_XP) at Psi = 0: dX/dt": n0["X"] - ne["X"],
        "(N0_XP2) - (NE_XP) at Psi = 0: dP/dt": n0["P"] - ne["P"],
    }


# -- Theorem NEUMANN2: the kernel of Λ1 on Θ(Ψ⁻¹(0)) ------------------------------------------------

def gl_coordinates(xi, eta):
    """The coordinates of ξ + η (ξ skew, η symmetric) in the basis of gl(n) of ``lambda1``'s columns
    (sec6_dimension_lemmas.gl_basis: E_i∧E_j, i < j, then E_ij + E_ji, i < j, and E_ii): ξ_ij, then η_ij, i ≤ j."""
    n = xi.shape[0]
    return ([xi[i, j] for i in range(n) for j in range(i + 1, n)]
            + [eta[i, j] for i in range(n) for j in range(i, n)])


def sym_units(s, m, tags):
    """E_ij + E_ji (i < j) and E_ii, i ≤ j in lexicographic order: a basis of Sym(m)."""
    out = []
    for i in range(m):
        for j in range(i, m):
            E = s.mat([[s.q(1) if (a, b) == (i, j) else s.q(0) for b in range(m)] for a in range(m)], tags)
            out.append(E + E.T if i != j else E)
    return out


def skew_units(s, m, tags):
    """E_i∧E_j (i < j): a basis of so(m)."""
    out = []
    for i in range(m):
        for j in range(i + 1, m):
            E = s.mat([[s.q(1) if (a, b) == (i, j) else s.q(0) for b in range(m)] for a in range(m)], tags)
            out.append(E - E.T)
    return out


def lema1_kernel_at_psi_zero(s, X, h):
    """Kernel vectors of Λ1(h + v), v = XXᵀ, at a point with Xᵀh X = 0 (Ψ = 0, so h1 = 0), in the coordinates of
    ``lambda1``'s columns: the solutions ξ + η of (L1) [ξ, v] = 0, (L2) [ξ, h] + [η, v] = 0 of the proof of
    LEMA1, which span gl(r) ⊕ gl(n − r) (Theorem NEUMANN2): with π = XXᵀ, π' = I − π, ξ block diagonal
    (XωXᵀ, ω ∈ so(r), and π'ξ'π', ξ' ∈ so(n)) with the off-diagonal η = π'Cπ − πCπ', C = [h, ξ], and η block
    diagonal (XσXᵀ, σ ∈ Sym(r), and π'σ'π', σ' ∈ Sym(n)) with ξ = 0."""
    n, r = s.n, s.r
    pi = X @ X.T
    pi_perp = s.In - pi
    zero = s.zeros(n, n, ("n", "n"))
    xis = [X @ w @ X.T for w in skew_units(s, r, ("r", "r"))]
    xis += [pi_perp @ w @ pi_perp for w in skew_units(s, n, ("n", "n"))]
    etas = [X @ w @ X.T for w in sym_units(s, r, ("r", "r"))]
    etas += [pi_perp @ w @ pi_perp for w in sym_units(s, n, ("n", "n"))]
    vectors = []
    for xi in xis:
        C = comm(h, xi)
        vectors.append(gl_coordinates(xi, pi_perp @ C @ pi - pi @ C @ pi_perp))
    vectors += [gl_coordinates(zero, eta) for eta in etas]
    return s.mat([list(row) for row in zip(*vectors)])


@claim("neumann2-kernel", paper=("NEUMANN2", "LEMA1", "KER"), kind="dim",
       sizes=admissible(5), exact_max_n=7,
       equivariance=EQUIVARIANCE_X,
       statement=r"(X_0,P_0)\in\Psi^{-1}(0)\ \text{generic},\ h=\Phi(X_0,P_0),\ v=X_0X_0^T:\quad "
                 r"\dim\ker\Lambda_1(h+v)=\dim(gl(r)\oplus gl(n-r)),\quad "
                 r"r(n-r)=\tfrac12\big(\dim gl(n)-\dim gl(r)-\dim gl(n-r)\big)=\dim G_{n,r}")
def neumann2_kernel(s):
    """The proof of Theorem NEUMANN2: at a generic point (X0, P0) of Ψ⁻¹(0) (so h1 = 0), the kernel of Λ1 at h + v = Θ(X0, P0) has the dimension of gl(r) ⊕ gl(n − r), so the leaf through it has dimension 2r(n − r) = 2 dim G_{n,r} (P0 = (I − XXᵀ)P: a generic point of Ψ⁻¹(0) over X; with h = Φ(X0, P0), the so(n) part of Θ as in Lemma LEMA1, where the proof prints h = Ψ(X0, P0): claim neumann2-h-size)."""
    n, r = s.n, s.r
    X = s.X
    P0 = horizontal(s, X, s.P)
    h = P0 @ X.T - X @ P0.T
    x = h + X @ X.T
    ker = r * r + (n - r) * (n - r)
    return {
        "X^T P0 (a point of Psi^{-1}(0))": X.T @ P0,
        "rank Lambda1(h+v) at Psi = 0": Rank(lambda1(s, x), n * n - ker, generic=True,
                                             meaning="n² − dim gl(r) − dim gl(n − r)",
                                             kernel=lema1_kernel_at_psi_zero(s, X, h)),
        "r(n-r) = (dim gl(n) - dim gl(r) - dim gl(n-r))/2": Count(2 * r * (n - r), n * n - ker,
                                                                  "twice dim G_{n,r} against the printed count"),
    }


@claim("neumann2-h-size", nature="formula", encodes='Let h = Ψ(X_0, P_0), v = X_0 X_0^T', paper=("NEUMANN2",), kind="dim",
       sizes=admissible(5), exact_max_n=7,
       fails_at=lambda n, r: r < n,
       place="the proof of Theorem 7.1",
       erratum="""The proof of Theorem 7.1 sets h = Ψ(X_0, P_0) and v = X_0 X_0^T and works with h + v in gl(n)
       and with the block h_1 of h.  Ψ(X_0, P_0) is r × r and v is n × n, so h + v is not defined for r < n (and on
       Ψ^{-1}(0) the printed h would be 0).  Corrected: h = Φ(X_0, P_0), the so(n) part of Θ(X_0, P_0), as in the
       proof of Lemma 6.2; its block h_1 = X_0^T h X_0 is Ψ(X_0, P_0), which is 0 on Ψ^{-1}(0), as the proof says
       next.  With this h the kernel of Λ_1(h + v) has the dimension of gl(r) ⊕ gl(n − r) (claim
       neumann2-kernel).""",
       statement=r"h=\Psi(X_0,P_0),\ v=X_0X_0^T:\ \text{the size of }h\text{ is the size }n\text{ of }v")
def printed_h_has_the_size_of_v(s):
    """The h printed in the proof of Theorem NEUMANN2, Ψ(X0, P0), has the size n of v = X0X0ᵀ, to which it is added."""
    return {"size of h = Ψ(X₀, P₀) = size of v": Count(s.Psi.shape[0], s.n,
                                                         "the size of h = Ψ(X₀, P₀), which must be the size n of v = X₀X₀ᵀ "
                                                         "for h + v to be defined")}


@printed_h_has_the_size_of_v.claim.correction("h = Φ(X₀, P₀) in place of Ψ(X₀, P₀)")
def printed_h_has_the_size_of_v_corrected(s):
    X = s.X
    P0 = horizontal(s, X, s.P)
    h = P0 @ X.T - X @ P0.T
    return {"size of h = Φ(X₀, P₀) = size of v": Count(h.shape[0], s.n, "the size of the corrected h = Φ(X₀, P₀)"),
            "h₁ = X₀ᵀ h X₀ = Ψ(X₀, P₀) = 0": X.T @ h @ X}


# -- the reduced equation (neum-gras) on e_1 ∧ … ∧ e_r ---------------------------------------------

def first_derivative(s, E, V):
    """d/dt (e_1∧…∧e_r) = Σ_i e_1∧…∧ė_i∧…∧e_r, the columns of E with velocities V, as Plücker coordinates."""
    r = len(E)
    out = None
    for i in range(r):
        term = plucker(s, replaced(E, {i: V[i]}), s.n)
        out = term if out is None else [a + b for a, b in zip(out, term)]
    return out


def neum_gras_rhs(s, X, Xdot):
    """The right-hand side of (neum-gras): −Σ_i e_1∧…∧Ae_i∧…∧e_r + 2Σ_{i<j} e_1∧…∧ė_i∧…∧ė_j∧…∧e_r
    + λ e_1∧…∧e_r with λ = tr(XᵀAX − ẊᵀẊ), as Plücker coordinates."""
    r, n = s.r, s.n
    E, V, AE = columns(X, r), columns(Xdot, r), columns(s.A @ X, r)
    lam = s.tr(X.T @ s.A @ X - Xdot.T @ Xdot)
    out = [lam * g for g in plucker(s, E, n)]
    for i in range(r):
        out = [o - g for o, g in zip(out, plucker(s, replaced(E, {i: AE[i]}), n))]
    for i, j in combinations(range(r), 2):
        out = [o + 2 * g for o, g in zip(out, plucker(s, replaced(E, {i: V[i], j: V[j]}), n))]
    return out


@claim("neum-gras", paper=("neum-gras", "gras-velocities", "NE_XP"), kind="id",
       sizes=admissible(n_max=5, r_max=3),
       equivariance="the Plücker coordinates of a rotated plane are those of the plane under the induced "
                    "linear action of SO(n) on the r-th exterior power, so the residual is covariant",
       statement=r"\tfrac{d^2}{dt^2}(e_1\wedge\dots\wedge e_r)=-\sum_{i}e_1\wedge\dots\wedge Ae_i\wedge\dots\wedge e_r"
                 r"+2\sum_{i<j}e_1\wedge\dots\wedge\dot e_i\wedge\dots\wedge\dot e_j\wedge\dots\wedge e_r"
                 r"+\lambda\,e_1\wedge\dots\wedge e_r,\quad \lambda=\tr(X^TAX-\dot X^T\dot X),\quad "
                 r"(\dot e_i,e_j)=0\iff\Psi=0")
def reduced_equation_on_the_grassmannian(s):
    """Along the Dirac flow of H_neum,−½ (the Neumann system (NE_XP)) the Plücker coordinates of e_1∧…∧e_r satisfy the second-order equation (neum-gras) with λ = tr Λ = tr(XᵀAX − ẊᵀẊ), whose right-hand side is invariant under the right SO(r)-action, and the velocity conditions (gras-velocities) (ė_i, e_j) = 0 hold exactly on Ψ⁻¹(0) (XᵀẊ = Ψ/2)."""
    flow = s.dirac_flow(H_neumann_euclidean)
    r = s.r

    def velocity_of_the_plane(t):   # d/dt(e_1∧…∧e_r) with ė = Ẋ = P, as printed in (NE_XP)
        return column(t, first_derivative(t, columns(t.X, r), columns(t.P, r)))

    second = s.d(velocity_of_the_plane, flow)
    rhs = column(s, neum_gras_rhs(s, s.X, flow.Xdot))
    right = {"X": s.X @ s.eta, "P": s.P @ s.eta}
    invariance = s.d(lambda t: column(t, neum_gras_rhs(t, t.X, t.P)), right)
    return {
        "dX/dt - P": flow.Xdot - s.P,
        "(neum-gras)": second - rhs,
        "(gras-velocities): X^T dX/dt - Psi/2": s.X.T @ flow.Xdot - s.Psi / 2,
        "right so(r)-action: d(right-hand side)": invariance,
    }


# -- r = n − 1: (iden1), (iden2) and the Neumann system on the sphere (neum-gras**) -------------------

def cross(s, cols):
    """The vector e with (v_1, …, v_{n−1}, e) having determinant (v_1, …, v_{n−1}, u) = (u, e) for every u:
    e_k = (−1)^{n+k} (v_1 ∧ … ∧ v_{n−1})_{\\{1..n\\} − k} (1-based k)."""
    n = s.n
    out = []
    for k in range(n):
        I = [i for i in range(n) if i != k]
        g = wedge(s, cols, I)
        out.append(g if (n + k + 1) % 2 == 0 else -g)
    return out


def vector(s, entries):
    """A column vector of ℝⁿ from its entries."""
    return s.mat([[x] for x in entries], ("n", "?"))


def add(*vs):
    return [sum(xs[1:], xs[0]) for xs in zip(*vs)]


# exact_max_n = 3: at (4,3) the symbolic method proves it in about 1.5 s, but its 128 mutants there cost the
# mutation analysis about 70 s more (several stop at their 30 s), so (4,3) stays with the modular method
@claim("neum-gras-sphere", paper=("iden1", "iden2", "neum-gras**", "neum-gras", "gras-velocities"), kind="id",
       sizes=admissible(n_max=5, n_min=2, where=lambda n, r: r == n - 1, condition="r = n - 1"), exact_max_n=4,
       statement=r"r=n-1:\ \mathcal X=(e_1,\dots,e_{n-1},e_n)\in SO(n),\ e_1\wedge\dots\wedge e_{n-1}\mapsto e_n,\quad "
                 r"\ddot e_n=(A-\tr A\,\mathbf I)e_n+\lambda e_n=Ae_n-\big((e_n,Ae_n)+(\dot e_n,\dot e_n)\big)e_n"
                 r"\ \text{on}\ \Psi^{-1}(0)")
def neumann_system_on_the_sphere(s):
    """For r = n − 1 the completion e_n of (e_1, …, e_{n−1}) to a positive orthonormal base (iden1) has as components the Plücker coordinates of e_1∧…∧e_{n−1} up to the signs (−1)^{n+k} (iden2), and on Ψ⁻¹(0), along (NE_XP), the second term of (neum-gras) vanishes and e_n satisfies the Neumann equation (neum-gras**) on S^{n−1}."""
    n, r = s.n, s.r
    X, A = s.X, s.A
    P0 = horizontal(s, X, s.P)                    # a point (X, P0) of Ψ⁻¹(0)
    flow = s.dirac_flow(H_neumann_euclidean)      # derived: (NE_XP) holds on all of T*V
    printed = flow_NE_at(s, X, P0)
    E, V = columns(X, r), columns(printed["X"], r)
    Acc = columns(printed["P"], r)                # Ẍ = Ṗ along (NE_XP)
    en = cross(s, E)
    en_dot = add(*[cross(s, replaced(E, {i: V[i]})) for i in range(r)])
    second_term = [s.q(0)] * n
    for i, j in combinations(range(r), 2):
        second_term = add(second_term, cross(s, replaced(E, {i: V[i], j: V[j]})))
    en_ddot = add(*[cross(s, replaced(E, {i: Acc[i]})) for i in range(r)], [2 * x for x in second_term])
    e, edot, eddot = vector(s, en), vector(s, en_dot), vector(s, en_ddot)
    frame = s.mat([[X[i, j] for j in range(r)] + [en[i]] for i in range(n)], ("n", "?"))
    lam = s.tr(X.T @ A @ X - printed["X"].T @ printed["X"])
    return {
        "dX/dt - P": flow.Xdot - s.P,
        "dP/dt + AX + X P^T P - X X^T A X": flow.Pdot + A @ s.X + s.X @ s.P.T @ s.P - s.X @ s.X.T @ A @ s.X,
        "(iden1): frame^T frame - I_n": frame.T @ frame - s.identity(n),
        "(iden1): det frame - 1": det(s, [[frame[i, j] for j in range(n)] for i in range(n)]) - s.q(1),
        "(gras-velocities) at Psi = 0: X^T dX/dt": X.T @ printed["X"],
        "second term of (neum-gras) at Psi = 0": column(s, second_term),
        "(neum-gras**), first form": eddot - (A @ e - s.tr(A) * e) - lam * e,
        "(neum-gras**), second form": eddot - A @ e + (e.T @ A @ e + edot.T @ edot)[0, 0] * e,
    }


# -- the quartic Hamiltonian (quartic) --------------------------------------------------------------

def H_quartic(s):
    """(quartic): H = ½tr(PᵀP) + tr(XᵀA²X) − tr(XᵀAXXᵀAX)."""
    X, A = s.X, s.A
    XAX = X.T @ A @ X
    return s.tr(s.P.T @ s.P) / 2 + s.tr(X.T @ A @ A @ X) - s.tr(XAX @ XAX)


@claim("quartic", paper=("quartic",), kind="id",
       sizes=admissible(n_max=5, r_max=1, condition="r = 1"), exact_max_n=7,
       statement=r"r=1:\ \tfrac12\tr(P^TP)+\tr(X^TA^2X)-\tr(X^TAXX^TAX)=\tfrac12(p,p)+\sum_i a_i^2e_i^2"
                 r"-\Big(\sum_ia_ie_i^2\Big)^2")
def quartic_hamiltonian_for_r_1(s):
    """For r = 1 the quartic Hamiltonian (quartic) takes the form ½(p, p) + Σ a_i²e_i² − (Σ a_i e_i²)² of the Neumann system with a potential of degree 4."""
    e, p, A = s.X, s.P, s.A          # r = 1: the columns e, p of R^n, A = diag(a_1, …, a_n)
    pp = s.tr(p.T @ p)               # (p, p)
    quad = s.tr(e.T @ A @ A @ e)     # Σ a_i² e_i² = (e, A²e)
    mean = s.tr(e.T @ A @ e)         # Σ a_i e_i² = (e, Ae)
    return {"(quartic), r = 1": H_quartic(s) - (pp / 2 + quad - mean * mean)}


@claim("quartic-psi-zero-invariant", paper=("quartic", "grassmannian"), kind="pb",
       sizes=admissible(n_max=5),
       statement=r"\tfrac{d}{dt}\Psi=0\ \text{along the Dirac flow of}\ H=\tfrac12\tr(P^TP)+\tr(X^TA^2X)-\tr(X^TAXX^TAX)")
def quartic_flow_keeps_psi(s):
    """The quartic Hamiltonian (quartic) is right SO(r)-invariant, so its Dirac flow conserves Ψ and leaves the invariant manifold Ψ⁻¹(0) ⊂ T*V_{n,r}, on which it is reduced to T*G_{n,r}."""
    flow = s.dirac_flow(H_quartic)
    return {"dPsi/dt": s.d(lambda t: t.Psi, flow)}
