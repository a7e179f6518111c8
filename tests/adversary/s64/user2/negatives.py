# ruff: noqa
"""Session 64, user 2: false twins (w64-) of the statements in claims.py.

Every twin is an ordinary claim declared false with fails_at=... and erratum=..., so the
*expected* verdict is `fails` (a `proved`/`checked`/`numeric` would be an unexpected,
and wrong, verdict).  Sizes are restricted to where the twin is really false
(checked in indep.py with numpy).

    stiefelsym verify --claims negatives.py --jobs 1
"""
from stiefelsym import Rank, admissible, block, claim, comm
from stiefelsym.bases import matrix_of, matrix_units, so_basis

from _common import dual_L, manakov_flow, neumann_euclid_flow, perelomov_L, skew_part, sym_part, theta

ALWAYS = lambda n, r: True  # noqa: E731


@claim("w64-phi-poisson", paper="momentum_map", kind="pb", section="2",
       sizes=admissible(n_max=5, n_min=3), fails_at=ALWAYS, erratum="false twin: sign of the bracket",
       statement=r"\{\Phi_\xi,\Phi_\zeta\}=-\langle\Phi,[\xi,\zeta]\rangle")
def w_phi(s):
    """FALSE twin: {Phi_xi, Phi_zeta} = -<Phi, [xi, zeta]> (the (-) bracket)."""
    xi, ze = s.xi, s.zeta
    lhs = s.bracket(lambda t: t.killing(t.Phi, xi), lambda t: t.killing(t.Phi, ze))
    return {"res": lhs + s.killing(s.Phi, comm(xi, ze))}


@claim("w64-psi-antipoisson", paper="momentum_right_map", kind="pb", section="2",
       sizes=admissible(n_max=5, r_min=3), fails_at=ALWAYS, erratum="false twin: (+) instead of (-)",
       statement=r"\{\Psi_\eta,\Psi_\theta\}=+\langle\Psi,[\eta,\theta]\rangle")
def w_psi(s):
    """FALSE twin (r >= 3; so(2) is abelian): {Psi_eta, Psi_theta} = +<Psi, [eta, theta]>."""
    et, th = s.eta, s.theta
    lhs = s.bracket(lambda t: t.killing(t.Psi, et), lambda t: t.killing(t.Psi, th))
    return {"res": lhs - s.killing(s.Psi, comm(et, th))}


@claim("w64-orbit-dim-2l", paper="2l", kind="dim", section="2",
       sizes=admissible(n_max=5, n_min=2, where=lambda n, r: r < n, condition="r < n"),
       fails_at=ALWAYS, erratum="false twin: 2r(n-r) instead of 2l",
       statement=r"\operatorname{rank}\operatorname{ad}_\Phi=2r(n-r)")
def w_orbit(s):
    """FALSE twin: the generic orbit of Phi has dimension 2r(n-r) (that is dim of the fibre count,
    not the orbit)."""
    n, r = int(s.n), int(s.r)
    M = matrix_of(s, lambda u: comm(u, s.Phi), so_basis(s, "n"), "skew")
    return {"rank ad_Phi": Rank(M, 2 * r * (n - r))}


