# ruff: noqa
"""Two claims on blocks of R^(n-r) for `stiefelsym mutate`: the tangent block at X0 (true) and P2ᵀP2 read as a
trace (true identity tr(P2ᵀP2) = tr(P2P2ᵀ)).
Run: stiefelsym mutate --claims mut_nr.py --size 4,2 --jobs 1 --report-dir OUT"""
from stiefelsym import admissible, block, claim


@claim("r2m-tangent", kind="id", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def tangent(s):
    """X₀ᵀP₀ + P₀ᵀX₀ = 0 at X₀ = (I_r; 0), P₀ = (η; P₂)."""
    X0 = block([[s.Ir], [s.zeros(s.n - s.r, s.r, ("n-r", "r"))]])
    P0 = block([[s.eta], [s.generic("P2", "n-r", "r")]])
    return {"tan": X0.T @ P0 + P0.T @ X0}


@claim("r2m-trace", kind="id", sizes=admissible(n_max=4, where=lambda n, r: r < n))
def trace(s):
    """tr(P₂ᵀP₂) = tr(P₂P₂ᵀ)."""
    P2 = s.generic("P2", "n-r", "r")
    return {"tr": s.tr(P2.T @ P2) - s.tr(P2 @ P2.T)}
