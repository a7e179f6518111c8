"""The own-scene route (own_scene_tangent.py) through brackets.linear and MatrixFunction.scaled, whose
callables are held by same_scene_function (the claim's own scene standing for every call's scene).
h = linear(a), a(t) = X Xᵀ with X = t.X (moves along {"X": V}) or s.X (a constant of the derived scene) by a
mode the claim switches.  For ONE function h(t, u) = <u, a(t)>, ∇h = a(t):
   A = d/dε h(t, y) = <y, ȧ>,   B = d/dε <y, ∇h(t, y)> = <y, ȧ>:  A = B,  ȧ = V Xᵀ + X Vᵀ.
  s79r2-own-linear-contradiction:  A = <y, VXᵀ + XVᵀ> and B = 0       FALSE (<y, VXᵀ + XVᵀ> ≠ 0 generically)
  s79r2-own-linear-true:           a reads t.X always: A = B = <y, VXᵀ + XVᵀ>   TRUE
  s79r2-own-scaled-contradiction:  g = quadratic().scaled(c), c(t) = tr(XᵀKX) (t.X or s.X):
                                   A = ½ ċ <y, y> and B = 0              FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, linear, quadratic

SZ = admissible(n_min=3, n_max=3)


def _lin(s, mode, switch):
    y = GL_N.generic(s, "y")
    V = s.fresh("n", "r")

    def a(t):
        X = t.X if mode[0] == "t" else s.X
        return X @ X.T
    h = linear(a)
    A = s.d(lambda t: h(t, y), {"X": V})
    if switch:
        mode[0] = "s"
    B = s.d(lambda t: t.killing(y, h.grad(t, y)), {"X": V})
    adot = V @ s.X.T + s.X @ V.T
    return y, adot, A, B


@claim("s79r2-own-linear-contradiction", kind="id", sizes=SZ)
def lin_contra(s):
    y, adot, A, B = _lin(s, ["t"], True)
    return {"A = <y, ȧ>": A - s.killing(y, adot), "B = 0": B}


@claim("s79r2-own-linear-true", kind="id", sizes=SZ)
def lin_true(s):
    y, adot, A, B = _lin(s, ["t"], False)
    return {"A = <y, ȧ>": A - s.killing(y, adot), "B = <y, ȧ>": B - s.killing(y, adot)}


@claim("s79r2-own-scaled-contradiction", kind="id", sizes=SZ)
def scaled_contra(s):
    y, K = GL_N.generic(s, "y"), GL_N.generic(s, "K")
    V = s.fresh("n", "r")
    mode = ["t"]

    def c(t):
        X = t.X if mode[0] == "t" else s.X
        return t.tr(X.T @ K @ X)
    h = quadratic().scaled(c)
    A = s.d(lambda t: h(t, y), {"X": V})
    mode[0] = "s"
    B = s.d(lambda t: t.killing(y, h.grad(t, y)), {"X": V})
    cdot = s.tr(V.T @ K @ s.X + s.X.T @ K @ V)
    return {"A = ½ ċ <y, y>": A - cdot * s.killing(y, y) / 2, "B = 0": B}
