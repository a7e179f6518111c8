# ruff: noqa
"""s72 hidden round: 15 further statements of Fedorov & Jovanović, written with the public API.

Every claim here is true as printed (or in the equivalent form its docstring says); the false twins are
in negatives.py.  Helpers (no claims) are in _h72_helpers.py."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stiefelsym import Count, Rank, RightInverse, admissible, block, claim, comm, elementary, twisted
from stiefelsym.bases import matrix_of, so_basis
from stiefelsym.brackets import casimir_residual, pencil, trace_power
from stiefelsym.systems import complex_point, derivative, re_trace

from _h72_helpers import (H_manakov_a3, H_neum_c, H_neum_kappa, L_complex, L_neum, Phi_eps, Phi_of, Psi_of,
                          flow_complex, i_2r, manakov_a3, tr_pow)


# 1 ---------------------------------------------------------------------------------------------------
def H_sphere(t):
    """(sphere_neum): ½(p, p) + ½(Ae, e)."""
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("h72-sphere-neumann-r1", paper=("sphere_neum", "neumann", "NE_XP"), kind="id",
       sizes=admissible(n_max=5, r_max=1, condition="r = 1 (the sphere)"))
def sphere_neumann_r1(s):
    """Introduction, (sphere_neum): at r = 1, H_neum,κ is the classical Neumann Hamiltonian ½(p,p) + ½(Ae,e) for
    every κ (tr(XᵀP)² = 0 on T*S^{n−1}), and its Dirac flow on (e,e) = 1, (e,p) = 0 is
    ė = p, ṗ = −Ae + ((Ae,e) − (p,p))e (the κ-flow is the same)."""
    e, p, A = s.X, s.P, s.A
    flow = s.dirac_flow(H_sphere)
    fk = s.dirac_flow(H_neum_kappa)
    pdot = -(A @ e) + e @ (e.T @ A @ e - p.T @ p)
    return {"H_neum,kappa - H_sphere": H_neum_kappa(s) - H_sphere(s),
            "edot - p": flow["X"] - p, "pdot - printed": flow["P"] - pdot,
            "kappa flow X": fk["X"] - p, "kappa flow P": fk["P"] - pdot}


# 2 ---------------------------------------------------------------------------------------------------
@claim("h72-neumann-lax-elementary", paper=("LA1", "LA2", "spectral-curve", "perelomov"), kind="lax",
       sizes=admissible(n_max=4))
def neumann_lax_elementary(s):
    """Theorem Neumann_LA and (spectral-curve): the coefficients e_1, e_2, e_3 of det(μI − 𝓛_neum(λ)) (elementary
    symmetric functions of the eigenvalues), 𝓛 = λΦ + XXᵀ − λ²A, are conserved along the Dirac flow of H_neum,κ,
    for every κ."""
    flow = s.dirac_flow(H_neum_kappa)
    out = {}
    for k in (1, 2, 3):
        out[f"d e_{k}(L(lambda))/dt"] = s.d(lambda t, k=k: elementary(t, L_neum(t, t.lam), 3)[k], flow)
    return out


# 3 ---------------------------------------------------------------------------------------------------
@claim("h72-manakov-b-a3", paper=("Manakov", "Euler-so(n)", "dot_XP2"), kind="lax", sizes=admissible(n_max=4))
def manakov_b_a3(s):
    """§4, the Manakov operator (Manakov) for B = A³: 𝔸ξ = ad_A⁻¹ad_Bξ = A²ξ + AξA + ξA² ((b_i − b_j)/(a_i − a_j) =
    a_i² + a_ia_j + a_j²); the geodesic flow of H_𝔸 = ½<𝔸Φ, Φ> is (dot_XP2) Ẋ = 𝔸(Φ)X, Ṗ = 𝔸(Φ)P, Φ obeys the Euler
    equations (Euler-so(n)) Φ̇ = [𝔸Φ, Φ], and the Lax pair L = Φ + λA, M = 𝔸(Φ) + λB holds: L̇ = [M, L]."""
    A, xi, lam = s.A, s.xi, s.lam
    flow = s.dirac_flow(H_manakov_a3)
    Phi = s.Phi
    AP = manakov_a3(s, Phi)
    return {"[A, A xi] - [A^3, xi]": comm(A, manakov_a3(s, xi)) - comm(A @ A @ A, xi),
            "Xdot - A(Phi)X": flow["X"] - AP @ s.X,
            "Pdot - A(Phi)P": flow["P"] - AP @ s.P,
            "Euler": s.d(lambda t: Phi_of(t.X, t.P), flow) - comm(AP, Phi),
            "Lax": s.d(lambda t: Phi_of(t.X, t.P) + t.A * t.lam, flow) - comm(AP + A @ A @ A * lam, Phi + A * lam)}


# 4 ---------------------------------------------------------------------------------------------------
@claim("h72-manakov-integrals-bracket", paper=("man", "Manakov"), kind="pb", sizes=admissible(n_max=4))
def manakov_integrals_bracket(s):
    """§4, (man): the integrals tr(λA + Σ p_i∧e_i)^k Poisson-commute for different λ (Dirac bracket):
    {tr(Φ + λA)³, tr(Φ + μA)⁴} = 0, and tr(Φ + μA)⁴ is conserved by the Manakov flow with B = A³."""
    mu = s.scalar("mu")
    f = lambda t: tr_pow(t, Phi_of(t.X, t.P) + t.A * t.lam, 3)
    g = lambda t: tr_pow(t, Phi_of(t.X, t.P) + t.A * mu, 4)
    return {"{f3(lam), f4(mu)}": s.bracket(f, g),
            "d f4(mu)/dt (Manakov, B = A^3)": s.d(g, s.dirac_flow(H_manakov_a3))}


# 5 ---------------------------------------------------------------------------------------------------
@claim("h72-pencil-casimir-rational", paper=("central", "LAMBDA12"), kind="pb", sizes=admissible(n_max=4))
def pencil_casimir_rational(s):
    """§6, the Casimirs of Λ_{λ1,λ2} for λ2 ≠ 0: at λ1 = 3, λ2 = 1 (λ2/(λ1+λ2) = 1/4) the functions
    tr(½h + v − ¼A)^k, k = 1, 2, 3, are Casimirs of 3Λ1 + Λ2 on gl(n) (x = h + v)."""
    T = pencil(lambda t: t.q(3), lambda t: t.q(1))
    x, b = s.generic("x", "n", "n"), s.generic("b", "n", "n")
    out = {}
    for k in (1, 2, 3):
        f = trace_power(k, so_scale=lambda t: t.q(1, 2), shift=lambda t: -(t.A / 4))
        out[f"Casimir k={k}"] = casimir_residual(s, T, f, x, b)
    return out


# 6 ---------------------------------------------------------------------------------------------------
def dPsi(t, dX, dP):
    return (t.d(lambda u: Psi_of(u.X, u.P), {"X": dX, "P": dP}),)


def dPsi_right(t, y):
    return (t.X @ y - t.X @ y, t.X @ y / 2)


@claim("h72-psi-submersion", paper=("momentum_right_map", "grassmannian"), kind="dim",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2 (so(1) = 0)"))
def psi_submersion(s):
    """§7 (T*G_{n,r} = Ψ⁻¹(0)/SO(r)) and (momentum_right_map): Ψ is a submersion on T*V: its differential maps the
    tangent space onto so(r) at every point, with right inverse y ↦ (δX, δP) = (0, Xy/2), which is tangent to T*V
    (it keeps XᵀX and XᵀP + PᵀX)."""
    y = s.eta
    v = {"P": s.X @ y / 2}
    return {"dPsi onto so(r)": RightInverse(dPsi, dPsi_right, on=("R^{n×r}", "R^{n×r}"), to=("so(r)",)),
            "d(XᵀX) along (0, Xy/2)": s.d(lambda t: t.X.T @ t.X, v),
            "d(XᵀP + PᵀX) along (0, Xy/2)": s.d(lambda t: t.X.T @ t.P + t.P.T @ t.X, v)}


# 7 ---------------------------------------------------------------------------------------------------
@claim("h72-grassmann-dim", paper=("grassmannian", "NEUMANN2"), kind="dim", sizes=admissible(n_max=6))
def grassmann_dim(s):
    """§7: dim Ψ⁻¹(0)/SO(r) = 2 dim V_{n,r} − 2 dim SO(r) = 2r(n − r) = dim T*G_{n,r}."""
    n, r = int(s.n), int(s.r)
    dimV = n * r - r * (r + 1) // 2
    return {"dim": Count(2 * dimV - r * (r - 1), 2 * r * (n - r))}


# 8 ---------------------------------------------------------------------------------------------------
@claim("h72-twisted-lax-elementary", paper=("mag-euk", "mag-nor", "mag-mom-stief", "LA1"), kind="lax",
       sizes=admissible(n_max=4, r_min=2, r_max=2, condition="r = 2 (Appendix 1)"))
def twisted_lax_elementary(s):
    """Appendix 1: along the twisted Neumann flows (mag-euk) (κ = −½) and (mag-nor) (κ = 0) of (T*V_{n,2}, ω_ε),
    the coefficients e_2, e_3 of the characteristic polynomial of 𝓛_ε(λ) = λΦ_ε + XXᵀ − λ²A are conserved
    (the Lax pair with Φ_ε)."""
    out = {}
    for name, c in (("euk", lambda t: t.q(-1, 2)), ("nor", lambda t: t.q(0))):
        flow = twisted.flow(s, H_neum_c(c))
        for k in (2, 3):
            out[f"{name}: d e_{k}/dt"] = s.d(
                lambda t, k=k: elementary(t, Phi_eps(t) * t.lam + t.X @ t.X.T - t.A * (t.lam * t.lam), 3)[k], flow)
    return out


# 9 ---------------------------------------------------------------------------------------------------
@claim("h72-psi2-casimir-of-invariants", paper=("REDUCED_BRACKET", "momentum_right_map", "perelomov"), kind="pb",
       sizes=admissible(n_max=4, r_min=2))
def psi2_commutes_with_invariants(s):
    """§6–7: tr Ψ² (a Casimir of so(r), hence of the reduced bracket) Poisson-commutes with every right
    SO(r)-invariant function: tr PᵀP, tr XᵀAX, tr 𝓛_neum(λ)³, and with Ψ_η = tr(ηΨ) itself."""
    eta = s.eta
    f = lambda t: t.tr(Psi_of(t.X, t.P) @ Psi_of(t.X, t.P))
    return {"{tr Psi^2, tr P^TP}": s.bracket(f, lambda t: t.tr(t.P.T @ t.P)),
            "{tr Psi^2, tr X^TAX}": s.bracket(f, lambda t: t.tr(t.X.T @ t.A @ t.X)),
            "{tr Psi^2, tr L^3}": s.bracket(f, lambda t: tr_pow(t, L_neum(t, t.lam), 3)),
            "{tr Psi^2, Psi_eta}": s.bracket(f, lambda t: t.tr(eta @ Psi_of(t.X, t.P)))}


# 10 --------------------------------------------------------------------------------------------------
@claim("h72-complex-dual-lax-traces", paper=("dual-complex", "LA3*", "W-eq"), kind="lax",
       sizes=admissible(n_max=3, r_max=2))
def complex_dual_lax_traces(s):
    """Appendix 2, Theorem dual-complex in the corrected form of the catalog's erratum ((λI − A)⁻¹ in all four
    blocks): tr 𝓛(λ)² (real and imaginary parts) is conserved along the complex Neumann system (W-eq)."""
    z = complex_point(s)
    fl = flow_complex(s, z)
    L = lambda t, w: L_complex(t, w, t.resolvent(t.lam))
    return {"d Re tr L^2": derivative(s, lambda t, w: re_trace(t, L(t, w) @ L(t, w)), z, fl),
            "d Im tr L^2": derivative(s, lambda t, w: re_trace(t, i_2r(t) @ L(t, w) @ L(t, w)), z, fl)}


# 11 --------------------------------------------------------------------------------------------------
def L_dual(t):
    """(LA3) 𝓛*(λ) = [[−XᵀRP, −XᵀRX], [I + PᵀRP, PᵀRX]], R = (λI − A)⁻¹."""
    R, X, P = t.resolvent(t.lam), t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [t.Ir + P.T @ R @ P, P.T @ R @ X]])


@claim("h72-dual-lax-trace4", paper=("DUAL", "LA3", "LA4"), kind="lax", sizes=admissible(n_max=4))
def dual_lax_trace4(s):
    """Theorem DUAL: tr 𝓛*(λ)² and tr 𝓛*(λ)⁴ are conserved along (N0_XP2) (κ = 0) and (NE_XP) (κ = −½)."""
    out = {}
    for name, c in (("N0", lambda t: t.q(0)), ("NE", lambda t: t.q(-1, 2))):
        flow = s.dirac_flow(H_neum_c(c))
        for k in (2, 4):
            out[f"{name}: d tr L*^{k}/dt"] = s.d(lambda t, k=k: tr_pow(t, L_dual(t), k), flow)
    return out


@claim("h72-dual-lax-traces-any-kappa", paper=("DUAL", "2r-integrals", "No"), kind="lax", sizes=admissible(n_max=4))
def dual_lax_any_kappa(s):
    """§8, after (2r-integrals): the spectral curve of 𝓛*(λ) is right SO(r)-invariant; since H_neum,κ − H_neum,0 is a
    multiple of tr Ψ², whose flow is the right SO(r)-action, tr 𝓛*(λ)² and tr 𝓛*(λ)⁴ are conserved along (No) for
    every κ (not only κ = 0, −½ of Theorem DUAL)."""
    flow = s.dirac_flow(H_neum_kappa)
    return {f"d tr L*^{k}/dt": s.d(lambda t, k=k: tr_pow(t, L_dual(t), k), flow) for k in (2, 4)}


# 12 --------------------------------------------------------------------------------------------------
@claim("h72-orbit-r1", paper=("2l",), kind="dim", sizes=admissible(n_max=5, n_min=2, r_max=1, condition="r = 1, n >= 2"))
def orbit_r1(s):
    """Lemma 2l at r = 1: the adjoint orbit of Φ = p∧e in so(n) has dimension 2l = 2(n − 2) (n > 3: 2r(n − r − 1);
    n ≤ 3: n(n−1)/2 − [n/2])."""
    n = int(s.n)
    M = matrix_of(s, lambda xi: comm(xi, s.Phi), so_basis(s, "n"), "skew")
    return {"rank ad_Phi": Rank(M, 2 * (n - 2))}


# 13 --------------------------------------------------------------------------------------------------
def L0(t):
    """(normal_metric_lagrangian) with (Phi_0), the velocity V = Ẋ in the slot P of the scene (XᵀẊ skew)."""
    X, V = t.X, t.P
    Phi0 = V @ X.T - X @ V.T - X @ (X.T @ V - V.T @ X) @ X.T / 2
    return t.killing(Phi0, Phi0) / 2


@claim("h72-normal-lagrangian-eas", paper=("normal_metric_lagrangian", "Phi_0", "P(dot_X)"), kind="id",
       sizes=admissible(n_max=4))
def normal_lagrangian_eas(s):
    """§3, (normal_metric_lagrangian), (Phi_0): on TV, L_0 = ½<Φ_0, Φ_0> = ½tr(ẊᵀẊ) + ¼tr((XᵀẊ)²)
    (= ½tr Ẋᵀ(I − ½XXᵀ)Ẋ), and the Legendre transformation P = ∂L_0/∂Ẋ of the printed L_0 is (P(dot_X))
    P = Ẋ − ½XXᵀẊ."""
    X, V = s.X, s.P
    K = X.T @ V
    _, LV = s.gradient(L0)
    return {"L0 - EAS": L0(s) - (s.tr(V.T @ V) / 2 + s.tr(K @ K) / 4),
            "dL0/dXdot - (P(dot_X))": LV - (V - X @ X.T @ V / 2)}


# 14 --------------------------------------------------------------------------------------------------
@claim("h72-invariants-closed", paper=("SO(n)-inv", "LEMA"), kind="pb", sizes=admissible(n_max=3))
def invariants_closed(s):
    """§2: C^∞(T*V)^{SO(n)} is closed under the Poisson bracket: the brackets {tr(S PᵀP), tr(T PᵀP)} and
    {tr(S PᵀP), Ψ_η} of the invariants (SO(n)-inv) (S, T symmetric) are SO(n)-invariant: {Φ_ξ, ·} = 0."""
    S = s.generic("S", "r", "r", "sym")
    T = s.generic("T", "r", "r", "sym")
    eta, xi = s.eta, s.xi
    f = lambda t: t.tr(S @ t.P.T @ t.P)
    g = lambda t: t.tr(T @ t.P.T @ t.P)
    h = lambda t: t.tr(eta @ Psi_of(t.X, t.P))
    Phi_xi = lambda t: t.killing(Phi_of(t.X, t.P), xi)
    left = s.dirac_flow(Phi_xi)
    return {"{Phi_xi, {f, g}}": s.d(lambda t: t.bracket(f, g), left),
            "{Phi_xi, {f, Psi_eta}}": s.d(lambda t: t.bracket(f, h), left)}


# 15 --------------------------------------------------------------------------------------------------
@claim("h72-neumann-r-n-geodesic", paper=("No", "DUAL"), kind="id",
       sizes=admissible(n_max=4, where=lambda n, r: r == n, condition="r = n"))
def neumann_r_n_geodesic(s):
    """The remark after Theorem DUAL (for r = n the Neumann flows are geodesic flows of bi-invariant metrics):
    at r = n the Dirac flow of H_neum,κ is Ẋ = 2(1 + κ)P, Ṗ = 2(1 + κ)PXᵀP."""
    flow = s.dirac_flow(H_neum_kappa)
    c = (s.kappa + 1) * 2
    return {"Xdot": flow["X"] - s.P * c, "Pdot": flow["P"] - s.P @ s.X.T @ s.P * c}


# 17 --------------------------------------------------------------------------------------------------
@claim("h72-neumann-flows-differ", paper=("No", "prep", "Neumann_LA"), kind="not", expect="nonzero",
       sizes=admissible(n_max=4, r_min=2, condition="r >= 2 (at r = 1 tr(XᵀP)² = 0)"))
def neumann_flows_differ(s):
    """§5, the paragraph before (prep) and the Introduction ("the Lax pair does not define the system itself"):
    for different κ the flows (No) do not coincide: Ẋ of H_neum,κ minus Ẋ of H_neum,0 is not zero (r ≥ 2)."""
    return {"Xdot(kappa) - Xdot(0)": s.dirac_flow(H_neum_kappa)["X"] - s.dirac_flow(H_neum_c(lambda t: t.q(0)))["X"]}


# 18 --------------------------------------------------------------------------------------------------
from stiefelsym.bases import sym_basis  # noqa: E402


@claim("h72-a-metric-lambda-unique", paper=("A_XP", "cond_XP2"), kind="dim", realization="metric",
       sizes=admissible(n_max=4))
def a_metric_lambda_unique(s):
    """§3, (A_XP): Λ is uniquely determined by ΛXᵀA⁻¹X + XᵀA⁻¹XΛ + 2PᵀA⁻²P = 0: the Lyapunov map
    Λ ↦ ΛM + MΛ, M = XᵀA⁻¹X, has full rank r(r+1)/2 on Sym(r) (generic rank; M is positive definite)."""
    r = int(s.r)
    M = s.X.T @ s.Ainv @ s.X
    L = matrix_of(s, lambda Lam: Lam @ M + M @ Lam, sym_basis(s, "r"), "sym")
    return {"rank": Rank(L, r * (r + 1) // 2)}
