"""Ten more statements of Fedorov & Jovanović that the catalog does not state, or states in another form, written
as a user writes them: the momentum map on a fibre (iso), the rank of the infinitesimal left action (hat), the
constraints as Casimirs of the Dirac bracket, the forms of Λ₁ and Λ_{1,-1} behind (L1)-(L4) in the proofs of
Lemmas LEMA1 and LEMA2, the Lax matrix (LA2) at λ = 0, the so(n, n) form of the big Lax pair of Appendix 2, the
right momentum of the metric ds²_A, the principal 2r-minors of Φ as squares of Plücker coordinates, and the
plane span{e, p} of the Poisson sphere.

    stiefelsym verify --claims examples/paper_extra3.py --method auto --jobs 1
    stiefelsym verify --claims examples/paper_extra3.py z-lemma1-kernel-form --method free

Only the public API: `stiefelsym`'s exports and the scene `s`.
"""
from itertools import combinations

from stiefelsym import Rank, admissible, block, claim, comm, elementary, det

#: r = 1, n >= 2 (T*S^{n-1})
R_IS_1 = admissible(n_max=5, n_min=2, r_in=(1,), condition="r = 1")
#: 2r <= n, where the principal 2r x 2r minors of Phi exist
TWO_R_LE_N = admissible(n_max=5, where=lambda n, r: 2 * r <= n, condition="2r <= n")


# ---------------------------------------------------------------------------------------------
# 1. (iso), (P-neutral), proof of Lemma LEMA1: Phi restricted to T*_X V lands in v = so(n-r)^perp
#    (at X0 the lower-right (n-r)x(n-r) block of h = Phi(X0, P0) is 0) and is injective there.
# ---------------------------------------------------------------------------------------------
@claim("z-iso-fibre", paper=("iso", "P-neutral", "LEMA1"), kind="id", section="2",
       statement=r"(I-XX^T)\Phi(I-XX^T)=0,\quad X^T\Phi X=\Psi,\quad P=\Phi X-\tfrac12X\Psi")
def iso_fibre(s):
    """(iso): the momentum map restricted to the fibre T*_X V takes values in v, the orthogonal complement of so(n-r) = {xi: xi X = 0, X^T xi = 0} (the block h = [[h1, h2], [-h2^T, 0]] of the proof of Lemma LEMA1), its so(r) part is Psi, and it determines P (so T*_X V = v)."""
    X, P, Phi, Psi = s.X, s.P, s.Phi, s.Psi
    Q = s.In - X @ X.T
    return {
        "(I - XX^T) Phi (I - XX^T)": Q @ Phi @ Q,
        "X^T Phi X - Psi": X.T @ Phi @ X - Psi,
        "P - (Phi X - X Psi / 2)": P - (Phi @ X - X @ Psi / 2),
    }


# ---------------------------------------------------------------------------------------------
# 2. (hat), §2: SO(n) acts transitively on V(n, r) with isotropy SO(n-r); so the infinitesimal
#    action xi -> xi X has rank dim so(n) - dim so(n-r) = dim V at every X, kernel (I-XX^T) so(n) (I-XX^T).
# ---------------------------------------------------------------------------------------------
def _so_basis_pairs(n):
    return [(i, j) for i in range(n) for j in range(i + 1, n)]


@claim("z-left-action-rank", paper=("hat", "base", "cond_X*"), kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2 (so(1) = 0)"),
       statement=r"\rank\{\xi\mapsto\xi X\}=\dim so(n)-\dim so(n-r)=rn-\tfrac{r(r+1)}2")
