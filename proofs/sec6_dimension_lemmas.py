"""§6 The dimension lemmas: LEMA1, LEMA2 and the kernels, the isotropic tori (dim_fol, NEUMANN), each with a two-sided certificate; and the rank of the pencil at λ₁ + λ₂ = 0."""
from __future__ import annotations

from stiefelsym import Count, Rank, admissible, claim, comm

from .sec6_compatible_brackets import differentials

SECTION = "6"


# -- the printed dimensions ----------------------------------------------------------------------

def dim_so(m):
    return m * (m - 1) // 2 if m > 1 else 0


def dim_sym(m):
    return m * (m + 1) // 2


def dim_V(n, r):
    return r * n - r * (r + 1) // 2


def leaf_printed(n, r):
    """(dimension): 2l = 2r(n − r) + r(r − 1)/2 − [r/2]."""
    return 2 * r * (n - r) + r * (r - 1) // 2 - r // 2


def ker_lema1_printed(n, r):
    """Proof of LEMA1: dim ker Λ1(h + v) = rank so(r) + dim so(n − r) + dim Sym(r) + dim Sym(n − r)."""
    return r // 2 + dim_so(n - r) + dim_sym(r) + dim_sym(n - r)


def ker_printed(n, r):
    """(KER): dim so(r)_{h1} ⊕ Sym(r) ⊕ gl(n − r)."""
    return r // 2 + dim_sym(r) + (n - r) ** 2


