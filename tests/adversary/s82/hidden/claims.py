"""s82 hidden statements (h2): 12 statements of Fedorov & Jovanović (§3/§4, §7, App. 1, App. 2) in my own
formulation, each with a false twin (ids n82-*, one change).  Truth: indep.py.in (numpy, no stiefelsym).

Derivations (by hand; numpy confirms):

 1 (§7 quartic) v = XXᵀ, v² = v.  [A, v] skew; ⟨c, c⟩ = −½tr c² and
   tr([A,v]²) = 2tr(AvAv) − 2tr(vA²), so ⟨[A,v],[A,v]⟩ = tr(vA²) − tr(vAvA)
   = tr XᵀA²X − tr(XᵀAX XᵀAX): the quartic potential is the squared length of [A, v] (a function of the plane).
   Twin: 2⟨[A,v],[A,v]⟩ (false where [A, v] ≠ 0: r < n).
 2 (§7 "(N0_XP2), (NE_XP) coincide on Ψ⁻¹(0)", every κ) P̃ = (I − XXᵀ)P gives XᵀP̃ = 0, a point of Ψ⁻¹(0).
   The κ-term −(½+κ)tr(XᵀP)² is quadratic in XᵀP, its gradient vanishes there, so the Dirac flow of H_κ at
   (X, P̃) is that of κ = −½: Ẋ = P̃, Ṗ = −AX + X(XᵀAX − P̃ᵀP̃) (NE_XP).  Twin: the same at (X, P) (false r ≥ 2).
 3 (§7 neum-gras, projector form) along (NE_XP) Ẋ = P, Ẍ = −AX + XΛ: v̈ = ẌXᵀ + 2PPᵀ + XẌᵀ
   = −(Av + vA) + 2PPᵀ + 2XΛXᵀ, Λ = XᵀAX − PᵀP.  Twin: Λ with +PᵀP (false n ≥ 2).
 4 (App.1 Prop. YM (i) + (LA1)) on so(n) × S^{n−1}, Ω̇ = [A, eeᵀ], ė = Ωe:
   d/dt ½⟨Ω,Ω⟩ = ⟨Ω, [A, eeᵀ]⟩ = −eᵀΩAe, d/dt(−½eᵀAe) = −eᵀAΩe = eᵀΩAe: H_CP conserved.  With v = I − eeᵀ,
   v̇ = −(Ωeeᵀ − eeᵀΩ) = [Ω, v], Ω̇ = [v, A]: (CPB), so tr(λΩ + v − λ²A)^k conserved.  Twin: +½(e, Ae) (n ≥ 2).
 5 (App.1 (mag6) on the reduced space) ë = Ω̇e + Ωė = Ae − (e,Ae)e + Ωė; F = Ω − ė∧e, ė∧e = ėeᵀ − eėᵀ,
   Fė = Ωė + |ė|²e (eᵀė = eᵀΩe = 0): ë = Ae − ((e,Ae) + (ė,ė))e + Fė.  Twin: F = Ω + ė∧e (n ≥ 2).
 6 (App.1 twisted, r = 2) the right SO(2) rotation preserves de₁∧de₂ and ι_{XJ}(de₁∧de₂) = d(½|e|²) = 0 on V,
   so the twisted Dirac flow of Ψ₁₂ = ⟨Ψ, J⟩ is the untwisted one, (XJ, PJ) (the ε-force εX is absorbed by Λ).
   Twin: (XJᵀ, PJᵀ).
 7 (App.1 mag-euk in matrix form) p-columns: εp₂, −εp₁ = εPJᵀ; the diagonal ε-terms −ε(e₁,p₂), +ε(e₂,p₁)
   are equal on T*V ((e₁,p₂) = −(e₂,p₁)) and equal −½εΨ₁₂: Ṗ = −AX + X(XᵀAX − PᵀP − ½εΨ₁₂I) + εPJᵀ, Ẋ = P.
   Twin: εPJ.
 8 (App.2 double, the GL(r) symmetry) Λ' = RΛR⁻¹ at (XRᵀ, YR⁻¹, ẊRᵀ, ẎR⁻¹): Ẍ' = ẌRᵀ, Ÿ' = ŸR⁻¹.
   Twin: Y ↦ YRᵀ (false: Ẍ' − ẌRᵀ = X(RᵀR − I)ΛᵀRᵀ).
 9 (App.2 coupled, the (X, P) lines of (C-eq), (C-L)) the Dirac flow of (C-neumann) has Ẋ = P − (1+2κ)XPᵀX,
   Ṗ = −AY + (1+2κ)PXᵀP + XΛ, Λ = ½(XᵀAY + YᵀAX) − PᵀP.  Twin: Λ = XᵀAY − PᵀP (not symmetric: r ≥ 2).
10 (App.2 complex (u(1))) Σ_j ψ_j = tr(ŻZ̄ᵀ − ZŻ̄ᵀ) = tr(ŻᵀZ̄) − tr(ZᵀŻ̄) = −tr ψ₀, and it is conserved along
   (W-eq).  Twin: Σ_j ψ_j = +tr ψ₀ (tr ψ₀ = −2i Im tr Z*Ż ≠ 0).
11 (§4 Manakov (man)) H = −½tr Φ²A = ½⟨Φ, AΦ + ΦA⟩; L = Φ + λA, M = AΦ + ΦA + λA² is a Lax pair, so the
   λ² coefficient of tr(Φ + λA)⁴, 4tr Φ²A² + 2tr ΦAΦA, is conserved.  Twin: tr Φ²A² + tr ΦAΦA (n ≥ 3).
12 (§3 normal metric (dot_X3), (dot_P3)) Ẋ = ΦX, Ṗ = ΦP with Φ conserved: Ẍ = Φ²X, P̈ = Φ²P (second derivative
   along the flow of the flow's own components).  Twin: ΦᵀΦ (= −Φ²).
"""
from stiefelsym import admissible, claim, comm, twisted
from stiefelsym.systems import complex_point, derivative, double_point, stiefel_pairs_flow

