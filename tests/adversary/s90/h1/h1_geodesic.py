"""h1: geodesic flows (Euclidean, normal, Jensen), own formulations, with false twins."""
from stiefelsym import admissible, claim, comm

SZ = admissible(n_max=4)


def HE(t):
    return t.tr(t.P.T @ t.P) / 2


def H0(t):
    return t.killing(t.Phi, t.Phi) / 2


def Hk(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


@claim("h1-euclid-xtp-conserved", paper="Euclidean_XP", kind="id", sizes=SZ)
def euclid_xtp(s):
    """Along the Euclidean geodesic flow the r×r matrix XᵀP is constant."""
    return {"d(XᵀP)": s.d(lambda t: t.X.T @ t.P, s.dirac_flow(HE))}


@claim("h1-euclid-gram-conserved-TWIN", paper="Euclidean_XP", kind="id", sizes=SZ)
def euclid_gram(s):
    """(false twin) Along the Euclidean geodesic flow PᵀP is constant."""
    return {"d(PᵀP)": s.d(lambda t: t.P.T @ t.P, s.dirac_flow(HE))}


@claim("h1-normal-gram-conserved", paper=("normal_metric", "SO(n)-inv"), kind="id", sizes=SZ)
def normal_gram(s):
    """Along the normal geodesic flow both PᵀP and XᵀP are constant."""
    f = s.dirac_flow(H0)
    return {"d(PᵀP)": s.d(lambda t: t.P.T @ t.P, f), "d(XᵀP)": s.d(lambda t: t.X.T @ t.P, f)}


@claim("h1-normal-xxt-conserved-TWIN", paper="normal_metric", kind="id", sizes=SZ)
def normal_xxt(s):
    """(false twin) Along the normal geodesic flow XXᵀ is constant."""
    return {"d(XXᵀ)": s.d(lambda t: t.X @ t.X.T, s.dirac_flow(H0))}


@claim("h1-jensen-xxt", paper=("EM", "prep"), kind="id", sizes=SZ)
def jensen_xxt(s):
    """Along the Jensen geodesic flow of H_κ, d(XXᵀ)/dt = [Φ, XXᵀ] for every κ."""
    G = s.X @ s.X.T
    return {"d(XXᵀ)": s.d(lambda t: t.X @ t.X.T, s.dirac_flow(Hk)) - comm(s.Phi, G)}


@claim("h1-jensen-xxt-TWIN", paper=("EM", "prep"), kind="id", sizes=SZ)
def jensen_xxt_twin(s):
    """(false twin) d(XXᵀ)/dt = [XXᵀ, Φ] along H_κ."""
    G = s.X @ s.X.T
    return {"d(XXᵀ)": s.d(lambda t: t.X @ t.X.T, s.dirac_flow(Hk)) - comm(G, s.Phi)}


@claim("h1-jensen-left-right", paper="EM", kind="id", sizes=SZ)
def jensen_left_right(s):
    """The Jensen flow is Ẋ = ΦX + κXΨ, Ṗ = ΦP + κPΨ."""
    f = s.dirac_flow(Hk)
    return {"Xdot": f["X"] - (s.Phi @ s.X + s.kappa * s.X @ s.Psi),
            "Pdot": f["P"] - (s.Phi @ s.P + s.kappa * s.P @ s.Psi)}


@claim("h1-jensen-left-right-TWIN", paper="EM", kind="id", sizes=SZ)
def jensen_left_right_twin(s):
    """(false twin) Ẋ = ΦX − κXΨ."""
    f = s.dirac_flow(Hk)
    return {"Xdot": f["X"] - (s.Phi @ s.X - s.kappa * s.X @ s.Psi)}


@claim("h1-normal-energy-velocity", paper=("normal_metric_lagrangian", "dot_X3"), kind="id", sizes=SZ)
def normal_energy(s):
    """With Ẋ the normal flow's velocity, H_0 = ½tr ẊᵀẊ + ¼tr((XᵀẊ)²)."""
    V = s.dirac_flow(H0)["X"]
    W = s.X.T @ V
    return {"H0": H0(s) - (s.tr(V.T @ V) / 2 + s.tr(W @ W) / 4)}


@claim("h1-normal-energy-velocity-TWIN", paper=("normal_metric_lagrangian", "dot_X3"), kind="id", sizes=SZ)
def normal_energy_twin(s):
    """(false twin) H_0 = ½tr ẊᵀẊ − ¼tr((XᵀẊ)²)."""
    V = s.dirac_flow(H0)["X"]
    W = s.X.T @ V
    return {"H0": H0(s) - (s.tr(V.T @ V) / 2 - s.tr(W @ W) / 4)}
