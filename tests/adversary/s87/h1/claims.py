"""s87h1: hidden statements of §4, §6, §7 of Fedorov–Jovanović, each TRUE statement with a FALSE twin.

Truth: by hand (below) and by numpy (truth_numpy.py -> truth_numpy_output.txt; no stiefelsym import;
its own Dirac flows/brackets with complex-step gradients).  K = XᵀP (skew on T*V), Ψ = 2K, Φ = PXᵀ − XPᵀ.

§4
 s87h1-manakov-euler (TRUE): along the Dirac flow of H_𝔸 = ½<𝔸Φ, Φ>, 𝔸ξ = Aξ + ξA (B = A²), Φ̇ = [𝔸Φ, Φ]
   (Euler-so(n)).  By hand: Ẋ = MX, Ṗ = MP with M = 𝔸Φ skew, so Φ̇ = MΦ + ΦMᵀ = [M, Φ].
 s87h1-manakov-euler-twin (FALSE for n ≥ 3; true at n ≤ 2, so(2) abelian): Φ̇ = [Φ, 𝔸Φ].
 s87h1-manakov-quartic (TRUE): 2tr(A²Φ²) + tr(AΦAΦ) (the λ² coefficient of tr(λA + Φ)⁴ of (man), /2) is
   conserved by the same flow.
 s87h1-manakov-quartic-twin (FALSE for n ≥ 3): tr(A²Φ²) + tr(AΦAΦ) conserved.
 s87h1-gram-psi-bracket (TRUE): the "straightforward calculation" of the remark after Theorem ET:
   {tr(G PᵀP), <Ψ, Ψ>} = 2 tr(G[PᵀP, Ψ]) (G generic r×r) — nonzero for 2 ≤ r < n.
   By hand: the field of <Ψ,Ψ> is the right action by a multiple of Ψ; the factor 2 from numpy.
 s87h1-gram-psi-bracket-twin (FALSE for 2 ≤ r < n): = −2 tr(G[PᵀP, Ψ]).
 s87h1-manakov-delta (TRUE, n ≥ 2r): δ = 2dim V − ddim − l = r(n − r), with ddim (ddim) and 2l (Lemma 2l).
 s87h1-manakov-delta-twin (FALSE at (2,2), (3,3), (4,3), (4,4), ...): the same for every n, r.

§6
 s87h1-lambda-1-minus-2 (TRUE): (LAMBDA) Λ_{1,−1} = Λ1 − Λ2 at x = h + v equals
   −<h, [η, θ]> + <A, [ξ, θ] + [η, ζ]> (generic h ∈ so(n), v ∈ Sym(n), ξ, ζ ∈ so(n), η, θ ∈ Sym(n)).
 s87h1-lambda-1-minus-2-twin (FALSE): +<h, [η, θ]> + ...
 s87h1-kernel-l3-l4 (TRUE): (L3), (L4): η = A², ξ = −(Ah + hA) lies in ker Λ_{1,−1}(h + v) at h + v = Θ(X, P):
   [η, A] = 0 and [ξ, A] = [A², h] = [η, h].  Residual Λ_{1,−1}(ξ + η, ζ + θ) from the definitions (LAMBDA12).
 s87h1-kernel-l3-l4-twin (FALSE for n ≥ 2): ξ = Ah + hA.
 s87h1-hb-euler (TRUE): along the geodesic flow of H_𝔹 (HB), 𝔹ξ = Bξ + ξB (B generic symmetric r×r),
   Ψ̇ = [Ψ, 𝔹Ψ], the Euler equations (e-so(r)) (Ψ is the momentum map of the right action).
 s87h1-hb-euler-twin (FALSE for r ≥ 3; true at r ≤ 2, so(2) abelian): Ψ̇ = −[Ψ, 𝔹Ψ].
 s87h1-neum-b-euler (TRUE): along the Neumann flow H_neum,𝔹 of Corollary COM the same Ψ̇ = [Ψ, 𝔹Ψ]
   (the potential ½tr XᵀAX is right-invariant).
 s87h1-neum-b-euler-twin (FALSE for r ≥ 2): Ψ̇ = [Ψ, 𝔹Ψ] + [Ψ, XᵀAX] (a torque of the potential).
 s87h1-lema1-rank (TRUE): Λ1 at x = h + v = Θ(X, P), as the map u ↦ [v, u] + [h, (u − uᵀ)/2] of gl(n)
   (Λ1(u, w) = <that, w>), has generic rank 2l = 2r(n − r) + r(r − 1)/2 − [r/2] (dimension).
 s87h1-lema1-rank-twin (FALSE for r ≥ 2): rank 2r(n − r) + r(r − 1)/2 + [r/2].
 s87h1-lema1-count (TRUE): n² − (rank so(r) + dim so(n−r) + dim Sym(r) + dim Sym(n−r)) = 2l.
 s87h1-lema1-count-twin (FALSE): with dim so(r) in place of dim Sym(r).

§7
 s87h1-neumann2-rank (TRUE): at a generic point of Ψ⁻¹(0) (P = (I − XXᵀ)Z) the same map has rank
   2r(n − r) = 2 dim G_{n,r} (kernel gl(r) ⊕ gl(n − r)).
 s87h1-neumann2-rank-twin (FALSE for r ≥ 3, true for r ≤ 2): rank 2l (the generic value of Lemma LEMA1).
 s87h1-velocity-psi (TRUE): along the Neumann flow (No) for every κ, XᵀẊ = (1 + κ)Ψ, so (gras-velocities)
   (ė_i, e_j) = 0 on Ψ⁻¹(0).  By hand: Ẋ = P − (1+2κ)XPᵀX, XᵀẊ = K + (1+2κ)K.
 s87h1-velocity-psi-twin (FALSE for r ≥ 2): XᵀẊ = (1 + 2κ)Ψ (true at κ = 0 only).
 s87h1-ne-multiplier (TRUE): for (NE_XP) (H = ½tr PᵀP + ½tr XᵀAX) the multipliers of (dot_XP) are
   Λ = XᵀAX − ẊᵀẊ (so λ = tr Λ of (neum-gras)) and Π = 0.
 s87h1-ne-multiplier-twin (FALSE for r ≥ 2): Λ = XᵀAX − ẊᵀẊ for the Neumann flow of every κ
   (the multiplier is XᵀAX − PᵀP, and ẊᵀẊ = PᵀP − (1+2κ)(3+2κ)K²).
"""
from __future__ import annotations

