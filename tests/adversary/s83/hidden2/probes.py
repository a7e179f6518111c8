"""Probes: which residual of h4-mag-multipliers the float method cannot resolve; natural rewritings."""
from stiefelsym import claim, twisted
from _h4common import ANY, H_E


@claim("h4p-pi-alone", kind="id", sizes=ANY)
def pi_alone(s):
    """Π = 0 for the twisted Euclidean flow (F = η)."""
    return {"Pi": twisted.multiplier_flow(s, H_E, F=s.eta)["Pi"]}


@claim("h4p-pi-alone-untwisted", kind="id", sizes=ANY)
def pi_alone_untwisted(s):
    """Π = 0 for the untwisted Euclidean Dirac flow (s.multiplier_flow)."""
    return {"Pi": s.multiplier_flow(H_E)["Pi"]}


@claim("h4p-xdot-tangent", kind="id", sizes=ANY)
def xdot_minus_p(s):
    """Ẋ − P = −XΠ = 0 (the same statement through Ẋ)."""
    return {"Xdot": twisted.multiplier_flow(s, H_E, F=s.eta).Xdot - s.P}
