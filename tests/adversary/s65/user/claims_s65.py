# ruff: noqa
"""Session s65: statements of Fedorov & Jovanovic not in the catalog under their own words
(intermediate steps of proofs, remarks), each with a deliberately false twin.

Every twin is declared with ``fails_at`` and ``erratum`` ("deliberate twin"), so that a
run in which every verdict is the expected one exits 0.
"""
from stiefelsym import Count, Rank, admissible, block, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis
from stiefelsym.systems import stiefel_pairs_flow

SMALL = admissible(n_max=4)


def dso(m):
    return m * (m - 1) // 2 if m > 1 else 0


def stack(s, *Ms):
    """Rows of several matrices (with the same number of columns) as one untyped matrix."""
    rows = []
    for M in Ms:
        m, k = M.shape
        rows += [[M[i, j] for j in range(int(k))] for i in range(int(m))]
    return s.mat(rows)


def Phi_of(X, P):
    return P @ X.T - X @ P.T


def Psi_of(X, P):
    return X.T @ P - P.T @ X


def cayley(s, K, I):
    return (I - K) @ (I + K).inv()


def H_kappa_at(s, X, P):
    K = X.T @ P
    return s.tr(P.T @ P) / 2 - (s.q(1, 2) + s.kappa) * s.tr(K @ K)


# ---------------------------------------------------------------- Section 2 ----------------

@claim("s65-ddim-stabilizer", paper=("ddim",), kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2"),
       statement=r"\dim\{\xi\in so(n):\xi X=\xi P=0\}=\dim SO(n-2r)\ (n>2r),\ 0\ (n\le 2r)")
def ddim_stabilizer(s):
    """Proof of Lemma ddim: the isotropy of a generic P_0 in SO(n-r) is trivial for n <= 2r and SO(n-2r) for
    n > 2r; equivalently xi -> (xi X, xi P) on so(n) has rank dim so(n) - dim so(n-2r)."""
    n, r = int(s.n), int(s.r)
    B = so_basis(s, "n")
    M = stack(s, matrix_of(s, lambda xi: xi @ s.X, B), matrix_of(s, lambda xi: xi @ s.P, B))
    k = dso(n) - (dso(n - 2 * r) if n > 2 * r else 0)
    return {"rank xi -> (xi X, xi P)": Rank(M, k)}


@claim("s65-ddim-stabilizer-twin", paper=("ddim",), kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2, where=lambda n, r: n - r >= 2, condition="n - r >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: the stabilizer of X alone, SO(n-r), in place of SO(n-2r)")
def ddim_stabilizer_twin(s):
    """Twin: xi -> (xi X, xi P) has rank dim so(n) - dim so(n-r)."""
    n, r = int(s.n), int(s.r)
    B = so_basis(s, "n")
    M = stack(s, matrix_of(s, lambda xi: xi @ s.X, B), matrix_of(s, lambda xi: xi @ s.P, B))
    return {"rank xi -> (xi X, xi P)": Rank(M, dso(n) - dso(n - r))}


def fibre_kernel(s):
    """Kernel of the fibre map in the coordinates of fibre_basis: (0, XK) for the r^2 units K."""
    n, r = int(s.n), int(s.r)
    X = s.X
    m0 = r * (r - 1) // 2
    cols = []
    for k in range(r):
        for l in range(r):
            col = [s.q(0)] * m0
            for a in range(n):
                for b in range(r):
                    col.append(X[a, k] if b == l else s.q(0))
            cols.append(col)
    return s.mat([list(row) for row in zip(*cols)])


def fibre_basis(s):
    X = s.X
    Q = s.In - X @ X.T
    return [X @ E for E in so_basis(s, "r")] + [Q @ U for U in matrix_units(s, "n", "r")]


@claim("s65-iso-fibre", paper=("iso", "P-neutral"), kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2"),
       statement=r"\Phi|_{T^*_XV}\ \text{injective},\ \Phi(T^*_XV)\perp so(n-r)")
