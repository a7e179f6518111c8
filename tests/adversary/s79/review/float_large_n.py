"""The float method's first field at n >= 32 (midrad53) is outside brackets._AFFINE_CHECKED: _check_symmetric
(quadratic's operator) and _check_affine (form_gradient) return without a check there.  Review4's W1 at n = 32:
op(x) = Bx on gl(n) (not symmetric for <,>): ∇(½<x, Bx>) = ½(Bx + xB), so
  s79-f32-quad-bx-false: {h, <·,b>}(x) = Λ(Bx, b)|_x            (FALSE; the engine's gradient if unchecked)
  s79-f32-quad-bx-true:  {h, <·,b>}(x) = Λ(½(Bx + xB), b)|_x    (TRUE; but the step should refuse op anyway)
  s79-f32-sharp-nonaffine-false: form_gradient of c ↦ <c, K> + <c, c> (not affine) equals the secant through
                         the basis: the step must refuse (its doc: an affine form)"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, lie_poisson, quadratic, linear

SZ = admissible(n_min=3, n_max=3)


@claim("s79-f32-quad-bx-false", kind="id", sizes=SZ)
def f32_false(s):
    B = s.generic("B", "n", "n")
    h = quadratic(lambda t, x: B @ x)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    T = lie_poisson(GL_N)
    return {"{h, g} = Λ(Bx, b)": T.bracket(s, h, linear(lambda t: b), x) - T(s, x, B @ x, b)}


@claim("s79-f32-quad-bx-true", kind="id", sizes=SZ)
def f32_true(s):
    B = s.generic("B", "n", "n")
    h = quadratic(lambda t, x: B @ x)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    T = lie_poisson(GL_N)
    return {"{h, g} = Λ(½(Bx+xB), b)": T.bracket(s, h, linear(lambda t: b), x) - T(s, x, (B @ x + x @ B) / 2, b)}