@claim("w64-euclid-noether", paper=("ET",), kind="pb", section="4",
       sizes=admissible(n_max=5, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n"),
       fails_at=ALWAYS, erratum="false twin: the Euclidean H in place of the normal H_0",
       statement=r"\{\tfrac12\tr P^TP,\tr(SP^TP)\}=0")
def w_noether(s):
    """FALSE twin: the Euclidean Hamiltonian commutes with the (p_i, p_j)."""
    S = s.generic("S", "r", "r", "sym")
    return {"res": s.bracket(lambda t: t.tr(t.P.T @ t.P) / 2, lambda t: t.tr(S @ t.P.T @ t.P))}


@claim("w64-manakov-integral", paper=("man", "dot_XP3*"), kind="id", section="4",
       sizes=admissible(n_max=5, n_min=3), fails_at=ALWAYS,
       erratum="false twin: the operator A^2 xi + xi A^2 (not the one with B = A^2)",
       statement=r"\tfrac{d}{dt}\tr(\Phi+\lambda A)^3=0\ \text{along }\dot X=(A^2\Phi+\Phi A^2)X")
def w_manakov(s):
    """FALSE twin: tr(Phi + lam A)^3 conserved along Xdot = (A^2 Phi + Phi A^2) X, Pdot = (...) P."""
    flow = manakov_flow(s, lambda t, m: t.A @ t.A @ m + m @ t.A @ t.A)
    lam = s.lam

    def I3(t):
        L = t.Phi + lam * t.A
        return t.tr(L @ L @ L)
    return {"res": s.d(I3, flow)}


@claim("w64-theta-poisson", paper=("LAMBDA12",), kind="pb", section="6",
       sizes=admissible(n_max=4, n_min=3), fails_at=ALWAYS,
       erratum="false twin: the full Lie-Poisson bracket of gl(n) instead of Lambda_1",
       statement=r"\{\Theta_u,\Theta_w\}=\langle\Theta,[u,w]\rangle")
def w_theta(s):
    """FALSE twin: Theta is Poisson into (gl(n), Lie-Poisson), i.e. the [eta, theta] term kept."""
    u, w = s.fresh("n", "n"), s.fresh("n", "n")
    lhs = s.bracket(lambda t: t.killing(theta(t), u), lambda t: t.killing(theta(t), w))
    return {"res": lhs - s.killing(theta(s), comm(u, w))}


@claim("w64-leaf-dim", paper=("dimension", "LEMA1"), kind="dim", section="6",
       sizes=admissible(n_max=5, r_min=2), fails_at=ALWAYS, erratum="false twin: [r/2] forgotten",
       statement=r"\operatorname{rank}\Lambda_1|_{\Theta}=2r(n-r)+\tfrac{r(r-1)}2")
def w_leaf(s):
    """FALSE twin (r >= 2): leaf dimension 2r(n-r) + r(r-1)/2."""
    n, r = int(s.n), int(s.r)
    x = theta(s)

    def f(E):
        return comm(x, skew_part(E)) + skew_part(comm(x, sym_part(E)))
    M = matrix_of(s, f, matrix_units(s, "n", "n"))
    return {"rank Lambda1": Rank(M, 2 * r * (n - r) + r * (r - 1) // 2)}


@claim("w64-perelomov-involution", paper=("perelomov",), kind="pb", section="6",
       sizes=admissible(n_max=4, n_min=3, where=lambda n, r: r < n, condition="r < n"),
       fails_at=ALWAYS, erratum="false twin: lam A in place of lam^2 A",
       statement=r"\{\tr(\lambda\Phi+XX^T-\lambda A)^2,\tr(\mu\Phi+XX^T-\mu A)^3\}=0")
def w_perelomov(s):
    """FALSE twin: with L(lam) = lam Phi + X X^T - lam A the traces commute."""
    lam, mu = s.lam, s.scalar("mu")

    def Lw(t, l):
        return l * t.Phi + t.X @ t.X.T - l * t.A

    def F(t):
        L = Lw(t, lam)
        return t.tr(L @ L)

    def G(t):
        L = Lw(t, mu)
        return t.tr(L @ L @ L)
    return {"res": s.bracket(F, G)}


@claim("w64-dual-lax-euclid", paper=("LA3", "LA4"), kind="lax", section="8",
       sizes=admissible(n_max=5), fails_at=ALWAYS, erratum="false twin: Lambda + lam I",
       statement=r"\mathcal A^*=\begin{pmatrix}0&I\\\Lambda+\lambda I&0\end{pmatrix}")
def w_dual_lax(s):
    """FALSE twin: A* = ((0, I), (Lambda + lam I, 0))."""
    Lam = s.X.T @ s.A @ s.X - s.P.T @ s.P
    Z = s.zeros(s.r, s.r, ("r", "r"))
    Ast = block([[Z, s.Ir], [Lam + s.lam * s.Ir, Z]])
    L = dual_L(s)
    return {"res": s.d(dual_L, neumann_euclid_flow(s)) - comm(L, Ast)}


@claim("w64-dual-odd-traces", paper=("LA3",), kind="id", section="8",
       sizes=admissible(n_max=5, r_min=2), fails_at=ALWAYS,
       erratum="false twin: lower-right block X^T R P (transpose of P^T R X)",
       statement=r"\tr\tilde{\mathcal L}^3=0")
def w_odd(s):
    """FALSE twin (r >= 2): with the lower-right block transposed the odd traces vanish."""
    R = s.resolvent(s.lam)
    X, P = s.X, s.P
    L = block([[-(X.T @ R @ P), -(X.T @ R @ X)], [s.Ir + P.T @ R @ P, X.T @ R @ P]])
    return {"tr L~^3": (L @ L @ L).trace()}


@claim("w64-dual-I2", paper=("2r-integrals",), kind="id", section="8",
       sizes=admissible(n_max=5, n_min=2, condition="n >= 2 (at n = 1, Phi = 0 and the twin holds)"), fails_at=ALWAYS, erratum="false twin: sign of the Phi term",
       statement=r"-\tfrac12\tr\mathcal L^{*2}=\tr(RXX^T)+\tfrac12\tr(R\Phi R\Phi)")
def w_I2(s):
    """FALSE twin: -1/2 tr L*^2 = tr(R X X^T) + 1/2 tr(R Phi R Phi)."""
    L = dual_L(s)
    R = s.resolvent(s.lam)
    rhs = s.tr(R @ s.X @ s.X.T) + s.tr(R @ s.Phi @ R @ s.Phi) / 2
    return {"res": -(L @ L).trace() / 2 - rhs}
