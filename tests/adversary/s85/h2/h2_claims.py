"""h2 (stop 85): hidden statements of §2, §5, §7 and the appendices, each with a false twin.

Truth derived independently by indep.py (numpy, no stiefelsym; output in indep_output.txt) and by hand:

h2-jensen-multipliers (TRUE): along the Dirac flow of H_κ = ½tr PᵀP − (½+κ)tr (XᵀP)² (the kinetic part of
  (neumann), the proof of Prop. (No) with A = 0), Π = 0 and Λ = −PᵀP for every κ.
h2-jensen-multipliers-twin (FALSE for r ≥ 2, true at r = 1): Λ = −ẊᵀẊ for every κ (the §3 form of the
  Euclidean metric, κ = −½ only): ẊᵀẊ = PᵀP − (2c + c²)K², c = 1 + 2κ, K = XᵀP (K = 0 at r = 1).
h2-general-multipliers (TRUE): (dot_XP) for a general H: Π = sym(XᵀH_P), Λ = sym(XᵀH_X − H_PᵀP) + ΠK − KΠ,
  K = XᵀP (from d/dt of the constraints; derived by hand).
h2-general-multipliers-twin (FALSE for r ≥ 2; true at r = 1 where [K, Π] = 0): KΠ − ΠK.
h2-quartic-multipliers (TRUE): (quartic) H = ½tr PᵀP + tr XᵀA²X − tr (XᵀAX)²: Π = 0,
  Λ = 2XᵀA²X − 4(XᵀAX)² − PᵀP.
h2-quartic-multipliers-twin (FALSE everywhere): 2(XᵀAX)² for 4(XᵀAX)².
h2-coupled-diagonal (TRUE): at X = Y, P = Q the flow of (C-neumann) is the Neumann flow (No) with the same κ
  (both points move alike); the corrected (C-eq) (YΠ) restricted to the diagonal.
h2-coupled-diagonal-twin (FALSE for r ≥ 2, true at r = 1): (No) with 1 + 4κ in place of 1 + 2κ.
h2-coupled-r1-metrics (TRUE, r = 1): App. 2 remark "in the case r = 1 ... all the above metrics coincide":
  the flows of (C-neumann) for κ and for κ = 0 coincide.
h2-coupled-r2-metrics-twin (FALSE, r = 2): the same at r = 2.
h2-pr-e-rank (TRUE, n ≥ 2): pr_e(ξ) = ξe⊗e + e⊗eξ (App. 1, e = Xe₁ a unit vector) maps so(n) onto
  e∧ℝⁿ ≅ T_eS^{n−1}: rank n − 1, idempotent, skew; pr_{e⊥}(ξ)e = 0.
h2-pr-e-rank-twin (FALSE): rank n.
h2-trL3-expansion (TRUE): tr 𝓛³ = r + λ²(3tr(Φ²XXᵀ) − 3tr(AXXᵀ)) + λ⁴(3tr(XXᵀA²) − 3tr(Φ²A)) − λ⁶tr A³
  for 𝓛 = λΦ + XXᵀ − λ²A (LA2), and the λ⁴ coefficient is conserved along (No) for every κ.
h2-trL3-expansion-twin (FALSE for r < n, n ≥ 2; the expansion part false wherever tr Φ²A ≠ 0): +3tr(Φ²A).
h2-neumann-kappas-commute (TRUE): {H_neum,κ, H_neum,κ'} = 0 for independent κ, κ' (Ψ conserved).
h2-neumann-kappas-commute-twin (FALSE for r < n, n ≥ 2): {H_neum,κ, ½tr PᵀP + tr XᵀAX} = 0.
h2-magnetic-multipliers (TRUE, r = 2): the Lagrange form of the twisted Euclidean Neumann flow (mag-euk) has
  Π = 0, Λ = XᵀAX − PᵀP − ½εΨ₁₂I₂ = XᵀAX − PᵀP + ½εΨF (F = E₁E₂ᵀ − E₂E₁ᵀ, Ψ = Ψ₁₂F), read off (mag-euk):
  Λ₁₁ = (e₁,Ae₁) − (p₁,p₁) − ε(e₁,p₂), Λ₂₂ = … + ε(e₂,p₁) and (e₂,p₁) = −(e₁,p₂) = −½Ψ₁₂.
h2-magnetic-multipliers-twin (FALSE): εΨF (factor 2).
h2-magnetic-energy (TRUE, r = 2): ⟨Φ_ε, Φ_ε⟩ + tr XᵀAX (−2 × the λ² coefficient of tr 𝓛_ε² / 2) is conserved
  along the twisted Euclidean flow (mag-euk).
h2-magnetic-energy-twin (FALSE for n ≥ 3; true at n = 2 where tr XᵀAX = tr A): ⟨Φ_ε, Φ_ε⟩ − tr XᵀAX.
"""
from stiefelsym import Rank, admissible, claim, twisted
from stiefelsym.bases import matrix_of, so_basis
from stiefelsym.systems import stiefel_pairs_flow