def iso_fibre(s):
    """(iso): the restriction of Phi to the fibre T*_X V is an isomorphism onto v = so(n-r)^perp: the linear map
    P -> P X^T - X P^T on the fibre {X^T P skew} has rank dim V, and its image has zero block on the
    complement of span X: (I - XX^T) Phi (I - XX^T) = 0."""
    n, r = int(s.n), int(s.r)
    X = s.X
    Q = s.In - X @ X.T
    M = matrix_of(s, lambda dP: dP @ X.T - X @ dP.T, fibre_basis(s), "skew")
    return {"rank on fibre": Rank(M, n * r - r * (r + 1) // 2, kernel=fibre_kernel(s)),
            "(I-XX^T) Phi (I-XX^T)": Q @ s.Phi @ Q}


@claim("s65-iso-fibre-twin", paper=("iso",), kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2, where=lambda n, r: n - r >= 2, condition="n - r >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: Phi maps one fibre onto all of so(n)")
def iso_fibre_twin(s):
    n, r = int(s.n), int(s.r)
    X = s.X
    M = matrix_of(s, lambda dP: dP @ X.T - X @ dP.T, fibre_basis(s), "skew")
    return {"rank on fibre": Rank(M, dso(n), kernel=fibre_kernel(s))}


# ---------------------------------------------------------------- Section 3 ----------------

@claim("s65-finite-invariance", paper=("EM",), kind="id", section="3", sizes=SMALL,
       statement=r"\Phi(XQ,PQ)=\Phi,\ \Psi(RX,RP)=\Psi,\ H_\kappa(RXQ,RPQ)=H_\kappa")
def finite_invariance(s):
    """Einstein metrics paragraph: Phi and Psi are invariant under the SO(r) and SO(n) actions respectively, so
    H_kappa is SO(n) x SO(r)-invariant (finite rotations Q = Cayley(eta), R = Cayley(xi))."""
    X, P = s.X, s.P
    Q = cayley(s, s.eta, s.Ir)
    R = cayley(s, s.xi, s.In)
    X2, P2 = R @ X @ Q, R @ P @ Q
    return {"Phi(XQ,PQ) - Phi": Phi_of(X @ Q, P @ Q) - s.Phi,
            "Psi(RX,RP) - Psi": Psi_of(R @ X, R @ P) - s.Psi,
            "H(RXQ,RPQ) - H": H_kappa_at(s, X2, P2) - H_kappa_at(s, X, P),
            "(RXQ)^T(RXQ) - I": X2.T @ X2 - s.Ir,
            "cond_XP at (RXQ,RPQ)": X2.T @ P2 + P2.T @ X2}


@claim("s65-finite-invariance-twin", paper=("EM",), kind="id", section="3",
       sizes=admissible(n_max=4, r_min=3, condition="r >= 3"),
       fails_at=lambda n, r: True, erratum="deliberate twin: Psi is equivariant (Q^T Psi Q), not invariant, under SO(r)")
def finite_invariance_twin(s):
    X, P = s.X, s.P
    Q = cayley(s, s.eta, s.Ir)
    return {"Psi(XQ,PQ) - Psi": Psi_of(X @ Q, P @ Q) - s.Psi}


@claim("s65-submersion-gradients", paper=("dot_XP2", "submersion_metric"), kind="id", section="3",
       sizes=admissible(n_max=4, n_min=2, condition="n >= 2"),
       statement=r"\partial H_\mathbb A/\partial P=\mathbb A(\Phi)X,\ -\partial H_\mathbb A/\partial X=\mathbb A(\Phi)P")
def submersion_gradients(s):
    """Proof of (dot_XP2): by the chain rule dH = dh_A o dPhi, the derivatives of H_A with respect to P and -X
    are A(Phi)X and A(Phi)P (in the ambient space)."""
    AA = s.sym_operator()
    H = lambda t: t.killing(AA(t.Phi), t.Phi) / 2
    HX, HP = s.gradient(H)
    M = AA(s.Phi)
    return {"dH/dP - A(Phi)X": HP - M @ s.X, "-dH/dX - A(Phi)P": -HX - M @ s.P}


@claim("s65-submersion-gradients-twin", paper=("dot_XP2",), kind="id", section="3",
       sizes=admissible(n_max=4, n_min=2, condition="n >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: sign of dH/dX")
def submersion_gradients_twin(s):
    AA = s.sym_operator()
    H = lambda t: t.killing(AA(t.Phi), t.Phi) / 2
    HX, HP = s.gradient(H)
    return {"dH/dX - A(Phi)P": HX - AA(s.Phi) @ s.P}


def H_sub(AA):
    return lambda t: t.killing(AA(t.Phi), t.Phi) / 2


@claim("s65-submersion-symmetry", paper=("submersion_metric", "normal_metric"), kind="id", section="3",
       sizes=SMALL, statement=r"H_\mathbb A\ \text{right }SO(r)\text{-invariant};\ H_0\ \text{left }SO(n)\text{-invariant}")
def submersion_symmetry(s):
    """Submersion Hamiltonians h o Phi are right SO(r)-invariant (Phi is); the normal metric, contrary to a
    generic submersion metric, is also SO(n)-invariant."""
    AA = s.sym_operator()
    X, P = s.X, s.P
    return {"d H_A along (X eta, P eta)": s.d(H_sub(AA), {"X": X @ s.eta, "P": P @ s.eta}),
            "d H_0 along (xi X, xi P)": s.d(lambda t: t.killing(t.Phi, t.Phi) / 2, {"X": s.xi @ X, "P": s.xi @ P})}


@claim("s65-submersion-symmetry-twin", paper=("submersion_metric",), kind="id", section="3",
       sizes=admissible(n_max=4, n_min=3, condition="n >= 3"),
       fails_at=lambda n, r: True, erratum="deliberate twin: a generic submersion metric is not left SO(n)-invariant")
def submersion_symmetry_twin(s):
    AA = s.sym_operator()
    X, P = s.X, s.P
    return {"d H_A along (xi X, xi P)": s.d(H_sub(AA), {"X": s.xi @ X, "P": s.xi @ P})}


# ---------------------------------------------------------------- Section 6 ----------------

def lambda_forms(s):
    h = s.generic("h", "n", "n", "skew")
    v = s.generic("v", "n", "n", "sym")
    xi, zeta = s.xi, s.zeta
    eta = s.generic("et", "n", "n", "sym")
    theta = s.generic("th", "n", "n", "sym")
    A = s.A
    k = lambda a, b: -s.tr(a @ b) / 2
    x = h + v
    L1 = k(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))
    L2 = k(x - A, comm(xi + eta, zeta + theta))
    return h, v, xi, zeta, eta, theta, A, k, L1, L2


@claim("s65-lambda-1-minus-1", paper=("LAMBDA", "LAMBDA12"), kind="id", section="6", sizes=SMALL,
       statement=r"\Lambda_{1,-1}(\xi+\eta,\zeta+\theta)|_{h+v}=-\langle h,[\eta,\theta]\rangle+\langle A,[\xi,\theta]+[\eta,\zeta]\rangle")
def lambda_1_minus_1(s):
    """(LAMBDA): Lambda_1 - Lambda_2 at x = h + v, from (LAMBDA12)."""
    h, v, xi, zeta, eta, theta, A, k, L1, L2 = lambda_forms(s)
    return {"(LAMBDA)": L1 - L2 - (-k(h, comm(eta, theta)) + k(A, comm(xi, theta) + comm(eta, zeta)))}


@claim("s65-lambda-1-minus-1-twin", paper=("LAMBDA",), kind="id", section="6",
       sizes=admissible(n_max=4, n_min=2, condition="n >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: + <h, [eta, theta]>")
def lambda_1_minus_1_twin(s):
    h, v, xi, zeta, eta, theta, A, k, L1, L2 = lambda_forms(s)
    return {"(LAMBDA)": L1 - L2 - (k(h, comm(eta, theta)) + k(A, comm(xi, theta) + comm(eta, zeta)))}


def lema1_blocks(s):
    n, r = int(s.n), int(s.r)
    m = n - r
    e1 = s.general_params("e1", r, r, ("r", "r"))
    e1 = e1 + e1.T
    e2 = s.general_params("e2", m, m, ("n-r", "n-r"))
    e2 = e2 + e2.T
    e3 = s.general_params("e3", r, m, ("r", "n-r"))
    Zrm = s.zeros(r, m, ("r", "n-r"))
    Zmr = s.zeros(m, r, ("n-r", "r"))
    Zmm = s.zeros(m, m, ("n-r", "n-r"))
    Zrr = s.zeros(r, r, ("r", "r"))
    eta = block([[e1, e3], [e3.T, e2]])
    v = block([[s.Ir, Zrm], [Zmr, Zmm]])
    return eta, v, e3, Zrr, Zmm


@claim("s65-lema1-eta-v", paper=("LEMA1", "L2"), kind="id", section="6",
       sizes=admissible(n_max=5, where=lambda n, r: r < n, condition="r < n"),
       statement=r"[\eta,v]=\begin{pmatrix}0&-\eta_3\\\eta_3^T&0\end{pmatrix}")
def lema1_eta_v(s):
    """Proof of Lemma LEMA1: for v = diag(I_r, 0) and eta = [[eta1, eta3], [eta3^T, eta2]] symmetric,
    [eta, v] = [[0, -eta3], [eta3^T, 0]]."""
    eta, v, e3, Zrr, Zmm = lema1_blocks(s)
    return {"[eta, v]": comm(eta, v) - block([[Zrr, -e3], [e3.T, Zmm]])}


@claim("s65-lema1-eta-v-twin", paper=("LEMA1",), kind="id", section="6",
       sizes=admissible(n_max=5, where=lambda n, r: r < n, condition="r < n"),
       fails_at=lambda n, r: True, erratum="deliberate twin: the signs of the off-diagonal blocks exchanged")
def lema1_eta_v_twin(s):
    eta, v, e3, Zrr, Zmm = lema1_blocks(s)
    return {"[eta, v]": comm(eta, v) - block([[Zrr, e3], [-e3.T, Zmm]])}


@claim("s65-h-blocks", paper=("LEMA1", "NEUMANN2"), kind="id", section="6", sizes=SMALL,
       statement=r"h=\Phi(X_0,P_0)=\begin{pmatrix}h_1&h_2\\-h_2^T&0\end{pmatrix},\ h_1=\Psi(X_0,P_0),\ h_2=-P_2^T")
def h_blocks(s):
    """Proof of LEMA1 (and of NEUMANN2, where Psi^{-1}(0) gives h_1 = 0): in the frame X, I - XX^T the momentum
    h = Phi has blocks h_1 = X^T Phi X = Psi, h_2 = X^T Phi (I - XX^T) = -P^T(I - XX^T) and a zero (2,2) block."""
    X, P = s.X, s.P
    Q = s.In - X @ X.T
    return {"h1 - Psi": X.T @ s.Phi @ X - s.Psi, "h2 + P^T Q": X.T @ s.Phi @ Q + P.T @ Q,
            "(2,2) block": Q @ s.Phi @ Q}


@claim("s65-h-blocks-twin", paper=("LEMA1",), kind="id", section="6",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: h_1 = -Psi")
def h_blocks_twin(s):
    return {"h1 + Psi": s.X.T @ s.Phi @ s.X + s.Psi}


def J_rows(s, count):
    cons = s.jacobian(lambda t: [t.X.T @ t.X, t.X.T @ t.P + t.P.T @ t.X], symmetric=True)
    rows = list(cons)
    for k in range(1, count + 1):
        rows += s.jacobian(lambda t, k=k: t.tr(_pow(t.Psi, 2 * k)))
    return s.mat(rows)


def _pow(M, k):
    R = M
    for _ in range(k - 1):
        R = R @ M
    return R


@claim("s65-jk-independent", paper=("torus", "REDUCED_BRACKET"), kind="dim", section="6",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"),
       statement=r"J_1,\dots,J_{[r/2]}\ \text{independent on }T^*V\ \text{(generic }\Psi)")
def jk_independent(s):
    """Proof of Theorem NEUMANN: J_k = tr(Psi^{2k}), k = 1..[r/2], are independent at a point where the
    Ad_SO(r) orbit of Psi is regular (generic points): the Jacobian of (cond_XP) and the J_k has rank
    r(r+1) + [r/2]."""
    r = int(s.r)
    return {"rank": Rank(J_rows(s, r // 2), r * (r + 1) + r // 2)}


@claim("s65-jk-independent-twin", paper=("torus",), kind="dim", section="6",
       sizes=admissible(n_max=3, r_min=2, r_max=2, condition="r = 2, n <= 3 (beyond, the exact function-field rank takes > 60 s)"),
       fails_at=lambda n, r: True, erratum="deliberate twin: J_{[r/2]+1} is not independent of the others")
def jk_independent_twin(s):
    r = int(s.r)
    return {"rank": Rank(J_rows(s, r // 2 + 1), r * (r + 1) + r // 2 + 1)}


# ---------------------------------------------------------------- Section 7 ----------------

@claim("s65-psi-zero", paper=("grassmannian",), kind="id", section="7", sizes=SMALL,
       statement=r"\Psi=2X^TP\ \text{on }T^*V,\ \text{so }(X,P)\in\Psi^{-1}(0)\iff X^TP=0")
def psi_zero(s):
    """Section 7: (X, P) lies in Psi^{-1}(0) iff X^T P = 0 (on T*V, Psi = 2 X^T P)."""
    return {"Psi - 2X^TP": s.Psi - 2 * (s.X.T @ s.P)}


@claim("s65-psi-zero-twin", paper=("grassmannian",), kind="id", section="7",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: factor 1 in place of 2")
def psi_zero_twin(s):
    return {"Psi - X^TP": s.Psi - s.X.T @ s.P}


def grassmannian_kernel(s):
    """Kernel of xi -> [xi, XX^T] in the coordinates xi_ij (i < j) of so_basis: X so(r) X^T + Q so(n) Q."""
    n = int(s.n)
    X = s.X
    Q = s.In - X @ X.T
    elems = [X @ E @ X.T for E in so_basis(s, "r")] + [Q @ E @ Q for E in so_basis(s, "n")]
    cols = [[M[i, j] for i in range(n) for j in range(i + 1, n)] for M in elems]
    return s.mat([list(row) for row in zip(*cols)])


@claim("s65-grassmannian-dimension", paper=("NEUMANN2",), kind="dim", section="7",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2"),
       statement=r"\dim G_{n,r}=r(n-r)=\tfrac12(\dim gl(n)-\dim gl(r)-\dim gl(n-r))")
def grassmannian_dimension(s):
    """Proof of Theorem NEUMANN2: dim G_{n,r} = r(n - r), the dimension of the adjoint orbit of v = XX^T
    (the tangent map xi -> [xi, XX^T] on so(n) has rank r(n-r)), which is
    (dim gl(n) - dim gl(r) - dim gl(n-r))/2."""
    n, r = int(s.n), int(s.r)
    v = s.X @ s.X.T
    M = matrix_of(s, lambda xi: comm(xi, v), so_basis(s, "n"), "sym")
    return {"rank": Rank(M, r * (n - r), kernel=grassmannian_kernel(s)),
            "count": Count((n * n - r * r - (n - r) * (n - r)) // 2, r * (n - r))}


@claim("s65-grassmannian-dimension-twin", paper=("NEUMANN2",), kind="dim", section="7",
       sizes=admissible(n_max=5, n_min=2, r_min=2, condition="r >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: dim V(n, r) in place of dim G(n, r)")
def grassmannian_dimension_twin(s):
    n, r = int(s.n), int(s.r)
    v = s.X @ s.X.T
    M = matrix_of(s, lambda xi: comm(xi, v), so_basis(s, "n"), "sym")
    return {"rank": Rank(M, n * r - r * (r + 1) // 2, kernel=grassmannian_kernel(s))}


# ---------------------------------------------------------------- Section 8 ----------------

@claim("s65-resolvent-identity", paper=("DUAL",), kind="id", section="8", sizes=SMALL,
       statement=r"A(\lambda I-A)^{-1}=(\lambda I-A)^{-1}A=\lambda(\lambda I-A)^{-1}-I")
def resolvent_identity(s):
    """The matrix identities used to check Theorem DUAL."""
    R = s.resolvent(s.lam)
    return {"AR": s.A @ R - (s.lam * R - s.In), "RA": R @ s.A - (s.lam * R - s.In)}


@claim("s65-resolvent-identity-twin", paper=("DUAL",), kind="id", section="8", sizes=SMALL,
       fails_at=lambda n, r: True, erratum="deliberate twin: + I")
def resolvent_identity_twin(s):
    R = s.resolvent(s.lam)
    return {"AR": s.A @ R - (s.lam * R + s.In)}


@claim("s65-dual-count", paper=("2r-integrals",), kind="dim", section="8",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2"),
       statement=r"N=(n-1)+\dots+(n-r)=r(n-r)+r(r-1)/2=\dim V_{n,r}")
def dual_count(s):
    """After (2r-integrals): the number N of nontrivial integrals of the dual Lax matrix is
    (n-1)+...+(n-r) = r(n-r) + r(r-1)/2, the dimension of the Stiefel variety (rank of xi -> xi X on so(n))."""
    n, r = int(s.n), int(s.r)
    N = sum(n - k for k in range(1, r + 1))
    M = matrix_of(s, lambda xi: xi @ s.X, so_basis(s, "n"))
    return {"N closed form": Count(N, r * (n - r) + r * (r - 1) // 2), "N = dim V": Rank(M, N)}


@claim("s65-dual-count-twin", paper=("2r-integrals",), kind="dim", section="8",
       sizes=admissible(n_max=5, n_min=2, r_min=1, condition="n >= 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: r(r+1)/2 in place of r(r-1)/2")
def dual_count_twin(s):
    n, r = int(s.n), int(s.r)
    N = sum(n - k for k in range(1, r + 1))
    return {"N closed form": Count(N, r * (n - r) + r * (r + 1) // 2)}


# ---------------------------------------------------------------- Appendix 1 ---------------

R1 = admissible(n_max=5, n_min=2, r_in=(1,), condition="r = 1")


def pr(e):
    return lambda xi: xi @ e @ e.T + e @ e.T @ xi


@claim("s65-od-projection", paper=("OD",), kind="dim", section="A1", sizes=R1,
       statement=r"\mathrm{pr}_{e}^2=\mathrm{pr}_e,\ \mathrm{pr}_e\xi=(\xi e)\wedge e,\ \mathrm{pr}_{e^\perp}(\xi)e=0,\ \mathrm{rank}\,\mathrm{pr}_{e^\perp}=\dim so(n-1)")
def od_projection(s):
    """(OD): pr_e(xi) = xi e(x)e + e(x)e xi is the projection onto e ^ R^n (idempotent, = (xi e) ^ e), its
    complement pr_{e-perp} kills e and is orthogonal to it, and {e ^ R^n}^perp = so(n-1) (ranks n-1 and
    (n-1)(n-2)/2)."""
    n = int(s.n)
    e = s.X
    p = pr(e)
    xi, zeta = s.xi, s.zeta
    perp = lambda m: m - p(m)
    B = so_basis(s, "n")
    out = {"pr^2 - pr": p(p(xi)) - p(xi),
           "pr(xi) - (xi e)^e": p(xi) - ((xi @ e) @ e.T - e @ (xi @ e).T),
           "pr_perp(xi) e": perp(xi) @ e,
           "<pr xi, pr_perp zeta>": s.tr(p(xi) @ perp(zeta)),
           "rank pr": Rank(matrix_of(s, p, B, "skew"), n - 1)}
    if n >= 3:
        out["rank pr_perp"] = Rank(matrix_of(s, perp, B, "skew"), dso(n - 1))
    return out


@claim("s65-od-projection-twin", paper=("OD",), kind="dim", section="A1", sizes=R1,
       fails_at=lambda n, r: True, erratum="deliberate twin: {e ^ R^n} of dimension n")
def od_projection_twin(s):
    n = int(s.n)
    return {"rank pr": Rank(matrix_of(s, pr(s.X), so_basis(s, "n"), "skew"), n)}


@claim("s65-ym-proof-line", paper=("mag6", "mag3", "Euler*"), kind="id", section="A1", sizes=R1,
       statement=r"(Ae\otimes e-e\otimes eA)e+(\dot e\wedge e)\dot e=Ae-((e,Ae)+(\dot e,\dot e))e")
def ym_proof_line(s):
    """Proof of Proposition YM (ii), second to third line, for a unit e and e' tangent (e^T e' = 0)."""
    e, ed, A = s.X, s.P, s.A
    lhs = (A @ e @ e.T - e @ e.T @ A) @ e + (ed @ e.T - e @ ed.T) @ ed
    rhs = A @ e - e @ (e.T @ A @ e + ed.T @ ed)
    return {"line": lhs - rhs}


@claim("s65-ym-proof-line-twin", paper=("mag6",), kind="id", section="A1", sizes=R1,
       fails_at=lambda n, r: True, erratum="deliberate twin: -(e', e') sign")
def ym_proof_line_twin(s):
    e, ed, A = s.X, s.P, s.A
    lhs = (A @ e @ e.T - e @ e.T @ A) @ e + (ed @ e.T - e @ ed.T) @ ed
    rhs = A @ e - e @ (e.T @ A @ e - ed.T @ ed)
    return {"line": lhs - rhs}


# ---------------------------------------------------------------- Appendix 2 ---------------

def T_kappa(t, z, kappa):
    XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    c = t.q(1, 2) + kappa
    return t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(XP @ XP) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(YQ @ YQ)


def coupled_H(kappa_of):
    return lambda t, z: T_kappa(t, z, kappa_of(t)) + t.tr(z["X"].T @ t.A @ z["Y"])


def coupled_flows_difference(s):
    z = {"X": s.X, "P": s.P, "Y": s.Y, "Q": s.Q}
    pairs = [("X", "P"), ("Y", "Q")]
    fk = stiefel_pairs_flow(s, coupled_H(lambda t: t.kappa), z, pairs)
    f0 = stiefel_pairs_flow(s, coupled_H(lambda t: t.q(0)), z, pairs)
    return {k + "' (kappa) - " + k + "' (0)": fk[k] - f0[k] for k in ("X", "P", "Y", "Q")}


@claim("s65-coupled-r1", paper=("C-neumann", "C-eq"), kind="id", section="A2",
       sizes=admissible(n_max=4, n_min=2, r_in=(1,), condition="r = 1"),
       statement=r"r=1:\ \text{all the metrics }T_\kappa\text{ give the same coupled flow}")
def coupled_r1(s):
    """Remark after (C-neumann): for r = 1, X^T P = Y^T Q = 0 and all the metrics coincide, so the coupled
    Neumann flows of every kappa are one flow."""
    out = coupled_flows_difference(s)
    out["X^T P"] = s.X.T @ s.P
    out["Y^T Q"] = s.Y.T @ s.Q
    return out


@claim("s65-coupled-r1-twin", paper=("C-neumann",), kind="id", section="A2",
       sizes=admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2"),
       fails_at=lambda n, r: True, erratum="deliberate twin: at r = 2 the coupled flows depend on kappa")
def coupled_r1_twin(s):
    return coupled_flows_difference(s)


# ---------------------------------------------------------------- Section 5 ----------------

def H_neum(kappa_of):
    def H(t):
        K = t.X.T @ t.P
        return (t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa_of(t)) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2)
    return H


def kappa_flow_difference(s):
    fk = s.dirac_flow(H_neum(lambda t: t.kappa))
    f0 = s.dirac_flow(H_neum(lambda t: t.q(0)))
    return {"X'(kappa) - X'(0)": fk["X"] - f0["X"], "P'(kappa) - P'(0)": fk["P"] - f0["P"]}


@claim("s65-kappa-flows-differ", paper=("No",), kind="not", expect="nonzero", section="5",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2"),
       statement=r"r\ge2:\ \text{the flows (No) for different }\kappa\text{ do not coincide}")
def kappa_flows_differ(s):
    """The Lax pair paragraph of Section 5: although the flows (No) for different kappa do not coincide (r >= 2),
    the derivatives of Phi and XX^T are the same (prep)."""
    return kappa_flow_difference(s)


@claim("s65-kappa-flows-differ-twin", paper=("No",), kind="not", expect="nonzero", section="5",
       sizes=admissible(n_max=4, r_max=1, condition="r = 1"),
       fails_at=lambda n, r: True, erratum="deliberate twin: at r = 1 (X^T P = 0) the flows (No) coincide for all kappa")
def kappa_flows_differ_twin(s):
    return kappa_flow_difference(s)
