"""The family r = 1 under the dimension-free method: an identity true at n <= 2 only, and a true one."""
from stiefelsym import admissible, claim


@claim("s76-r1-n2-only", kind="id", sizes=admissible(n_max=4, r_max=1))
def r1_n2_only(s):
    """|P|² XXᵀ + PPᵀ = |P|² I: true at n <= 2 (X, P/|P| span R²), FALSE at n >= 3."""
    p2 = s.tr(s.P.T @ s.P)
    return {"r": p2 * (s.X @ s.X.T) + s.P @ s.P.T - p2 * s.In}


@claim("s76-r1-phi-cubed", kind="id", sizes=admissible(n_max=4, r_max=1))
def r1_phi_cubed(s):
    """Φ³ = −|P|² Φ at r = 1 (true for every n)."""
    return {"r": s.Phi @ s.Phi @ s.Phi + s.tr(s.P.T @ s.P) * s.Phi}


@claim("s76-r1-phi-cubed-twin", kind="id", sizes=admissible(n_max=4, r_max=1))
def r1_phi_cubed_twin(s):
    """FALSE: Φ³ = −2|P|² Φ at r = 1 (true only where P = 0, n = 1)."""
    return {"r": s.Phi @ s.Phi @ s.Phi + 2 * s.tr(s.P.T @ s.P) * s.Phi}
