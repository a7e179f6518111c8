"""gradient_check is a constant step (zero=True): its derivative along every flow is taken as 0, and the check
is made at the base point only.  A declared gradient that agrees with the value's at the claim's scene but not
along a tangent (it keeps the claim's scene s in a closure where the value reads the tangent scene t) passes.

h(t, y) = <y, t.X t.Xᵀ>  (<a, b> = −½ tr(ab)): its gradient (in gl, for <,>) at any y is t.X t.Xᵀ, so along a
tangent X + εV:  d/dε ∇h(t_ε, x) = V Xᵀ + X Vᵀ  (≠ 0 for generic V, X).
Declared gradient: (t, y) ↦ s.X s.Xᵀ (the claim's scene kept): equal at ε = 0, derivative 0.
  h4-tan-capture-false:     d∇h = 0                              FALSE   (by hand: VXᵀ + XVᵀ ≠ 0)
  h4-tan-capture-truetwin:  d∇h = VXᵀ + XVᵀ                      TRUE
  h4-tan-bracket-false:     d/dε {h, <., b>}(x) = 0              FALSE   (= <x, [VXᵀ + XVᵀ, b]>, generic ≠ 0)
  h4-tan-honest-true:       honest gradient t.X t.Xᵀ, d∇h = VXᵀ + XVᵀ    TRUE
  h4-tan-honest-false:      honest gradient, d∇h = 0                     FALSE
  h4-tan-add-truetwin:      h = ½<y, y>, declared y + (t.X − s.X) s.Xᵀ:  d∇h = 0   TRUE
  h4-tan-add-false:         same, d∇h = V Xᵀ                                       FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction, lie_poisson, linear

SZ = admissible(n_min=3, n_max=3)


def _capture(s):
    return MatrixFunction(lambda t, y: t.killing(y, t.X @ t.X.T), lambda t, y: s.X @ s.X.T, "<y, XXᵀ>")


def _honest(s):
    return MatrixFunction(lambda t, y: t.killing(y, t.X @ t.X.T), lambda t, y: t.X @ t.X.T, "<y, XXᵀ>")


def _d(s, f):
    x = GL_N.generic(s, "x")
    V = s.fresh("n", "r")
    return x, V, s.d(lambda t: f.grad(t, x), {"X": V})


@claim("h4-tan-capture-false", kind="id", sizes=SZ)
def cap_false(s):
    x, V, d = _d(s, _capture(s))
    return {"d∇h(x) = 0": d}


@claim("h4-tan-capture-truetwin", kind="id", sizes=SZ)
def cap_true(s):
    x, V, d = _d(s, _capture(s))
    return {"d∇h(x) = VXᵀ + XVᵀ": d - V @ s.X.T - s.X @ V.T}


@claim("h4-tan-bracket-false", kind="id", sizes=SZ)
def br_false(s):
    f = _capture(s)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    V = s.fresh("n", "r")
    T = lie_poisson(GL_N)
    g = linear(lambda t: b)
    return {"d{h, <.,b>}(x) = 0": s.d(lambda t: T.bracket(t, f, g, x), {"X": V})}


@claim("h4-tan-honest-true", kind="id", sizes=SZ)
def hon_true(s):
    x, V, d = _d(s, _honest(s))
    return {"d∇h(x) = VXᵀ + XVᵀ": d - V @ s.X.T - s.X @ V.T}


@claim("h4-tan-honest-false", kind="id", sizes=SZ)
def hon_false(s):
    x, V, d = _d(s, _honest(s))
    return {"d∇h(x) = 0": d}


def _add(s):
    return MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y + (t.X - s.X) @ s.X.T, "½<y, y>")


@claim("h4-tan-add-truetwin", kind="id", sizes=SZ)
def add_true(s):
    x, V, d = _d(s, _add(s))
    return {"d∇h(x) = 0": d}


@claim("h4-tan-add-false", kind="id", sizes=SZ)
def add_false(s):
    x, V, d = _d(s, _add(s))
    return {"d∇h(x) = VXᵀ": d - V @ s.X.T}
