# ruff: noqa
"""Session 64, user 2: statements of Sections 2, 4, 6 and 8 of Fedorov & Jovanovic, restated.

    stiefelsym verify --claims claims.py --jobs 1

All ids are prefixed v64-.  Each has a false twin in negatives.py (w64-).
"""
from stiefelsym import Rank, admissible, block, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis


from _common import dual_L, manakov_flow, neumann_euclid_flow, perelomov_L, skew_part, sym_part, theta


# -- Section 2: momentum maps ----------------------------------------------------------

@claim("v64-phi-poisson", paper="momentum_map", kind="pb", section="2",
       sizes=admissible(n_max=5, n_min=2),
       statement=r"\{\langle\Phi,\xi\rangle,\langle\Phi,\zeta\rangle\}=\langle\Phi,[\xi,\zeta]\rangle")
def phi_is_poisson(s):
    """Phi is a Poisson map to so(n) with the (+) Lie-Poisson bracket: for linear functions
    Phi_xi = <Phi, xi>, {Phi_xi, Phi_zeta} = <Phi, [xi, zeta]> (Dirac bracket)."""
    xi, ze = s.xi, s.zeta
    lhs = s.bracket(lambda t: t.killing(t.Phi, xi), lambda t: t.killing(t.Phi, ze))
    return {"{Phi_xi, Phi_zeta} - <Phi,[xi,zeta]>": lhs - s.killing(s.Phi, comm(xi, ze))}


@claim("v64-psi-antipoisson", paper="momentum_right_map", kind="pb", section="2",
       sizes=admissible(n_max=5, r_min=2),
       statement=r"\{\langle\Psi,\eta\rangle,\langle\Psi,\theta\rangle\}=-\langle\Psi,[\eta,\theta]\rangle")
def psi_is_antipoisson(s):
    """Psi is anti-Poisson: {Psi_eta, Psi_theta} = -<Psi, [eta, theta]> ((-) bracket on so(r))."""
    et, th = s.eta, s.theta
    lhs = s.bracket(lambda t: t.killing(t.Psi, et), lambda t: t.killing(t.Psi, th))
    return {"{Psi_eta, Psi_theta} + <Psi,[eta,theta]>": lhs + s.killing(s.Psi, comm(et, th))}


@claim("v64-orbit-dim-2l", paper="2l", kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2),
       statement=r"\operatorname{rank}(\xi\mapsto[\xi,\Phi])=2l")
def orbit_dimension(s):
    """Lemma 2l: the adjoint orbit of a generic Phi(X, P) in so(n) has dimension
    2l = n(n-1)/2 - [n/2] for n <= 2r+1 and 2r(n-r-1) for n > 2r+1,
    i.e. ad_Phi has that rank on so(n)."""
    n, r = int(s.n), int(s.r)
    two_l = n * (n - 1) // 2 - n // 2 if n <= 2 * r + 1 else 2 * r * (n - r - 1)
    M = matrix_of(s, lambda u: comm(u, s.Phi), so_basis(s, "n"), "skew")
    return {"rank ad_Phi": Rank(M, two_l)}


# -- Section 4: integrability of geodesic flows ---------------------------------------------

@claim("v64-normal-noether", paper=("bols-jov", "SO(n)-inv"), kind="pb", section="4",
       sizes=admissible(n_max=5),
       statement=r"\{H_0,\tr(SP^TP)\}=0")
def normal_commutes_with_PtP(s):
    """Noether: the normal-metric Hamiltonian H_0 = 1/2 <Phi, Phi> commutes with the
    SO(n)-invariant functions (p_i, p_j): {H_0, tr(S P^T P)} = 0 for every symmetric S."""
    S = s.generic("S", "r", "r", "sym")
    return {"{H0, tr S PtP}": s.bracket(lambda t: t.killing(t.Phi, t.Phi) / 2,
                                        lambda t: t.tr(S @ t.P.T @ t.P))}