from stiefelsym import Count, Rank, admissible, claim, comm
from stiefelsym.bases import matrix_of, matrix_units

ANY = admissible(n_max=4)


# ---------------------------------------------------------------- §4
def manakov_op(t, xi):
    return t.A @ xi + xi @ t.A


def H_manakov(t):
    return t.killing(manakov_op(t, t.Phi), t.Phi) / 2


@claim("s87h1-manakov-euler", kind="lax", section="4", sizes=ANY)
def manakov_euler(s):
    """Along the Manakov flow (B = A²), Φ̇ = [𝔸Φ, Φ] (TRUE)."""
    f = s.dirac_flow(H_manakov)
    return {"dPhi": s.d(lambda t: t.Phi, f) - comm(manakov_op(s, s.Phi), s.Phi)}


@claim("s87h1-manakov-euler-twin", kind="lax", section="4", sizes=ANY)
def manakov_euler_twin(s):
    """FALSE twin: Φ̇ = [Φ, 𝔸Φ]."""
    f = s.dirac_flow(H_manakov)
    return {"dPhi": s.d(lambda t: t.Phi, f) - comm(s.Phi, manakov_op(s, s.Phi))}


@claim("s87h1-manakov-quartic", kind="pb", section="4", sizes=ANY)
def manakov_quartic(s):
    """2tr(A²Φ²) + tr(AΦAΦ) is an integral of the Manakov flow (TRUE)."""
    f = s.dirac_flow(H_manakov)
    F = lambda t: 2 * t.tr(t.A @ t.A @ t.Phi @ t.Phi) + t.tr(t.A @ t.Phi @ t.A @ t.Phi)
    return {"dF": s.d(F, f)}


