"""False claims with an obvious one-step fix (a sign, a factor 2, a transpose), for mutate --corrections; and a
true claim.  Truth in each docstring (by hand: XᵀX = I_r, XᵀP skew on T*V, Φ, Ψ skew)."""
from stiefelsym import admissible, claim


@claim("r2-c-sign", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="a sign",
       statement=r"\Psi = X^T P + P^T X")
def sign(s):
    """Ψ = XᵀP + PᵀX: FALSE (Ψ = XᵀP − PᵀX); one-step fix: the sign of PᵀX."""
    return {"Psi": s.Psi - (s.X.T @ s.P + s.P.T @ s.X)}


@claim("r2-c-factor", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="a factor",
       statement=r"X^T P = \Psi")
def factor(s):
    """XᵀP = Ψ: FALSE (Ψ = 2XᵀP on T*V, since PᵀX = −XᵀP); one-step fix: a factor 2 (2XᵀP = Ψ or XᵀP = Ψ/2)."""
    return {"XtP": s.X.T @ s.P - s.Psi}


@claim("r2-c-transpose", kind="id", sizes=admissible(n_max=3), fails_at=lambda n, r: True, erratum="a transpose",
       statement=r"\Phi X = P - X X^T P")
def transpose(s):
    """ΦX = P − XXᵀP: FALSE for r ≥ 1 (ΦX = PXᵀX − XPᵀX = P + X XᵀP since PᵀX = −XᵀP); fix: the sign of XXᵀP."""
    return {"PhiX": s.Phi @ s.X - (s.P - s.X @ s.X.T @ s.P)}
