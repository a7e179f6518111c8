"""A function handed to the scene (a Hamiltonian for s.gradient, for the scene at another point) that
closes over a value of the enclosing scene (its P).  The free scene's letters X, P are shared by every
scene, so the captured P is taken for the function's own variable P: its gradient in P is X, and at
another point (-X, -P) the captured P is substituted by -P.  Read as the function of u it is, with P a
fixed matrix, grad_P tr(P^T u.X) = 0 and grad_X = P at every point.  The fixed-size methods do not
evaluate such a function (they stop with an error), so the free method is alone in deciding it."""
from stiefelsym import admissible, claim
from stiefelsym import twisted

ALL = admissible(n_max=4, n_min=2)


@claim("adv-captured-grad", kind="id", sizes=ALL, statement="grad_P tr(P^T u.X) = X, P the base point's")
def captured_grad(s):
    """False for the captured P as a constant (grad_P = 0)."""
    gX, gP = s.gradient(lambda u: u.tr(s.P.T @ u.X))
    return {"r": gP - s.X}


@claim("adv-captured-at-point", kind="id", sizes=ALL,
       statement="at (-X, -P), grad_X tr(P^T u.X) = -P, P the base point's")
def captured_at_point(s):
    """False for the captured P as a constant (grad_X = P at every point)."""
    t = twisted.at_point(s, -s.X, -s.P)
    gX, _gP = t.gradient(lambda u: u.tr(s.P.T @ u.X))
    return {"r": gX + s.P}


@claim("adv-captured-point-value", kind="id", sizes=ALL,
       statement="at (-X, -P), grad_X tr(t.P^T u.X) = P, t.P = -P the point's momentum")
def captured_point_value(s):
    """False under either reading: t.P = -P as a fixed matrix gives grad_X = -P; as the point scene's own
    variable (the function tr(u.P^T u.X) at the point) it gives the point's P, -P as well."""
    t = twisted.at_point(s, -s.X, -s.P)
    gX, _gP = t.gradient(lambda u: u.tr(t.P.T @ u.X))
    return {"r": gX - s.P}


@claim("adv-captured-scalar", kind="id", sizes=ALL,
       statement="grad_P of c tr(u.X^T A u.X), c = tr(P^T P) of the base point, is 2 tr(X^T A X) P")
def captured_scalar(s):
    """False for c the number it is (the function does not depend on u.P: grad_P = 0)."""
    c = s.tr(s.P.T @ s.P)
    _gX, gP = s.gradient(lambda u: c * u.tr(u.X.T @ u.A @ u.X))
    return {"r": gP - 2 * s.tr(s.X.T @ s.A @ s.X) * s.P}


@claim("adv-captured-default-flow", kind="id", sizes=ALL,
       statement="the ambient flow of tr(P^T u.X), P the base point's (a default argument), has Xdot = X")
def captured_default_flow(s):
    """False for P the constant it is (H_P = 0, so Xdot = 0): the capture is a default argument."""
    flow = s.canonical_flow(lambda u, Pc=s.P: u.tr(Pc.T @ u.X))
    return {"r": flow.Xdot - s.X}


@claim("adv-captured-d-at-point", kind="id", sizes=ALL,
       statement="at (-X, -P), the derivative of tr(P^T u.X) along the flow of tr(u.P^T u.P)/2 is -tr(P^T P)")
def captured_d_at_point(s):
    """False for P the constant it is: along Xdot = P_t - X_t Pi = -P (at the point), d tr(P^T u.X) = -tr(P^T P);
    read as the point's variable (P -> -P) it would give +tr(P^T P).  A derivative, not a gradient."""
    t = twisted.at_point(s, -s.X, -s.P)
    flow = t.dirac_flow(lambda u: u.tr(u.P.T @ u.P) / 2)
    return {"r": t.d(lambda u: u.tr(s.P.T @ u.X), flow) - s.tr(s.P.T @ s.P)}


@claim("adv-captured-control", kind="id", sizes=ALL,
       statement="grad_X tr(P^T u.X) = P and grad_P = 0, P the base point's (true: P is a constant of u)")
def captured_control(s):
    """True: the captured P is a fixed matrix, so the gradient in u.X is P and the gradient in u.P vanishes."""
    gX, gP = s.gradient(lambda u: u.tr(s.P.T @ u.X) + u.tr(u.X.T @ s.A @ u.X))
    return {"grad_X": gX - s.P - 2 * s.A @ s.X, "grad_P": gP}


