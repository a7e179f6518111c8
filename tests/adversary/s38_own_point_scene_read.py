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


def potential_reads_its_scene(t, z):
    """½tr(z_Pᵀz_P) + tr(t.Xᵀ A z_X): the potential's first factor is the scene's X (its gradient in z_X is AX)."""
    return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(t.X.T @ t.A @ z["X"])


def neumann_own(t, z):
    """½tr(z_Pᵀz_P) + tr(z_Xᵀ A z_X) (its gradient in z_X is 2AX)."""
    return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(z["X"].T @ t.A @ z["X"])


def neumann_half(t, z):
    """½tr(z_Pᵀz_P) + ½tr(z_Xᵀ A z_X) (its gradient in z_X is AX)."""
    return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(z["X"].T @ t.A @ z["X"]) * t.q(1, 2)


@claim("adv-s38-pairs-flow-scene-read", kind="id", sizes=SZ)
def pairs_flow_scene_read(s):
    """The pairs flow of potential_reads_its_scene is the flow of neumann_half (true: both gradients are (AX, P))."""
    z = {"X": s.X, "P": s.P}
    f = systems.stiefel_pairs_flow(s, potential_reads_its_scene, z, [("X", "P")])
    g = systems.stiefel_pairs_flow(s, neumann_half, z, [("X", "P")])
    return {"X": f["X"] - g["X"], "P": f["P"] - g["P"]}


@claim("adv-s38-pairs-flow-scene-read-false", kind="id", sizes=SZ)
def pairs_flow_scene_read_false(s):
    """... is the flow of neumann_own (false: its gradient in X is 2AX)."""
    z = {"X": s.X, "P": s.P}
    f = systems.stiefel_pairs_flow(s, potential_reads_its_scene, z, [("X", "P")])
    g = systems.stiefel_pairs_flow(s, neumann_own, z, [("X", "P")])
    return {"X": f["X"] - g["X"], "P": f["P"] - g["P"]}
