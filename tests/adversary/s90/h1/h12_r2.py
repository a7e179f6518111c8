"""h12: statements true only at r = 2 (so(2) is one-dimensional), stated at r = 2 and wrongly beyond."""
from stiefelsym import admissible, claim, comm


@claim("h12-psi-square-r2", paper="momentum_right_map", kind="id", sizes=admissible(n_max=4, r_min=2, r_max=2))
def psi_sq(s):
    """At r = 2, Ψ² = ½tr(Ψ²) I₂."""
    return {"psi2": s.Psi @ s.Psi - s.tr(s.Psi @ s.Psi) / 2 * s.Ir}


@claim("h12-psi-square-r2-TWIN", paper="momentum_right_map", kind="id", sizes=admissible(n_max=4, r_min=2, r_max=2))
def psi_sq_twin(s):
    """(false twin) At r = 2, Ψ² = tr(Ψ²) I₂."""
    return {"psi2": s.Psi @ s.Psi - s.tr(s.Psi @ s.Psi) * s.Ir}


@claim("h12-psi-square-r-ge-2-WRONGRANGE", paper="momentum_right_map", kind="id", sizes=admissible(n_max=4, r_min=2))
def psi_sq_range(s):
    """(false for r ≥ 3) For r ≥ 2, Ψ² = ½tr(Ψ²) I_r."""
    return {"psi2": s.Psi @ s.Psi - s.tr(s.Psi @ s.Psi) / 2 * s.Ir}


@claim("h12-psi-commutes-gram-r2", paper=("SO(n)-inv",), kind="id", sizes=admissible(n_max=4, r_min=2, r_max=2))
def psi_eta_comm(s):
    """At r = 2, Ψ commutes with every skew η: [Ψ, η] = 0."""
    return {"c": comm(s.Psi, s.eta)}


@claim("h12-psi-commutes-eta-all-r-WRONG", paper=("SO(n)-inv",), kind="id", sizes=admissible(n_max=4))
def psi_eta_all(s):
    """(false for r ≥ 3) [Ψ, η] = 0 for every skew η."""
    return {"c": comm(s.Psi, s.eta)}
