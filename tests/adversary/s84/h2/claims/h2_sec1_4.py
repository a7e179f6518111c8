"""h2 hidden statements from §1 (Introduction) and §4 (Integrability of geodesic flows).
Each true statement (id h2-...) has one or two false twins (id ...-twin*, one change each).
Truth derived by hand (docstrings) and numerically by ../truth_numpy.py (logs/truth_numpy.log).

T1  h2-sphere-neumann (TRUE, r = 1): at r = 1, XᵀP = 0 on T*V, so H_neum,κ = ½(p,p) + ½(Ae,e) for every κ
    (the Neumann system on the sphere (sphere_neum) of §1 is the r = 1 case, independently of the metric).
    h2-sphere-neumann-twin (FALSE, stated for r >= 2): the same κ-independence for r >= 2; tr((XᵀP)²) ≠ 0 there.
T2  h2-kappa-difference (TRUE): the Dirac flows of H_neum,κ and H_neum,0 differ by 2κ(XW, PW), W = XᵀP ∈ so(r)
    (an infinitesimal right SO(r)-action), and dΘ along (XW, PW) is 0: the big Lax pair cannot tell the κ apart
    (§1: "for r > 1 this Lax pair does not define a Neumann system uniquely").
    -twin (FALSE, 2 <= r): difference 2κ(XW, −PW).  -twin2 (FALSE, 2 <= r < n): dΘ along (XW, −PW) = 0
    (dΦ along it is −2(PWXᵀ + XWPᵀ) ≠ 0; at r = n it vanishes, so the twin is stated for r < n).
T3  h2-submersion-generic-op (TRUE): for a generic symmetric operator 𝔸 on so(n), along the Dirac flow of
    H_𝔸 = ½<𝔸Φ, Φ>: Ẋ = 𝔸(Φ)X (dot_XP2), Φ̇ = [𝔸Φ, Φ] (Euler-so(n)), Ψ̇ = 0 and d(PᵀP)/dt = 0 (the
    SO(n)-invariants (SO(n)-inv) are integrals of every submersion metric, as Theorem 4.2 uses).
    -twin (FALSE): Φ̇ = [Φ, 𝔸Φ].  -twin2 (FALSE): d(PPᵀ)/dt = 0.
T4  h2-manakov-cube-lax (TRUE): B = A³, 𝔸₃ξ = A²ξ + AξA + ξA² (ad_A𝔸₃ = ad_{A³}), the Manakov Lax pair
    d/dt(Φ + λA) = [𝔸₃Φ + λA³, Φ + λA] along the Dirac flow of ½<𝔸₃Φ, Φ>.
    -twin (FALSE): −λA³.  -twin2 (FALSE): λA² in place of λB = λA³.
T5  h2-man-noether (TRUE): (man) commutes with (SO(n)-inv): {tr(Φ+λA)³, tr(S PᵀP)} = 0, {tr(Φ+λA)², Ψ_η} = 0
    (S generic symmetric r×r).  -twin (FALSE): {tr(Φ+λA)³, tr(S XᵀAX)} = 0 (XᵀAX is not SO(n)-invariant).
T6  h2-man-dual-U (TRUE): with U = (P X) (n × 2r), M = AΦ + ΦA, along (dot_XP3*): d(UᵀRU)/dt = Uᵀ[R, M]U
    (R = (λI − A)⁻¹); L*_man = −J UᵀRU; and dL*_man/dt = [L*_man, J Uᵀ(A + λI)U].
    -twin (FALSE): Uᵀ[M, R]U.  -twin-printed (FALSE, n >= 2: the printed (LA-MAN3) with (A + λI)⁻¹, a known
    erratum of the catalog, manakov-dual-lax).
T7  h2-manakov-reflection (TRUE): (dot_XP3*) is equivariant under S = S_1: F(SX, SP) = S F(X, P), and
    L*_man(SX, SP) = L*_man(X, P) (reflections).  -twin (FALSE): F(SX, SP) = F(X, P).
T8  h2-jensen-invariants (TRUE): SO(n)×SO(r)-invariant functions are integrals of H_κ (Theorem ET):
    {tr((PᵀP)²), H_κ} = {tr(PᵀPΨ²), H_κ} = 0.  -twin (FALSE, 2 <= r <= n-1): {tr(S PᵀP), H_κ} = 0.
T9  h2-gram-psi-not (TRUE not-claim, 2 <= r <= n-1; Remark after ET): {tr(S PᵀP), <Ψ,Ψ>} ≠ 0.
    -twin (FALSE not-claim, r = n): the same ≠ 0 at r = n, where PᵀP = −Ψ²/4 and the bracket vanishes.
"""
from stiefelsym import admissible, block, claim, comm