@claim("s87h1-manakov-quartic-twin", kind="pb", section="4", sizes=ANY)
def manakov_quartic_twin(s):
    """FALSE twin: tr(A²Φ²) + tr(AΦAΦ) is an integral."""
    f = s.dirac_flow(H_manakov)
    F = lambda t: t.tr(t.A @ t.A @ t.Phi @ t.Phi) + t.tr(t.A @ t.Phi @ t.A @ t.Phi)
    return {"dF": s.d(F, f)}


def _gram_psi(s):
    G = s.generic("G", "r", "r")
    return s.bracket(lambda t: t.tr(G @ t.P.T @ t.P), lambda t: t.killing(t.Psi, t.Psi)), G


@claim("s87h1-gram-psi-bracket", kind="pb", section="4", sizes=ANY)
def gram_psi(s):
    """{tr(G PᵀP), <Ψ,Ψ>} = 2tr(G[PᵀP, Ψ]) (TRUE)."""
    b, G = _gram_psi(s)
    return {"bracket": b - 2 * s.tr(G @ comm(s.P.T @ s.P, s.Psi))}


@claim("s87h1-gram-psi-bracket-twin", kind="pb", section="4", sizes=ANY)
def gram_psi_twin(s):
    """FALSE twin: {tr(G PᵀP), <Ψ,Ψ>} = −2tr(G[PᵀP, Ψ])."""
    b, G = _gram_psi(s)
    return {"bracket": b + 2 * s.tr(G @ comm(s.P.T @ s.P, s.Psi))}


