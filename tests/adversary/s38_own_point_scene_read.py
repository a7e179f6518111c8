"""Round 8: systems.derivative(s, F, point, tangent) is d/dε F(t, point + ε·tangent): only the point handed to F
moves, F's scene t (its X, P, Y, Q) does not.  On the dimension-free scene at its own point (the point is the
scene's letters) the derivative moved the scene's letters with the point, so a function that reads t.X as well as
its argument was differentiated twice: a false statement proved for every n, r that every coordinate scene refutes."""
from stiefelsym import admissible, claim
from stiefelsym import systems

SZ = admissible(n_max=4)


def reads_its_scene(t, z):
    """tr(t.Xᵀ A z_X): the scene's X (not moved) against the point's."""
    return t.tr(t.X.T @ t.A @ z["X"])


def reads_both(t, z):
    return t.tr(t.X.T @ t.A @ z["X"]) + t.tr(t.P.T @ z["P"])


@claim("adv-s38-own-point-scene-read", kind="id", sizes=SZ)
def own_point_scene_read(s):
    """d/dε tr(Xᵀ A (X + εP)) = tr(XᵀAP) at the point {X, P} along (P, ·) (true: t.X is not moved)."""
    d = systems.derivative(s, reads_its_scene, {"X": s.X, "P": s.P}, {"X": s.P})
    return {"d": d - s.tr(s.X.T @ s.A @ s.P)}


@claim("adv-s38-own-point-scene-read-false", kind="id", sizes=SZ)
def own_point_scene_read_false(s):
    """... = 2 tr(XᵀAP) (false: what moving t.X with the point gives)."""
    d = systems.derivative(s, reads_its_scene, {"X": s.X, "P": s.P}, {"X": s.P})
    return {"d": d - 2 * s.tr(s.X.T @ s.A @ s.P)}


@claim("adv-s38-coupled-point-scene-read-false", kind="id", sizes=SZ)
def coupled_point_scene_read_false(s):
    """At the coupled point {X, P, Y, Q} along (P, X, 0, 0): 2 tr(XᵀAP) + 2 tr(PᵀX) (false: it is
    tr(XᵀAP) + tr(PᵀX), and tr(PᵀX) = 0 on T*V)."""
    z = {"X": s.X, "P": s.P, "Y": s.Y, "Q": s.Q}
    d = systems.derivative(s, reads_both, z, {"X": s.P, "P": s.X})
    return {"d": d - 2 * s.tr(s.X.T @ s.A @ s.P) - 2 * s.tr(s.P.T @ s.X)}
