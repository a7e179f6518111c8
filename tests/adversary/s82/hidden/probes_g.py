"""s82 hidden (h2): a point-dependent multiple of eta as field strength (skew by construction; not a closed form,
but the flow is pointwise): the twisted flow of Psi12 at r = 2 is still (XJ, PJ) pointwise (the eps-force eps f X
is absorbed by Lambda), and its twin (XJ^T, PJ^T) is false.  Methods must agree."""
from stiefelsym import admissible, claim, twisted
from _h82_helpers import psi12

R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def _g(s, transpose):
    J = twisted.magnetic_matrix(s)
    F = s.tr(s.P.T @ s.P) * s.eta
    f = twisted.flow(s, psi12, F)
    M = J.T if transpose else J
    return {"X' - XJ": f["X"] - s.X @ M, "P' - PJ": f["P"] - s.P @ M}


@claim("p82g-pointwise-F-psi12", kind="pb", sizes=R2)
def g1(s):
    """Ψ₁₂ flow for F = tr(PᵀP)η is (XJ, PJ)."""
    return _g(s, False)


@claim("p82g-pointwise-F-psi12-twin", kind="pb", sizes=R2, fails_at=lambda n, r: True, erratum="twin")
def g2(s):
    """Twin: (XJᵀ, PJᵀ)."""
    return _g(s, True)