from _h82_helpers import (H_coupled, H_euclid_neumann, H_kappa_at, H_manakov, H_normal, flow_complex,
                          flow_double, psi0_trace, psi12, psi_sum)

ALL = admissible(n_max=5)
SMALL = admissible(n_max=4)
R1 = admissible(n_max=5, r_in=(1,), condition="r = 1 (a unit vector e of S^{n-1})")
R2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


# 1 ---------------------------------------------------------------------------------------------
def _quartic(s, factor):
    v = s.X @ s.X.T
    c = comm(s.A, v)
    U = s.tr(s.X.T @ s.A @ s.A @ s.X) - s.tr(s.X.T @ s.A @ s.X @ s.X.T @ s.A @ s.X)
    return {"U_quartic - <[A,v],[A,v]>": U - factor * s.killing(c, c)}


@claim("h82-quartic-commutator", paper=("quartic",), kind="id", sizes=ALL)
def quartic_commutator(s):
    """The potential of (quartic), tr XᵀA²X − tr(XᵀAXXᵀAX), is ⟨[A, XXᵀ], [A, XXᵀ]⟩."""
    return _quartic(s, 1)


@claim("n82-quartic-commutator", paper=("quartic",), kind="id", sizes=ALL, fails_at=lambda n, r: r < n,
       erratum="twin: factor 2")
def quartic_commutator_twin(s):
    """Twin: 2⟨[A, XXᵀ], [A, XXᵀ]⟩."""
    return _quartic(s, 2)


# 2 ---------------------------------------------------------------------------------------------
def _kappa_flow(s, project):
    X, A = s.X, s.A
    P = (s.In - X @ X.T) @ s.P if project else s.P
    f = stiefel_pairs_flow(s, H_kappa_at, {"X": X, "P": P}, [("X", "P")])
    return {"X' - (NE_XP)": f["X"] - P, "P' - (NE_XP)": f["P"] - (-(A @ X) + X @ (X.T @ A @ X - P.T @ P))}


@claim("h82-kappa-flows-psi-zero", paper=("grassmannian", "neumann", "NE_XP"), kind="id", sizes=SMALL)
def kappa_flows_psi_zero(s):
    """At (X, (I − XXᵀ)P) ∈ Ψ⁻¹(0) the Dirac flow of H_{neum,κ} (κ generic) is (NE_XP)."""
    return _kappa_flow(s, True)


@claim("n82-kappa-flows-psi-zero", paper=("grassmannian", "neumann", "NE_XP"), kind="id", sizes=SMALL,
       fails_at=lambda n, r: r >= 2, erratum="twin: at (X, P), not on Psi^{-1}(0)")
def kappa_flows_psi_zero_twin(s):
    """Twin: at (X, P)."""
    return _kappa_flow(s, False)


