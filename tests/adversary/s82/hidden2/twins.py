"""s82 hidden2 (h5): the false twins of claims.py, one change each, stated at the sizes where they are false
(numpy: indep_output.txt, the 'twin' columns).  Every `fails` is correct here; `proved`/`checked`/`numeric` wrong."""
from __future__ import annotations

from stiefelsym import Rank, admissible, block, claim, comm, elementary
from stiefelsym.bases import matrix_of, matrix_units

from _common import H_kappa, H_kappa0, J_r, L_star, e2_explicit, theta  # noqa: F401
from _common import centralizer_kernel, gl_orbit_rank, l1_kernel, l1_matrix, so_r_fields, theta_jacobian

R_LT_N = admissible(n_max=5, where=lambda n, r: r < n, condition="r < n (at r = n tr XᵀAP = 0 and tr XᵀAX = tr A)")
R_GE_2 = admissible(n_max=5, r_min=2, condition="r >= 2 (PᵀX = 0 and so(1) = 0 at r = 1)")
N2 = admissible(n_max=5, n_min=2, condition="n >= 2")
ALL = admissible(n_max=5)
R1 = admissible(n_max=5, r_max=1, condition="r = 1")


@claim("h5x-neumann-potential-rate", kind="id", section="5", sizes=R_LT_N)
def potential_rate(s):
    """Twin: dV/dt = (1 + 2κ) tr(XᵀAP) (a factor)."""
    flow = s.dirac_flow(H_kappa)
    V = lambda t: t.tr(t.X.T @ t.A @ t.X) / 2
    return {"dV/dt - (1+2k) tr(X^T A P)": s.d(V, flow) - (1 + 2 * s.kappa) * s.tr(s.X.T @ s.A @ s.P)}


@claim("h5x-neumann-quadratic-integral", kind="pb", section="5", sizes=R_LT_N)
def quadratic_integral(s):
    """Twin: tr Φ² + 2 tr XᵀAX conserved (a sign)."""
    flow = s.dirac_flow(H_kappa)
    return {"d/dt (tr Phi^2 + 2 tr X^T A X)": s.d(lambda t: t.tr(t.Phi @ t.Phi) + 2 * t.tr(t.X.T @ t.A @ t.X), flow)}


@claim("h5x-neumann-kappa-linear", kind="id", section="5", sizes=R_GE_2)
def kappa_linear(s):
    """Twin: the P part of flow_κ − flow_0 is −2κ PXᵀP (a sign)."""
    f, f0 = s.dirac_flow(H_kappa), s.dirac_flow(H_kappa0)
    X, P, k = s.X, s.P, s.kappa
    return {"X: difference": f.Xdot - f0.Xdot - k * (-2 * (X @ P.T @ X)),
            "P: difference": f.Pdot - f0.Pdot - k * (-2 * (P @ X.T @ P))}


@claim("h5x-theta-rank", kind="dim", section="6", sizes=ALL)
def theta_rank(s):
    """Twin: rank 2nr − r(r−1)/2 + 1 (one too many), with the true kernel certificate."""
    n, r = int(s.n), int(s.r)
    return {"rank [dTheta; dC]": Rank(theta_jacobian(s), 2 * n * r - r * (r - 1) // 2 + 1, generic=True,
                                      kernel=so_r_fields(s))}


