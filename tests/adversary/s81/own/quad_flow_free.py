"""Stop 80's quad_flow.py on the dimension-free scene (c(t) = tr(XᵀX − I_r), no size used as a number): an operator
u ↦ u + c(t)u² that is linear and symmetric on V(n, r) (c = 0 there) and not along a flow off it (ċ = 2tr(XᵀV)).
The scene's check compared a dual number's parts as one coefficient and crashed (SympifyError); it now compares
both parts.
  s81-qff-false:    d∇h(x) = ċx²               FALSE (the gradient of ½<y, y + cy²> is y + (3/2)cy²)
  s81-qff-truetwin: d∇h(x) = (3/2)ċx²          TRUE of h; refused (the operator is not linear along the flow)
  s81-qff-honest:   op = c(t)·u (linear, symmetric at every t): d∇h(x) = ċx     TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic
SZ = admissible(n_min=3, n_max=3)
def _c(t):
    return t.tr(t.X.T @ t.X - t.Ir)
def _run(s):
    x, V = GL_N.generic(s, "x"), s.fresh("n", "r")
    h = quadratic(lambda t, u: u + (u @ u) * _c(t))
    cdot = s.tr(s.X.T @ V) * 2
    return s.d(lambda t: h.grad(t, x), {"X": V}), x @ x * cdot
@claim("s81-qff-false", kind="id", sizes=SZ)
def qf_false(s):
    d, w = _run(s)
    return {"d∇h(x) = ċx²": d - w}
@claim("s81-qff-truetwin", kind="id", sizes=SZ)
def qf_true(s):
    d, w = _run(s)
    return {"d∇h(x) = (3/2)ċx²": d - w * s.q(3, 2)}
@claim("s81-qff-honest", kind="id", sizes=SZ)
def qf_h(s):
    x, V = GL_N.generic(s, "x"), s.fresh("n", "r")
    h = quadratic(lambda t, u: u * _c(t))
    return {"d∇h(x) = ċ x": s.d(lambda t: h.grad(t, x), {"X": V}) - x * (s.tr(s.X.T @ V) * 2)}
