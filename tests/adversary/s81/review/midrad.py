"""The ball method at n >= 32 evaluates first over float64 midpoint-radius pairs (field "midrad53",
backends/midrad.py; methods/fixed_size.py _ball_component: MIDRAD_MIN_N = 32).  brackets._AFFINE_CHECKED lists
"symbolic", "rational", "modular", "float64", "mpmath", "arb" and not "midrad": gradient_check returns 0 without a
check (`if not _field_in(s, _AFFINE_CHECKED): return x - x`), _vanishes says True and _check_symmetric returns
(quadratic's operator unchecked), _check_affine (form_gradient) returns.  So at n >= 32 the ball method takes every
declared gradient and every operator of `quadratic` on trust, if the midrad enclosures decide.

  f = MatrixFunction(y ↦ 0, y ↦ A): the zero function (stop 80's own mf-zero-with-gradient, without the "f = 0"
  statement).  {f, <·, b>}(x) = Λ(∇f, b) = <x, [∇f, b]> = 0 since ∇f = 0 at every point.
     r81-mr-zero-false:  {f, <·, b>}(x) = <x, [A, b]>    FALSE (= 0 ≠ <x, [A, b]> for generic x, b)
     r81-mr-zero-true:   {f, <·, b>}(x) = 0              TRUE
  h = quadratic(u ↦ Ku − uK) (K generic): h(x) = ½<x, [K, x]> = −¼ tr(x(Kx − xK)) = −¼(tr(xKx) − tr(xxK)) = 0, so
  ∇h = 0 and {h, <·, b>} = 0; with the operator taken as the gradient, <x, [[K, x], b]>.
     r81-mr-ad-false:    {h, <·, b>}(x) = <x, [[K, x], b]>    FALSE
     r81-mr-ad-true:     {h, <·, b>}(x) = 0                   TRUE
  Controls (honest gradients): f(y) = <y, A> with ∇f = A: {f, <·, b>} = <x, [A, b]> TRUE / = 0 FALSE.
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, MatrixFunction, lie_poisson, linear, quadratic

SZ = admissible(n_min=3, n_max=3)


def _br(s, f):
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    return x, b, lie_poisson(GL_N).bracket(s, f, linear(lambda t: b), x)


def _zero():
    return MatrixFunction(lambda t, y: t.killing(y, y) * 0, lambda t, y: t.A, "0")


@claim("r81-mr-zero-false", kind="pb", sizes=SZ)
def zero_false(s):
    x, b, br = _br(s, _zero())
    return {"{f, <.,b>} = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


@claim("r81-mr-zero-true", kind="pb", sizes=SZ)
def zero_true(s):
    x, b, br = _br(s, _zero())
    return {"{f, <.,b>} = 0": br}


def _ad(s):
    K = GL_N.generic(s, "K")
    return K, quadratic(lambda t, u: K @ u - u @ K, "½<x, [K, x]>")


@claim("r81-mr-ad-false", kind="pb", sizes=SZ)
def ad_false(s):
    K, h = _ad(s)
    x, b, br = _br(s, h)
    return {"{h, <.,b>} = <x, [[K,x], b]>": br - s.killing(x, comm(comm(K, x), b))}


@claim("r81-mr-ad-true", kind="pb", sizes=SZ)
def ad_true(s):
    K, h = _ad(s)
    x, b, br = _br(s, h)
    return {"{h, <.,b>} = 0": br}


def _lin():
    return MatrixFunction(lambda t, y: t.killing(y, t.A), lambda t, y: t.A, "<y, A>")


@claim("r81-mr-ctrl-true", kind="pb", sizes=SZ)
def ctrl_true(s):
    x, b, br = _br(s, _lin())
    return {"{f, <.,b>} = <x, [A, b]>": br - s.killing(x, comm(s.A, b))}


@claim("r81-mr-ctrl-false", kind="pb", sizes=SZ)
def ctrl_false(s):
    x, b, br = _br(s, _lin())
    return {"{f, <.,b>} = 0": br}
