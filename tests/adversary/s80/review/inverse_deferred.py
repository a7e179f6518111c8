"""check_calls runs when the claim's dict is built, BEFORE the Inverse statements of the dict are traced
(trace.py: t.check_calls(), then t.inverse(v) for each Inverse): a held object called by an Inverse's op or inv
is recorded and never held.

g = quadratic().scaled(c), c a scalar of the scene: g(x) = ½c<x, x>, ∇g(x) = c·x.  c returns 1 at its first call
and 2 after (a mode the claim flips once its dict's other checks are made).
Truth (by hand), for ONE function c of the scene (the claim's own scene at every call here):
  "∇g(y0) = y0" at a generic y0 forces c(s) = 1, so op(y) = ∇g(y) = y and inv(op(x)) = x/2 ≠ x.
  s80r-inv-deferred-contradiction: {∇g(y0) − y0, Inverse(op = ∇g, inv = y ↦ y/2 on R^{n×r})}    FALSE
  s80r-inv-deferred-control-true:  the same with two objects g1 (c = 1), g2 (c = 2)                 TRUE
  s80r-inv-deferred-honest-false:  one stateless g (c = 1)                                          FALSE (refuted)
  s80r-inv-inside-contradiction:   the state flipped INSIDE the Inverse (op's first call c = 1 (calls of c in the
                                   Inverse alone), inv reads c too)                                 FALSE
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import quadratic
from stiefelsym.ir.statements import Inverse

SZ = admissible(n_min=3, n_max=3)


@claim("s80r-inv-deferred-contradiction", kind="id", sizes=SZ)
def contra(s):
    mode = [1]
    g = quadratic().scaled(lambda t: mode[0])
    y0 = s.generic("y0", "n", "r")
    first = g.grad(s, y0) - y0
    mode[0] = 2
    return {"∇g(y0) = y0": first, "∇g inverted by y/2": Inverse(lambda t, y: g.grad(t, y), lambda t, y: y / 2,
                                                                 "R^{n×r}")}


@claim("s80r-inv-deferred-control-true", kind="id", sizes=SZ)
def control(s):
    g1 = quadratic().scaled(lambda t: 1)
    g2 = quadratic().scaled(lambda t: 2)
    y0 = s.generic("y0", "n", "r")
    return {"∇g1(y0) = y0": g1.grad(s, y0) - y0,
            "∇g2 inverted by y/2": Inverse(lambda t, y: g2.grad(t, y), lambda t, y: y / 2, "R^{n×r}")}


@claim("s80r-inv-deferred-honest-false", kind="id", sizes=SZ)
def honest(s):
    g = quadratic().scaled(lambda t: 1)
    y0 = s.generic("y0", "n", "r")
    return {"∇g(y0) = y0": g.grad(s, y0) - y0,
            "∇g inverted by y/2": Inverse(lambda t, y: g.grad(t, y), lambda t, y: y / 2, "R^{n×r}")}


@claim("s80r-inv-inside-contradiction", kind="id", sizes=SZ)
def inside(s):
    calls = []

    def c(t):
        calls.append(1)
        return 1 if len(calls) == 1 else 2
    g = quadratic().scaled(c)
    # op(y) = ∇g(y) − y·(c − 1)... : op's call reads c once (1), inv's reads c (2): op(y) = y, inv(y) = ∇g(y)/4·2
    return {"op = ∇g, inv = ∇g / 4": Inverse(lambda t, y: g.grad(t, y), lambda t, y: g.grad(t, y) / 4, "R^{n×r}")}
