"""h3 hidden statements, §2: Ψ and XᵀP on T*V (a consequence of (cond_XP)), and XᵀΦX = Ψ."""
from stiefelsym import admissible, claim


@claim("h3-psi-from-xtp", kind="id", section="2", sizes=admissible(5))
def psi_from_xtp(s):
    """(cond_XP): PᵀX = −XᵀP, so Ψ = XᵀP − PᵀX = 2XᵀP; and XᵀΦX = XᵀPXᵀX − XᵀXPᵀX = XᵀP − PᵀX = Ψ."""
    return {"Psi = 2 X^T P": s.Psi - 2 * s.X.T @ s.P, "X^T Phi X = Psi": s.X.T @ s.Phi @ s.X - s.Psi}


@claim("h3-psi-from-xtp-twin", kind="id", section="2", sizes=admissible(5, r_min=2, condition="r >= 2"))
def psi_from_xtp_twin(s):
    """FALSE twin (r ≥ 2; at r = 1 XᵀP = 0): Ψ = 2PᵀX (transpose), i.e. Ψ = −Ψ."""
    return {"Psi = 2 P^T X": s.Psi - 2 * s.P.T @ s.X, "X^T Phi X = Psi": s.X.T @ s.Phi @ s.X - s.Psi}


@claim("h3-xphix-twin", kind="id", section="2", sizes=admissible(5, r_min=2, condition="r >= 2"))
def xphix_twin(s):
    """FALSE twin (r ≥ 2): XᵀΦX = −Ψ (sign)."""
    return {"Psi = 2 X^T P": s.Psi - 2 * s.X.T @ s.P, "X^T Phi X = -Psi": s.X.T @ s.Phi @ s.X + s.Psi}
