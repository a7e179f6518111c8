"""h2 probe: the multipliers of a flow at a point of the claim's own (twisted.at_point) under the free method.

p2-atpoint-multipliers (TRUE): at the scene's own point, re-entered by twisted.at_point(s, X, P), the Lagrange
  multipliers of ½tr PᵀP + ½tr XᵀAX are Π = 0, Λ = XᵀAX − PᵀP.
p2-atpoint-multipliers-twin (FALSE for n >= 1 with P != 0 or ...): Λ = XᵀAX + PᵀP.
p2-own-multipliers (TRUE): the same at the scene itself (no at_point).
"""
from stiefelsym import admissible, claim, twisted


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("p2-atpoint-multipliers", kind="id", section="2", sizes=admissible(n_max=3))
def atpoint(s):
    """At twisted.at_point(s, X, P): Π = 0, Λ = XᵀAX − PᵀP."""
    h = twisted.at_point(s, s.X, s.P)
    m = h.multiplier_flow(H_E)
    return {"Pi": m["Pi"], "Lambda": m["Lambda"] - (h.X.T @ h.A @ h.X - h.P.T @ h.P)}


@claim("p2-atpoint-multipliers-twin", kind="id", section="2", sizes=admissible(n_max=3))
def atpoint_twin(s):
    """FALSE: Λ = XᵀAX + PᵀP."""
    h = twisted.at_point(s, s.X, s.P)
    m = h.multiplier_flow(H_E)
    return {"Lambda": m["Lambda"] - (h.X.T @ h.A @ h.X + h.P.T @ h.P)}


@claim("p2-own-multipliers", kind="id", section="2", sizes=admissible(n_max=3))
def own(s):
    """At the scene: Π = 0, Λ = XᵀAX − PᵀP."""
    m = s.multiplier_flow(H_E)
    return {"Pi": m["Pi"], "Lambda": m["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P)}
