"""s86h2: hidden statements of §3, Appendix 1 (§9) and Appendix 2 (§10), each TRUE statement with a FALSE twin.

Truth derived by hand (below) and by numpy (truth_numpy.py, truth_numpy_output.txt, no stiefelsym import).
K = XᵀP (skew on T*V), Φ = PXᵀ − XPᵀ, Ψ = XᵀP − PᵀX = 2K, c = 1 + 2κ.

§3
 s86h2-jensen-pdot (TRUE): along the Dirac flow of H_κ = ½⟨Φ,Φ⟩ + κ/2⟨Ψ,Ψ⟩, Ṗ = ΦP + κPΨ.
   Ṗ = cPXᵀP − XPᵀP (the κ-flow), ΦP = PXᵀP − XPᵀP, PΨ = 2PXᵀP.
 s86h2-jensen-pdot-twin (FALSE, r ≥ 2): Ṗ = ΦP − κPΨ (sign).
 s86h2-jensen-accel (TRUE): along the same flow Ẍ = Φ²X + 2κΦXΨ + κ²XΨ² (X(t) = e^{tΦ}X₀e^{tκΨ}: Ẋ = ΦX + κXΨ,
   Φ, Ψ conserved).
 s86h2-jensen-accel-twin (FALSE, r ≥ 2): cross term κΦXΨ (factor 2 dropped).
 s86h2-jensen-ptp (TRUE): d(PᵀP)/dt = 2κ[PᵀP, XᵀP] along the H_κ flow (κ = 0: PᵀP conserved).
 s86h2-jensen-ptp-twin (FALSE, r ≥ 2): 2κ[XᵀP, PᵀP] (commutator order).
 s86h2-metric-lambda-equivariant (TRUE, metric realization (cond_XP2)): ds²_A is right SO(r)-invariant; the
   multiplier Λ = XᵀṖ of (A_XP) moves along the right action (Xη, Pη) by dΛ = Λη − ηΛ (Λ(XR,PR) = RᵀΛR).
 s86h2-metric-lambda-equivariant-twin (FALSE, r ≥ 2): dΛ = ηΛ − Λη.

Appendix 1
 s86h2-rigid-body-velocities (TRUE, r = n): along the flow of H_CP = ½⟨M,M⟩ + ½(tr A − (e_n, Ae_n)), M = Φ, the
   space angular velocity Ẋ𝒳⁻¹ = ẊXᵀ equals M = Φ and the body one XᵀẊ equals m = XᵀMX = Ψ.
 s86h2-rigid-body-velocities-twin (FALSE, n ≥ 2): ẊᵀX = Ψ (transpose; ẊᵀX = −Ψ).
 s86h2-hcp-right-invariant (TRUE, r = n): H_CP is invariant under rotations of span(e₁..e_{n−1}): dH_CP = 0 along
   (Xη̃, Pη̃), η̃ = DηD, D = E_{<n}E_{<n}ᵀ the projector onto the first n − 1 coordinates.
 s86h2-hcp-right-invariant-twin (FALSE, n ≥ 2): the same for every η ∈ so(n) (the full right SO(n)).
 s86h2-magnetic-nor-minus-euk (TRUE, r = 2): for ω_ε, (mag-nor) − (mag-euk) = ½Ψ₁₂(XJ, PJ), J = E₁E₂ᵀ − E₂E₁ᵀ,
   Ψ₁₂ = (e₁,p₂) − (e₂,p₁): the two magnetic flows differ by the right SO(2) generator (H₀ = H_E + ¼⟨Ψ,Ψ⟩ and
   ¼⟨Ψ,Ψ⟩ = ½Ψ₁₂²).  By hand from the printed ė₁: −(e₁,p₂)e₂ = −½Ψ₁₂e₂ = ½Ψ₁₂ (XJ)₁.
 s86h2-magnetic-nor-minus-euk-twin (FALSE): −½Ψ₁₂(XJ, PJ).

Appendix 2
 s86h2-double-swap (TRUE): (X, Y, Ẋ, Ẏ) ↦ (Y, X, Ẏ, Ẋ) is a symmetry of (D-Lag), (D0): the Euler–Lagrange
   accelerations at the swapped point are the swapped accelerations, and Λ of (D-L) goes to Λᵀ.
 s86h2-double-swap-twin (FALSE, r ≥ 2 generic): Λ goes to Λ.
 s86h2-double-diagonal-momenta (TRUE): the diagonal (ℝ*)ⁿ-symmetry (X, Y) ↦ (DX, D⁻¹Y) (D diagonal, commuting with A)
   gives conserved tr(E(XẎᵀ − YẊᵀ)), E = (I − S)/2, S an orthogonal symmetry commuting with A (the real analogue of
   the u(1)ⁿ momenta of W(n,r)).
 s86h2-double-diagonal-momenta-twin (FALSE): tr(E(XẎᵀ + YẊᵀ)).
 s86h2-big-lax-so-n-n (TRUE): L(ν) and A(ν) = L₊(ν) of (so(n,n)) are in so(n,n): MᵀJ + JM = 0, J = diag(Iₙ, −Iₙ)
   (checked on ν·L(ν), ν·A(ν)).
 s86h2-big-lax-so-n-n-twin (FALSE): L(ν) ∈ so(2n), νL + νLᵀ = 0.
 s86h2-coupled-torque (TRUE): along the flow of (C-neumann), any κ, d(XᵀP − PᵀX)/dt = YᵀAX − XᵀAY (so only the
   sum with YᵀQ − QᵀY is conserved).
 s86h2-coupled-torque-twin (FALSE): XᵀAY − YᵀAX.
 s86h2-perturbed-euclid-dual-lax (TRUE): at κ = −½ the perturbed H_κ (Euclidean metric + tr(XᵀP YᵀQ)) implies
   (LA3*C) with the diagonal blocks of 𝓐(λ) equal to −YᵀQ (rows 1, 2) and −XᵀP (rows 3, 4) (the paper's
   (1 + 2κ)XᵀP + 2κYᵀQ at κ = −½).
 s86h2-perturbed-euclid-dual-lax-twin (FALSE, r ≥ 1): diagonal blocks XᵀP, YᵀQ as for κ = 0.
"""
from __future__ import annotations

