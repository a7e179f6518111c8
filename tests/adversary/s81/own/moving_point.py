"""A declared gradient taken at a point that moves along the flow (x = X Xᵀ), inside a derivative.

h(y) = ½<y, y> + <y, y²>/3 with <a, b> = −½ tr(ab): dh(δ) = <y, δ> + <y², δ>, so ∇h(y) = y + y² (y symmetric
or not: tr(y² δ) is cyclic).  Along the flow X ↦ X + εV, x = XXᵀ moves with ẋ = VXᵀ + XVᵀ, and
    d/dε ∇h(x_ε) = ẋ + ẋx + xẋ.
  s81-mp-true:        d∇h(x) = ẋ + ẋx + xẋ                                     TRUE
  s81-mp-false:       d∇h(x) = ẋ + 2xẋ                                         FALSE (ẋx ≠ xẋ for generic V)
  s81-mp-capture:     the declared gradient y + y² written as y + x·y with x = s.X s.Xᵀ kept from the claim's
                      scene (right at the point: x·x = x²; along the flow the kept x does not move):
                      d∇h = ẋ + ẋx + xẋ                                         TRUE of h, refused (the gradient
                      is not the value's along the flow) or decided, never "fails"
  s81-mp-capture-false: the same, d∇h = ẋ + xẋ (what the kept x gives)          FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _h():
    return MatrixFunction(lambda t, y: t.killing(y, y) / 2 + t.killing(y, y @ y) / 3, lambda t, y: y + y @ y, "h")


def _captured(s):
    x0 = s.X @ s.X.T
    return MatrixFunction(lambda t, y: t.killing(y, y) / 2 + t.killing(y, y @ y) / 3, lambda t, y: y + x0 @ y, "h")


def _run(s, f):
    V = s.fresh("n", "r")
    d = s.d(lambda t: f.grad(t, t.X @ t.X.T), {"X": V})
    x, xd = s.X @ s.X.T, V @ s.X.T + s.X @ V.T
    return d, x, xd


@claim("s81-mp-true", kind="id", sizes=SZ)
def mp_true(s):
    d, x, xd = _run(s, _h())
    return {"d∇h(x) = ẋ + ẋx + xẋ": d - xd - xd @ x - x @ xd}


@claim("s81-mp-false", kind="id", sizes=SZ)
def mp_false(s):
    d, x, xd = _run(s, _h())
    return {"d∇h(x) = ẋ + 2xẋ": d - xd - x @ xd * 2}


@claim("s81-mp-capture", kind="id", sizes=SZ)
def mp_capture(s):
    d, x, xd = _run(s, _captured(s))
    return {"d∇h(x) = ẋ + ẋx + xẋ": d - xd - xd @ x - x @ xd}


@claim("s81-mp-capture-false", kind="id", sizes=SZ)
def mp_capture_false(s):
    d, x, xd = _run(s, _captured(s))
    return {"d∇h(x) = ẋ + xẋ": d - xd - x @ xd}
