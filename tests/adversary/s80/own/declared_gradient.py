"""Stop 80's own find: a MatrixFunction built with a gradient that is not its value's.

MatrixFunction(value, gradient) took the gradient on trust: a bracket, a Casimir residual or a Hamiltonian flow of h
used the declared gradient.  f = MatrixFunction(y ↦ 0, y ↦ A) is the zero function, whose Lie–Poisson bracket with
every function is 0; with the declared gradient A, {f, <·, b>}(x) = <x, [A, b]> was proved by every method, free for
all n, r included.  Every gradient is now checked against its value where it is taken (brackets.gradient_check).
  mf-zero-with-gradient:   f = 0 and {f, <·, b>} = <x, [A, b]>                 FALSE (a contradiction): refused
  mf-linear-declared-true: f(y) = <y, A> with the declared gradient A, and {f, <·, b>} = <x, [A, b]>       TRUE
  mf-cubic-declared-true:  f(y) = tr(y³) with its gradient −6y², written by hand            TRUE
  mf-cubic-declared-false: the same with the gradient −6(y²)ᵀ: not the gradient (y is not symmetric): refused
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, MatrixFunction, lie_poisson, linear

SZ = admissible(n_min=3, n_max=3)


def _bracket(s, f):
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    return x, b, lie_poisson(GL_N).bracket(s, f, linear(lambda t: b), x)


@claim("mf-zero-with-gradient", kind="pb", sizes=SZ)
def zero(s):
    f = MatrixFunction(lambda t, y: t.killing(y, y) * 0, lambda t, y: t.A, "0")
    x, b, br = _bracket(s, f)
    return {"f = 0": f(s, x), "{f, <.,b>} = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


@claim("mf-linear-declared-true", kind="pb", sizes=SZ)
def linear_true(s):
    f = MatrixFunction(lambda t, y: t.killing(y, t.A), lambda t, y: t.A, "<y, A>")
    x, b, br = _bracket(s, f)
    return {"{f, <.,b>} = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


def _cubic(transpose):
    # d tr(y³) = 3 tr(y² dy), and <G, dy> = −½ tr(G dy) = 3 tr(y² dy) for G = −6y²: the transpose is wrong
    def grad(t, y):
        g = (y @ y) * (-6)
        return g.T if transpose else g
    return MatrixFunction(lambda t, y: (y @ y @ y).trace(), grad, "tr y³")


@claim("mf-cubic-declared-true", kind="pb", sizes=SZ)
def cubic_true(s):
    f = _cubic(False)
    x = GL_N.generic(s, "x")
    return {"∇f(x) = −6x²": f.grad(s, x) + (x @ x) * 6}


@claim("mf-cubic-declared-false", kind="pb", sizes=SZ)
def cubic_false(s):
    f = _cubic(True)
    x = GL_N.generic(s, "x")
    return {"∇f(x) = −6(x²)ᵀ": f.grad(s, x) + (x @ x).T * 6}


@claim("mf-entry-zero-gradient", kind="pb", sizes=SZ)
def entry_zero(s):
    """f(y) = y₁₁ (an entry: the free scene needs coordinates) declared with gradient 0: {f, <·, b>} = 0 is FALSE
    (its gradient is −2E₁₁, and <x, [E₁₁, b]> ≠ 0): refused."""
    f = MatrixFunction(lambda t, y: y[0, 0], lambda t, y: y * 0, "y11")
    x, b, br = _bracket(s, f)
    return {"{f, <.,b>} = 0": br}
