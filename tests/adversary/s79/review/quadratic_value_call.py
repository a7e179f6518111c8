"""brackets.quadratic(op): the value h(y) = ½<y, op(y)> calls op inline (brackets.py:276), outside the step that
checks op (symmetric_operator_check) and outside same_step_function (which holds the primitive's traced op and
the gradient's inline call at x to one function).  An op that tests its argument (B·y on the claim's own y, the
identity on anything else) or keeps state (B·y on its first call, the identity after) makes the value that of
½<y, By> while the gradient is x.

gl(n), <a, b> = -½tr(ab), B generic.  Λ the Lie-Poisson tensor of gl(n): Λ(a, b)|_x = <x, [a, b]>.
  If h(y) = ½<y, By> for a generic y (an identity in y's parameters), then h = ½<·, B·> everywhere, so
  ∇h(x) = ½(Bx + xB) and {h, <·, b>}(x) = <x, [½(Bx + xB), b]>, not 0 for generic B (review4's numpy check);
  if instead ∇h(x) = x then {h, <·,b>}(x) = <x, [x, b]> = 0 and h(y) = ½<y, y>.
  s79-quadval-ident-contradiction:  both "h(y) = ½<y, By>" and "{h, <·,b>}(x) = 0" (FALSE: no h satisfies both)
  s79-quadval-state-contradiction:  the same with the stateful op
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, lie_poisson, quadratic, linear

SZ = admissible(n_min=3, n_max=3)


@claim("s79-quadval-ident-contradiction", kind="id", sizes=SZ)
def ident(s):
    B = s.generic("B", "n", "n")
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    h = quadratic(lambda t, u: B @ u if u is y else u)
    val = h(s, y) - s.killing(y, B @ y) / 2
    br = lie_poisson(GL_N).bracket(s, h, linear(lambda t: b), x)
    return {"h(y) = ½<y, By>": val, "{h, <.,b>}(x) = 0": br}


@claim("s79-quadval-state-contradiction", kind="id", sizes=SZ)
def state(s):
    B = s.generic("B", "n", "n")
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    calls = []

    def op(t, u):
        calls.append(1)
        return B @ u if len(calls) == 1 else u
    h = quadratic(op)
    val = h(s, y) - s.killing(y, B @ y) / 2
    br = lie_poisson(GL_N).bracket(s, h, linear(lambda t: b), x)
    return {"h(y) = ½<y, By>": val, "{h, <.,b>}(x) = 0": br}