def sym(M):
    return (M + M.T) / 2


def H_jensen(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K)


@claim("h2-jensen-multipliers", kind="pb", section="2", sizes=admissible(n_max=4))
def jensen_multipliers(s):
    """Along the Dirac flow of ½tr PᵀP − (½+κ)tr(XᵀP)², Π = 0 and Λ = −PᵀP for every κ."""
    f = s.multiplier_flow(H_jensen)
    g = s.dirac_flow(H_jensen)
    return {"Pi": f["Pi"], "Lambda": f["Lambda"] + s.P.T @ s.P,
            "Xdot agrees": f.Xdot - g.Xdot, "Pdot agrees": f.Pdot - g.Pdot}


@claim("h2-jensen-multipliers-twin", kind="pb", section="2", sizes=admissible(n_max=4))
def jensen_multipliers_twin(s):
    """FALSE for r >= 2: Λ = −ẊᵀẊ for every κ."""
    f = s.multiplier_flow(H_jensen)
    return {"Lambda": f["Lambda"] + f.Xdot.T @ f.Xdot}


def H_general(t):
    U, V, B = t.generic("U", "n", "r"), t.generic("V", "n", "r"), t.generic("B", "n", "n")
    return (t.tr(U.T @ t.X) + t.tr(V.T @ t.P) + t.tr(t.P.T @ B @ t.X)
            + t.tr(t.P.T @ t.P) * t.tr(t.X.T @ t.A @ t.X) / 2)


def general_multipliers(s, sign):
    f = s.dirac_flow(H_general)
    m = s.multiplier_flow(H_general)
    HX, HP = s.gradient(H_general)
    K = s.X.T @ s.P
    Pi = sym(s.X.T @ HP)
    Lam = sym(s.X.T @ HX - HP.T @ s.P) + sign * (Pi @ K - K @ Pi)
    return {"Pi": m["Pi"] - Pi, "Lambda": m["Lambda"] - Lam,
            "Xdot (Dirac)": f.Xdot - (HP - s.X @ Pi),
            "Pdot (Dirac)": f.Pdot - (-HX + s.X @ Lam + s.P @ Pi)}


@claim("h2-general-multipliers", kind="pb", section="2", sizes=admissible(n_max=4))
def general_multipliers_true(s):
    """(dot_XP) for a general H: Π = sym(XᵀH_P), Λ = sym(XᵀH_X − H_PᵀP) + ΠK − KΠ, K = XᵀP."""
    return general_multipliers(s, 1)


@claim("h2-general-multipliers-twin", kind="pb", section="2", sizes=admissible(n_max=4))
def general_multipliers_twin(s):
    """FALSE for r >= 2: KΠ − ΠK."""
    return general_multipliers(s, -1)


def H_quartic(t):
    X, A = t.X, t.A
    S = X.T @ A @ X
    return t.tr(t.P.T @ t.P) / 2 + t.tr(X.T @ A @ A @ X) - t.tr(S @ S)


def quartic_multipliers(s, c):
    m = s.multiplier_flow(H_quartic)
    X, A = s.X, s.A
    S = X.T @ A @ X
    return {"Pi": m["Pi"], "Lambda": m["Lambda"] - (2 * X.T @ A @ A @ X - c * S @ S - s.P.T @ s.P)}


@claim("h2-quartic-multipliers", kind="id", section="7", sizes=admissible(n_max=4))
def quartic_multipliers_true(s):
    """(quartic): Π = 0, Λ = 2XᵀA²X − 4(XᵀAX)² − PᵀP."""
    return quartic_multipliers(s, 4)


