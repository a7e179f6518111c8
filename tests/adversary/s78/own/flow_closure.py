"""The flow of pairs of Stiefel points (systems.stiefel_pairs_flow) of a Hamiltonian that reads the point by
another road than its variable z: the second point closed over (z0["Y"] of the claim), or its own scene's Y.
The step differentiates H in z only, so such a reading would be a constant there and the flow that of another
Hamiltonian; refused when traced, under every method.  H(z) = ½tr(PᵀP) + tr(XᵀY)·c with c read through z is
accepted, and its X-component is P."""
from stiefelsym import claim
from stiefelsym.systems import coupled_point, stiefel_pairs_flow

PAIRS = [("X", "P"), ("Y", "Q")]


@claim("o78-flow-closure", kind="id", sizes=[(3, 1), (3, 2)])
def flow_closure(s):
    z0 = coupled_point(s)
    Y = z0["Y"]

    def H(t, z):
        return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(z["X"].T @ Y)
    f = stiefel_pairs_flow(s, H, z0, PAIRS)
    return {"Xdot": f["X"] - z0["P"]}


@claim("o78-flow-own-scene", kind="id", sizes=[(3, 1), (3, 2)])
def flow_own_scene(s):
    z0 = coupled_point(s)

    def H(t, z):
        return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(z["X"].T @ t.Y)
    f = stiefel_pairs_flow(s, H, z0, PAIRS)
    return {"Xdot": f["X"] - z0["P"]}


@claim("o78-flow-through-z-true", kind="id", sizes=[(3, 1), (3, 2)])
def flow_through_z(s):
    z0 = coupled_point(s)

    def H(t, z):
        return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(z["X"].T @ z["Y"])
    f = stiefel_pairs_flow(s, H, z0, PAIRS)
    return {"Xdot": f["X"] - z0["P"]}


@claim("o78-flow-through-z-false", kind="id", sizes=[(3, 2)])
def flow_through_z_false(s):
    z0 = coupled_point(s)

    def H(t, z):
        return t.tr(z["P"].T @ z["P"]) * t.q(1, 2) + t.tr(z["X"].T @ z["Y"])
    f = stiefel_pairs_flow(s, H, z0, PAIRS)
    X, P = z0["X"], z0["P"]
    return {"Xdot": f["X"] - (P - X @ (X.T @ P))}
