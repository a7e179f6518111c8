"""Lax matrices for `stiefelsym discover neumann-normal --lax FILE:L`: L commutes with itself, so every L in the
search space (words of degree <= 3, at most one A) is a homogeneous solution ("+ any multiple of L").
With L = XXᵀ + cA, c = 2⁴⁰ + 1, the homogeneous solution is XXᵀ + cA (or A + XXᵀ/c), not XXᵀ + c'A for any
other c'."""


def L_small(s):
    """XXᵀ + 3A."""
    return s.X @ s.X.T + s.A * 3


def L_big(s):
    """XXᵀ + (2⁴⁰ + 1)A."""
    return s.X @ s.X.T + s.A * (2**40 + 1)


def flow_still(s):
    """Ẋ = 0, Ṗ = XΨ (tangent: XᵀṖ = Ψ is skew): X does not move, so XXᵀ + cA is conserved and A(λ) = 0 is a
    partner of it; its homogeneous solutions are the matrices of the space that commute with XXᵀ + cA."""
    return {"X": s.X * 0, "P": s.X @ s.Psi}
