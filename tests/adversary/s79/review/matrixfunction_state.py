"""The library's MatrixFunction builders call the claim's callable once for the value and again for the gradient
(linear(a): value <x, a(s)>, gradient a(s); f.scaled(c): value f·c(s), gradient ∇f·c(s)), and nothing holds the
calls to one function (as quadratic's operator and checked_tensor's form are held).  A callable with state is K
on its first call, 0 (or 1) after.

gl(n), <a, b> = -½tr(ab); Λ the Lie-Poisson tensor <x, [a, b]>; K, b, x, y generic.
  If f(y) = <y, K> for a generic y, then ∇f = K and {f, <·,b>}(x) = <x, [K, b]> ≠ 0 (generic K, b, x).
  s79-linear-state-contradiction:  "f(y) = <y, K>" and "{f, <·,b>}(x) = 0"                        (FALSE)
  s79-scaled-state-contradiction:  g = (½<·,·>).scaled(c), c = λ on its first call, 0 after (λ = s.scalar):
                                   "g(y) = λ/2 <y, y>" and "∇g(x) = 0"  (FALSE: ∇g(x) = λx)
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, lie_poisson, linear, quadratic

SZ = admissible(n_min=3, n_max=3)


@claim("s79-linear-state-contradiction", kind="id", sizes=SZ)
def lin(s):
    K = GL_N.generic(s, "K")
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    calls = []

    def a(t):
        calls.append(1)
        return K if len(calls) == 1 else K * 0
    f = linear(a)
    val = f(s, y) - s.killing(y, K)
    br = lie_poisson(GL_N).bracket(s, f, linear(lambda t: b), x)
    return {"f(y) = <y, K>": val, "{f, <.,b>}(x) = 0": br}


@claim("s79-scaled-state-contradiction", kind="id", sizes=SZ)
def scaled(s):
    lam = s.scalar("lam")
    x, y = GL_N.generic(s, "x"), GL_N.generic(s, "y")
    calls = []

    def c(t):
        calls.append(1)
        return lam if len(calls) == 1 else lam * 0
    g = quadratic().scaled(c)
    return {"g(y) = λ/2 <y, y>": g(s, y) - s.killing(y, y) * lam / 2, "∇g(x) = 0": g.grad(s, x)}
