"""h2 probe (adversarial): a claim that catches the KeyError of the free at_point scene's multiplier_flow.

p2-catch-keyerror (FALSE for n >= 2): at twisted.at_point(s, X, P), Λ = XᵀAX + PᵀP (true Λ = XᵀAX − PᵀP);
  where the flow has no 'Lambda' the claim returns Ẋ − P instead (0: a vacuous residual).
"""
from stiefelsym import admissible, claim, twisted


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("p2-catch-keyerror", kind="id", section="2", sizes=admissible(n_max=3))
def catch(s):
    """FALSE: Λ = XᵀAX + PᵀP at the at_point scene (a KeyError caught)."""
    h = twisted.at_point(s, s.X, s.P)
    m = h.multiplier_flow(H_E)
    try:
        return {"Lambda": m["Lambda"] - (h.X.T @ h.A @ h.X + h.P.T @ h.P)}
    except KeyError:
        return {"Lambda": m.Xdot - h.P}
