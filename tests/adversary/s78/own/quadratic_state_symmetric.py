"""A stateful operator that is symmetric at every call but not the same at every call: the gradient's evaluation
sees S (symmetric), the value's the identity.  No function h satisfies both residuals; refused."""
from stiefelsym import admissible, claim
from stiefelsym.backends.matrix import comm
from stiefelsym.brackets import GL_N, lie_poisson, linear, quadratic

SZ = admissible(n_max=3, n_min=3)


@claim("o78-quad-state-sym-contradiction", kind="id", sizes=SZ)
def contradiction(s):
    S = s.generic("S", "n", "n", "sym")
    calls = []

    def op(t, y):
        calls.append(1)
        return S @ y if len(calls) <= 2 else y
    h = quadratic(op)
    x, b, y = GL_N.generic(s, "x"), GL_N.generic(s, "b"), GL_N.generic(s, "y")
    br = lie_poisson(GL_N).bracket(s, h, linear(lambda t: b), x)
    return {"{h,g}(x) = <x,[Sx,b]>": br - s.killing(x, comm(S @ x, b)),
            "h(y) = ½<y,y>": h(s, y) - s.killing(y, y) / 2}
