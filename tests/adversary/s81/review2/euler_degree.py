"""A MatrixFunction whose value takes another's checked gradient (Euler's identity): F(y) = <∇f(y), y> with
f = trace_power(k) (homogeneous of degree k, no shift), so F = k·f and ∇F = k·∇f, declared as such.  F's check takes
its value's gradient; the value holds f's check, which refuses the reverse tape, so the gradient is taken from a
basis (polynomial_gradient, degree <= 6).  At k = 7 the value has degree 7.
  r81b-eu4-true:  F.grad(x) = 4∇f(x), f(x) = tr x⁴ ... F(x) = 4 f(x)         TRUE (k = 4)
  r81b-eu4-false: F(x) = 3 f(x)                                                 FALSE
  r81b-eu7-true:  F.grad(x) − 7∇f(x) = 0 and F(x) = 7 f(x)  (k = 7)             TRUE
  r81b-eu7-false: F(x) = 6 f(x)                                                 FALSE
(f(x) = tr x^k is not 0 for a generic x, so the false twins are false.)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction, trace_power

SZ = admissible(n_min=3, n_max=3)


def _F(k):
    f = trace_power(k)
    return f, MatrixFunction(lambda t, y: t.killing(f.grad(t, y), y), lambda t, y: f.grad(t, y) * k, f"<∇tr y^{k}, y>")


def _checks(s, k, c):
    f, F = _F(k)
    x = GL_N.generic(s, "x")
    return {"∇F = k∇f": F.grad(s, x) - f.grad(s, x) * k, "F = c f": F(s, x) - f(s, x) * c}


@claim("r81b-eu4-true", kind="id", sizes=SZ)
def eu4_true(s):
    return _checks(s, 4, 4)


@claim("r81b-eu4-false", kind="id", sizes=SZ)
def eu4_false(s):
    return _checks(s, 4, 3)


@claim("r81b-eu7-true", kind="id", sizes=SZ)
def eu7_true(s):
    return _checks(s, 7, 7)


@claim("r81b-eu7-false", kind="id", sizes=SZ)
def eu7_false(s):
    return _checks(s, 7, 6)