N = 4


def H_neum(t, kappa):
    W = t.X.T @ t.P
    return t.tr(t.P.T @ t.P) / 2 - (t.q(1, 2) + kappa) * t.tr(W @ W) + t.tr(t.X.T @ t.A @ t.X) / 2


def H_k(t):
    return H_neum(t, t.kappa)


def H_0(t):
    return H_neum(t, t.q(0))


def Theta(t):
    return t.P @ t.X.T - t.X @ t.P.T + t.X @ t.X.T


# ---------------------------------------------------------------- T1
@claim("h2-sphere-neumann", kind="id", section="1", sizes=admissible(n_max=5, r_max=1, condition="r = 1"))
def sphere_neumann(s):
    """TRUE (r = 1): H_neum,κ = ½(p,p) + ½(Ae,e) for every κ (XᵀP = 0 on T*S^{n-1})."""
    return {"H_k - H_sphere": H_k(s) - (s.tr(s.P.T @ s.P) / 2 + s.tr(s.X.T @ s.A @ s.X) / 2)}


@claim("h2-sphere-neumann-twin", kind="id", section="1", sizes=admissible(n_max=5, r_min=2, condition="r >= 2"))
def sphere_neumann_twin(s):
    """FALSE (r >= 2): H_neum,κ = ½tr(PᵀP) + ½tr(XᵀAX) for every κ."""
    return {"H_k - H_sphere": H_k(s) - (s.tr(s.P.T @ s.P) / 2 + s.tr(s.X.T @ s.A @ s.X) / 2)}


# ---------------------------------------------------------------- T2
@claim("h2-kappa-difference", kind="id", section="1", sizes=admissible(n_max=N))
def kappa_difference(s):
    """TRUE: flow(H_κ) − flow(H_0) = 2κ(XW, PW), W = XᵀP; dΘ(XW, PW) = 0."""
    fk, f0 = s.dirac_flow(H_k), s.dirac_flow(H_0)
    W = s.X.T @ s.P
    return {"dX": fk.Xdot - f0.Xdot - 2 * s.kappa * (s.X @ W),
            "dP": fk.Pdot - f0.Pdot - 2 * s.kappa * (s.P @ W),
            "dTheta(XW,PW)": s.d(Theta, {"X": s.X @ W, "P": s.P @ W})}


@claim("h2-kappa-difference-twin", kind="id", section="1", sizes=admissible(n_max=N, r_min=2, condition="r >= 2"))
def kappa_difference_twin(s):
    """FALSE (r >= 2): the difference is 2κ(XW, −PW)."""
    fk, f0 = s.dirac_flow(H_k), s.dirac_flow(H_0)
    W = s.X.T @ s.P
    return {"dX": fk.Xdot - f0.Xdot - 2 * s.kappa * (s.X @ W),
            "dP": fk.Pdot - f0.Pdot + 2 * s.kappa * (s.P @ W)}


@claim("h2-kappa-difference-twin2", kind="id", section="1",
       sizes=admissible(n_max=N, r_min=2, where=lambda n, r: r < n, condition="2 <= r < n"))
