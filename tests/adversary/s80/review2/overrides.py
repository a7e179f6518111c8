"""MatrixFunction subclasses and the raw fields.

The engine's steps take a function's gradient by f.grad (lie_poisson's bracket, casimir_residual): a subclass
that overrides grad (or __call__) is never checked.  f below is the zero function (value 0); its Lie–Poisson
bracket with <., b> is 0, whatever gradient is declared (stop 80's own find mf-zero-with-gradient, through an
override).
  h4-ov-grad-false:     class Z(MatrixFunction) with grad = A, value 0: {f, <., b>}(x) = <x, [A, b]>   FALSE (it is 0)
  h4-ov-grad-truetwin:  the same, {f, <., b>}(x) = 0                                                TRUE
  h4-ov-casimir-false:  casimir_residual(f = 0 with grad = x): claimed 0 for the Lie–Poisson tensor
                        of gl — with grad x, Λ(x; x, b) = <x, [x, b]> = 0 anyway, so this one is TRUE
                        (a control of the route)
  h4-ov-dataclass-false: dataclasses.replace(f_honest, gradient=...) — a MatrixFunction made without the
                        constructor: checked like any (expected refused)
  h4-ov-nr-float-true:  quadratic() at a point of R^{n×r}: ∇h(Y) = Y (TRUE; float/ball: polynomial_gradient
                        takes square points only — a false refusal if refused)
  h4-ov-so-true:        f(y) = <y, A> on so(n) with the gradient of so(n), skew(A) (TRUE as a statement
                        about so(n): the bracket of lie_poisson(SO_N) at x in so(n) with b in so(n) only reads
                        the so(n) part): {f, <., b>}(x) = <x, [skew A, b]>
"""
import dataclasses

from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, SO_N, MatrixFunction, lie_poisson, linear, quadratic, skew

SZ = admissible(n_min=3, n_max=3)


class Z(MatrixFunction):
    def grad(self, s, x):
        return self.gradient(s, x)


def _zero():
    return Z(lambda t, y: t.killing(y, y) * 0, lambda t, y: t.A, "0")


def _br(s, f, space=GL_N):
    x, b = space.generic(s, "x"), space.generic(s, "b")
    return x, b, lie_poisson(space).bracket(s, f, linear(lambda t: b), x)


@claim("h4-ov-grad-false", kind="pb", sizes=SZ)
def ov_false(s):
    f = _zero()
    x, b, br = _br(s, f)
    return {"f = 0": f(s, x), "{f, <.,b>} = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


@claim("h4-ov-grad-truetwin", kind="pb", sizes=SZ)
def ov_true(s):
    f = _zero()
    x, b, br = _br(s, f)
    return {"f = 0": f(s, x), "{f, <.,b>} = 0": br}


@claim("h4-ov-dataclass-false", kind="pb", sizes=SZ)
def dc_false(s):
    f = dataclasses.replace(linear(lambda t: t.A), value=lambda t, y: t.killing(y, y) * 0)
    x, b, br = _br(s, f)
    return {"f = 0": f(s, x), "{f, <.,b>} = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


@claim("h4-ov-nr-float-true", kind="id", sizes=SZ)
def nr_true(s):
    Y = s.generic("Y", "n", "r")
    return {"∇h(Y) = Y": quadratic().grad(s, Y) - Y}


@claim("h4-ov-so-true", kind="pb", sizes=SZ)
def so_true(s):
    f = MatrixFunction(lambda t, y: t.killing(y, t.A), lambda t, y: skew(t.A), "<y, A>")
    x, b, br = _br(s, f, SO_N)
    return {"{f, <.,b>} = <x, [skew A, b]>": br - s.killing(x, comm(skew(s.A), b))}
