"""s88h1: hidden statements of §2 and §5 of Fedorov–Jovanović, each TRUE statement with a FALSE twin.

Notation: K = XᵀP (skew on T*V), Ψ = XᵀP − PᵀX = 2K, Φ = PXᵀ − XPᵀ, V = ½tr XᵀAX, ⟨a,b⟩ = −½tr(ab),
{f, H} = df(X_H) with X_H the Dirac flow (dot_XP): Ẋ = H_P − XΠ, Ṗ = −H_X + XΛ + PΠ.
Truth: by hand (below) and by numpy (truth_numpy.py, no stiefelsym import).

§2
 s88h1-base-commute (TRUE): {tr UᵀX, tr WᵀX} = 0 (functions on the base commute for the Dirac bracket).
 s88h1-base-commute-twin (FALSE, except (1,1) where P = 0): {tr UᵀP, tr WᵀP} = 0.
 s88h1-xp-bracket (TRUE): {tr UᵀX, tr WᵀP} = tr(UᵀW) − ½tr(UᵀX(XᵀW + WᵀX)).  The flow of tr WᵀP has
   Ẋ = W − XΠ, Π = sym(XᵀW).
 s88h1-xp-bracket-twin (FALSE): the same with factor 1 in place of ½.
 s88h1-phi-x-bracket (TRUE): {Φ_ξ, tr UᵀX} = −tr(UᵀξX)  (the flow of Φ_ξ is (ξX, ξP)).
 s88h1-phi-x-bracket-twin (FALSE, n ≥ 2): = +tr(UᵀξX).
 s88h1-psi-gram-bracket (TRUE): {Ψ_η, tr(B PᵀP)} = tr(B[η, PᵀP])  (the flow of Ψ_η is (Xη, Pη)).
 s88h1-psi-gram-bracket-twin (FALSE for r ≥ 2; true at r = 1, so(1) = 0): = tr(B[PᵀP, η]).
 s88h1-left-orbit-rank (TRUE): ξ ↦ (ξX, ξP) on so(n) has generic rank dim so(n) − dim so(n − min(n, 2r)),
   which is 2 dim V − ddim (the SO(n)-orbits in T*V; isotropy so(span(X,P)^⊥)).
 s88h1-left-orbit-rank-twin (FALSE where n − r ≥ 2 and n−r ≠ n−2r... e.g. (3,1),(4,1),(4,2),(5,x)): rank dim so(n) − dim so(n − r).
 s88h1-casimir-invariants (TRUE): ⟨Φ,Φ⟩ = tr PᵀP + ½⟨Ψ,Ψ⟩ (the Casimir in the functions (SO(n)-inv)).
 s88h1-casimir-invariants-twin (FALSE for r ≥ 2; true at r = 1, Ψ = 0): ⟨Φ,Φ⟩ = tr PᵀP − ½⟨Ψ,Ψ⟩.
 s88h1-phi-psi-restrict (TRUE): XᵀΦX = Ψ.
 s88h1-phi-psi-restrict-twin (FALSE for r ≥ 2): XᵀΦX = −Ψ.
 s88h1-constraint-matrix-rank (TRUE): the r(r+1) × r(r+1) matrix {F_i, F_j}_0 has generic rank r(r+1).
 s88h1-constraint-matrix-rank-twin (FALSE): generic rank r(r+1) − 1.

§5
 s88h1-kappa-difference (TRUE): X_{H_neum,κ} − X_{H_neum,0} = κ(XΨ, PΨ)  (Dirac flows).
 s88h1-kappa-difference-twin (FALSE for r ≥ 2): = 2κ(XΨ, PΨ).
 s88h1-potential-rate (TRUE): along the printed (No) (as a tangent vector), dV/dt = tr(XᵀAP) for every κ.
 s88h1-potential-rate-twin (FALSE): dV/dt = 2tr(XᵀAP).
 s88h1-xt-pdot (TRUE): along the Dirac flow of H_neum,κ, XᵀṖ = −PᵀP + (1+2κ)(XᵀP)².
 s88h1-xt-pdot-twin (FALSE for r ≥ 2): = −PᵀP + (1+κ)(XᵀP)².
 s88h1-cubic-integral (TRUE): I₃ = tr(Φ²XXᵀ) − tr(AXXᵀ) (λ² coefficient of tr 𝓛³/3) is conserved by the Dirac
   flow of H_neum,κ.
 s88h1-cubic-integral-twin (FALSE for r < n; true at r = n, where Φ̇ = 0 and XXᵀ = I): tr(Φ²XXᵀ) + tr(AXXᵀ).
 s88h1-quartic-spectral (TRUE): tr 𝓛(λ)⁴ conserved (k = 4 of (perelomov)).
 s88h1-quartic-spectral-twin (FALSE for r < n, n ≥ 2): tr(λΦ + XXᵀ + λ²A)² conserved.
 s88h1-potential-constant (TRUE, r = n): tr XᵀAX = tr A ("the potential is constant for r = n").
 s88h1-potential-constant-twin (FALSE, r = n − 1): the same.
 s88h1-energy-printed (TRUE): H_neum,κ is constant along the printed (No) (tangent vector).
 s88h1-energy-printed-twin (FALSE): the kinetic part ½tr PᵀP − (½+κ)tr(XᵀP)² alone is constant along (No).
 s88h1-phi-projector (TRUE): [Φ, XXᵀ] = PXᵀ + XPᵀ on T*V  (so d(XXᵀ)/dt = [Φ, XXᵀ] for (NE_XP)).
 s88h1-phi-projector-twin (FALSE for r < n; true at r = n, both sides 0): [XXᵀ, Φ] = PXᵀ + XPᵀ.
"""
from __future__ import annotations

