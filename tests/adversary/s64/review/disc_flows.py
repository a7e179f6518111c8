# ruff: noqa
"""Flows and Hamiltonians of my own for `stiefelsym discover` (r64); no claims here."""


def H_scalar(t):
    """Neumann with a free coefficient c: ½tr PᵀP + c·½tr XᵀAX (c a claim scalar)."""
    c = t.scalar("c")
    return t.tr(t.P.T @ t.P) / 2 + c * t.tr(t.X.T @ t.A @ t.X) / 2


def H_entry(t):
    """A Hamiltonian that reads a coordinate: ½tr PᵀP + X₁₁ (not O(n)-invariant)."""
    return t.tr(t.P.T @ t.P) / 2 + t.X[0, 0]


def flow_not_tangent(t):
    """A 'flow' that leaves T*V: Xdot = X, Pdot = 0."""
    return {"X": t.X, "P": 0 * t.P}
