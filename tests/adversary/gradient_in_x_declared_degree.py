"""gradient_in_x trusts the degree a PoissonTensor declares: for a cubic form declared of degree 2 it
interpolates the polynomial t ↦ Λ(b, c)|_{x + t e_k} at t = 0, 1, 2 over a basis e_k, which is not the
derivative of a cubic, so two tensors with the same form and declared degrees 2 and 3 get different
"gradients" at the same point.  The claim below (the gradient in x does not depend on the declared degree)
is true; every fixed-size method answers `fails`.  degree_residual checks the declared degree, but only in
the claims that include poisson_checks: gradient_in_x itself (traced inline, not an engine step) does not.
"""
from stiefelsym import admissible, claim, comm
from stiefelsym.brackets import PoissonTensor, SO_R, gradient_in_x

ALL = admissible(n_max=4, n_min=3, r_min=3)


def cubic(degree):
    return PoissonTensor(SO_R, lambda s, x, a, b: s.killing(x @ x @ x, comm(a, b)), degree, "cubic")


@claim("adv-gradient-in-x-declared-degree", kind="id", sizes=ALL)
def gradient_declared_degree(s):
    """The gradient in x of a cubic tensor's form is the same whether it declares degree 2 or 3 (true)."""
    x, b, c = s.Psi, s.theta, s.eta
    return {"v": gradient_in_x(s, cubic(2), x, b, c) - gradient_in_x(s, cubic(3), x, b, c)}