@claim("adv-captured-twisted-flow-at-point", kind="id", sizes=admissible(n_max=4, n_min=2, r_min=2, r_max=2),
       statement="at (-X, -P), the twisted flow of tr(P^T u.X), P the base point's, has Xdot = 0 and Pdot = P")
def captured_twisted_flow_at_point(s):
    """The twisted flow (an engine step that hands H to the scene of the generic point itself) at (-X, -P).
    For P the constant it is, H_X = P and H_P = 0, so Xdot = 0, Lambda = sym((-X)^T P) = 0 and Pdot = -P:
    false.  Moved with the point (P -> -P) it would give Pdot = P."""
    t = twisted.at_point(s, -s.X, -s.P)
    flow = twisted.flow(t, lambda u: u.tr(s.P.T @ u.X))
    return {"Xdot": flow.Xdot, "Pdot": flow.Pdot - s.P}


@claim("adv-nested-gradient", kind="id", sizes=ALL,
       statement="grad_X of tr(G(u)^T u.X), G(u) = grad_X tr(u.X^T u.X) = 2 u.X taken inside, is 2X")
def nested_gradient(s):
    """False: G(u) = 2 u.X depends on u, so the gradient of tr(2 u.X^T u.X) is 4X (a nested function's letters
    must be renamed back to the enclosing function's own, not to the base scene's)."""
    gX, _gP = s.gradient(lambda u: u.tr(u.gradient(lambda w: w.tr(w.X.T @ w.X))[0].T @ u.X))
    return {"r": gX - 2 * s.X}


@claim("adv-nested-gradient-control", kind="id", sizes=ALL,
       statement="grad_X of tr(G(u)^T u.X), G(u) = grad_X tr(u.X^T u.X) = 2 u.X taken inside, is 4X (true)")
def nested_gradient_control(s):
    """True: the gradient of tr(2 u.X^T u.X) is 4X."""
    gX, _gP = s.gradient(lambda u: u.tr(u.gradient(lambda w: w.tr(w.X.T @ w.X))[0].T @ u.X))
    return {"r": gX - 4 * s.X}


@claim("adv-nested-derivative", kind="id", sizes=ALL,
       statement="grad_X of H(u) = d/dt tr(u.X^T u.X)/2 along Xdot = u.P (a derivative taken inside) is 0")
def nested_derivative(s):
    """False: H(u) = tr(u.X^T u.P), so grad_X H = P (the tangent scene of a function's scene must keep the
    function's own letters)."""
    gX, _gP = s.gradient(lambda u: u.d(lambda w: w.tr(w.X.T @ w.X) / 2, {"X": u.P, "P": u.P}))
    return {"r": gX}


@claim("adv-nested-bracket", kind="id", sizes=ALL,
       statement="grad_X of H(u) = {tr(X^T A X), tr(P^T P)/2}(u) (a bracket taken inside) is 0")
def nested_bracket(s):
    """False: along the Dirac flow of tr(P^T P)/2 (Xdot = P), d tr(X^T A X) = 2 tr(X^T A P), whose gradient in X is
    2AP; the flow's multipliers need the rules of the scene's own point, so a flow inside a function is refused."""
    gX, _gP = s.gradient(lambda u: u.bracket(lambda w: w.tr(w.X.T @ w.A @ w.X), lambda w: w.tr(w.P.T @ w.P) / 2))
    return {"r": gX}


@claim("adv-nested-derivative-control", kind="id", sizes=ALL,
       statement="grad_X of H(u) = d/dt tr(u.X^T u.X)/2 along Xdot = u.P is P (true)")
def nested_derivative_control(s):
    """True: H(u) = tr(u.X^T u.P)."""
    gX, _gP = s.gradient(lambda u: u.d(lambda w: w.tr(w.X.T @ w.X) / 2, {"X": u.P, "P": u.P}))
    return {"r": gX - s.P}


@claim("adv-nested-bracket-ambient", kind="id", sizes=ALL,
       statement="grad_P of H(u) = {tr(X^T A X), tr(P^T P)/2}(u) is 2AX")
def nested_bracket_ambient(s):
    """False as an ambient gradient: the flow of tr(P^T P)/2 has Xdot = P - X Pi with Pi = sym(X^T P) as written,
    which vanishes on T*V only, so grad_P of H = 2 tr(X^T A (P - X Pi)) is 2AX - 2 X X^T A X there; solving Pi modulo
    the constraints (Pi = 0) inside the function, as a Dirac flow may, would prove it."""
    _gX, gP = s.gradient(lambda u: u.bracket(lambda w: w.tr(w.X.T @ w.A @ w.X), lambda w: w.tr(w.P.T @ w.P) / 2))
    return {"r": gP - 2 * s.A @ s.X}
