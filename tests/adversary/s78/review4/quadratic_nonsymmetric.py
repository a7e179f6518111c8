"""brackets.quadratic(op): "h(x) = ½<x, op(x)> with op symmetric for <,>, ∇h = op(x)".  Nothing checks that op
is symmetric (or linear): for any other op the carried gradient op(x) is not the gradient of h, and every bracket,
Casimir residual and sharp built from it is that of another function.

(a) so(n), op = ad_K (K skew): ad_K is SKEW for <,>, so h(x) = ½<x, [K, x]> = 0 identically (a constant
    function: a Casimir of every tensor, with gradient 0).  Casimir residual Λ(∇h, b)|_x of the Lie-Poisson tensor
    is 0 (TRUE, r4-quad-adk-casimir-true); the carried gradient gives <x, [[K, x], b]> (FALSE twin).
(b) gl(n), op(x) = Bx (B generic): h(x) = -¼tr(xBx), ∇h = ½(Bx + xB) for <a, b> = -½tr(ab).  The Lie-Poisson
    bracket {h, g}(x) for g = <., b>: Λ(½(Bx + xB), b)|_x (TRUE) vs Λ(Bx, b)|_x (FALSE).
Hand derivations checked numerically in quadratic_nonsymmetric_check.py.in."""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import SO_N, GL_N, lie_poisson, quadratic, linear, casimir_residual

SZ = admissible(n_max=3, n_min=3)


def _adk(s):
    K = SO_N.generic(s, "K")
    return K, quadratic(lambda t, x: comm(K, x), "½<x, [K, x]>")


@claim("r4-quad-adk-value-zero", kind="id", sizes=SZ)
def adk_value(s):
    K, h = _adk(s)
    x = SO_N.generic(s, "x")
    return {"h(x) = ½<x,[K,x]> = 0": h(s, x)}


@claim("r4-quad-adk-casimir-true", kind="id", sizes=SZ)
def adk_casimir_true(s):
    K, h = _adk(s)
    x, b = SO_N.generic(s, "x"), SO_N.generic(s, "b")
    return {"h = 0 is a Casimir": casimir_residual(s, lie_poisson(SO_N), h, x, b)}


@claim("r4-quad-adk-casimir-false", kind="id", sizes=SZ)
def adk_casimir_false(s):
    K, h = _adk(s)
    x, b = SO_N.generic(s, "x"), SO_N.generic(s, "b")
    return {"Λ(∇h, b) = <x,[[K,x],b]>": casimir_residual(s, lie_poisson(SO_N), h, x, b)
            - s.killing(x, comm(comm(K, x), b))}


def _bx(s):
    B = s.generic("B", "n", "n")
    return B, quadratic(lambda t, x: B @ x, "½<x, Bx>")


@claim("r4-quad-bx-bracket-true", kind="id", sizes=SZ)
def bx_true(s):
    B, h = _bx(s)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    T = lie_poisson(GL_N)
    g = linear(lambda t: b)
    return {"{h, g}(x) = Λ(½(Bx + xB), b)": T.bracket(s, h, g, x) - T(s, x, (B @ x + x @ B) / 2, b)}


@claim("r4-quad-bx-bracket-false", kind="id", sizes=SZ)
def bx_false(s):
    B, h = _bx(s)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    T = lie_poisson(GL_N)
    g = linear(lambda t: b)
    return {"{h, g}(x) = Λ(Bx, b)": T.bracket(s, h, g, x) - T(s, x, B @ x, b)}
