"""False refusals from gradient_check (TRUE claims).  On fields without reverse mode (float64, mpmath, arb) the
value's gradient is taken by polynomial_gradient, degree <= MAX_FORM_DEGREE = 6.
  h4-ref-tp7-true:   ∇ tr(x⁷) = −14 x⁶ for the engine's own trace_power(7) at x in gl(n)      TRUE
  h4-ref-tp3-true:   the same for trace_power(3) (control): ∇ tr(x³) = −6 x²                     TRUE
  h4-ref-sq4-true:   h = <y, y>⁴ (degree 8), ∇h = 4<y, y>³·2y = 8<y, y>³ y                       TRUE
  h4-ref-so-true:    (overrides.py h4-ov-so-true, the gradient of so(n) declared) — see there
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction, trace_power

SZ = admissible(n_min=3, n_max=3)


def _pow(x, k):
    acc = x
    for _ in range(k - 1):
        acc = acc @ x
    return acc


@claim("h4-ref-tp7-true", kind="id", sizes=SZ)
def tp7(s):
    x = GL_N.generic(s, "x")
    return {"∇tr x⁷ = −14x⁶": trace_power(7).grad(s, x) + _pow(x, 6) * 14}


@claim("h4-ref-tp3-true", kind="id", sizes=SZ)
def tp3(s):
    x = GL_N.generic(s, "x")
    return {"∇tr x³ = −6x²": trace_power(3).grad(s, x) + _pow(x, 2) * 6}


@claim("h4-ref-sq4-true", kind="id", sizes=SZ)
def sq4(s):
    x = GL_N.generic(s, "x")
    k = lambda t, y: t.killing(y, y)  # noqa: E731
    f = MatrixFunction(lambda t, y: k(t, y) * k(t, y) * k(t, y) * k(t, y), lambda t, y: y * (k(t, y) * k(t, y) * k(t, y) * 8))
    return {"∇<y,y>⁴ = 8<y,y>³y": f.grad(s, x) - x * (k(s, x) * k(s, x) * k(s, x) * 8)}
