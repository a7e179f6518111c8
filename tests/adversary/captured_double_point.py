"""Attacks on the fix of route O (a function handed to the free scene gets fresh letters): the derivative
at a point of the double system (X, Y, Xdot, Ydot), where the free scene differentiates F(t, z) as a
polynomial in the point's own letters, so a captured value of the scene's (its DY) is moved with z."""
from stiefelsym import admissible, claim, systems

ALL = admissible(n_max=4, n_min=2)


@claim("adv-captured-double-derivative", kind="id", sizes=ALL,
       statement="d/de tr(DY^T z_X) along (X, -Y, Xdot, -Ydot) at the double point is 0, DY the scene's (captured)")
def captured_double_derivative(s):
    """False for DY the constant it is: the derivative is tr(DY^T DX) = tr(I_r) = r, not 0."""
    point = {"X": s.DX, "Y": s.DY, "Xdot": s.DXdot, "Ydot": s.DYdot}
    tangent = {"X": s.DX, "Y": -s.DY, "Xdot": s.DXdot, "Ydot": -s.DYdot}
    DY = s.DY
    return {"r": systems.derivative(s, lambda t, z: t.tr(DY.T @ z["X"]), point, tangent)}


@claim("adv-captured-double-control", kind="id", sizes=ALL,
       statement="d/de tr(z_Y^T z_X) along (X, -Y, Xdot, -Ydot) at the double point is 0 (true: X^T Y = I_r)")
def captured_double_control(s):
    """True: tr(Y^T X) = r on the constraint set, and the tangent keeps it."""
    point = {"X": s.DX, "Y": s.DY, "Xdot": s.DXdot, "Ydot": s.DYdot}
    tangent = {"X": s.DX, "Y": -s.DY, "Xdot": s.DXdot, "Ydot": -s.DYdot}
    return {"r": systems.derivative(s, lambda t, z: t.tr(z["Y"].T @ z["X"]), point, tangent)}

