"""A check made on the claim's scene s (f.grad(s, x_t)) at a point x_t that moves with the function of s.gradient
(or of a bracket, a flow): the graph leaves the step to the scene (x_t moves), the scene's reverse tape evaluates
gradient_check(s, value, x_t, G) with s the claim's own scene, whose field is not "reverse(": _refuse_on_tape does
not see the tape.  Is the check then made of the adjoint, or of the value only?

h(y) = ½<y, y> on n×n matrices: ∇h(y) = y at every y.  Declared G(s, y) = y²: equal to ∇h exactly at projectors.
x_t = t.X t.Xᵀ (a projector at the claim's point, XᵀX = I).
  Hf(t) := <f.grad(s, x_t), B>.  As a function of the scene, with the true gradient, Hf(t) = <x_t, B> =: Hh(t).
  With the declared one it would be Hd(t) := <x_t², B>, which agrees with Hh on V(n, r) but not off it (so their
  ambient gradients differ: ∂/∂X of <XXᵀXXᵀ, B> − <XXᵀ, B> at XᵀX = I is
  −½[(B + Bᵀ)XXᵀX + XXᵀ(B + Bᵀ)X] ... ≠ 0 in general; the engine's own decides Hh vs Hd: control r81-ro-ctrl-differ).
  r81-ro-true:   s.gradient(Hf) = s.gradient(Hh)      TRUE
  r81-ro-false:  s.gradient(Hf) = s.gradient(Hd)      FALSE
  r81-ro-br-true / -false: s.bracket(Hf, K) = s.bracket(Hh, K) / = s.bracket(Hd, K), K = ½tr(PᵀP) + <X, C>
  r81-ro-ctrl-differ: s.gradient(Hh) = s.gradient(Hd)  FALSE (the control that the two differ)
Closure variant (G(s, y) = 2y − s.X s.Xᵀ: right at y = XXᵀ only): Hd2(t) = <2x_t − XXᵀ, B> (XXᵀ constant):
  r81-ro2-true:  s.gradient(Hf2) = s.gradient(Hh)     TRUE
  r81-ro2-false: s.gradient(Hf2) = s.gradient(Hd2) = 2 s.gradient(Hh)   FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _half():
    return lambda t, y: t.killing(y, y) / 2


def _parts(s, kind):
    B = GL_N.generic(s, "B")
    if kind == 1:
        f = MatrixFunction(_half(), lambda t, y: y @ y, "½<y, y>")
    else:
        P0 = s.X @ s.X.T
        f = MatrixFunction(_half(), lambda t, y: y * 2 - P0, "½<y, y>")
    Hf = lambda t: t.killing(f.grad(s, t.X @ t.X.T), B)
    Hh = lambda t: t.killing(t.X @ t.X.T, B)
    Hd = lambda t: t.killing(t.X @ t.X.T @ t.X @ t.X.T, B)
    return Hf, Hh, Hd


def _K(s):
    C = s.generic("C", "n", "r")
    return lambda t: t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ C)


@claim("r81-ro-true", kind="id", sizes=SZ)
def ro_true(s):
    Hf, Hh, Hd = _parts(s, 1)
    a, b = s.gradient(Hf), s.gradient(Hh)
    return {"∇_X": a[0] - b[0], "∇_P": a[1] - b[1]}


@claim("r81-ro-false", kind="id", sizes=SZ)
def ro_false(s):
    Hf, Hh, Hd = _parts(s, 1)
    a, b = s.gradient(Hf), s.gradient(Hd)
    return {"∇_X": a[0] - b[0], "∇_P": a[1] - b[1]}


@claim("r81-ro-ctrl-differ", kind="id", sizes=SZ)
def ro_ctrl(s):
    Hf, Hh, Hd = _parts(s, 1)
    a, b = s.gradient(Hh), s.gradient(Hd)
    return {"∇_X": a[0] - b[0]}


@claim("r81-ro-br-true", kind="id", sizes=SZ)
def br_true(s):
    Hf, Hh, Hd = _parts(s, 1)
    K = _K(s)
    return {"{Hf, K} = {Hh, K}": s.bracket(Hf, K) - s.bracket(Hh, K)}


@claim("r81-ro-br-false", kind="id", sizes=SZ)
def br_false(s):
    Hf, Hh, Hd = _parts(s, 1)
    K = _K(s)
    return {"{Hf, K} = {Hd, K}": s.bracket(Hf, K) - s.bracket(Hd, K)}


@claim("r81-ro2-true", kind="id", sizes=SZ)
def ro2_true(s):
    Hf, Hh, Hd = _parts(s, 2)
    a, b = s.gradient(Hf), s.gradient(Hh)
    return {"∇_X": a[0] - b[0]}


@claim("r81-ro2-false", kind="id", sizes=SZ)
def ro2_false(s):
    Hf, Hh, Hd = _parts(s, 2)
    a, b = s.gradient(Hf), s.gradient(Hh)
    return {"∇_X = 2∇Hh": a[0] - b[0] * 2}
