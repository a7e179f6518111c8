"""MatrixFunction.__add__ / __mul__ / scaled build the new function's value from the operands' RAW value fields
(self.value(s, x)), so the operand's value at the combined function's gradient check is never recorded under the
operand's value (same_inline_function in __call__ and same_step_function in grad hold self.value, the combined
lambda): a value that tests its point is another function at the check than at the claim's own call f(s, x).

f.value(t, y) = <y, A> at y = x (the claim's generic point), 0 elsewhere (a test `y is x`); f.gradient = 0.
  h4-comb-add-contradiction:    {f(x) = <x, A>, ∇(f + z)(x) = 0}      (z the zero function, gradient 0)
  h4-comb-scaled-contradiction: {f(x) = <x, A>, ∇(f·1)(x) = 0}        (f.scaled(1))
Truth (by hand): for ONE function f of the point, f(x) = <x, A> at a generic x is an identity in x, so f = <·, A>,
∇f = A and ∇(f + 0) = ∇(1·f) = A ≠ 0 (A generic).  The claims are FALSE.
  h4-comb-add-control-false:    the pure value <y, A> with gradient 0: {f(x) = <x, A>, ∇(f + z)(x) = 0}  FALSE
                                (the check sees <p, A>: refused, expected error)
  h4-comb-add-control-true:     the pure value with gradient A: {f(x) = <x, A>, ∇(f + z)(x) = A}         TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _f(x, test=True, grad_A=False):
    def value(t, y):
        return t.killing(y, t.A) if (y is x or not test) else t.killing(y, y) * 0
    return MatrixFunction(value, (lambda t, y: t.A) if grad_A else (lambda t, y: t.A * 0), "f")


def _z():
    return MatrixFunction(lambda t, y: t.killing(y, y) * 0, lambda t, y: t.A * 0, "0")


@claim("h4-comb-add-contradiction", kind="id", sizes=SZ)
def add_c(s):
    x = GL_N.generic(s, "x")
    f = _f(x)
    return {"f(x) = <x, A>": f(s, x) - s.killing(x, s.A), "∇(f + 0)(x) = 0": (f + _z()).grad(s, x)}


@claim("h4-comb-scaled-contradiction", kind="id", sizes=SZ)
def scaled_c(s):
    x = GL_N.generic(s, "x")
    f = _f(x)
    return {"f(x) = <x, A>": f(s, x) - s.killing(x, s.A), "∇(1·f)(x) = 0": f.scaled(lambda t: t.q(1)).grad(s, x)}


@claim("h4-comb-add-control-false", kind="id", sizes=SZ)
def add_cf(s):
    x = GL_N.generic(s, "x")
    f = _f(x, test=False)
    return {"f(x) = <x, A>": f(s, x) - s.killing(x, s.A), "∇(f + 0)(x) = 0": (f + _z()).grad(s, x)}


@claim("h4-comb-add-control-true", kind="id", sizes=SZ)
def add_ct(s):
    x = GL_N.generic(s, "x")
    f = _f(x, test=False, grad_A=True)
    return {"f(x) = <x, A>": f(s, x) - s.killing(x, s.A), "∇(f + 0)(x) = A": (f + _z()).grad(s, x) - s.A}
