"""h2 (stop 85), third file: §5 at r = n (truth: indep_c.py, indep_c_output.txt).

h2-rn-velocity (TRUE, r = n): along (No) on T*V(n, n) = T*O(n), Ẋ = (1 + κ)ΦX and dΦ/dt = 0 (the potential is
  constant for r = n, the Neumann flow is the geodesic flow of the bi-invariant-plus-κ metric).  By hand:
  Ẋ = P − (1+2κ)XPᵀX = ΦX − 2κXPᵀX = ΦX + κXΨ for every r, and XΨ = XXᵀΦX = ΦX at r = n.
h2-rn-velocity-twin (FALSE at r = n ≥ 2): (1 + 2κ)ΦX.
h2-velocity-all-r (TRUE, every r): Ẋ = ΦX + κXΨ along (No).
h2-rn-velocity-all-r-twin (FALSE for r < n): the r = n identity Ẋ = (1 + κ)ΦX stated for every n, r.
"""
from stiefelsym import admissible, claim


def H_neum(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


RN = admissible(n_max=5, r_is_n=True, condition="r = n")


@claim("h2-rn-velocity", kind="id", section="5", sizes=RN)
def rn_velocity(s):
    """r = n: Ẋ = (1 + κ)ΦX and dΦ/dt = 0 along (No)."""
    f = s.dirac_flow(H_neum)
    return {"Xdot": f.Xdot - (1 + s.kappa) * s.Phi @ s.X, "dPhi/dt": s.d(lambda t: t.Phi, f)}


@claim("h2-rn-velocity-twin", kind="id", section="5", sizes=RN)
def rn_velocity_twin(s):
    """FALSE: (1 + 2κ)ΦX."""
    f = s.dirac_flow(H_neum)
    return {"Xdot": f.Xdot - (1 + 2 * s.kappa) * s.Phi @ s.X}


@claim("h2-velocity-all-r", kind="id", section="5", sizes=admissible(n_max=5))
def velocity_all_r(s):
    """Ẋ = ΦX + κXΨ along (No)."""
    f = s.dirac_flow(H_neum)
    return {"Xdot": f.Xdot - (s.Phi @ s.X + s.kappa * s.X @ s.Psi)}


@claim("h2-rn-velocity-all-r-twin", kind="id", section="5", sizes=admissible(n_max=5))
def rn_velocity_all_r_twin(s):
    """FALSE for r < n: Ẋ = (1 + κ)ΦX for every r."""
    f = s.dirac_flow(H_neum)
    return {"Xdot": f.Xdot - (1 + s.kappa) * s.Phi @ s.X}
