"""h6: the dual Lax pair of the Neumann systems, own formulations, with false twins."""
from stiefelsym import admissible, block, claim, comm

SZ = admissible(n_max=4)


def HNE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def HN0(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def Ls(t, lam, with_identity=True):
    R = t.resolvent(lam)
    X, P = t.X, t.P
    low = P.T @ R @ P + (t.Ir if with_identity else 0 * t.Ir)
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [low, P.T @ R @ X]])


def sq(M):
    return M @ M


@claim("h6-dual-trace-square-conserved", paper=("LA3", "LA4", "NE_XP"), kind="id", sizes=SZ)
def trsq(s):
    """tr L*(λ)² and tr L*(λ)⁴ are constant along (NE_XP)."""
    lam = s.lam
    f = s.dirac_flow(HNE)
    return {"d tr L²": s.d(lambda t: t.tr(sq(Ls(t, lam))), f),
            "d tr L⁴": s.d(lambda t: t.tr(sq(sq(Ls(t, lam)))), f)}


@claim("h6-dual-trace-square-no-identity-TWIN", paper=("LA3", "LA4", "NE_XP"), kind="id", sizes=SZ)
def trsq_twin(s):
    """(false twin) the same without I_r in the lower-left block."""
    lam = s.lam
    return {"d tr L²": s.d(lambda t: t.tr(sq(Ls(t, lam, False))), s.dirac_flow(HNE))}


@claim("h6-dual-lax-normal", paper=("DUAL", "LA3", "LA4", "N0_XP2"), kind="lax", sizes=SZ)
def dual_n0(s):
    """Along (N0_XP2), d/dt L* = [L*, A*] with A* = ((XᵀP, I), (Λ − λI, −PᵀX)), Λ = XᵀAX − PᵀP."""
    lam = s.lam
    X, P = s.X, s.P
    Lam = X.T @ s.A @ X - P.T @ P
    As = block([[X.T @ P, s.Ir], [Lam - lam * s.Ir, -(P.T @ X)]])
    return {"lax": s.d(lambda t: Ls(t, lam), s.dirac_flow(HN0)) - comm(Ls(s, lam), As)}


@claim("h6-dual-lax-normal-TWIN", paper=("DUAL", "LA3", "LA4", "N0_XP2"), kind="lax", sizes=SZ)
def dual_n0_twin(s):
    """(false twin) d/dt L* = [A*, L*]."""
    lam = s.lam
    X, P = s.X, s.P
    Lam = X.T @ s.A @ X - P.T @ P
    As = block([[X.T @ P, s.Ir], [Lam - lam * s.Ir, -(P.T @ X)]])
    return {"lax": s.d(lambda t: Ls(t, lam), s.dirac_flow(HN0)) - comm(As, Ls(s, lam))}


@claim("h6-odd-traces-vanish", paper="2r-integrals", kind="id", sizes=SZ)
def odd(s):
    """tr L*(λ) = tr L*(λ)³ = 0 on T*V (odd powers of w drop out of the spectral curve)."""
    L = Ls(s, s.lam)
    return {"tr L": s.tr(L), "tr L³": s.tr(L @ L @ L)}


@claim("h6-even-trace-vanishes-TWIN", paper="2r-integrals", kind="id", sizes=SZ)
def even_twin(s):
    """(false twin) tr L*(λ)² = 0."""
    L = Ls(s, s.lam)
    return {"tr L²": s.tr(L @ L)}
