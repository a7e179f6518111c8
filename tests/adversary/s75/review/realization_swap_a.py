"""Run with this file (realization="metric": XᵀA⁻¹P + PᵀA⁻¹X = 0 is a constraint, so the claim is TRUE), report
with realization_swap_b.py (the same claim in the standard realization, where it is FALSE)."""
from stiefelsym import claim


@claim("s75-realization-swap", kind="id", realization="metric", sizes=[(3, 2)])
def realization_swap(s):
    """XᵀA⁻¹P + PᵀA⁻¹X = 0."""
    return {"w": s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X}
