"""A misprint whose one-step corrections hold at the default sizes (n <= 3) but not for every n:
Φ³ = −½ tr(Φ²) Φ (FALSE); Φ³ = ½ tr(Φ²) Φ holds where rank Φ <= 2 (r = 1 or n <= 3), FALSE at (4,2)."""
from stiefelsym import admissible, claim


@claim("s75-corr-phi-cubic", kind="id", sizes=admissible(n_max=3),
       fails_at=lambda n, r: True, erratum="the sign of the trace term")
def corr_phi_cubic(s):
    """Φ³ = −½ tr(Φ²) Φ."""
    F2 = s.Phi @ s.Phi
    return {"w": F2 @ s.Phi + s.Phi * s.tr(F2) / 2}
