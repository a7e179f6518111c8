"""Class 3 (exceptions as a side channel), new tricks: catch the engine's refusals (the size door, a refused
attribute, a refused MatrixFunction argument, a checked step's trace-time refusal) and branch on them.

Each -false claim returns XXᵀ − I_n (FALSE at r < n) on the branch that would be taken at one moment and
XᵀX − I_r (TRUE) on the other; a wrong verdict is proved/checked/numeric of the false branch's graph, or a free
proof of a graph that is not the one of the fixed sizes.
"""
from stiefelsym import admissible, claim
from stiefelsym.brackets import MatrixFunction

SZ = admissible(n_max=3, n_min=2)


def _true(s):
    return s.X.T @ s.X - s.Ir


def _false(s):
    return s.X @ s.X.T - s.In


@claim("c3-door-false", kind="id", sizes=SZ)
def c3_door_false(s):
    """FALSE at every stated size (r < n): the size door raises with symbolic sizes, the claim catches it and
    returns the TRUE residual there, the FALSE one at a number."""
    try:
        int(s.n)
    except BaseException:
        return {"r": _true(s)}
    return {"r": _false(s)}


@claim("c3-attr-false", kind="id", sizes=SZ)
def c3_attr_false(s):
    """FALSE: a refused private attribute of a size, caught; the branch taken where it does not raise is false."""
    try:
        s.n.value
    except BaseException:
        return {"r": _false(s)}
    return {"r": _true(s)}


@claim("c3-grad-false", kind="id", sizes=SZ)
def c3_grad_false(s):
    """FALSE: a MatrixFunction whose gradient callable raises on the dimension-free scene's letters (via a refused
    operation) and returns a wrong gradient elsewhere; caught, a false residual."""
    def gradient(t, y):
        try:
            _ = y[0, 0]
        except BaseException:
            return y * 0
        return y * 0
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, gradient)
    try:
        G = h.grad(s, s.X @ s.X.T)
    except BaseException:
        return {"r": _true(s)}
    return {"r": G}


@claim("c3-grad-true", kind="id", sizes=SZ)
def c3_grad_true(s):
    """TRUE: ∇(½<y, y>) = y at y = XXᵀ: residual ∇h − XXᵀ."""
    h = MatrixFunction(lambda t, y: t.killing(y, y) / 2, lambda t, y: y)
    return {"r": h.grad(s, s.X @ s.X.T) - s.X @ s.X.T}