from stiefelsym import Rank, admissible, block, claim, comm
from stiefelsym.bases import matrix_of, so_basis

ANY = admissible(n_max=4)


def dso(m):
    return m * (m - 1) // 2 if m > 1 else 0


# ---------------------------------------------------------------- §2
@claim("s88h1-base-commute", kind="pb", section="2", sizes=ANY)
def base_commute(s):
    """{tr UᵀX, tr WᵀX} = 0 (TRUE)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {"b": s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.X))}


@claim("s88h1-base-commute-twin", kind="pb", section="2", sizes=ANY)
def base_commute_twin(s):
    """{tr UᵀP, tr WᵀP} = 0 (FALSE)."""
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    return {"b": s.bracket(lambda t: t.tr(U.T @ t.P), lambda t: t.tr(W.T @ t.P))}


def xp_bracket(s, c):
    U, W = s.fresh("n", "r"), s.fresh("n", "r")
    X = s.X
    return {"b": s.bracket(lambda t: t.tr(U.T @ t.X), lambda t: t.tr(W.T @ t.P))
            - (s.tr(U.T @ W) - c * s.tr(U.T @ X @ (X.T @ W + W.T @ X)))}


@claim("s88h1-xp-bracket", kind="pb", section="2", sizes=ANY)
def xp_true(s):
    """{tr UᵀX, tr WᵀP} = tr UᵀW − ½tr(UᵀX(XᵀW + WᵀX)) (TRUE)."""
    return xp_bracket(s, s.q(1, 2))


@claim("s88h1-xp-bracket-twin", kind="pb", section="2", sizes=ANY)
def xp_twin(s):
    """factor 1 (FALSE)."""
    return xp_bracket(s, s.q(1))


def phi_x(s, sign):
    U = s.generic("U", "n", "r")
    return {"b": s.bracket(lambda t: t.killing(t.Phi, s.xi), lambda t: t.tr(U.T @ t.X))
            + sign * s.tr(U.T @ s.xi @ s.X)}


@claim("s88h1-phi-x-bracket", kind="pb", section="2", sizes=ANY)
def phi_x_true(s):
    """{Φ_ξ, tr UᵀX} = −tr(UᵀξX) (TRUE)."""
    return phi_x(s, 1)


@claim("s88h1-phi-x-bracket-twin", kind="pb", section="2", sizes=ANY)
def phi_x_twin(s):
    """= +tr(UᵀξX) (FALSE)."""
    return phi_x(s, -1)


def psi_gram(s, flip):
    B = s.generic("B", "r", "r")
    G = s.P.T @ s.P
    rhs = comm(G, s.eta) if flip else comm(s.eta, G)
    return {"b": s.bracket(lambda t: t.killing(t.Psi, s.eta), lambda t: t.tr(B @ t.P.T @ t.P)) - s.tr(B @ rhs)}


@claim("s88h1-psi-gram-bracket", kind="pb", section="2", sizes=ANY)
def psi_gram_true(s):
    """{Ψ_η, tr(B PᵀP)} = tr(B[η, PᵀP]) (TRUE)."""
    return psi_gram(s, False)


@claim("s88h1-psi-gram-bracket-twin", kind="pb", section="2", sizes=ANY)
def psi_gram_twin(s):
    """= tr(B[PᵀP, η]) (FALSE for r ≥ 2)."""
    return psi_gram(s, True)


def left_matrix(s):
    return matrix_of(s, lambda xi: block([[xi @ s.X, xi @ s.P]]), so_basis(s, "n"))


@claim("s88h1-left-orbit-rank", kind="dim", section="2", sizes=ANY)
def left_orbit_rank(s):
    """rank = dim so(n) − dim so(n − min(n, 2r)) (TRUE)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(left_matrix(s), dso(n) - dso(n - min(n, 2 * r)))}


