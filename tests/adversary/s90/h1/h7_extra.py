# ruff: noqa: F401
"""h7: further reformulations (multipliers of another spelling, CPB Hamiltonian, Casimir-like brackets,
Noether integrals of the Manakov flow, r = 1 / r >= 2 statements, 'not' claims)."""
from stiefelsym import admissible, claim, comm

SZ = admissible(n_max=4)


def H0pot(t):
    """H_neum0 written as ½⟨Φ, Φ⟩ + ½tr XᵀAX (equal to (N0_XP2)'s H on T*V, different off it)."""
    return t.killing(t.Phi, t.Phi) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def HN0(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def Hm(t):
    return -t.tr(t.A @ t.Phi @ t.Phi) / 2


def HNE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("h7-killing-spelling-same-flow", paper=("N0_XP2", "normal_metric"), kind="id", sizes=SZ)
def same_flow(s):
    """½⟨Φ,Φ⟩ + ½tr XᵀAX and (N0_XP2)'s Hamiltonian have the same Dirac flow."""
    f, g = s.dirac_flow(H0pot), s.dirac_flow(HN0)
    return {"X": f["X"] - g["X"], "P": f["P"] - g["P"]}


@claim("h7-killing-spelling-multipliers-TWIN", paper=("N0_XP2",), kind="id", sizes=SZ)
def killing_mult(s):
    """(false twin) With H written ½⟨Φ,Φ⟩ + ½tr XᵀAX: Π = XᵀP."""
    f = s.multiplier_flow(H0pot)
    return {"Pi": f["Pi"] - s.X.T @ s.P}


@claim("h7-cpb-hamiltonian", paper=("CPB", "N0_XP2"), kind="id", sizes=SZ)
def cpb_h(s):
    """H_neum0 = ½⟨h, h⟩ − ⟨A, v⟩ at h = Φ, v = XXᵀ."""
    return {"H": HN0(s) - (s.killing(s.Phi, s.Phi) / 2 - s.killing(s.A, s.X @ s.X.T))}


@claim("h7-cpb-hamiltonian-TWIN", paper=("CPB", "N0_XP2"), kind="id", sizes=SZ)
def cpb_h_twin(s):
    """(false twin) + ⟨A, v⟩."""
    return {"H": HN0(s) - (s.killing(s.Phi, s.Phi) / 2 + s.killing(s.A, s.X @ s.X.T))}


@claim("h7-psi2-gram", paper=("momentum_right_map", "SO(n)-inv"), kind="pb", sizes=SZ)
def psi2_gram(s):
    """{tr Ψ², tr PᵀP} = 0 and {tr Ψ², ⟨Φ, ξ⟩} = 0."""
    xi = s.xi
    return {"a": s.bracket(lambda t: t.tr(t.Psi @ t.Psi), lambda t: t.tr(t.P.T @ t.P)),
            "b": s.bracket(lambda t: t.tr(t.Psi @ t.Psi), lambda t: t.killing(t.Phi, xi))}


@claim("h7-psi2-gram-S-TWIN", paper=("momentum_right_map", "SO(n)-inv"), kind="pb", sizes=SZ)
def psi2_gram_twin(s):
    """(false twin) {tr Ψ², tr(S PᵀP)} = 0 for every S."""
    S = s.fresh("r", "r")
    return {"a": s.bracket(lambda t: t.tr(t.Psi @ t.Psi), lambda t: t.tr(S @ t.P.T @ t.P))}


@claim("h7-manakov-noether", paper=("man", "SO(n)-inv"), kind="id", sizes=SZ)
def man_noether(s):
    """The SO(n)-invariants PᵀP and Ψ are constant along (dot_XP3*)."""
    f = s.dirac_flow(Hm)
    return {"Gram": s.d(lambda t: t.P.T @ t.P, f), "Psi": s.d(lambda t: t.Psi, f)}


@claim("h7-manakov-noether-TWIN", paper=("man", "SO(n)-inv"), kind="id", sizes=SZ)
def man_noether_twin(s):
    """(false twin) XᵀAX is constant along (dot_XP3*)."""
    return {"XtAX": s.d(lambda t: t.X.T @ t.A @ t.X, s.dirac_flow(Hm))}


@claim("h7-xtp-zero-r1", paper="cond_XP", kind="id", sizes=admissible(n_max=4, r_min=1, r_max=1))
def xtp_r1(s):
    """At r = 1, XᵀP = 0 on T*V."""
    return {"XtP": s.X.T @ s.P}


@claim("h7-xtp-nonzero-r2", paper="cond_XP", kind="not", expect="nonzero", sizes=admissible(n_max=4, r_min=2))
def xtp_r2(s):
    """For r ≥ 2, XᵀP does not vanish identically on T*V."""
    return {"XtP": s.X.T @ s.P}


@claim("h7-psi-not-conserved-WRONG", paper=("neumann", "momentum_right_map"), kind="not", expect="nonzero", sizes=SZ)
def psi_not_cons(s):
    """(false 'not' statement) Ψ is not conserved by (NE_XP)."""
    return {"dPsi": s.d(lambda t: t.Psi, s.dirac_flow(HNE))}


@claim("h7-gram-not-conserved-euclid-neumann", paper=("NE_XP",), kind="not", expect="nonzero", sizes=admissible(n_max=4, r_min=2))
def gram_not(s):
    """For r ≥ 2, tr(PᵀP) is not conserved by (NE_XP) (the potential exchanges energy)."""
    return {"d": s.d(lambda t: t.tr(t.P.T @ t.P), s.dirac_flow(HNE))}


@claim("h7-killing-spelling-pi-zero", paper=("N0_XP2",), kind="id", sizes=SZ)
def killing_pi0(s):
    """With H written ½⟨Φ,Φ⟩ + ½tr XᵀAX the multiplier Π is 0."""
    return {"Pi": s.multiplier_flow(H0pot)["Pi"]}
