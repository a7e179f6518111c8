"""Which chart do the point methods use in the metric realization?  In (cond_XP2) XᵀA⁻¹P is skew and XᵀP is not:
XᵀP + PᵀX = 0 is FALSE there, XᵀA⁻¹P + PᵀA⁻¹X = 0 TRUE."""
from stiefelsym import claim

SZ = [(3, 2), (4, 2)]


@claim("s75-metric-standard-constraint", kind="id", realization="metric", sizes=SZ)
def metric_standard_constraint(s):
    """XᵀP + PᵀX = 0 in the metric realization: FALSE."""
    return {"w": s.X.T @ s.P + s.P.T @ s.X}


@claim("s75-metric-own-constraint", kind="id", realization="metric", sizes=SZ)
def metric_own_constraint(s):
    """XᵀA⁻¹P + PᵀA⁻¹X = 0 in the metric realization: TRUE."""
    return {"w": s.X.T @ s.Ainv @ s.P + s.P.T @ s.Ainv @ s.X}
