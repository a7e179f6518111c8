"""Stop 73's own attempt on the exact method's new order: tiny budgets, a residual that is zero at the chart's
origin only, a nonvanishing claim that vanishes identically, and their true twins."""
from stiefelsym import admissible, claim


@claim("s73-own-origin-false", kind="id", sizes=admissible(n_max=4))
def origin_false(s):
    """X₁₁ = 1: it holds at the chart's origin X = (E_1..E_r) only: FALSE."""
    return {"X11": s.X[0, 0] - s.q(1)}


@claim("s73-own-nonzero-false", kind="id", sizes=admissible(n_max=4), expect="nonzero")
def nonzero_false(s):
    """XᵀX − I_r is not identically zero: FALSE (it vanishes on V)."""
    return {"XtX - I": s.X.T @ s.X - s.Ir}


@claim("s73-own-true", kind="id", sizes=admissible(n_max=4))
def own_true(s):
    """Ψ = XᵀP − PᵀX is skew: TRUE."""
    Psi = s.X.T @ s.P - s.P.T @ s.X
    return {"Psi + Psi^T": Psi + Psi.T}
