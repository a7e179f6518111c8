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
