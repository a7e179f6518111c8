"""Free tangent scene: FreeScene.declared_gradient_holds strips the Dual parts of x and G (`point`) and refuses a
value that is a Dual; a value that is NOT a Dual on the tangent scene (a constant of the claim: python 0, a value
of the claim's scene s) passes with G's Dual part never compared.

h(t, y) = 0 (the zero function on every scene): its gradient is 0 at every y, on every scene, so along any flow
d/dε ∇h(t_ε, x) = 0.   Declared gradient: (t, y) ↦ (t.X − s.X) s.Xᵀ: equals 0 at the claim's scene (t = s), its
derivative along X + εV is V Xᵀ ≠ 0.  (The declared gradient is right at the point only, not along the flow.)
  r81-fz-false:   d∇h(x) = V Xᵀ        FALSE  (the true derivative is 0; V Xᵀ ≠ 0 for generic V, X)
  r81-fz-true:    d∇h(x) = 0           TRUE
Same with h(t, y) = <s.X s.Xᵀ, s.A> (a constant of the claim's scene: gradient 0):
  r81-fc-false / r81-fc-true.
Same with h(t, y) = <y, s.X s.Xᵀ> (reads y and the claim's scene only): ∇h = s.X s.Xᵀ on every scene (a constant of
the derivative), declared (t, y) ↦ t.X s.Xᵀ: d∇h = 0 (true), V Xᵀ (false):  r81-fs-false / r81-fs-true.
Controls: the honest declared gradient 0: d∇h = 0 (true) / = V Xᵀ (false): r81-fh-true / r81-fh-false.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def _d(s, f):
    x = GL_N.generic(s, "x")
    V = s.fresh("n", "r")
    return V, s.d(lambda t: f.grad(t, x), {"X": V})


def _zero(s):
    return MatrixFunction(lambda t, y: 0, lambda t, y: (t.X - s.X) @ s.X.T, "0")


def _const(s):
    return MatrixFunction(lambda t, y: s.killing(s.X @ s.X.T, s.A),
                          lambda t, y: (t.X - s.X) @ s.X.T, "c")


def _sval(s):
    return MatrixFunction(lambda t, y: s.killing(y, s.X @ s.X.T), lambda t, y: t.X @ s.X.T, "<y, XXᵀ>")


def _honest(s):
    return MatrixFunction(lambda t, y: 0, lambda t, y: (t.X - t.X) @ t.X.T, "0")


@claim("r81-fz-false", kind="id", sizes=SZ)
def fz_false(s):
    V, d = _d(s, _zero(s))
    return {"d∇h(x) = VXᵀ": d - V @ s.X.T}


@claim("r81-fz-true", kind="id", sizes=SZ)
def fz_true(s):
    V, d = _d(s, _zero(s))
    return {"d∇h(x) = 0": d}


@claim("r81-fc-false", kind="id", sizes=SZ)
def fc_false(s):
    V, d = _d(s, _const(s))
    return {"d∇h(x) = VXᵀ": d - V @ s.X.T}


@claim("r81-fc-true", kind="id", sizes=SZ)
def fc_true(s):
    V, d = _d(s, _const(s))
    return {"d∇h(x) = 0": d}


@claim("r81-fs-false", kind="id", sizes=SZ)
def fs_false(s):
    V, d = _d(s, _sval(s))
    return {"d∇h(x) = VXᵀ": d - V @ s.X.T}


@claim("r81-fs-true", kind="id", sizes=SZ)
def fs_true(s):
    V, d = _d(s, _sval(s))
    return {"d∇h(x) = 0": d}


@claim("r81-fh-true", kind="id", sizes=SZ)
def fh_true(s):
    V, d = _d(s, _honest(s))
    return {"d∇h(x) = 0": d}


@claim("r81-fh-false", kind="id", sizes=SZ)
def fh_false(s):
    V, d = _d(s, _honest(s))
    return {"d∇h(x) = VXᵀ": d - V @ s.X.T}
