"""The one-function hold lets the claim's own scene stand for a call's scene (trace.py `_with_own`): a value
the function reads from the claim's scene (s.X, a CONSTANT of every derived scene, guide "Functions handed to
the scene") and one it reads from the scene it is called on (t.X, which MOVES along the flow of s.d) trace to
the same graph.  An op that reads t.X at the value's call and s.X at the gradient's is then held "one function".

h = quadratic(op), op(t, u) = c·u with c = X₁₁ (t's or s's, by a mode the claim switches), y generic in gl(n),
V generic n×r; s.d(F, {"X": V}) = d/dε F(X + εV).
Truth (by hand): for ONE function h(t, u) = ½ c(t) <u, u> with ∇h(t, u) = c(t) u (any c of the scene):
   A:  d/dε h(t, y)          = ½ ċ <y, y>
   B:  d/dε <y, ∇h(t, y)>    = ċ <y, y>
so A = ½ B always.
  s79r2-own-scene-contradiction:  A = ½ V₁₁ <y, y>  and  B = 0   (needs ċ = V₁₁ and ċ<y,y> = 0, <y,y> ≠ 0: FALSE)
  s79r2-own-scene-moving-true:    op reads t.X at every call: A = ½ V₁₁<y,y> and B = V₁₁<y,y>            TRUE
  s79r2-own-scene-const-true:     op reads s.X at every call: A = 0 and B = 0                            TRUE
  s79r2-own-scene-moving-false:   op reads t.X at every call: A = ½ V₁₁<y,y> and B = 0                   FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _h(s, mode):
    def op(t, u):
        c = (t.X if mode[0] == "t" else s.X)[0, 0]
        return u * c
    return quadratic(op)


def _AB(s, mode, switch):
    y = GL_N.generic(s, "y")
    V = s.fresh("n", "r")
    h = _h(s, mode)
    A = s.d(lambda t: h(t, y), {"X": V})
    if switch:
        mode[0] = "s"
    B = s.d(lambda t: t.killing(y, h.grad(t, y)), {"X": V})
    return y, V, A, B


@claim("s79r2-own-scene-contradiction", kind="id", sizes=SZ)
def contra(s):
    y, V, A, B = _AB(s, ["t"], True)
    return {"A = ½ V11 <y, y>": A - V[0, 0] * s.killing(y, y) / 2, "B = 0": B}


@claim("s79r2-own-scene-moving-true", kind="id", sizes=SZ)
def moving_true(s):
    y, V, A, B = _AB(s, ["t"], False)
    return {"A = ½ V11 <y, y>": A - V[0, 0] * s.killing(y, y) / 2, "B = V11 <y, y>": B - V[0, 0] * s.killing(y, y)}


@claim("s79r2-own-scene-const-true", kind="id", sizes=SZ)
def const_true(s):
    y, V, A, B = _AB(s, ["s"], False)
    return {"A = 0": A, "B = 0": B}


@claim("s79r2-own-scene-moving-false", kind="id", sizes=SZ)
def moving_false(s):
    y, V, A, B = _AB(s, ["t"], False)
    return {"A = ½ V11 <y, y>": A - V[0, 0] * s.killing(y, y) / 2, "B = 0": B}