def left_action_rank(s):
    """The left SO(n) action on V(n, r) is transitive with isotropy SO(n-r) (hat): the linear map so(n) -> R^{n x r}, xi -> xi X, has rank dim V = rn - r(r+1)/2, its kernel being Q so(n) Q, Q = I - XX^T."""
    n, r, X = s.n, s.r, s.X
    pairs = _so_basis_pairs(n)
    # column (i, j): vec((E_i E_j^T - E_j E_i^T) X): row i gets X[j, :], row j gets -X[i, :]
    rows = []
    for a in range(n):
        for b in range(r):
            row = []
            for (i, j) in pairs:
                if a == i:
                    row.append(X[j, b])
                elif a == j:
                    row.append(-X[i, b])
                else:
                    row.append(0)
            rows.append(row)
    M = s.mat(rows)
    Q = s.In - X @ X.T
    # kernel: coordinates (i < j) of Q (E_k E_l^T - E_l E_k^T) Q, one column per (k, l)
    krows = []
    for (i, j) in pairs:
        krows.append([Q[i, k] * Q[l, j] - Q[i, l] * Q[k, j] for (k, l) in pairs])
    K = s.mat(krows)
    return {"rank of xi -> xi X": Rank(M, n * r - r * (r + 1) // 2, kernel=K,
                                        meaning="dim so(n) - dim so(n-r) = dim V(n, r)")}


# ---------------------------------------------------------------------------------------------
# 3. (Dirac_bracket), §2: "T*V is a symplectic leaf of the Dirac bracket and the restriction of
#    {f1, f2} to T*V depends only on the restrictions of f1, f2 to T*V".
# ---------------------------------------------------------------------------------------------
@claim("z-dirac-restriction", paper=("Dirac_bracket", "cond_XP", "scalar"), kind="pb", section="2",
       sizes=admissible(n_max=4),
       statement=r"\{F_i,h\}=0,\quad \{f+F_1g+F_2k,h\}=\{f,h\}\ \text{on }T^*V")
def dirac_restriction(s):
    """The constraint functions (scalar) are Casimirs of the Dirac bracket (Dirac_bracket), so T*V is a union of its symplectic leaves, and {f, h} on T*V depends only on the restriction of f to T*V: adding multiples of constraints to f does not change it."""
    U, W, V = s.fresh("n", "r"), s.fresh("n", "r"), s.fresh("n", "r")
    S1, S2 = s.generic("S1", "r", "r", "sym"), s.generic("S2", "r", "r", "sym")

    def F1(t):  # a combination of the F_ij = (e_i, e_j) - delta_ij
        return t.tr(S1 @ (t.X.T @ t.X - t.Ir))

    def F2(t):  # a combination of the G_ij = (e_i, p_j) + (e_j, p_i)
        return t.tr(S2 @ (t.X.T @ t.P + t.P.T @ t.X))

    def f(t):
        return t.tr(U.T @ t.P) * t.tr(W.T @ t.X) + t.tr(t.P.T @ t.A @ t.P)

    def h(t):
        return t.tr(V.T @ t.P) * t.tr(V.T @ t.P) + t.tr(t.X.T @ t.A @ t.X @ t.X.T @ t.P)

    def f_changed(t):
        return f(t) + F1(t) * t.tr(U.T @ t.X) + F2(t) * t.tr(W.T @ t.P)

    return {
        "{F1, h}": s.bracket(F1, h),
        "{F2, h}": s.bracket(F2, h),
        "{f + F1 g + F2 k, h} - {f, h}": s.bracket(f_changed, h) - s.bracket(f, h),
    }


# ---------------------------------------------------------------------------------------------
# 4. Proof of Lemma LEMA1: Lambda_1 at x = h + v = Theta(X, P), in the form that gives (L1), (L2),
#    and [eta, v] = [[0, -eta3], [eta3^T, 0]] written without coordinates.
# ---------------------------------------------------------------------------------------------
def lambda1(t, x, xi, eta, zeta, theta):
    """(LAMBDA12): Lambda_1(xi + eta, zeta + theta)|_x = <x, [xi, zeta] + [xi, theta] + [eta, zeta]>."""
    return t.killing(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))


def lambda2(t, x, xi, eta, zeta, theta):
    """(LAMBDA12): Lambda_2(xi + eta, zeta + theta)|_x = <x - A, [xi + eta, zeta + theta]>."""
    return t.killing(x - t.A, comm(xi + eta, zeta + theta))


@claim("z-lemma1-kernel-form", paper=("LEMA1", "L1", "L2", "LAMBDA12"), kind="id", section="6",
       sizes=admissible(n_max=5),
       statement=r"\Lambda_1(\xi+\eta,\zeta+\theta)|_{h+v}=-\langle[\xi,h]+[\eta,v],\zeta\rangle-\langle[\xi,v],\theta\rangle,"
                 r"\ [\eta,v]=(I-v)\eta v-v\eta(I-v)")