@claim("s88h1-left-orbit-rank-twin", kind="dim", section="2", sizes=ANY)
def left_orbit_rank_twin(s):
    """rank = dim so(n) − dim so(n − r) (FALSE where they differ)."""
    n, r = int(s.n), int(s.r)
    return {"rank": Rank(left_matrix(s), dso(n) - dso(n - r))}


@claim("s88h1-casimir-invariants", kind="id", section="2", sizes=ANY)
def casimir_true(s):
    """⟨Φ,Φ⟩ = tr PᵀP + ½⟨Ψ,Ψ⟩ (TRUE)."""
    return {"c": s.killing(s.Phi, s.Phi) - s.tr(s.P.T @ s.P) - s.killing(s.Psi, s.Psi) / 2}


@claim("s88h1-casimir-invariants-twin", kind="id", section="2", sizes=ANY)
def casimir_twin(s):
    """⟨Φ,Φ⟩ = tr PᵀP − ½⟨Ψ,Ψ⟩ (FALSE for r ≥ 2)."""
    return {"c": s.killing(s.Phi, s.Phi) - s.tr(s.P.T @ s.P) + s.killing(s.Psi, s.Psi) / 2}


@claim("s88h1-phi-psi-restrict", kind="id", section="2", sizes=ANY)
def phi_psi_true(s):
    """XᵀΦX = Ψ (TRUE)."""
    return {"r": s.X.T @ s.Phi @ s.X - s.Psi}


@claim("s88h1-phi-psi-restrict-twin", kind="id", section="2", sizes=ANY)
def phi_psi_twin(s):
    """XᵀΦX = −Ψ (FALSE for r ≥ 2)."""
    return {"r": s.X.T @ s.Phi @ s.X + s.Psi}


@claim("s88h1-constraint-matrix-rank", kind="dim", section="2", sizes=ANY)
def cmat_true(s):
    """{F_i, F_j}_0 has generic rank r(r+1) (TRUE)."""
    r = int(s.r)
    return {"rank": Rank(s.mat(s.constraint_bracket_matrix()), r * (r + 1))}


@claim("s88h1-constraint-matrix-rank-twin", kind="dim", section="2", sizes=ANY)
def cmat_twin(s):
    """generic rank r(r+1) − 1 (FALSE)."""
    r = int(s.r)
    return {"rank": Rank(s.mat(s.constraint_bracket_matrix()), r * (r + 1) - 1)}


# ---------------------------------------------------------------- §5
def H_neum(t, kappa):
    K = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa) * t.tr(K @ K) + t.tr(t.X.T @ t.A @ t.X) / 2


def printed_No(s):
    X, P, A = s.X, s.P, s.A
    c = 1 + 2 * s.kappa
    return {"X": P - c * (X @ P.T @ X), "P": -(A @ X) - X @ P.T @ P + c * (P @ X.T @ P) + X @ X.T @ A @ X}


def kappa_diff(s, c):
    k = s.kappa
    f1 = s.dirac_flow(lambda t: H_neum(t, k))
    f0 = s.dirac_flow(lambda t: H_neum(t, t.q(0)))
    return {"X": f1.Xdot - f0.Xdot - c * k * (s.X @ s.Psi), "P": f1.Pdot - f0.Pdot - c * k * (s.P @ s.Psi)}


@claim("s88h1-kappa-difference", kind="id", section="5", sizes=ANY)
def kappa_diff_true(s):
    """X_{H_κ} − X_{H_0} = κ(XΨ, PΨ) (TRUE)."""
    return kappa_diff(s, 1)


@claim("s88h1-kappa-difference-twin", kind="id", section="5", sizes=ANY)
def kappa_diff_twin(s):
    """= 2κ(XΨ, PΨ) (FALSE for r ≥ 2)."""
    return kappa_diff(s, 2)


@claim("s88h1-potential-rate", kind="id", section="5", sizes=ANY)
def pot_rate(s):
    """dV/dt = tr(XᵀAP) along printed (No) (TRUE)."""
    return {"dV": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X) / 2, printed_No(s)) - s.tr(s.X.T @ s.A @ s.P)}


@claim("s88h1-potential-rate-twin", kind="id", section="5", sizes=ANY)
def pot_rate_twin(s):
    """dV/dt = 2tr(XᵀAP) (FALSE)."""
    return {"dV": s.d(lambda t: t.tr(t.X.T @ t.A @ t.X) / 2, printed_No(s)) - 2 * s.tr(s.X.T @ s.A @ s.P)}


