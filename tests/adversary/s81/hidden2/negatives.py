"""s81 hidden2 (h81b): the false twins of claims.py (one change each), stated where numpy finds them false."""
from __future__ import annotations

from stiefelsym import Rank, admissible, claim, comm, twisted
from stiefelsym.systems import complex_point, derivative, double_point, realify_real

from claims import (H_A, M_double, Phi_c, YXt, ZZs, flow_complex, flow_double, generic_function,
                    phi_jacobian_and_kernel)

SMALL = admissible(n_max=4)
R2 = admissible(n_max=4, r_min=2, r_max=2, condition="r = 2")
R_GE_2 = admissible(n_max=4, r_min=2, condition="r >= 2")
R_LT_N = admissible(n_max=4, where=lambda n, r: r < n, condition="r < n")
TWO_R_LE_N = admissible(n_max=5, where=lambda n, r: 2 * r <= n, condition="n >= 2r")
ALL = lambda n, r: True


@claim("n81b-metric-leaf-standard", kind="pb", section="3", realization="metric", sizes=SMALL, fails_at=lambda n, r: n > 1,
       erratum="twin: the standard constraint XᵀP + PᵀX is not a Casimir of {,}_A")
def metric_leaf_standard(s):
    """Twin of h81b-metric-leaf-casimirs: tr C(XᵀP + PᵀX) (the standard realization's constraint) in place of
    tr C(XᵀA⁻¹P + PᵀA⁻¹X)."""
    C = s.fresh("r", "r")
    return {"{tr C (X^T P + P^T X), f}_A": s.bracket(lambda t: t.tr(C @ (t.X.T @ t.P + t.P.T @ t.X)),
                                                      generic_function(s))}


@claim("n81b-metric-positions-momenta", kind="pb", section="3", realization="metric", sizes=SMALL, fails_at=ALL,
       erratum="twin: the canonical value tr UᵀW for {tr UᵀX, tr WᵀP}_A")