def lemma1_kernel_form(s):
    """Proof of Lemma LEMA1: at x = h + v, h = Phi, v = XX^T, Lambda_1(xi + eta, zeta + theta) = -<[xi, h] + [eta, v], zeta> - <[xi, v], theta>, so xi + eta is in the kernel iff (L1) [xi, v] = 0 and (L2) [xi, h] + [eta, v] = 0; and [eta, v] has only the off-diagonal blocks -eta3, eta3^T of the proof."""
    h, v = s.Phi, s.X @ s.X.T
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta_n", "n", "n", "sym"), s.generic("theta_n", "n", "n", "sym")
    Q = s.In - v
    lhs = lambda1(s, h + v, xi, eta, zeta, theta)
    rhs = -s.killing(comm(xi, h) + comm(eta, v), zeta) - s.killing(comm(xi, v), theta)
    return {
        "Lambda_1 - kernel form": lhs - rhs,
        "[eta, v] - (Q eta v - v eta Q)": comm(eta, v) - (Q @ eta @ v - v @ eta @ Q),
    }


# ---------------------------------------------------------------------------------------------
# 5. (LAMBDA), proof of Lemma LEMA2: Lambda_{1,-1} at h + v, and the form giving (L3), (L4).
# ---------------------------------------------------------------------------------------------
@claim("z-lambda-1-minus-1", paper=("LAMBDA", "L3", "L4", "LAMBDA12"), kind="id", section="6",
       sizes=admissible(n_max=5),
       statement=r"\Lambda_{1,-1}(\xi+\eta,\zeta+\theta)|_{h+v}=-\langle h,[\eta,\theta]\rangle+\langle A,[\xi,\theta]+[\eta,\zeta]\rangle"
                 r"=-\langle[\xi,A]-[\eta,h],\theta\rangle-\langle[\eta,A],\zeta\rangle")
def lambda_one_minus_one(s):
    """(LAMBDA): Lambda_{1,-1} = Lambda_1 - Lambda_2 at x = h + v = Theta(X, P) is -<h, [eta, theta]> + <A, [xi, theta] + [eta, zeta]>, which is -<[xi, A] - [eta, h], theta> - <[eta, A], zeta>: its kernel is given by (L3) [eta, A] = 0 and (L4) [xi, A] - [eta, h] = 0."""
    h, v = s.Phi, s.X @ s.X.T
    xi, zeta = s.xi, s.zeta
    eta, theta = s.generic("eta_n", "n", "n", "sym"), s.generic("theta_n", "n", "n", "sym")
    x = h + v
    pencil = lambda1(s, x, xi, eta, zeta, theta) - lambda2(s, x, xi, eta, zeta, theta)
    printed = -s.killing(h, comm(eta, theta)) + s.killing(s.A, comm(xi, theta) + comm(eta, zeta))
    kernel_form = -s.killing(comm(xi, s.A) - comm(eta, h), theta) - s.killing(comm(eta, s.A), zeta)
    return {"Lambda_{1,-1} - (LAMBDA)": pencil - printed, "(LAMBDA) - (L3),(L4) form": printed - kernel_form}


# ---------------------------------------------------------------------------------------------
# 6. (LA2), (spectral-curve) at the spectral parameter lambda = 0: L_neum(0) = XX^T is the orthogonal
#    projector onto span(e_1..e_r), so det(L_neum(0) - mu I) = (-mu)^{n-r}(1-mu)^r.
# ---------------------------------------------------------------------------------------------
def L_neum(t, lam):
    """(LA2): L_neum(lambda) = lambda Phi + XX^T - lambda^2 A."""
    return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A


@claim("z-spectral-curve-at-zero", paper=("LA2", "spectral-curve", "perelomov"), kind="id", section="5",
       statement=r"\mathcal L_{neum}(0)^2=\mathcal L_{neum}(0),\ \tr\mathcal L_{neum}(0)^k=r,\ e_j(\mathcal L_{neum}(0))=\binom rj\ (j\le3)")
