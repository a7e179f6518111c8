"""s86h2 variants (to see whether the free method's refusals of claims.py are about the form):

 s86h2v-jensen-accel-printed (TRUE): as s86h2-jensen-accel, with the velocity written out, Ẋ = P − (1 + 2κ)XPᵀX,
   differentiated along the derived flow of H_κ.
"""
from stiefelsym import admissible, claim

ANY = admissible(n_max=5)


def H_jensen(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


@claim("s86h2v-jensen-accel-printed", kind="id", section="3", sizes=ANY)
def jensen_accel_printed(s):
    """Ẍ = Φ²X + 2κΦXΨ + κ²XΨ², Ẋ = P − (1+2κ)XPᵀX differentiated along the H_κ flow (TRUE)."""
    f = s.dirac_flow(H_jensen)
    k = s.kappa
    vel = lambda t: t.P - (1 + 2 * t.kappa) * t.X @ t.P.T @ t.X
    Phi, Psi, X = s.Phi, s.Psi, s.X
    return {"Xdot": f.Xdot - vel(s),
            "Xddot": s.d(vel, f) - (Phi @ Phi @ X + 2 * k * Phi @ X @ Psi + k * k * X @ Psi @ Psi)}