def kappa_difference_twin2(s):
    """FALSE (2 <= r < n): dΘ along (XW, −PW) = 0."""
    W = s.X.T @ s.P
    return {"dTheta(XW,-PW)": s.d(Theta, {"X": s.X @ W, "P": -(s.P @ W)})}


# ---------------------------------------------------------------- T3
def H_AA(t):
    return t.killing(t.sym_operator("AA")(t.Phi), t.Phi) / 2


def _sub_flow(s):
    flow = s.dirac_flow(H_AA)
    AA = s.sym_operator("AA")
    return flow, AA(s.Phi)


@claim("h2-submersion-generic-op", kind="id", section="4", sizes=admissible(n_max=N))
def submersion_generic(s):
    """TRUE: Ẋ = 𝔸(Φ)X, Φ̇ = [𝔸Φ, Φ], Ψ̇ = 0, d(PᵀP)/dt = 0 along the flow of ½<𝔸Φ, Φ>."""
    flow, AP = _sub_flow(s)
    return {"Xdot - AA(Phi)X": flow.Xdot - AP @ s.X,
            "Phidot - [AA Phi, Phi]": s.d(lambda t: t.Phi, flow) - comm(AP, s.Phi),
            "Psidot": s.d(lambda t: t.Psi, flow),
            "d(P^TP)/dt": s.d(lambda t: t.P.T @ t.P, flow)}


@claim("h2-submersion-generic-op-twin", kind="id", section="4", sizes=admissible(n_max=N, n_min=3, condition="n >= 3 (so(2) is abelian)"))
def submersion_generic_twin(s):
    """FALSE: Φ̇ = [Φ, 𝔸Φ]."""
    flow, AP = _sub_flow(s)
    return {"Phidot - [Phi, AA Phi]": s.d(lambda t: t.Phi, flow) - comm(s.Phi, AP)}


@claim("h2-submersion-generic-op-twin2", kind="id", section="4", sizes=admissible(n_max=N, n_min=2, where=lambda n, r: (n, r) != (2, 2), condition="n >= 2, (n, r) != (2, 2)"))
def submersion_generic_twin2(s):
    """FALSE: d(PPᵀ)/dt = 0."""
    flow, _ = _sub_flow(s)
    return {"d(PP^T)/dt": s.d(lambda t: t.P @ t.P.T, flow)}


# ---------------------------------------------------------------- T4
def AA3(t, xi):
    A = t.A
    return A @ A @ xi + A @ xi @ A + xi @ A @ A


def H_A3(t):
    return t.killing(AA3(t, t.Phi), t.Phi) / 2


def _lax3(s, M_extra):
    flow = s.dirac_flow(H_A3)
    L = s.Phi + s.lam * s.A
    return {"dL/dt - [M, L]": s.d(lambda t: t.Phi + t.lam * t.A, flow) - comm(AA3(s, s.Phi) + M_extra, L)}


@claim("h2-manakov-cube-lax", kind="lax", section="4", sizes=admissible(n_max=N))
def manakov_cube_lax(s):
    """TRUE: d/dt(Φ + λA) = [𝔸₃Φ + λA³, Φ + λA], and ad_A 𝔸₃ = ad_{A³} on so(n)."""
    out = _lax3(s, s.lam * (s.A @ s.A @ s.A))
    out["ad_A AA3(xi) - ad_A3 xi"] = comm(s.A, AA3(s, s.xi)) - comm(s.A @ s.A @ s.A, s.xi)
    return out


