"""s81 hidden2 (h81b): probes of the metric realization's multipliers and of the appendix points (not paper
statements; p81b-* true, q81b-* false).  numpy: indep_probes.py.in."""
from __future__ import annotations

from stiefelsym import admissible, claim
from stiefelsym.systems import complex_point, ctranspose, double_point, realify_real

SMALL = admissible(n_max=4)
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2")
R_LT_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")


def H_A(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


def geo(s):
    flow = s.dirac_flow(H_A)
    Lam = s.X.T @ flow.Pdot
    M = s.X.T @ s.Ainv @ s.X
    C = s.P.T @ s.Ainv @ s.Ainv @ s.P
    return Lam, M, C


@claim("p81b-metric-lambda-trace", kind="id", realization="metric", sizes=SMALL)
def metric_lambda_trace(s):
    """tr(ΛM) = −tr(PᵀA⁻²P) along (A_XP): the trace of ΛM + MΛ + 2PᵀA⁻²P = 0."""
    Lam, M, C = geo(s)
    return {"tr(Lambda M) + tr C": s.tr(Lam @ M) + s.tr(C)}


@claim("q81b-metric-lambda-commutes", kind="id", realization="metric", sizes=R_GE_2, fails_at=lambda n, r: (n, r) != (2, 2),
       erratum="false: Λ does not commute with M = XᵀA⁻¹X for r ≥ 2")
def metric_lambda_commutes(s):
    """False: ΛM = MΛ."""
    Lam, M, C = geo(s)
    return {"Lambda M - M Lambda": Lam @ M - M @ Lam}


@claim("q81b-metric-lambda-half", kind="id", realization="metric", sizes=R_GE_2, fails_at=lambda n, r: (n, r) != (2, 2),
       erratum="false: ΛM = −PᵀA⁻²P needs [Λ, M] = 0")
def metric_lambda_half(s):
    """False: ΛM + PᵀA⁻²P = 0."""
    Lam, M, C = geo(s)
    return {"Lambda M + C": Lam @ M + C}


@claim("q81b-metric-lambda-standard", kind="id", realization="metric", sizes=SMALL, fails_at=lambda n, r: n > 1,
       erratum="false: the standard realization's Λ = −PᵀP")
def metric_lambda_standard(s):
    """False: Λ = −PᵀA⁻¹P (the multiplier of a unit-A formula)."""
    Lam, M, C = geo(s)
    return {"Lambda + P^T A^-1 P": Lam + s.P.T @ s.Ainv @ s.P}


@claim("p81b-double-projector", kind="id", sizes=SMALL)
def double_projector(s):
    """YXᵀY = Y and XYᵀX = X (XᵀY = I)."""
    z = double_point(s)
    X, Y = z["X"], z["Y"]
    return {"Y X^T Y - Y": Y @ X.T @ Y - Y, "X Y^T X - X": X @ Y.T @ X - X}


@claim("q81b-double-x-orthonormal", kind="id", sizes=SMALL, fails_at=lambda n, r: True,
       erratum="false: X of the double system is not orthonormal")
def double_x_orthonormal(s):
    """False: YXᵀX = Y (would need XᵀX = I)."""
    z = double_point(s)
    X, Y = z["X"], z["Y"]
    return {"Y X^T X - Y": Y @ X.T @ X - Y}


@claim("p81b-complex-projector", kind="id", sizes=SMALL)
def complex_projector(s):
    """ZZ*Z = Z on W(n, r) (Z*Z = I)."""
    Z = complex_point(s)["Z"]
    return {"Z Z* Z - Z": Z @ Z.T @ Z - Z}


@claim("q81b-complex-plain-transpose", kind="id", sizes=SMALL, fails_at=lambda n, r: True,
       erratum="false: ZᵀZ (no conjugate) is not I_r")
def complex_plain_transpose(s):
    """False: ZᵀZ = I_r (plain transpose, ctranspose)."""
    Z = complex_point(s)["Z"]
    return {"Z^T Z - I": ctranspose(s, Z) @ Z - realify_real(s, s.Ir)}
