"""h2: Neumann systems, own formulations, with false twins."""
from stiefelsym import admissible, claim, comm

SZ = admissible(n_max=4)


def Hn(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def HNE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def Lneu(t, lam):
    return lam * t.Phi + t.X @ t.X.T - lam * lam * t.A


def Lneu_bad(t, lam):
    return lam * t.Phi + t.X @ t.X.T + lam * lam * t.A


@claim("h2-potential-rate", paper="NE_XP", kind="id", sizes=SZ)
def potential_rate(s):
    """Along (NE_XP), d/dt tr(XᵀAX) = 2 tr(XᵀAP)."""
    return {"d": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), s.dirac_flow(HNE)) - 2 * s.tr(s.X.T @ s.A @ s.P)}


@claim("h2-potential-rate-TWIN", paper="NE_XP", kind="id", sizes=SZ)
def potential_rate_twin(s):
    """(false twin) d/dt tr(XᵀAX) = tr(XᵀAP)."""
    return {"d": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X), s.dirac_flow(HNE)) - s.tr(s.X.T @ s.A @ s.P)}


@claim("h2-multipliers", paper=("No", "neumann"), kind="id", sizes=SZ)
def multipliers(s):
    """For H_neum,κ as printed, Π = 0 and Λ = XᵀAX − PᵀP."""
    f = s.multiplier_flow(Hn)
    return {"Pi": f["Pi"], "Lambda": f["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P)}


@claim("h2-multipliers-TWIN", paper=("No", "neumann"), kind="id", sizes=SZ)
def multipliers_twin(s):
    """(false twin) Λ = XᵀAX + PᵀP."""
    f = s.multiplier_flow(Hn)
    return {"Lambda": f["Lambda"] - (s.X.T @ s.A @ s.X + s.P.T @ s.P)}


@claim("h2-psi-commutes-with-H", paper=("neumann", "momentum_right_map"), kind="pb", sizes=SZ)
def psi_commutes(s):
    """{tr(ζΨ), H_neum,κ} = 0 for every ζ."""
    z = s.fresh("r", "r")
    return {"pb": s.bracket(lambda t: t.tr(z @ t.Psi), Hn)}


@claim("h2-gram-commutes-with-H-TWIN", paper=("neumann",), kind="pb", sizes=SZ)
def gram_commutes(s):
    """(false twin) {tr(S PᵀP), H_neum,κ} = 0 for every S."""
    S = s.fresh("r", "r")
    return {"pb": s.bracket(lambda t: t.tr(S @ t.P.T @ t.P), Hn)}


@claim("h2-perelomov-cubic-conserved", paper=("perelomov", "No"), kind="id", sizes=SZ)
def perelomov_cubic(s):
    """tr L(λ)³ with L = λΦ + XXᵀ − λ²A is constant along (No) for every κ."""
    return {"d": s.d(lambda t: t.tr(Lneu(t, t.lam) @ Lneu(t, t.lam) @ Lneu(t, t.lam)), s.dirac_flow(Hn))}


@claim("h2-perelomov-cubic-conserved-TWIN", paper=("perelomov", "No"), kind="id", sizes=SZ)
def perelomov_cubic_twin(s):
    """(false twin) with +λ²A."""
    return {"d": s.d(lambda t: t.tr(Lneu_bad(t, t.lam) @ Lneu_bad(t, t.lam) @ Lneu_bad(t, t.lam)), s.dirac_flow(Hn))}


@claim("h2-perelomov-involution", paper=("perelomov", "spectral-curve"), kind="pb", sizes=SZ)
def perelomov_inv(s):
    """{tr L(λ)², tr L(μ)³} = 0."""
    mu = s.scalar("mu")
    return {"pb": s.bracket(lambda t: t.tr(Lneu(t, t.lam) @ Lneu(t, t.lam)),
                            lambda t: t.tr(Lneu(t, mu) @ Lneu(t, mu) @ Lneu(t, mu)))}


@claim("h2-perelomov-involution-TWIN", paper=("perelomov", "spectral-curve"), kind="pb", sizes=SZ)
def perelomov_inv_twin(s):
    """(false twin) {tr L(λ)², tr L̃(μ)³} = 0 with L̃ = μΦ + XXᵀ + μ²A."""
    mu = s.scalar("mu")
    return {"pb": s.bracket(lambda t: t.tr(Lneu(t, t.lam) @ Lneu(t, t.lam)),
                            lambda t: t.tr(Lneu_bad(t, mu) @ Lneu_bad(t, mu) @ Lneu_bad(t, mu)))}


@claim("h2-lax-scaled", paper=("LA1", "LA2"), kind="lax", sizes=SZ)
def lax_scaled(s):
    """Along (No), d/dt M = [Φ − λA, M] with M = Φ − λA + λ⁻¹XXᵀ."""
    lam = s.lam
    M = lambda t: t.Phi - lam * t.A + t.X @ t.X.T / lam
    return {"lax": s.d(M, s.dirac_flow(Hn)) - comm(s.Phi - lam * s.A, M(s))}


@claim("h2-lax-scaled-TWIN", paper=("LA1", "LA2"), kind="lax", sizes=SZ)
def lax_scaled_twin(s):
    """(false twin) d/dt M = [Φ + λA, M]."""
    lam = s.lam
    M = lambda t: t.Phi - lam * t.A + t.X @ t.X.T / lam
    return {"lax": s.d(M, s.dirac_flow(Hn)) - comm(s.Phi + lam * s.A, M(s))}


@claim("h2-potential-constant-r-n", paper="Neumann_potential", kind="id", sizes=admissible(n_max=4, r_is_n=True))
def pot_const(s):
    """For r = n the potential is constant: tr(XᵀAX) = tr A."""
    return {"V": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A)}


@claim("h2-uhlenbeck-n3", paper=("sphere_neum", "perelomov"), kind="id", sizes=[(3, 1)])
def uhlenbeck(s):
    """At (3,1), F₁ = x₁² + Σ_{j≠1}(x₁p_j − x_jp₁)²/(a₁ − a_j) is constant along (NE_XP)."""
    a = s.a
    def F(t):
        x = [t.X[i, 0] for i in range(3)]
        p = [t.P[i, 0] for i in range(3)]
        out = x[0] * x[0]
        for j in (1, 2):
            m = x[0] * p[j] - x[j] * p[0]
            out = out + m * m / (a[0] - a[j])
        return out
    return {"dF1": s.d(F, s.dirac_flow(HNE))}


@claim("h2-uhlenbeck-n3-TWIN", paper=("sphere_neum", "perelomov"), kind="id", sizes=[(3, 1)])
def uhlenbeck_twin(s):
    """(false twin) denominators a_j − a₁."""
    a = s.a
    def F(t):
        x = [t.X[i, 0] for i in range(3)]
        p = [t.P[i, 0] for i in range(3)]
        out = x[0] * x[0]
        for j in (1, 2):
            m = x[0] * p[j] - x[j] * p[0]
            out = out + m * m / (a[j] - a[0])
        return out
    return {"dF1": s.d(F, s.dirac_flow(HNE))}