def metric_positions_momenta(s):
    """Twin of h81b-metric-positions-commute: {tr UᵀX, tr WᵀP}_A = tr UᵀW (the Dirac correction dropped)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {"{tr U^T X, tr W^T P}_A - tr U^T W":
            s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.P)) - s.tr(U.T @ W)}


@claim("n81b-metric-neumann-multiplier-I", kind="id", section="3", realization="metric", sizes=SMALL, fails_at=ALL,
       erratum="twin: −I_r for −2I_r in the equation of Λ")
def metric_neumann_multiplier_I(s):
    """Twin of h81b-metric-neumann-multiplier: ΛM + MΛ + 2PᵀA⁻²P − I_r = 0."""
    H = lambda t: H_A(t) + t.tr(t.X.T @ t.A @ t.X) / 2
    flow = s.dirac_flow(H)
    X, P = s.X, s.P
    Lam = X.T @ (flow.Pdot + s.A @ X)
    M = X.T @ s.Ainv @ X
    return {"Lambda M + M Lambda + 2 P^T A^-2 P - I": Lam @ M + M @ Lam + 2 * (P.T @ s.Ainv @ s.Ainv @ P) - s.Ir}


@claim("n81b-double-prep-order", kind="id", section="A2", sizes=SMALL, fails_at=lambda n, r: r < n,
       erratum="twin: [A, YXᵀ] for [YXᵀ, A]")
def double_prep_order(s):
    """Twin of h81b-double-prep: dM/dt = [A, YXᵀ]."""
    z = double_point(s)
    return {"dM/dt - [A, YX^T]": derivative(s, M_double, z, flow_double(s, z)) - comm(s.A, YXt(s, z))}


@claim("n81b-double-lax-plus", kind="lax", section="A2", sizes=SMALL, fails_at=lambda n, r: n > 1,
       erratum="twin: 𝓐 = M + λA")
def double_lax_plus(s):
    """Twin of h81b-double-lax-n: 𝓐(λ) = M + λA."""
    z = double_point(s)
    lam = s.lam
    L = lambda t, w: lam * M_double(t, w) + YXt(t, w) - lam * lam * t.A
    Am = M_double(s, z) + lam * s.A
    return {"dL/dt - [A, L]": derivative(s, L, z, flow_double(s, z)) - comm(Am, L(s, z))}


@claim("n81b-complex-prep-order", kind="id", section="A2", sizes=admissible(n_max=3), fails_at=lambda n, r: r < n,
       erratum="twin: [A, ZZ*] for [ZZ*, A]")
def complex_prep_order(s):
    """Twin of h81b-complex-prep: dΦ_c/dt = [A, ZZ*]."""
    z = complex_point(s)
    A = realify_real(s, s.A)
    return {"dPhi_c/dt - [A, ZZ*]": derivative(s, Phi_c, z, flow_complex(s, z)) - comm(A, ZZs(s, z))}


@claim("n81b-complex-lax-plus", kind="pb", section="A2", sizes=admissible(n_max=3), fails_at=lambda n, r: r < n,
       erratum="twin: +λ²A in 𝓛_c")
def complex_lax_plus(s):
    """Twin of h81b-complex-lax-traces: tr(λΦ_c + ZZ* + λ²A)² conserved."""
    z = complex_point(s)
    lam = s.lam

    def L(t, w):
        return lam * Phi_c(t, w) + ZZs(t, w) + lam * lam * realify_real(t, t.A)

    return {"d tr L^2/dt": derivative(s, lambda t, w: (L(t, w) @ L(t, w)).trace(), z, flow_complex(s, z))}


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2


@claim("n81b-twisted-kinetic", kind="pb", section="A1", sizes=R2, fails_at=lambda n, r: r < n,
       erratum="twin: the kinetic H_E in place of a potential")
def twisted_kinetic(s):
    """Twin of h81b-twisted-positions: the twisted flow of H_E is the untwisted one."""
    tw, d = twisted.flow(s, H_E), s.dirac_flow(H_E)
    return {"X' twisted - X' untwisted": tw.Xdot - d.Xdot, "P' twisted - P' untwisted": tw.Pdot - d.Pdot}


@claim("n81b-twisted-kinetic-any-F", kind="pb", section="A1", sizes=R_GE_2, fails_at=lambda n, r: (n, r) != (2, 2),
       erratum="twin: the kinetic H_E in place of a potential")
def twisted_kinetic_any_F(s):
    """Twin of h81b-twisted-positions-any-F: the twisted flow of H_E is the untwisted one."""
    F = s.generic("Fmag", "r", "r", "skew")
    tw, d = twisted.flow(s, H_E, F), s.dirac_flow(H_E)
    return {"X' twisted - X' untwisted": tw.Xdot - d.Xdot, "P' twisted - P' untwisted": tw.Pdot - d.Pdot}


@claim("n81b-phi-ambient-rank-high", kind="dim", section="2", sizes=TWO_R_LE_N, fails_at=ALL,
       erratum="twin: r(2r − 1) for r(2r + 1)")
def phi_ambient_rank_high(s):
    """Twin of h81b-phi-ambient-rank: rank 2nr − r(2r − 1), with the same kernel certificate."""
    n, r = int(s.n), int(s.r)
    J, K = phi_jacobian_and_kernel(s)
    return {"rank dPhi": Rank(J, 2 * n * r - r * (2 * r - 1), kernel=K)}


@claim("n81b-phi-ambient-rank-low", kind="dim", section="2", sizes=TWO_R_LE_N, fails_at=ALL,
       erratum="twin: one less than the rank")
def phi_ambient_rank_low(s):
    """Second twin of h81b-phi-ambient-rank: rank 2nr − r(2r + 1) − 1, with the kernel certificate."""
    n, r = int(s.n), int(s.r)
    J, K = phi_jacobian_and_kernel(s)
    return {"rank dPhi": Rank(J, 2 * n * r - r * (2 * r + 1) - 1, kernel=K)}