def spectral_curve_at_zero(s):
    """At lambda = 0 the Lax matrix (LA2) is XX^T, a projector of rank r: the spectral curve (spectral-curve) meets lambda = 0 in mu = 0 (n - r times) and mu = 1 (r times), and the integrals (perelomov) there are the constants tr(XX^T)^k = r."""
    L0 = L_neum(s, s.q(0))
    rho = s.tr(s.Ir)
    e = elementary(s, L0, 3)
    checks = {"L(0)^2 - L(0)": L0 @ L0 - L0}
    for k in (1, 2, 3, 4):
        acc = L0
        for _ in range(k - 1):
            acc = acc @ L0
        checks[f"tr L(0)^{k} - r"] = s.tr(acc) - rho
    checks["e_1 - r"] = e[1] - rho
    checks["e_2 - r(r-1)/2"] = e[2] - rho * (rho - 1) / 2
    checks["e_3 - r(r-1)(r-2)/6"] = e[3] - rho * (rho - 1) * (rho - 2) / 6
    return checks


# ---------------------------------------------------------------------------------------------
# 7. (so(n,n)), Appendix 2: "a big Lax pair of the r-coupled systems with so(n,n)-matrices":
#    L(nu), A(nu) preserve the split form J = diag(I_n, -I_n).
# ---------------------------------------------------------------------------------------------
@claim("z-coupled-so-n-n", paper=("so(n,n)", "C-neumann"), kind="id", section="A2",
       sizes=admissible(n_max=4),
       statement=r"L(\nu)^TJ+JL(\nu)=0,\ A(\nu)^TJ+JA(\nu)=0,\ J=\mathrm{diag}(I_n,-I_n)")
def coupled_so_n_n(s):
    """(so(n,n)): the matrices L(nu) and A(nu) = L_+(nu) of the big Lax pair of the r-coupled Neumann systems lie in so(n, n) = {M : M^T J + J M = 0}, J = diag(I_n, -I_n) (checked for nu L(nu), which has no pole)."""
    X, P, Y, Q, A, nu = s.X, s.P, s.Y, s.Q, s.A, s.lam
    Z = s.zeros(s.n, s.n, ("n", "n"))
    J = block([[s.In, Z], [Z, -s.In]])
    AA = block([[Z, A], [A, Z]])
    D = block([[P @ X.T - X @ P.T, Z], [Z, Q @ Y.T - Y @ Q.T]])
    K = block([[Z, X @ Y.T], [Y @ X.T, Z]])
    nuL = nu * nu * AA + nu * D + K            # nu * L(nu)
    Aplus = nu * AA + D                         # A(nu) = L_+(nu)
    return {"(nu L)^T J + J (nu L)": nuL.T @ J + J @ nuL, "A^T J + J A": Aplus.T @ J + J @ Aplus}


# ---------------------------------------------------------------------------------------------
# 8. Remark after (A_XP): ds^2_A is right SO(r)-invariant, so the momentum X^T P - P^T X of the right
#    action is conserved by the geodesic flow (A_XP) on the realization (cond_XP2).
# ---------------------------------------------------------------------------------------------
def H_A(t):
    """H_A = 1/2 tr(P^T A^{-1} P)."""
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


@claim("z-a-metric-right-momentum", paper=("A_XP", "cond_XP2", "leg2"), kind="pb", section="3",
       realization="metric", sizes=admissible(n_max=4),
       statement=r"\tfrac{d}{dt}(X^TP-P^TX)=0\ \text{along (A\_XP)};\ \tfrac{d}{ds}H_A(Xe^{s\eta},Pe^{s\eta})=0")