@claim("v64-euclid-not-noether", paper=("ET",), kind="not", expect="nonzero", section="4",
       sizes=admissible(n_max=5, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n"),
       statement=r"\{\tfrac12\tr P^TP,\tr(SP^TP)\}\neq0")
def euclid_does_not_commute(s):
    """Remark after Theorem ET: (p_i, p_j) do not Poisson commute with the Euclidean
    Hamiltonian (equivalently with <Psi, Psi>), for 2 <= r < n."""
    S = s.generic("S", "r", "r", "sym")
    return {"{HE, tr S PtP}": s.bracket(lambda t: t.tr(t.P.T @ t.P) / 2,
                                        lambda t: t.tr(S @ t.P.T @ t.P))}


@claim("v64-manakov-integral", paper=("man", "dot_XP3*"), kind="id", section="4",
       sizes=admissible(n_max=5),
       statement=r"\tfrac{d}{dt}\tr(\Phi+\lambda A)^3=0\ \text{along (dot\_XP3*)}")
def manakov_integral(s):
    """The integrals (man) tr(lambda A + Phi)^3 are conserved along the Manakov geodesic
    flow (dot_XP3*), Xdot = A(Phi) X, Pdot = A(Phi) P with A(xi) = A xi + xi A."""
    flow = manakov_flow(s, lambda t, m: t.A @ m + m @ t.A)
    lam = s.lam

    def I3(t):
        L = t.Phi + lam * t.A
        return t.tr(L @ L @ L)
    return {"d/dt tr(Phi + lam A)^3": s.d(I3, flow)}


@claim("v64-manakov-sign-trap", paper=("man",), kind="id", section="4",
       sizes=admissible(n_max=5),
       statement=r"\tfrac{d}{dt}\tr(\Phi-\lambda A)^3=0")
def manakov_sign_trap(s):
    """A 'sign twin' that is true: tr(Phi - lam A)^k = (-1)^k tr(Phi + lam A)^k (transpose),
    so it is conserved along (dot_XP3*) as well."""
    flow = manakov_flow(s, lambda t, m: t.A @ m + m @ t.A)
    lam = s.lam

    def I3(t):
        L = t.Phi - lam * t.A
        return t.tr(L @ L @ L)
    return {"d/dt tr(Phi - lam A)^3": s.d(I3, flow)}


# -- Section 6: compatible Poisson brackets -------------------------------------------------

@claim("v64-theta-poisson", paper=("LAMBDA12",), kind="pb", section="6",
       sizes=admissible(n_max=4),
       statement=r"\{\langle\Theta,u\rangle,\langle\Theta,w\rangle\}=\Lambda_1(u,w)|_{\Theta}")
def theta_is_poisson(s):
    """Theta = Phi + X X^T is a Poisson map (T*V, Dirac) -> (gl(n), Lambda_1):
    for u = xi + eta, w = zeta + theta in so(n) + Sym(n),
    {<Theta,u>, <Theta,w>} = <Theta, [xi,zeta] + [xi,theta] + [eta,zeta]>."""
    u, w = s.fresh("n", "n"), s.fresh("n", "n")
    xi, eta = skew_part(u), sym_part(u)
    ze, th = skew_part(w), sym_part(w)
    lhs = s.bracket(lambda t: t.killing(theta(t), u), lambda t: t.killing(theta(t), w))
    rhs = s.killing(theta(s), comm(xi, ze) + comm(xi, th) + comm(eta, ze))
    return {"{Theta_u, Theta_w} - Lambda1(u,w)": lhs - rhs}


@claim("v64-leaf-dim", paper=("dimension", "LEMA1"), kind="dim", section="6",
       sizes=admissible(n_max=5),
       statement=r"\operatorname{rank}\Lambda_1|_{\Theta(X,P)}=2r(n-r)+\tfrac{r(r-1)}2-[\tfrac r2]")
def leaf_dimension(s):
    """Lemma LEMA1: the symplectic leaf of (gl(n), Lambda_1) through Theta(X, P) has
    dimension 2r(n-r) + r(r-1)/2 - [r/2]: the rank of u = xi + eta -> [x, xi] + skew[x, eta]."""
    n, r = int(s.n), int(s.r)
    x = theta(s)

    def f(E):
        xi, eta = skew_part(E), sym_part(E)
        return comm(x, xi) + skew_part(comm(x, eta))
    M = matrix_of(s, f, matrix_units(s, "n", "n"))
    return {"rank Lambda1": Rank(M, 2 * r * (n - r) + r * (r - 1) // 2 - r // 2)}


@claim("v64-perelomov-involution", paper=("perelomov", "central"), kind="pb", section="6",
       sizes=admissible(n_max=4),
       statement=r"\{\tr\mathcal L(\lambda)^2,\tr\mathcal L(\mu)^3\}=0")
def perelomov_involution(s):
    """The integrals (perelomov) = Theta^* F commute for two values of the spectral
    parameter: {tr L(lam)^2, tr L(mu)^3} = 0, L(lam) = lam Phi + X X^T - lam^2 A."""
    lam, mu = s.lam, s.scalar("mu")

    def F(t):
        L = perelomov_L(t, lam)
        return t.tr(L @ L)

    def G(t):
        L = perelomov_L(t, mu)
        return t.tr(L @ L @ L)
    return {"{tr L(lam)^2, tr L(mu)^3}": s.bracket(F, G)}


# -- Section 8: the dual Lax pair --------------------------------------------------------------

@claim("v64-dual-lax-euclid", paper=("LA3", "LA4"), kind="lax", section="8",
       sizes=admissible(n_max=5),
       statement=r"\dot{\mathcal L}^*=[\mathcal L^*,\mathcal A^*],\ \mathcal A^*=\begin{pmatrix}0&I\\\Lambda-\lambda I&0\end{pmatrix}")
def dual_lax_euclid(s):
    """Theorem DUAL for (NE_XP): dL*/dt = [L*, A*] with A* = ((0, I), (Lambda - lam I, 0)),
    Lambda = X^T A X - P^T P."""
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    Z = s.zeros(s.r, s.r, ("r", "r"))
    Ast = block([[Z, s.Ir], [Lam - s.lam * s.Ir, Z]])
    L = dual_L(s)
    return {"dL*/dt - [L*, A*]": s.d(dual_L, neumann_euclid_flow(s)) - comm(L, Ast)}


@claim("v64-dual-odd-traces", paper=("LA3",), kind="id", section="8",
       sizes=admissible(n_max=5),
       statement=r"\tr\mathcal L^*(\lambda)=\tr\mathcal L^*(\lambda)^3=0")
def dual_odd_traces(s):
    """'Due to the symplectic block structure of L*, the coefficients at odd powers of w
    in the spectral curve are zero': tr L* = 0 and tr L*^3 = 0 on T*V."""
    L = dual_L(s)
    return {"tr L*": L.trace(), "tr L*^3": (L @ L @ L).trace()}


@claim("v64-dual-I2", paper=("2r-integrals",), kind="id", section="8",
       sizes=admissible(n_max=5),
       statement=r"-\tfrac12\tr\mathcal L^*(\lambda)^2=\tr(RXX^T)-\tfrac12\tr(R\Phi R\Phi)")
def dual_I2(s):
    """The first integral I_2(lam) of the dual spectral curve, divided by a(lam):
    -1/2 tr L*(lam)^2 = sum_i (XX^T)_ii/(lam - a_i) + sum_{i<j} Phi_ij^2/((lam-a_i)(lam-a_j))
    = tr(R X X^T) - 1/2 tr(R Phi R Phi), R = (lam I - A)^{-1}."""
    L = dual_L(s)
    R = s.resolvent(s.lam)
    rhs = s.tr(R @ s.X @ s.X.T) - s.tr(R @ s.Phi @ R @ s.Phi) / 2
    return {"-1/2 tr L*^2 - I2/a": -(L @ L).trace() / 2 - rhs}