def torus_twice_printed(n, r):
    """Twice (dim_fol): 2r(n − r) + r(r − 1)/2 − [r/2] + 2[r/2]."""
    return leaf_printed(n, r) + 2 * (r // 2)


# -- gl(n) = so(n) + Sym(n) and the pencil Λ1, Λ2 ----------------------------------------------------

def unit(s, m, k, a, b, tags):
    """The m x k matrix unit E_ab."""
    zero, one = s.q(0), s.q(1)
    return s.mat([[one if (i, j) == (a, b) else zero for j in range(k)] for i in range(m)], tags)


def gl_kinds(n):
    """The kinds of the elements of :func:`gl_basis`, in its order: ("so", i, j) for E_i∧E_j (i < j), then
    ("sym", i, j) for E_ij + E_ji (i < j) and E_ii (i = j)."""
    return ([("so", i, j) for i in range(n) for j in range(i + 1, n)]
            + [("sym", i, j) for i in range(n) for j in range(i, n)])


def gl_basis(s):
    """E_i∧E_j (i < j), then E_ij + E_ji (i < j) and E_ii: a basis of so(n) + Sym(n); and its kinds."""
    n, tags = s.n, ("n", "n")
    basis, kinds = [], gl_kinds(n)
    for kind, i, j in kinds:
        if kind == "so":
            basis.append(unit(s, n, n, i, j, tags) - unit(s, n, n, j, i, tags))
        else:
            E = unit(s, n, n, i, j, tags)
            basis.append(E + E.T if i != j else E)
    return basis, kinds


def pair(C, kind):
    """tr(C u) for the basis element u of the given kind, read off the entries of C."""
    what, i, j = kind
    if what == "so":
        return C[j, i] - C[i, j]
    return C[j, i] + C[i, j] if i != j else C[i, i]


def form_matrix(s, y, kinds_rows, basis_rows, kinds_cols, drop_sym_sym):
    """(tr(y [u_a, u_b])) = (tr([y, u_a] u_b)): −2 times <y, [u_a, u_b]>; with ``drop_sym_sym`` the
    Sym × Sym block is 0 (Λ1, the semidirect product so(n) ⊕_ad Sym(n))."""
    rows = []
    for u, ka in zip(basis_rows, kinds_rows):
        C = comm(y, u)
        rows.append([s.q(0) if drop_sym_sym and ka[0] == "sym" and kb[0] == "sym" else pair(C, kb)
                     for kb in kinds_cols])
    return rows


def lambda1(s, x):
    basis, kinds = gl_basis(s)
    return s.mat(form_matrix(s, x, kinds, basis, kinds, True))


def lambda2(s, x, A):
    basis, kinds = gl_basis(s)
    return s.mat(form_matrix(s, x - A, kinds, basis, kinds, False))


def theta(s):
    """Θ = Φ + XXᵀ = h + v."""
    return s.Phi + s.X @ s.X.T


def entries(s, M):
    n = s.n
    return [M[i, j] for i in range(n) for j in range(n)]


def linear_system(s, image):
    """The matrix of a linear map gl(n) -> (n x n matrices)^k, u ↦ image(ξ, η) (u = ξ + η), in the
    basis of gl(n) (columns) and the entries of the images (rows)."""
    basis, kinds = gl_basis(s)
    zero = s.zeros(s.n, s.n, ("n", "n"))
    columns = []
    for u, k in zip(basis, kinds):
        xi, eta = (u, zero) if k[0] == "so" else (zero, u)
        columns.append([e for M in image(xi, eta) for e in entries(s, M)])
    return s.mat([list(row) for row in zip(*columns)])



# -- kernel certificates: columns in the coordinates of gl_basis (the columns of Λ1, Λ2) ---------------

def gl_coords(s, xi, eta):
    """The coordinates of ξ + η (ξ ∈ so(n), η ∈ Sym(n)) in the basis of :func:`gl_basis`."""
    return [(xi if k[0] == "so" else eta)[k[1], k[2]] for k in gl_kinds(s.n)]


def gl_split(s, z):
    """The so(n) and Sym(n) parts of z ∈ gl(n)."""
    half = s.q(1, 2)
    return (z - z.T) * half, (z + z.T) * half


def as_columns(s, cols):
    """The matrix whose columns are the given lists of scalars."""
    return s.mat([list(row) for row in zip(*cols)])


def generic_gl(s):
    """A generic point y = S + K of gl(n): S a generic symmetric, K a generic skew n×n matrix (every element of
    gl(n) is uniquely so), in whose parameters y + yᵀ = 2S has one term per entry."""
    return s.generic("S", "n", "n", "sym") + s.generic("K", "n", "n", "skew")


def kernel_generic_lambda1(s, y):
    """ker Λ1 at a generic y = h + v ∈ gl(n): the gradients of the Casimirs tr(v^k), (ξ, η) = (0, v^(k−1)),
    k = 1..n (here with 2v = y + yᵀ)."""
    n = s.n
    zero = s.zeros(n, n, ("n", "n"))
    v2 = y + y.T
    cols, power = [], s.In
    for _ in range(n):
        cols.append(gl_coords(s, zero, power))
        power = power @ v2
    return as_columns(s, cols)


def lema1_kernel_columns(s):
    """ker Λ1(h + v) at h + v = Θ(X, P), the solutions of (L1), (L2) of the proof of LEMA1 in the frame
    im X ⊕ (im X)^⊥ (v = XXᵀ = diag(I, 0), h = [[Ψ, −bᵀ], [b, 0]], b = QP, Q = I − XXᵀ):
    ξ = XΨ^(2k+1)Xᵀ ∈ so(r)_{h1} with η = QPΨ^(2k+1)Xᵀ − XΨ^(2k+1)PᵀQ (η21 = bξ1),
    η = XSXᵀ (S ∈ Sym(r)), ξ = q_i q_jᵀ − q_j q_iᵀ ∈ so(n − r) with η = XPᵀξ − ξPXᵀ (η21 = −ξ2 b),
    η = q_i q_jᵀ + q_j q_iᵀ ∈ Sym(n − r) (q_i = Q e_i, i > r)."""
    n, r = s.n, s.r
    X, P, Psi = s.X, s.P, s.Psi
    Q = s.In - X @ X.T
    zero = s.zeros(n, n, ("n", "n"))
    cols = []
    power = Psi
    for _ in range(r // 2):
        cols.append(gl_coords(s, X @ power @ X.T, Q @ P @ power @ X.T - X @ power @ P.T @ Q))
        power = power @ Psi @ Psi
    for a in range(r):
        for b in range(a, r):
            E = unit(s, r, r, a, b, ("r", "r"))
            cols.append(gl_coords(s, zero, X @ (E + E.T if a != b else E) @ X.T))
    q = [Q[0:n, i:i + 1] for i in range(r, n)]
    for i in range(n - r):
        for j in range(i + 1, n - r):
            xi = q[i] @ q[j].T - q[j] @ q[i].T
            cols.append(gl_coords(s, xi, X @ P.T @ xi - xi @ P @ X.T))
    for i in range(n - r):
        for j in range(i, n - r):
            cols.append(gl_coords(s, zero, q[i] @ q[j].T + q[j] @ q[i].T))
    return cols


def power_of(M, k, identity):
    out = identity
    for _ in range(k):
        out = out @ M
    return out


def kernel_lambda_1m1(s, h, A):
    """ker Λ_{1,−1}(h + v), the solutions of (L3), (L4): η = A^j, ξ = −Σ_{i<j} A^i h A^(j−1−i)
    (so [ξ, A] = [A^j, h]), j = 0..n−1: the gradients of the Casimirs of Λ_{1,−1}."""
    n = s.n
    cols = []
    for j in range(n):
        xi = s.zeros(n, n, ("n", "n"))
        for i in range(j):
            xi = xi - power_of(A, i, s.In) @ h @ power_of(A, j - 1 - i, s.In)
        cols.append(gl_coords(s, xi, power_of(A, j, s.In)))
    return as_columns(s, cols)


def kernel_lambda2(s, x, A):
    """ker Λ2(x): the centralizer of x − A, (x − A)^k, k = 0..n−1 (the gradients of tr(x − A)^(k+1))."""
    n = s.n
    cols, power = [], s.In
    for _ in range(n):
        cols.append(gl_coords(s, *gl_split(s, power)))
        power = power @ (x - A)
    return as_columns(s, cols)


def kernel_pencil(s, h, v, A, t):
    """ker (Λ1 + tΛ2)(h + v): the gradients of the Casimirs tr(λh + v − λ²A)^k of the pencil (central) at
    λ² = t/(1 + t): with M = λh + v − λ²A, M^k = E_k + λO_k (E_k ∈ Sym(n), O_k ∈ so(n)), the vector
    (ξ, η) = (λ²O_k, E_k), here times (1 + t)^(k+1) (a = 1 + t, b = t: Ẽ_{k+1} = (av − bA)Ẽ_k + bhÕ_k,
    Õ_{k+1} = ahẼ_k + (av − bA)Õ_k, (ξ, η) = (bÕ_k, aẼ_k)), k = 0..n−1."""
    n = s.n
    a, b = t + s.q(1), t
    N = v * a - A * b
    E, O = s.In, s.zeros(n, n, ("n", "n"))
    cols = []
    for _ in range(n):
        cols.append(gl_coords(s, O * b, E * a))
        E, O = N @ E + h @ O * b, h @ E * a + N @ O
    return as_columns(s, cols)


EQUIVARIANCE_X = ("Λ1 is Ad_O(n)-invariant and Θ(gX, gP) = gΘ(X, P)gᵀ, so the rank at Θ(X, P) is O(n)-invariant; "
                  "the basis of gl(n) only lists the bilinear form in coordinates")
EQUIVARIANCE_XA = ("Λ1 and Λ2 at (Θ, A) are covariant under (X, P, A) ↦ (gX, gP, gAgᵀ), so the ranks are "
                   "O(n)-invariant; the basis of gl(n) only lists the bilinear forms in coordinates")


# -- Lemma LEMA1 -----------------------------------------------------------------------------------

@claim("pencil-leaf-dimension", paper=("dimension", "LEMA1", "L1", "L2"), kind="dim", exact_max_n=7,
       sizes=admissible(5), equivariance=EQUIVARIANCE_X,
       statement=r"\rank\Lambda_1(h+v)=n^2-\dim\ker\Lambda_1(h+v)=2r(n-r)+\tfrac{r(r-1)}2-\left[\tfrac r2\right],"
                 r"\quad \xi+\eta\in\ker\Lambda_1(h+v)\iff[\xi,v]=0,\ [\xi,h]+[\eta,v]=0")
def pencil_leaf_dimension(s):
    """Lemma LEMA1: at a generic h + v = Θ(X, P) the bracket Λ1 has rank (dimension), its kernel is the solution space of (L1), (L2), of dimension rank so(r) + dim so(n−r) + dim Sym(r) + dim Sym(n−r)."""
    n, r = s.n, s.r
    h, v = s.Phi, s.X @ s.X.T
    L1L2 = linear_system(s, lambda xi, eta: [comm(xi, v), comm(xi, h) + comm(eta, v)])
    K = as_columns(s, lema1_kernel_columns(s))     # the solutions of (L1), (L2) in the proof of LEMA1
    return {
        "rank Lambda1(h+v)": Rank(lambda1(s, h + v), leaf_printed(n, r), generic=True,
                                  meaning="the dimension of a generic symplectic leaf in Θ(T*V)", kernel=K),
        "rank of (L1), (L2)": Rank(L1L2, n * n - ker_lema1_printed(n, r), generic=True,
                                   meaning="n² − dim of the solutions of (L1), (L2)", kernel=K),
        "n^2 - dim ker = (dimension)": Count(n * n - ker_lema1_printed(n, r), leaf_printed(n, r),
                                             "the last line of the proof of LEMA1"),
    }


def generic_leaf_rank(n):
    """The rank n² − n of Λ1 at a generic point of gl(n) (its Casimirs: tr(h + v)^k... n of them)."""
    return n * n - n


@claim("pencil-leaves-singular", nature="range", paper=("dimension",), kind="dim",
       sizes=admissible(5), exact_max_n=7, equivariance=EQUIVARIANCE_X,
       fails_at=lambda n, r: r == 1 and n <= 2,
       place="the inequality (5) §6 in the proof of Theorem 6.1",
       erratum="""(5) §6 says 2l < n² − n: the leaves in Θ(T*V) are singular leaves of (gl(n), Λ₁).  For
       (n, r) = (1, 1) and (2, 1), that is on V_{1,1} and on V_{2,1} = S¹, the two sides are equal (0 = 0 and
       2 = 2): there Θ(T*V) meets the regular leaves.  The strict inequality holds at every other size (checked at
       every size of the tables).  The witness codes the inequality as a number: 1 where it holds, 0 where it
       fails; at (1, 1) and (2, 1) it computes 0, where the printed statement gives 1.""",
       statement=r"2l=2r(n-r)+\tfrac{r(r-1)}2-\left[\tfrac r2\right]<n^2-n=\rank\Lambda_1\ \text{at a generic point of } gl(n)")
def pencil_leaves_singular(s):
    """(dimension): the generic leaf in Θ(T*V) is singular in (gl(n), Λ1): 2l < n² − n, the rank of Λ1 at a generic point of gl(n)."""
    n, r = s.n, s.r
    y = generic_gl(s)
    return {
        "rank Λ₁ at a generic point of gl(n)": Rank(lambda1(s, y), generic_leaf_rank(n), generic=True,
                                                         meaning="n² − n", kernel=kernel_generic_lambda1(s, y)),
        "2l < n² − n": Count(int(leaf_printed(n, r) < generic_leaf_rank(n)), 1,
                                       "the leaves in Θ(T*V) are singular leaves of (gl(n), Λ₁)"),
    }


@pencil_leaves_singular.claim.correction("2l <= n² − n (equality at (1,1) and (2,1))")
def pencil_leaves_singular_corrected(s):
    n, r = s.n, s.r
    y = generic_gl(s)
    return {
        "rank Λ₁ at a generic point of gl(n)": Rank(lambda1(s, y), generic_leaf_rank(n), generic=True,
                                                         kernel=kernel_generic_lambda1(s, y)),
        "2l ≤ n² − n": Count(int(leaf_printed(n, r) <= generic_leaf_rank(n)), 1,
                                        "the leaves in Θ(T*V) are leaves of (gl(n), Λ₁) of rank at most n² − n"),
    }


# -- the pencil at λ1 + λ2 = 0 ---------------------------------------------------------------------------

def so_rows(s, y, drop_sym_sym):
    """The so(n) rows of :func:`form_matrix` at y (the bilinear form with a first argument in so(n))."""
    basis, kinds = gl_basis(s)
    k = s.n * (s.n - 1) // 2
    return s.mat(form_matrix(s, y, kinds[:k], basis[:k], kinds, drop_sym_sym))


def pencil_so_rows(s, l1, l2, x):
    """The so(n) rows of Λ_{λ₁,λ₂}(x) = λ1Λ1(x) + λ2Λ2(x) (up to the factor −2 of :func:`form_matrix`)."""
    return so_rows(s, x, True) * l1 + so_rows(s, x - s.A, False) * l2


@claim("pencil-gl-isomorphism", nature="statement", paper=("central", "LAMBDA12"), kind="dim", exact_max_n=7,
       sizes=admissible(5, n_min=2, condition="n >= 2 (so(1) = 0)"), fails_at=lambda n, r: True,
       place="the sentence before (4) §6",
       erratum="""§6 says: “For λ₂ ≠ 0, the bracket Λ_{λ₁,λ₂} is isomorphic to the canonical Lie–Poisson
       bracket on gl(n)”.  That bracket vanishes at 0, so Λ_{λ₁,λ₂} would vanish at some point x₀.  At
       λ₁ + λ₂ = 0 it vanishes nowhere: the rows of Λ_{−1,1}(x) whose first argument lies in so(n) do not depend on x
       (Λ_{λ₁,λ₂}(ξ, ·)|_x = (λ₁ + λ₂)⟨x, [ξ, ·]⟩ − λ₂⟨A, [ξ, ·]⟩ for ξ ∈ so(n)), and they have rank n(n − 1)/2
       for distinct a_i, since ξ ↦ [A, ξ] is injective on so(n).  So Λ_{−λ₂,λ₂} has rank n² − n at every point
       of gl(n), x = 0 included, and is not isomorphic to a Lie–Poisson bracket.  The number the witness
       computes is the rank of those rows at x = 0, where the printed statement gives 0.  The Casimirs printed
       next take the square root of λ₂/(λ₁ + λ₂), and the proof of Lemma 6.3, where all objects are complexified,
       states the isomorphism with gl(n, ℂ) “if λ₁ + λ₂ ≠ 0, λ₂ ≠ 0”.  Over ℝ the condition is λ₂/(λ₁ + λ₂) > 0:
       with λ₁ = σ(1 − μ²), λ₂ = σμ², σ ≠ 0 and μ ≠ 0 real, the map ψ(h + v) = μh + v − μ²A (that of the claim
       pencil-casimirs) takes Λ_{λ₁,λ₂} to σμ times the Lie–Poisson bracket of gl(n), and Λ_{λ₁,λ₂} vanishes at
       x₀ = ψ⁻¹(0) = μ²A; the correction checks this identity of brackets and the zero at x₀.  For
       λ₂/(λ₁ + λ₂) < 0 the same map needs an imaginary μ, and the real bracket is that of the other real form
       so(n) ⊕ i·Sym(n) = u(n) of gl(n, ℂ), not gl(n, ℝ).""",
       statement=r"\lambda_2\ne0\ \Rightarrow\ \Lambda_{\lambda_1,\lambda_2}\cong\text{the Lie--Poisson bracket of }"
                 r"gl(n),\ \text{which vanishes at }0")
def pencil_gl_isomorphism(s):
    """The pencil bracket Λ_{λ₁,λ₂} with λ₂ ≠ 0 is isomorphic to the Lie–Poisson bracket of gl(n), so it vanishes at some point: at λ₁ = −λ₂ = −1 its so(n) rows do not depend on x, so they would vanish at x = 0."""
    one = s.q(1)
    x, zero = generic_gl(s), s.zeros(s.n, s.n, ("n", "n"))
    at_0 = pencil_so_rows(s, -one, one, zero)
    return {
        "so(n) rows of Lambda_{-1,1}(x) - Lambda_{-1,1}(0)": pencil_so_rows(s, -one, one, x) - at_0,
        "rank of the so(n) rows of Lambda_{-1,1}(0)": Rank(at_0, 0, meaning="0: Λ_{−1,1} vanishes at some point"),
    }


@pencil_gl_isomorphism.claim.correction("λ₂/(λ₁ + λ₂) > 0 in place of λ₂ ≠ 0 (over ℂ: λ₁ + λ₂ ≠ 0 and λ₂ ≠ 0)")
def pencil_gl_isomorphism_corrected(s):
    # λ1 = σ(1 − μ²), λ2 = σμ² with σ = λ1 + λ2 ≠ 0 (σ scales the bracket and is left out); μ is real exactly when
    # λ2/(λ1 + λ2) > 0.  With L = μ on so(n) and 1 on Sym(n), Λ_{1−μ²,μ²}(x)(Lα, Lβ) = μ⟨ψ(x), [α, β]⟩ for
    # ψ(h + v) = μh + v − μ²A: for μ ≠ 0, ψ maps Λ to μ times the Lie–Poisson bracket of gl(n), and Λ vanishes at
    # x0 = ψ⁻¹(0) = μ²A
    mu, one, zero = s.scalar("mu"), s.q(1), s.q(0)
    h, v = s.generic("K", "n", "n", "skew"), s.generic("S", "n", "n", "sym")
    basis, kinds = gl_basis(s)
    c = mu * mu
    L = s.mat([[(mu if a[0] == "so" else one) if i == j else zero for j in range(len(kinds))]
               for i, a in enumerate(kinds)])
    psi = h * mu + v - s.A * c
    x0 = s.A * c
    return {
        "L Lambda_{1-mu^2,mu^2}(h + v) L - mu <psi(h + v), [., .]>":
            L @ (lambda1(s, h + v) * (one - c) + lambda2(s, h + v, s.A) * c) @ L
            - s.mat(form_matrix(s, psi, kinds, basis, kinds, False)) * mu,
        "Lambda_{1-mu^2,mu^2} at x0 = mu^2 A": lambda1(s, x0) * (one - c) + lambda2(s, x0, s.A) * c,
    }


# -- Lemma LEMA2: (A1) ---------------------------------------------------------------------------------

@claim("pencil-rank-a1", paper=("LEMA2", "LAMBDA", "L3", "L4"), kind="dim",
       sizes=admissible(5), exact_max_n=5, exact_max_r={6: 6, 7: 2}, equivariance=EQUIVARIANCE_XA,
       statement=r"\rank\Lambda_{1,-1}(h+v)=\rank\Lambda_{1,t}(h+v)=\rank\Lambda_2(h+v)=n^2-n,\quad "
                 r"\xi+\eta\in\ker\Lambda_{1,-1}\iff[\eta,A]=0,\ [\xi,A]-[\eta,h]=0")
def pencil_rank_A1(s):
    """(A1) of Lemma LEMA2: at a generic h + v = Θ(X, P) the brackets Λ_{1,−1} (LAMBDA), Λ2 and Λ1 + tΛ2 (t generic) have the maximal rank n² − n, and the kernel of Λ_{1,−1} is the n-dimensional solution space of (L3), (L4)."""
    n = s.n
    h, v = s.Phi, s.X @ s.X.T
    x, A = h + v, s.A
    L1, L2 = lambda1(s, x), lambda2(s, x, A)
    t = s.scalar("t")
    L3L4 = linear_system(s, lambda xi, eta: [comm(eta, A), comm(xi, A) - comm(eta, h)])
    K1m1 = kernel_lambda_1m1(s, h, A)
    return {
        "rank Lambda_{1,-1}": Rank(L1 - L2, n * n - n, generic=True, meaning="(A1) at λ1 + λ2 = 0", kernel=K1m1),
        "rank Lambda_2": Rank(L2, n * n - n, generic=True, meaning="(A1) at λ1 = 0", kernel=kernel_lambda2(s, x, A)),
        "rank Lambda_1 + t Lambda_2": Rank(L1 + L2 * t, n * n - n, generic=True, meaning="(A1) at a generic t",
                                           kernel=kernel_pencil(s, h, v, A, t)),
        "rank of (L3), (L4)": Rank(L3L4, n * n - n, generic=True, meaning="n² − n: the solutions are n-dimensional",
                                   kernel=K1m1),
    }


# -- Lemma LEMA2: (KER), (A2), (L5)–(L8) at the paper's point ---------------------------------------------

def paper_point(s):
    """X0 = (E_1..E_r), h = diag(h1, 0) with h1 generic in so(r), v = X0X0ᵀ, A = diag(a_1..a_n) generic:
    built from the claim's own parameters (the point of the proof of (A2))."""
    n, r = s.n, s.r
    X0 = s.mat([[s.q(1) if i == j else s.q(0) for j in range(r)] for i in range(n)], ("n", "r"))
    h1 = s.eta + s.eta          # 2η, η a generic element of so(r)
    A = s.mat([[s.scalar(f"a{i}") if i == j else s.q(0) for j in range(n)] for i in range(n)], ("n", "n"))
    return X0, X0 @ h1 @ X0.T, X0 @ X0.T, h1, A


def printed_kernel(s, X0, h1):
    """A spanning set of so(r)_{h1} ⊕ Sym(r) ⊕ gl(n − r): odd powers of h1, Sym(r), Q E_ab Q
    (Q = I − X0X0ᵀ)."""
    n, r = s.n, s.r
    out = []
    power = h1
    for _ in range(r // 2):
        out.append(X0 @ power @ X0.T)
        power = power @ h1 @ h1
    for a in range(r):
        for b in range(a, r):
            E = unit(s, r, r, a, b, ("r", "r"))
            out.append(X0 @ (E + E.T if a != b else E) @ X0.T)
    Q = s.In - X0 @ X0.T
    out += [Q @ unit(s, n, n, a, b, ("n", "n")) @ Q for a in range(r, n) for b in range(r, n)]
    return out


def a2_restricted_kernel(s, h1):
    """The kernel of Λ_{1,−1} restricted to (KER), as coefficients on :func:`printed_kernel`: (L7) ξ2 = 0 and
    (L8) η2 = E_aa (a > r, A2 diagonal), and the r solutions of (L5), (L6) (corrected) in so(r)_{h1} ⊕ Sym(r):
    (ξ1, η1) = (0, h1^k) for k even and (h1^k, −Σ_{i<k} h1^i A1 h1^(k−1−i)) for k odd, k = 0..r−1 (the limits
    at λ → 0 of the Casimir gradients of the pencil, λ skew(Z^k) + sym(Z^k) over λ^k, Z = h1 − λA1)."""
    n, r = s.n, s.r
    A1 = s.mat([[s.scalar(f"a{i}") if i == j else s.q(0) for j in range(r)] for i in range(r)], ("r", "r"))
    zero, one = s.q(0), s.q(1)
    cartan, lower = r // 2, [(a, b) for a in range(r, n) for b in range(r, n)]
    powers = [s.identity(r, "r")]
    for _ in range(r):
        powers.append(powers[-1] @ h1)
    cols = []
    for k in range(r):
        c = [zero] * cartan
        if k % 2 == 0:
            eta1 = powers[k]
        else:
            c[(k - 1) // 2] = one
            eta1 = s.zeros(r, r, ("r", "r"))
            for i in range(k):
                eta1 = eta1 - powers[i] @ A1 @ powers[k - 1 - i]
        cols.append(c + [eta1[a, b] for a in range(r) for b in range(a, r)] + [zero] * len(lower))
    for d in range(r, n):
        cols.append([zero] * (cartan + r * (r + 1) // 2) + [one if (a, b) == (d, d) else zero for a, b in lower])
    return as_columns(s, cols)


def lambda_forms(s, x, A):
    """Λ1(z, w) and Λ_{1,−1}(z, w) as functions of two elements of gl(n) (up to the factor −2):
    <y, [z, w]> = −½tr(y[z, w]) with the Sym × Sym part dropped for Λ1."""
    half = s.q(1, 2)

    def sym(M):
        return (M + M.T) * half

    def L1(z, w):
        return s.tr(x @ comm(z, w)) - s.tr(x @ comm(sym(z), sym(w)))

    def L1m1(z, w):
        return L1(z, w) - s.tr((x - A) @ comm(z, w))
    return L1, L1m1


@claim("pencil-kernel-ker-a2", paper=("KER", "A2", "L7", "L8"), kind="dim",
       sizes=admissible(5), exact_max_n=5, exact_max_r={6: 6, 7: 6},
       equivariance="the point is built from the claim's own parameters (no chart coordinate)",
       statement=r"\ker\Lambda_1(h+v)=so(r)_{h_1}\oplus Sym(r)\oplus gl(n-r),\quad "
                 r"\dim\{z\in\ker\Lambda_1\mid\Lambda_{1,-1}(z,\ker\Lambda_1)=0\}=n\quad (h=\mathrm{diag}(h_1,0))")
def pencil_kernel_and_A2(s):
    """At h = diag(h1, 0) with h1 generic and A diagonal, ker Λ1(h + v) is so(r)_{h1} ⊕ Sym(r) ⊕ gl(n−r) (KER) — the printed space lies in the kernel and has its dimension — and the kernel of Λ_{1,−1} restricted to it has dimension n (A2), on which (L7) ξ2 = 0 and (L8) [A2, η2] = 0 hold."""
    n, r = s.n, s.r
    X0, h, v, h1, A = paper_point(s)
    x = h + v
    L1, L1m1 = lambda_forms(s, x, A)
    K = printed_kernel(s, X0, h1)
    test = s.xi + (s.generic("T", "n", "n") + s.generic("T", "n", "n").T)   # a generic element of gl(n)
    restricted_rows = [[L1m1(a, b) for b in K] for a in K]
    restricted = s.mat(restricted_rows)
    # (L7), (L8): on the kernel of the restricted form, the lower blocks have ξ2 = 0 and [A2, η2] = 0
    Q = s.In - X0 @ X0.T
    half = s.q(1, 2)
    l7_l8 = []
    for k in K:
        low = Q @ k @ Q
        xi2, eta2 = (low - low.T) * half, (low + low.T) * half
        l7_l8.append(entries(s, xi2) + entries(s, comm(A, eta2)))
    with_l7_l8 = s.mat(restricted_rows + [list(row) for row in zip(*l7_l8)])
    KA2 = a2_restricted_kernel(s, h1)
    return {
        "rank Lambda1": Rank(lambda1(s, x), n * n - ker_printed(n, r), generic=True,
                             meaning="n² − dim (KER)",
                             kernel=as_columns(s, [gl_coords(s, *gl_split(s, k)) for k in K])),  # (KER) itself
        "(KER) lies in ker Lambda1": [L1(k, test) for k in K],
        "rank of the (KER) spanning set": Rank(s.mat([entries(s, k) for k in K]), ker_printed(n, r), generic=True,
                                               meaning="dim so(r)_{h1} ⊕ Sym(r) ⊕ gl(n−r)"),
        "(A2)": Rank(restricted, ker_printed(n, r) - n, generic=True,
                     meaning="dim (KER) − n: the restriction of Λ_{1,−1} to ker Λ1 has an n-dimensional kernel",
                     kernel=KA2),
        "(L7), (L8) on that kernel": Rank(with_l7_l8, ker_printed(n, r) - n, generic=True,
                                          meaning="adding ξ2 = 0 and [A2, η2] = 0 leaves the kernel unchanged",
                                          kernel=KA2),
    }


def a2_system(s, x, A):
    """The block matrix [[Λ1, 0], [Λ_{1,−1}, −Λ1]] of the forms at x (Λ_{1,−1} = Λ1 − Λ2): its
    solutions (z, y) are the z ∈ ker Λ1 with Λ_{1,−1}z ∈ im Λ1 = (ker Λ1)^⊥ (Λ1 is skew), i.e. the
    kernel of Λ_{1,−1} restricted to ker Λ1, each with y up to ker Λ1.  So its rank is
    2n² − dim ker Λ1 − dim{z ∈ ker Λ1 | Λ_{1,−1}(z, ker Λ1) = 0}."""
    basis, kinds = gl_basis(s)
    rows1 = form_matrix(s, x, kinds, basis, kinds, True)
    rows2 = form_matrix(s, x - A, kinds, basis, kinds, False)
    zero = s.q(0)
    top = [row + [zero] * len(row) for row in rows1]
    bottom = [[a - b for a, b in zip(r1, r2)] + [-a for a in r1] for r1, r2 in zip(rows1, rows2)]
    return s.mat(top + bottom)


def truncated_product(P1, P2, D, zero):
    """The product of two matrix polynomials in λ (lists of coefficients), up to λ^D."""
    out = []
    for d in range(D + 1):
        terms = [P1[i] @ P2[d - i] for i in range(max(0, d - len(P2) + 1), min(d, len(P1) - 1) + 1)]
        out.append(sum(terms[1:], terms[0]) if terms else zero)
    return out


def truncated_power(P, k, D, identity, zero):
    out = [identity]
    for _ in range(k):
        out = truncated_product(out, P, D, zero)
    return out


def a2_system_kernel(s, x, A):
    """The kernel of :func:`a2_system`: (0, y), y ∈ ker Λ1 (:func:`lema1_kernel_columns`), and n vectors
    (z, y) = (w(0), w'(0)) of analytic families w(σ) ∈ ker(Λ1 + tΛ2), σ = t/(1 + t) = λ² (then Λ1 w(0) = 0 and
    Λ1 w'(0) + Λ2 w(0) = 0, so Λ_{1,−1}z = Λ1 y): w = (λ skew F + sym F)/λ^(2c) for the polynomials
    F = (M − I)^k M^r, c = ⌈k/2⌉, k = 0..r−1, and F = M^j (M − I)^(2j+2), c = j, j = 0..n−r−1, of
    M = λh + v − λ²A, whose Casimir gradients span the pencil's kernel (Bolsinov's limit argument of (A2):
    the near-1 eigenvalues of M give the so(r)_{h1} ⊕ Sym(r) part, the near-0 ones the Sym(n − r) part)."""
    n, r = s.n, s.r
    h, v = gl_split(s, x)
    zero = s.zeros(n, n, ("n", "n"))
    M, M_I = [v, h, -A], [v - s.In, h, -A]
    families = []
    for k in range(r):
        c = (k + 1) // 2
        D = 2 * c + 2
        families.append((truncated_product(truncated_power(M_I, k, D, s.In, zero),
                                           truncated_power(M, r, D, s.In, zero), D, zero), c))
    for j in range(n - r):
        D = 2 * j + 2
        families.append((truncated_product(truncated_power(M, j, D, s.In, zero),
                                           truncated_power(M_I, 2 * j + 2, D, s.In, zero), D, zero), j))
    cols = []
    for F, c in families:
        # the coefficient of σ^m in λ skew F + sym F: (F_{2m−1}, F_{2m})
        z = gl_coords(s, F[2 * c - 1] if c > 0 else zero, F[2 * c])
        cols.append(z + gl_coords(s, F[2 * c + 1], F[2 * c + 2]))
    zeros = [s.q(0)] * (n * n)
    cols += [zeros + col for col in lema1_kernel_columns(s)]
    return as_columns(s, cols)


@claim("pencil-a2-generic", paper=("LEMA2", "A2", "LAMBDA"), kind="dim",
       sizes=admissible(5), exact_max_n=5, exact_max_r={6: 6, 7: 1}, equivariance=EQUIVARIANCE_XA,
       statement=r"\dim\{z\in\ker\Lambda_1(x)\mid\Lambda_{1,-1}(z,\ker\Lambda_1(x))=0\}=n,\quad "
                 r"x=h+v=\Theta(X,P)\ \text{generic}")
def pencil_a2_at_a_generic_point(s):
    """(A2) of Lemma LEMA2 at a generic point x = h + v = Θ(X, P) of Θ(T*V) (not only at the point h = diag(h1, 0) of the proof): the kernel of Λ_{1,−1} restricted to ker Λ1(x) has dimension n (computed as 2n² − dim ker Λ1 − the rank of the system z ∈ ker Λ1, Λ_{1,−1}z ∈ im Λ1)."""
    n, r = s.n, s.r
    x = theta(s)
    return {
        "rank Lambda1(h+v)": Rank(lambda1(s, x), leaf_printed(n, r), generic=True,
                                  meaning="(dimension): n² − dim ker Λ1",
                                  kernel=as_columns(s, lema1_kernel_columns(s))),
        "(A2)": Rank(a2_system(s, x, s.A), n * n - n + leaf_printed(n, r), generic=True,
                     meaning="2n² − dim ker Λ1 − n: the restriction of Λ_{1,−1} to ker Λ1 has an n-dimensional kernel",
                     kernel=a2_system_kernel(s, x, s.A)),
    }


def l5_l6_matrix(s, printed):
    """The system (L5), (L6) on ξ1 ∈ so(r)_{h1} (odd powers of h1), η1 ∈ Sym(r), at A1 = diag(a_1..a_r):
    (L6) as printed, [A1, η1] ∈ so(r)^⊥, or corrected, [A1, η1] ⟂ so(r)_{h1}."""
    r = s.r
    _, _, _, h1, A = paper_point(s)
    A1 = s.mat([[s.scalar(f"a{i}") if i == j else s.q(0) for j in range(r)] for i in range(r)], ("r", "r"))
    cartan, power = [], h1
    for _ in range(r // 2):
        cartan.append(power)
        power = power @ h1 @ h1
    zero = s.zeros(r, r, ("r", "r"))
    unknowns = [(c, zero) for c in cartan]
    for a in range(r):
        for b in range(a, r):
            E = unit(s, r, r, a, b, ("r", "r"))
            unknowns.append((zero, E + E.T if a != b else E))
    columns = []
    for xi1, eta1 in unknowns:
        L5 = comm(A1, xi1) - comm(h1, eta1)
        C6 = comm(A1, eta1)
        col = [L5[i, j] for i in range(r) for j in range(r)]
        if printed:   # so(r)^⊥ in gl(r) is Sym(r): the skew matrix [A1, η1] must vanish
            col += [C6[i, j] for i in range(r) for j in range(r)]
        else:
            col += [s.tr(C6 @ c) for c in cartan]
        columns.append(col)
    return s.mat([list(row) for row in zip(*columns)]), len(unknowns)


@claim("pencil-l5-l6", nature="formula", paper=("L5", "L6"), kind="dim",
       sizes=admissible(5, r_max=3), exact_max_n=7, equivariance="the system is built from the claim's own parameters (no chart coordinate)",
       fails_at=lambda n, r: r >= 3,
       place="the proof of Lemma 6.3, at (17) §6",
       erratum="""The proof of Lemma 6.3 says that the solutions (ξ₁, η₁) of (16), (17) §6 within
       so(r)_{h₁} ⊕ Sym(r) form an r-dimensional space.  With (17) §6 as printed, [A₁, η₁] ∈ so(r, ℂ)^⊥ = Sym(r),
       the skew matrix [A₁, η₁] must vanish, and at r = 3 the solutions form a 2-dimensional space (1 for r = 1,
       2 for r = 2), where the proof gives r = 3.  The number the witness computes is the rank of the system, the
       number of unknowns minus that dimension: at r = 3 there are 7 unknowns (1 in the Cartan subalgebra
       so(3)_{h₁}, 6 in Sym(3)), and the rank is at least 5 (its rank at an exact point), where the printed
       dimension gives 4 = 7 − 3; so the dimension is at most 2, and it is at least 2, since (ξ₁, η₁) = (0, I_r)
       and (h₁, −A₁) solve the system as printed.  What the restriction of Λ_{1,−1} to ker Λ₁ gives (pairing with ζ₁ in the Cartan
       subalgebra so(r, ℂ)_{h₁}) is [A₁, η₁] ⟂ so(r, ℂ)_{h₁}; with that (17) §6 the solutions are r-dimensional and
       (11) §6 follows.""",
       statement=r"\dim\{(\xi_1,\eta_1)\in so(r)_{h_1}\oplus Sym(r)\mid [A_1,\xi_1]-[h_1,\eta_1]=0,\ "
                 r"[A_1,\eta_1]\in so(r,\mathbb C)^\perp\}=r")
def pencil_l5_l6(s):
    """The solutions of (L5), (L6) in so(r)_{h1} ⊕ Sym(r) form an r-dimensional space (the proof of (A2), after Theorem 1.6 of Bolsinov)."""
    M, unknowns = l5_l6_matrix(s, printed=True)
    return {"rank of (16), (17) §6": Rank(M, unknowns - s.r, generic=True, meaning="unknowns − r")}


@pencil_l5_l6.claim.correction("(17) §6: [A₁, η₁] ⟂ so(r, ℂ)_{h₁} in place of [A₁, η₁] ∈ so(r, ℂ)^⊥")
def pencil_l5_l6_corrected(s):
    M, unknowns = l5_l6_matrix(s, printed=False)
    return {"rank of (16), (17) §6": Rank(M, unknowns - s.r, generic=True, meaning="unknowns − r")}


# -- the Casimirs: complete on the leaf (LEMA2) and the tori (NEUMANN, dim_fol) ---------------------------

def casimir_gradient_rows(s, x, A):
    """Coordinates (in the basis of gl(n), up to the diagonal Gram matrix) of the gradients of
    tr(λh + v − λ²A)^k, k = 1..n, at 2n values of λ (degree <= 2k − 1 in λ: these span every λ)."""
    n = s.n
    basis, kinds = gl_basis(s)
    half = s.q(1, 2)
    h, v = (x - x.T) * half, (x + x.T) * half
    gram_inv = {"so": s.q(1), "sym": s.q(-1)}
    rows = []
    for lam in range(2 * n):
        L = s.q(lam)
        M = h * L + v - A * (L * L)
        power = s.In
        for k in range(1, n + 1):
            row = []
            for kind in kinds:
                g = pair(power, kind) * s.q(k)
                g = g * L if kind[0] == "so" else g
                row.append(g * (gram_inv[kind[0]] if kind[1] != kind[2] or kind[0] == "so" else s.q(-2)))
            rows.append(row)
            power = power @ M
    return rows


@claim("casimirs-complete-on-leaf", paper=("LEMA2", "central", "dimension"), kind="dim",
       sizes=admissible(5), exact_max_n=4, exact_max_r={5: 2}, equivariance=EQUIVARIANCE_XA,
       statement=r"\rank\{d f|_{T_x\mathcal O}: f\in\mathcal F\}=l=\tfrac12\dim\mathcal O,\quad x=\Theta(X,P)\ \text{generic}")
def casimirs_complete_on_leaf(s):
    """Lemma LEMA2: among the functions (central) there are l = ½(dimension) independent on a generic symplectic leaf 𝒪 ⊂ Θ(T*V) (the rank of df restricted to Tₓ𝒪 = Λ1(x)(gl(n)))."""
    n, r = s.n, s.r
    x = theta(s)
    rows = casimir_gradient_rows(s, x, s.A)
    G = s.mat(rows)
    # ker Λ1 and the gradients themselves: dF(Λ1 dF) = {F, F}_1 = 0, the functions are in involution (those at
    # λ = 1..[n/2] + 1 are enough: λ = 0 gives the Casimirs tr v^k of Λ1, already in ker Λ1)
    K = as_columns(s, lema1_kernel_columns(s) + rows[n: n * (n // 2 + 2)])
    return {"rank dF . Lambda1": Rank(G @ lambda1(s, x), leaf_printed(n, r) // 2, generic=True,
                                      meaning="l independent Casimirs on the leaf", kernel=K)}


def torus_functions(s, with_casimirs=True):
    """The integrals of Theorem NEUMANN as scalar functions of the scene: tr(λΦ + XXᵀ − λ²A)^k
    (k = 1..n, 2n values of λ) and the entries Ψ_ij, i < j."""
    n, r = s.n, s.r
    funcs = []
    if with_casimirs:
        for lam in range(2 * n):
            for k in range(1, n + 1):
                def f(t, lam=lam, k=k):
                    L = t.q(lam)
                    M = t.Phi * L + t.X @ t.X.T - t.A * (L * L)
                    P = M
                    for _ in range(k - 1):
                        P = P @ M
                    return t.tr(P)
                funcs.append(f)
    for i in range(r):
        for j in range(i + 1, r):
            funcs.append(lambda t, i=i, j=j: t.Psi[i, j])
    return funcs


def torus_values(t, with_casimirs=True):
    """The values at the scene t of the functions of :func:`torus_functions`, in the same order, with
    XXᵀ formed once and the powers of each matrix λΦ + XXᵀ − λ²A taken once."""
    n, r = t.n, t.r
    out = []
    if with_casimirs:
        XXt = t.X @ t.X.T
        for lam in range(2 * n):
            L = t.q(lam)
            M = t.Phi * L + XXt - t.A * (L * L)
            P = None
            for _ in range(n):
                P = M if P is None else P @ M
                out.append(t.tr(P))
    Psi = t.Psi
    for i in range(r):
        for j in range(i + 1, r):
            out.append(Psi[i, j])
    return out


def torus_kernel(s):
    """The tangent vectors of the tori: the Dirac flows (coordinates of X, then of P) of the integrals
    tr(λΦ + XXᵀ − λ²A)^k and of the Casimirs tr Ψ^(2k), k = 1..[r/2], of so(r) (which commute with every
    Ψ_ij): they commute with all the functions and are tangent to T*V."""
    n, r = s.n, s.r
    functions = torus_functions(s, with_casimirs=True)[n: n * (n // 2 + 2)]    # λ = 1..[n/2] + 1 are enough
    for k in range(1, r // 2 + 1):
        def casimir(t, k=k):
            return t.tr(power_of(t.Psi, 2 * k, t.Ir))
        functions.append(casimir)
    cols = []
    for f in functions:
        flow = s.dirac_flow(f)
        FX, FP = flow["X"], flow["P"]
        cols.append([FX[i, j] for i in range(n) for j in range(r)] + [FP[i, j] for i in range(n) for j in range(r)])
    return as_columns(s, cols)


@claim("neumann-torus-dimension", paper=("NEUMANN", "dim_fol", "torus"), kind="dim",
       sizes=admissible(5), exact_max_n=4, exact_max_r={5: 1}, equivariance=EQUIVARIANCE_XA,
       statement=r"2\dim V_{n,r}-\rank d\big(\Theta^*\mathcal F,\Psi\big)=\tfrac12\Big(2r(n-r)+\tfrac{r(r-1)}2-"
                 r"\left[\tfrac r2\right]\Big)+\left[\tfrac r2\right]")
def neumann_torus_dimension(s):
    """Theorem NEUMANN: the integrals Θ*𝓕 (perelomov) and Ψ have 2dim V − (dim_fol) independent differentials on T*V, so the generic isotropic tori have the dimension (dim_fol) (the rank on T*V is the rank of the Jacobian with the constraints' rows, less r(r+1))."""
    n, r = s.n, s.r
    rows = differentials(s, torus_functions(s)) + s.jacobian(s.constraints.build)
    expected = 2 * dim_V(n, r) - torus_twice_printed(n, r) // 2 + r * (r + 1)
    return {
        "rank d(Theta*F, Psi, constraints)": Rank(s.mat(rows), expected, generic=True,
                                                  meaning="2 dim V − (dim_fol) + r(r+1)", kernel=torus_kernel(s)),
        "(dim_fol) is an integer": Count(torus_twice_printed(n, r) % 2, 0, "2·(dim_fol) is even"),
    }