@claim("h2-quartic-multipliers-twin", kind="id", section="7", sizes=admissible(n_max=4))
def quartic_multipliers_twin(s):
    """FALSE: 2(XᵀAX)²."""
    return quartic_multipliers(s, 2)


def H_coupled(kappa):
    def H(t, z):
        XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
        c = t.q(1, 2) + kappa(t)
        return (t.tr(z["P"].T @ z["P"]) / 2 - c * t.tr(XP @ XP) + t.tr(z["Q"].T @ z["Q"]) / 2 - c * t.tr(YQ @ YQ)
                + t.tr(z["X"].T @ t.A @ z["Y"]))
    return H


def coupled_diag(s, c):
    z = {"X": s.X, "P": s.P, "Y": s.X, "Q": s.P}
    f = stiefel_pairs_flow(s, H_coupled(lambda t: t.kappa), z, [("X", "P"), ("Y", "Q")])
    X, P, A = s.X, s.P, s.A
    NoX = P - c * X @ P.T @ X
    NoP = -(A @ X) - X @ P.T @ P + c * P @ X.T @ P + X @ X.T @ A @ X
    return {"Xdot": f["X"] - NoX, "Pdot": f["P"] - NoP, "Ydot": f["Y"] - NoX, "Qdot": f["Q"] - NoP}


@claim("h2-coupled-diagonal", kind="id", section="A2", sizes=admissible(n_max=4))
def coupled_diagonal(s):
    """At X = Y, P = Q the flow of (C-neumann) is (No) with the same κ for both points."""
    return coupled_diag(s, 1 + 2 * s.kappa)


@claim("h2-coupled-diagonal-twin", kind="id", section="A2", sizes=admissible(n_max=4))
def coupled_diagonal_twin(s):
    """FALSE for r >= 2: (No) with 1 + 4κ."""
    return coupled_diag(s, 1 + 4 * s.kappa)


def coupled_metrics(s):
    z = {"X": s.X, "P": s.P, "Y": s.Y, "Q": s.Q}
    pairs = [("X", "P"), ("Y", "Q")]
    f = stiefel_pairs_flow(s, H_coupled(lambda t: t.kappa), z, pairs)
    g = stiefel_pairs_flow(s, H_coupled(lambda t: t.q(0)), z, pairs)
    return {k: f[k] - g[k] for k in ("X", "P", "Y", "Q")}


@claim("h2-coupled-r1-metrics", kind="id", section="A2", sizes=admissible(n_max=4, r_max=1, condition="r = 1"))
def coupled_r1_metrics(s):
    """r = 1: the coupled flows of (C-neumann) for κ and for κ = 0 coincide (all the metrics coincide)."""
    return coupled_metrics(s)


@claim("h2-coupled-r2-metrics-twin", kind="id", section="A2",
       sizes=admissible(n_max=4, r_min=2, r_max=2, condition="r = 2"))
def coupled_r2_metrics_twin(s):
    """FALSE: at r = 2 the coupled flows for κ and κ = 0 coincide."""
    return coupled_metrics(s)


def pr_e(xi, e):
    return xi @ e @ e.T + e @ e.T @ xi



@claim("h2-pr-e-rank", kind="dim", section="A1", sizes=admissible(n_max=4, n_min=2))
def pr_e_rank(s):
    """pr_e(ξ) = ξe⊗e + e⊗eξ (e = Xe₁) has rank n − 1 on so(n), is skew, idempotent, and pr_{e⊥}(ξ)e = 0."""
    e = s.X[:, 0:1]
    n = int(s.n)
    M = matrix_of(s, lambda xi: pr_e(xi, e), so_basis(s, "n"))
    xi = s.xi
    return {"rank": Rank(M, n - 1),
            "skew": pr_e(xi, e) + pr_e(xi, e).T,
            "idempotent": pr_e(pr_e(xi, e), e) - pr_e(xi, e),
            "perp annihilates e": (xi - pr_e(xi, e)) @ e}


@claim("h2-pr-e-rank-twin", kind="dim", section="A1", sizes=admissible(n_max=4, n_min=2))
def pr_e_rank_twin(s):
    """FALSE: rank n."""
    e = s.X[:, 0:1]
    n = int(s.n)
    M = matrix_of(s, lambda xi: pr_e(xi, e), so_basis(s, "n"))
    return {"rank": Rank(M, n)}


