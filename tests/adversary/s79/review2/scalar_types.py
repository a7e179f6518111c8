"""same_scene_function holds a callable's value to one graph only when the value is a Tracer, an int or a
Fraction (trace.py ~1696: `type(value) not in (Tracer, int, Fraction)` → returned unchecked).  A scalar of
another Python type — bool (True/False), numpy integers — escapes, so a stateful c of MatrixFunction.scaled
returning True at the value's call and False at the gradient's is not refused.

h = quadratic().scaled(c): for ONE function h(u) = c·½<u, u> (c a constant of the scene), ∇h(u) = c·u.
  s79r2-bool-scaled-contradiction:   h(y) = ½<y, y>  and  ∇h(y) = 0     FALSE (c = 1 and c·y = 0, y generic)
  s79r2-npint-scaled-contradiction:  the same with numpy.int64(1), numpy.int64(0)         FALSE
  s79r2-int-scaled-refused:          the same with Python ints 1, 0 (control: refused)     FALSE
  s79r2-bool-scaled-true:            c always True: h(y) = ½<y, y> and ∇h(y) = y        TRUE
"""
import numpy as np

from stiefelsym import admissible, claim
from stiefelsym.brackets import GL_N, quadratic

SZ = admissible(n_min=3, n_max=3)


def _stateful(first, later):
    calls = [0]

    def c(t):
        calls[0] += 1
        return first if calls[0] == 1 else later
    return c


def _two(s, c):
    y = GL_N.generic(s, "y")
    h = quadratic().scaled(c)
    return y, h(s, y), h.grad(s, y)


@claim("s79r2-bool-scaled-contradiction", kind="id", sizes=SZ)
def bool_contra(s):
    y, v, g = _two(s, _stateful(True, False))
    return {"h(y) = ½<y, y>": v - s.killing(y, y) / 2, "∇h(y) = 0": g}


@claim("s79r2-npint-scaled-contradiction", kind="id", sizes=SZ)
def npint_contra(s):
    y, v, g = _two(s, _stateful(np.int64(1), np.int64(0)))
    return {"h(y) = ½<y, y>": v - s.killing(y, y) / 2, "∇h(y) = 0": g}


@claim("s79r2-int-scaled-refused", kind="id", sizes=SZ)
def int_contra(s):
    y, v, g = _two(s, _stateful(1, 0))
    return {"h(y) = ½<y, y>": v - s.killing(y, y) / 2, "∇h(y) = 0": g}


@claim("s79r2-bool-scaled-true", kind="id", sizes=SZ)
def bool_true(s):
    y, v, g = _two(s, lambda t: True)
    return {"h(y) = ½<y, y>": v - s.killing(y, y) / 2, "∇h(y) = y": g - y}