from stiefelsym import admissible, block, claim, comm, twisted
from stiefelsym.systems import coupled_point, derivative, double_point, euler_lagrange, real_coordinates, \
    stiefel_pairs_flow

ANY = admissible(n_max=5)
ON_SO_N = admissible(n_max=5, n_min=2, r_is_n=True, condition="r = n")
ON_V_N2 = admissible(n_max=5, n_min=2, r_min=2, r_max=2, condition="r = 2")


# ---------------------------------------------------------------- §3
def H_jensen(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


@claim("s86h2-jensen-pdot", kind="id", section="3", sizes=ANY)
def jensen_pdot(s):
    """Ṗ = ΦP + κPΨ along the Dirac flow of H_κ (TRUE)."""
    f = s.dirac_flow(H_jensen)
    return {"Pdot": f.Pdot - (s.Phi @ s.P + s.kappa * s.P @ s.Psi)}


@claim("s86h2-jensen-pdot-twin", kind="id", section="3", sizes=ANY)
def jensen_pdot_twin(s):
    """FALSE twin: Ṗ = ΦP − κPΨ."""
    f = s.dirac_flow(H_jensen)
    return {"Pdot": f.Pdot - (s.Phi @ s.P - s.kappa * s.P @ s.Psi)}


def _jensen_velocity(t):
    return t.dirac_flow(H_jensen).Xdot


@claim("s86h2-jensen-accel", kind="id", section="3", sizes=ANY)
def jensen_accel(s):
    """Ẍ = Φ²X + 2κΦXΨ + κ²XΨ² along the H_κ flow (TRUE)."""
    f = s.dirac_flow(H_jensen)
    Phi, Psi, X, k = s.Phi, s.Psi, s.X, s.kappa
    return {"Xddot": s.d(_jensen_velocity, f) - (Phi @ Phi @ X + 2 * k * Phi @ X @ Psi + k * k * X @ Psi @ Psi)}


@claim("s86h2-jensen-accel-twin", kind="id", section="3", sizes=ANY)
def jensen_accel_twin(s):
    """FALSE twin: Ẍ = Φ²X + κΦXΨ + κ²XΨ²."""
    f = s.dirac_flow(H_jensen)
    Phi, Psi, X, k = s.Phi, s.Psi, s.X, s.kappa
    return {"Xddot": s.d(_jensen_velocity, f) - (Phi @ Phi @ X + k * Phi @ X @ Psi + k * k * X @ Psi @ Psi)}


@claim("s86h2-jensen-ptp", kind="id", section="3", sizes=ANY)
def jensen_ptp(s):
    """d(PᵀP)/dt = 2κ[PᵀP, XᵀP] along the H_κ flow (TRUE)."""
    f = s.dirac_flow(H_jensen)
    G, K = s.P.T @ s.P, s.X.T @ s.P
    return {"d(PtP)/dt": s.d(lambda t: t.P.T @ t.P, f) - 2 * s.kappa * comm(G, K)}


@claim("s86h2-jensen-ptp-twin", kind="id", section="3", sizes=ANY)
def jensen_ptp_twin(s):
    """FALSE twin: d(PᵀP)/dt = 2κ[XᵀP, PᵀP]."""
    f = s.dirac_flow(H_jensen)
    G, K = s.P.T @ s.P, s.X.T @ s.P
    return {"d(PtP)/dt": s.d(lambda t: t.P.T @ t.P, f) - 2 * s.kappa * comm(K, G)}


def H_metric_A(t):
    return t.tr(t.P.T @ t.Ainv @ t.P) / 2


def _metric_lambda(t):
    return t.X.T @ t.dirac_flow(H_metric_A).Pdot


@claim("s86h2-metric-lambda-equivariant", kind="id", section="3", sizes=ANY, realization="metric")
def metric_lambda_equivariant(s):
    """(A_XP): along the right action (Xη, Pη), dΛ = Λη − ηΛ, Λ = XᵀṖ (TRUE)."""
    Lam = _metric_lambda(s)
    return {"dLambda": s.d(_metric_lambda, {"X": s.X @ s.eta, "P": s.P @ s.eta}) - (Lam @ s.eta - s.eta @ Lam)}


@claim("s86h2-metric-lambda-equivariant-twin", kind="id", section="3", sizes=ANY, realization="metric")
def metric_lambda_equivariant_twin(s):
    """FALSE twin: dΛ = ηΛ − Λη."""
    Lam = _metric_lambda(s)
    return {"dLambda": s.d(_metric_lambda, {"X": s.X @ s.eta, "P": s.P @ s.eta}) - (s.eta @ Lam - Lam @ s.eta)}


# ---------------------------------------------------------------- Appendix 1
def H_CP(t):
    en = t.X @ twisted.last_basis_vector(t)
    return t.killing(t.Phi, t.Phi) / 2 + (t.tr(t.A) - t.tr(en.T @ t.A @ en)) / 2


@claim("s86h2-rigid-body-velocities", kind="id", section="A1", sizes=ON_SO_N)
def rigid_body_velocities(s):
    """r = n, flow of H_CP: ẊXᵀ = Φ, XᵀẊ = Ψ (TRUE)."""
    f = s.dirac_flow(H_CP)
    return {"space": f.Xdot @ s.X.T - s.Phi, "body": s.X.T @ f.Xdot - s.Psi}


@claim("s86h2-rigid-body-velocities-twin", kind="id", section="A1", sizes=ON_SO_N)
def rigid_body_velocities_twin(s):
    """FALSE twin: ẊᵀX = Ψ (transpose)."""
    f = s.dirac_flow(H_CP)
    return {"body": f.Xdot.T @ s.X - s.Psi}


@claim("s86h2-hcp-right-invariant", kind="id", section="A1", sizes=ON_SO_N)
def hcp_right_invariant(s):
    """r = n: dH_CP = 0 along (Xη̃, Pη̃), η̃ = DηD, D = E_{<n}E_{<n}ᵀ (TRUE)."""
    L = twisted.leading_basis_vectors(s)
    D = L @ L.T
    e = D @ s.eta @ D
    return {"dH_CP": s.d(H_CP, {"X": s.X @ e, "P": s.P @ e})}


@claim("s86h2-hcp-right-invariant-twin", kind="id", section="A1", sizes=ON_SO_N)
def hcp_right_invariant_twin(s):
    """FALSE twin: dH_CP = 0 along (Xη, Pη) for every η ∈ so(n)."""
    return {"dH_CP": s.d(H_CP, {"X": s.X @ s.eta, "P": s.P @ s.eta})}


def H_nor(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def H_euk(t):
    return t.tr(t.P.T @ t.P) / 2 + t.tr(t.X.T @ t.A @ t.X) / 2


def _nor_minus_euk(s, sign):
    J = twisted.magnetic_matrix(s)
    E1, E2 = twisted.basis_vector(s, 0), twisted.basis_vector(s, 1)
    psi12 = s.tr(E1.T @ s.Psi @ E2)
    fn, fe = twisted.flow(s, H_nor), twisted.flow(s, H_euk)
    c = sign * psi12 / 2
    return {"X": fn.Xdot - fe.Xdot - c * (s.X @ J), "P": fn.Pdot - fe.Pdot - c * (s.P @ J)}


@claim("s86h2-magnetic-nor-minus-euk", kind="id", section="A1", sizes=ON_V_N2)
def magnetic_nor_minus_euk(s):
    """r = 2, twisted form: (mag-nor) − (mag-euk) = ½Ψ₁₂(XJ, PJ) (TRUE)."""
    return _nor_minus_euk(s, 1)


@claim("s86h2-magnetic-nor-minus-euk-twin", kind="id", section="A1", sizes=ON_V_N2)
def magnetic_nor_minus_euk_twin(s):
    """FALSE twin: −½Ψ₁₂(XJ, PJ)."""
    return _nor_minus_euk(s, -1)


# ---------------------------------------------------------------- Appendix 2
def T_double(t, v):
    return t.tr(v["X"].T @ v["Y"])


def U_double(t, q):
    return t.tr(q["X"].T @ t.A @ q["Y"])


def D0(t, q):
    return [q["X"].T @ q["Y"] - t.Ir]


def _acc(s, z):
    acc, _ = euler_lagrange(s, T_double, U_double, D0, {"X": z["X"], "Y": z["Y"]},
                            {"X": z["Xdot"], "Y": z["Ydot"]}, real_coordinates(s, ["X", "Y"]))
    return acc


def _lam(s, z):
    return z["X"].T @ s.A @ z["Y"] - z["Xdot"].T @ z["Ydot"]


def _swap(z):
    return {"X": z["Y"], "Y": z["X"], "Xdot": z["Ydot"], "Ydot": z["Xdot"]}


@claim("s86h2-double-swap", kind="id", section="A2", sizes=ANY)
def double_swap(s):
    """(D-Lag), (D0) are swap-symmetric: accelerations at the swapped point are swapped; Λ ↦ Λᵀ (TRUE)."""
    z = double_point(s)
    a, b = _acc(s, z), _acc(s, _swap(z))
    return {"X'' swapped": b["X"] - a["Y"], "Y'' swapped": b["Y"] - a["X"],
            "Lambda swapped": _lam(s, _swap(z)) - _lam(s, z).T}


@claim("s86h2-double-swap-twin", kind="id", section="A2", sizes=ANY)
def double_swap_twin(s):
    """FALSE twin: Λ(swapped point) = Λ."""
    z = double_point(s)
    return {"Lambda swapped": _lam(s, _swap(z)) - _lam(s, z)}


def _double_tangent(s, z):
    a = _acc(s, z)
    return {"X": z["Xdot"], "Y": z["Ydot"], "Xdot": a["X"], "Ydot": a["Y"]}


def _diag_momentum(sign):
    def mu(t, w):
        E = (t.In - twisted.reflection(t)) * t.q(1, 2)
        return t.tr(E @ (w["X"] @ w["Ydot"].T + sign * w["Y"] @ w["Xdot"].T))
    return mu


@claim("s86h2-double-diagonal-momenta", kind="pb", section="A2", sizes=ANY)
def double_diagonal_momenta(s):
    """d/dt tr(E(XẎᵀ − YẊᵀ)) = 0 along (D-eq), E = (I − S)/2, SA = AS (TRUE)."""
    z = double_point(s)
    return {"d mu/dt": derivative(s, _diag_momentum(-1), z, _double_tangent(s, z))}


@claim("s86h2-double-diagonal-momenta-twin", kind="pb", section="A2", sizes=ANY)
def double_diagonal_momenta_twin(s):
    """FALSE twin: d/dt tr(E(XẎᵀ + YẊᵀ)) = 0."""
    z = double_point(s)
    return {"d mu/dt": derivative(s, _diag_momentum(1), z, _double_tangent(s, z))}


def _big_L_times_nu(s, plus):
    nu = s.scalar("nu")
    O = s.zeros(s.n, s.n, ("n", "n"))
    X, P, Y, Q, A = s.X, s.P, s.Y, s.Q, s.A
    M = nu * nu * block([[O, A], [A, O]]) + nu * block([[P @ X.T - X @ P.T, O], [O, Q @ Y.T - Y @ Q.T]])
    if not plus:
        M = M + block([[O, X @ Y.T], [Y @ X.T, O]])
    return M


def _J(s):
    O = s.zeros(s.n, s.n, ("n", "n"))
    return block([[s.In, O], [O, -s.In]])


@claim("s86h2-big-lax-so-n-n", kind="id", section="A2", sizes=ANY)
def big_lax_so_n_n(s):
    """ν·L(ν), ν·A(ν) of (so(n,n)) satisfy MᵀJ + JM = 0, J = diag(Iₙ, −Iₙ) (TRUE)."""
    J = _J(s)
    L, Ap = _big_L_times_nu(s, False), _big_L_times_nu(s, True)
    return {"L": L.T @ J + J @ L, "A": Ap.T @ J + J @ Ap}


@claim("s86h2-big-lax-so-n-n-twin", kind="id", section="A2", sizes=ANY)
def big_lax_so_n_n_twin(s):
    """FALSE twin: ν·L(ν) is skew (L ∈ so(2n))."""
    L = _big_L_times_nu(s, False)
    return {"L": L.T + L}


def H_coupled(t, z):
    XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    c = t.q(1, 2) + t.kappa
    return (t.q(1, 2) * t.tr(z["P"].T @ z["P"]) - c * t.tr(XP @ XP)
            + t.q(1, 2) * t.tr(z["Q"].T @ z["Q"]) - c * t.tr(YQ @ YQ) + t.tr(z["X"].T @ t.A @ z["Y"]))


def _torque(s, sign):
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_coupled, z, [("X", "P"), ("Y", "Q")])
    rate = derivative(s, lambda t, w: w["X"].T @ w["P"] - w["P"].T @ w["X"], z, fl)
    X, Y, A = s.X, s.Y, s.A
    return {"d Psi_X/dt": rate - sign * (Y.T @ A @ X - X.T @ A @ Y)}


@claim("s86h2-coupled-torque", kind="id", section="A2", sizes=ANY)
def coupled_torque(s):
    """d(XᵀP − PᵀX)/dt = YᵀAX − XᵀAY along the flow of (C-neumann) (TRUE)."""
    return _torque(s, 1)


@claim("s86h2-coupled-torque-twin", kind="id", section="A2", sizes=ANY)
def coupled_torque_twin(s):
    """FALSE twin: XᵀAY − YᵀAX."""
    return _torque(s, -1)


def H_perturbed_euclid(t, z):
    """H_κ at κ = −½: ½tr PᵀP + ½tr QᵀQ + tr(XᵀAY) + tr(XᵀP YᵀQ)."""
    return (t.q(1, 2) * t.tr(z["P"].T @ z["P"]) + t.q(1, 2) * t.tr(z["Q"].T @ z["Q"])
            + t.tr(z["X"].T @ t.A @ z["Y"]) + t.tr(z["X"].T @ z["P"] @ z["Y"].T @ z["Q"]))


def F_lambda(t, U, V):
    return U.T @ t.resolvent(t.lam) @ t.resolvent(-t.lam) @ V


def L_dual_coupled(t, z):
    X, P, Y, Q, A, lam, I = z["X"], z["P"], z["Y"], z["Q"], t.A, t.lam, t.Ir
    F = lambda U, V: F_lambda(t, U, V)
    return block([
        [lam * F(P, X), lam * F(P, P), F(A @ P, Y), -I + F(A @ P, Q)],
        [-lam * F(X, X), -lam * F(X, P), -F(A @ X, Y), -F(A @ X, Q)],
        [F(A @ Q, X), -I + F(A @ Q, P), lam * F(Q, Y), lam * F(Q, Q)],
        [-F(A @ Y, X), -F(A @ Y, P), -lam * F(Y, Y), -lam * F(Y, Q)]])


def A_dual_coupled(t, z, d1, d2):
    X, P, Y, Q, A = z["X"], z["P"], z["Y"], z["Q"], t.A
    S = (X.T @ A @ Y + Y.T @ A @ X) / 2
    Lam, Pi = S - P.T @ P, S - Q.T @ Q
    O, I = t.zeros(t.r, t.r, ("r", "r")), t.Ir
    lam = t.scalar_matrix(t.lam, t.r, "r")
    return block([[d1, Lam, O, -lam], [I, d1, O, O], [O, -lam, d2, Pi], [O, O, I, d2]])


def _dual_residual(s, swapped):
    z = coupled_point(s)
    fl = stiefel_pairs_flow(s, H_perturbed_euclid, z, [("X", "P"), ("Y", "Q")])
    XP, YQ = z["X"].T @ z["P"], z["Y"].T @ z["Q"]
    d1, d2 = (-YQ, -XP) if swapped else (XP, YQ)
    return {"LA3*C": derivative(s, L_dual_coupled, z, fl) - comm(L_dual_coupled(s, z), A_dual_coupled(s, z, d1, d2))}


@claim("s86h2-perturbed-euclid-dual-lax", kind="lax", section="A2", sizes=admissible(n_max=3))
def perturbed_euclid_dual_lax(s):
    """κ = −½ perturbed coupled system: (LA3*C) with diagonal blocks −YᵀQ, −XᵀP (TRUE)."""
    return _dual_residual(s, True)


@claim("s86h2-perturbed-euclid-dual-lax-twin", kind="lax", section="A2", sizes=admissible(n_max=3))
def perturbed_euclid_dual_lax_twin(s):
    """FALSE twin: diagonal blocks XᵀP, YᵀQ."""
    return _dual_residual(s, False)
