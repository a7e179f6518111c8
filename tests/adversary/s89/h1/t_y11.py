"""s89h1: the second point (Y, Q) at (1,1), where no parameter enters.

 s89h1-y-is-identity (FALSE at (1,1)): Y = I_1.  T*V(1,1) = {±1} x {0}: Y may be -1.  (Refused by the engine:
   Y is n×r, I_n is n×n: the spaces differ; honest error.  See t_const.py s89h1-y00 for the same statement by entries.)
 s89h1-y-equals-x (FALSE at (1,1)): Y - X = 0  (X = 1, Y = -1 is a point).
 s89h1-xy-product (FALSE at (1,1)): XᵀY = I_1 (det(XᵀY) can be -1).
 s89h1-yy (TRUE at every size): YᵀY = I_r.
"""
from stiefelsym import claim, admissible

ONE = admissible(n_min=1, stated_n_max=1, condition="n = r = 1")


@claim("s89h1-y-is-identity", kind="id", sizes=[(1, 1)])
def y_is_identity(s):
    """Y = I (false at (1,1): Y = -1 is a point)."""
    return {"r": s.Y - s.In}


@claim("s89h1-y-equals-x", kind="id", sizes=[(1, 1)])
def y_equals_x(s):
    """Y = X (false)."""
    return {"r": s.Y - s.X}


@claim("s89h1-xy-product", kind="id", sizes=[(1, 1)])
def xy_product(s):
    """XᵀY = I_1 (false)."""
    return {"r": s.X.T @ s.Y - s.Ir}


@claim("s89h1-yy", kind="id", sizes=[(1, 1), (2, 1), (2, 2)])
def yy(s):
    """YᵀY = I_r (true)."""
    return {"r": s.Y.T @ s.Y - s.Ir}
