"""Second derivatives through a declared gradient that is right at V(n, r) to first order but not to second:
  f: value ½<y, y> (gradient y for every scene), declared G(u, y) = y + K2(u), K2(u) = X (XᵀX − I)² Xᵀ (X = u.X).
  K2 and its first derivative vanish on V(n, r) (a square of XᵀX − I), its second does not:
    d_V d_W K2 = X (S_V S_W + S_W S_V) Xᵀ on V(n, r), S_V = VᵀX + XᵀV  (≠ 0 for generic V, W).
  x = a generic n×n constant.
  r81b-so1-true:   d_V ∇f(x) = 0                        TRUE (and d_V K2 = 0: also what G gives)
  r81b-so2-true:   d_V d_W ∇f(x) = 0                    TRUE
  r81b-so2-false:  d_V d_W ∇f(x) = X(S_V S_W + S_W S_V)Xᵀ   FALSE
  Hessian route: H(u) = <f.grad(u, x), B> = <x, B> (constant):
  r81b-hs-true:    d_V (∂H/∂X) = 0                      TRUE
  r81b-hs-false:   d_V (∂H/∂X) = d_V ∂<K2, B>/∂X        FALSE (≠ 0)
  gradient of a derivative:
  r81b-gd-true:    ∂/∂X d_W H = 0                       TRUE
  r81b-gd-false:   ∂/∂X d_W H = ∂/∂X d_W <K2, B>        FALSE (≠ 0)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, MatrixFunction

SZ = admissible(n_min=3, n_max=3)


def K2(u):
    E = u.X.T @ u.X - u.Ir
    return u.X @ E @ E @ u.X.T


def _f():
    return MatrixFunction(lambda u, y: u.killing(y, y) / 2, lambda u, y: y + K2(u), "½<y, y>")


def _data(s):
    return GL_N.generic(s, "x"), GL_N.generic(s, "B"), s.fresh("n", "r"), s.fresh("n", "r")


@claim("r81b-so1-true", kind="id", sizes=SZ)
def so1(s):
    x, B, V, W = _data(s)
    f = _f()
    return {"d∇f = 0": s.d(lambda t: f.grad(t, x), {"X": V})}


def _dd(s, x, V, W):
    f = _f()
    return s.d(lambda t: t.d(lambda u: f.grad(u, x), {"X": W}), {"X": V})


@claim("r81b-so2-true", kind="id", sizes=SZ)
def so2_true(s):
    x, B, V, W = _data(s)
    return {"dd∇f = 0": _dd(s, x, V, W)}


@claim("r81b-so2-false", kind="id", sizes=SZ)
def so2_false(s):
    x, B, V, W = _data(s)
    X = s.X
    SV, SW = V.T @ X + X.T @ V, W.T @ X + X.T @ W
    return {"dd∇f = X(SvSw + SwSv)Xᵀ": _dd(s, x, V, W) - X @ (SV @ SW + SW @ SV) @ X.T}


@claim("r81b-hs-true", kind="id", sizes=SZ)
def hs_true(s):
    x, B, V, W = _data(s)
    f = _f()
    return {"d ∂H/∂X = 0": s.d(lambda t: t.gradient(lambda u: u.killing(f.grad(u, x), B))[0], {"X": V})}


@claim("r81b-hs-false", kind="id", sizes=SZ)
def hs_false(s):
    x, B, V, W = _data(s)
    f = _f()
    a = s.d(lambda t: t.gradient(lambda u: u.killing(f.grad(u, x), B))[0], {"X": V})
    b = s.d(lambda t: t.gradient(lambda u: u.killing(K2(u), B))[0], {"X": V})
    return {"d ∂H/∂X = d ∂<K2,B>/∂X": a - b}


@claim("r81b-gd-true", kind="id", sizes=SZ)
def gd_true(s):
    x, B, V, W = _data(s)
    f = _f()
    return {"∂/∂X d_W H = 0": s.gradient(lambda t: t.d(lambda u: u.killing(f.grad(u, x), B), {"X": W}))[0]}


@claim("r81b-gd-false", kind="id", sizes=SZ)
def gd_false(s):
    x, B, V, W = _data(s)
    f = _f()
    a = s.gradient(lambda t: t.d(lambda u: u.killing(f.grad(u, x), B), {"X": W}))[0]
    b = s.gradient(lambda t: t.d(lambda u: u.killing(K2(u), B), {"X": W}))[0]
    return {"∂/∂X d_W H = ∂/∂X d_W <K2,B>": a - b}
