"""Honest claims a mathematician would write, where a declared gradient (or quadratic's operator) is checked along
a flow or inside a gradient: are they still decided after the change (false refusals)?  Each with a false twin.

T = Lie–Poisson on gl(n), {f, g}(x) = <x, [∇f, ∇g]>, <a, b> = −½tr(ab).
 h = quadratic(u ↦ Au + uA): <y, Az + zA> = −½tr(yAz + yzA) = <z, Ay + yA> (tr(zAy) = tr(yzA), tr(zyA) = tr(yAz)),
   so op is linear and symmetric and ∇h(x) = Ax + xA.  g = <·, b>.  {h, g}(x) = <x, [Ax + xA, b]>.
 x_t = t.X t.Xᵀ, flow X + εV.  Both sides of each claim are the same function of t, so their derivatives agree:
   r81-nat-d-true:  d/dε {h, g}(x_t) = d/dε <x_t, [A x_t + x_t A, b]>      TRUE
   r81-nat-d-false: d/dε {h, g}(x_t) = d/dε <x_t, [A x_t, b]>              FALSE (differs by d<x_t,[x_t A, b]>, ≠ 0)
 The same along the Dirac flow of the Neumann Hamiltonian H = ½tr(PᵀP) + ½tr(XᵀAX), at Φ instead of x_t
 (Φ is not conserved by this flow for generic A; along the geodesic flow ½tr(PᵀP) alone it is, and both sides'
 derivatives would vanish):
   r81-nat-flow-true / -false (false for r < n only: at r = n the potential ½tr(A XXᵀ) = ½tr A is constant on
   O(n), the flow is geodesic and Φ is conserved, so both sides have derivative 0).
 Gradient (s.gradient) of the same function of the scene, against the gradient of its explicit form:
   r81-nat-grad-true / -false.
 A MatrixFunction on n×r matrices: k(Y) = −½tr(YᵀY), dk(δ) = −tr(Yᵀδ) = <2Yᵀ, δ>, declared ∇k = 2Yᵀ (r×n);
 d/dε ∇k(t.X) along V = 2Vᵀ:
   r81-nat-nr-true:  d∇k(X) = 2Vᵀ    TRUE ;   r81-nat-nr-false: d∇k(X) = Vᵀ    FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, MatrixFunction, lie_poisson, linear, quadratic

SZ = admissible(n_min=3, n_max=3)
T = lie_poisson(GL_N)


def _hg(s):
    b = GL_N.generic(s, "b")
    h = quadratic(lambda t, u: t.A @ u + u @ t.A, "½<x, Ax + xA>")
    g = linear(lambda t: b)
    return b, h, g


def _sides(s, point):
    b, h, g = _hg(s)
    F = lambda t: T.bracket(t, h, g, point(t))
    E = lambda t: t.killing(point(t), comm(t.A @ point(t) + point(t) @ t.A, b))
    W = lambda t: t.killing(point(t), comm(t.A @ point(t), b))
    return F, E, W


def _xt(t):
    return t.X @ t.X.T


@claim("r81-nat-d-true", kind="id", sizes=SZ)
def d_true(s):
    F, E, W = _sides(s, _xt)
    V = s.fresh("n", "r")
    return {"d{h,g} = dE": s.d(F, {"X": V}) - s.d(E, {"X": V})}


@claim("r81-nat-d-false", kind="id", sizes=SZ)
def d_false(s):
    F, E, W = _sides(s, _xt)
    V = s.fresh("n", "r")
    return {"d{h,g} = dW": s.d(F, {"X": V}) - s.d(W, {"X": V})}


def _H(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("r81-nat-flow-true", kind="id", sizes=SZ)
def flow_true(s):
    F, E, W = _sides(s, lambda t: t.Phi)
    fl = s.dirac_flow(_H)
    return {"d{h,g}(Φ) = dE": s.d(F, fl) - s.d(E, fl)}


@claim("r81-nat-flow-false", kind="id", sizes=SZ)
def flow_false(s):
    F, E, W = _sides(s, lambda t: t.Phi)
    fl = s.dirac_flow(_H)
    return {"d{h,g}(Φ) = dW": s.d(F, fl) - s.d(W, fl)}


@claim("r81-nat-grad-true", kind="id", sizes=SZ)
def grad_true(s):
    F, E, W = _sides(s, _xt)
    a, c = s.gradient(F), s.gradient(E)
    return {"∇_X F = ∇_X E": a[0] - c[0]}


@claim("r81-nat-grad-false", kind="id", sizes=SZ)
def grad_false(s):
    F, E, W = _sides(s, _xt)
    a, c = s.gradient(F), s.gradient(W)
    return {"∇_X F = ∇_X W": a[0] - c[0]}


def _k():
    return MatrixFunction(lambda t, y: t.tr(y.T @ y) * (-1) / 2, lambda t, y: y.T * 2, "−½tr(YᵀY)")


@claim("r81-nat-nr-true", kind="id", sizes=SZ)
def nr_true(s):
    V = s.fresh("n", "r")
    return {"d∇k(X) = 2Vᵀ": s.d(lambda t: _k().grad(t, t.X), {"X": V}) - V.T * 2}


@claim("r81-nat-nr-false", kind="id", sizes=SZ)
def nr_false(s):
    V = s.fresh("n", "r")
    return {"d∇k(X) = Vᵀ": s.d(lambda t: _k().grad(t, t.X), {"X": V}) - V.T}
