# ruff: noqa
"""s72 hidden round: 15 false twins of the statements of claims.py, one change each.

Each is an ordinary claim with ``fails_at`` = the sizes where plain numpy (indep.py) finds it false; where it
holds by a coincidence (a small size), it is expected to hold there."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, Rank, RightInverse, admissible, block, claim, comm, elementary, twisted
from stiefelsym.bases import matrix_of, so_basis
from stiefelsym.brackets import casimir_residual, pencil, trace_power
from stiefelsym.systems import complex_point, derivative, re_trace

from _h72_helpers import (H_manakov_a3, H_neum_c, H_neum_kappa, L_complex, L_neum, Phi_eps, Phi_of, Psi_of,
                          flow_complex, i_2r, manakov_a3, tr_pow)


def H_sphere(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


ALL = lambda n, r: True


# 1 ---------------------------------------------------------------------------------------------------
@claim("n72-sphere-neumann-plus", kind="id", sizes=admissible(n_max=5, r_max=1, condition="r = 1"),
       fails_at=lambda n, r: n >= 2, erratum="twin: +(p,p) in the multiplier")
def sphere_plus(s):
    """Twin of h72-sphere-neumann-r1: ṗ = −Ae + ((Ae,e) + (p,p))e."""
    e, p, A = s.X, s.P, s.A
    flow = s.dirac_flow(H_sphere)
    return {"pdot": flow["P"] - (-(A @ e) + e @ (e.T @ A @ e + p.T @ p))}


# 2 ---------------------------------------------------------------------------------------------------
@claim("n72-neumann-lax-plus-a", kind="lax", sizes=admissible(n_max=4), fails_at=lambda n, r: r < n,
       erratum="twin: +λ²A in 𝓛")
def lax_plus_a(s):
    """Twin of h72-neumann-lax-elementary: e_1, e_2, e_3 of λΦ + XXᵀ + λ²A conserved along H_neum,κ."""
    flow = s.dirac_flow(H_neum_kappa)
    out = {}
    for k in (1, 2, 3):
        out[f"d e_{k}/dt"] = s.d(lambda t, k=k: elementary(t, L_neum(t, t.lam, +1), 3)[k], flow)
    return out


# 3 ---------------------------------------------------------------------------------------------------
@claim("n72-manakov-b-a2-in-m", kind="lax", sizes=admissible(n_max=4), fails_at=lambda n, r: n >= 2,
       erratum="twin: M = 𝔸(Φ) + λA² for 𝔸 = ad_A⁻¹ad_{A³}")
def manakov_wrong_b(s):
    """Twin of h72-manakov-b-a3: the Lax pair with M = 𝔸(Φ) + λA² (B = A² in M, A³ in 𝔸)."""
    A, lam = s.A, s.lam
    flow = s.dirac_flow(H_manakov_a3)
    Phi = s.Phi
    return {"Lax": s.d(lambda t: Phi_of(t.X, t.P) + t.A * t.lam, flow)
            - comm(manakov_a3(s, Phi) + A @ A * lam, Phi + A * lam)}


# 4 ---------------------------------------------------------------------------------------------------
@claim("n72-manakov-integrals-a2", kind="pb", sizes=admissible(n_max=4), fails_at=lambda n, r: n >= 3,
       erratum="twin: A² in the second integral")
def manakov_integrals_a2(s):
    """Twin of h72-manakov-integrals-bracket: {tr(Φ + λA)³, tr(Φ + μA²)³} = 0."""
    mu = s.scalar("mu")
    f = lambda t: tr_pow(t, Phi_of(t.X, t.P) + t.A * t.lam, 3)
    g = lambda t: tr_pow(t, Phi_of(t.X, t.P) + t.A @ t.A * mu, 3)
    return {"{f3(lam), g3(mu)}": s.bracket(f, g)}


# 5 ---------------------------------------------------------------------------------------------------
@claim("n72-pencil-casimir-half-a", kind="pb", sizes=admissible(n_max=4), fails_at=lambda n, r: n >= 2,
       erratum="twin: −½A in place of −¼A")
def pencil_half_a(s):
    """Twin of h72-pencil-casimir-rational: tr(½h + v − ½A)^k Casimirs of 3Λ1 + Λ2."""
    T = pencil(lambda t: t.q(3), lambda t: t.q(1))
    x, b = s.generic("x", "n", "n"), s.generic("b", "n", "n")
    out = {}
    for k in (1, 2, 3):
        f = trace_power(k, so_scale=lambda t: t.q(1, 2), shift=lambda t: -(t.A / 2))
        out[f"Casimir k={k}"] = casimir_residual(s, T, f, x, b)
    return out


# 6 ---------------------------------------------------------------------------------------------------
def dPsi(t, dX, dP):
    return (t.d(lambda u: Psi_of(u.X, u.P), {"X": dX, "P": dP}),)


def dPsi_right_wrong(t, y):
    return (t.X @ y - t.X @ y, t.X @ y)


@claim("n72-psi-submersion-factor", kind="dim", sizes=admissible(n_max=4, r_min=2), fails_at=ALL,
       erratum="twin: right inverse y ↦ (0, Xy)")
def psi_factor(s):
    """Twin of h72-psi-submersion: right inverse y ↦ (0, Xy)."""
    return {"dPsi onto so(r)": RightInverse(dPsi, dPsi_right_wrong, on=("R^{n×r}", "R^{n×r}"), to=("so(r)",))}


# 7 ---------------------------------------------------------------------------------------------------
@claim("n72-grassmann-dim-one-quotient", kind="dim", sizes=admissible(n_max=6), fails_at=lambda n, r: r >= 2,
       erratum="twin: only one so(r) removed")
def grassmann_one(s):
    """Twin of h72-grassmann-dim: 2 dim V − dim SO(r) = 2r(n − r)."""
    n, r = int(s.n), int(s.r)
    dimV = n * r - r * (r + 1) // 2
    return {"dim": Count(2 * dimV - r * (r - 1) // 2, 2 * r * (n - r))}


# 8 ---------------------------------------------------------------------------------------------------
@claim("n72-twisted-lax-phi", kind="lax", sizes=admissible(n_max=4, r_min=2, r_max=2), fails_at=lambda n, r: n >= 3,
       erratum="twin: Φ in place of Φ_ε")
def twisted_phi(s):
    """Twin of h72-twisted-lax-elementary: e_2, e_3 of λΦ + XXᵀ − λ²A (Φ, not Φ_ε) conserved along (mag-euk), (mag-nor)."""
    out = {}
    for name, c in (("euk", lambda t: t.q(-1, 2)), ("nor", lambda t: t.q(0))):
        flow = twisted.flow(s, H_neum_c(c))
        for k in (2, 3):
            out[f"{name}: d e_{k}/dt"] = s.d(lambda t, k=k: elementary(t, L_neum(t, t.lam), 3)[k], flow)
    return out


# 9 ---------------------------------------------------------------------------------------------------
@claim("n72-psi2-gram-weighted", kind="pb", sizes=admissible(n_max=4, r_min=2), fails_at=lambda n, r: r < n,
       erratum="twin: tr(N PᵀP) with N generic symmetric (not SO(r)-invariant)")
def psi2_weighted(s):
    """Twin of h72-psi2-casimir-of-invariants: {tr Ψ², tr(N PᵀP)} = 0 for a generic symmetric N."""
    N = s.generic("N", "r", "r", "sym")
    f = lambda t: t.tr(Psi_of(t.X, t.P) @ Psi_of(t.X, t.P))
    return {"{tr Psi^2, tr N P^TP}": s.bracket(f, lambda t: t.tr(N @ t.P.T @ t.P))}


# 10 --------------------------------------------------------------------------------------------------
@claim("n72-complex-dual-lax-printed", kind="lax", sizes=admissible(n_max=3, r_max=2), fails_at=lambda n, r: r < n,
       erratum="twin: (I − λA)⁻¹ off the diagonal, as printed in (LA3*)")
def complex_printed(s):
    """Twin of h72-complex-dual-lax-traces: with the printed (I − λA)⁻¹ in the off-diagonal blocks."""
    z = complex_point(s)
    fl = flow_complex(s, z)
    L = lambda t, w: L_complex(t, w, t.resolvent(t.q(1) / t.lam) / t.lam)
    return {"d Re tr L^2": derivative(s, lambda t, w: re_trace(t, L(t, w) @ L(t, w)), z, fl),
            "d Im tr L^2": derivative(s, lambda t, w: re_trace(t, i_2r(t) @ L(t, w) @ L(t, w)), z, fl)}


# 11 --------------------------------------------------------------------------------------------------
def L_dual(t):
    R, X, P = t.resolvent(t.lam), t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


def L_dual_low(t, low):
    R, X, P = t.resolvent(t.lam), t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir * low + P.T @ R @ P, P.T @ R @ X]])


@claim("n72-dual-lax-trace4-minus-i", kind="lax", sizes=admissible(n_max=4), fails_at=lambda n, r: r < n,
       erratum="twin: −I_r in the lower-left block of 𝓛*")
def dual_minus_i(s):
    """Twin of h72-dual-lax-trace4: with −I_r + PᵀRP in the lower-left block, tr 𝓛'(λ)² and tr 𝓛'(λ)⁴ conserved
    along (N0_XP2) and (NE_XP)."""
    out = {}
    for name, c in (("N0", lambda t: t.q(0)), ("NE", lambda t: t.q(-1, 2))):
        flow = s.dirac_flow(H_neum_c(c))
        for k in (2, 4):
            out[f"{name}: d tr L'^{k}/dt"] = s.d(lambda t, k=k: tr_pow(t, L_dual_low(t, -1), k), flow)
    return out


# 12 --------------------------------------------------------------------------------------------------
@claim("n72-orbit-r1-full", kind="dim", sizes=admissible(n_max=5, n_min=2, r_max=1), fails_at=ALL,
       erratum="twin: 2(n − 1)")
def orbit_full(s):
    """Twin of h72-orbit-r1: rank ad_Φ = 2(n − 1) at r = 1."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: comm(xi, s.Phi), so_basis(s, "n"), "skew")
    return {"rank ad_Phi": Rank(M, 2 * (n - 1))}


