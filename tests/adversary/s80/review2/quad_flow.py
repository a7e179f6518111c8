"""The same class through the older zero step symmetric_operator_check (quadratic's op): an op that is linear and
symmetric on V(n, r) (at the base point the check sees) but not along a direction off it.

op(t, u) = u + c(t)·u², c(t) = tr(t.Xᵀ t.X) − r (= 0 on V(n, r); along {X: V}: ċ = 2 tr(XᵀV) ≠ 0 for generic V).
h(t, y) = ½<y, op(t, y)> = ½<y, y> + ½c<y, y²>; with <a, b> = −½tr(ab): d(½<y, y²>) = −¾ tr(y² dy) = <(3/2)y², dy>,
so the gradient of y ↦ h(t, y) is y + (3/2)c(t)·y², and d/dε ∇h(t_ε, x) = (3/2)ċ x², while op gives ċ x².
(The engine differentiates ambiently: tan_constraint.py's control h4-con-ctrl-true.)
  h4-qf-false:     d/dε quadratic(op).grad(t, x) along V = ċ x²         FALSE (it is (3/2)ċ x²)
  h4-qf-truetwin:  the same = (3/2)ċ x²                                  TRUE (whatever h's gradient is, it is the
                   gradient of its value; or, if one reads quadratic's contract as "op is linear": refused — never
                   "fails")
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _c(t):
    return t.tr(t.X.T @ t.X) - t.r


def _run(s):
    x, V = GL_N.generic(s, "x"), s.fresh("n", "r")
    h = quadratic(lambda t, u: u + (u @ u) * _c(t))
    cdot = s.tr(s.X.T @ V) * 2
    return s.d(lambda t: h.grad(t, x), {"X": V}), x @ x * cdot


@claim("h4-qf-false", kind="id", sizes=SZ)
def qf_false(s):
    d, w = _run(s)
    return {"d∇h(x) = ċx²": d - w}


@claim("h4-qf-truetwin", kind="id", sizes=SZ)
def qf_true(s):
    d, w = _run(s)
    return {"d∇h(x) = (3/2)ċx²": d - w * s.q(3, 2)}
