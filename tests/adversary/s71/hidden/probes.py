# ruff: noqa
"""API probes: what a reader would write for the blocks of the proofs at X0 = (E_1 … E_r)."""
from stiefelsym import admissible, block, claim


@claim("p71-generic-n-minus-r", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def generic_n_minus_r(s):
    """A generic (n − r) × r block P_2, as in (P-neutral)."""
    P2 = s.generic("P2", "n-r", "r")
    return {"P2 − P2": P2 - P2}


@claim("p71-x0-block", kind="id", sizes=admissible(n_max=3, where=lambda n, r: r < n))
def x0_block(s):
    """X0 = (I_r; 0) as a block matrix, and P0 = (P_1; P_2), P_1 skew: X0ᵀP0 + P0ᵀX0 = 0."""
    Z = s.zeros(s.n - s.r, s.r, ("n-r", "r"))
    X0 = block([[s.Ir], [Z]])
    P0 = block([[s.eta], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    return {"X0ᵀP0 + P0ᵀX0": X0.T @ P0 + P0.T @ X0}
