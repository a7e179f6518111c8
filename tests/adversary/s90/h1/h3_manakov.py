"""h3: Manakov flows (B = A²), own formulations, with false twins."""
from stiefelsym import admissible, block, claim, comm

SZ = admissible(n_max=4)


def Hm(t):
    """½⟨Φ, 𝔸Φ⟩ with 𝔸ξ = Aξ + ξA, written as −½tr(AΦ²)."""
    return -t.tr(t.A @ t.Phi @ t.Phi) / 2


def Mop(t):
    return t.A @ t.Phi + t.Phi @ t.A


@claim("h3-manakov-flow", paper=("Manakov*", "dot_XP3*"), kind="id", sizes=SZ)
def manakov_flow(s):
    """The Dirac flow of −½tr(AΦ²) is Ẋ = (AΦ + ΦA)X, Ṗ = (AΦ + ΦA)P."""
    f = s.dirac_flow(Hm)
    return {"Xdot": f["X"] - Mop(s) @ s.X, "Pdot": f["P"] - Mop(s) @ s.P}


@claim("h3-manakov-flow-TWIN", paper=("Manakov*", "dot_XP3*"), kind="id", sizes=SZ)
def manakov_flow_twin(s):
    """(false twin) Ẋ = (AΦ − ΦA)X."""
    f = s.dirac_flow(Hm)
    return {"Xdot": f["X"] - (s.A @ s.Phi - s.Phi @ s.A) @ s.X}


@claim("h3-manakov-lax", paper=("Manakov", "Manakov*"), kind="lax", sizes=SZ)
def manakov_lax(s):
    """Along (dot_XP3*), d/dt(Φ + λA) = [AΦ + ΦA + λA², Φ + λA]."""
    lam = s.lam
    L = lambda t: t.Phi + lam * t.A
    return {"lax": s.d(L, s.dirac_flow(Hm)) - comm(Mop(s) + lam * s.A @ s.A, L(s))}


@claim("h3-manakov-lax-TWIN", paper=("Manakov", "Manakov*"), kind="lax", sizes=SZ)
def manakov_lax_twin(s):
    """(false twin) d/dt L = [L, 𝔸(Φ) + λA²]."""
    lam = s.lam
    L = lambda t: t.Phi + lam * t.A
    return {"lax": s.d(L, s.dirac_flow(Hm)) - comm(L(s), Mop(s) + lam * s.A @ s.A)}


@claim("h3-manakov-integral-phi2a", paper="man", kind="id", sizes=SZ)
def manakov_int(s):
    """tr(Φ²A) (the λ-coefficient of tr(Φ + λA)³ / 3) is constant along (dot_XP3*)."""
    return {"d": s.d(lambda t: t.tr(t.Phi @ t.Phi @ t.A), s.dirac_flow(Hm))}


@claim("h3-manakov-integral-phi2a2-TWIN", paper="man", kind="id", sizes=SZ)
def manakov_int_twin(s):
    """(false twin) tr(Φ²A²) is constant along (dot_XP3*)."""
    return {"d": s.d(lambda t: t.tr(t.Phi @ t.Phi @ t.A @ t.A), s.dirac_flow(Hm))}


@claim("h3-shift-involution", paper="man", kind="pb", sizes=SZ)
def shift_inv(s):
    """{tr(Φ + λA)², tr(Φ + μA)³} = 0."""
    lam, mu = s.lam, s.scalar("mu")
    f = lambda t: t.tr((t.Phi + lam * t.A) @ (t.Phi + lam * t.A))
    g = lambda t: t.tr((t.Phi + mu * t.A) @ (t.Phi + mu * t.A) @ (t.Phi + mu * t.A))
    return {"pb": s.bracket(f, g)}


@claim("h3-shift-involution-TWIN", paper="man", kind="pb", sizes=SZ)
def shift_inv_twin(s):
    """(false twin) {tr(Φ²A), tr(Φ²A²)} = 0."""
    return {"pb": s.bracket(lambda t: t.tr(t.Phi @ t.Phi @ t.A), lambda t: t.tr(t.Phi @ t.Phi @ t.A @ t.A))}


def Lstar(t, lam):
    R = t.resolvent(lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [P.T @ R @ P, P.T @ R @ X]])


def Astar(t, lam, S):
    X, P = t.X, t.P
    return block([[X.T @ S @ P, X.T @ S @ X], [-(P.T @ S @ P), -(P.T @ S @ X)]])


@claim("h3-man-la-as-printed", paper=("MAN-LA", "MAN-LA2", "LA-MAN3"), kind="lax", sizes=SZ)
def man_la_printed(s):
    """(MAN-LA) as printed: d/dt L* = [L*, A*] with (A + λI)⁻¹ in A*."""
    lam = s.lam
    S = -s.resolvent(-lam)
    return {"lax": s.d(lambda t: Lstar(t, lam), s.dirac_flow(Hm)) - comm(Lstar(s, lam), Astar(s, lam, S))}


@claim("h3-man-la-with-A-plus-lambda", paper=("MAN-LA", "MAN-LA2", "LA-MAN3"), kind="lax", sizes=SZ)
def man_la_corr(s):
    """(MAN-LA) with A + λI in place of (A + λI)⁻¹ in A*."""
    lam = s.lam
    S = s.A + lam * s.In
    return {"lax": s.d(lambda t: Lstar(t, lam), s.dirac_flow(Hm)) - comm(Lstar(s, lam), Astar(s, lam, S))}