def H_neum(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def trL3(s, sign):
    lam, A, V, F = s.lam, s.A, s.X @ s.X.T, s.Phi
    L = lam * F + V - lam * lam * A
    lam2, lam4 = lam * lam, lam * lam * lam * lam
    expansion = (s.r + lam2 * (3 * s.tr(F @ F @ V) - 3 * s.tr(A @ V))
                 + lam4 * (3 * s.tr(V @ A @ A) - sign * 3 * s.tr(F @ F @ A)) - lam4 * lam2 * s.tr(A @ A @ A))
    c4 = lambda t: t.tr(t.X.T @ t.A @ t.A @ t.X) - sign * t.tr(t.Phi @ t.Phi @ t.A)
    return {"tr L^3 expansion": s.tr(L @ L @ L) - expansion,
            "lambda^4 coefficient conserved": s.d(c4, s.dirac_flow(H_neum))}


@claim("h2-trL3-expansion", kind="pb", section="5", sizes=admissible(n_max=4))
def trL3_true(s):
    """tr 𝓛³ = r + λ²(3trΦ²XXᵀ − 3trAXXᵀ) + λ⁴(3trXXᵀA² − 3trΦ²A) − λ⁶trA³; its λ⁴ coefficient is conserved along (No)."""
    return trL3(s, 1)


@claim("h2-trL3-expansion-twin", kind="pb", section="5", sizes=admissible(n_max=4))
def trL3_twin(s):
    """FALSE: +3trΦ²A."""
    return trL3(s, -1)


def H_neum_k2(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.scalar("k2")) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_twice_potential(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X)


@claim("h2-neumann-kappas-commute", kind="pb", section="5", sizes=admissible(n_max=4))
def kappas_commute(s):
    """{H_neum,κ, H_neum,κ'} = 0 for independent κ, κ'."""
    return {"bracket": s.bracket(H_neum, H_neum_k2)}


@claim("h2-neumann-kappas-commute-twin", kind="pb", section="5", sizes=admissible(n_max=4))
def kappas_commute_twin(s):
    """FALSE for r < n: {H_neum,κ, ½trPᵀP + trXᵀAX} = 0."""
    return {"bracket": s.bracket(H_neum, H_twice_potential)}


ON_V_N2 = admissible(n_max=4, n_min=2, r_min=2, r_max=2, condition="r = 2")


def H_E(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def mag_mult(s, c):
    m = twisted.multiplier_flow(s, H_E)
    F = twisted.magnetic_matrix(s)
    return {"Pi": m["Pi"],
            "Lambda": m["Lambda"] - (s.X.T @ s.A @ s.X - s.P.T @ s.P + c * s.eps * s.Psi @ F),
            "Xdot = P": m.Xdot - s.P}


@claim("h2-magnetic-multipliers", kind="id", section="A1", sizes=ON_V_N2)
def magnetic_multipliers(s):
    """(mag-euk) in Lagrange form: Π = 0, Λ = XᵀAX − PᵀP + ½εΨF = XᵀAX − PᵀP − ½εΨ₁₂I."""
    return mag_mult(s, s.q(1, 2))


@claim("h2-magnetic-multipliers-twin", kind="id", section="A1", sizes=ON_V_N2)
def magnetic_multipliers_twin(s):
    """FALSE: εΨF."""
    return mag_mult(s, 1)


def e1e2(t):
    e1, e2 = t.X @ twisted.basis_vector(t, 0), t.X @ twisted.basis_vector(t, 1)
    return e1 @ e2.T - e2 @ e1.T


def mag_energy(s, sign):
    flow = twisted.flow(s, H_E)
    I = lambda t: (t.killing(t.Phi + t.eps * e1e2(t), t.Phi + t.eps * e1e2(t))
                   + sign * t.tr(t.X.T @ t.A @ t.X))
    return {"d/dt": s.d(I, flow)}


@claim("h2-magnetic-energy", kind="pb", section="A1", sizes=ON_V_N2)
def magnetic_energy(s):
    """⟨Φ_ε, Φ_ε⟩ + trXᵀAX is conserved along (mag-euk)."""
    return mag_energy(s, 1)


@claim("h2-magnetic-energy-twin", kind="pb", section="A1", sizes=ON_V_N2)
def magnetic_energy_twin(s):
    """FALSE for n >= 3: ⟨Φ_ε, Φ_ε⟩ − trXᵀAX."""
    return mag_energy(s, -1)