# 3 ---------------------------------------------------------------------------------------------
def _proj_accel(s, sign):
    flow = s.dirac_flow(H_euclid_neumann)
    vdot = lambda t: t.d(lambda u: u.X @ u.X.T, t.dirac_flow(H_euclid_neumann))
    X, P, A = s.X, s.P, s.A
    v = X @ X.T
    Lam = X.T @ A @ X + sign * (P.T @ P)
    return {"v'' - formula": s.d(vdot, flow) - (-(A @ v + v @ A) + 2 * (P @ P.T) + 2 * (X @ Lam @ X.T))}


@claim("h82-grassmann-projector-accel", paper=("neum-gras", "NE_XP", "grassmannian"), kind="id", sizes=SMALL)
def grassmann_projector_accel(s):
    """d²(XXᵀ)/dt² along (NE_XP) is −(Av + vA) + 2PPᵀ + 2XΛXᵀ, Λ = XᵀAX − PᵀP."""
    return _proj_accel(s, -1)


@claim("n82-grassmann-projector-accel", paper=("neum-gras", "NE_XP", "grassmannian"), kind="id", sizes=SMALL,
       fails_at=lambda n, r: n >= 2, erratum="twin: Lambda with +P^T P")
def grassmann_projector_accel_twin(s):
    """Twin: Λ = XᵀAX + PᵀP."""
    return _proj_accel(s, 1)


# 4 ---------------------------------------------------------------------------------------------
def _euler_ss(t, z):
    e = z["e"]
    return {"Om": comm(t.A, e @ e.T), "e": z["Om"] @ e}


def _euler_ss_claim(s, sign, traces):
    z = {"Om": s.xi, "e": s.X}
    f = _euler_ss(s, z)
    H = lambda t, w: t.killing(w["Om"], w["Om"]) / 2 + (t.tr(t.A) + sign * t.tr(w["e"].T @ t.A @ w["e"])) / 2
    out = {"dH_CP/dt": derivative(s, H, z, f)}
    if traces:
        def trL(k):
            def F(t, w):
                L = t.lam * w["Om"] + t.In - w["e"] @ w["e"].T - t.lam * t.lam * t.A
                M = L
                for _ in range(k - 1):
                    M = M @ L
                return t.tr(M)
            return F
        for k in (2, 3):
            out[f"d tr L^{k}/dt"] = derivative(s, trL(k), z, f)
    return out


@claim("h82-euler-star-star-integrals", paper=("YM", "Euler**", "mag*", "LA1"), kind="pb", sizes=R1)
def euler_star_star_integrals(s):
    """Along (Euler**) on so(n) × S^{n−1}: H_CP = ½⟨Ω,Ω⟩ + ½(tr A − (e, Ae)) and tr(λΩ + I − eeᵀ − λ²A)^k, k = 2, 3, are conserved."""
    return _euler_ss_claim(s, -1, True)


@claim("n82-euler-star-star-integrals", paper=("YM", "Euler**", "mag*"), kind="pb", sizes=R1,
       fails_at=lambda n, r: n >= 2, erratum="twin: +1/2 (e, Ae)")
def euler_star_star_integrals_twin(s):
    """Twin: ½⟨Ω,Ω⟩ + ½(tr A + (e, Ae))."""
    return _euler_ss_claim(s, 1, False)


# 5 ---------------------------------------------------------------------------------------------
def _ym(s, sign):
    z = {"Om": s.xi, "e": s.X}
    f = _euler_ss(s, z)
    e, A = s.X, s.A
    ed = f["e"]
    edd = derivative(s, lambda t, w: w["Om"] @ w["e"], z, f)
    w = ed @ e.T - e @ ed.T
    F = s.xi + sign * w
    return {"e'' - (mag6)": edd - (A @ e - e @ (e.T @ A @ e + ed.T @ ed)) - F @ ed}


@claim("h82-ym-reduced-second-derivative", paper=("YM", "mag6", "mag3", "OD"), kind="id", sizes=R1)
def ym_reduced_second_derivative(s):
    """On so(n) × S^{n−1} along (Euler**): ë = Ae − ((e,Ae) + (ė,ė))e + F_Ω ė, F_Ω = Ω − ė∧e."""
    return _ym(s, -1)


@claim("n82-ym-reduced-second-derivative", paper=("YM", "mag6"), kind="id", sizes=R1,
       fails_at=lambda n, r: n >= 2, erratum="twin: F = Omega + e' wedge e")