def a_metric_right_momentum(s):
    """The remark after (A_XP): ds^2_A is right SO(r)-invariant (H_A is invariant under (X eta, P eta), eta in so(r), which also preserves (cond_XP2)), so the Noether momentum X^T P - P^T X = X^T A Xdot - Xdot^T A X is an integral of the geodesic flow (A_XP)."""
    X, P = s.X, s.P
    flow = s.dirac_flow(H_A)
    printed = {"X": s.Ainv @ P, "P": X @ (X.T @ flow.Pdot)}
    right = {"X": X @ s.eta, "P": P @ s.eta}
    return {
        "d/dt (X^T P - P^T X) along the Dirac flow": s.d(lambda t: t.X.T @ t.P - t.P.T @ t.X, flow),
        "d/dt (X^T P - P^T X) along (A_XP)": s.d(lambda t: t.X.T @ t.P - t.P.T @ t.X, printed),
        "d H_A along (X eta, P eta)": s.d(H_A, right),
        "d (X^T A^-1 P + P^T A^-1 X) along (X eta, P eta)":
            s.d(lambda t: t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X, right),
    }


# ---------------------------------------------------------------------------------------------
# 9. §8 after (2r-integrals): |Phi|^{I_2r}_{I_2r} = (e_1 ^ ... ^ e_r ^ p_1 ^ ... ^ p_r)_{I_2r}^2.
# ---------------------------------------------------------------------------------------------
@claim("z-phi-minors-pluecker", paper=("2r-integrals", "forms", "VV"), kind="id", section="8",
       sizes=TWO_R_LE_N,
       statement=r"|\Phi|^{I_{2r}}_{I_{2r}}=(e_1\wedge\cdots\wedge e_r\wedge p_1\wedge\cdots\wedge p_r)^2_{I_{2r}}")
def phi_minors_are_pluecker_squares(s):
    """The note after (2r-integrals): every principal 2r x 2r minor of Phi = PX^T - XP^T is the square of the Pluecker coordinate of e_1 ^ ... ^ e_r ^ p_1 ^ ... ^ p_r with the same rows (a Pfaffian identity, Phi = W J W^T with W = (X P))."""
    n, r = s.n, s.r
    W = block([[s.X, s.P]])
    checks = {}
    for I in combinations(range(n), 2 * r):
        S = s.mat([[1 if c == I[a] else 0 for c in range(n)] for a in range(2 * r)], ("?", "n"))
        minor_phi = det(s, S @ s.Phi @ S.T)
        pl = det(s, S @ W)
        checks["minor " + ",".join(str(i + 1) for i in I)] = minor_phi - pl * pl
    return checks


# ---------------------------------------------------------------------------------------------
# 10. Corollary after (sp1), (P_q): for the Poisson sphere, Sigma(t) = span{e, p} = span{e, A edot}.
# ---------------------------------------------------------------------------------------------
def H_poisson_sphere(t):
    """H = 1/2 <AA Phi, Phi> with the Manakov operator for B = -A^{-1}: AA(xi) = A^{-1} xi A^{-1}."""
    return t.killing(t.Ainv @ t.Phi @ t.Ainv, t.Phi) / 2


@claim("z-poisson-sphere-plane", paper=("sp1", "P_q", "Chasles-Manakov"), kind="dim", section="8",
       sizes=R_IS_1,
       statement=r"r=1:\ \mathrm{span}\{e,p\}=\mathrm{span}\{e,A\dot e\},\ \rank(e,p,A\dot e)=\rank(e,A\dot e)=2")
def poisson_sphere_plane(s):
    """The Corollary of Theorem Chasles-Manakov: along the geodesic flow of the Poisson sphere metric (sp1) (r = 1, B = -A^{-1}), the moving 2-plane span{e, p} equals span{e, A edot}: A edot = (A^{-1}e, e) p - (A^{-1}e, p) e, and (e, p, A edot) has rank 2 with kernel ((A^{-1}e,p), -(A^{-1}e,e), 1)."""
    e, p = s.X, s.P
    flow = s.dirac_flow(H_poisson_sphere)
    Aed = s.A @ flow.Xdot
    c = s.tr(e.T @ s.Ainv @ e)
    d = s.tr(e.T @ s.Ainv @ p)
    M = block([[e, p, Aed]])
    K = s.mat([[d], [-c], [s.q(1)]])
    return {
        "A edot - (c p - d e)": Aed - (c * p - d * e),
        "rank (e, p, A edot)": Rank(M, 2, kernel=K, meaning="span{e, p} = span{e, A edot}"),
        "rank (e, A edot)": Rank(block([[e, Aed]]), 2, meaning="A edot is not along e"),
    }
