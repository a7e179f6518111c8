"""s81 hidden2 (h81b): more probes of the appendix points under free/exact (q81b-* false, p81b-* true)."""
from __future__ import annotations

from stiefelsym import admissible, claim, comm
from stiefelsym.systems import complex_point, ctranspose, derivative, double_point

from claims import flow_double, M_double, Phi_c

SMALL = admissible(n_max=4)
R_LT_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")


@claim("q81b-double-xyt-lax", kind="id", sizes=R_LT_N, fails_at=lambda n, r: True,
       erratum="false: d(XYᵀ)/dt = [M, XYᵀ] needs XᵀX = I")
def double_xyt_lax(s):
    """False (r < n): d(XYᵀ)/dt = [M, XYᵀ] (the projector in the other order)."""
    z = double_point(s)
    f = lambda t, w: w["X"] @ w["Y"].T
    return {"d(XY^T)/dt - [M, XY^T]": derivative(s, f, z, flow_double(s, z)) - comm(M_double(s, z), f(s, z))}


@claim("p81b-double-xyt-lax", kind="id", sizes=SMALL)
def double_xyt_lax_true(s):
    """True: d(XYᵀ)/dt = [XYᵀ, Mᵀ]... written as d(XYᵀ)/dt = ẊYᵀ + XẎᵀ = −[Mᵀ, XYᵀ] with Mᵀ = XẎᵀ − ẊYᵀ
    (transpose of d(YXᵀ)/dt = [M, YXᵀ])."""
    z = double_point(s)
    f = lambda t, w: w["X"] @ w["Y"].T
    Mt = M_double(s, z).T
    return {"d(XY^T)/dt + [M^T, XY^T]": derivative(s, f, z, flow_double(s, z)) + comm(Mt, f(s, z))}


@claim("q81b-double-xtx", kind="id", sizes=SMALL, fails_at=lambda n, r: True, erratum="false: XᵀX ≠ I")
def double_xtx(s):
    """False: XᵀX = I_r for the double point."""
    z = double_point(s)
    return {"X^T X - I": z["X"].T @ z["X"] - s.Ir}


@claim("q81b-complex-phi-hermitian", kind="id", sizes=SMALL, fails_at=lambda n, r: True,
       erratum="false: Φ_c is anti-Hermitian, not Hermitian")
def complex_phi_hermitian(s):
    """False: Φ_c = Φ_c* (it is anti-Hermitian and nonzero)."""
    z = complex_point(s)
    F = Phi_c(s, z)
    return {"Phi_c - Phi_c*": F - F.T}


@claim("q81b-complex-phi-symmetric", kind="id", sizes=SMALL, fails_at=lambda n, r: True,
       erratum="false: Φ_c is not complex-antisymmetric (Φ_cᵀ ≠ −Φ_c)")
def complex_phi_symmetric(s):
    """False: Φ_cᵀ = −Φ_c with the plain transpose (true only for real data)."""
    z = complex_point(s)
    F = Phi_c(s, z)
    return {"Phi_c + Phi_c^T": F + ctranspose(s, F)}
