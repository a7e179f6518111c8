"""A MatrixFunction at a realified (complex) point, along a tangent of the point (systems.derivative), and on the
real scene's point seen as complex: honest claims a mathematician would write (false refusals?), each with a
false twin.  Realified 2n×2n matrices: y = Z Z* (Z* = Zᵀ realified, the conjugate transpose, which is
ctranspose's conjugate: M* ↦ realified transpose).  f = ½<y, y> with its gradient y (honest, in gl of the
realified matrices: <a, b> = −½ tr(ab) on 2n×2n real matrices).
  d/dε ∇f(Z Zᵀ) along Z ↦ Z + εW (realified transposes, W = realify(U, U') with U, U' fresh):  W Zᵀ + Z Wᵀ.
  r81b-cp-true:   d∇f = WZᵀ + ZWᵀ       TRUE
  r81b-cp-false:  d∇f = WZᵀ             FALSE
  r81b-cpq-true / -false: the same with quadratic() (its operator's check) instead of the declared gradient.
  r81b-rc-true / -false: on the real point seen as complex (real_complex_point), along the realified real V.
  r81b-cp0-true / -false: ∇f(ZZᵀ) = ZZᵀ (true) / = 2ZZᵀ (false: ZZᵀ ≠ 0), no derivative.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction, quadratic
from stiefelsym.systems import complex_point, derivative, real_complex_point, realify_real

SZ = admissible(n_min=3, n_max=3)


def _f():
    return MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y, "½<y,y>")


def _run(s, f, point):
    z = point(s)
    if point is complex_point:
        W = s.realify(s.fresh("n", "r"), s.fresh("n", "r"))
    else:
        W = realify_real(s, s.fresh("n", "r"))
    d = derivative(s, lambda t, w: f.grad(t, w["Z"] @ w["Z"].T), z, {"Z": W})
    Z = z["Z"]
    return d, W @ Z.T, Z @ W.T


@claim("r81b-cp-true", kind="id", sizes=SZ)
def cp_true(s):
    d, a, b = _run(s, _f(), complex_point)
    return {"d∇f = WZᵀ + ZWᵀ": d - a - b}


@claim("r81b-cp-false", kind="id", sizes=SZ)
def cp_false(s):
    d, a, b = _run(s, _f(), complex_point)
    return {"d∇f = WZᵀ": d - a}


@claim("r81b-cpq-true", kind="id", sizes=SZ)
def cpq_true(s):
    d, a, b = _run(s, quadratic(), complex_point)
    return {"d∇f = WZᵀ + ZWᵀ": d - a - b}


@claim("r81b-cpq-false", kind="id", sizes=SZ)
def cpq_false(s):
    d, a, b = _run(s, quadratic(), complex_point)
    return {"d∇f = WZᵀ": d - a}


@claim("r81b-rc-true", kind="id", sizes=SZ)
def rc_true(s):
    d, a, b = _run(s, _f(), real_complex_point)
    return {"d∇f = WZᵀ + ZWᵀ": d - a - b}


@claim("r81b-rc-false", kind="id", sizes=SZ)
def rc_false(s):
    d, a, b = _run(s, _f(), real_complex_point)
    return {"d∇f = WZᵀ": d - a}


# no derivative: the check alone at a realified point (exact and modular take the value's gradient by reverse mode,
# float and ball from a basis)
@claim("r81b-cp0-true", kind="id", sizes=SZ)
def cp0_true(s):
    Z = s.Zc
    return {"∇f(ZZᵀ) = ZZᵀ": _f().grad(s, Z @ Z.T) - Z @ Z.T}


@claim("r81b-cp0-false", kind="id", sizes=SZ)
def cp0_false(s):
    Z = s.Zc
    return {"∇f(ZZᵀ) = 2ZZᵀ": _f().grad(s, Z @ Z.T) - Z @ Z.T * 2}
