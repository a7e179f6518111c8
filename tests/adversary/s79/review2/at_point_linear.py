"""same_scene_function / same_inline_function check a call only on a TraceScene of the running trace; a callable
called on another scene object (the problem at another point, twisted.at_point) might escape the hold.
h = linear(a), a stateful (K at its first call, 2K after); s1 = at_point(s, X, P) (the same point).
For ONE function h(u) = <u, a(t)>, ∇h = a(t) on the scene t = s1:
  s79r2-atpoint-linear-contradiction:  h_{s1}(y) = <y, K>  and  ∇h_{s1}(y) = 2K      FALSE (K generic, ≠ 0)
  s79r2-atpoint-linear-true:           a ≡ K: h_{s1}(y) = <y, K> and ∇h_{s1}(y) = K    TRUE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, linear
from stiefelsym.twisted import at_point

SZ = admissible(n_min=3, n_max=3)


def _h(s, stateful):
    K = GL_N.generic(s, "K")
    calls = [0]

    def a(t):
        calls[0] += 1
        return K if (calls[0] == 1 or not stateful) else K * 2
    return K, linear(a)


@claim("s79r2-atpoint-linear-contradiction", kind="id", sizes=SZ)
def contra(s):
    K, h = _h(s, True)
    y = GL_N.generic(s, "y")
    s1 = at_point(s, s.X, s.P)
    return {"h(y) = <y, K>": h(s1, y) - s.killing(y, K), "∇h(y) = 2K": h.grad(s1, y) - K * 2}


@claim("s79r2-atpoint-linear-true", kind="id", sizes=SZ)
def true_(s):
    K, h = _h(s, False)
    y = GL_N.generic(s, "y")
    s1 = at_point(s, s.X, s.P)
    return {"h(y) = <y, K>": h(s1, y) - s.killing(y, K), "∇h(y) = K": h.grad(s1, y) - K}