# 13 --------------------------------------------------------------------------------------------------
def L0(t):
    X, V = t.X, t.P
    Phi0 = V @ X.T - X @ V.T - X @ (X.T @ V - V.T @ X) @ X.T / 2
    return t.killing(Phi0, Phi0) / 2


@claim("n72-normal-lagrangian-minus", kind="id", sizes=admissible(n_max=4), fails_at=lambda n, r: r >= 2,
       erratum="twin: −¼ tr((XᵀẊ)²)")
def lagrangian_minus(s):
    """Twin of h72-normal-lagrangian-eas: L_0 = ½tr(ẊᵀẊ) − ¼tr((XᵀẊ)²)."""
    X, V = s.X, s.P
    K = X.T @ V
    return {"L0 - twin": L0(s) - (s.tr(V.T @ V) / 2 - s.tr(K @ K) / 4)}


# 14 --------------------------------------------------------------------------------------------------
@claim("n72-invariants-closed-pap", kind="pb", sizes=admissible(n_max=3), fails_at=lambda n, r: n >= 2,
       erratum="twin: tr(S PᵀAP) is not SO(n)-invariant")
def invariants_pap(s):
    """Twin of h72-invariants-closed: {Φ_ξ, {tr(S PᵀAP), tr(T PᵀP)}} = 0."""
    S = s.generic("S", "r", "r", "sym")
    T = s.generic("T", "r", "r", "sym")
    xi = s.xi
    f = lambda t: t.tr(S @ t.P.T @ t.A @ t.P)
    g = lambda t: t.tr(T @ t.P.T @ t.P)
    Phi_xi = lambda t: t.killing(Phi_of(t.X, t.P), xi)
    return {"{Phi_xi, {f, g}}": s.d(lambda t: t.bracket(f, g), s.dirac_flow(Phi_xi))}


