"""s81 hidden2 (h81b): false identities of the appendix points that a wrong rewriting rule would prove (q81b-*)."""
from __future__ import annotations

from stiefelsym import admissible, claim

from stiefelsym.systems import complex_point, double_point, realify_real

R_LT_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")
SMALL = admissible(n_max=4)


@claim("q81b-double-xyt-identity", kind="id", sizes=R_LT_N, fails_at=lambda n, r: True, erratum="false for r < n")
def double_xyt_identity(s):
    """False (r < n): XYᵀ = I_n."""
    z = double_point(s)
    return {"XY^T - I_n": z["X"] @ z["Y"].T - s.In}


@claim("q81b-double-gram-product", kind="id", sizes=SMALL, fails_at=lambda n, r: True, erratum="false")
def double_gram_product(s):
    """False: (XᵀX)(YᵀY) = I_r."""
    z = double_point(s)
    X, Y = z["X"], z["Y"]
    return {"(X^T X)(Y^T Y) - I": (X.T @ X) @ (Y.T @ Y) - s.Ir}


@claim("q81b-double-velocity-orthogonal", kind="id", sizes=SMALL, fails_at=lambda n, r: True, erratum="false")
def double_velocity_orthogonal(s):
    """False: ẊᵀY = 0 (only ẊᵀY + XᵀẎ = 0 holds)."""
    z = double_point(s)
    return {"Xdot^T Y": z["Xdot"].T @ z["Y"]}


@claim("p81b-double-velocity-trace", kind="id", sizes=SMALL)
def double_velocity_trace(s):
    """True: tr(ẊᵀY) = −tr(XᵀẎ)."""
    z = double_point(s)
    return {"tr Xdot^T Y + tr X^T Ydot": (z["Xdot"].T @ z["Y"]).trace() + (z["X"].T @ z["Ydot"]).trace()}


@claim("q81b-complex-zzt-identity", kind="id", sizes=R_LT_N, fails_at=lambda n, r: True, erratum="false for r < n")
def complex_zzt(s):
    """False (r < n): ZZ* = I_n."""
    Z = complex_point(s)["Z"]
    return {"ZZ* - I": Z @ Z.T - realify_real(s, s.In)}


@claim("q81b-complex-velocity-zero", kind="id", sizes=SMALL, fails_at=lambda n, r: True, erratum="false")
def complex_velocity(s):
    """False: Z*Ż = 0 (only its Hermitian part vanishes)."""
    z = complex_point(s)
    return {"Z* Zdot": z["Z"].T @ z["Zdot"]}


@claim("p81b-complex-velocity-antihermitian", kind="id", sizes=SMALL)
def complex_velocity_ah(s):
    """True: Z*Ż + (Z*Ż)* = 0."""
    z = complex_point(s)
    M = z["Z"].T @ z["Zdot"]
    return {"Z* Zdot + (Z* Zdot)*": M + M.T}
