"""The claim of realization_swap_a.py in the standard realization: FALSE."""
from stiefelsym import claim


@claim("s75-realization-swap", kind="id", sizes=[(3, 2)])
def realization_swap(s):
    """XᵀA⁻¹P + PᵀA⁻¹X = 0."""
    return {"w": s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X}
