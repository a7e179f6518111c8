"""For `stiefelsym discover FILE:flow_still --lax FILE:L_identity`: L = Iₙ commutes with every matrix and is
conserved, so every element of the search space is a Lax partner: the space of solutions is the whole space
(dimension N), and each of its N directions is verified (N + 1 runs per method)."""


def L_identity(s):
    """Iₙ."""
    return s.In


def L_XXt(s):
    """XXᵀ."""
    return s.X @ s.X.T


def flow_still(s):
    """Ẋ = 0, Ṗ = XΨ."""
    return {"X": s.X * 0, "P": s.X @ s.Psi}
