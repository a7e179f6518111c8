"""Divisions by expressions that vanish on T*V (or at the random points modulo a prime): the error names the
division; the verdicts must stay those of the claim (an error or a refusal, never a pass or a fail), the text
must be escaped in the reports, and a long expression is capped."""
from stiefelsym import claim


@claim("r2-div-trace", kind="id", sizes=[(3, 2)])
def div_trace(s):
    """XᵀAX·(tr XᵀX − r)⁻¹ = 0 (undefined on T*V)."""
    return {"w": s.X.T @ s.A @ s.X / (s.tr(s.X.T @ s.X) - s.r)}


@claim("r2-div-long", kind="id", sizes=[(3, 2)])
def div_long(s):
    """A division by a long expression that vanishes on T*V: undefined."""
    M = s.X.T @ s.P + s.P.T @ s.X
    for _ in range(12):
        M = M @ (s.X.T @ s.A @ s.X) + (s.X.T @ s.A @ s.X) @ M
    return {"w": s.X.T @ s.X / (s.tr(M @ M.T) + s.tr(s.X.T @ s.X) - s.r)}


@claim("r2-div-inverse", kind="id", sizes=[(3, 2)])
def div_inverse(s):
    """(XᵀP + PᵀX)⁻¹ = 0 (undefined on T*V)."""
    return {"w": s.inv(s.X.T @ s.P + s.P.T @ s.X)}
