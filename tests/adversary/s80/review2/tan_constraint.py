"""The same hole as tan_grad.py without a closure: the declared gradient differs from the value's by a term that
vanishes on V(n, r) (X(XᵀX − I)Xᵀ), so the check, made at the base point only, passes (exact: the point is on
V(n, r); free: modulo XᵀX = I); its derivative along a V off the tangent space, or the ambient gradient s.gradient
(reverse mode / the derivative of the IR), is not 0.  The engine takes every other function ambiently: the honest
controls (the term written in the claim) give d[X(XᵀX − I)Xᵀ] = X(VᵀX + XᵀV)Xᵀ ≠ 0.

h(t, y) = ½<y, y> for every scene: ∇h(t, y) = y for every t, so d/dε ∇h(t_ε, x) = 0 along every V.
Declared: G(t, y) = y + K(t), K(t) = t.X (t.Xᵀ t.X − I) t.Xᵀ.
  h4-con-d-false:       d∇h(x) along V = X(VᵀX + XᵀV)Xᵀ        FALSE (it is 0)
  h4-con-d-truetwin:    d∇h(x) along V = 0                     TRUE
  h4-con-ctrl-true:     d K along V = X(VᵀX + XᵀV)Xᵀ            TRUE (the engine's ambient derivative, control)
  h4-con-grad-false:    s.gradient(<∇h(x), B>)_X = gradient of <K, B> (≠ 0)      FALSE (H = <x, B> has ∂H/∂X = 0)
  h4-con-grad-truetwin: s.gradient(<∇h(x), B>)_X = 0                              TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def K(t):
    return t.X @ (t.X.T @ t.X - t.Ir) @ t.X.T


def _f():
    return MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y + K(t), "½<y, y>")


def _dK(s, V):
    X = s.X
    return X @ (V.T @ X + X.T @ V) @ X.T


@claim("h4-con-d-false", kind="id", sizes=SZ)
def d_false(s):
    f, x, V = _f(), GL_N.generic(s, "x"), s.fresh("n", "r")
    return {"d∇h(x) = X(VᵀX + XᵀV)Xᵀ": s.d(lambda t: f.grad(t, x), {"X": V}) - _dK(s, V)}


@claim("h4-con-d-truetwin", kind="id", sizes=SZ)
def d_true(s):
    f, x, V = _f(), GL_N.generic(s, "x"), s.fresh("n", "r")
    return {"d∇h(x) = 0": s.d(lambda t: f.grad(t, x), {"X": V})}


@claim("h4-con-ctrl-true", kind="id", sizes=SZ)
def ctrl(s):
    V = s.fresh("n", "r")
    return {"dK = X(VᵀX + XᵀV)Xᵀ": s.d(lambda t: K(t), {"X": V}) - _dK(s, V)}


def _grads(s):
    f, x, B = _f(), GL_N.generic(s, "x"), GL_N.generic(s, "B")
    HX, HP = s.gradient(lambda t: t.killing(f.grad(t, x), B))
    KX, KP = s.gradient(lambda t: t.killing(K(t), B))
    return HX, KX


@claim("h4-con-grad-false", kind="id", sizes=SZ)
def g_false(s):
    HX, KX = _grads(s)
    return {"∂<∇h(x), B>/∂X = ∂<K, B>/∂X": HX - KX}


@claim("h4-con-grad-truetwin", kind="id", sizes=SZ)
def g_true(s):
    HX, KX = _grads(s)
    return {"∂<∇h(x), B>/∂X = 0": HX}
