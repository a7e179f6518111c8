# ruff: noqa
"""Class 1: entries of X read through the unit matrices the engine's systems step hands out
(systems.real_coordinates), through derivatives at a point of one's own, and through blocks.
All FALSE on T*V except where a docstring says true."""
from stiefelsym import admissible, claim, block, systems

S = admissible(n_min=3, n_max=4, r_in=(2,))


@claim("c1u-unit-read", kind="id", sizes=S)
def unit_read(s):
    """false: tr(E11^T X) = 1 (X11 = 1 at X0 only)."""
    coords = systems.real_coordinates(s, ["X"])
    E = coords[0][1]
    return {"x": s.tr(E.T @ s.X) - 1}


@claim("c1u-unit-deriv", kind="id", sizes=S)
def unit_deriv(s):
    """false: d/de tr(X^T X X^T X)(X + e E11) = 4 (it is 4 (X X^T X)_11 = 4 X11 on T*V)."""
    coords = systems.real_coordinates(s, ["X"])
    E = coords[0][1]
    F = lambda t, z: t.tr(z["X"].T @ z["X"] @ z["X"].T @ z["X"])
    return {"x": systems.derivative(s, F, {"X": s.X}, {"X": E}) - 4}


@claim("c1u-unit-block", kind="id", sizes=S)
def unit_block(s):
    """false: the block [E11, X] times [[I],[-I]] has zero first entry...: tr(E11^T (X - E11)) = 0."""
    coords = systems.real_coordinates(s, ["X"])
    E = coords[0][1]
    B = block([[E, s.X]])
    C = B @ block([[-s.Ir], [s.Ir]])      # X - E11
    return {"x": s.tr(E.T @ C)}


@claim("c1u-unit-sum", kind="id", sizes=S)
def unit_sum(s):
    """false: sum over units E of tr(E^T X)^2 computed as tr(X^T X) minus the first unit's square = r - 1
    (tr(E11^T X)^2 = X11^2 = 1 at X0)."""
    coords = systems.real_coordinates(s, ["X"])
    E = coords[0][1]
    a = s.tr(E.T @ s.X)
    return {"x": s.tr(s.X.T @ s.X) - a * a - (s.r - 1)}


@claim("c1u-unit-true", kind="id", sizes=S)
def unit_true(s):
    """true: sum over all units E_ij of tr(E^T X)^2 = tr(X^T X) = r."""
    coords = systems.real_coordinates(s, ["X"])
    acc = 0
    for name, E in coords:
        a = s.tr(E.T @ s.X)
        acc = acc + a * a
    return {"x": acc - s.r}


@claim("c1u-unit-true2", kind="id", sizes=S)
def unit_true2(s):
    """true: tr(E11^T (X X^T X - X)) = 0 (X^T X = I)."""
    coords = systems.real_coordinates(s, ["X"])
    E = coords[0][1]
    return {"x": s.tr(E.T @ (s.X @ s.X.T @ s.X - s.X))}
