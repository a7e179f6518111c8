"""W2's class through systems.derivative (like={"F": "point"}): one stateful F, two derivative calls, the second
point given with its keys in the other order.

F(t, z) = c·tr(z_Xᵀ A z_X), c = 1 at the first call and 2 after (a mode the claim flips).
d/dε F(z + ε·(P, 0)) = 2c·tr(XᵀAP)  (A symmetric).
ld4-order-false: d1 = 2 tr(XᵀAP) and d2 = 4 tr(XᵀAP) for ONE function F: needs tr(XᵀAP) = 0, which is false at a
   generic point (e.g. n = 3, r = 2: tr(XᵀAP) is a nonzero polynomial on T*V): FALSE.
ld4-same-order: the same with the keys in the same order (held: refused).
ld4-control: two F objects (c = 1, c = 2): TRUE.
"""
from stiefelsym import admissible, claim
from stiefelsym.systems import derivative

SZ = admissible(n_max=3, n_min=2)


def _contra(s, reverse):
    mode = [1]

    def F(t, z):
        return t.tr(z["X"].T @ t.A @ z["X"]) * mode[0]
    d1 = derivative(s, F, {"X": s.X, "P": s.P}, {"X": s.P})
    mode[0] = 2
    z2 = {"P": s.P, "X": s.X} if reverse else {"X": s.X, "P": s.P}
    d2 = derivative(s, F, z2, {"X": s.P})
    e = s.tr(s.X.T @ s.A @ s.P)
    return {"d1": d1 - 2 * e, "d2": d2 - 4 * e}


@claim("ld4-order-false", kind="id", sizes=SZ)
def ld4_order(s):
    """FALSE (module docstring)."""
    return _contra(s, True)


@claim("ld4-same-order", kind="id", sizes=SZ)
def ld4_same(s):
    """FALSE, keys in the same order."""
    return _contra(s, False)


@claim("ld4-control", kind="id", sizes=SZ)
def ld4_control(s):
    """TRUE: two F objects."""
    d1 = derivative(s, lambda t, z: t.tr(z["X"].T @ t.A @ z["X"]), {"X": s.X, "P": s.P}, {"X": s.P})
    d2 = derivative(s, lambda t, z: t.tr(z["X"].T @ t.A @ z["X"]) * 2, {"P": s.P, "X": s.X}, {"X": s.P})
    e = s.tr(s.X.T @ s.A @ s.P)
    return {"d1": d1 - 2 * e, "d2": d2 - 4 * e}
