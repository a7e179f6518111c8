"""own_scene_tangent.py without entries (for the dimension-free method): c = tr(Xᵀ K X), K generic in gl(n),
ċ along {"X": V} = tr(Vᵀ K X + Xᵀ K V).  h(t, u) = ½ c <u, u>, ∇h = c·u, where c reads t.X (moving) or s.X
(the claim's scene: a constant of the derived scene) by a mode the claim switches between its statements.
Truth (by hand): for one function h, A = d/dε h(y) = ½ ċ <y, y> and B = d/dε <y, ∇h(y)> = ċ <y, y>: A = ½ B.
  s79r2-own-scene-free-contradiction:  A = ½ ċ <y, y>  and  B = 0     FALSE (ċ <y, y> ≠ 0 generically)
  s79r2-own-scene-free-true:           the same op reading t.X always: A = ½ ċ<y,y>, B = ċ<y,y>   TRUE
  s79r2-own-scene-free-false:          op reading t.X always: A = ½ ċ<y,y>, B = 0                 FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _AB(s, mode, switch):
    y, K = GL_N.generic(s, "y"), GL_N.generic(s, "K")
    V = s.fresh("n", "r")

    def op(t, u):
        X = t.X if mode[0] == "t" else s.X
        return u * t.tr(X.T @ K @ X)
    h = quadratic(op)
    A = s.d(lambda t: h(t, y), {"X": V})
    if switch:
        mode[0] = "s"
    B = s.d(lambda t: t.killing(y, h.grad(t, y)), {"X": V})
    cdot = s.tr(V.T @ K @ s.X + s.X.T @ K @ V)
    return y, cdot, A, B


@claim("s79r2-own-scene-free-contradiction", kind="id", sizes=SZ)
def contra(s):
    y, cdot, A, B = _AB(s, ["t"], True)
    return {"A = ½ ċ <y, y>": A - cdot * s.killing(y, y) / 2, "B = 0": B}


@claim("s79r2-own-scene-free-true", kind="id", sizes=SZ)
def true_(s):
    y, cdot, A, B = _AB(s, ["t"], False)
    return {"A = ½ ċ <y, y>": A - cdot * s.killing(y, y) / 2, "B = ċ <y, y>": B - cdot * s.killing(y, y)}


@claim("s79r2-own-scene-free-false", kind="id", sizes=SZ)
def false_(s):
    y, cdot, A, B = _AB(s, ["t"], False)
    return {"A = ½ ċ <y, y>": A - cdot * s.killing(y, y) / 2, "B = 0": B}
