"""Free tangent scene, a value that is not a Dual there: FreeScene.declared_gradient_holds strips the Dual parts of
x and G (`point`, free/scene.py) and refuses a value that is a Dual (the commit's (c)); a value that does not read the
tangent scene (the constant 0, or a constant of the claim's scene) is no Dual, so G's Dual part is never compared.

h(t, y) = 0 on every scene: ∇h = 0 at every y, on every scene, so along any flow d/dε ∇h(t_ε, x) = 0 (TRUE).
Declared gradient K(t) = t.X t.Xᵀ t.X t.Xᵀ − t.X t.Xᵀ: 0 on V(n, r) (XᵀX = I), right at the claim's point; along the
ambient flow X + εV its derivative is  dK = V XᵀX Xᵀ + X VᵀX Xᵀ + X XᵀV Xᵀ + X XᵀX Vᵀ − V Xᵀ − X Vᵀ
                                            = X (VᵀX + XᵀV) Xᵀ   (XᵀX = I),  ≠ 0 for generic V.
  r81-fk-false:  d∇h(x) = X(VᵀX + XᵀV)Xᵀ    FALSE  (truth: 0)
  r81-fk-true:   d∇h(x) = 0                  TRUE
  r81-fk-ctrl:   d K(t) = X(VᵀX + XᵀV)Xᵀ     TRUE   (control: the engine differentiates K ambiently)
The same with h(t, y) = s.q(0) (the claim's scene's zero): r81-fq-false / r81-fq-true.
The same through lie_poisson's bracket: {h, <., b>}(x) = <x, [∇h, b]> = 0 for h = 0 on every scene, so
d/dε {h, <·, b>} = 0 (TRUE, r81-fkb-true); the engine's would be <x, [dK, b]> (FALSE twin r81-fkb-false).
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction, lie_poisson, linear

SZ = admissible(n_min=3, n_max=3)


def K(t):
    XX = t.X @ t.X.T
    return XX @ XX - XX


def dK(s, V):
    return s.X @ (V.T @ s.X + s.X.T @ V) @ s.X.T


def _f0(s):
    return MatrixFunction(lambda t, y: 0, lambda t, y: K(t), "0")


def _fq(s):
    return MatrixFunction(lambda t, y: s.q(0), lambda t, y: K(t), "0")


def _d(s, f):
    x = GL_N.generic(s, "x")
    V = s.fresh("n", "r")
    return V, s.d(lambda t: f.grad(t, x), {"X": V})


@claim("r81-fk-false", kind="id", sizes=SZ)
def fk_false(s):
    V, d = _d(s, _f0(s))
    return {"d∇h(x) = X(VᵀX + XᵀV)Xᵀ": d - dK(s, V)}


@claim("r81-fk-true", kind="id", sizes=SZ)
def fk_true(s):
    V, d = _d(s, _f0(s))
    return {"d∇h(x) = 0": d}


@claim("r81-fk-ctrl", kind="id", sizes=SZ)
def fk_ctrl(s):
    V = s.fresh("n", "r")
    return {"dK = X(VᵀX + XᵀV)Xᵀ": s.d(K, {"X": V}) - dK(s, V)}


@claim("r81-fq-false", kind="id", sizes=SZ)
def fq_false(s):
    V, d = _d(s, _fq(s))
    return {"d∇h(x) = X(VᵀX + XᵀV)Xᵀ": d - dK(s, V)}


@claim("r81-fq-true", kind="id", sizes=SZ)
def fq_true(s):
    V, d = _d(s, _fq(s))
    return {"d∇h(x) = 0": d}


def _br(s):
    f = _f0(s)
    x, b = GL_N.generic(s, "x"), GL_N.generic(s, "b")
    V = s.fresh("n", "r")
    T = lie_poisson(GL_N)
    g = linear(lambda t: b)
    return x, b, V, s.d(lambda t: T.bracket(t, f, g, x), {"X": V})


@claim("r81-fkb-false", kind="id", sizes=SZ)
def fkb_false(s):
    x, b, V, d = _br(s)
    D = dK(s, V)
    return {"d{h, <.,b>}(x) = <x, [dK, b]>": d - s.killing(x, D @ b - b @ D)}


@claim("r81-fkb-true", kind="id", sizes=SZ)
def fkb_true(s):
    x, b, V, d = _br(s)
    return {"d{h, <.,b>}(x) = 0": d}