def xt_pdot(s, c):
    f = s.dirac_flow(lambda t: H_neum(t, t.kappa))
    K = s.X.T @ s.P
    return {"XtPdot": s.X.T @ f.Pdot - (-(s.P.T @ s.P) + c * (K @ K))}


@claim("s88h1-xt-pdot", kind="id", section="5", sizes=ANY)
def xt_pdot_true(s):
    """XᵀṖ = −PᵀP + (1+2κ)K² (TRUE)."""
    return xt_pdot(s, 1 + 2 * s.kappa)


@claim("s88h1-xt-pdot-twin", kind="id", section="5", sizes=ANY)
def xt_pdot_twin(s):
    """XᵀṖ = −PᵀP + (1+κ)K² (FALSE for r ≥ 2)."""
    return xt_pdot(s, 1 + s.kappa)


def cubic(t, sign):
    V = t.X @ t.X.T
    return t.tr(t.Phi @ t.Phi @ V) + sign * t.tr(t.A @ V)


@claim("s88h1-cubic-integral", kind="pb", section="5", sizes=ANY)
def cubic_true(s):
    """I₃ = tr(Φ²XXᵀ) − tr(AXXᵀ) conserved (TRUE)."""
    return {"dI": s.d(lambda t: cubic(t, -1), s.dirac_flow(lambda t: H_neum(t, t.kappa)))}


@claim("s88h1-cubic-integral-twin", kind="pb", section="5", sizes=ANY)
def cubic_twin(s):
    """tr(Φ²XXᵀ) + tr(AXXᵀ) conserved (FALSE for r < n)."""
    return {"dI": s.d(lambda t: cubic(t, 1), s.dirac_flow(lambda t: H_neum(t, t.kappa)))}


def power_tr(t, M, k):
    acc = M
    for _ in range(k - 1):
        acc = acc @ M
    return t.tr(acc)


@claim("s88h1-quartic-spectral", kind="pb", section="5", sizes=ANY)
def quartic_true(s):
    """tr 𝓛(λ)⁴ conserved (TRUE)."""
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T - t.lam * t.lam * t.A  # noqa: E731
    return {"d": s.d(lambda t: power_tr(t, L(t), 4), s.dirac_flow(lambda t: H_neum(t, t.kappa)))}


@claim("s88h1-quartic-spectral-twin", kind="pb", section="5", sizes=ANY)
def quartic_twin(s):
    """tr(λΦ + XXᵀ + λ²A)² conserved (FALSE for r < n)."""
    L = lambda t: t.lam * t.Phi + t.X @ t.X.T + t.lam * t.lam * t.A  # noqa: E731
    return {"d": s.d(lambda t: power_tr(t, L(t), 2), s.dirac_flow(lambda t: H_neum(t, t.kappa)))}


@claim("s88h1-potential-constant", kind="id", section="5", sizes=admissible(n_max=4, r_is_n=True))
def pot_const(s):
    """tr XᵀAX = tr A at r = n (TRUE)."""
    return {"V": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A)}


@claim("s88h1-potential-constant-twin", kind="id", section="5",
       sizes=[(2, 1), (3, 2), (4, 3)])
def pot_const_twin(s):
    """tr XᵀAX = tr A at r = n − 1 (FALSE)."""
    return {"V": s.tr(s.X.T @ s.A @ s.X) - s.tr(s.A)}


@claim("s88h1-energy-printed", kind="pb", section="5", sizes=ANY)
def energy_true(s):
    """H_neum,κ constant along printed (No) (TRUE)."""
    return {"dH": s.d(lambda t: H_neum(t, t.kappa), printed_No(s))}


@claim("s88h1-energy-printed-twin", kind="pb", section="5", sizes=ANY)
def energy_twin(s):
    """kinetic part alone constant along (No) (FALSE)."""
    def T(t):
        K = t.X.T @ t.P
        return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + t.kappa) * t.tr(K @ K)
    return {"dT": s.d(T, printed_No(s))}


@claim("s88h1-phi-projector", kind="id", section="5", sizes=ANY)
def phi_proj(s):
    """[Φ, XXᵀ] = PXᵀ + XPᵀ (TRUE)."""
    return {"c": comm(s.Phi, s.X @ s.X.T) - (s.P @ s.X.T + s.X @ s.P.T)}


@claim("s88h1-phi-projector-twin", kind="id", section="5", sizes=ANY)
def phi_proj_twin(s):
    """[XXᵀ, Φ] = PXᵀ + XPᵀ (FALSE for r < n)."""
    return {"c": comm(s.X @ s.X.T, s.Phi) - (s.P @ s.X.T + s.X @ s.P.T)}