def ym_reduced_second_derivative_twin(s):
    """Twin: F = Ω + ė∧e."""
    return _ym(s, 1)


# 6 ---------------------------------------------------------------------------------------------
def _psi12_flow(s, transpose):
    J = twisted.magnetic_matrix(s)
    M = J.T if transpose else J
    f = twisted.flow(s, psi12)
    return {"X' - XJ": f["X"] - s.X @ M, "P' - PJ": f["P"] - s.P @ M}


@claim("h82-twisted-psi12-flow", paper=("twisted", "mag-euk"), kind="pb", sizes=R2)
def twisted_psi12_flow(s):
    """For ω_ε, the Hamiltonian vector field of Ψ₁₂ = ⟨Ψ, J⟩ is the right rotation (XJ, PJ), J = E₁∧E₂."""
    return _psi12_flow(s, False)


@claim("n82-twisted-psi12-flow", paper=("twisted", "mag-euk"), kind="pb", sizes=R2,
       fails_at=lambda n, r: True, erratum="twin: J^T")
def twisted_psi12_flow_twin(s):
    """Twin: (XJᵀ, PJᵀ)."""
    return _psi12_flow(s, True)


# 7 ---------------------------------------------------------------------------------------------
def _mag_euk(s, transpose):
    J = twisted.magnetic_matrix(s)
    X, P, A = s.X, s.P, s.A
    f = twisted.flow(s, H_euclid_neumann)
    Lam = X.T @ A @ X - P.T @ P - s.eps * psi12(s) * s.Ir / 2
    M = J if transpose else J.T
    return {"X' - P": f["X"] - P, "P' - matrix form": f["P"] - (-(A @ X) + X @ Lam + s.eps * (P @ M))}


@claim("h82-mag-euk-matrix-form", paper=("mag-euk", "twisted"), kind="id", sizes=R2)
def mag_euk_matrix_form(s):
    """(mag-euk): Ẋ = P, Ṗ = −AX + X(XᵀAX − PᵀP − ½εΨ₁₂I) + εPJᵀ."""
    return _mag_euk(s, False)


@claim("n82-mag-euk-matrix-form", paper=("mag-euk", "twisted"), kind="id", sizes=R2,
       fails_at=lambda n, r: True, erratum="twin: eps P J")
def mag_euk_matrix_form_twin(s):
    """Twin: εPJ."""
    return _mag_euk(s, True)


# 8 ---------------------------------------------------------------------------------------------
def _double_equiv(s, wrong):
    z = double_point(s)
    R = s.generic("R", "r", "r")
    Ri = R.T if wrong else R.inv()
    z2 = {"X": z["X"] @ R.T, "Y": z["Y"] @ Ri, "Xdot": z["Xdot"] @ R.T, "Ydot": z["Ydot"] @ Ri}
    f, f2 = flow_double(s, z), flow_double(s, z2)
    return {"X''(z') - X'' R^T": f2["Xdot"] - f["Xdot"] @ R.T, "Y''(z') - Y'' R^-1": f2["Ydot"] - f["Ydot"] @ Ri}


@claim("h82-double-gl-r-equivariance", paper=("dual-D", "D-eq", "D-L"), kind="id", sizes=ALL)
def double_gl_r_equivariance(s):
    """(D-eq) is equivariant under (X, Y, Ẋ, Ẏ) ↦ (XRᵀ, YR⁻¹, ẊRᵀ, ẎR⁻¹), R ∈ GL(r)."""
    return _double_equiv(s, False)


@claim("n82-double-gl-r-equivariance", paper=("dual-D", "D-eq"), kind="id", sizes=ALL,
       fails_at=lambda n, r: True, erratum="twin: Y R^T")
def double_gl_r_equivariance_twin(s):
    """Twin: Y ↦ YRᵀ."""
    return _double_equiv(s, True)


# 9 ---------------------------------------------------------------------------------------------
def _coupled_half(s, wrong):
    X, P, Y, Q, A = s.X, s.P, s.Y, s.Q, s.A
    f = stiefel_pairs_flow(s, H_coupled, {"X": X, "P": P, "Y": Y, "Q": Q}, [("X", "P"), ("Y", "Q")])
    c = 1 + 2 * s.kappa
    Lam = (X.T @ A @ Y - P.T @ P) if wrong else ((X.T @ A @ Y + Y.T @ A @ X) / 2 - P.T @ P)
    return {"X' - (C-eq)": f["X"] - (P - c * (X @ P.T @ X)),
            "P' - (C-eq)": f["P"] - (-(A @ Y) + c * (P @ X.T @ P) + X @ Lam)}


