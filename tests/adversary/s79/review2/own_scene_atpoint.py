"""W2 without derivatives: the problem at another point s1 = twisted.at_point(s, X1, P1) of T*V, with
X1 = H X, P1 = H P (H = I − 2vvᵀ/vᵀv, a reflection: X1ᵀX1 = I, X1ᵀP1 + P1ᵀX1 = XᵀP + PᵀX = 0).
h = linear(a), a(t) = X Xᵀ with X = t.X (s1's point) or s.X (the claim's), by a mode the claim switches.
For ONE function h(u) = <u, a(t)>, ∇h = a(t) on the scene s1: h_{s1}(y) = <y, ∇h_{s1}(y)>.
  s79r2-own-atpoint-contradiction:  h_{s1}(y) = <y, X1X1ᵀ> and ∇h_{s1}(y) = XXᵀ   FALSE at r < n (X1X1ᵀ = HXXᵀH ≠
                                    XXᵀ: the first makes a(s1) = X1X1ᵀ, <,> nondegenerate on gl(n)); TRUE at r = n
                                    (XXᵀ = I = X1X1ᵀ): so (3,3) is no wrong verdict
  s79r2-own-atpoint-true:           a reads t.X always: h_{s1}(y) = <y, X1X1ᵀ>, ∇h_{s1}(y) = X1X1ᵀ   TRUE
  s79r2-own-atpoint-false:          a reads t.X always: ∇h_{s1}(y) = XXᵀ             FALSE at r < n, TRUE at r = n
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, linear
from stiefelsym.twisted import at_point

SZ = admissible(n_min=3, n_max=3)


def _setup(s, mode, switch):
    y = GL_N.generic(s, "y")
    v = s.fresh("n", "r")[:, 0:1]
    H = s.In - v @ v.T * 2 / (v.T @ v)[0, 0]
    X1, P1 = H @ s.X, H @ s.P
    s1 = at_point(s, X1, P1)

    def a(t):
        X = t.X if mode[0] == "t" else s.X
        return X @ X.T
    h = linear(a)
    val = h(s1, y)
    if switch:
        mode[0] = "s"
    grad = h.grad(s1, y)
    return y, X1, val, grad


@claim("s79r2-own-atpoint-contradiction", kind="id", sizes=SZ)
def contra(s):
    y, X1, val, grad = _setup(s, ["t"], True)
    return {"h(y) = <y, X1X1ᵀ>": val - s.killing(y, X1 @ X1.T), "∇h(y) = XXᵀ": grad - s.X @ s.X.T}


@claim("s79r2-own-atpoint-true", kind="id", sizes=SZ)
def true_(s):
    y, X1, val, grad = _setup(s, ["t"], False)
    return {"h(y) = <y, X1X1ᵀ>": val - s.killing(y, X1 @ X1.T), "∇h(y) = X1X1ᵀ": grad - X1 @ X1.T}


@claim("s79r2-own-atpoint-false", kind="id", sizes=SZ)
def false_(s):
    y, X1, val, grad = _setup(s, ["t"], False)
    return {"h(y) = <y, X1X1ᵀ>": val - s.killing(y, X1 @ X1.T), "∇h(y) = XXᵀ": grad - s.X @ s.X.T}
