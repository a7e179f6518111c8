"""Item 2: the Hamiltonian of stiefel_pairs_flow / hamiltonian_flow reads the point through an extra key of its
own variable: the point dict gets "C" = X₀ (a copy of the position, not in the pairs), H(z) = ½tr(PᵀP) +
½tr(XᵀAC) read through z.  The step's check (o78-flow-closure refuses H closing over a point value) sees H read
its own variable only.  Meant: H = ½tr PᵀP + ½tr XᵀAX (C is X), the Neumann Hamiltonian, whose Dirac flow at
a point of T*V is Ẋ = P, Ṗ = −AX + XΛ with Λ = XᵀAX − PᵀP (TRUE).  With C a constant, H_X = ½AC, and the flow
is Ṗ = −½AX + X(½XᵀAX − PᵀP) (the engine's; FALSE for the Hamiltonian meant)."""
from stiefelsym import claim
from stiefelsym.systems import stiefel_pairs_flow, hamiltonian_flow, symmetric_entries

PAIRS = [("X", "P")]
SZ = [(2, 1), (3, 1), (3, 2)]


def H(t, z):
    return t.tr(z["P"].T @ z["P"]) / 2 + t.tr(z["X"].T @ t.A @ z["C"]) / 2


def _flow(s):
    X, P = s.X, s.P
    return stiefel_pairs_flow(s, H, {"X": X, "P": P, "C": X}, PAIRS), X, P, s.A


@claim("r3-pairs-extra-true", kind="id", sizes=SZ)
def pairs_true(s):
    f, X, P, A = _flow(s)
    Lam = X.T @ A @ X - P.T @ P
    return {"Xdot": f["X"] - P, "Pdot": f["P"] - (-(A @ X) + X @ Lam)}


@claim("r3-pairs-extra-false", kind="id", sizes=SZ)
def pairs_false(s):
    f, X, P, A = _flow(s)
    Lam = X.T @ A @ X / 2 - P.T @ P
    return {"Xdot": f["X"] - P, "Pdot": f["P"] - (-(A @ X) / 2 + X @ Lam)}


def F(t, z):
    X, P = z["X"], z["P"]
    return symmetric_entries(X.T @ X - t.Ir) + symmetric_entries(X.T @ P + P.T @ X)


@claim("r3-hflow-extra-true", kind="id", sizes=SZ)
def hflow_true(s):
    X, P, A = s.X, s.P, s.A
    f, _ = hamiltonian_flow(s, H, F, {"X": X, "P": P, "C": X}, PAIRS)
    Lam = X.T @ A @ X - P.T @ P
    return {"Xdot": f["X"] - P, "Pdot": f["P"] - (-(A @ X) + X @ Lam)}


@claim("r3-hflow-extra-false", kind="id", sizes=SZ)
def hflow_false(s):
    X, P, A = s.X, s.P, s.A
    f, _ = hamiltonian_flow(s, H, F, {"X": X, "P": P, "C": X}, PAIRS)
    Lam = X.T @ A @ X / 2 - P.T @ P
    return {"Xdot": f["X"] - P, "Pdot": f["P"] - (-(A @ X) / 2 + X @ Lam)}
