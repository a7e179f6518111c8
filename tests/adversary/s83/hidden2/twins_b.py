"""h4 hidden trial, batch b: false twins."""
from __future__ import annotations

from stiefelsym import claim, det, twisted
from stiefelsym.systems import (complex_coordinates, complex_point, coupled_point, derivative, double_point,
                                euler_lagrange, hermitian_entries, re_trace, realify_real, stiefel_pairs_flow)

from _h4common import ANY, R1, R_GE2, R_LT_N, H_kappa, Phi_eta, star, deq_tangent, L_dual_dbl


def _G(s):
    return s.generic("G", "r", "r", "skew")


@claim("h4t-mag-affine-in-F", kind="id", sizes=ANY)
def mag_affine_in_F(s):
    """Twin: the flow(0) term dropped (linear instead of affine): residual −flow(0) = −(Dirac flow) ≠ 0."""
    f12 = twisted.flow(s, H_kappa, F=s.eta + _G(s))
    f1 = twisted.flow(s, H_kappa, F=s.eta)
    f2 = twisted.flow(s, H_kappa, F=_G(s))
    return {"X": f12.Xdot - f1.Xdot - f2.Xdot, "P": f12.Pdot - f1.Pdot - f2.Pdot}


@claim("h4t-mag-form-of-flows", kind="pb", sizes=R_LT_N)
def mag_form_of_flows(s):
    """Twin: ω_F(X_f, X_g) = +{f, g}_F (sign); {f, g} = −tr(XᵀAξX)... ≠ 0 for r < n."""
    f = lambda t: t.killing(Phi_eta(t), t.xi)
    Xf = twisted.flow(s, f, F=s.eta)
    Xg = twisted.flow(s, H_kappa, F=s.eta)
    u = {"X": Xf.Xdot, "P": Xf.Pdot}
    v = {"X": Xg.Xdot, "P": Xg.Pdot}
    return {"omega(Xf, Xg) - {f, g}": twisted.form(s, u, v, F=s.eta) - twisted.bracket(s, f, H_kappa, F=s.eta)}


def _T_c(t, v):
    return re_trace(t, star(v["Z"]) @ v["Z"]) / 2


def _U_c(t, q):
    return re_trace(t, star(q["Z"]) @ realify_real(t, t.A) @ q["Z"]) / 2


def _W0(t, q):
    return hermitian_entries(star(q["Z"]) @ q["Z"] - realify_real(t, t.Ir))


@claim("h4t-complex-energy", kind="pb", sizes=R_LT_N)
def complex_energy(s):
    """Twin: the Lagrangian T − U (sign of the potential); true at r = n (ZZ* = I), so stated for r < n."""
    z = complex_point(s)
    acc, _ = euler_lagrange(s, _T_c, _U_c, _W0, {"Z": z["Z"]}, {"Z": z["Zdot"]}, complex_coordinates(s, ["Z"]))
    tan = {"Z": z["Zdot"], "Zdot": acc["Z"]}
    E = lambda t, w: _T_c(t, {"Z": w["Zdot"]}) - _U_c(t, {"Z": w["Z"]})
    return {"dE/dt": derivative(s, E, z, tan)}


@claim("h4t-double-det-r1", kind="pb", sizes=R1)
def double_det_r1(s):
    """Twin: the printed (I − λA)⁻¹ off the diagonal."""
    z = double_point(s)
    return {"d det L/dt": derivative(s, lambda t, w: det(t, L_dual_dbl(t, w, True)), z, deq_tangent(s, z))}


def _Hk(t, z):
    c = t.q(1, 2) + t.kappa
    K1, K2 = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    return (t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(K1 @ K1) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(K2 @ K2)
            + t.tr(z["X"].T @ t.A @ z["Y"]))


@claim("h4t-coupled-K-rate", kind="id", sizes=R_GE2)
def coupled_K_rate(s):
    """Twin: the same rate said for every κ (the flow of H_κ): the terms −2κ(XPᵀXYᵀ + XYᵀQYᵀ) are nonzero for r ≥ 2."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, _Hk, z, [("X", "P"), ("Y", "Q")])
    X, P, Y, Q = s.X, s.P, s.Y, s.Q
    return {"d(XY^T)/dt": derivative(s, lambda t, w: w["X"] @ w["Y"].T, z, fl)
            - ((P @ X.T - X @ P.T) @ X @ Y.T - X @ Y.T @ (Q @ Y.T - Y @ Q.T))}