@claim("h82-coupled-xp-half", paper=("C-neumann", "C-eq", "C-L"), kind="id", sizes=admissible(n_max=3))
def coupled_xp_half(s):
    """The (X, P) lines of (C-eq) with Λ of (C-L) are the Dirac flow of (C-neumann), κ generic."""
    return _coupled_half(s, False)


@claim("n82-coupled-xp-half", paper=("C-neumann", "C-eq", "C-L"), kind="id", sizes=admissible(n_max=3),
       fails_at=lambda n, r: r >= 2, erratum="twin: Lambda = X^T A Y - P^T P")
def coupled_xp_half_twin(s):
    """Twin: Λ = XᵀAY − PᵀP."""
    return _coupled_half(s, True)


# 10 --------------------------------------------------------------------------------------------
def _psi_sum(s, sign, dyn):
    z = complex_point(s)
    a, b = psi_sum(s, z)
    c, d = psi0_trace(s, z)
    out = {"Re(sum psi_j + tr psi_0)": a + sign * c, "Im(sum psi_j + tr psi_0)": b + sign * d}
    if dyn:
        da, db = derivative(s, psi_sum, z, flow_complex(s, z))
        out["d/dt Re sum psi_j"] = da
        out["d/dt Im sum psi_j"] = db
    return out


@claim("h82-complex-psi-sum", paper=("u(1)", "W-eq", "W-L"), kind="pb", sizes=admissible(n_max=3))
def complex_psi_sum(s):
    """Σ_j ψ_j = −tr ψ₀ on TW(n, r), and it is conserved along (W-eq)."""
    return _psi_sum(s, 1, True)


@claim("n82-complex-psi-sum", paper=("u(1)", "W-eq"), kind="pb", sizes=admissible(n_max=3),
       fails_at=lambda n, r: True, erratum="twin: + tr psi_0")
def complex_psi_sum_twin(s):
    """Twin: Σ_j ψ_j = tr ψ₀."""
    return _psi_sum(s, -1, False)


# 11 --------------------------------------------------------------------------------------------
def _manakov(s, c2):
    flow = s.dirac_flow(H_manakov)
    I = lambda t: c2 * t.tr(t.Phi @ t.Phi @ t.A @ t.A) + t.tr(t.Phi @ t.A @ t.Phi @ t.A)
    return {"dI/dt": s.d(I, flow)}


@claim("h82-manakov-lambda2", paper=("man", "Manakov", "dot_XP2"), kind="pb", sizes=SMALL)
def manakov_lambda2(s):
    """Along the flow of ½⟨Φ, AΦ + ΦA⟩: 2tr Φ²A² + tr ΦAΦA (the λ² coefficient of tr(Φ + λA)⁴, halved) is conserved."""
    return _manakov(s, 2)


@claim("n82-manakov-lambda2", paper=("man", "Manakov"), kind="pb", sizes=SMALL, fails_at=lambda n, r: n >= 3,
       erratum="twin: coefficient 1")
def manakov_lambda2_twin(s):
    """Twin: tr Φ²A² + tr ΦAΦA."""
    return _manakov(s, 1)


# 12 --------------------------------------------------------------------------------------------
def _normal_accel(s, transpose):
    flow = s.dirac_flow(H_normal)
    Xd = lambda t: t.dirac_flow(H_normal)["X"]
    Pd = lambda t: t.dirac_flow(H_normal)["P"]
    Ph = s.Phi
    M = (Ph.T @ Ph) if transpose else (Ph @ Ph)
    return {"X'' - Phi^2 X": s.d(Xd, flow) - M @ s.X, "P'' - Phi^2 P": s.d(Pd, flow) - M @ s.P}


@claim("h82-normal-geodesic-accel", paper=("normal_metric", "dot_X3", "dot_P3"), kind="id", sizes=SMALL)
def normal_geodesic_accel(s):
    """Along the normal geodesic flow, Ẍ = Φ²X and P̈ = Φ²P."""
    return _normal_accel(s, False)


@claim("n82-normal-geodesic-accel", paper=("normal_metric", "dot_X3", "dot_P3"), kind="id", sizes=SMALL,
       fails_at=lambda n, r: n >= 2, erratum="twin: Phi^T Phi")
def normal_geodesic_accel_twin(s):
    """Twin: ΦᵀΦ."""
    return _normal_accel(s, True)
