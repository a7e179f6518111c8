"""FALSE REFUSALS (R1, a realistic instance): the engine's own Λ2(a, b)|_x = <x − A, [a, b]> (lambda2(), the
paper's (LAMBDA12)) at the covector A itself.  The form reads s.A from the scene it is called on; called on the
claim's scene with a = s.A (the gradient of the linear function <·, A>), the node the form reads IS the
argument's, and the call's graph is read as <x − a, [a, b]> against the reference <x − A(scene), [a, b]>.

Truth (by hand): <A, [A, b]> = −½tr(A(Ab − bA)) = 0, so
  Λ2(A, b)|_x = <x − A, [A, b]> = <x, [A, b]>, and Λ2(a, b)|_y = <y − A, [a, b]> by definition.
  s79r2-lambda2-at-A-true:   {<·, A>, <·, b>}_2(x) = <x, [A, b]>  and  Λ2(a, b)|_y = <y − A, [a, b]>     TRUE
  s79r2-lambda2-at-A-false:  {<·, A>, <·, b>}_2(x) = 0            and  Λ2(a, b)|_y = <y − A, [a, b]>     FALSE
  s79r2-lambda2-at-A-alone:  the first statement alone (one call: nothing to compare)                     TRUE
  s79r2-pencil-casimir-true: checked_tensor(Λ2)(x; A, b) = <x, [A, b]>  (one checked call at A)            TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, lambda2, linear, checked_tensor

SZ = admissible(n_min=3, n_max=3)


def _parts(s):
    x, y, a, b = (GL_N.generic(s, nm) for nm in ("x", "y", "a", "b"))
    T2 = lambda2()
    br = T2.bracket(s, linear(lambda t: t.A), linear(lambda t: b), x)
    other = T2(s, y, a, b) - s.killing(y - s.A, comm(a, b))
    return x, b, br, other


@claim("s79r2-lambda2-at-A-true", kind="id", sizes=SZ)
def at_A_true(s):
    x, b, br, other = _parts(s)
    return {"{<·,A>, <·,b>}_2(x) = <x, [A, b]>": br - s.killing(x, comm(s.A, b)), "Λ2 at y": other}


@claim("s79r2-lambda2-at-A-false", kind="id", sizes=SZ)
def at_A_false(s):
    x, b, br, other = _parts(s)
    return {"{<·,A>, <·,b>}_2(x) = 0": br, "Λ2 at y": other}


@claim("s79r2-lambda2-at-A-alone", kind="id", sizes=SZ)
def at_A_alone(s):
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    br = lambda2().bracket(s, linear(lambda t: t.A), linear(lambda t: b), x)
    return {"{<·,A>, <·,b>}_2(x) = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


@claim("s79r2-pencil-casimir-true", kind="id", sizes=SZ)
def checked_at_A(s):
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    C = checked_tensor(lambda2())
    return {"Λ2(A, b)|x = <x, [A, b]> (checked)": C(s, x, s.A, b) - s.killing(x, comm(s.A, b))}
