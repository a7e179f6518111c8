"""h3 hidden statements, §2 in the metric realization (cond_XP2): its constraints are Casimirs of its Dirac bracket."""
from stiefelsym import admissible, claim


def H_lin(t):
    return t.tr(t.generic("U", "n", "r").T @ t.X) + t.tr(t.generic("V", "n", "r").T @ t.P)


def C_metric(t):
    T = t.generic("T", "r", "r", "sym")
    return t.tr(T @ (t.X.T @ t.Ainv @ t.P + t.P.T @ t.Ainv @ t.X))


def C_standard(t):
    T = t.generic("T", "r", "r", "sym")
    return t.tr(T @ (t.X.T @ t.P + t.P.T @ t.X))


@claim("h3-metric-casimir", kind="pb", section="2", realization="metric", sizes=admissible(4))
def metric_casimir(s):
    """In the realization XᵀX = I, XᵀA⁻¹P + PᵀA⁻¹X = 0 the Dirac bracket is built on these constraints, so
    {tr(T(XᵀA⁻¹P + PᵀA⁻¹X)), H} = 0 for every H (the argument of A1)."""
    return {"{G_A, H}": s.bracket(C_metric, H_lin)}


@claim("h3-metric-casimir-twin", kind="pb", section="2", realization="metric", sizes=admissible(4, n_min=2, condition="n >= 2"))
def metric_casimir_twin(s):
    """FALSE twin: the standard realization's constraint XᵀP + PᵀX is not a Casimir there (its bracket with H is
    the derivative of XᵀP + PᵀX along the flow of H, which moves it)."""
    return {"{G, H}": s.bracket(C_standard, H_lin)}