@claim("h2-manakov-cube-lax-twin", kind="lax", section="4", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def manakov_cube_lax_twin(s):
    """FALSE: M = 𝔸₃Φ − λA³."""
    return _lax3(s, -(s.lam * (s.A @ s.A @ s.A)))


@claim("h2-manakov-cube-lax-twin2", kind="lax", section="4", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def manakov_cube_lax_twin2(s):
    """FALSE: M = 𝔸₃Φ + λA²."""
    return _lax3(s, s.lam * (s.A @ s.A))


# ---------------------------------------------------------------- T5
def man(k):
    def f(t):
        M = t.Phi + t.lam * t.A
        acc = M
        for _ in range(k - 1):
            acc = acc @ M
        return t.tr(acc)
    return f


def trSPP(t):
    return t.tr(t.generic("S", "r", "r", "sym") @ t.P.T @ t.P)


@claim("h2-man-noether", kind="pb", section="4", sizes=admissible(n_max=N))
def man_noether(s):
    """TRUE: {tr(Φ+λA)³, tr(S PᵀP)} = 0, {tr(Φ+λA)², Ψ_η} = 0."""
    return {"{man3, trSPP}": s.bracket(man(3), trSPP),
            "{man2, Psi_eta}": s.bracket(man(2), lambda t: t.killing(t.Psi, t.eta))}


@claim("h2-man-noether-twin", kind="pb", section="4", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def man_noether_twin(s):
    """FALSE: {tr(Φ+λA)³, tr(S XᵀAX)} = 0."""
    return {"{man3, tr S X^TAX}": s.bracket(man(3), lambda t: t.tr(t.generic("S", "r", "r", "sym") @ t.X.T @ t.A @ t.X))}


# ---------------------------------------------------------------- T6
def F3(s, X, P):
    Phi = P @ X.T - X @ P.T
    M = s.A @ Phi + Phi @ s.A
    return {"X": M @ X, "P": M @ P}


def U_of(t):
    return block([[t.P, t.X]])


def Jr(s):
    z = s.zeros(s.r, s.r, ("r", "r"))
    return block([[z, s.Ir], [-s.Ir, z]])


def Lman(t):
    R = t.resolvent(t.lam)
    X, P = t.X, t.P
    return block([[-(X.T @ R @ P), -(X.T @ R @ X)], [P.T @ R @ P, P.T @ R @ X]])


@claim("h2-man-dual-U", kind="lax", section="4", sizes=admissible(n_max=N))
def man_dual_U(s):
    """TRUE: d(UᵀRU)/dt = Uᵀ[R, M]U, L*_man = −JUᵀRU, dL*_man/dt = [L*_man, JUᵀ(A+λI)U] along (dot_XP3*)."""
    F = F3(s, s.X, s.P)
    R = s.resolvent(s.lam)
    U = U_of(s)
    M = s.A @ s.Phi + s.Phi @ s.A
    Acorr = Jr(s) @ U.T @ (s.A + s.lam * s.In) @ U
    return {"d(U^TRU) - U^T[R,M]U": s.d(lambda t: U_of(t).T @ t.resolvent(t.lam) @ U_of(t), F) - U.T @ comm(R, M) @ U,
            "Lman + J U^TRU": Lman(s) + Jr(s) @ U.T @ R @ U,
            "dLman - [Lman, A*corr]": s.d(Lman, F) - comm(Lman(s), Acorr)}


@claim("h2-man-dual-U-twin", kind="lax", section="4", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def man_dual_U_twin(s):
    """FALSE: d(UᵀRU)/dt = Uᵀ[M, R]U."""
    F = F3(s, s.X, s.P)
    R = s.resolvent(s.lam)
    U = U_of(s)
    M = s.A @ s.Phi + s.Phi @ s.A
    return {"d(U^TRU) - U^T[M,R]U": s.d(lambda t: U_of(t).T @ t.resolvent(t.lam) @ U_of(t), F) - U.T @ comm(M, R) @ U}


@claim("h2-man-dual-printed-twin", kind="lax", section="4", sizes=admissible(n_max=N, n_min=2, condition="n >= 2"))
def man_dual_printed_twin(s):
    """FALSE (n >= 2): (MAN-LA) with the printed (LA-MAN3), entries with (A + λI)⁻¹ (known erratum)."""
    F = F3(s, s.X, s.P)
    Ri = (s.A + s.lam * s.In).inv()
    X, P = s.X, s.P
    Ap = block([[X.T @ Ri @ P, X.T @ Ri @ X], [-(P.T @ Ri @ P), -(P.T @ Ri @ X)]])
    return {"dLman - [Lman, A*printed]": s.d(Lman, F) - comm(Lman(s), Ap)}


# ---------------------------------------------------------------- T7
def S1(s):
    n = s.n
    return s.mat([[(s.q(-1) if i == 0 else s.q(1)) if i == j else s.q(0) for j in range(n)] for i in range(n)], ("n", "n"))


@claim("h2-manakov-reflection", kind="id", section="4", sizes=admissible(n_max=5))
def manakov_reflection(s):
    """TRUE: F(SX, SP) = S F(X, P) for (dot_XP3*), and L*_man(SX, SP) = L*_man(X, P), S = S_1."""
    S = S1(s)
    Fs, F = F3(s, S @ s.X, S @ s.P), F3(s, s.X, s.P)
    R = s.resolvent(s.lam)
    X, P = S @ s.X, S @ s.P
    LmS = block([[-(X.T @ R @ P), -(X.T @ R @ X)], [P.T @ R @ P, P.T @ R @ X]])
    return {"X": Fs["X"] - S @ F["X"], "P": Fs["P"] - S @ F["P"], "Lman": LmS - Lman(s)}


@claim("h2-manakov-reflection-twin", kind="id", section="4", sizes=admissible(n_max=5, n_min=2, condition="n >= 2"))
def manakov_reflection_twin(s):
    """FALSE: F(SX, SP) = F(X, P)."""
    S = S1(s)
    Fs, F = F3(s, S @ s.X, S @ s.P), F3(s, s.X, s.P)
    return {"X": Fs["X"] - F["X"], "P": Fs["P"] - F["P"]}


# ---------------------------------------------------------------- T8, T9
def H_J(t):
    return t.killing(t.Phi, t.Phi) / 2 + t.kappa * t.killing(t.Psi, t.Psi) / 2


@claim("h2-jensen-invariants", kind="pb", section="4", sizes=admissible(n_max=N))
def jensen_invariants(s):
    """TRUE: {tr((PᵀP)²), H_κ} = {tr(PᵀPΨ²), H_κ} = 0."""
    return {"{tr (P^TP)^2, H_k}": s.bracket(lambda t: t.tr(t.P.T @ t.P @ t.P.T @ t.P), H_J),
            "{tr P^TP Psi^2, H_k}": s.bracket(lambda t: t.tr(t.P.T @ t.P @ t.Psi @ t.Psi), H_J)}


@claim("h2-jensen-invariants-twin", kind="pb", section="4",
       sizes=admissible(n_max=N, r_min=2, where=lambda n, r: r < n, condition="2 <= r <= n - 1"))
def jensen_invariants_twin(s):
    """FALSE (2 <= r <= n-1): {tr(S PᵀP), H_κ} = 0."""
    return {"{trSPP, H_k}": s.bracket(trSPP, H_J)}


@claim("h2-gram-psi-not", kind="not", expect="nonzero", section="4",
       sizes=admissible(n_max=N, r_min=2, where=lambda n, r: r < n, condition="2 <= r <= n - 1"))
def gram_psi_not(s):
    """TRUE (2 <= r <= n-1): {tr(S PᵀP), <Ψ,Ψ>} ≠ 0."""
    return {"{trSPP, <Psi,Psi>}": s.bracket(trSPP, lambda t: t.killing(t.Psi, t.Psi))}


@claim("h2-gram-psi-not-twin", kind="not", expect="nonzero", section="4",
       sizes=admissible(n_max=N, r_min=2, where=lambda n, r: r == n, condition="r = n >= 2"))
def gram_psi_not_twin(s):
    """FALSE (r = n): {tr(S PᵀP), <Ψ,Ψ>} ≠ 0 -- it vanishes identically there."""
    return {"{trSPP, <Psi,Psi>}": s.bracket(trSPP, lambda t: t.killing(t.Psi, t.Psi))}
