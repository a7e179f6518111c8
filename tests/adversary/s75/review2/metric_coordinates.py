"""Metric-realization claims that read coordinates (no equivariance): the exact method's chart text at r < n and
r = n, and the verdicts (XᵀA⁻¹P + PᵀA⁻¹X = 0 TRUE; its (1,1) entry TRUE; (XᵀP)₁₂ + (XᵀP)₂₁ = 0 FALSE)."""
from stiefelsym import claim

SZ = [(3, 2), (3, 3), (4, 1)]


@claim("r2-metric-coord-true", kind="id", realization="metric", sizes=SZ)
def metric_coord_true(s):
    """The (1,1) entry of XᵀA⁻¹P + PᵀA⁻¹X is 0, with X's first entry read."""
    M = s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X
    return {"w": M * s.X[0, 0]}


@claim("r2-metric-coord-false", kind="id", realization="metric", sizes=SZ)
def metric_coord_false(s):
    """XᵀP + PᵀX = 0 times X's first entry, in the metric realization: FALSE."""
    return {"w": (s.X.T @ s.P + s.P.T @ s.X) * s.X[0, 0]}
