"""R1 through quadratic (one argument, but the op reads its scene): op(u) = M u + u M, M = XXᵀ of the scene the op
is called on (linear, symmetric for <,>: <y, Mz + zM> = −½tr(yMz + yzM) = <z, My + yM>).  The value h(M) =
½<M, 2M²> = <M, M²>: the argument M = s.X @ s.X.T IS the node the op builds from its scene.
  s79r2-quad-at-M-true:   h(M) = <M, M²>  and  ∇h(y) = My + yM    TRUE
  s79r2-quad-at-M-false:  h(M) = 0        and  ∇h(y) = My + yM    FALSE at r < n? <M, M²> = −½tr(M³) = −½ r ≠ 0 (M
                          a projection of rank r: M³ = M, tr M = r): FALSE at every size
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _h(s):
    return quadratic(lambda t, u: (t.X @ t.X.T) @ u + u @ (t.X @ t.X.T))


@claim("s79r2-quad-at-M-true", kind="id", sizes=SZ)
def at_M_true(s):
    h, y, M = _h(s), GL_N.generic(s, "y"), s.X @ s.X.T
    return {"h(M) = <M, M²>": h(s, M) - s.killing(M, M @ M), "∇h(y) = My + yM": h.grad(s, y) - (M @ y + y @ M)}


@claim("s79r2-quad-at-M-false", kind="id", sizes=SZ)
def at_M_false(s):
    h, y, M = _h(s), GL_N.generic(s, "y"), s.X @ s.X.T
    return {"h(M) = 0": h(s, M), "∇h(y) = My + yM": h.grad(s, y) - (M @ y + y @ M)}
