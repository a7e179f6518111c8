"""h4 hidden trial, batch b: five more statements of Appendices 1 and 2 (true versions)."""
from __future__ import annotations

from stiefelsym import claim, det, twisted
from stiefelsym.systems import (complex_coordinates, complex_point, coupled_point, derivative, double_point,
                                euler_lagrange, hermitian_entries, re_trace, realify_real, stiefel_pairs_flow)

from _h4common import ANY, R1, H_kappa, Phi_eta, star, deq_tangent, L_dual_dbl


def _G(s):
    """A second generic element of so(r) (s.theta is refused as a field strength: see FINDINGS)."""
    return s.generic("G", "r", "r", "skew")


@claim("h4-mag-affine-in-F", kind="id", sizes=ANY)
def mag_affine_in_F(s):
    """The twisted flow is affine in the field strength: Ẋ = H_P − XΠ does not involve F (Π from XᵀẊ + ẊᵀX = 0),
    Ṗ = −H_X − εẊF + XΛ + PΠ with Λ affine in F (tangency is linear).  So for F₁ = η, F₂ = G (generic skew):
    flow(η + θ) − flow(η) − flow(θ) + flow(0) = 0 (flow(0) written with F = η − η)."""
    f12 = twisted.flow(s, H_kappa, F=s.eta + _G(s))
    f1 = twisted.flow(s, H_kappa, F=s.eta)
    f2 = twisted.flow(s, H_kappa, F=_G(s))
    f0 = twisted.flow(s, H_kappa, F=s.eta - s.eta)
    return {"X": f12.Xdot - f1.Xdot - f2.Xdot + f0.Xdot, "P": f12.Pdot - f1.Pdot - f2.Pdot + f0.Pdot}


@claim("h4-mag-form-of-flows", kind="pb", sizes=ANY)
def mag_form_of_flows(s):
    """ω_F(X_f, X_g) = −{f, g}_F: i_{X_f}ω = −df, so ω(X_f, X_g) = −df(X_g), and {f, g} = df along X_g.
    f = ⟨Φ_F, ξ⟩, g = H_neum,κ, F = η, any rank."""
    f = lambda t: t.killing(Phi_eta(t), t.xi)
    Xf = twisted.flow(s, f, F=s.eta)
    Xg = twisted.flow(s, H_kappa, F=s.eta)
    u = {"X": Xf.Xdot, "P": Xf.Pdot}
    v = {"X": Xg.Xdot, "P": Xg.Pdot}
    return {"omega(Xf, Xg) + {f, g}": twisted.form(s, u, v, F=s.eta) + twisted.bracket(s, f, H_kappa, F=s.eta)}


def _T_c(t, v):
    return re_trace(t, star(v["Z"]) @ v["Z"]) / 2


def _U_c(t, q):
    return re_trace(t, star(q["Z"]) @ realify_real(t, t.A) @ q["Z"]) / 2


def _W0(t, q):
    return hermitian_entries(star(q["Z"]) @ q["Z"] - realify_real(t, t.Ir))


@claim("h4-complex-energy", kind="pb", sizes=ANY)
def complex_energy(s):
    """E = ½Re tr(Ż*Ż) + ½Re tr(Z*AZ) is conserved along the Euler–Lagrange flow of L = T − U with Z*Z = I
    (energy of a natural system with holonomic constraints: dE/dt = Re tr(Ż*(Z̈ + AZ)) = Re tr(Ż*ZΛ) = 0,
    Λ Hermitian, Ż*Z skew-Hermitian)."""
    z = complex_point(s)
    acc, _ = euler_lagrange(s, _T_c, _U_c, _W0, {"Z": z["Z"]}, {"Z": z["Zdot"]}, complex_coordinates(s, ["Z"]))
    tan = {"Z": z["Zdot"], "Zdot": acc["Z"]}
    E = lambda t, w: _T_c(t, {"Z": w["Zdot"]}) + _U_c(t, {"Z": w["Z"]})
    return {"dE/dt": derivative(s, E, z, tan)}


@claim("h4-double-det-r1", kind="pb", sizes=R1)
def double_det_r1(s):
    """r = 1: the Lax matrix (LA3*D) (resolvent in all four blocks) is 2×2 and its determinant is conserved along
    (D-eq) (det is a spectral invariant of d𝓛/dt = [𝓛, 𝓐])."""
    z = double_point(s)
    return {"d det L/dt": derivative(s, lambda t, w: det(t, L_dual_dbl(t, w)), z, deq_tangent(s, z))}


def _H0(t, z):
    """(C-neumann) at κ = 0."""
    K1, K2 = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    return (t.tr(z["P"].T @ z["P"]) / 2 - t.tr(K1 @ K1) / 2 + t.tr(z["Q"].T @ z["Q"]) / 2 - t.tr(K2 @ K2) / 2
            + t.tr(z["X"].T @ t.A @ z["Y"]))


@claim("h4-coupled-K-rate", kind="id", sizes=ANY)
def coupled_K_rate(s):
    """κ = 0: d/dt(XYᵀ) = ẊYᵀ + XẎᵀ with Ẋ = P − XPᵀX, Ẏ = Q − YQᵀY equals
    (PXᵀ − XPᵀ)XYᵀ − XYᵀ(QYᵀ − YQᵀ) = PYᵀ − XPᵀXYᵀ − XYᵀQYᵀ + XQᵀ: the (1,2) block of dK/dt = [M, K]."""
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, _H0, z, [("X", "P"), ("Y", "Q")])
    X, P, Y, Q = s.X, s.P, s.Y, s.Q
    return {"d(XY^T)/dt": derivative(s, lambda t, w: w["X"] @ w["Y"].T, z, fl)
            - ((P @ X.T - X @ P.T) @ X @ Y.T - X @ Y.T @ (Q @ Y.T - Y @ Q.T))}
