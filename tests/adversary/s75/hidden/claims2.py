# ruff: noqa
"""s75 hidden round, second file: one more statement (r = 1) and its false twin (kept apart so that the runs of
claims.py and negatives.py already under way read unchanged files)."""
from stiefelsym import admissible, claim

R_IS_1 = admissible(n_max=5, r_max=1, condition="r = 1 (T*S^{n−1})")


def _theta_parts(s):
    h, v = s.Phi, s.X @ s.X.T
    return h, v


@claim("h75-theta-r1-orbit-relations", paper=("CPB", "LAMBDA12", "sphere_neum"), kind="id", sizes=R_IS_1)
def theta_r1_orbit_relations(s):
    """§6, remark after Theorem NEUMANN (the Neumann system on the sphere as a system on an orbit, Ratiu):
    at r = 1 the image Θ(e, p) = h + v, h = p ∧ e, v = e ⊗ e, lies on {v² = v, tr v = 1, vhv = 0, h = hv + vh}
    (for r ≥ 2, h − hv − vh = −XΨXᵀ does not vanish)."""
    h, v = _theta_parts(s)
    return {"v^2 - v": v @ v - v, "tr v - 1": s.tr(v) - 1, "v h v": v @ h @ v, "h - hv - vh": h - h @ v - v @ h}


@claim("n75-theta-r1-wrong-sign", kind="id", sizes=R_IS_1, fails_at=lambda n, r: n >= 2,
       erratum="twin: h = hv − vh (true only at n = 1, where h = 0)")
def theta_r1_wrong_sign(s):
    """False twin of h75-theta-r1-orbit-relations: h = hv − vh."""
    h, v = _theta_parts(s)
    return {"h - hv + vh": h - h @ v + v @ h}