def _delta(n, r):
    dso = lambda m: m * (m - 1) // 2
    dimV = n * r - r * (r + 1) // 2
    ddim = dimV - dso(n - r) + (dso(n - 2 * r) if n > 2 * r else 0)
    two_l = (n * (n - 1) // 2 - n // 2) if n <= 2 * r + 1 else 2 * r * (n - r - 1)
    return 2 * (2 * dimV - ddim) - two_l   # 2δ


@claim("s87h1-manakov-delta", kind="dim", section="4",
       sizes=admissible(n_max=5, where=lambda n, r: n >= 2 * r, condition="n >= 2r"))
def manakov_delta(s):
    """δ = 2dim V − ddim − l = r(n − r) for n ≥ 2r (TRUE)."""
    n, r = int(s.n), int(s.r)
    return {"2 delta": Count(_delta(n, r), 2 * r * (n - r))}


@claim("s87h1-manakov-delta-twin", kind="dim", section="4", sizes=admissible(n_max=5))
def manakov_delta_twin(s):
    """FALSE twin: δ = r(n − r) for every n, r."""
    n, r = int(s.n), int(s.r)
    return {"2 delta": Count(_delta(n, r), 2 * r * (n - r))}


# ---------------------------------------------------------------- §6
def lam1(s, x, xi, eta, zeta, theta):
    return s.killing(x, comm(xi, zeta) + comm(xi, theta) + comm(eta, zeta))


def lam2(s, x, xi, eta, zeta, theta):
    return s.killing(x - s.A, comm(xi + eta, zeta + theta))


@claim("s87h1-lambda-1-minus-2", kind="pb", section="6", sizes=ANY)
def lambda_1_minus_2(s):
    """(LAMBDA): Λ1 − Λ2 at h + v = −<h,[η,θ]> + <A,[ξ,θ] + [η,ζ]> (TRUE)."""
    h, v = s.generic("h", "n", "n", "skew"), s.generic("v", "n", "n", "sym")
    eta, theta = s.generic("eta", "n", "n", "sym"), s.generic("theta", "n", "n", "sym")
    xi, zeta = s.xi, s.zeta
    lhs = lam1(s, h + v, xi, eta, zeta, theta) - lam2(s, h + v, xi, eta, zeta, theta)
    rhs = -s.killing(h, comm(eta, theta)) + s.killing(s.A, comm(xi, theta) + comm(eta, zeta))
    return {"LAMBDA": lhs - rhs}


@claim("s87h1-lambda-1-minus-2-twin", kind="pb", section="6", sizes=ANY)
def lambda_1_minus_2_twin(s):
    """FALSE twin: + <h,[η,θ]>."""
    h, v = s.generic("h", "n", "n", "skew"), s.generic("v", "n", "n", "sym")
    eta, theta = s.generic("eta", "n", "n", "sym"), s.generic("theta", "n", "n", "sym")
    xi, zeta = s.xi, s.zeta
    lhs = lam1(s, h + v, xi, eta, zeta, theta) - lam2(s, h + v, xi, eta, zeta, theta)
    rhs = s.killing(h, comm(eta, theta)) + s.killing(s.A, comm(xi, theta) + comm(eta, zeta))
    return {"LAMBDA": lhs - rhs}


def _kernel_residual(s, sign):
    h, v = s.Phi, s.X @ s.X.T
    eta = s.A @ s.A
    xi = sign * (s.A @ h + h @ s.A)
    zeta, theta = s.zeta, s.generic("theta", "n", "n", "sym")
    return lam1(s, h + v, xi, eta, zeta, theta) - lam2(s, h + v, xi, eta, zeta, theta)


@claim("s87h1-kernel-l3-l4", kind="pb", section="6", sizes=ANY)
def kernel_l3_l4(s):
    """η = A², ξ = −(Ah + hA) ∈ ker Λ_{1,−1}(Θ(X,P)) (TRUE)."""
    return {"Lambda_{1,-1}(xi+eta, .)": _kernel_residual(s, -1)}


@claim("s87h1-kernel-l3-l4-twin", kind="pb", section="6", sizes=ANY)
def kernel_l3_l4_twin(s):
    """FALSE twin: ξ = Ah + hA."""
    return {"Lambda_{1,-1}(xi+eta, .)": _kernel_residual(s, 1)}


def _bop(B, xi):
    return B @ xi + xi @ B


def _H_B(B):
    return lambda t: t.tr(t.P.T @ t.P) / 2 - t.tr(t.Psi @ _bop(B, t.Psi)) / 4


def _H_neum_B(B):
    return lambda t: t.tr(t.P.T @ t.P) / 2 - t.tr(t.Psi @ _bop(B, t.Psi)) / 4 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s87h1-hb-euler", kind="lax", section="6", sizes=ANY)
def hb_euler(s):
    """Along H_𝔹: Ψ̇ = [Ψ, 𝔹Ψ] (TRUE)."""
    B = s.generic("B", "r", "r", "sym")
    f = s.dirac_flow(_H_B(B))
    return {"dPsi": s.d(lambda t: t.Psi, f) - comm(s.Psi, _bop(B, s.Psi))}


@claim("s87h1-hb-euler-twin", kind="lax", section="6", sizes=ANY)
def hb_euler_twin(s):
    """FALSE twin: Ψ̇ = −[Ψ, 𝔹Ψ]."""
    B = s.generic("B", "r", "r", "sym")
    f = s.dirac_flow(_H_B(B))
    return {"dPsi": s.d(lambda t: t.Psi, f) + comm(s.Psi, _bop(B, s.Psi))}


@claim("s87h1-neum-b-euler", kind="lax", section="6", sizes=ANY)
def neum_b_euler(s):
    """Along H_neum,𝔹: Ψ̇ = [Ψ, 𝔹Ψ] (TRUE)."""
    B = s.generic("B", "r", "r", "sym")
    f = s.dirac_flow(_H_neum_B(B))
    return {"dPsi": s.d(lambda t: t.Psi, f) - comm(s.Psi, _bop(B, s.Psi))}


@claim("s87h1-neum-b-euler-twin", kind="lax", section="6", sizes=ANY)
def neum_b_euler_twin(s):
    """FALSE twin: Ψ̇ = [Ψ, 𝔹Ψ] + [Ψ, XᵀAX]."""
    B = s.generic("B", "r", "r", "sym")
    f = s.dirac_flow(_H_neum_B(B))
    return {"dPsi": s.d(lambda t: t.Psi, f) - comm(s.Psi, _bop(B, s.Psi)) - comm(s.Psi, s.X.T @ s.A @ s.X)}


def lambda1_matrix(s, P):
    h, v = P @ s.X.T - s.X @ P.T, s.X @ s.X.T
    return matrix_of(s, lambda u: comm(v, u) + comm(h, (u - u.T) / 2), matrix_units(s, "n", "n"))


def two_l(n, r):
    return 2 * r * (n - r) + r * (r - 1) // 2 - r // 2


@claim("s87h1-lema1-rank", kind="dim", section="6", sizes=ANY)
def lema1_rank(s):
    """rank Λ1(Θ(X,P)) = 2l (TRUE)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(lambda1_matrix(s, s.P), two_l(n, r))}


@claim("s87h1-lema1-rank-twin", kind="dim", section="6", sizes=ANY)
def lema1_rank_twin(s):
    """FALSE twin: rank 2r(n−r) + r(r−1)/2 + [r/2]."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(lambda1_matrix(s, s.P), 2 * r * (n - r) + r * (r - 1) // 2 + r // 2)}


@claim("s87h1-lema1-count", kind="dim", section="6", sizes=admissible(n_max=6))
def lema1_count(s):
    """n² − dim ker Λ1 = 2l (TRUE)."""
    n, r = int(s.n), int(s.r)
    dso, dsym = (lambda m: m * (m - 1) // 2), (lambda m: m * (m + 1) // 2)
    return {"n^2 - dim ker": Count(n * n - (r // 2 + dso(n - r) + dsym(r) + dsym(n - r)), two_l(n, r))}


@claim("s87h1-lema1-count-twin", kind="dim", section="6", sizes=admissible(n_max=6))
def lema1_count_twin(s):
    """FALSE twin: dim so(r) for dim Sym(r)."""
    n, r = int(s.n), int(s.r)
    dso, dsym = (lambda m: m * (m - 1) // 2), (lambda m: m * (m + 1) // 2)
    return {"n^2 - dim ker": Count(n * n - (r // 2 + dso(n - r) + dso(r) + dsym(n - r)), two_l(n, r))}


# ---------------------------------------------------------------- §7
def _p_on_psi_zero(s):
    Z = s.generic("Z", "n", "r")
    return (s.In - s.X @ s.X.T) @ Z


@claim("s87h1-neumann2-rank", kind="dim", section="7", sizes=ANY)
def neumann2_rank(s):
    """At Ψ = 0: rank Λ1(Θ) = 2r(n − r) (TRUE)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(lambda1_matrix(s, _p_on_psi_zero(s)), 2 * r * (n - r))}


@claim("s87h1-neumann2-rank-twin", kind="dim", section="7", sizes=ANY)
def neumann2_rank_twin(s):
    """FALSE twin (r ≥ 3): at Ψ = 0 the rank is still 2l."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(lambda1_matrix(s, _p_on_psi_zero(s)), two_l(n, r))}


def H_neumann(t):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_NE(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


@claim("s87h1-velocity-psi", kind="id", section="7", sizes=ANY)
def velocity_psi(s):
    """Along (No): XᵀẊ = (1 + κ)Ψ (TRUE)."""
    f = s.dirac_flow(H_neumann)
    return {"XtXdot": s.X.T @ f.Xdot - (1 + s.kappa) * s.Psi}


@claim("s87h1-velocity-psi-twin", kind="id", section="7", sizes=ANY)
def velocity_psi_twin(s):
    """FALSE twin: XᵀẊ = (1 + 2κ)Ψ."""
    f = s.dirac_flow(H_neumann)
    return {"XtXdot": s.X.T @ f.Xdot - (1 + 2 * s.kappa) * s.Psi}


@claim("s87h1-ne-multiplier", kind="id", section="7", sizes=ANY)
def ne_multiplier(s):
    """(NE_XP): Λ = XᵀAX − ẊᵀẊ, Π = 0 (TRUE)."""
    f = s.multiplier_flow(H_NE)
    Xd = f["X"]
    return {"Lambda": f["Lambda"] - (s.X.T @ s.A @ s.X - Xd.T @ Xd), "Pi": f["Pi"]}


@claim("s87h1-ne-multiplier-twin", kind="id", section="7", sizes=ANY)
def ne_multiplier_twin(s):
    """FALSE twin: Λ = XᵀAX − ẊᵀẊ for the Neumann flow of every κ."""
    f = s.multiplier_flow(H_neumann)
    Xd = f["X"]
    return {"Lambda": f["Lambda"] - (s.X.T @ s.A @ s.X - Xd.T @ Xd)}
