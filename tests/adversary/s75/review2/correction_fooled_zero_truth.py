"""The truth behind correction_fooled_zero.py.in: the 'printed formula' ½·XXᵀAX + x·XXᵀAX − XPᵀP
(x = 1/2 + p₁p₂p₃) does NOT keep T*V (FALSE), while XXᵀAX − XPᵀP does (TRUE)."""
from fractions import Fraction
from stiefelsym import claim

X_BIG = Fraction(1, 2) + (2**61 - 1) * (2**62 - 57) * (2**60 - 93)


def _residual(s, c):
    M = s.X @ s.X.T @ s.A @ s.X * c - s.X @ s.P.T @ s.P
    tangent = {"X": s.P, "P": -(s.A @ s.X) + M}
    return {"d(XᵀP + PᵀX)/dt": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, tangent)}


@claim("r2-fooled-zero-printed", kind="id", sizes=[(4, 2)])
def fooled_printed(s):
    """The printed formula of correction_fooled_zero keeps XᵀP + PᵀX = 0 (FALSE)."""
    return _residual(s, Fraction(1, 2) + X_BIG)


@claim("r2-fooled-zero-true", kind="id", sizes=[(4, 2)])
def fooled_true(s):
    """XXᵀAX − XPᵀP keeps XᵀP + PᵀX = 0 (TRUE)."""
    return _residual(s, 1)
