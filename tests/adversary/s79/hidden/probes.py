import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stiefelsym import admissible, claim
from stiefelsym import twisted
from _h79_helpers import H_neum_k, flow_No
from stiefelsym.systems import derivative

@claim("p79-mag-force-all-r", kind="id", sizes=admissible(n_max=4, n_min=2, r_min=2))
def p(s):
    """The r = 2 magnetic force identity stated for every r >= 2 (magnetic_matrix exists at r = 2 only)."""
    flow = twisted.flow(s, H_neum_k)
    plain = flow_No(s, s.kappa)
    J = twisted.magnetic_matrix(s)
    force = -s.eps * ((s.In - s.X @ s.X.T) @ s.P @ J)
    return {"dX/dt": flow.Xdot - plain["X"], "dP/dt": flow.Pdot - (plain["P"] + force)}

@claim("p79-mag-force-eta-all-r", kind="id", sizes=admissible(n_max=4, n_min=2, r_min=2))
def q(s):
    """With F = eta (generic so(r)): twisted flow of H_neum,kappa = (No) + (0, -eps (I - XX^T) P eta): numpy true at r = 2, FALSE at r = 3 (kappa-dependent)."""
    flow = twisted.flow(s, H_neum_k, F=s.eta)
    plain = flow_No(s, s.kappa)
    force = -s.eps * ((s.In - s.X @ s.X.T) @ s.P @ s.eta)
    return {"dX/dt": flow.Xdot - plain["X"], "dP/dt": flow.Pdot - (plain["P"] + force)}



S = admissible(n_max=4, n_min=2)

@claim("p79-deriv-nontangent-false", kind="id", sizes=S)
def a(s):
    """FALSE: d/de (tr e^T e) along a generic (non-tangent) G vanishes (it is 2 tr(X^T G))."""
    G = s.generic("G", "n", "r")
    return {"d|e|^2": derivative(s, lambda t, w: t.tr(w["e"].T @ w["e"]), {"e": s.X}, {"e": G})}

@claim("p79-deriv-tangent-true", kind="id", sizes=S)
def b(s):
    """TRUE: along xi X (tangent), d/de (e^T e) = 0."""
    return {"d e^T e": derivative(s, lambda t, w: w["e"].T @ w["e"], {"e": s.X}, {"e": s.xi @ s.X})}

@claim("p79-deriv-second-order-false", kind="id", sizes=S)
def c(s):
    """FALSE: the derivative of (e^T e)(e^T e) - e^T e along G vanishes (on the sphere e^T e = I, but the derivative is 2 sym(X^T G))."""
    G = s.generic("G", "n", "r")
    f = lambda t, w: (w["e"].T @ w["e"]) @ (w["e"].T @ w["e"]) - w["e"].T @ w["e"]
    return {"d": derivative(s, f, {"e": s.X}, {"e": G})}

@claim("p79-deriv-own-point-scene-constant-true", kind="id", sizes=S)
def d(s):
    """TRUE (my first reading was wrong): t.X is the scene's X, a constant of the derivative at a point of my own, so the two terms cancel."""
    G = s.generic("G", "n", "r")
    return {"d": derivative(s, lambda t, w: t.tr(w["e"].T @ w["e"]) - t.tr(t.X.T @ w["e"]) * 2, {"e": s.X}, {"e": G})}
