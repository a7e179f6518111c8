"""Helpers of the h4 hidden trial (no claims).  Everything is written from the paper's formulas,
not from proofs/."""
from __future__ import annotations

from stiefelsym import admissible, block
from stiefelsym import twisted
from stiefelsym.systems import (coupled_point, double_point,
                                euler_lagrange, real_coordinates, realify_real, stiefel_pairs_flow)

# ---- sizes -------------------------------------------------------------------------------------
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")
ANY = admissible(n_max=4)
R_GE2 = admissible(n_max=4, r_min=2, condition="r >= 2")
R_GE3 = admissible(n_max=4, r_min=3, condition="r >= 3")
R1 = admissible(n_max=4, r_min=1, r_max=1, condition="r = 1")
R_LT_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")
N_GE2 = admissible(n_max=4, n_min=2, condition="n >= 2")


# ---- Appendix 1 --------------------------------------------------------------------------------
def H_kappa(t):
    """H_neum,κ = ½tr PᵀP − (½+κ)tr (XᵀP)² + ½tr XᵀAX."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_E(t):
    """κ = −½: ½tr PᵀP + ½tr XᵀAX."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_N(t):
    """κ = 0: ½tr PᵀP − ½tr (XᵀP)² + ½tr XᵀAX."""
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - t.tr(K @ K) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def U_pot(t):
    return t.tr(t.X.T @ t.A @ t.X) / 2


def Phi_e(t):
    """Φ_ε = Φ + ε X J Xᵀ with J = E1∧E2 (r = 2)."""
    J = twisted.magnetic_matrix(t)
    return t.Phi + t.eps * (t.X @ J @ t.X.T)


def Phi_eta(t):
    """Φ_F with F = η: Φ + εXηXᵀ."""
    return t.Phi + t.eps * (t.X @ t.eta @ t.X.T)


def L_mag(t, sign=-1):
    return t.lam * Phi_e(t) + t.X @ t.X.T + sign * (t.lam * t.lam) * t.A


# ---- Appendix 2: double -------------------------------------------------------------------------
def T_dbl(t, v):
    return t.tr(v["X"].T @ v["Y"])


def U_dbl(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def el_double_tangent(s):
    """The tangent (Ẋ, Ẏ, Ẍ, Ÿ) at the double point, Ẍ, Ÿ from the Euler–Lagrange equations."""
    z = double_point(s)
    acc, _ = euler_lagrange(s, T_dbl, U_dbl, D0, {"X": z["X"], "Y": z["Y"]},
                            {"X": z["Xdot"], "Y": z["Ydot"]}, real_coordinates(s, ["X", "Y"]))
    return z, {"X": z["Xdot"], "Y": z["Ydot"], "Xdot": acc["X"], "Ydot": acc["Y"]}


def Lam_dbl(t, z):
    """(D-L): Λ = XᵀAY − ẊᵀẎ."""
    return z["X"].T @ t.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]


def deq_tangent(t, z):
    """(D-eq) typed: Ẍ = −AX + XΛᵀ, Ÿ = −AY + YΛ."""
    Lam = Lam_dbl(t, z)
    return {"X": z["Xdot"], "Y": z["Ydot"], "Xdot": -(t.A @ z["X"]) + z["X"] @ Lam.T,
            "Ydot": -(t.A @ z["Y"]) + z["Y"] @ Lam}


def L_dual_dbl(t, z, flipped=False):
    """(LA3*D), R = (λI − A)⁻¹ in every block (flipped: (I − λA)⁻¹ = R(1/λ)/λ off the diagonal)."""
    R = t.resolvent(t.lam)
    F = (t.resolvent(t.q(1) / t.lam) / t.lam) if flipped else R
    X, Y, Xd, Yd = z["X"], z["Y"], z["Xdot"], z["Ydot"]
    return block([[-(X.T @ R @ Yd), -(X.T @ F @ Y)], [t.Ir + Xd.T @ F @ Yd, Xd.T @ R @ Y]])


# ---- Appendix 2: coupled ------------------------------------------------------------------------
def H_cpl(t, z):
    """(C-neumann) with a free κ: T_κ(X,P) + T_κ(Y,Q) + tr XᵀAY."""
    c = t.q(1, 2) + t.kappa
    K1, K2 = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    return (t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(K1 @ K1) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(K2 @ K2)
            + t.tr(z["X"].T @ t.A @ z["Y"]))


def coupled_flow(s):
    return stiefel_pairs_flow(s, H_cpl, coupled_point(s), [("X", "P"), ("Y", "Q")])


# ---- Appendix 2: complex ------------------------------------------------------------------------
def star(M):
    """Conjugate transpose of a realified matrix: the real transpose."""
    return M.T


def W_eq_tangent(t, z):
    """(W-eq) typed: Z̈ = −AZ + ZΛ, Λ = Z*AZ − Ż*Ż."""
    A = realify_real(t, t.A)
    Z, Zd = z["Z"], z["Zdot"]
    Lam = star(Z) @ A @ Z - star(Zd) @ Zd
    return {"Z": Zd, "Zdot": -(A @ Z) + Z @ Lam}
