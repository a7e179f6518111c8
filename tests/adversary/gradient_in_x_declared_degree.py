"""The gradient in x of a Poisson tensor's form must not depend on the degree the tensor declares.  It
used to: gradient_in_x interpolated t ↦ Λ(b, c)|_{x + t e_k} at t = 0, ..., T.degree over a basis e_k,
so a cubic form declared of degree 2 got a "gradient" that is not the derivative of a cubic, and the
true claim below failed under every fixed-size method.  The gradient is now one engine step
(polynomial_gradient) that derives the form's degree itself (T.degree is not read), so:

* the true claim (the same gradient whether the cubic declares 2 or 3) passes;
* the false claim (the cubic's gradient is the quadratic's) fails;
* a form that is no polynomial in x (an inverse) has no degree: refused (error), not interpolated.
"""
from stiefelsym import admissible, claim, comm
from stiefelsym.brackets import PoissonTensor, SO_R, gradient_in_x

ALL = admissible(n_max=4, n_min=3, r_min=3)


def cubic(degree):
    return PoissonTensor(SO_R, lambda s, x, a, b: s.killing(x @ x @ x, comm(a, b)), degree, "cubic")


def quadratic(degree):
    return PoissonTensor(SO_R, lambda s, x, a, b: s.killing(x @ x, comm(a, b)), degree, "quadratic")


def rational(degree):
    return PoissonTensor(SO_R, lambda s, x, a, b: s.killing((s.Ir + x @ x.T).inv(), a @ b), degree, "rational")


@claim("adv-gradient-in-x-declared-degree", kind="id", sizes=ALL)
def gradient_declared_degree(s):
    """The gradient in x of a cubic tensor's form is the same whether it declares degree 2 or 3 (true)."""
    x, b, c = s.Psi, s.theta, s.eta
    return {"v": gradient_in_x(s, cubic(2), x, b, c) - gradient_in_x(s, cubic(3), x, b, c)}


@claim("adv-gradient-in-x-cubic-is-quadratic", kind="id", sizes=ALL)
def gradient_cubic_quadratic(s):
    """The gradient in x of the cubic form is that of the quadratic one, both declared of degree 1 (false)."""
    x, b, c = s.Psi, s.theta, s.eta
    return {"v": gradient_in_x(s, cubic(1), x, b, c) - gradient_in_x(s, quadratic(1), x, b, c)}


@claim("adv-gradient-in-x-rational", kind="id", sizes=ALL)
def gradient_rational(s):
    """The gradient in x of a form with an inverse, declared of degree 1, is its secant through a basis
    (false: the form is no polynomial; refused)."""
    x, b, c = s.Psi, s.theta, s.eta
    T = rational(1)
    return {"v": gradient_in_x(s, T, x, b, c) - gradient_in_x(s, T, s.Ir * 0, b, c)}