# 15 --------------------------------------------------------------------------------------------------
@claim("n72-neumann-r-n-factor", kind="id", sizes=admissible(n_max=4, where=lambda n, r: r == n),
       fails_at=lambda n, r: n >= 2, erratum="twin: (1 + κ) in place of 2(1 + κ)")
def r_n_factor(s):
    """Twin of h72-neumann-r-n-geodesic: Ẋ = (1 + κ)P, Ṗ = (1 + κ)PXᵀP at r = n."""
    flow = s.dirac_flow(H_neum_kappa)
    c = s.kappa + 1
    return {"Xdot": flow["X"] - s.P * c, "Pdot": flow["P"] - s.P @ s.X.T @ s.P * c}


# 16 --------------------------------------------------------------------------------------------------
@claim("n72-neumann-xxt-derivatives-differ", kind="not", expect="nonzero", sizes=admissible(n_max=4, r_min=2),
       fails_at=ALL, erratum="twin: the derivatives of XXᵀ are the same for every κ (prep)")
def xxt_differ(s):
    """Twin of h72-neumann-flows-differ (one change: XXᵀ in place of X): d(XXᵀ)/dt along H_neum,κ and along
    H_neum,0 differ."""
    F = lambda t: t.X @ t.X.T
    return {"d(XX^T)/dt (kappa) - (0)": s.d(F, s.dirac_flow(H_neum_kappa))
            - s.d(F, s.dirac_flow(H_neum_c(lambda t: t.q(0))))}


# 17 --------------------------------------------------------------------------------------------------
from stiefelsym.bases import sym_basis  # noqa: E402


@claim("n72-a-metric-lambda-commutator", kind="dim", realization="metric", sizes=admissible(n_max=4),
       fails_at=ALL, erratum="twin: ΛM − MΛ (its kernel contains the polynomials in M)")
def a_metric_commutator(s):
    """Twin of h72-a-metric-lambda-unique: Λ ↦ ΛM − MΛ has full rank r(r+1)/2 on Sym(r)."""
    r = int(s.r)
    M = s.X.T @ s.Ainv @ s.X
    L = matrix_of(s, lambda Lam: Lam @ M - M @ Lam, sym_basis(s, "r"), "sym")
    return {"rank": Rank(L, r * (r + 1) // 2)}