@claim("h5x-theta-rank-nokernel", kind="dim", section="6", sizes=ALL)
def theta_rank_nokernel(s):
    """Twin: rank 2nr − r(r−1)/2 + 1 (one too many), no certificate."""
    n, r = int(s.n), int(s.r)
    return {"rank [dTheta; dC]": Rank(theta_jacobian(s), 2 * n * r - r * (r - 1) // 2 + 1, generic=True)}


@claim("h5x-theta-rank-low", kind="dim", section="6", sizes=ALL)
def theta_rank_low(s):
    """Twin: rank 2nr − r(r−1)/2 − 1 (one too few), with the kernel."""
    n, r = int(s.n), int(s.r)
    return {"rank [dTheta; dC]": Rank(theta_jacobian(s), 2 * n * r - r * (r - 1) // 2 - 1, generic=True,
                                      kernel=so_r_fields(s))}


@claim("h5x-l1-rank", kind="dim", section="6", sizes=N2)
def l1_rank(s):
    """Twin: rank r(n − r) + 1, with the true kernel."""
    n, r = int(s.n), int(s.r)
    return {"rank ad_v on so(n)": Rank(l1_matrix(s), r * (n - r) + 1, generic=True, kernel=l1_kernel(s))}


@claim("h5x-l1-rank-everywhere", kind="dim", section="6", sizes=N2)
def l1_rank_everywhere(s):
    """Twin: rank r(n − r) − 1 at every point."""
    n, r = int(s.n), int(s.r)
    return {"rank ad_v on so(n) everywhere": Rank(l1_matrix(s), r * (n - r) - 1, generic=False)}


@claim("h5x-gl-orbit-at-theta", kind="dim", section="6", sizes=ALL)
def gl_orbit_at_theta(s):
    """Twin: one more than the true rank, with the true kernel."""
    n, r = int(s.n), int(s.r)
    x = theta(s)
    M = matrix_of(s, lambda u: comm(x, u), matrix_units(s, "n", "n"))
    return {"rank ad_Theta on gl(n)": Rank(M, gl_orbit_rank(n, r) + 1, generic=True, kernel=centralizer_kernel(s, x))}


@claim("h5x-gl-orbit-regular", kind="dim", section="6",
       sizes=admissible(n_max=5, where=lambda n, r: n - 2 * r >= 2, condition="n - 2r >= 2"))
def gl_orbit_regular(s):
    """Twin (a natural misreading): Θ regular in gl(n), rank n² − n, where n − 2r ≥ 2 (no certificate)."""
    n = int(s.n)
    x = theta(s)
    M = matrix_of(s, lambda u: comm(x, u), matrix_units(s, "n", "n"))
    return {"rank ad_Theta on gl(n)": Rank(M, n * n - n, generic=True)}


@claim("h5x-dual-e2-trace", kind="id", section="8", sizes=N2)
def dual_e2_trace(s):
    """Twin: e₂(𝓛*) = tr(RXXᵀ) + ½tr(RΦRΦ) (a sign)."""
    L = L_star(s, s.lam)
    return {"e2(L*) - (...)": elementary(s, L, 2)[2] - e2_explicit(s, s.lam, sign=1)}


@claim("h5x-dual-so-r-covariance", kind="id", section="8", sizes=R_GE_2)
def dual_so_r_covariance(s):
    """Twin: δ𝓛* = [diag(η, η), 𝓛*] (the order)."""
    eta = s.eta
    z = s.zeros(s.r, s.r, ("r", "r"))
    D = block([[eta, z], [z, eta]])
    dL = s.d(lambda t: L_star(t, s.lam), {"X": s.X @ eta, "P": s.P @ eta})
    return {"dL* - [diag(eta, eta), L*]": dL - comm(D, L_star(s, s.lam))}


@claim("h5x-dual-hamiltonian-matrix", kind="id", section="8", sizes=ALL)
def dual_hamiltonian_matrix(s):
    """Twin: J𝓛*(λ) skew (a transpose sign)."""
    JL = J_r(s) @ L_star(s, s.lam)
    return {"J L* + (J L*)^T": JL + JL.T}


@claim("h5x-chasles-r1-discriminant", kind="geo", section="8", sizes=R1)
def chasles_r1_discriminant(s):
    """Twin: the quadrics Σ x_i²/(λ − a_i) = 1 (C = +R, a sign)."""
    C = s.resolvent(s.lam)
    e, p = s.X, s.P
    disc = s.tr(e.T @ C @ e) * (s.tr(p.T @ C @ p) - 1) - s.tr(e.T @ C @ p) * s.tr(e.T @ C @ p)
    return {"disc - e2(L*)": disc - elementary(s, L_star(s, s.lam), 2)[2]}


@claim("h5x-dual-e2-conserved-every-kappa", kind="pb", section="8", sizes=R_LT_N)
def dual_e2_conserved(s):
    """Twin: tr(RXXᵀ) + ½tr(RΦRΦ) conserved (a sign)."""
    flow = s.dirac_flow(H_kappa)
    return {"d e2/dt": s.d(lambda t: e2_explicit(t, s.lam, sign=1), flow)}
