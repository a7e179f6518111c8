"""User flows and Lax matrices for `stiefelsym discover` (not a claims file: functions only)."""


def zero_flow(s):
    """Ẋ = 0, Ṗ = 0: every function is conserved."""
    return {"X": s.X - s.X, "P": s.P - s.P}


def scaled_geodesic(s):
    """Ẋ = P, Ṗ = −X PᵀP (the Euclidean geodesic flow's Ẋ, and Ṗ of the normal metric's at r = 1)."""
    return {"X": s.P, "P": -(s.X @ s.P.T @ s.P)}


def rotation_flow(s):
    """Ẋ = ΞX, Ṗ = ΞP with Ξ = A P Xᵀ − X Pᵀ A (skew): conserves the O(n)-invariant traces tr(PᵀP),
    tr(XᵀP), ..., but not those with A."""
    Xi = s.A @ s.P @ s.X.T - s.X @ s.P.T @ s.A
    return {"X": Xi @ s.X, "P": Xi @ s.P}


def hamiltonian_kinetic(s):
    return s.tr(s.P.T @ s.P) / 2


def lax_const(s):
    """L(λ) = A + λ I: constant along every flow; any A(λ) commuting with L is a partner."""
    return s.A + s.lam * s.In
